//! Physical constants shared by the models and the processing of measured
//! data. This module imports nothing, so that any layer (the vehicle model,
//! the measured runs, the readers) can use it without depending on another.
//!
//! Units: SI, rad. Source: the conventional value of standard gravity
//! adopted by the 3rd CGPM (1901), as in ISO 80000-3 (2019); the steepest
//! road banks: Daytona's 31°, Talladega's 33° (the tracks' published
//! figures).

/// Standard gravity, m/s².
pub const G: f64 = 9.80665;

/// The steepest road bank, rad (0.61, 35°): Daytona's banking is 31°,
/// Talladega's 33°. A scenario's `road_bank` beyond it is refused and a
/// run's `bank` column beyond it is said to be in degrees: one limit.
pub const STEEPEST_BANK: f64 = 0.61;

/// The most iterations a user's cap may give a stage of the staged Magic
/// Formula fit: a stage that converges does so in tens to hundreds (the
/// default 150 is continued to 50 per free parameter), and each iteration
/// replays every row.
pub const MOST_STAGE_ITERATIONS: usize = 10_000;

/// The longest simulated run, s (100,000 s, 27.8 h): a history holds
/// 2,000,000 rows after its first (`io::MAX_ROWS`), one every output step
/// of at most 0.05 s. A manoeuvre's `end` beyond it is refused at its key
/// (1e9 s was refused as below its lower limit only; up to 1e6 s passed
/// on to the rows' refusal, which asked for a step no scenario may set).
pub const LONGEST_RUN: f64 = 1e5;

/// The highest inflation pressure a tyre is tested or evaluated at, Pa
/// (5 MPa): above any pneumatic tyre's (a car's 200–300 kPa, a truck's
/// up to 1 MPa, a track bicycle's 1.4 MPa). `tyre-eval` refuses a point's
/// pressure above it and `identify` a rig file's: one limit, so that no
/// file `identify` writes from such a column reads back without a word.
pub const MOST_PRESSURE: f64 = 5e6;
