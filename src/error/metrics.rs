//! The step-steer metrics' errors (GB/T 6323 / ISO 7401 windows on a
//! record): why a record's metrics could not be computed. Durations in s,
//! steer in rad.

use thiserror::Error;

/// Why the metrics could not be computed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MetricsError {
    /// Channels of different lengths or too few samples.
    #[error("a step-steer record needs at least 10 samples with equal-length channels")]
    Shape,
    /// The record is too short for the windows.
    #[error("the record ({0:.3} s) is shorter than the initial and steady windows together")]
    TooShort(f64),
    /// No steer step in the record.
    #[error(
        "no steer step: the steer changes by {0:.3e} rad between the initial and steady windows"
    )]
    NoStep(f64),
    /// A response does not change.
    #[error("the {0} does not change between the initial and steady windows")]
    NoResponse(&'static str),
    /// A response never reaches 90 % of its steady value.
    #[error("the {0} never reaches 90 % of its steady-state value")]
    NoCrossing(&'static str),
}
