//! What a whole-run RMS hides: a gap confined to a short stretch (a lagged
//! step diluted by its steady part), a persistent bias below three noise
//! floors but many standard errors of a mean, and a time shift between the
//! simulated and measured channel (the shift, not the residual's likeness
//! to the steer, says "the measurement lags by 0.10 s").
//!
//! - Sliding windows of [`WINDOW`] s, every half window from one window
//!   into the run (the replay's own start transient left out): a window's mean
//!   square residual over the noise floor's square is, under pure noise, F
//!   with the window's effective sample count (its samples over the noise's
//!   integrated autocorrelation time) and the floor's (the samples it was
//!   estimated from, likewise: a floor estimated low by chance must not
//!   make noise a gap); Paulson's approximation to its quantile; each window is
//!   tested at [`FALSE_ALARM`] over the number of windows (Bonferroni), so
//!   a record of pure noise shows a local gap in at most about one run in a
//!   hundred, however long.
//! - The bias against its standard error `max(floor, sd(e))·√(τ/n)`, τ the
//!   noise's integrated autocorrelation time (the residual less a moving
//!   mean that spans the noise's own correlation time,
//!   [`super::drift::bias_noise_time`]; Sokal's window as the calibration's
//!   means use), not the whole residual's: a persistent error is slow, and
//!   counted as noise it made itself its own excuse (a sideslip twice the
//!   model's read "1.8 standard errors over 3 effective samples" of 800),
//!   while a noise slower than a fixed quarter second, counted by it, read
//!   as a bias (a state estimator's sideslip); significant beyond
//!   [`BIAS_STANDARD_ERRORS`].
//! - The floor is counted as what it stands for
//!   ([`crate::diagnose::model::scale::floor_counting`]): measured scatter
//!   and a gyro's or accelerometer's floor (even over a smoothed or
//!   noise-free record: a low-pass leaves a white noise's mean's standard
//!   error as it was) are white noise, one draw a sample, `floor²/n`; the
//!   floor of a sideslip that reads as an estimator's output (assumed, or
//!   stated by the user) stands for the estimator's drift and
//!   misalignment, slow error, one draw for the whole run, the whole
//!   `floor²` added to the noise's part (an offset moves the residual's
//!   mean, not its scatter, so no scatter covers it): a mean is then a
//!   bias only beyond [`SLOW_BIAS_STANDARD_ERRORS`] of it, about three
//!   floors, the whole-run test's line, and beyond
//!   [`BIAS_STANDARD_ERRORS`] of the noise's part alone. The counting used
//!   is reported per channel (`bias_counting`, and in the words).
//! - The time shift: the lag of the largest correlation of the measured
//!   channel with the simulated one over ±[`MAX_SHIFT`] s, refined between
//!   samples by a parabola through the peak and its neighbours; only where
//!   that correlation reaches [`SHIFT_CORRELATION`] (a channel with a
//!   response well above its noise). Positive: the measurement lags the
//!   simulation, `measured(t) ≈ simulated(t − shift)`.
//!
//! Units: the channel's own; times in s.

use crate::diagnose::model::scale::FloorCounting;
use crate::measured::calibration::stats::integrated_time;
use crate::stats::CentredSums;
use serde::Serialize;

/// Length of the sliding windows, s: a yaw or lateral response rises in
/// 0.1–0.3 s, so a lag or a transient error lives within about half a
/// second.
pub const WINDOW: f64 = 0.5;

/// The half windows into a replay where the scan's first window starts:
/// one whole [`WINDOW`], the replay's own start transient left out.
const FIRST_HALF_WINDOW: usize = 2;

/// Where the scored span of a replay that starts at `t0` begins, s: the
/// start of the scan's first window ([`worst_window`]). The overlays draw
/// their model lines from there, so the figure leaves out what the scan
/// leaves out.
pub fn scored_from(t0: f64) -> f64 {
    t0 + 0.5 * WINDOW * FIRST_HALF_WINDOW as f64
}

/// The chance that pure noise shows a local gap in any window of a run.
pub const FALSE_ALARM: f64 = 0.01;

/// Standard errors of the mean beyond which a bias is significant (a
/// normal tail of 6e-5 on both sides: rare on pure noise even with the
/// autocorrelation time estimated).
pub const BIAS_STANDARD_ERRORS: f64 = 4.0;

/// The least correlation of the measured channel with the shifted
/// simulated one for a time shift to be stated.
pub const SHIFT_CORRELATION: f64 = 0.9;

