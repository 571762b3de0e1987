//! What `identify` says of the `.tir` file it writes by the checks
//! `tyre-eval` makes of a file whatever its points
//! ([`crate::jobs::tyre_eval::FileChecks`]: a pure-curve peak |F|/Fz above
//! 2.5, a longitudinal slip stiffness negative inside the file's load
//! range), made on the text as written, over the ranges written (the
//! data's, which may reach past a template's: `FSAE_Defaults.tir`'s FZMAX
//! 2000 N widened to the Hoosier data's 2928.5 N carried its `PKX1 = 50`,
//! `PKX2 = −80` past 1625 N, where its force opposes its slip). Said on
//! the terminal, in the report and as `$ warning:` lines of the file's
//! header, with the file's own line numbers; and a template's `PKY1`,
//! `PKY4` on MFeval's branch, said as read.

use super::StartArg;
use crate::error::{Error, FitError};
use crate::format::{exact, readable};
use crate::identify::mf_staged::Stage;
use crate::jobs::tyre_eval::of_text;
use crate::tyre::mf::MagicFormula;
use std::path::Path;

/// The `.tir` text `head` + the checks' `$ warning:` lines + `body`, to be
/// written at `path`, and the checks' warnings. The checks are made on the
/// text itself: a second pass gives the line numbers of the text with its
/// warning lines in (the comments change no check, so their count holds).
pub(super) fn with_file_checks(path: &Path, head: &str, body: &str) -> (String, Vec<String>) {
    let comments =
        |w: &[String]| -> String { w.iter().map(|l| format!("$ warning: {l}\n")).collect() };
    let first = of_text(path, &format!("{head}{body}")).lines();
    let draft = format!("{head}{}{body}", comments(&first));
    let warnings = of_text(path, &draft).lines();
    (format!("{head}{}{body}", comments(&warnings)), warnings)
}

/// Refuses the `.tir` `text` whose pure Fx the paper's scheme fitted
/// (`start` paper and the stage among those `fitted`) when its
/// longitudinal slip stiffness turns negative
/// inside its own load range (the data's): the scheme has no physical
/// bounds, and on noise-free MF data it stopped at `PKX1` 1.59, `PKX2`
/// −3.99, negative from 5597 N of the data's 6000 N, the pure Fx stage
/// at σ 88 %, a file every message disowned. Refused, not refitted: the
/// user asked for the paper's scheme, and the data start is the default
/// the words name. The other schemes keep `PKX1` in its box, and a
/// template's own coefficients carried past its range stay a warning (the
/// user's tyre, not this fit's).
pub(super) fn refuse_paper_turn(
    start: StartArg,
    path: &Path,
    text: &str,
    fitted: &[Stage],
) -> Result<(), Error> {
    let paper = start == StartArg::Paper && fitted.contains(&Stage::PureFx);
    let Some(t) = of_text(path, text).longitudinal_turn.filter(|_| paper) else {
        return Ok(());
    };
    let (lo, hi, _) = t.range;
    let span = match (t.from, t.above) {
        (Some(f), true) => format!(
            "from Fz = {} N up to the data's {} N",
            readable(f, 4),
            readable(hi, 4)
        ),
        (Some(f), false) => format!(
            "from the data's {} N up to Fz = {} N",
            readable(lo, 4),
            readable(f, 4)
        ),
        (None, _) => format!(
            "over the data's whole {} to {} N",
            readable(lo, 4),
            readable(hi, 4)
        ),
    };
    let turn = format!(
        "the paper's scheme (--start paper) took PKX1 = {}, PKX2 = {}: the longitudinal slip stiffness Kxκ = Fz·(PKX1 + PKX2·dfz)·exp(PKX3·dfz) is negative {span}",
        readable(t.pkx1.0, 5),
        readable(t.pkx2.0, 5)
    );
    Err(FitError::PaperTurn { turn }.into())
}

/// The load coefficients of each slip stiffness (at `NOMPRES`, no camber):
/// a held one of these can turn the stiffness over (`held_turn.rs`).
const STIFFNESS_KEYS: [(&str, &[&str]); 2] = [
    ("cornering", &["PKY1", "PKY2", "PKY4", "PPY1", "PPY2"]),
    (
        "longitudinal slip",
        &["PKX1", "PKX2", "PKX3", "PPX1", "PPX2"],
    ),
];

/// Refuses the fitted `tyre` where a slip stiffness changes sign inside
/// the loads written (the data's) and a value given with `--hold` is one
/// of its load coefficients ([`crate::error::HeldTurn`]). Found by
/// behaviour, as `tyre-eval` finds it of any file. Without a held one the
/// fit's boxes keep the stiffness of one sign, and a template's own
/// coefficients are its file's warnings.
pub(super) fn refuse_held_turn(hold: &[(String, f64)], tyre: &MagicFormula) -> Result<(), Error> {
    let (Some(lo), Some(hi)) = (tyre.limits.fz_min, tyre.limits.fz_max) else {
        return Ok(());
    };
    let whole = crate::tyre::Tyre::MagicFormula(Box::new(tyre.clone()));
    for turn in crate::jobs::tyre_eval::sign_changes(&whole, &[lo.max(1.0), hi]) {
        let keys = STIFFNESS_KEYS
            .iter()
            .find(|(s, _)| *s == turn.stiffness)
            .map_or(&[][..], |(_, k)| *k);
        let held: Vec<crate::error::HeldValue> = hold
            .iter()
            .filter(|(k, _)| keys.contains(&k.as_str()))
            .map(|(k, v)| crate::error::HeldValue {
                name: k.clone(),
                value: *v,
                search_box: crate::identify::mf_staged::fixed_bounds(k),
            })
            .collect();
        if !held.is_empty() {
            let e = crate::error::HeldTurn {
                held,
                stiffness: turn.stiffness,
                between: turn.between,
                changes: turn.changes,
                loads: (lo, hi),
            };
            return Err(FitError::HeldTurn(Box::new(e)).into());
        }
    }
    Ok(())
}

/// A template's `PKY1`, `PKY4` on the other branch of Kyα (`PKY4 < 0`),
/// which the fit reads (and writes) with both signs turned: said.
pub(super) fn stiffness_branch_note(t: &MagicFormula) -> Option<String> {
    let c = &t.coefficients;
    (c.PKY4 < 0.0).then(|| {
        format!(
            "the template's PKY1 = {}, PKY4 = {} are read as PKY1 = {}, PKY4 = {}: the same cornering stiffness (Kyα ∝ PKY1·sin(PKY4·atan(Fz/(PKY2·Fz0))), odd in the two together) on the branch the fit keeps PKY4 on (0.1 to 5)",
            exact(c.PKY1),
            exact(c.PKY4),
            exact(-c.PKY1),
            exact(-c.PKY4)
        )
    })
}
