//! A fitted parameter's fold refits one by one ([`FoldRefit`]: the runs a
//! fold leaves out, the value refitted on the others, whether that refit
//! converged) and the rule by which a fold stands apart from the others
//! ([`folds_apart`]; `ParameterValue::folds_apart` applies it). Where the
//! runs disagree beyond their noise (`ParameterValue::understated`) the
//! jackknife says only that they do;
//! a fold standing apart says which run: leaving out one run that
//! carries something of its own (its own logger's delay, its own set-up)
//! moves the refit away from every fold that keeps it. Values in the
//! parameter's own unit. Source: the grouped jackknife's leave-out values
//! (Efron & Stein 1981), read one by one as outlier diagnostics of the
//! runs (Cook 1977's leave-one-out influence).

use serde::Serialize;

/// One fold refit of a parameter.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FoldRefit {
    /// The runs the fold leaves out (their names as the campaign reads
    /// them; empty where not known, a value made without its campaign).
    pub left_out: Vec<String>,
    /// The parameter refitted on the other runs, in its unit.
    #[serde(serialize_with = "crate::report::finite_or_null")]
    pub value: f64,
    /// The refit converged (else it stopped at its iteration limit, and
    /// its value is where it stopped).
    pub converged: bool,
}

/// How many times the others' spread a fold's value must lie from their
/// mean to stand apart. The spread is the others' grouped jackknife, the
/// measure the report gives as the fold spread, `(n−1)/√n` times their
/// standard deviation for `n` others (1.15–2.3 of it for 3–7): 3× it is
/// 3.5–7 standard deviations of a fold's scatter among them, which
/// normal scatter passes far under 0.3 % of the time. Less would name a
/// fold of the runs' ordinary scatter on 5–8 folds, where the jackknife's
/// own relative error is 35–50 % (the same 3 as [`crate::diagnose::report::UNDERSTATED`]).
pub const APART: f64 = 3.0;

/// The folds of `values` (one per fold) each of which lies more than
/// [`APART`] times the larger of the other folds' jackknife spread and
/// `floor` from their mean. `floor` is what the runs' noise alone moves
/// a fold by (`ParameterValue::fold_yardstick`): others that agree more
/// closely than noise allows (a noise-free campaign) do not make a fold
/// of ordinary noise stand apart. None below three folds (two others
/// leave one difference for a spread) or with a value not finite.
pub fn folds_apart(values: &[f64], floor: f64) -> Vec<usize> {
    let k = values.len();
    if k < 3 || values.iter().any(|v| !v.is_finite()) {
        return Vec::new();
    }
    (0..k)
        .filter(|&i| {
            let others = || values.iter().enumerate().filter(move |&(j, _)| j != i);
            let n = (k - 1) as f64;
            let mean = others().map(|(_, v)| v).sum::<f64>() / n;
            let ss: f64 = others().map(|(_, v)| (v - mean).powi(2)).sum();
            let spread = ((n - 1.0) / n * ss).sqrt();
            (values[i] - mean).abs() > APART * spread.max(floor)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Eight folds: seven within ±0.001 s of 0.053 s, the one leaving out
    /// a run with 0.15 s more delay at 0.031 s (its own logger): that one
    /// is named, none of the seven.
    #[test]
    fn a_fold_far_beyond_the_others_spread_is_named_alone() {
        let values = [
            0.0530, 0.0525, 0.0535, 0.0310, 0.0528, 0.0533, 0.0531, 0.0527,
        ];
        assert_eq!(folds_apart(&values, 0.0006), vec![3]);
        // The same fold within 3× the floor (what noise alone moves a fold
        // by) is not named: 0.022 s from the others against 3 × 0.008 s.
        assert!(folds_apart(&values, 0.008).is_empty());
        // Just past 3× the floor it is: 0.0220 s against 3 × 0.0072 s.
        assert_eq!(folds_apart(&values, 0.0072), vec![3]);
    }

    /// Folds that scatter alike, each within 3× the others' spread, name
    /// none: the five of `parameter_tests`' roll steer (±0.02 about
    /// −0.41), and two of eight apart from six (each within the spread the
    /// other one gives the rest).
    #[test]
    fn folds_within_their_spread_name_none() {
        let alike = [-0.39, -0.43, -0.41, -0.39, -0.43];
        assert!(folds_apart(&alike, 0.0).is_empty());
        let two = [0.05, 0.051, 0.049, 0.05, 0.02, 0.021, 0.05, 0.05];
        assert!(folds_apart(&two, 0.0).is_empty());
        // Fewer than three folds, or a value not finite: nothing to judge.
        assert!(folds_apart(&[0.05, 0.02], 0.0).is_empty());
        assert!(folds_apart(&[0.05, 0.05, f64::NAN, 0.02], 0.0).is_empty());
    }

    /// The spread is the others' jackknife, √((n−1)/n·Σ(θ−θ̄)²), not
    /// their standard deviation: three others at 0, 0.1, 0.2 have a
    /// jackknife √(2/3·0.02) = 0.11547; a fourth fold at 0.1 ± 3× that
    /// (0.3464) is on the line.
    #[test]
    fn the_rule_is_three_of_the_others_jackknife() {
        let spread = (2.0f64 / 3.0 * 0.02).sqrt();
        let inside = [0.0, 0.1, 0.2, 0.1 + 3.0 * spread - 1e-9];
        assert!(!folds_apart(&inside, 0.0).contains(&3));
        let beyond = [0.0, 0.1, 0.2, 0.1 + 3.0 * spread + 1e-9];
        assert_eq!(folds_apart(&beyond, 0.0), vec![3]);
    }
}
