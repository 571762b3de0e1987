//! Why a measured piece ends at a time gap, said where the run goes on
//! after it: a hole of more than [`GAP_INTERVALS`] sample intervals splits
//! a run (the metrics chapter of the book; `diagnose` splits alike), so
//! that no response is measured across samples the logger never wrote,
//! and each piece is measured alone. A user's 100 Hz run with 5 samples
//! missing 2 s after its step lost the 5 s after the hole (62 % of the
//! run) and cut its total-variance window, with only the cleaning's
//! "split" and "dropped" lines to say so. Times in s.

use crate::measured::clean::{CleaningReport, GlitchKind, GAP_INTERVALS};

/// The warning on a measured piece that ends (at `t_end`, s) where a time
/// gap of `report` starts, the run going on after it: the gap, the rule,
/// what was lost, and how to keep it. `dt` is the run's median sample
/// interval (s).
pub(super) fn piece_ended_by_gap(report: &CleaningReport, t_end: f64, dt: f64) -> Option<String> {
    let gap = report
        .glitches
        .iter()
        .find(|g| g.kind == GlitchKind::TimeGap && (g.t - t_end).abs() <= 0.5 * dt)?;
    let after: Vec<_> = report
        .dropped_pieces
        .iter()
        .filter(|p| p.t_start >= gap.t + gap.value - 0.5 * dt)
        .collect();
    let samples: usize = after.iter().map(|p| p.samples).sum();
    let lost = match samples {
        0 => String::new(),
        n => format!(
            " (here the {} s after it were dropped, {} of the {} samples read, {} %: a piece is measured only where it holds a steer step)",
            crate::format::rounded(after.iter().map(|p| p.t_end - p.t_start).sum::<f64>(), 3),
            n,
            report.samples_read,
            (100.0 * n as f64 / report.samples_read.max(1) as f64).round()
        ),
    };
    let missing = ((gap.value / dt).round() as i64 - 1).max(0);
    Some(format!(
        "the measured piece ends at {:.3} s where a time gap of {} s ({missing} samples missing at the log's {} s interval) splits the run: a hole longer than {GAP_INTERVALS} intervals is not interpolated, so that nothing is measured across samples the logger never wrote, and the piece after it is measured alone{lost}; to measure across the hole, fill it in the file (interpolate the missing samples) and say so where the results are used",
        t_end,
        crate::format::rounded(gap.value, 3),
        crate::format::rounded(dt, 3),
    ))
}
