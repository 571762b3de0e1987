//! Why a campaign's key is wrong for the campaign it is in: a Magic
//! Formula named as the rig model ([`StagedMagicFormula`]), a tyre model
//! named with no rig data to fit it to ([`TyreSourceError`]), a
//! `min_speed` no car is measured above. Speeds in m/s.

pub use super::staged::{GivenTyres, StagedMagicFormula, TyreSourceError};
use thiserror::Error;

/// The highest `[diagnose] min_speed` taken, m/s (360 km/h): no car's
/// handling log is measured above it, so a larger value is a speed in
/// km/h, or a slip.
pub const MAX_MIN_SPEED: f64 = 100.0;

/// Why a campaign's key is wrong for its campaign.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CampaignReason {
    /// A Magic Formula named as a campaign's rig model.
    #[error(transparent)]
    StagedMagicFormula(StagedMagicFormula),
    /// A `[tyres] model` with no rig data to fit it to.
    #[error(transparent)]
    ModelWithoutRig(TyreSourceError),
    /// A `min_speed` above [`MAX_MIN_SPEED`], m/s.
    #[error("is above {} m/s ({} km/h), faster than any car's handling log: every sample would be excluded as slow; the key is in m/s (is it in km/h? {} km/h is {} m/s)", crate::format::rounded(MAX_MIN_SPEED, 4), crate::format::rounded(MAX_MIN_SPEED * 3.6, 4), crate::format::rounded(*min_speed, 6), crate::format::rounded(*min_speed / 3.6, 3))]
    MinSpeedAbsurd {
        /// The value given, m/s.
        min_speed: f64,
    },
}
