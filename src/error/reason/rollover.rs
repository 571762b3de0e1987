//! The refusal of a steady lateral acceleration a car cannot hold on four
//! wheels ([`ParamReason::BeyondRollover`]): a rigid car's inner wheels
//! lift where the load transfer m·ay·h/t takes all of their load m·g/2,
//! at ay = g·t/(2h), the static stability factor t/(2h) in g (NHTSA's
//! rollover resistance rating; Gillespie (1992), *Fundamentals of Vehicle
//! Dynamics*, ch. 9). On the narrower track, whose axle lifts first. The
//! 2-DOF model keeps every wheel on the road, so a step steer sized for
//! such an acceleration would be simulated as if the car did not tip.
//! Units: m/s², m; the sign of ay (left or right turn) does not matter.

use super::ParamReason;
use crate::format::rounded;

/// What [`ParamReason::BeyondRollover`] says, boxed.
#[derive(Debug, Clone, PartialEq)]
pub struct Rollover {
    /// g·t/(2h), m/s².
    pub threshold: f64,
    /// The narrower track t, m.
    pub track: f64,
    /// The centre-of-gravity height h, m.
    pub cg_height: f64,
}

impl Rollover {
    /// The threshold of a car of tracks `front` and `rear` and centre of
    /// gravity `cg_height` high.
    pub fn of(front: f64, rear: f64, cg_height: f64) -> Self {
        let track = front.min(rear);
        Self {
            threshold: crate::constants::G * track / (2.0 * cg_height),
            track,
            cg_height,
        }
    }

    /// Whether a steady `ay` (either sign) is at or beyond it.
    pub fn reached_by(&self, ay: f64) -> bool {
        ay.abs() >= self.threshold
    }
}

impl From<Rollover> for ParamReason {
    fn from(r: Rollover) -> Self {
        ParamReason::BeyondRollover(Box::new(r))
    }
}

/// The message of [`ParamReason::BeyondRollover`].
pub(super) fn beyond_rollover(r: &Rollover) -> String {
    format!(
        "at or beyond the rollover threshold g·t/(2h) = 9.80665 × {} / (2 × {}) = {} m/s² ({} g; t the narrower track, h the cg_height): the inner wheels would lift before the car reached it, and the 2-DOF model keeps all four on the road; ask for less",
        rounded(r.track, 4),
        rounded(r.cg_height, 4),
        rounded(r.threshold, 4),
        rounded(r.threshold / crate::constants::G, 3),
    )
}
