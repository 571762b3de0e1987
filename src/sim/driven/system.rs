//! [`Driven`] as the ODE the integrators step: the model's rates at the
//! inputs of time `t`, each load-transfer solve seeded from the stage's
//! own history, and the run's progress counted as it goes.

use super::Driven;
use crate::sim::ode::{OdeSystem, W_PROBE, W_TIME_PROBE};
use crate::vehicle::{LoadTransferSeed, StateVector};

impl<const N: usize> OdeSystem<N> for Driven<'_> {
    fn derivatives(&mut self, t: f64, x: &[f64; N]) -> [f64; N] {
        if let Some(p) = &self.progress {
            p.at(t);
        }
        let inp = self.inputs(t);
        let mut full: StateVector = [0.0; 6];
        full[..N].copy_from_slice(x);
        if matches!(self.stage, Some((_, W_PROBE | W_TIME_PROBE))) {
            // A Jacobian or time probe: at the wheel loads of the step's own
            // solution, not solved again (one evaluation; and a solve, exact
            // only to its tolerance, would put that tolerance over the
            // probe's small step into W, unsmooth in a fit's parameters);
            // the stages' seeds and the record left alone.
            let mut seed = LoadTransferSeed {
                ay: [self.last.1.ay; 3],
                slope: self.seeds[0].slope,
            };
            let (dx, o) = self.model.rates_in(
                &self.scalars,
                &full,
                &inp,
                (&mut seed, &mut self.cosine),
                f64::INFINITY,
            );
            self.load_evaluations += u64::from(o.load_iterations);
            return std::array::from_fn(|i| dx[i]);
        }
        let j = self.seed(t);
        let (dx, o) = self.model.rates_in(
            &self.scalars,
            &full,
            &inp,
            (&mut self.seeds[j], &mut self.cosine),
            self.load_tolerance,
        );
        if self.stage.is_none() {
            let [(t1, a1), _] = self.history;
            self.history = [(t, o.ay), (t1, a1)];
            self.adaptive.record(t, o.ay);
        }
        self.load_evaluations += u64::from(o.load_iterations);
        self.last = (inp, o);
        std::array::from_fn(|i| dx[i])
    }

    fn dopri5_stage(&mut self, stage: usize) {
        self.adaptive.stage = stage;
    }

    fn rk4_stage(&mut self, step: usize, stage: usize) {
        self.stage = Some((step, stage));
    }

    fn w_stage(&mut self, step: usize, stage: usize) {
        self.stage = Some((step, stage));
    }

    /// (β, r) always; the lagged slip angles and the roll states only when
    /// the model integrates them.
    fn implicit_states(&self) -> [bool; N] {
        let e = &self.model.options.effects;
        std::array::from_fn(|i| match i {
            0 | 1 => true,
            2 | 3 => e.lagged(),
            _ => e.uses_roll(),
        })
    }
}
