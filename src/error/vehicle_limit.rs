//! The physical ranges of `[vehicle]` keys the other checks leave open, as
//! [`super::ParamReason::VehicleRange`] says them: `steering_ratio = 1e9`
//! was read without a word (the key is validated, not used by the 2-DOF
//! model, whose input is the road-wheel angle). Dimensionless.

use thiserror::Error;

/// The least steering ratio (steering-wheel angle / road-wheel angle): a
/// kart's direct steering is about 1.
pub const MIN_STEERING_RATIO: f64 = 1.0;

/// The largest steering ratio: a heavy truck's is about 25–30, a car's
/// 12–20; 100 holds every vehicle's with room.
pub const MAX_STEERING_RATIO: f64 = 100.0;

/// Which `[vehicle]` key's range a value left.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Error)]
pub enum VehicleLimit {
    /// The steering ratio.
    #[error("must lie in 1–100: a steering ratio is the steering-wheel angle over the road-wheel angle, about 1 on a kart, 12–20 on a car, up to about 30 on a heavy truck (is it a percentage, or an angle?)")]
    SteeringRatio,
}
