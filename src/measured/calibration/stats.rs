//! The statistics of a calibration: a channel's mean over one span, robust
//! to logger glitches, with a standard error that holds for autocorrelated
//! samples; and the pooling of several spans' means with a test of whether
//! they agree.
//!
//! - Glitches: samples farther than [`OUTLIER_MADS`] robust deviations
//!   (`1.4826·MAD`) from the span's median are left out of the mean (a zero
//!   read or a spike of a real logger sits far outside a parked sensor's
//!   noise). A channel with no spread at all (every sample one value: a
//!   gated yaw rate at exactly 0, a held GPS sideslip) has no offset to
//!   measure and gives none.
//! - Standard error: `s/√n_eff`, with `n_eff = n/τ` and `τ = 1 + 2·Σ ρ(k)`
//!   the integrated autocorrelation time, summed over lags `k ≤ M` with the
//!   smallest window `M ≥ C·τ(M)`, `C` = [`SOKAL_WINDOW`] (the automatic
//!   windowing of Madras & Sokal 1988 and Sokal 1997), corrected for the
//!   bias `−(2M + 1)/n` of covariances taken about the span's own mean
//!   (Sokal 1997). White noise has
//!   `τ ≈ 1`; a first-order (AR(1)) noise of lag-one correlation φ has
//!   `τ = (1 + φ)/(1 − φ)`. `τ` is held within `[1, n]`: a span never counts
//!   more independent samples than it has, nor fewer than one.
//! - Pooling: a random-effects mean of the spans' means (DerSimonian &
//!   Laird 1986): Cochran's `Q = Σ w(m − m̄)²` about the inverse-variance
//!   mean (`w = 1/s²`) gives the spans' spread beyond their errors,
//!   `τ² = max(0, (Q − (k − 1))/(Σw − Σw²/Σw))`, and each span is weighed
//!   by `1/(s² + τ²)`, the standard error `1/√Σ(1/(s² + τ²))`. Where the
//!   spans agree within their errors τ = 0 and this is the inverse-variance
//!   mean; where they drift, a short span's tiny error cannot carry the
//!   mean for the rest (it did under the Birge ratio, which only widened
//!   the error). The spans agree when `χ²` stays below its
//!   [`AGREEMENT_QUANTILE`] quantile with `k − 1` degrees of freedom (the
//!   Wilson & Hilferty 1931 cube-root
//!   approximation); else the offset drifts between them.

use crate::measured::clean::median;

/// Samples beyond this many robust deviations of the span's median are
/// glitches, left out of its mean.
pub(super) const OUTLIER_MADS: f64 = 5.0;

/// The automatic window's factor `C` (Sokal 1997 finds 4–10 adequate for
/// decays near exponential).
pub(super) const SOKAL_WINDOW: f64 = 5.0;

/// Quantile of χ² below which spans agree.
pub(super) const AGREEMENT_QUANTILE: f64 = 0.99;

/// The standard normal quantile of [`AGREEMENT_QUANTILE`].
const AGREEMENT_Z: f64 = 2.326_347_874;

/// A channel's mean over one span.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct MeanEstimate {
    pub(super) mean: f64,
    pub(super) std_error: f64,
    pub(super) samples: usize,
    pub(super) effective_samples: f64,
    pub(super) outliers: usize,
}

/// The samples of `v` within [`OUTLIER_MADS`] robust deviations of its
/// median, in order, and how many were left out; None when `v` is empty or
/// holds one value throughout. A channel quantised so coarsely that most
/// samples share one value has a zero MAD: its spread is then taken as one
/// quantisation step (the smallest nonzero deviation).
pub(super) fn without_glitches(v: &[f64]) -> Option<(Vec<f64>, usize)> {
    let m = median(&mut v.to_vec());
    let mut dev: Vec<f64> = v.iter().map(|x| (x - m).abs()).collect();
    let mut s = 1.4826 * median(&mut dev);
    if s == 0.0 {
        s = dev.iter().copied().filter(|&d| d > 0.0).reduce(f64::min)?;
    }
    let kept: Vec<f64> = v
        .iter()
        .copied()
        .filter(|x| (x - m).abs() <= OUTLIER_MADS * s)
        .collect();
    let left = v.len() - kept.len();
    Some((kept, left))
}

