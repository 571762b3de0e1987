//! What a measured run holds besides the manoeuvre: standstills, crawling
//! and the glitches of real loggers (`FORMATS.md`), found, treated and
//! listed before any replay or score.
//!
//! - Time gaps split a run (a replay cannot bridge a dropout): an interval
//!   longer than five times the median interval on each side of it
//!   (`gaps.rs`; a change of the logger's rate is no gap).
//! - Holes shorter than a gap (rows dropped: every third row of a 100 Hz
//!   log missing) do not split it: the replay runs across them and scores
//!   the rows present. They are counted per run and said, with the regular
//!   pattern they make where there is one (`holes.rs`), never as "0 time
//!   gaps" alone.
//! - Glitches are found on every sample of the driving and response channels
//!   (steer, speed; yaw rate, ay, beta) with robust statistics of the
//!   channel itself. Its scale is `σ_d = 1.4826·MAD(Δx)`, the robust spread
//!   of the sample-to-sample differences (white noise of deviation s gives
//!   `σ_d = √2·s`; a smooth signal gives its typical change per sample), with
//!   a floor of [`RANGE_FLOOR`] of the channel's 1–99 % range for noise-free
//!   channels. The detection threshold is `T = max(K·σ_d, floor)`, K =
//!   [`SPIKE_MADS`].
//!   - zero read: one to [`MAX_ZERO_RUN`] samples read as exactly 0 while the
//!     two samples on each side (on the one side at an end of the run) lie
//!     beyond T, all with one sign;
//!   - isolated spike: a sample beyond T from the line through its two
//!     neighbours, on the same side of both, while the neighbours agree with
//!     each other better than with it, and its neighbours bend back
//!     against its own bend (a step has one side only; a peak of a smooth
//!     signal stays well inside T, and one sampled coarsely, a step's
//!     sideslip hump at 25 Hz, bends one way over three samples);
//!   - stuck value: a value held exactly for at least [`MIN_STUCK`] samples
//!     where the chance of such a hold, `n·p0^(L−1)` with p0 the channel's
//!     share of zero differences, is below 1e-3 (a quantised or noise-free
//!     channel holds values by nature and is never called stuck), and
//!     only where the channel beside the hold moves by more than its
//!     resolution (1.5 times its smallest non-zero difference there) on at
//!     least half its samples. What separates a stuck logger from a
//!     settled response is the noise: a logger that stops updating cuts a
//!     channel that was moving by several steps of its resolution on every
//!     sample; a settled noise-free response (a simulation written to 9
//!     significant digits) creeps to its value by its last digit, and a
//!     quantised channel whose noise is below its step dithers by one
//!     count, and both then hold for as long as the response stays within
//!     a step — no stuck sensor; nor is a response channel's hold that
//!     it approached smoothly while the other responses are steady over
//!     it (`settled.rs`: a noise-free step logged at 20 Hz); nor is a
//!     steer's hold whose repair stays within the steer's quantum, or
//!     over which neither the car's curvature leaves what the held level
//!     explains nor the steer's trend would have crossed three quanta
//!     (`steer_hold.rs`: a quantised steer held in a steady corner);
//!   - the noise of a quantised channel (more than 1 % of its successive
//!     samples equal) is at least its step/√12, so `σ_d` is at least
//!     step/√6: a sample one count from its neighbours is no spike.
//!   - a speed read as exactly 0 for at most [`MAX_ZERO_RUN`] samples
//!     between samples at `min_speed` or faster, from which no car could
//!     have stopped within one interval nor started again within one
//!     (beyond 1.5 g both ways, `speed_dropout.rs`), is a zero read too,
//!     found before the slow spans, which it would otherwise split;
//! - Inputs that drive the replay (steer, speed) are repaired by linear
//!   interpolation in time across the glitch, so the replay is not kicked;
//!   in response channels (yaw rate, ay, beta) the sample is masked: left out
//!   of fits and scores.
//! - Samples slower than `min_speed` (a standstill when the car stands,
//!   below [`STANDSTILL_SPEED`], over at least half the span; else a crawl,
//!   a climb from rest among them) are excluded: the model is a
//!   driving model, and at a standstill its output chatters on sensor noise.
//!   The moving pieces they leave are replayed separately; in a diagnosis
//!   pieces shorter than [`MIN_RUN_SECONDS`] or [`MIN_RUN_SAMPLES`] are
//!   dropped; a single replay or the metrics of a run take its longest
//!   piece and list the others as dropped.
//!
//! Everything found, excluded or dropped is in the [`CleaningReport`].
//! Units: SI, rad, times in s.
//!
//! Layout: this file holds the thresholds and the settings; `report.rs` the
//! report types; `glitches.rs` the detection and treatment of glitches in
//! one channel; `gaps.rs` the time gaps; `holes.rs` the holes in time shorter than a gap
//! (rows dropped), `missing.rs` how they are reported; `steer_hold.rs` whether a steer's hold is
//! stuck; `pieces.rs` the slow spans and pieces, and the
//! cleaning entry points; `inject.rs` glitches injected for tests.

