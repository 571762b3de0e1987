//! The physical ranges of an equilibrium sweep's search box (`[box]`), as
//! [`super::Limit::Sweep`] says them: `beta_max = 30` (degrees where radians
//! are read) searched a box of ±30 rad without a word. Units: rad. Also the
//! least counts of its swarm (`[pso]`): `particles = 0` ran a swarm of two
//! and `iterations = 0` no flight at all, both without a word.

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
    /// `yaw_rate_max`, rad/s, as given, beyond [`MAX_BOX_YAW_RATES`] times
    /// the largest steady yaw rate of the sweep.
    #[error("{}", yaw_rate(*given, *steady))]
    YawRate {
        /// The value as read, rad/s.
        given: f64,
        /// The largest steady yaw rate of the sweep, μ_peak·μ·g/u_min, rad/s.
        steady: f64,
    },
    /// A `[pso]` count below what the swarm needs.
    #[error("{}", swarm_count(*count))]
    SwarmCount {
        /// Which count.
        count: SwarmCount,
    },
}

/// A count of the PSO equilibrium search (`[pso]`), each with the least
/// the search needs ([`SwarmCount::least`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SwarmCount {
    /// `particles`: a ring swarm draws each particle to the best of itself
    /// and its two neighbours, so it needs three.
    Particles,
    /// `iterations`: a swarm that never moves searches only its random
    /// first positions.
    Iterations,
    /// `rounds`: no round, no search.
    Rounds,
}

impl SwarmCount {
    /// The least count the search needs.
    pub fn least(self) -> usize {
        match self {
            SwarmCount::Particles => 3,
            SwarmCount::Iterations | SwarmCount::Rounds => 1,
        }
    }
}

/// What a count below its least is refused with.
fn swarm_count(count: SwarmCount) -> String {
    let why = match count {
        SwarmCount::Particles => "the swarm is a ring, each particle drawn to the best of itself and its two neighbours, and fewer particles make no ring (0 or 1 ran as a swarm of 2 without a word)",
        SwarmCount::Iterations => "with none the swarm never moves, and its random first positions are all the search would see",
        SwarmCount::Rounds => "with none the swarm never flies, and every equilibrium would be the exact solver's alone",
    };
    format!(
        "must be at least {}: {why}; leave the key out for the default",
        count.least()
    )
}

/// How many times the largest steady yaw rate a search box may reach: no
/// equilibrium lies beyond 1 (steady, m·u·r is the tyres' lateral force,
/// at most μ_peak·μ·m·g), and a box ten times wider spreads the search over
/// a plane 99 % empty.
pub const MAX_BOX_YAW_RATES: f64 = 10.0;

/// What a `yaw_rate_max` beyond [`MAX_BOX_YAW_RATES`] steady yaw rates is
/// refused with: the value said in deg/s when read as such lands inside.
fn yaw_rate(given: f64, steady: f64) -> String {
    let limit = MAX_BOX_YAW_RATES * steady;
    let rule = format!(
        "must lie in (0, {}] rad/s: no equilibrium turns faster than μ_peak·μ·g/u_min = {} rad/s (at the slowest speed swept, the tyres' peak force on the highest friction), and a box {MAX_BOX_YAW_RATES} times that is searched almost all in vain; leave the key out for the default, 1.2 times it; the key is in rad/s",
        rounded(limit, 4),
        rounded(steady, 4)
    );
    let rad = given.to_radians();
    if rad > 0.0 && rad <= limit {
        format!(
            "{rule}: did you mean {} rad/s ({} deg/s)?",
            rounded(rad, 4),
            rounded(given, 4)
        )
    } else {
        rule
    }
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
