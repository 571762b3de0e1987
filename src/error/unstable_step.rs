//! A fixed RK4 step beyond the method's stability limit for the model a
//! scenario drives: the fastest mode (a tyre lag's `u/σ`, or the bicycle
//! model's own at low speed) decays at a rate ρ, and RK4's stability region
//! ends at `h·ρ ≈ 2.785` on the negative real axis. Past it the run blows
//! up: angles of 1e162 rad and NaN rows were written with exit 0
//! (fresh-eyes round 9). Refused at the step (or the method, where the
//! step is the default) with the rate, its cause and the remedies.

use super::number::Num;
use crate::format::{fixed, rounded, significant};
use std::fmt;

/// RK4's stability limit on the negative real axis (the root of
/// `|1 + z + z²/2 + z³/6 + z⁴/24| = 1`, z < 0).
pub const RK4_STABILITY_LIMIT: f64 = 2.785;

/// The numbers of the refusal. s, 1/s, m/s, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UnstableStep {
    /// The fixed step, s.
    pub step: f64,
    /// The model's fastest rate at `speed`, 1/s.
    pub rate: f64,
    /// The speed where it is fastest, m/s.
    pub speed: f64,
    /// The tyres' relaxation length where the lag sets the rate, m.
    pub relaxation_length: Option<f64>,
}

impl fmt::Display for UnstableStep {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let cause = match self.relaxation_length {
            Some(sigma) => format!(
                "the tyres' lag, u/σ with `relaxation_length` = {} m",
                Num(sigma)
            ),
            None => "the yaw, sideslip and roll modes".to_string(),
        };
        let largest = 0.9 * RK4_STABILITY_LIMIT / self.rate;
        write!(
            f,
            "RK4 at a fixed step of {} s is unstable for this model: its fastest mode decays at {} 1/s at {} m/s ({cause}), so h·ρ = {} is beyond RK4's stability limit of {} and the run would blow up; use a step of at most {} s (h·ρ ≤ 2.5), or method = \"dopri5\" (the default), which chooses its own steps",
            Num(self.step),
            rounded(self.rate, 4),
            fixed(self.speed, 1),
            rounded(self.step * self.rate, 3),
            RK4_STABILITY_LIMIT,
            significant(largest, 2)
        )
    }
}
