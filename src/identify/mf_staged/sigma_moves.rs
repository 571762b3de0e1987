//! How a stage's σ moves after its own fit. A later stage refits
//! coefficients an earlier stage's channel reads too (the combined
//! aligning moment's `SSZ*` move the pure rows' `Mz` through their small
//! `Fx`), so the σ a stage ended its own fit and holds at (the σ its last
//! held line gives) is not always the σ of the written tyre, which its
//! line gives. Each later stage that moves it is recorded with the σ
//! after it, and the stage's line says how it got from one to the other:
//! the car205 grid with `--hold PKY4=-50` printed "σ 1.689 %" for the
//! pure Mz stage beside its QBZ2 line's "σ 1.245514 % held against
//! 1.245514 % free", with nothing to join the two. σ is % of the
//! channel's RMS over the stage's rows.

use super::params::Stage;
use super::release::sigma;
use super::{MfRow, StageReport};
use crate::tyre::mf::MagicFormula;
use serde::Serialize;

/// A later stage that moved an earlier stage's σ, and the σ after it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SigmaMove {
    /// The later stage whose fit moved it.
    pub by: Stage,
    /// The earlier stage's σ after it, %.
    pub sigma_percent: f64,
}

/// The change of σ, relative to itself, below which a later stage is
/// not said to move it: a thousandth, what the printed three decimals
/// of a σ of 1 % show (MFeval's sample file on the book's grid: its
/// pure Mz moved from 0.039940 % to 0.039939 % by the combined Mz stage,
/// no move a reader of either line would see).
const MOVED: f64 = 1e-3;

/// Records, in each fitted report of `earlier`, the move of its σ over
/// its rows of `rows` that the tyre `t` as `stage` left it makes.
pub(super) fn record_moves(
    earlier: &mut [StageReport],
    stage: Stage,
    t: &MagicFormula,
    rows: &[MfRow],
) {
    for r in earlier.iter_mut().filter(|r| r.skipped.is_none()) {
        let last = r.sigma_moved_by.last().map(|m| m.sigma_percent);
        let Some(last) = last.or(r.sigma_own_percent) else {
            continue;
        };
        let sel: Vec<&MfRow> = rows.iter().filter(|row| r.stage.takes(row)).collect();
        let (now, ..) = sigma(r.stage, t, &sel);
        if (now - last).abs() > MOVED * last.abs() {
            r.sigma_moved_by.push(SigmaMove {
                by: stage,
                sigma_percent: now,
            });
        }
    }
}

/// The stage's σ as its line says it, and where a later stage moved it,
/// the clause its parenthesis adds: the σ its own fit and holds ended at
/// and each move, with the digits that tell them apart.
pub fn sigma_said(r: &StageReport) -> (String, String) {
    let Some(own) = r.sigma_own_percent.filter(|_| !r.sigma_moved_by.is_empty()) else {
        return (format!("σ {:.3} %", r.sigma_percent), String::new());
    };
    let mut values = vec![r.sigma_percent, own];
    values.extend(r.sigma_moved_by.iter().map(|m| m.sigma_percent));
    let shown = crate::format::fixed_apart(&values, 3);
    // Its last hold's σ held is that σ: said where it has one.
    let held = r.parameters.iter().any(|p| {
        matches!(
            p.held,
            Some(super::HoldReason::NotIdentifiable {
                hold_order: Some(_),
                ..
            })
        )
    });
    let own = if held {
        "at the end of its own fit and holds, as its last held line says"
    } else {
        "at the end of its own fit"
    };
    let moves: Vec<String> = r
        .sigma_moved_by
        .iter()
        .zip(&shown[2..])
        .map(|(m, s)| format!("{s} % after the {} stage's fit", m.by.label()))
        .collect();
    (
        format!("σ {} %", shown[0]),
        format!(
            "; {} % {own}, moved by later stages that refit coefficients its channel reads: {}",
            shown[1],
            moves.join(", then ")
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stage a later one moved says both σ and the mover; one none
    /// moved says its σ alone, as before.
    #[test]
    fn a_moved_sigma_says_where_it_ended_its_own_fit_and_what_moved_it() {
        let mut r = StageReport::skipped(
            Stage::PureMz,
            crate::error::SkipReason::TooFewRows { rows: 0, free: 0 },
        );
        (r.skipped, r.sigma_percent, r.sigma_own_percent) = (None, 1.6893, Some(1.2455));
        assert_eq!(sigma_said(&r), ("σ 1.689 %".into(), String::new()));
        r.sigma_moved_by.push(SigmaMove {
            by: Stage::CombinedMz,
            sigma_percent: 1.6893,
        });
        let (sigma, clause) = sigma_said(&r);
        assert_eq!(sigma, "σ 1.689 %");
        assert_eq!(clause, "; 1.246 % at the end of its own fit, moved by later stages that refit coefficients its channel reads: 1.689 % after the combined Mz stage's fit");
    }
}
