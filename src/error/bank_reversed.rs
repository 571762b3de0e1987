//! A `bank` column logged in the other sign: a body-fixed accelerometer
//! reads `a_y = u·r + d(u·β)/dt + g·sin(bank) + b_ay` with the bank
//! positive where the left edge is higher (ISO 8855, `FORMATS.md`), so a
//! logger whose convention is the right edge higher gives a column whose
//! `g·sin(bank)` the run's `ay` shows with the other sign. Read as logged,
//! the run then looks like a unit slip (a held bank's offset beyond any
//! mounted sensor's, "in degrees?"; a bank that follows the turns pulls
//! the slope of `ay` on the kinematic acceleration to 0.5, "mph?"); read
//! reversed, it is a car's. Judged by `io/run_bank.rs`. Units: m/s², rad.

use super::number::Num;
use crate::format::fixed;
use thiserror::Error;

/// The numbers of the refusal, by the check that found it.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum BankReversed {
    /// A bank that holds through the run: the offset each reading implies.
    #[error("column `bank`: the bank column's sign looks reversed: over {bins} half-second means, `ay` − speed × yaw_rate{} − g·sin(bank) has a median of {} m/s² with the bank as logged (an accelerometer offset beyond the ±{} m/s² of any sensor on its mount) and {} m/s² with the bank in degrees, while with its sign reversed it is {} m/s², the smallest: the accelerometer feels this bank with the other sign; bank is positive with the left edge higher (FORMATS.md, ISO 8855): negate the column", if *with_beta { " − d(speed·beta)/dt" } else { "" }, fixed(*as_logged, 2), Num(*plausible), fixed(*as_degrees, 2), fixed(*as_reversed, 2))]
    Held {
        /// The median ay offset the bank as logged implies, m/s².
        as_logged: f64,
        /// The same with the bank in degrees, m/s².
        as_degrees: f64,
        /// The same with the bank's sign reversed, m/s².
        as_reversed: f64,
        /// The largest accelerometer offset taken as one, m/s².
        plausible: f64,
        /// The half-second means judged.
        bins: usize,
        /// Whether the d(u·β)/dt term was removed (a `beta` column).
        with_beta: bool,
    },
    /// A bank that follows the turns: the slope of `ay` on the kinematic
    /// lateral acceleration with each reading, through the origin.
    #[error("column `bank`: the bank column's sign looks reversed: over {bins} half-second means of the run turning at speed, `ay` regressed on speed × yaw_rate{beta} + g·sin(bank) has a slope of {} (R² {}) with the bank as logged, {} (R² {}) without the bank, and {} (R² {}) with its sign reversed, the best fit and a car's slope (about 1, between {} and {} with body roll): the accelerometer feels this bank with the other sign, and no unit is wrong; bank is positive with the left edge higher (FORMATS.md, ISO 8855): negate the column", fixed(*slope, 3), fixed(*r2, 3), fixed(*without, 3), fixed(*without_r2, 3), fixed(*reversed, 3), fixed(*reversed_r2, 3), Num(range.0), Num(range.1), beta = if *with_beta { " + d(speed·beta)/dt" } else { "" })]
    Slope {
        /// The slope with the bank as logged.
        slope: f64,
        /// Its R².
        r2: f64,
        /// The slope without the bank term.
        without: f64,
        /// Its R².
        without_r2: f64,
        /// The slope with the bank's sign reversed.
        reversed: f64,
        /// Its R².
        reversed_r2: f64,
        /// A car's slopes.
        range: (f64, f64),
        /// The turning half-second means fitted.
        bins: usize,
        /// Whether the d(u·β)/dt term is in the regressor (a `beta` column).
        with_beta: bool,
    },
}
