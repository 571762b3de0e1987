//! The augmented model of the sim-to-real diagnosis ([`Augmented`]): the
//! vehicle model ([`crate::vehicle`]) with the candidate effects of
//! [`crate::diagnose::effects`] set in its [`Effects`] — the base model's
//! own with a candidate's applied on top (`crate::diagnose::fit::layout`)
//! —, on the campaign's road, and its replay of a run.
//!
//! The physics is the vehicle model's own ([`VehicleModel::rates`], which
//! reads every number of its [`Effects`]: the vehicle values and road
//! friction they scale too), integrated by the simulation's integrator
//! ([`Integrator::replay`]: RK4 on a grid where the run's inputs are
//! sampled once, [`Drive`], so repeated replays only evaluate the model).
//! What this module adds is what acts outside the right-hand side: the
//! sensors ([`crate::vehicle::Sensors`]) applied to the response, and the
//! steer path. With every effect off it is the base model (tested against
//! [`crate::sim::Integrator::run`]).
//!
//! The steer path ([`crate::vehicle::SteerPath`]: an actuator's delay and
//! first-order lag between the logged steer and the road wheels) is linear
//! in the input, so it is no state of the model: a replay whose steer path
//! is on runs a copy of the drive whose steer samples are the path's exact
//! output for the logged (piecewise-linear) steer ([`Augmented::steered`]);
//! one whose path is off runs the drive itself. [`Augmented::simulate`]
//! replays the drive it is given: the callers that replay logged runs
//! ([`crate::diagnose::model::replay::Prepared::drive_for`], the proving
//! ground) pass it through [`Augmented::steered`] first. Units: SI, rad.

pub(crate) mod axles;
pub(crate) mod channels;
pub(crate) mod replay;
pub(crate) mod scale;

use crate::manoeuvre::Interpolator;
pub use crate::sim::{Drive, FixedStep};
use crate::sim::{Integrator, TimeHistory};
use crate::vehicle::{Effects, ModelOptions, State, StateVector, VehicleModel, LOAD_TOLERANCE};
use std::borrow::Cow;

/// The vehicle model with effects, on the campaign's road.
#[derive(Debug, Clone, PartialEq)]
pub struct Augmented {
    /// The vehicle model (vehicle, tyres, kinematics, load transfer) with
    /// its effects: the base model's, and a candidate's set on them.
    pub model: VehicleModel,
    /// Road friction scale of the campaign (the effects may scale it).
    pub friction: f64,
}

impl Augmented {
    /// The model `model` with its own effects, on a road of friction
    /// `friction`.
    pub fn new(model: VehicleModel, friction: f64) -> Self {
        Self { model, friction }
    }

    /// The effects.
    pub fn effects(&self) -> &Effects {
        &self.model.options.effects
    }

    /// The effects, to set them.
    pub fn effects_mut(&mut self) -> &mut Effects {
        &mut self.model.options.effects
    }

    /// Whether `other` integrates the same history as this model from the
    /// same state: the two differ at most in their sensors, which act on the
    /// response only (their offsets move the start state, which the caller
    /// compares).
    pub(crate) fn same_dynamics(&self, other: &Augmented) -> bool {
        let (a, b) = (&self.model, &other.model);
        let options = ModelOptions {
            effects: Effects {
                sensors: a.options.effects.sensors,
                ..b.options.effects
            },
            ..b.options
        };
        a.vehicle == b.vehicle
            && a.front == b.front
            && a.rear == b.rear
            && a.options == options
            && self.friction == other.friction
    }

