//! The words of a steer-unit limit that the run's speed lowered: a car's
//! steady `r·l/(u·δ)` falls with speed as `1/(1 + K·u²/l)` (K its
//! understeer gradient, rad per m/s²), so a run judged at high speed is
//! refused (or warned of) below a smaller ratio than the fixed one, and
//! the refusal says which and why (the rule:
//! `crate::metrics::measured::least_gain`). Units: SI, rad; the gradient
//! said in °/g as engineers quote it.

use crate::format::readable;
use std::fmt;

/// A limit on `r·l/(u·δ)` lowered by the speed its samples were taken at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitAtSpeed {
    /// The limit the ratio is judged against.
    pub limit: f64,
    /// The least ratio a car gives at that speed: the most understeering
    /// one's, with the wheelbase the ratio is taken with.
    pub least: f64,
    /// The limit's share of `least` (a half for a refusal, three quarters
    /// for a warning).
    pub share: f64,
    /// The median speed of the samples judged, m/s.
    pub speed: f64,
    /// The most understeering car's gradient, rad per m/s².
    pub gradient: f64,
}

impl fmt::Display for LimitAtSpeed {
    /// `below 0.0151: half of 0.0303, the least a car understeering 6°/g
    /// gives at 90.0 m/s`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // 0.15/0.2 is 0.7499…: the share is named to a part in a million.
        let near = |x: f64| (self.share - x).abs() < 1e-6;
        let share = match self.share {
            _ if near(0.5) => "half".to_string(),
            _ if near(0.75) => "three quarters".to_string(),
            s => readable(s, 2),
        };
        let per_g = self.gradient.to_degrees() * crate::constants::G;
        write!(
            f,
            "below {}: {share} of {}, the least a car understeering {}°/g gives at {} m/s",
            readable(self.limit, 3),
            readable(self.least, 3),
            crate::format::rounded(per_g, 3),
            readable(self.speed, 3)
        )
    }
}
