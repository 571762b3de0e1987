//! The step-steer metrics' errors (GB/T 6323 / ISO 7401 windows on a
//! record): why a record's metrics could not be computed. Durations in s,
//! steer in rad.

use crate::format::{fixed, significant};
use thiserror::Error;

/// An angle in rad with its value in degrees: "0.0017 rad (0.10°)".
fn angle(v: f64) -> String {
    format!("{} rad ({}°)", significant(v, 2), fixed(v.to_degrees(), 2))
}

/// The sentence of [`MetricsError::NoStep`] in plain terms: where the
/// steer stays, or how little it moves, against the step it needs.
fn no_step(initial: f64, steady: f64, min: f64) -> String {
    let change = steady - initial;
    if !change.is_finite() {
        return "no steer step: the steer is not a number in the initial or steady window".into();
    }
    if change.abs() < 1e-9 {
        return format!(
            "no steer step: the steer stays at {} from the initial window to the steady one; \
             a step steer needs a change of at least {}",
            angle(initial),
            angle(min)
        );
    }
    format!(
        "no steer step: the steer goes from {} in the initial window to {} in the steady one, \
         a change of {}, less than the {} a step steer needs",
        angle(initial),
        angle(steady),
        angle(change),
        angle(min)
    )
}

/// Why the metrics could not be computed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MetricsError {
    /// Channels of different lengths or too few samples.
    #[error("a step-steer record needs at least 10 samples with equal-length channels")]
    Shape,
    /// The record is too short for the windows.
    #[error("the record ({0:.3} s) is shorter than the initial and steady windows together")]
    TooShort(f64),
    /// No steer step in the record: the steer's means in the initial and
    /// steady windows, rad, and the least change that is a step.
    #[error("{}", no_step(*initial, *steady, *min))]
    NoStep {
        /// Mean steer in the initial window, rad.
        initial: f64,
        /// Mean steer in the steady window, rad.
        steady: f64,
        /// The smallest change that counts as a step, rad.
        min: f64,
    },
    /// The steer does not cross half its step after the initial window.
    #[error("the steer never crosses half its step between the initial and steady windows")]
    NoHalfStep,
    /// A response does not change.
    #[error("the {0} does not change between the initial and steady windows")]
    NoResponse(&'static str),
    /// A response never reaches 90 % of its steady value.
    #[error("the {0} never reaches 90 % of its steady-state value")]
    NoCrossing(&'static str),
}