/// The integrated autocorrelation time of `x` about `mean`, in samples,
/// within `[1, n]`.
pub(crate) fn integrated_time(x: &[f64], mean: f64) -> f64 {
    let n = x.len();
    let d: Vec<f64> = x.iter().map(|v| v - mean).collect();
    let c0 = d.iter().map(|v| v * v).sum::<f64>() / n as f64;
    if n < 4 || c0 <= 0.0 {
        return 1.0;
    }
    let longest = n / 4;
    let mut tau = 1.0;
    let mut window = None;
    for k in 1..=longest {
        let ck = d[..n - k]
            .iter()
            .zip(&d[k..])
            .map(|(a, b)| a * b)
            .sum::<f64>()
            / n as f64;
        tau += 2.0 * ck / c0;
        if k as f64 >= SOKAL_WINDOW * tau {
            window = Some(k);
            break;
        }
    }
    // A window that never closes (a span shorter than a few correlation
    // times, or a drift within it): the correlation time is at least what
    // the longest window allows.
    if window.is_none() {
        tau = tau.max(longest as f64 / SOKAL_WINDOW);
    }
    // The covariances about the span's own mean are each low by about the
    // mean's variance, so the windowed sum falls short by (2M + 1)/n of
    // itself (Sokal 1997): undone here, or a span a few dozen correlation
    // times long would claim a standard error 10–20 % too small.
    let m = window.unwrap_or(longest) as f64;
    (tau * n as f64 / (n as f64 - 2.0 * m - 1.0)).clamp(1.0, n as f64)
}

/// The mean of `v` with its glitches left out and its standard error for
/// autocorrelated samples; None when `v` holds one value (or nothing).
pub(super) fn mean_estimate(v: &[f64]) -> Option<MeanEstimate> {
    let (kept, outliers) = without_glitches(v)?;
    let n = kept.len();
    let mean = kept.iter().sum::<f64>() / n as f64;
    let var = if n > 1 {
        kept.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64
    } else {
        0.0
    };
    let effective = n as f64 / integrated_time(&kept, mean);
    Some(MeanEstimate {
        mean,
        std_error: (var / effective).sqrt(),
        samples: n,
        effective_samples: effective,
        outliers,
    })
}

/// Several spans' means pooled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Pool {
    pub(super) mean: f64,
    /// The random-effects standard error: the spans' own errors and their
    /// scatter beyond them (`between`) together.
    pub(super) std_error: f64,
    /// χ² (Cochran's Q) of the spans about their inverse-variance mean.
    pub(super) chi2: f64,
    pub(super) dof: usize,
    pub(super) agree: bool,
    /// The spread of the spans' true offsets beyond their errors
    /// (DerSimonian–Laird τ; 0 where χ² ≤ dof).
    pub(super) between: f64,
}

/// Pools `(mean, standard error)` pairs (at least one) as a random-effects
/// mean (DerSimonian & Laird 1986): where the spans scatter beyond their
/// errors (a drifting offset), each is weighed by `1/(s² + τ²)`, τ² the
/// between-span variance estimated from Cochran's χ², so that a short span
/// with a tiny error of its own cannot carry the mean for the rest (fixed
/// inverse-variance weights did: one 4 s straight against a lap's). Where
/// they agree (χ² ≤ dof), τ = 0 and the mean is the inverse-variance one.
pub(super) fn pool(means: &[(f64, f64)]) -> Pool {
    // A noise-free span has a zero standard error: floor it at rounding.
    let var: Vec<f64> = means
        .iter()
        .map(|&(m, s)| s.max(f64::EPSILON * m.abs().max(1e-300)).powi(2))
        .collect();
    let weighted = |w: &[f64]| {
        let sw: f64 = w.iter().sum();
        let mean = means.iter().zip(w).map(|(&(m, _), w)| w * m).sum::<f64>() / sw;
        (mean, sw)
    };
    let w: Vec<f64> = var.iter().map(|v| 1.0 / v).collect();
    let (fixed, sw) = weighted(&w);
    let chi2: f64 = means
        .iter()
        .zip(&w)
        .map(|(&(m, _), w)| w * (m - fixed).powi(2))
        .sum();
    let dof = means.len() - 1;
    let sw2: f64 = w.iter().map(|w| w * w).sum();
    let tau2 = match dof {
        0 => 0.0,
        _ => ((chi2 - dof as f64) / (sw - sw2 / sw)).max(0.0),
    };
    let w_re: Vec<f64> = var.iter().map(|v| 1.0 / (v + tau2)).collect();
    let (mean, sw_re) = weighted(&w_re);
    Pool {
        mean,
        std_error: 1.0 / sw_re.sqrt(),
        chi2,
        dof,
        agree: dof == 0 || chi2 <= chi2_quantile(dof, AGREEMENT_Z),
        between: tau2.sqrt(),
    }
}

