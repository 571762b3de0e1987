//! The slow spans of a measured run (below `min_speed`: a standstill, a
//! crawl, a stretch reversing) and how the terminal says them. Speeds in
//! m/s (ISO 8855: forward positive), times in s.

use crate::format::plural;
use serde::Serialize;

/// Why a slow span was excluded.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SlowKind {
    /// The car stood in it (below 0.5 m/s over at least half its samples).
    Standstill,
    /// The car moved below the minimum speed for most of the span: a
    /// crawl, or a climb from rest.
    Crawl,
    /// The car moved backwards (below −0.5 m/s) over more than half the
    /// span: the model drives forwards only (ISO 8855 x forward), so it is
    /// excluded as the slow spans are.
    Reversing,
}

/// A span of samples below the minimum speed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SlowSpan {
    /// The run.
    pub run: String,
    /// First excluded sample, s.
    pub t_start: f64,
    /// Last excluded sample, s.
    pub t_end: f64,
    /// Samples excluded.
    pub samples: usize,
    /// Highest speed in the span, m/s.
    pub max_speed: f64,
    /// Lowest speed in the span, m/s (negative where the car reversed).
    pub min_speed: f64,
    /// Standstill, crawl or reversing.
    pub kind: SlowKind,
}

impl SlowKind {
    /// Name in reports.
    pub fn name(self) -> &'static str {
        match self {
            SlowKind::Standstill => "standstill",
            SlowKind::Crawl => "crawl",
            SlowKind::Reversing => "reversing",
        }
    }
}

/// A slow span as the terminal says it.
pub(super) fn slow_line(s: &SlowSpan, min_speed: f64) -> String {
    format!(
        "{} {:.2}–{:.2} s in {} ({}, {}) excluded",
        s.kind.name(),
        s.t_start,
        s.t_end,
        s.run,
        plural(s.samples, "sample", "samples"),
        why_slow(s.kind, (s.max_speed, s.min_speed), min_speed)
    )
}

/// Why a slow span (or a row of them) whose speeds lie in `(max, min)`
/// is excluded.
fn why_slow(kind: SlowKind, (max, min): (f64, f64), min_speed: f64) -> String {
    let threshold = min_speed;
    let min_speed = crate::format::rounded(min_speed, 4);
    match kind {
        // Truncated: a car backing at 3.004 m/s did not reach 3.01.
        SlowKind::Reversing => format!(
            "backwards at up to {:.2} m/s: the model drives forwards only, from min_speed = {min_speed} m/s",
            (-min * 100.0).floor() / 100.0
        ),
        // A speed flickering across the threshold for a sample or two
        // between slow ones joins the span (`pieces::FLICKER_SAMPLES`):
        // its top speed is then at or above min_speed, and said so.
        _ if max >= threshold => format!(
            "below min_speed = {min_speed} m/s but for flickers across it between slow samples, up to {:.2} m/s, counted with the span",
            (max * 100.0).ceil() / 100.0
        ),
        // Truncated: a span below 5 m/s must not read "at most 5.00".
        _ => format!(
            "at most {:.2} m/s, below min_speed = {min_speed} m/s",
            (max * 100.0).floor() / 100.0
        ),
    }
}

/// Alike slow spans in a row (one run and kind) in one line.
pub(super) fn slows_line(row: &[SlowSpan], min_speed: f64) -> String {
    let (s, last) = (&row[0], &row[row.len() - 1]);
    let samples: usize = row.iter().map(|s| s.samples).sum();
    let top = row.iter().fold(0.0_f64, |m, s| m.max(s.max_speed));
    let low = row.iter().fold(0.0_f64, |m, s| m.min(s.min_speed));
    format!(
        "{} in {}: {} spans, the first {:.2}–{:.2} s, the last {:.2}–{:.2} s ({}, {}) excluded",
        s.kind.name(),
        s.run,
        row.len(),
        s.t_start,
        s.t_end,
        last.t_start,
        last.t_end,
        plural(samples, "sample", "samples"),
        why_slow(s.kind, (top, low), min_speed)
    )
}