/// The largest time shift searched, s.
pub const MAX_SHIFT: f64 = 1.0;

/// The sliding window that carries the most evidence of a gap.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WindowGap {
    /// Its start, s (the run's time).
    pub start: f64,
    /// Its end, s.
    pub end: f64,
    /// Samples in it.
    pub samples: usize,
    /// RMS residual over it.
    pub rms: f64,
    /// That RMS in noise floors (`null` on a zero floor).
    #[serde(serialize_with = "crate::report::finite_or_null")]
    pub noise_floors: f64,
    /// The RMS in noise floors that pure noise exceeds in no window of the
    /// run with a chance above [`FALSE_ALARM`] (`null` where the floor
    /// rests on too few effective samples to set one).
    #[serde(serialize_with = "crate::report::finite_or_null")]
    pub threshold_noise_floors: f64,
    /// Windows tested.
    pub windows_tested: usize,
    /// Windows whose RMS is above their threshold: all or most of them is
    /// a gap along the run (an offset), not in one stretch.
    pub windows_significant: usize,
    /// Its RMS above the threshold.
    pub significant: bool,
}

/// Standard errors of the mean beyond which a bias is significant where
/// the floor is counted as a slow error ([`FloorCounting::Slow`]): the
/// floor's part is then one draw for the run, so the standard error is
/// about one floor and the line is the whole-run test's three noise floors
/// (a normal tail of 0.003 on both sides: a run's mean is one draw of the
/// error, as its RMS is).
pub const SLOW_BIAS_STANDARD_ERRORS: f64 = 3.0;

/// The standard errors beyond which a bias counted by `counting` is
/// significant.
pub fn bias_threshold(counting: FloorCounting) -> f64 {
    match counting {
        FloorCounting::White => BIAS_STANDARD_ERRORS,
        FloorCounting::Slow => SLOW_BIAS_STANDARD_ERRORS,
    }
}

/// A bias tested against its standard error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BiasTest {
    /// Standard error of the mean residual.
    pub standard_error: f64,
    /// |bias| in standard errors.
    pub standard_errors: f64,
    /// Effective samples (samples over the autocorrelation time).
    pub effective_samples: f64,
    /// How the floor's part above the residual's scatter was counted.
    pub counting: FloorCounting,
    /// Beyond [`bias_threshold`] of the counting.
    pub significant: bool,
}

