//! A run's yaw rate against a neutral car's where its steer is held: the
//! median of `r·l/(u·δ)` (1 for a neutral car, ISO 8855 signs: a left
//! steer turns left), the shares turning with and against the steer, and
//! the share of lateral acceleration turning with it, which says which
//! channel a reversal is in (ay = u·r in a steady turn: an `ay` with the
//! steer and a yaw rate against it is a yaw rate of the other sign),
//! and the samples' median speed, which the limits on the ratio fall
//! with (an understeering car's is `1/(1 + K·u²/l)`:
//! `measured/least_gain.rs`). Units: SI, rad, m/s.

use crate::measured::MeasuredRun;

/// A run's yaw rate against a neutral car's where its steer is held
/// ([`yaw_per_neutral`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct YawPerNeutral {
    /// The median of `r·l/(u·δ)`.
    pub median: f64,
    /// The held steered samples it is taken over.
    pub samples: usize,
    /// Their median speed, m/s: a car's ratio falls with it (the limits
    /// it is judged by: `measured/least_gain.rs`).
    pub speed: f64,
    /// Their share whose yaw rate turns with the steer (`r·δ > 0`).
    pub with_steer: f64,
    /// Their share whose yaw rate turns against it (`r·δ < 0`).
    pub against: f64,
    /// The one value the yaw rate holds over all of them, if it holds one
    /// (a sensor frozen after the step), rad/s.
    pub one_value: Option<f64>,
    /// Their share whose lateral acceleration turns with the steer
    /// (`ay·δ > 0`), where the run has `ay`: which of steer and yaw rate
    /// a reversal is in.
    pub ay_with_steer: Option<f64>,
}

impl YawPerNeutral {
    /// The share of `samples` of `run` whose `ay` has the steer's sign
    /// (None without `ay`).
    pub(super) fn ay_with_steer(run: &MeasuredRun, samples: &[usize]) -> Option<f64> {
        let ay = run.ay.as_ref()?;
        let with = samples
            .iter()
            .filter(|&&i| ay[i] * run.steer[i] > 0.0)
            .count();
        (!samples.is_empty()).then(|| with as f64 / samples.len() as f64)
    }
}
