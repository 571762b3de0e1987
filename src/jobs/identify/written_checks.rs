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

use crate::format::exact;
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
