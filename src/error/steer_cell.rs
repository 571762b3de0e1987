//! One steer sample of a measured run beyond any angle a steer sensor
//! logs, in any unit a steer is written in (`1e308`): refused at its cell
//! (`io/run.rs`), as a speed beyond any vehicle's is. Below that limit a
//! lone spike is a glitch the cleaning repairs (a road-wheel steer logged
//! as 10 rad for one sample), and a column beyond ±90° over more than 1 %
//! of the run is refused as a unit slip (`SteerBeyondQuarterTurn`); a
//! sample of 1e10 rad or more defeated the cleaning's robust statistics
//! and was said as a steer that "does not hold its step: … at inf %"
//! (round 50). Units: rad.

use super::number::Num;
use thiserror::Error;

/// A steer sample beyond [`crate::io::ABSURD_STEER`].
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("column `steer`: {} rad is beyond ±{} rad, which no steer sensor logs in any unit a steer is written in (a road wheel turns less than 0.8 rad at full lock; a steering wheel logged in degrees stays within about ±1100): this cell is no reading of a steer, and no spike the cleaning can repair from its neighbours (it repairs a lone spike below the limit); mend or remove this row", Num(*value), Num(*limit))]
pub struct SteerBeyondAnySensor {
    /// The steer as read, rad.
    pub value: f64,
    /// The limit, rad.
    pub limit: f64,
}
