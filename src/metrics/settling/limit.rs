//! What the settling words may claim of where a response's trend heads.
//! A trend is read through the steady window (its parts' means, carried
//! on as a geometric approach or, where it does not slow, by a window's
//! change: `settling::trend_of_parts`); carried on, a lateral
//! acceleration's can pass the most any car reaches on its road (round
//! 40: a step sized for 9 m/s² on friction 1 averaged 9.39 m/s² and its
//! trend was said to head 0.63 m/s² beyond, to 10.02 m/s², past the
//! 9.81 m/s² its tyres give).
//!
//! Where that limit is known (`simulate`: its tyres' peak lateral forces
//! at static load over the mass, or μ·g where a tyre has no limit of its
//! own), a trend that would pass it is said to climb toward it, with the
//! room left, never where the line goes. Where it is not (a measured
//! record: its road's friction and its tyres' peaks are unknown), a
//! rising lateral acceleration's trend is said as the window's trend
//! carried on, which the car's grip bounds, not as a value the car
//! reaches. The yaw rate and sideslip are said as before: neither is
//! bounded by the grip alone (a spinning car's yaw rate is not).
//!
//! Units: m/s² for the limit; shares of the step for the trend.

use crate::constants::G;
use std::fmt;

/// What sets a run's lateral-acceleration limit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AyLimitSource {
    /// The tyres' peak lateral forces at static load, on the road's
    /// friction, over the mass.
    Tyres,
    /// The road's μ·g: a tyre with no friction limit of its own (linear).
    Road,
}

/// The most |ay| a run can reach, m/s², and what sets it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AyLimit {
    /// The limit, m/s² (a magnitude).
    pub value: f64,
    /// What sets it.
    pub source: AyLimitSource,
}

impl AyLimit {
    /// The limit of a car of `mass` (kg) whose front and rear axles carry
    /// `loads` (N, static) on tyres of peak friction coefficients `mu` (on
    /// the road's friction): Σ μᵢ·Fzᵢ / m, the most lateral force its tyres
    /// give at once over its mass (a steady turn is bounded by the weaker
    /// axle's μᵢ·g, at most this). Where a tyre has no limit (μᵢ infinite),
    /// the road's `friction`·g.
    pub fn of_axles(mu: [f64; 2], loads: [f64; 2], mass: f64, friction: f64) -> Self {
        match mu.iter().all(|m| m.is_finite()) {
            true => AyLimit {
                value: (mu[0] * loads[0] + mu[1] * loads[1]) / mass,
                source: AyLimitSource::Tyres,
            },
            false => AyLimit {
                value: friction * G,
                source: AyLimitSource::Road,
            },
        }
    }
}

impl fmt::Display for AyLimit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.source {
            AyLimitSource::Tyres => write!(
                f,
                "the {:.2} m/s² the tyres can give on this road (their peak lateral forces at static load over the mass)",
                self.value
            ),
            AyLimitSource::Road => write!(f, "the {:.2} m/s² (μ·g) this road can give", self.value),
        }
    }
}

/// A run's lateral-acceleration limit against its steady change
/// `ay_steady` (m/s²: the step the settling's shares are of, from straight
/// running, where the lateral acceleration is nil on a flat road).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ceiling {
    /// The limit.
    pub limit: AyLimit,
    /// The lateral acceleration's steady change, m/s².
    pub ay_steady: f64,
}

impl Ceiling {
    /// The room from the steady value up to the limit, a share of the
    /// step (≤ 0 where the run is there already).
    pub fn room(&self) -> f64 {
        let steady = self.ay_steady.abs();
        (self.limit.value - steady) / steady.max(1e-12)
    }
}

/// The verb's form: "the trend heads …" or "its trend heading …".
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Verb {
    Finite,
    Participle,
}

/// Where the trend of channel `name` heads, `heads` a share of its step
/// beyond the window's mean (`rising`: above it on the step's scale),
/// said from `from` ("its steady value", "the window's mean"), bounded
/// as the module says: a rising lateral acceleration's trend that would
/// pass `ceiling` climbs toward it; without a ceiling it is the window's
/// trend carried on.
pub(super) fn trend_words(
    name: &str,
    (heads, rising): (f64, bool),
    ceiling: Option<&Ceiling>,
    (verb, from): (Verb, &str),
) -> String {
    let share = |x: f64| crate::format::significant(100.0 * x, 2);
    let (head, climb) = match verb {
        Verb::Finite => ("heads", "climbs"),
        Verb::Participle => ("heading", "climbing"),
    };
    let toward = if rising { "beyond" } else { "back below" };
    let plain = format!("{head} {} % of its step {toward} {from}", share(heads));
    if name != "lateral acceleration" || !rising {
        return plain;
    }
    match ceiling {
        None => format!(
            "{plain} (the window's trend carried on: the car's grip, which this record does not give, bounds where it ends)"
        ),
        Some(c) if heads <= c.room() => plain,
        Some(c) if c.room() > 0.0 => format!(
            "{climb} toward {}, {} % of its step above {from} (a line through the window would pass it, where no car on this road goes)",
            c.limit,
            share(c.room())
        ),
        Some(c) => format!("{climb} on beyond {}, which the run already passes", c.limit),
    }
}
