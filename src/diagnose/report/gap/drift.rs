//! The noise's integrated autocorrelation time a bias is counted by, with
//! the moving mean it is measured about following the noise's own
//! correlation time.
//!
//! The residual less its moving mean is the noise (the scan's `noise_time`):
//! its slow parts (a persistent error, a step, a replay's start) are not
//! noise, or an error makes itself its own excuse. But a fixed quarter
//! second mean counts only what the noise does faster than that: a smooth
//! output (a state estimator's sideslip) or a low-passed sensor drifts
//! slower, its slow wander read as many independent samples, and pure noise
//! read as a bias (Putnam's sideslip). So the mean's half width grows to
//! [`SPANS`] of the noise's correlation time, the time read from the
//! residual less the mean so far by its lag-one correlation
//! `ρ = 1 − γ(1)/σ²` (Box & Jenkins 1976's first-order autoregression,
//! `T = −1/ln ρ` samples), where the one-step variogram `γ(1)` and the
//! variance `σ²` are each a median of squares: a step in the residual
//! moves a few dozen samples of the fast part and one difference, not
//! their medians, so a persistent error does not widen the mean, while a
//! correlated noise, correlated everywhere, does. The count is the larger
//! of the fast part's integrated time (Sokal 1997) and the first-order
//! one, `(1 + ρ)/(1 − ρ)`, ρ corrected for the share of the noise's
//! variance the mean takes away (`τ/L` for a mean of `L` samples).
//!
//! Units: samples.

use crate::measured::calibration::stats::integrated_time;

/// The least half width of the moving mean, s: a quarter of the scan's
/// 0.5 s window, within which a lag or a transient error lives.
pub const MEAN_HALF: f64 = 0.125;

/// Correlation times of the noise the moving mean spans on either side
/// once it follows them: about 10 % of a first-order noise's variance is
/// then taken by the mean, corrected for.
pub const SPANS: f64 = 10.0;

/// The median of `v` (NaN for none).
fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The lag-one correlation `1 − γ(1)/σ²` of the zero-mean `x`, each a
/// median of squares (both scaled alike for a normal noise, the scale
/// cancels), within [0, 1).
fn robust_lag_one(x: &[f64]) -> f64 {
    let variance = median(x.iter().map(|v| v * v).collect());
    let step = median(x.windows(2).map(|w| (w[1] - w[0]).powi(2)).collect());
    if variance.is_nan() || variance <= 0.0 {
        return 0.0;
    }
    (1.0 - 0.5 * step / variance).clamp(0.0, 1.0 - 1e-12)
}

/// The first-order count `(1 + ρ)/(1 − ρ)` of a noise whose lag-one
/// correlation reads `rho` less a moving mean of `len` samples: the mean
/// takes `τ/len` of its variance, so `1 − ρ` reads `(1 − ρ)/(1 − τ/len)`;
/// with `x = 1 − ρ`, `τ ≈ 2/x`, `x² − x̂·x + 2x̂/len = 0`.
fn first_order_time(rho: f64, len: f64) -> f64 {
    let read = 1.0 - rho;
    let disc = (read * read - 8.0 * read / len).max(0.0);
    let x = 0.5 * (read + disc.sqrt());
    (2.0 - x) / x
}

/// Samples in [`MEAN_HALF`] at the mean step of the times `t`
/// (at least one): the half width of the moving mean the noise is read
/// about.
pub(super) fn quarter_window_samples(t: &[f64]) -> usize {
    let n = t.len();
    let dt = (t[n - 1] - t[0]) / (n - 1).max(1) as f64;
    ((MEAN_HALF / dt).round() as usize).max(1)
}

/// `e` less its centred moving mean over `half` samples on either side
/// (fewer at the ends).
pub(super) fn less_moving_mean(e: &[f64], half: usize) -> Vec<f64> {
    let n = e.len();
    let mut sum = vec![0.0; n + 1];
    for i in 0..n {
        sum[i + 1] = sum[i] + e[i];
    }
    (0..n)
        .map(|i| {
            let (a, b) = (i.saturating_sub(half), (i + half + 1).min(n));
            e[i] - (sum[b] - sum[a]) / (b - a) as f64
        })
        .collect()
}

/// The noise's integrated autocorrelation time in the residual `e` at
/// times `t`, samples, about a moving mean [`SPANS`] of the noise's
/// correlation times wide on either side (at least a quarter
/// [`MEAN_HALF`] on either side, at most a quarter of the run).
pub(super) fn bias_noise_time(t: &[f64], e: &[f64]) -> f64 {
    let n = e.len();
    if n < 8 {
        return 1.0;
    }
    let most = (n / 4).max(1);
    let first_half = quarter_window_samples(t).min(most);
    let mut half = first_half;
    loop {
        let fast = less_moving_mean(e, half);
        let rho = robust_lag_one(&fast);
        let time = if rho > 0.0 { -1.0 / rho.ln() } else { 0.0 };
        let wanted = (SPANS * time).ceil() as usize;
        let sokal = integrated_time(&fast, fast.iter().sum::<f64>() / fast.len() as f64).max(1.0);
        if wanted <= first_half {
            // Resolved within the quarter second: the fast part's count
            // alone, as the window test's (the scan's `noise_time`).
            return sokal;
        }
        if wanted <= half || half >= most {
            return sokal.max(first_order_time(rho, (2 * half + 1) as f64));
        }
        // At least half again: a correlation read low through a narrow
        // mean reaches its width in a few steps.
        half = wanted.max(half + half / 2 + 1).min(most);
    }
}

