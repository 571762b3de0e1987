//! Why a measured run gives no metrics, said from its cleaning: no
//! sample moving at `min_speed` or faster, or pieces that moved but whose
//! steer made no step (each with its span in s and why), with the time
//! gaps the cleaning split the run at.

use crate::error::{InputProblem, RefusedPiece};
use crate::measured::clean::{CleaningReport, GlitchKind};
use std::path::Path;

/// The problem of the run of `path` that `cleaning` found no piece with
/// a steer step in.
pub(super) fn no_step_problem(
    cleaning: &CleaningReport,
    path: &Path,
    min_speed: f64,
) -> InputProblem {
    if cleaning.dropped_pieces.is_empty() {
        return InputProblem::NoMovingSamples {
            min_speed,
            slow: cleaning.samples_slow,
            read: cleaning.samples_read,
        };
    }
    let whole = path.display().to_string();
    let pieces = cleaning
        .dropped_pieces
        .iter()
        .filter_map(|p| {
            Some(RefusedPiece {
                // A piece named as the file is the whole run.
                name: (p.name != whole).then(|| p.name.clone()),
                t_start: p.t_start,
                t_end: p.t_end,
                reason: p.reason.clone()?,
            })
        })
        .collect();
    let gaps = cleaning
        .glitches
        .iter()
        .filter(|g| g.kind == GlitchKind::TimeGap)
        .map(|g| (g.t, g.value))
        .collect();
    InputProblem::NoSteerStep { pieces, gaps }
}
