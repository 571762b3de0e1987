//! A `bank` column in degrees read as radians: a body-fixed accelerometer
//! reads `a_y = u·r + d(u·β)/dt + g·sin(bank) + b_ay` (ISO 8855,
//! `FORMATS.md` signs), so the run's `ay` beside its kinematic lateral
//! acceleration says which unit the logged bank acts in. Read in radians, a
//! bank of 0.5 (meaning 0.5°) is 28.6° and takes g·sin(0.5) = 4.7 m/s² out
//! of every sample: the calibration then reads a −4.4 m/s² accelerometer
//! offset. Only a bank that holds through the run is judged so: a varying
//! one's share of `ay` stands apart from the offset (0 where the car does
//! not feel the logged bank, which is no unit slip). Judged by `io/run_bank.rs`. Units: m/s², rad.

use super::number::Num;
use crate::format::fixed;
use thiserror::Error;

/// The numbers of the refusal.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("column `bank`: {} read in radians is {}°, whose g·sin(bank) this run's `ay` does not show: over {bins} half-second means, `ay` − speed × yaw_rate{} − g·sin(bank) has a median of {} m/s² (an accelerometer offset beyond the ±{} m/s² of any sensor on its mount), where with the bank in degrees it is {} m/s²; the bank holds through the run (g·sin(bank) varies by {} m/s², standard deviation, under the {} m/s² that would tell its share of `ay` from an offset): angles are in radians (FORMATS.md); is the column in degrees? Convert it, or say so: `degrees = [\"bank\"]` under [runs] in a campaign or a replay's [manoeuvre]; if the road under the car is not banked so (another track's or a survey's bank), leave the column out", Num(*value), fixed(value.to_degrees(), 1), if *with_beta { " − d(speed·beta)/dt" } else { "" }, fixed(*as_radians, 2), Num(*plausible), fixed(*as_degrees, 2), fixed(*spread, 2), Num(*varies))]
pub struct BankInDegrees {
    /// The bank at the row named, as read.
    pub value: f64,
    /// The median ay offset the bank in radians implies, m/s².
    pub as_radians: f64,
    /// The median ay offset the bank in degrees implies, m/s².
    pub as_degrees: f64,
    /// The largest accelerometer offset taken as one, m/s².
    pub plausible: f64,
    /// The standard deviation of g·sin(bank), the bank read in radians,
    /// over the means, m/s².
    pub spread: f64,
    /// The least such spread at which the bank's share is fitted apart
    /// from the offset (and the unit not judged), m/s².
    pub varies: f64,
    /// The half-second means judged.
    pub bins: usize,
    /// Whether the d(u·β)/dt term was removed (a `beta` column).
    pub with_beta: bool,
}
