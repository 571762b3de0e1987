//! The physical ranges of an equilibrium sweep's search box (`[box]`), as
//! [`super::Limit::Sweep`] says them: `beta_max = 30` (degrees where radians
//! are read) searched a box of ±30 rad without a word. Units: rad.

use crate::format::rounded;
use thiserror::Error;

/// The largest sideslip a search box may reach, rad (90°): beyond it the
/// car runs backward, and no equilibrium of the model lies there.
pub const MAX_BOX_SIDESLIP: f64 = std::f64::consts::FRAC_PI_2;

/// Which of a search box's ranges a value left.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum SweepLimit {
    /// `beta_max`, rad, as given.
    #[error("{}", sideslip(*given))]
    Sideslip {
        /// The value as read, rad.
        given: f64,
    },
}

/// What a `beta_max` beyond 90° is refused with: the value said in degrees
/// when read as such lands inside the range.
fn sideslip(given: f64) -> String {
    let rule = "must lie in (0, 1.5708]: a sideslip beyond ±90° (1.5708 rad) is a car running backward, where the model has no equilibrium; the key is in rad";
    let rad = given.to_radians();
    if rad > 0.0 && rad <= MAX_BOX_SIDESLIP {
        format!(
            "{rule}: did you mean {} rad ({}°)?",
            rounded(rad, 4),
            rounded(given, 4)
        )
    } else {
        rule.to_string()
    }
}
