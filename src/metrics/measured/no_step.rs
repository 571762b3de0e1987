//! Why a measured run gives no metrics, said from its cleaning: no
//! sample moving at `min_speed` or faster, or pieces that moved but whose
//! steer made no step (each with its span in s and why), with the time
//! gaps the cleaning split the run at; a piece that starts at a gap's end
//! with the wheels turned is said to start after its step, cut by the hole.

use crate::error::{GapAt, InputProblem, MetricsError, PieceRefusal, RefusedPiece};
use crate::measured::clean::{CleaningReport, GlitchKind, Piece};
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
    let gaps: Vec<(f64, f64)> = cleaning
        .glitches
        .iter()
        .filter(|g| g.kind == GlitchKind::TimeGap)
        .map(|g| (g.t, g.value))
        .collect();
    let pieces = cleaning
        .dropped_pieces
        .iter()
        .filter_map(|p| {
            let reason = p.reason.clone()?;
            Some(RefusedPiece {
                // A piece named as the file is the whole run.
                name: (p.name != whole).then(|| p.name.clone()),
                t_start: p.t_start,
                t_end: p.t_end,
                reason: after_gap(reason, p, &gaps),
            })
        })
        .collect();
    InputProblem::NoSteerStep { pieces, gaps }
}

/// The reason of piece `p` where it starts at the end of one of the time
/// `gaps` (start, length, s) with the wheels turned: its step lies before
/// the hole, and "start the record before the steer moves" (the advice
/// for a record cut after its step) is wrong where the record does. Else
/// `reason`.
fn after_gap(reason: PieceRefusal, p: &Piece, gaps: &[(f64, f64)]) -> PieceRefusal {
    let PieceRefusal::NoStepMetrics(MetricsError::NoStep {
        initial,
        steady,
        min,
        ..
    }) = reason
    else {
        return reason;
    };
    let dt = (p.t_end - p.t_start) / p.samples.saturating_sub(1).max(1) as f64;
    let turned = initial.abs() >= min && (steady - initial).abs() < min;
    match gaps
        .iter()
        .find(|(t, length)| (t + length - p.t_start).abs() <= 0.5 * dt)
    {
        Some(&(from, length)) if turned => PieceRefusal::StartsTurnedAtGap {
            turned: initial,
            gap: GapAt {
                from,
                to: from + length,
                missing: ((length / dt).round() as usize).saturating_sub(1),
            },
        },
        _ => reason,
    }
}