    /// The drive the road wheels see when the steer logged as (`t`,
    /// `steer`), which `drive` samples, goes through the steer path:
    /// `drive` itself while the path is off (so the replay is the base
    /// model's bit for bit), else a copy whose steer at every stage time is
    /// the path's output ([`crate::vehicle::SteerPath::apply`]).
    pub(crate) fn steered<'d>(&self, drive: &'d Drive, t: &[f64], steer: &[f64]) -> Cow<'d, Drive> {
        let path = self.effects().steer_path;
        if path.is_off() {
            Cow::Borrowed(drive)
        } else {
            let wheel = path.apply(t, steer, &drive.stage_times());
            Cow::Owned(drive.clone().with_steer(wheel))
        }
    }

    /// The state that starts a replay at sideslip `beta` and yaw rate
    /// `yaw_rate`: lag states at their kinematic slip angles, roll at its
    /// steady value for ay = u·r.
    pub(crate) fn initial_state(&self, drive: &Drive, beta: f64, yaw_rate: f64) -> StateVector {
        Self::quasi_static(&self.model, self.friction, drive, beta, yaw_rate)
    }

    fn quasi_static(
        model: &VehicleModel,
        friction: f64,
        drive: &Drive,
        beta: f64,
        yaw_rate: f64,
    ) -> StateVector {
        let x = State { beta, yaw_rate };
        model.quasi_static_state(&x, &drive.first_inputs(friction))
    }

    /// Replays the drive from `x0`; the history carries the roll.
    pub(crate) fn simulate(&self, drive: &Drive, x0: StateVector) -> TimeHistory {
        Self::replay(&self.model, self.friction, drive, x0, LOAD_TOLERANCE)
    }

    /// Replays the drive from the state [`Augmented::initial_state`] gives
    /// for `beta` and `yaw_rate`, building the model once (the fits replay
    /// every run at every evaluation).
    #[cfg(test)]
    pub(crate) fn simulate_from(&self, drive: &Drive, beta: f64, yaw_rate: f64) -> TimeHistory {
        self.simulate_from_to(drive, beta, yaw_rate, LOAD_TOLERANCE)
    }

    /// [`Augmented::simulate_from`] with the load-transfer loop solved to
    /// relative tolerance `tol`.
    pub(crate) fn simulate_from_to(
        &self,
        drive: &Drive,
        beta: f64,
        yaw_rate: f64,
        tol: f64,
    ) -> TimeHistory {
        let x0 = Self::quasi_static(&self.model, self.friction, drive, beta, yaw_rate);
        Self::replay(&self.model, self.friction, drive, x0, tol)
    }

    fn replay(
        model: &VehicleModel,
        friction: f64,
        drive: &Drive,
        x0: StateVector,
        tol: f64,
    ) -> TimeHistory {
        let integrator = Integrator {
            friction,
            ..Integrator::default()
        };
        integrator.replay_to(model, drive, x0, tol)
    }

    /// What the sensors record of a response, interpolated at `times`:
    /// (yaw rate, ay, β). A yawed accelerometer's longitudinal
    /// acceleration is the response's speed rate (a simulation's own
    /// du/dt); a replay of a drive with an `ax` of its own reads that one
    /// ([`Augmented::observe_driven`]).
    pub(crate) fn observe(&self, response: &TimeHistory, times: &[f64]) -> Observed {
        let ax = if self.effects().sensors.reads_ax() {
            speed_rate(&response.t, &response.speed)
        } else {
            Vec::new()
        };
        self.observe_with_ax(response, &ax, times)
    }

    /// [`Augmented::observe`] of a replay of `drive`, whose longitudinal
    /// acceleration ([`Drive::ax_samples`]: a logged `ax`, else the
    /// speed's smoothed derivative) a yawed accelerometer reads.
    pub(crate) fn observe_driven(
        &self,
        response: &TimeHistory,
        drive: &Drive,
        times: &[f64],
    ) -> Observed {
        let ax = if self.effects().sensors.reads_ax() {
            let (t, ax) = grid_ax(drive);
            let mut nodes = Interpolator::new(&t);
            response.t.iter().map(|&s| nodes.at(&ax, s)).collect()
        } else {
            Vec::new()
        };
        self.observe_with_ax(response, &ax, times)
    }

    /// [`Augmented::observe`] with the longitudinal acceleration `ax` at
    /// the response's times (empty where the sensors do not read it,
    /// [`crate::vehicle::Sensors::reads_ax`]).
    pub(crate) fn observe_with_ax(
        &self,
        response: &TimeHistory,
        ax: &[f64],
        times: &[f64],
    ) -> Observed {
        let [yaw_rate, ay, beta] = self.seen_rows(response, 0..response.len(), ax, times);
        let mut nodes = Interpolator::new(&response.t);
        Observed {
            yaw_rate,
            ay,
            beta,
            roll: times.iter().map(|&t| nodes.at(&response.roll, t)).collect(),
        }
    }

    /// What the sensors record (yaw rate, ay, β) of the rows `rows` of a
    /// response alone, interpolated at `times`, `ax` at those rows' times:
    /// over every row, [`Augmented::observe_with_ax`]'s. Over fewer, a
    /// value is that one's to the bit where everything it reads lies
    /// inside the rows, away from their ends (a chunk of a replay scored
    /// while it runs, `replay::chunked`): the sensors' rate, delay and the
    /// interpolation read only neighbouring rows.
    pub(crate) fn seen_rows(
        &self,
        response: &TimeHistory,
        rows: std::ops::Range<usize>,
        ax: &[f64],
        times: &[f64],
    ) -> [Vec<f64>; 3] {
        let h = response;
        let r = || rows.clone();
        let t = &h.t[r()];
        let seen = self.effects().sensors.seen(
            t,
            &h.speed[r()],
            ax,
            &h.yaw_rate[r()],
            &h.ay[r()],
            &h.beta[r()],
        );
        seen.map(|ys| {
            let mut nodes = Interpolator::new(t);
            times.iter().map(|&s| nodes.at(&ys, s)).collect()
        })
    }
}

/// The longitudinal acceleration `drive` gives the model at its grid
/// times (the first stage of every step is at its grid time, [`Drive`]'s
/// layout for either method): (times, ax), m/s².
pub(crate) fn grid_ax(drive: &Drive) -> (Vec<f64>, Vec<f64>) {
    let (times, ax) = (drive.stage_times(), drive.ax_samples());
    let per = (ax.len() - 1) / drive.steps.max(1);
    (0..=drive.steps)
        .map(|i| (times[per * i], ax[per * i]))
        .unzip()
}

/// The rate of `speed` over `t` by central differences (one-sided at the
/// ends), m/s².
fn speed_rate(t: &[f64], speed: &[f64]) -> Vec<f64> {
    let n = t.len();
    (0..n)
        .map(|i| {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(n - 1));
            if b > a {
                (speed[b] - speed[a]) / (t[b] - t[a])
            } else {
                0.0
            }
        })
        .collect()
}

/// Simulated measurements at a run's sample times.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Observed {
    /// Yaw rate, rad/s.
    pub yaw_rate: Vec<f64>,
    /// Lateral acceleration as the accelerometer reads it, m/s².
    pub ay: Vec<f64>,
    /// Sideslip, rad.
    pub beta: Vec<f64>,
    /// Body roll (the model's state, without sensor effects), rad.
    pub roll: Vec<f64>,
}

#[cfg(test)]
mod nesting_tests;
#[cfg(test)]
mod tests;
