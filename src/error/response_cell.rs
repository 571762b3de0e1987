//! One response sample of a measured run beyond anything a car does: a
//! yaw rate, lateral acceleration or sideslip no car produces (`1e308`,
//! or an `ay` of 500 m/s²), refused at its cell (`io/run_response.rs`, beside
//! a speed beyond any vehicle's), after the checks of the columns' units,
//! so that a column in another unit is named as such first. Below the
//! limits a lone spike is a glitch the cleaning masks; beyond them the
//! cleaning masked it as one ("spike at 4.980 s: ay 1e308 (1 sample,
//! masked)", round 51), a cell that is no reading said as a glitch of the
//! car. Units: rad/s, m/s², rad.

use super::number::Num;
use thiserror::Error;

/// A response channel a measured run logs, as its refusal names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Response {
    /// Yaw rate, rad/s.
    YawRate,
    /// Lateral acceleration, m/s².
    Ay,
    /// Sideslip, rad.
    Beta,
}

impl Response {
    /// The column's name in a run file.
    pub fn column(self) -> &'static str {
        match self {
            Response::YawRate => "yaw_rate",
            Response::Ay => "ay",
            Response::Beta => "beta",
        }
    }

    /// The column's unit in a run file (`FORMATS.md`).
    pub fn unit(self) -> &'static str {
        match self {
            Response::YawRate => "rad/s",
            Response::Ay => "m/s²",
            Response::Beta => "rad",
        }
    }

    /// The limit `limit` said in another unit, and what a car does: why
    /// no car reaches it.
    fn why(self, limit: f64) -> String {
        match self {
            Response::YawRate => format!(
                "{} deg/s, {} turns a second), which no car's yaw rate reaches (a car spinning out turns at about 2 rad/s",
                crate::format::fixed(limit.to_degrees(), 0),
                crate::format::readable(limit / std::f64::consts::TAU, 2),
            ),
            Response::Ay => format!(
                "{} g), which no car's lateral acceleration reaches (a road car's tyres give about 1 g, a racing car's downforce about 4–5 g for moments",
                crate::format::readable(limit / crate::constants::G, 2),
            ),
            Response::Beta => format!(
                "{} deg), which no sideslip reaches (the angle between the car's heading and its velocity lies within half a turn either way",
                crate::format::fixed(limit.to_degrees(), 0),
            ),
        }
    }
}

/// A response sample beyond any car's (`io/run_response.rs`'s
/// `absurd_limit`).
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("column `{}`: {} {} is beyond ±{} {} (±{}): this cell is no reading of the car, and no spike the cleaning can repair from its neighbours (it masks a lone spike within the limit); mend or remove this row", channel.column(), Num(*value), channel.unit(), Num(*limit), channel.unit(), channel.why(*limit))]
pub struct ResponseBeyondAnyCar {
    /// The channel.
    pub channel: Response,
    /// The sample as read, in the channel's unit.
    pub value: f64,
    /// The limit, in the channel's unit.
    pub limit: f64,
}
