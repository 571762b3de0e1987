//! The fold refits that stand apart ([`ParameterValue::folds_apart`]) in
//! words: the runs each leaves out, its value against the other folds'
//! range, and which runs to check. Values in the parameter's own unit.
//!
//! Leaving one run out, the fold that stands apart is the fold without the
//! odd run (every other fold keeps it) — or the fold without the run that
//! pins the value, where the others then follow an odd run among them: on
//! round 47's campaign the sweep carries most of what determines a sensor
//! delay, and leaving it out lets a step logged 0.15 s late take the
//! steps' fit to 0.078 s, while the fold without that step gives the
//! synth's 0.0496 s. The fold values alone cannot tell the two apart; the
//! Satterthwaite count of the folds' noise (`fold_noise_dof`, about 1 where
//! one fold carries the rest) says when the second reading is open, and the
//! words then name the run whose fold moves the other way most too.

use super::value;
use crate::diagnose::report::fold_refits::APART;
use crate::diagnose::report::{FoldRefit, ParameterValue};

/// Below this Satterthwaite count one fold carries more of what
/// determines the parameter than the others together (2 for two folds
/// alike, about 1 for one alone): the fold standing apart may be the one
/// that pins the value rather than an odd run.
pub(super) const ONE_FOLD_CARRIES: f64 = 2.0;

/// The words of the folds standing apart, where the effect removes
/// something significant (`removes`): `; the fold leaving out … refits it
/// to …, the other n folds to …–…, beyond 3× their spread: …`. A refit
/// that did not converge is said so (its value is where it stopped).
/// Empty where no fold stands apart.
pub(super) fn apart(p: &ParameterValue, removes: bool) -> String {
    let apart = p.folds_apart();
    let others: Vec<(usize, &FoldRefit)> = (p.fold_refits.iter().enumerate())
        .filter(|(i, _)| !apart.contains(i))
        .collect();
    if !removes || apart.is_empty() || others.is_empty() {
        return String::new();
    }
    let unit = match p.unit {
        "" | "-" => String::new(),
        u => format!(" {u}"),
    };
    let lo = others
        .iter()
        .map(|f| f.1.value)
        .fold(f64::INFINITY, f64::min);
    let hi = (others.iter().map(|f| f.1.value)).fold(f64::NEG_INFINITY, f64::max);
    let named: Vec<&FoldRefit> = apart.iter().map(|&i| &p.fold_refits[i]).collect();
    let folds: Vec<String> = named.iter().map(|f| leaving(f)).collect();
    let values: Vec<String> = named.iter().map(|f| value(f.value)).collect();
    let (fold, refit) = match named.len() {
        1 => ("fold", "refits"),
        _ => ("folds", "refit"),
    };
    let stopped: Vec<String> = (named.iter().filter(|f| !f.converged))
        .map(|f| leaving(f))
        .collect();
    let stopped = match stopped.as_slice() {
        [] => String::new(),
        s => format!(
            " (the refit leaving out {} did not converge: its value is where it stopped, so check that refit before the run)",
            s.join(" / ")
        ),
    };
    format!(
        "; the {fold} leaving out {} {refit} it to {}{unit}, the other {} folds to {}–{}{unit}, beyond {APART}× their spread: {}{stopped}",
        folds.join(" / leaving out "),
        values.join(" / "),
        others.len(),
        value(lo),
        value(hi),
        check(p, &named, &others, &unit),
    )
}

/// The runs a fold leaves out, joined by `and` (`an unnamed run` where
/// not known).
fn leaving(f: &FoldRefit) -> String {
    match f.left_out.as_slice() {
        [] => "an unnamed run".to_string(),
        runs => runs.join(" and "),
    }
}

/// Which runs to check. One fold of one run apart, where the folds carry
/// alike: that run. Where one fold carries most of what determines it
/// ([`ONE_FOLD_CARRIES`]), that run, or — it pinning the value — the run
/// of the fold that moves from the all-run fit most the other way (its
/// run pulls the value towards where the apart fold went).
fn check(
    p: &ParameterValue,
    named: &[&FoldRefit],
    others: &[(usize, &FoldRefit)],
    unit: &str,
) -> String {
    const OWN: &str = "(its own logger, its own set-up)";
    let [one] = named else {
        return format!("check those runs {OWN}, unless the effect misses what they alone excite");
    };
    let runs = one.left_out.len().max(1);
    let run = if runs == 1 {
        "that run is the one"
    } else {
        "one of those runs is the one"
    };
    let carried = p.fold_noise_dof.is_some_and(|nu| nu < ONE_FOLD_CARRIES);
    let side = (one.value - p.value).signum();
    let pulling = (others.iter())
        .map(|(_, f)| (f, side * (p.value - f.value)))
        .filter(|(_, moved)| *moved > 0.0)
        .max_by(|a, b| a.1.total_cmp(&b.1));
    const UNLESS: &str = "unless the effect misses what that run alone excites";
    match pulling {
        Some((f, _)) if carried => format!(
            "check {} {OWN} and {} (its fold {}{unit}): one fold carrying most of what determines it, without {} the others follow the run that pulls them most the other way — {UNLESS}",
            if runs == 1 { "that run" } else { "those runs" },
            leaving(f),
            value(f.value),
            if runs == 1 { "that run" } else { "them" },
        ),
        _ => format!("{run} to check {OWN}, {UNLESS}"),
    }
}
