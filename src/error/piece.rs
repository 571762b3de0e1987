//! The moving pieces of a measured run that were not used, and why: what
//! [`InputProblem::NoSteerStep`] lists. A run that is one piece, all its
//! samples, is the file the error already names, so its piece goes
//! unnamed and the message says the file once.
//!
//! [`InputProblem::NoSteerStep`]: super::InputProblem::NoSteerStep

use super::reason::angle;
use super::MetricsError;
use crate::format::rounded;
use thiserror::Error;

/// A moving piece of a run that was not used, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct RefusedPiece {
    /// The piece's name (`file#k`); `None` when it is the whole run, which
    /// the error's file names.
    pub name: Option<String>,
    /// Its first time, s.
    pub t_start: f64,
    /// Its last time, s.
    pub t_end: f64,
    /// Why it was not used.
    pub reason: PieceRefusal,
}

/// Why a moving piece of a run was not used (the cleaning report's reason
/// for dropping it).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PieceRefusal {
    /// Shorter than a piece must be to be replayed or measured.
    #[error("too short")]
    TooShort,
    /// Another piece of the run was used (a single use takes one).
    #[error("another piece was used")]
    AnotherPieceUsed,
    /// A replay's piece whose steer stays between `from` and `to` (a
    /// range less than `min`, a step's worth) while another piece of the
    /// run moves it: the piece that moves it is replayed, the longest
    /// otherwise. Rad.
    #[error("{} while another piece moves it, and that piece is replayed; to replay this one, cut the run file to its span", steer_held(*from, *to, *min))]
    SteerHeld {
        /// The steer's least value in the piece, rad.
        from: f64,
        /// Its largest, rad.
        to: f64,
        /// The least range that moves the steer, rad.
        min: f64,
    },
    /// The part of a run after its first steer step, holding the later
    /// steps (a return, a step on a step) that start at `at`, s: the
    /// metrics read the first step alone.
    #[error("it holds {} (at {}): the metrics read the first step", if at.len() == 1 { "a later steer step" } else { "later steer steps" }, at.iter().map(|t| format!("{t:.2} s")).collect::<Vec<_>>().join(", "))]
    LaterSteps {
        /// The later steps' times, s.
        at: Vec<f64>,
    },
    /// The piece gives no step-steer metrics.
    #[error("no step-steer metrics ({0})")]
    NoStepMetrics(MetricsError),
    /// Too short because a time gap ends it after its steer moved: what the
    /// piece after the hole lacks (`measured::clean::cut_by_gap`).
    #[error("too short ({} s, under the {} s a piece needs), because a time gap ends it ({gap}): it holds {} s of running before the steer moves at {} s (by {}) and the first {} s of the response, which the piece after the hole starts without; to keep them, {FILL}", rounded(*length, 3), rounded(*least, 3), rounded(*before, 3), rounded(*moves_at, 3), angle(*change), rounded(gap.from - moves_at, 3))]
    CutByGap {
        /// The piece's length and the least a piece needs, s.
        length: f64,
        /// The least length a piece needs, s.
        least: f64,
        /// Running before the steer moves, s.
        before: f64,
        /// When the steer moves, s.
        moves_at: f64,
        /// How far it moves within the piece, rad.
        change: f64,
        /// The gap that ends the piece.
        gap: GapAt,
    },
    /// A piece that starts where a time gap ends with the wheels already
    /// turned: the step lies before the hole and the hole cuts its
    /// response (`metrics`), rad.
    #[error("it starts where a time gap ends ({gap}) with the wheels already turned by {}: its steer step lies before the hole, which cuts the step's response; to measure the step across the hole, {FILL}", angle(*turned))]
    StartsTurnedAtGap {
        /// The steer held at the piece's start, rad.
        turned: f64,
        /// The gap before it.
        gap: GapAt,
    },
}

