//! A ranked candidate's warnings in words ([`RankWarning`]): held-out and
//! in-sample removals that disagree, axles that are no tyre, fold refits
//! far from the all-run fit, a set fitted worse than its subset, folds that
//! did not converge. Shares in percent; values in the parameter's unit.

use super::{no_tyre_list, value};
use crate::diagnose::report::outcome::RankWarning;

/// A ranked candidate's warnings in one line (None without any).
pub fn rank_warnings(w: &[RankWarning]) -> Option<String> {
    let lines: Vec<String> = w.iter().map(rank_warning).collect();
    (!lines.is_empty()).then(|| lines.join("; "))
}

/// One warning on a ranked candidate.
pub fn rank_warning(w: &RankWarning) -> String {
    match w {
        RankWarning::Disagreement {
            insample_percent,
            heldout_percent,
        } => {
            // A negative reduction is a larger gap, not a smaller removal.
            let heldout = if *heldout_percent < 0.0 {
                format!("makes it {:.0} % larger", -heldout_percent)
            } else {
                format!("only {heldout_percent:.0} %")
            };
            format!(
                "the fit on all runs removes {insample_percent:.0} % of the gap but {heldout} on held-out runs: the effect does not generalise across runs, or the runs cannot pin its parameters"
            )
        }
        RankWarning::AxlesNoTyre { no_tyre } => format!(
            "fitted with it, the axles are no tyre ({}): it cannot be a verdict",
            no_tyre_list(no_tyre)
        ),
        RankWarning::FoldsFar {
            parameter,
            value: v,
            std_error,
            reported_std_error,
            fold_value,
            distance,
            far,
            folds,
        } => {
            // The robust standard error the table gives, where there is one.
            let given = if reported_std_error.is_finite() && *reported_std_error > 0.0 {
                format!(
                    "; {:.1} times the ± {} given, robust to correlated residuals",
                    (fold_value - v).abs() / reported_std_error,
                    super::std_error(*reported_std_error)
                )
            } else {
                String::new()
            };
            format!(
                "{far} of {folds} fold refits land far from the fit on all runs ({parameter} {} against {}: {distance:.1} times its standard error of white residuals, ± {}{given}): its held-out score measures a fit on fewer runs as much as the effect",
                value(*fold_value),
                value(*v),
                super::std_error(*std_error),
            )
        }
        RankWarning::WorseThanSubset {
            subset,
            subset_error,
            error,
        } => format!(
            "it fits the runs worse than {subset}, which it contains (in-sample error {error:.3} against {subset_error:.3}): its fit stopped short of that optimum or holds a parameter {subset} fits, so its scores understate the set"
        ),
        RankWarning::ContributesNothing {
            effects,
            reduces_to,
        } => {
            let to = if reduces_to.is_empty() {
                "the base model".to_string()
            } else {
                crate::diagnose::effects::joined(reduces_to, "+")
            };
            format!(
                "{} contribute{} nothing (every parameter at its off value, within its standard error): the set reduces to {to}, and what it gains over that comes from the axles refitted, not from {}; it cannot be a verdict",
                crate::diagnose::effects::joined(effects, "+"),
                if effects.len() == 1 { "s" } else { "" },
                if effects.len() == 1 { "it" } else { "them" },
            )
        }
        RankWarning::FoldsNotConverged { failed, folds } => {
            format!("{failed} of {folds} fold refits did not converge")
        }
    }
}
