//! Parameter uncertainty of a least-squares fit at its optimum: the
//! covariance `s²·(JᵀJ)⁻¹` with `s² = Σr²/(m − n)` (m residuals, n
//! parameters) from the Jacobian of the residuals, the Gauss–Newton
//! approximation of the Hessian (Seber & Wild, *Nonlinear Regression*,
//! 1989, §2.1). Used by the tyre identification and the diagnosis alike.

use nalgebra::DMatrix;

/// Which columns of `j` the data see: a column whose norm is below 1e-9 of
/// the largest is a parameter the residuals do not depend on (an offset of
/// a channel that is not measured, a parameter pinned at its bound).
pub(crate) fn seen_columns(j: &DMatrix<f64>) -> Vec<bool> {
    let norms: Vec<f64> = j.column_iter().map(|c| c.norm()).collect();
    let largest = norms.iter().copied().fold(0.0, f64::max);
    norms.iter().map(|&n| n > 1e-9 * largest).collect()
}

/// The covariance of the parameters of a fit whose residuals have Jacobian
/// `j` and sum of squares `sum_squares` at the optimum, over the columns
/// the data see (the rows and columns of unseen parameters are NaN).
/// (JᵀJ), its columns scaled to unit norm, is inverted by SVD with singular
/// values below 1e-14 of the largest dropped; the parameters along a
/// dropped direction (they trade exactly) are NaN too.
/// None when no parameter is seen.
pub(crate) fn covariance(j: &DMatrix<f64>, sum_squares: f64) -> Option<DMatrix<f64>> {
    let (m, n) = j.shape();
    let seen: Vec<usize> = seen_columns(j)
        .into_iter()
        .enumerate()
        .filter_map(|(c, seen)| seen.then_some(c))
        .collect();
    if seen.is_empty() {
        return None;
    }
    let s2 = sum_squares / m.saturating_sub(n).max(1) as f64;
    // Columns scaled to unit norm first (Jacobi scaling): parameters of
    // very different units (a share near its limit beside an offset in
    // rad/s) otherwise spread JᵀJ's singular values past the cut-off, and
    // the pseudo-inverse drops directions the data do determine, giving
    // standard errors orders of magnitude too small.
    let mut js = j.select_columns(seen.iter());
    let norms: Vec<f64> = js.column_iter().map(|c| c.norm()).collect();
    for (mut c, &norm) in js.column_iter_mut().zip(&norms) {
        c /= norm;
    }
    let svd = (js.transpose() * &js).svd(true, true);
    let smax = svd.singular_values.max();
    let cut = 1e-14 * smax;
    // A direction the data do not determine (two parameters that trade
    // exactly) is dropped by the pseudo-inverse, which would then report
    // the minimum-norm variance along it, far too small: the parameters
    // that take part in it have no standard error (NaN).
    let mut undetermined = vec![false; seen.len()];
    if let Some(v_t) = &svd.v_t {
        for (r, &sv) in svd.singular_values.iter().enumerate() {
            if sv <= cut {
                for (a, u) in undetermined.iter_mut().enumerate() {
                    *u |= v_t[(r, a)].abs() > 1e-3;
                }
            }
        }
    }
    let inv = svd.pseudo_inverse(cut).ok()?;
    let mut out = DMatrix::from_element(n, n, f64::NAN);
    for (a, &i) in seen.iter().enumerate() {
        for (b, &k) in seen.iter().enumerate() {
            if !undetermined[a] && !undetermined[b] {
                out[(i, k)] = s2 * inv[(a, b)] / (norms[a] * norms[b]);
            }
        }
    }
    Some(out)
}

/// Standard errors (square roots of the covariance's diagonal); NaN for a
/// parameter the data do not see or whose variance is not a finite
/// non-negative number.
pub(crate) fn standard_errors(j: &DMatrix<f64>, sum_squares: f64) -> Vec<f64> {
    let n = j.ncols();
    match covariance(j, sum_squares) {
        Some(c) => (0..n)
            .map(|i| {
                let v = c[(i, i)];
                if v.is_finite() && v >= 0.0 {
                    v.sqrt()
                } else {
                    f64::NAN
                }
            })
            .collect(),
        None => vec![f64::NAN; n],
    }
}