#[cfg(test)]
mod tests {
    use super::super::scan::{bias_test, SLOW_BIAS_STANDARD_ERRORS};
    use super::*;
    use crate::diagnose::model::scale::FloorCounting;

    /// A state estimator's sideslip error over 120 s at 100 Hz: a
    /// first-order wander of 0.001 rad and correlation time 3 s (smooth:
    /// its sample-to-sample step is 0.00008 rad), plus `offset`, seeded
    /// `seed`.
    fn estimator_wander(seed: u64, offset: f64) -> (Vec<f64>, Vec<f64>) {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let mut gauss = || crate::optim::stats::gauss(&mut rng);
        let rho = (-0.01_f64 / 3.0).exp();
        let k = (1.0 - rho * rho).sqrt();
        let mut x = 0.001 * gauss();
        let t: Vec<f64> = (0..12_000).map(|i| 0.01 * i as f64).collect();
        let e = t
            .iter()
            .map(|_| {
                x = rho * x + 0.001 * k * gauss();
                x + offset
            })
            .collect();
        (t, e)
    }

    /// Against an estimated output's assumed 0.005 rad floor, counted as
    /// the slow error it stands for: the wander alone is no bias on any of
    /// eight seeds, nor is a misalignment of half a floor (0.0025 rad),
    /// which the white count made eleven standard errors of 0.00023 rad;
    /// an offset of four floors (0.02 rad) is a bias, its standard error
    /// one floor (`√(floor² + σ²τ/n)`, the wander's own part, σ 0.001 rad
    /// over its correlation time, a five-hundredth of the floor's).
    #[test]
    fn an_estimator_s_mean_is_a_bias_only_beyond_its_slow_floor() {
        let floor = 0.005;
        for seed in 1..=8 {
            for offset in [0.0, 0.0025] {
                let (t, e) = estimator_wander(seed, offset);
                let slow = bias_test(&t, &e, floor, FloorCounting::Slow, true);
                assert!(!slow.significant, "{seed} {offset}: {slow:?}");
                assert_eq!(slow.counting, FloorCounting::Slow);
                let white = bias_test(&t, &e, floor, FloorCounting::White, true);
                assert_eq!(white.significant, offset > 0.0, "{seed}: {white:?}");
            }
            let (t, e) = estimator_wander(seed, 0.02);
            let b = bias_test(&t, &e, floor, FloorCounting::Slow, true);
            let closed = floor;
            assert!(
                (b.standard_error / closed - 1.0).abs() < 0.02,
                "{seed}: {b:?} against {closed}"
            );
            assert!(
                b.significant && b.standard_errors > SLOW_BIAS_STANDARD_ERRORS,
                "{seed}: {b:?}"
            );
        }
    }

    /// The window test counts the slow floor as the bias test does: on the
    /// estimator's sideslip of [`estimator_wander`] against its assumed
    /// 0.005 rad floor, right or off by half, one or two floors, no window
    /// is a gap and the mean no bias, on eight seeds (a window of 50
    /// samples averaged the floor down as white noise and called every
    /// window of a half-floor offset a gap, beside "no bias"); four floors
    /// off (0.02 rad), both find it, in every window.
    #[test]
    fn the_windows_and_the_bias_agree_on_an_estimator_s_sideslip() {
        use super::super::scan::{noise_time, scored_from, worst_window};
        let floor = 0.005;
        let slow = (floor, FloorCounting::Slow);
        for seed in 1..=8 {
            for offset in [0.0, 0.0025, 0.005, 0.01, 0.02] {
                let (t, e) = estimator_wander(seed, offset);
                let tau = noise_time(&t, &e);
                let w = worst_window(&t, scored_from(t[0]), &e, slow, tau, t.len(), true).unwrap();
                let b = bias_test(&t, &e, floor, FloorCounting::Slow, true);
                let far = offset > 3.0 * floor;
                assert_eq!(b.significant, far, "{seed} {offset}: {b:?}");
                assert_eq!(w.significant, far, "{seed} {offset}: {w:?}");
                let every = w.windows_significant == w.windows_tested;
                assert_eq!(every, far, "{seed} {offset}: {w:?}");
                assert_eq!(w.windows_significant > 0, far, "{seed} {offset}: {w:?}");
            }
        }
    }

    /// The closed form of the correction: a mean of `L` samples takes
    /// `τ/L` of the variance, so a noise of `1 − ρ = x` reads
    /// `x/(1 − 2/(x·L))`, and is read back.
    #[test]
    fn the_mean_s_share_is_undone() {
        for (x, len) in [(0.01, 2001.0), (0.002, 20001.0), (0.5, 25.0)] {
            let read = x / (1.0 - 2.0 / (x * len));
            let back = first_order_time(1.0 - read, len);
            let exact = (2.0 - x) / x;
            assert!((back / exact - 1.0).abs() < 1e-9, "{x}: {back} {exact}");
        }
    }
}
