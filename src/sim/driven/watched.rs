//! A replay of a sampled drive that a caller watches while it runs
//! ([`Integrator::replay_watched`]): every so many recorded rows it is
//! shown the history so far and may stop the integration there. The
//! integration is [`Integrator::replay_to`]'s, the same loop of the same
//! method over the same grid with the same state carried from step to step
//! (nothing restarts at a look): a replay that is not stopped is that one's
//! to the bit, and one that is stopped holds its first rows. The
//! diagnosis uses it to stop a replay whose cost is already known to be
//! above what its fit can accept ([`crate::diagnose`]'s problems). Units:
//! SI, rad.

use super::{record, Driven, Source, W_REFRESH};
use crate::sim::ode;
use crate::sim::{Drive, FixedStep, Integrator, TimeHistory};
use crate::vehicle::{StateVector, VehicleModel};

impl Integrator {
    /// [`Integrator::replay_to`] of `drive` from `x0`, with `watch` shown
    /// the history after every `every` rows (not after the last): None as
    /// soon as it returns false (the integration stopped there), else the
    /// whole replay, `replay_to`'s to the bit. `every` = 0 watches nothing.
    /// Also returns the rows integrated, stopped or not.
    pub(crate) fn replay_watched(
        &self,
        model: &VehicleModel,
        drive: &Drive,
        x0: StateVector,
        tol: f64,
        every: usize,
        mut watch: impl FnMut(&TimeHistory) -> bool,
    ) -> (Option<TimeHistory>, usize) {
        if every == 0 {
            let hist = self.replay_to(model, drive, x0, tol);
            let rows = hist.len();
            return (Some(hist), rows);
        }
        let mut sys = Driven::new(model, Source::Sampled(drive), self.friction, tol);
        let n = drive.steps;
        // `run_rk4::<6>` and `run_w`'s history: a replay records the roll.
        let mut hist = TimeHistory::with_capacity(n + 1, true);
        let mut stopped = false;
        // `record` as the unwatched runs call it, then the look: a false
        // stops the method's loop before its next step.
        let mut row = |sys: &mut Driven, i: usize, t: f64, x: &StateVector| {
            record(&mut hist, sys, t, x);
            if i < n && hist.len().is_multiple_of(every) && !watch(&hist) {
                stopped = true;
            }
            !stopped
        };
        let (t0, h) = (drive.start, drive.step);
        match drive.method {
            FixedStep::Rk4 => {
                ode::rk4(&mut sys, t0, h, n, x0, &mut row);
            }
            FixedStep::RosenbrockW => {
                ode::rosenbrock_w(&mut sys, t0, h, n, x0, W_REFRESH, &mut row);
            }
        }
        let rows = hist.len();
        if stopped {
            return (None, rows);
        }
        hist.load_evaluations = sys.load_evaluations;
        (Some(hist), rows)
    }
}