/// Standard errors robust to residuals correlated within blocks: the
/// sandwich `A⁻¹·B·A⁻¹` with `A = JᵀJ` and `B = Σ_b G_b·G_bᵀ`, `G_b` the
/// score `Σ_{k∈b} J_kᵀ·r_k` of block `b` (the rows `blocks` names; each
/// other row a block of its own). Blocks long against the residuals'
/// correlation make it the batch-means estimate of the scores' long-run
/// variance (heteroscedasticity and autocorrelation consistent; Newey &
/// West 1987, Conley 1999 on blocks). NaN where [`standard_errors`] is.
#[cfg(test)]
pub(crate) fn sandwich_standard_errors(
    j: &DMatrix<f64>,
    r: &[f64],
    blocks: &[std::ops::Range<usize>],
) -> Vec<f64> {
    let n = j.ncols();
    let Some(v) = sandwich_covariance(j, r, blocks) else {
        return vec![f64::NAN; n];
    };
    (0..n)
        .map(|i| {
            if v[(i, i)] >= 0.0 {
                v[(i, i)].sqrt()
            } else {
                f64::NAN
            }
        })
        .collect()
}

/// The covariance of the block sandwich, whose diagonal's roots are the
/// standard errors `sandwich_standard_errors` gives (NaN
/// in the rows and columns of the parameters it leaves without one; None
/// where `JᵀJ` has no inverse): what a combination of the parameters, a
/// sum of two, is determined to.
pub(crate) fn sandwich_covariance(
    j: &DMatrix<f64>,
    r: &[f64],
    blocks: &[std::ops::Range<usize>],
) -> Option<DMatrix<f64>> {
    let (m, n) = j.shape();
    // `covariance` with a sum of squares of m − n is s² = 1: (JᵀJ)⁻¹.
    let bread = covariance(j, m.saturating_sub(n).max(1) as f64)?;
    let ok: Vec<usize> = (0..n).filter(|&i| bread[(i, i)].is_finite()).collect();
    let mut meat = DMatrix::<f64>::zeros(n, n);
    let mut add = |rows: std::ops::Range<usize>| {
        let mut g = nalgebra::DVector::<f64>::zeros(n);
        for k in rows {
            for &i in &ok {
                g[i] += j[(k, i)] * r[k];
            }
        }
        meat.ger(1.0, &g, &g, 1.0);
    };
    let mut in_block = vec![false; m];
    for b in blocks {
        in_block[b.clone()].fill(true);
        add(b.clone());
    }
    for k in (0..m).filter(|&k| !in_block[k]) {
        add(k..k + 1);
    }
    let bread_ok = DMatrix::from_fn(n, n, |a, b| {
        if ok.contains(&a) && ok.contains(&b) {
            bread[(a, b)]
        } else {
            0.0
        }
    });
    let v = &bread_ok * meat * &bread_ok;
    Some(DMatrix::from_fn(n, n, |a, b| {
        if ok.contains(&a) && ok.contains(&b) {
            v[(a, b)]
        } else {
            f64::NAN
        }
    }))
}

