//! How far the cross-validation's fold refits move from the all-run fit by
//! the runs' noise alone: the yardstick their scatter is judged by.
//!
//! Linearised at the all-run optimum θ̂ (where `Jᵀr = 0`), the refit
//! without the held-out rows `H` of fold `i` moves by
//! `δᵢ = (J₋ᵢᵀJ₋ᵢ)⁻¹ J_Hᵀ r_H`, whose variance under residual noise of
//! variance σ² is `σ²[(J₋ᵢᵀJ₋ᵢ)⁻¹ − (JᵀJ)⁻¹]` (the difference of two
//! nested least-squares covariances). The grouped jackknife
//! `(k−1)/k · Σ(θᵢ − θ̄)²` then expects, relative to the all-run variance
//! `σ²[(JᵀJ)⁻¹]_jj`, the square of
//! `f_j = √((k−1)/k · Σᵢ ([(J₋ᵢᵀJ₋ᵢ)⁻¹]_jj / [(JᵀJ)⁻¹]_jj − 1))`.
//! With runs of equal information `f_j = 1`, the jackknife's usual
//! agreement with the standard error; where one run carries most of what
//! determines a parameter (the only sweep of a campaign, for a lag),
//! leaving it out moves the fit far by noise alone, `f_j ≫ 1`, and the
//! delete-one jackknife overstates the variance (Wu 1986, who weighs each
//! deletion by its leverage for the same reason). The folds' variances
//! `vᵢ` are unequal, so the jackknife's own scatter is that of a χ² with
//! the Satterthwaite (1946) count `ν = (Σvᵢ)²/Σvᵢ²` degrees of freedom:
//! 7 for eight folds alike, about 1 where one fold carries the rest. Units:
//! none (a factor of a standard error, a count).

use crate::diagnose::model::replay::Prepared;
use nalgebra::DMatrix;
use std::ops::Range;

/// The residual rows, in the all-run problem of `runs` (their rows in run
/// order), of the runs `pick` takes: a fold's held-out rows, or its
/// training rows ([`crate::diagnose::fit::refit::training_rows`]).
pub(crate) fn run_rows(runs: &[Prepared], pick: impl Fn(usize) -> bool) -> Vec<Range<usize>> {
    let mut start = 0;
    let mut rows = Vec::new();
    for (i, r) in runs.iter().enumerate() {
        let n = r.count();
        if pick(i) {
            rows.push(start..start + n);
        }
        start += n;
    }
    rows
}

/// The residual rows of the runs `held_out`: a fold's held-out rows.
pub(crate) fn held_rows(runs: &[Prepared], held_out: &[usize]) -> Vec<Range<usize>> {
    run_rows(runs, |i| held_out.contains(&i))
}

/// `(f_j, ν_j)` for each column of the Jacobian `j` (the all-run fit's,
/// prior rows included), each fold leaving out the rows `held[i]`; only
/// the columns `free` (a fitted parameter inside its box) take part, the
/// others get NaN, as does every column where a normal matrix is singular.
pub(crate) fn fold_noise_factors(
    j: &DMatrix<f64>,
    held: &[Vec<Range<usize>>],
    free: &[bool],
) -> Vec<(f64, f64)> {
    let n = j.ncols();
    let cols: Vec<usize> = (0..n)
        .filter(|&c| free.get(c).copied().unwrap_or(false))
        .collect();
    let mut out = vec![(f64::NAN, f64::NAN); n];
    let k = held.len();
    if cols.is_empty() || k < 2 {
        return out;
    }
    let sub = j.select_columns(&cols);
    let normal = sub.transpose() * &sub;
    let Some(all) = normal.clone().try_inverse() else {
        return out;
    };
    let mut sum = vec![0.0; cols.len()];
    let mut squares = vec![0.0; cols.len()];
    for rows in held {
        let mut without = normal.clone();
        for r in rows {
            let h = sub.rows(r.start, r.len());
            without -= h.transpose() * h;
        }
        let Some(inv) = without.try_inverse() else {
            return out;
        };
        for (c, (s, q)) in sum.iter_mut().zip(&mut squares).enumerate() {
            let v = (inv[(c, c)] / all[(c, c)] - 1.0).max(0.0);
            *s += v;
            *q += v * v;
        }
    }
    for ((c, s), q) in cols.iter().zip(sum).zip(squares) {
        let nu = if q > 0.0 { s * s / q } else { f64::NAN };
        out[*c] = (((k - 1) as f64 / k as f64 * s).sqrt(), nu);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A Jacobian of `runs` runs of `n` rows each, one column, each run's
    /// rows `weight[run]` (its information `weight²·n`).
    fn runs(weights: &[f64], n: usize) -> (DMatrix<f64>, Vec<Vec<Range<usize>>>) {
        let j = DMatrix::from_fn(weights.len() * n, 1, |r, _| weights[r / n]);
        let held = (0..weights.len())
            .map(|i| std::iter::once(i * n..(i + 1) * n).collect())
            .collect();
        (j, held)
    }

    #[test]
    fn runs_of_equal_information_expect_the_standard_error_itself() {
        let (j, held) = runs(&[1.0; 8], 50);
        let f = fold_noise_factors(&j, &held, &[true]);
        assert!((f[0].0 - 1.0).abs() < 1e-12, "{f:?}");
        // Eight folds alike: as many degrees of freedom.
        assert!((f[0].1 - 8.0).abs() < 1e-9, "{f:?}");
    }

    #[test]
    fn a_run_that_carries_most_of_the_information_moves_its_fold_far() {
        // One run with 100× the information of each of seven others:
        // leaving it out multiplies the variance by (100 + 7)/7.
        let (j, held) = runs(&[10.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0], 50);
        let f = fold_noise_factors(&j, &held, &[true]);
        let expected: f64 = 7.0 / 8.0 * ((107.0 / 7.0 - 1.0) + 7.0 * (107.0 / 106.0 - 1.0));
        assert!(
            (f[0].0 - expected.sqrt()).abs() < 1e-9,
            "{f:?} against {}",
            expected.sqrt()
        );
        assert!(f[0].0 > 3.0, "{f:?}");
        // The one fold is nearly all of it: about one degree of freedom.
        assert!((1.0..1.3).contains(&f[0].1), "{f:?}");
    }

    #[test]
    fn a_parameter_not_fitted_or_a_singular_fold_gets_no_factor() {
        let (j, held) = runs(&[1.0; 4], 10);
        assert!(fold_noise_factors(&j, &held, &[false])[0].0.is_nan());
        // One run holds all the rows that see the parameter.
        let (j, held) = runs(&[1.0, 0.0, 0.0, 0.0], 10);
        assert!(fold_noise_factors(&j, &held, &[true])[0].0.is_nan());
    }
}
