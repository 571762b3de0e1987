//! The load-transfer seeds of the adaptive method (Dormand–Prince,
//! [`crate::sim::ode::dopri5`]): where each stage's solve of `ay = Y(ay)/m`
//! starts, from that stage's own last solutions or from the stages before
//! it, whichever predicted that stage better last time. Units: s, m/s².

use crate::sim::ode::ADAPTIVE_STAGES;

/// The load-transfer seeds of the adaptive method, stage by stage: each
/// stage's last three (t, ay) solutions, newest first, and how far each of
/// the two predictions (the driven system's linear one across stages, and
/// [`stage_prediction`]) missed that stage's last solution. The one that
/// missed by less is taken: the stage's own history predicts far better at
/// small steps (a tight tolerance), the stages before it at large ones.
#[derive(Debug, Clone, Copy)]
pub(super) struct Adaptive {
    /// The stage being evaluated ([`crate::sim::ode::OdeSystem::dopri5_stage`]).
    pub(super) stage: usize,
    solutions: [[(f64, f64); 3]; ADAPTIVE_STAGES],
    /// |prediction − solution| of [the stage's own, the linear], m/s².
    misses: [[f64; 2]; ADAPTIVE_STAGES],
    /// This evaluation's two predictions (the stage's own None).
    predicted: (Option<f64>, f64),
}

impl Default for Adaptive {
    fn default() -> Self {
        Self {
            stage: 0,
            solutions: [[(f64::NAN, 0.0); 3]; ADAPTIVE_STAGES],
            misses: [[f64::INFINITY, 0.0]; ADAPTIVE_STAGES],
            predicted: (None, 0.0),
        }
    }
}

impl Adaptive {
    /// The seed at `t` of the current stage, `linear` the prediction from
    /// the stages before it.
    pub(super) fn choose(&mut self, t: f64, linear: f64) -> f64 {
        let own = stage_prediction(&self.solutions[self.stage], t);
        self.predicted = (own, linear);
        let [miss_own, miss_linear] = self.misses[self.stage];
        match own {
            Some(p) if miss_own <= miss_linear => p,
            _ => linear,
        }
    }

    /// Records the current stage's solution `ay` at `t`.
    pub(super) fn record(&mut self, t: f64, ay: f64) {
        let s = self.stage;
        let (own, linear) = self.predicted;
        self.misses[s] = [
            own.map_or(f64::INFINITY, |p| (p - ay).abs()),
            (linear - ay).abs(),
        ];
        let last = self.solutions[s];
        self.solutions[s] = [(t, ay), last[0], last[1]];
    }
}

/// The quadratic through the last three (t, ay) solutions `h` of one stage
/// of the adaptive method (newest first), at `t`: None unless their times
/// differ and `t` lies within twice their span of the newest. A stage's
/// state is off the solution by about the same amount from one step to the
/// next, so its own solutions predict its next one far better than the
/// solutions of the stage before it: over a 10 s PAC89 step steer at rtol
/// 1e-10, 1.5 % of the seeds instead of 17 % end more than 6e-4 m/s² (where
/// the Newton solve's one-pass ending stops holding) from the root
/// (measured on a Python model of the integration); the load-transfer
/// passes drop from 1.18 to 1.02 a right-hand side.
pub(super) fn stage_prediction(h: &[(f64, f64); 3], t: f64) -> Option<f64> {
    let [(t2, a2), (t1, a1), (t0, a0)] = *h;
    let distinct = t2 != t1 && t1 != t0 && t2 != t0;
    if !(distinct && (t - t2).abs() <= 2.0 * (t2 - t0).abs()) {
        return None;
    }
    // Newton's divided differences.
    let d21 = (a2 - a1) / (t2 - t1);
    let d10 = (a1 - a0) / (t1 - t0);
    let d210 = (d21 - d10) / (t2 - t0);
    Some(a2 + (t - t2) * (d21 + d210 * (t - t1)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stage whose solutions lie on a quadratic in time: its own
    /// prediction is exact (to rounding) and is taken once it has missed by
    /// less than the other; before (too few solutions, or a first miss not
    /// yet measured) and far beyond its solutions' span the other is; the
    /// other stages keep their own histories.
    #[test]
    fn a_stage_is_seeded_from_its_own_quadratic_once_that_predicted_better() {
        let q = |t: f64| 0.3 - 2.0 * t + 5.0 * t * t;
        let mut a = Adaptive {
            stage: 3,
            ..Adaptive::default()
        };
        for t in [0.0, 0.01, 0.025] {
            assert_eq!(a.choose(t, 7.0), 7.0, "{t}: too few solutions");
            a.record(t, q(t));
        }
        // Its own prediction exists now, but its miss is not yet measured.
        assert_eq!(a.choose(0.04, 7.0), 7.0);
        a.record(0.04, q(0.04));
        let p = a.choose(0.05, 7.0);
        assert!((p - q(0.05)).abs() < 1e-12, "{p} vs {}", q(0.05));
        a.record(0.05, q(0.05));
        // Beyond twice the span of the three solutions: not extrapolated.
        assert_eq!(a.choose(0.2, 7.0), 7.0);
        // When the other predicted better, the other.
        let mut b = a;
        b.misses[3] = [1e-3, 1e-4];
        assert_eq!(b.choose(0.06, 7.0), 7.0);
        // Another stage has no history of its own.
        a.stage = 4;
        assert_eq!(a.choose(0.06, -1.0), -1.0);
        assert_eq!(
            stage_prediction(&[(1.0, 2.0), (1.0, 2.0), (0.5, 1.0)], 1.1),
            None
        );
    }
}