/// The upper-tail standard normal quantile: `z` with `P(Z > z) = p`
/// (bisection on the complementary error function).
fn upper_normal_quantile(p: f64) -> f64 {
    let tail = |z: f64| 0.5 * libm::erfc(z / std::f64::consts::SQRT_2);
    let (mut lo, mut hi) = (-10.0, 40.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if tail(mid) > p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The quantile of F(`k1`, `k2`) at the upper normal quantile `z`
/// (Paulson 1942: the cube roots of the two χ²'s over their degrees of
/// freedom are nearly normal, as Wilson & Hilferty found); infinite where
/// `k2` is too small for it.
fn f_quantile(k1: f64, k2: f64, z: f64) -> f64 {
    let (a, b) = (2.0 / (9.0 * k1), 2.0 / (9.0 * k2));
    let den = (1.0 - b).powi(2) - z * z * b;
    let disc = b * (1.0 - a).powi(2) + a * (1.0 - b).powi(2) - z * z * a * b;
    if den <= 0.0 || disc < 0.0 {
        return f64::INFINITY;
    }
    ((((1.0 - a) * (1.0 - b) + z * disc.sqrt()) / den).max(0.0)).powi(3)
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len().max(1) as f64
}

/// The integrated autocorrelation time of `x` about its mean, samples
/// (1 for white noise; 1 for fewer than four samples).
pub(super) fn correlation_time(x: &[f64]) -> f64 {
    integrated_time(x, mean(x))
}

/// The noise's integrated autocorrelation time in the residual `e` at
/// times `t`, samples: that of `e` less its centred moving mean over half
/// a [`WINDOW`]. The residual's slow parts (a replay's start transient, a
/// gap itself) are not noise: counted as such, they stretched the time
/// and raised the windows' threshold past any gap (8.8 noise floors on a
/// clean replay, 45 on the Putnam log). A noise correlated over more than
/// a quarter-second is under-counted: the window test is then less strict
/// than stated.
pub(super) fn noise_time(t: &[f64], e: &[f64]) -> f64 {
    if e.len() < 4 {
        return 1.0;
    }
    let fast = super::drift::less_moving_mean(e, super::drift::quarter_window_samples(t));
    correlation_time(&fast).max(1.0)
}

/// The sliding window of the residual `e` at times `t` whose RMS is the
/// most noise floors above its threshold, the noise's autocorrelation time
/// `tau` samples and the floor estimated from `floor_samples` samples (its
/// effective count `floor_samples/tau`); `resolved` false (noise-free data: a zero floor) makes
/// no window significant. The first window starts at `from` ([`scored_from`]
/// of the replay's start: one [`WINDOW`] into it).
/// None on a run shorter than two windows.
pub(super) fn worst_window(
    t: &[f64],
    from: f64,
    e: &[f64],
    floor: f64,
    tau: f64,
    floor_samples: usize,
    resolved: bool,
) -> Option<WindowGap> {
    let tau = tau.max(1.0);
    let k2 = (floor_samples as f64 / tau).max(1.0);
    let t1 = t[t.len() - 1];
    // From `from`, one window into the replay ([`scored_from`]): a
    // replay's first half second follows from the initial state it
    // estimates from noisy samples, a transient of the replay, not of the
    // model (a clean sedan replay's ay read "a gap in one stretch: 1.5
    // noise floors from t = 0.00 s").
    let starts: Vec<f64> = (0..)
        .map(|j| from + 0.5 * WINDOW * j as f64)
        .take_while(|s| s + WINDOW <= t1 + 1e-9)
        .collect();
    let m = starts.len();
    let z = upper_normal_quantile(FALSE_ALARM / m.max(1) as f64);
    let windows: Vec<WindowGap> = starts
        .into_iter()
        .filter_map(|start| {
            let end = start + WINDOW;
            // The times are sorted: the window is a slice, found by bisection.
            let v = &e[t.partition_point(|&x| x < start)..t.partition_point(|&x| x < end)];
            if v.len() < 3 {
                return None;
            }
            let rms = (v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt();
            let k = (v.len() as f64 / tau).max(1.0);
            let threshold = f_quantile(k, k2, z).sqrt();
            let floors = rms / floor;
            Some(WindowGap {
                start,
                end,
                samples: v.len(),
                rms,
                noise_floors: floors,
                threshold_noise_floors: threshold,
                windows_tested: m,
                windows_significant: 0,
                significant: resolved && floors > threshold,
            })
        })
        .collect();
    let windows_significant = windows.iter().filter(|w| w.significant).count();
    windows
        .into_iter()
        .max_by(|a, b| {
            let ratio = |w: &WindowGap| w.noise_floors / w.threshold_noise_floors;
            ratio(a).total_cmp(&ratio(b))
        })
        .map(|w| WindowGap {
            windows_significant,
            ..w
        })
}

/// The residual `e` at times `t`: its mean against its standard error, the
/// noise floor `floor` the least scatter it is judged with, the effective
/// samples counted by the noise's correlation time about a mean that
/// follows it ([`super::drift::bias_noise_time`]), not by the residual's
/// own: the error tested is not its noise, and a noise slower than a
/// quarter second is not an error. Where the floor exceeds the residual's
/// own scatter, the excess is counted as the floor's `counting` says
/// ([`FloorCounting`]). White, over every sample: counted over the
/// correlation time of a replay's deterministic transient error
/// (0.00026 rad/s against a 0.005 rad/s floor), a 0.01 rad/s gyro offset
/// read "1.3 standard errors … over 0 effective samples". Slow, once over
/// the run: an estimator's sideslip trusted to 0.005 rad had any 0.5 mrad
/// mean "a bias" of ten standard errors of 0.0001 rad (Putnam's log: 19
/// of its 46 channels), though the floor stands for the estimator's own
/// drift and misalignment, which a run's mean inside it may well be.
pub(super) fn bias_test(
    t: &[f64],
    e: &[f64],
    floor: f64,
    counting: FloorCounting,
    resolved: bool,
) -> BiasTest {
    let n = e.len().max(1) as f64;
    let m = mean(e);
    let var = e.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / n;
    let tau = super::drift::bias_noise_time(t, e);
    // The floor in `n × (the mean's variance)`. White: a draw a sample,
    // and only its excess over the residual's scatter, which already holds
    // that noise. Slow: one draw for all `n`, and the whole floor, since
    // an estimator's offset moves the residual's mean, not its scatter.
    let weighed = var * tau
        + match counting {
            FloorCounting::White => (floor * floor - var).max(0.0),
            FloorCounting::Slow => floor * floor * n,
        };
    let standard_error = (weighed / n).sqrt();
    let standard_errors = m.abs() / standard_error;
    // Beyond its line, and beyond the white line of the residual's own
    // noise alone (the slow line is for the floor's one draw, not for a
    // noise counted over many samples).
    let noise_alone = m.abs() / (var * tau / n).sqrt();
    BiasTest {
        standard_error,
        standard_errors,
        effective_samples: n * var.max(floor * floor) / weighed.max(f64::MIN_POSITIVE),
        counting,
        significant: resolved
            && standard_errors > bias_threshold(counting)
            && noise_alone > BIAS_STANDARD_ERRORS,
    }
}

/// Pearson correlation of `a[i]` with `b[i − k]` (k of either sign) over
/// their overlap.
pub(super) fn lagged_correlation(a: &[f64], b: &[f64], k: isize) -> f64 {
    let n = a.len();
    let l = k.unsigned_abs();
    if l + 3 > n {
        return f64::NAN;
    }
    let (x, y) = if k >= 0 {
        (&a[l..], &b[..n - l])
    } else {
        (&a[..n - l], &b[l..])
    };
    CentredSums::of(x, y).correlation().unwrap_or(f64::NAN)
}

/// The time shift of `measured` behind `simulated`, s (positive: the
/// measurement lags), sampled every `dt` s; None where the best
/// correlation is below [`SHIFT_CORRELATION`] or lies at the search's edge.
pub(super) fn time_shift(dt: f64, measured: &[f64], simulated: &[f64]) -> Option<f64> {
    let n = measured.len();
    if n < 8 || dt <= 0.0 {
        return None;
    }
    let most = ((MAX_SHIFT / dt).round() as isize).min(n as isize / 4);
    let rho: Vec<f64> = (-most..=most)
        .map(|k| lagged_correlation(measured, simulated, k))
        .collect();
    let (best, &peak) = rho
        .iter()
        .enumerate()
        .filter(|(_, r)| r.is_finite())
        .max_by(|a, b| a.1.total_cmp(b.1))?;
    if peak < SHIFT_CORRELATION || best == 0 || best + 1 == rho.len() {
        return None;
    }
    let (a, c) = (rho[best - 1], rho[best + 1]);
    let curvature = a - 2.0 * peak + c;
    let offset = if curvature < 0.0 {
        (0.5 * (a - c) / curvature).clamp(-0.5, 0.5)
    } else {
        0.0
    };
    Some((best as f64 - most as f64 + offset) * dt)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_normal_tail_quantiles_match_the_tables() {
        for (p, z) in [(0.05, 1.644_854), (0.01, 2.326_348), (1e-4, 3.719_016)] {
            assert!((upper_normal_quantile(p) - z).abs() < 1e-4, "{p}");
        }
    }

    #[test]
    fn the_f_quantiles_match_the_tables_and_tend_to_chi_square() {
        // F₀.₉₉(50, 100) = 1.735, F₀.₉₉(10, 20) = 3.368 (tables).
        let z = upper_normal_quantile(0.01);
        assert!((f_quantile(50.0, 100.0, z) / 1.735 - 1.0).abs() < 0.01);
        assert!((f_quantile(10.0, 20.0, z) / 3.368 - 1.0).abs() < 0.02);
        // A floor known exactly: χ²₀.₉₉(50)/50 = 76.154/50.
        assert!((f_quantile(50.0, 1e12, z) / (76.154 / 50.0) - 1.0).abs() < 0.005);
    }

    #[test]
    fn pure_noise_shows_a_local_gap_in_about_one_run_in_a_hundred() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let t: Vec<f64> = (0..1000).map(|i| 0.01 * i as f64).collect();
        let mut alarms = 0;
        for _ in 0..400 {
            let e: Vec<f64> = t
                .iter()
                .map(|_| crate::optim::stats::gauss(&mut rng))
                .collect();
            // The floor estimated from the first 100 samples, as before an input.
            let pre = &e[..100];
            let floor = (pre.iter().map(|x| x * x).sum::<f64>() / 100.0).sqrt();
            let tau = noise_time(&t, &e);
            let w = worst_window(&t, scored_from(t[0]), &e, floor, tau, 100, true).unwrap();
            alarms += usize::from(w.significant);
        }
        assert!(alarms <= 10, "{alarms} of 400");
    }

    /// A replay's slow start transient (5 noise floors decaying over
    /// 0.5 s) is not noise: the noise's time stays near one sample, and a
    /// 0.5 s stretch of 3 noise floors later in the run is found. The
    /// whole residual's correlation time, the transient counted as noise,
    /// lifts the threshold past it.
    #[test]
    fn a_slow_start_transient_does_not_hide_a_later_stretch() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let t: Vec<f64> = (0..600).map(|i| 0.01 * i as f64).collect();
        let e: Vec<f64> = t
            .iter()
            .map(|&x| {
                let start = 5.0 * (-x / 0.15).exp();
                let stretch = if (3.0..3.5).contains(&x) { 3.0 } else { 0.0 };
                start + stretch + crate::optim::stats::gauss(&mut rng)
            })
            .collect();
        let tau = noise_time(&t, &e);
        assert!(tau < 1.5, "{tau}");
        // The stretch, looked for after the transient, the floor from a
        // hundred samples (a second before the input).
        let (t1, e1) = (&t[100..], &e[100..]);
        let w = worst_window(t1, scored_from(t1[0]), e1, 1.0, tau, 100, true).unwrap();
        assert!(w.significant && (2.75..=3.25).contains(&w.start), "{w:?}");
        let whole = correlation_time(&e);
        let hidden = worst_window(t1, scored_from(t1[0]), e1, 1.0, whole, 100, true).unwrap();
        assert!(!hidden.significant, "τ {whole}: {hidden:?}");
    }

    /// A persistent error does not excuse itself. A residual of white
    /// noise σ = 1 plus a step of 2 halfway through 800 samples (a sideslip
    /// twice the model's from a step steer on): its mean is 1, its noise
    /// white (τ = 1), so the standard error is √(σ² + 1)/√800 = 0.0500
    /// (the scatter about the mean counts the step's ±1 too) and the bias
    /// 20 standard errors over 800 effective samples. The whole residual's
    /// correlation time, the step counted as noise, leaves a few dozen
    /// samples and the bias under the 4 standard errors.
    #[test]
    fn a_step_in_the_residual_is_a_bias_over_the_noise_s_samples() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(11);
        let t: Vec<f64> = (0..800).map(|i| 0.01 * i as f64).collect();
        let noise: Vec<f64> = t
            .iter()
            .map(|_| crate::optim::stats::gauss(&mut rng))
            .collect();
        // The noise exactly of mean 0 and sd 1: the closed form holds to the sample.
        let m = mean(&noise);
        let sd = (noise.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / 800.0).sqrt();
        let e: Vec<f64> = noise
            .iter()
            .enumerate()
            .map(|(i, x)| (x - m) / sd + if i >= 400 { 2.0 } else { 0.0 })
            .collect();
        let b = bias_test(&t, &e, 1.0, FloorCounting::White, true);
        let closed = 2.0_f64.sqrt() / 800.0_f64.sqrt();
        assert!(b.effective_samples > 600.0, "{b:?}");
        assert!(
            (b.standard_error / closed - 1.0).abs() < 0.15,
            "{b:?} against {closed}"
        );
        assert!(b.significant && b.standard_errors > 17.0, "{b:?}");
        // The whole residual's correlation time, the step counted as noise.
        let whole = correlation_time(&e);
        let old = 1.0 / (2.0 * whole / 800.0).sqrt();
        assert!(800.0 / whole < 0.1 * b.effective_samples, "τ {whole}");
        assert!(
            old < BIAS_STANDARD_ERRORS,
            "τ {whole}: {old} standard errors"
        );
    }

    /// A noise-free residual: a constant offset of two floors' tenths and a
    /// smooth wiggle far below the floor. The floor is white by its
    /// definition, so the offset is 0.2·√800 ≈ 5.7 standard errors over all
    /// 800 samples, not a bias hidden by the wiggle's long correlation time.
    #[test]
    fn an_offset_on_a_noise_free_residual_is_judged_by_the_white_floor() {
        let t: Vec<f64> = (0..800).map(|i| 0.01 * i as f64).collect();
        let e: Vec<f64> = t
            .iter()
            .map(|&t| 0.2 + 1e-4 * (2.0 * std::f64::consts::PI * 0.3 * t).sin())
            .collect();
        let b = bias_test(&t, &e, 1.0, FloorCounting::White, true);
        assert!(b.significant, "{b:?}");
        assert!(
            (b.standard_errors - 0.2 * 800f64.sqrt()).abs() < 0.01,
            "{b:?}"
        );
        assert!((b.effective_samples - 800.0).abs() < 1.0, "{b:?}");
    }

    /// Pure white noise about zero is no bias: its noise time is one sample.
    #[test]
    fn white_noise_is_no_bias() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        let t: Vec<f64> = (0..800).map(|i| 0.01 * i as f64).collect();
        let mut alarms = 0;
        for _ in 0..200 {
            let e: Vec<f64> = t
                .iter()
                .map(|_| crate::optim::stats::gauss(&mut rng))
                .collect();
            alarms += usize::from(bias_test(&t, &e, 1.0, FloorCounting::White, true).significant);
        }
        assert!(alarms <= 1, "{alarms} of 200");
    }

    #[test]
    fn a_smooth_step_delayed_by_a_tenth_of_a_second_reads_that_shift() {
        let dt = 0.01;
        let step = |x: f64| 1.0 - (-(x - 1.0).max(0.0) / 0.15).exp();
        let t: Vec<f64> = (0..600).map(|i| i as f64 * dt).collect();
        let sim: Vec<f64> = t.iter().map(|&x| step(x)).collect();
        for shift in [0.1, -0.043, 0.237] {
            let meas: Vec<f64> = t.iter().map(|&x| step(x - shift)).collect();
            let s = time_shift(dt, &meas, &sim).unwrap();
            assert!((s - shift).abs() < 0.2 * dt, "{shift}: {s}");
        }
        // Nothing to align: noise alone.
        let flat = vec![0.0; 600];
        assert_eq!(time_shift(dt, &flat, &sim), None);
    }

    /// First-order noise `x_i = ρ x_{i−1} + √(1 − ρ²) w_i` of unit
    /// variance, `n` samples, its correlation time `time` samples.
    fn first_order(rng: &mut rand_chacha::ChaCha8Rng, n: usize, time: f64) -> Vec<f64> {
        let rho = (-1.0 / time).exp();
        let k = (1.0 - rho * rho).sqrt();
        let mut x = crate::optim::stats::gauss(rng);
        (0..n)
            .map(|_| {
                x = rho * x + k * crate::optim::stats::gauss(rng);
                x
            })
            .collect()
    }

    /// First-order noise of correlation time 0.5, 1 and 3 s sampled at
    /// 100 Hz for 300 s: its effective sample count is `n(1 − ρ)/(1 + ρ)`
    /// (50 to 300 of 30,000), read within 15 % on average, and it is no
    /// bias (none of 20 runs each). The quarter-second mean alone counted
    /// thousands of samples and called most of them a bias.
    #[test]
    fn a_first_order_noise_counts_its_closed_form_samples_and_is_no_bias() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(17);
        let n = 30_000;
        let t: Vec<f64> = (0..n).map(|i| 0.01 * i as f64).collect();
        let mut alarms = 0;
        let mut old_alarms = 0;
        for seconds in [0.5_f64, 1.0, 3.0] {
            let rho = (-0.01 / seconds).exp();
            let closed = n as f64 * (1.0 - rho) / (1.0 + rho);
            let mut ratios = Vec::new();
            for _ in 0..20 {
                let e = first_order(&mut rng, n, seconds / 0.01);
                let b = bias_test(&t, &e, 0.0, FloorCounting::White, true);
                ratios.push(b.effective_samples / closed);
                alarms += usize::from(b.significant);
                let old = noise_time(&t, &e);
                let m = e.iter().sum::<f64>() / n as f64;
                let sd = (e.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / n as f64).sqrt();
                let z = m.abs() / (sd * (old / n as f64).sqrt());
                old_alarms += usize::from(z > BIAS_STANDARD_ERRORS);
            }
            // Each within the scatter of a count read from 100 to 600
            // correlation times; their mean within 15 % of the closed form.
            let mean = ratios.iter().sum::<f64>() / ratios.len() as f64;
            assert!((0.85..1.15).contains(&mean), "{seconds} s: {ratios:?}");
            assert!(
                ratios.iter().all(|r| (0.6..1.6).contains(r)),
                "{seconds} s: {ratios:?}"
            );
        }
        assert!(alarms == 0, "{alarms} of 60");
        assert!(
            old_alarms > 30,
            "the quarter-second count: {old_alarms} of 60"
        );
    }
}