/// The steer of a piece held between `from` and `to` (rad), less than
/// the `min` a step moves it by: said by where it is held and how far it
/// moves, each number with the digits that tell it from the others ("its
/// steer stays within 0 rad" read as a steer at 0 for one held at 0.010
/// rad).
fn steer_held(from: f64, to: f64, min: f64) -> String {
    let moved = crate::format::readable_apart(&[to - from, min], 2);
    if from == to {
        return format!(
            "its steer holds at {} rad throughout (it does not move; a step moves it by {} rad or more)",
            crate::format::readable(from, 2),
            moved[1]
        );
    }
    let range = crate::format::readable_apart(&[from, to], 2);
    format!(
        "its steer stays between {} and {} rad (it moves by {} rad, less than the {} rad of a step)",
        range[0], range[1], moved[0], moved[1]
    )
}

/// What to do with a hole that cuts a step: the advice of [`PieceRefusal::CutByGap`] and
/// [`PieceRefusal::StartsTurnedAtGap`].
const FILL: &str = "fill the hole in the file (interpolate the missing samples) and say so where the results are used";

/// A time gap that split a run: from the last sample before it to the
/// first after, s, and the samples missing at the run's interval.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GapAt {
    /// The last sample before the gap, s.
    pub from: f64,
    /// The first sample after it, s.
    pub to: f64,
    /// Samples missing in it.
    pub missing: usize,
}

impl std::fmt::Display for GapAt {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "no rows {:.3}–{:.3} s, {}",
            self.from,
            self.to,
            crate::format::plural(self.missing, "sample missing", "samples missing")
        )
    }
}

/// The message of a run none of whose `pieces` holds a steer step: each
/// piece by name, span and reason, and the time `gaps` (start, length, s)
/// that split the run into them (a step cut by a gap reads as two pieces
/// without one, which only the gap explains); a run that is one unnamed
/// piece by its reason alone (its span is the file's).
pub(super) fn no_steer_step(pieces: &[RefusedPiece], gaps: &[(f64, f64)]) -> String {
    if let [RefusedPiece {
        name: None,
        t_start,
        t_end,
        reason,
    }] = pieces
    {
        return match reason {
            PieceRefusal::TooShort => {
                format!("no step-steer metrics (the run, {t_start:.2}–{t_end:.2} s, is too short)")
            }
            PieceRefusal::NoStepMetrics(_) => reason.to_string(),
            PieceRefusal::CutByGap { .. } | PieceRefusal::StartsTurnedAtGap { .. } => {
                format!("no step-steer metrics: {reason}")
            }
            PieceRefusal::AnotherPieceUsed
            | PieceRefusal::SteerHeld { .. }
            | PieceRefusal::LaterSteps { .. } => {
                format!("no step-steer metrics ({reason})")
            }
        };
    }
    let each: Vec<String> = pieces
        .iter()
        .map(|p| {
            let name = p.name.as_deref().unwrap_or("the run");
            format!("{name} ({:.2}–{:.2} s): {}", p.t_start, p.t_end, p.reason)
        })
        .collect();
    let split = match gaps {
        [] => String::new(),
        _ => {
            let at: Vec<String> = gaps
                .iter()
                .map(|(t, dt)| format!("{t:.3}–{:.3} s", t + dt))
                .collect();
            format!(
                " (the run is split where its clock jumps: no rows {})",
                at.join(", ")
            )
        }
    };
    format!(
        "no moving piece holds a steer step: {}{split}",
        each.join("; ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A piece held at 0.010 rad was said to stay "within 0 rad": the
    /// sentence says where the steer is held, and a span just under a
    /// step's is not printed as the step.
    #[test]
    fn a_held_steer_is_said_where_it_is_held_never_as_zero() {
        let held = |from, to| {
            PieceRefusal::SteerHeld {
                from,
                to,
                min: 0.00017,
            }
            .to_string()
        };
        let at = held(0.01, 0.01);
        assert!(at.starts_with("its steer holds at 0.010 rad throughout (it does not move; a step moves it by 0.00017 rad or more)"), "{at}");
        let near = held(0.01, 0.010169);
        assert!(near.starts_with("its steer stays between 0.0100 and 0.0102 rad (it moves by 0.000169 rad, less than the 0.000170 rad of a step)"), "{near}");
    }
}