/// The χ² quantile with `dof` degrees of freedom at the standard normal
/// quantile `z` (Wilson & Hilferty 1931: `(χ²/k)^(1/3)` is nearly normal
/// with mean `1 − 2/(9k)` and variance `2/(9k)`).
pub(crate) fn chi2_quantile(dof: usize, z: f64) -> f64 {
    chi2_quantile_of(dof as f64, z)
}

/// [`chi2_quantile`] for a real number of degrees of freedom `k` (a
/// Satterthwaite count).
pub(crate) fn chi2_quantile_of(k: f64, z: f64) -> f64 {
    let a = 2.0 / (9.0 * k);
    k * (1.0 - a + z * a.sqrt()).powi(3)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_chi_square_quantiles_match_the_tables() {
        // χ²₀.₉₉ for 1, 2, 5, 10 degrees of freedom: 6.635, 9.210, 15.086,
        // 23.209 (standard tables); Wilson–Hilferty is within 1 % at k = 1
        // and 0.2 % from k = 2.
        for (k, table, tol) in [
            (1, 6.635, 0.01),
            (2, 9.210, 0.002),
            (5, 15.086, 0.0025),
            (10, 23.209, 0.0015),
        ] {
            let q = chi2_quantile(k, AGREEMENT_Z);
            assert!((q / table - 1.0).abs() < tol, "k = {k}: {q}");
        }
    }

    #[test]
    fn an_ar1_noise_has_its_closed_form_correlation_time() {
        // τ = (1 + φ)/(1 − φ): 19 at φ = 0.9; white noise: 1.
        let white = crate::identify::data::white_noise(20_000, 1.0, 3);
        let mut x = vec![0.0; white.len()];
        for i in 1..x.len() {
            x[i] = 0.9 * x[i - 1] + white[i];
        }
        let tau = integrated_time(&x, 0.0);
        assert!((tau / 19.0 - 1.0).abs() < 0.15, "{tau}");
        let tau = integrated_time(&white, 0.0);
        assert!((tau - 1.0).abs() < 0.1, "{tau}");
    }

    #[test]
    fn spans_that_scatter_beyond_their_errors_do_not_agree() {
        let p = pool(&[(1.0, 0.01), (1.01, 0.01), (0.995, 0.01)]);
        assert!(p.agree && (p.mean - 1.001_667).abs() < 1e-6);
        assert!((p.std_error - 0.01 / 3f64.sqrt()).abs() < 1e-12);
        assert_eq!(p.between, 0.0);
        // Ten errors apart: a drift, and the pooled error grows with it
        // (τ² = (Q − 1)/(Σw − Σw²/Σw) = 49/1e4: two spans, each weighed
        // 1/(1e-4 + 4.9e-3) = 200, so ± 1/√400).
        let p = pool(&[(1.0, 0.01), (1.1, 0.01)]);
        assert!(!p.agree);
        assert!((p.std_error - 0.05).abs() < 1e-12, "{}", p.std_error);
        assert!((p.between - 0.07).abs() < 1e-12, "{}", p.between);
        assert!(p.chi2 > 49.0 && p.dof == 1);
    }

    #[test]
    fn a_short_span_with_a_tiny_error_does_not_carry_a_drifting_mean() {
        // A 4 s straight at −0.600 ± 0.001 beside three laps' −0.66 to
        // −0.68 ± 0.01: inverse-variance weights gave −0.602; the spans'
        // scatter (τ ≈ 0.049) weighs them about alike: −0.652.
        let spans = [
            (-0.600, 0.001),
            (-0.670, 0.01),
            (-0.680, 0.01),
            (-0.660, 0.01),
        ];
        let p = pool(&spans);
        assert!(!p.agree);
        let plain = spans.iter().map(|s| s.0).sum::<f64>() / 4.0;
        assert!((p.mean - plain).abs() < 0.005, "{} against {plain}", p.mean);
        assert!(p.mean < -0.64, "{}", p.mean);
        assert!((0.045..0.055).contains(&p.between), "{}", p.between);
        // The error covers the spread of four spans, not the short one's.
        assert!(p.std_error > 0.01, "{}", p.std_error);
    }
}