/// A standard normal draw (Box–Muller) from a seeded stream: the noise of
/// the tests' synthetic data and of `metrics`' noisy copies of a run.
pub fn gauss(rng: &mut rand_chacha::ChaCha8Rng) -> f64 {
    use rand::RngExt;
    let (u1, u2): (f64, f64) = (rng.random::<f64>().max(1e-300), rng.random());
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn straight_line_fit_has_the_textbook_standard_errors() {
        // y = a + b·x on x = 0..4: Var(b) = s²/Σ(x − x̄)², Var(a) =
        // s²·Σx²/(m·Σ(x − x̄)²).
        let x = [0.0, 1.0, 2.0, 3.0, 4.0];
        let j = DMatrix::from_fn(5, 2, |i, c| if c == 0 { 1.0 } else { x[i] });
        let ss = 0.3;
        let s2 = ss / 3.0;
        let sxx = 10.0;
        let e = standard_errors(&j, ss);
        assert!((e[1] - (s2 / sxx).sqrt()).abs() < 1e-12);
        assert!((e[0] - (s2 * 30.0 / (5.0 * sxx)).sqrt()).abs() < 1e-12);
    }

    /// A mean of AR(1) noise (ρ = 0.9): the textbook standard error is
    /// `√((1 + ρ)/(1 − ρ))` ≈ 4.4 times too small; the sandwich over
    /// blocks of 200 samples finds the spread of the mean over many
    /// series, and with every row its own block it is the textbook one.
    #[test]
    fn the_block_sandwich_finds_the_spread_of_a_mean_of_correlated_noise() {
        use rand::{RngExt, SeedableRng};
        let (n, rho) = (20_000, 0.9);
        let j = DMatrix::from_element(n, 1, 1.0);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let blocks: Vec<_> = (0..n / 200).map(|b| b * 200..(b + 1) * 200).collect();
        let (mut means, mut robust, mut textbook) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..40 {
            let mut x = 0.0;
            let e: Vec<f64> = (0..n)
                .map(|_| {
                    let w: f64 = rng.random::<f64>() - 0.5;
                    x = rho * x + w;
                    x
                })
                .collect();
            let mean = e.iter().sum::<f64>() / n as f64;
            let r: Vec<f64> = e.iter().map(|v| v - mean).collect();
            means.push(mean);
            robust.push(sandwich_standard_errors(&j, &r, &blocks)[0]);
            let ss: f64 = r.iter().map(|v| v * v).sum();
            textbook.push(standard_errors(&j, ss)[0]);
            let alone = sandwich_standard_errors(&j, &r, &[]);
            assert!((alone[0] / textbook[textbook.len() - 1] - 1.0).abs() < 1e-3);
        }
        let spread = (means.iter().map(|m| m * m).sum::<f64>() / means.len() as f64).sqrt();
        let avg = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
        assert!(
            (avg(&robust) / spread - 1.0).abs() < 0.3,
            "{} vs {spread}",
            avg(&robust)
        );
        assert!(
            avg(&textbook) < spread / 3.5,
            "{} vs {spread}",
            avg(&textbook)
        );
    }

    #[test]
    fn an_unseen_parameter_gets_nan_and_leaves_the_others_alone() {
        let x = [0.0, 1.0, 2.0, 3.0, 4.0];
        let with = DMatrix::from_fn(5, 3, |i, c| match c {
            0 => 1.0,
            1 => 0.0,
            _ => x[i],
        });
        let without = DMatrix::from_fn(5, 2, |i, c| if c == 0 { 1.0 } else { x[i] });
        let a = standard_errors(&with, 0.3);
        // One more parameter in the degrees of freedom: s² over 2, not 3.
        let b = standard_errors(&without, 0.3 * 3.0 / 2.0);
        assert!(a[1].is_nan());
        assert!((a[0] - b[0]).abs() < 1e-12 && (a[2] - b[1]).abs() < 1e-12);
    }

    #[test]
    fn parameters_in_units_eight_orders_apart_keep_their_standard_errors() {
        // The straight line with its slope in units 1e8 times smaller: the
        // slope's standard error scales by 1e-8, the intercept's stays.
        let x = [0.0, 1.0, 2.0, 3.0, 4.0];
        let j = DMatrix::from_fn(5, 2, |i, c| if c == 0 { 1.0 } else { x[i] });
        let scaled = DMatrix::from_fn(5, 2, |i, c| if c == 0 { 1.0 } else { 1e8 * x[i] });
        let a = standard_errors(&j, 0.3);
        let b = standard_errors(&scaled, 0.3);
        assert!((b[0] / a[0] - 1.0).abs() < 1e-9, "{a:?} {b:?}");
        assert!((b[1] * 1e8 / a[1] - 1.0).abs() < 1e-9, "{a:?} {b:?}");
    }

    #[test]
    fn parameters_that_trade_exactly_have_no_standard_error() {
        // y = a + b + c·x: a and b enter only as their sum.
        let x = [0.0, 1.0, 2.0, 3.0, 4.0];
        let j = DMatrix::from_fn(5, 3, |i, c| if c < 2 { 1.0 } else { x[i] });
        let se = standard_errors(&j, 0.3);
        assert!(se[0].is_nan() && se[1].is_nan(), "{se:?}");
        // The slope is still determined, with the textbook error.
        assert!(
            (se[2] - (0.3 / 2.0 / 10.0f64).sqrt()).abs() < 1e-12,
            "{se:?}"
        );
    }
}