mod cut_by_gap;
mod gaps;
mod glitches;
mod held;
pub(crate) mod holes;
mod inject;
mod missing;
mod moves;
mod pieces;
mod repair;
mod report;
mod settled;
mod slow;
mod speed_dropout;
mod steer_hold;
#[cfg(test)]
mod test_signals;

pub(crate) use gaps::gapless;
pub use glitches::treat_glitches;
pub(crate) use glitches::{median, median_interval, midpoint_median, quantile};
pub use held::treat_held;
pub use inject::inject_glitches;
pub use missing::ReadAcross;
pub use pieces::{
    clean_for_metrics, clean_run, clean_runs, clean_single, clean_single_reported,
    clean_single_with, fill_masked, fill_masked_by_channel, segments, slice, source_file,
};
pub use report::{
    CleaningReport, Glitch, GlitchCounts, GlitchKind, HeldChannel, Piece, RunChannel, SlowKind,
    SlowSpan, Treatment,
};

/// Shortest run a diagnosis accepts, s: a step response needs its
/// pre-input window, rise and settling.
pub const MIN_RUN_SECONDS: f64 = 2.0;

/// Fewest samples a run must have.
pub const MIN_RUN_SAMPLES: usize = 20;

/// Default lowest speed of a replayed sample, m/s.
pub(crate) const DEFAULT_MIN_SPEED: f64 = 5.0;
/// The channels searched for holds and glitches: the replay's inputs and
/// its responses.
const SEARCHED: [RunChannel; 5] = [
    RunChannel::Steer,
    RunChannel::Speed,
    RunChannel::YawRate,
    RunChannel::Ay,
    RunChannel::Beta,
];

/// Below this speed a slow span is a standstill rather than a crawl, m/s.
pub(crate) const STANDSTILL_SPEED: f64 = 0.5;
/// Spike and zero-read threshold in robust deviations of the differences.
pub(crate) const SPIKE_MADS: f64 = 10.0;
/// Threshold floor as a share of the channel's 1–99 % range.
pub(crate) const RANGE_FLOOR: f64 = 0.02;
/// Longest run of zeros still called a zero read.
pub(crate) const MAX_ZERO_RUN: usize = 10;
/// Fewest samples of an exact hold called stuck.
pub(crate) const MIN_STUCK: usize = 5;
/// Samples on each side of a hold that show how the channel moves there.
pub(crate) const STUCK_CONTEXT: usize = 10;
/// A time gap: this many of the median sample intervals around it.
pub(crate) const GAP_INTERVALS: f64 = 5.0;

/// Cleaning settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CleanSettings {
    /// Lowest speed replayed, m/s.
    pub min_speed: f64,
    /// Shortest piece kept, s.
    pub min_piece_seconds: f64,
    /// Fewest samples of a piece kept.
    pub min_piece_samples: usize,
}

impl CleanSettings {
    /// For a diagnosis: pieces must show a response
    /// ([`MIN_RUN_SECONDS`], [`MIN_RUN_SAMPLES`]).
    pub fn diagnosis(min_speed: f64) -> Self {
        Self {
            min_speed,
            min_piece_seconds: MIN_RUN_SECONDS,
            min_piece_samples: MIN_RUN_SAMPLES,
        }
    }
    /// For one replay or one set of metrics: any piece of two samples.
    pub fn single(min_speed: f64) -> Self {
        Self {
            min_speed,
            min_piece_seconds: 0.0,
            min_piece_samples: 2,
        }
    }
}

impl Default for CleanSettings {
    fn default() -> Self {
        Self::diagnosis(DEFAULT_MIN_SPEED)
    }
}
