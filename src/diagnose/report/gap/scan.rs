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
//!   ([`crate::diagnose::model::scale::floor_counting`]): measured scatter,
//!   an unstated sideslip whose record is white however quiet (a sensor's
//!   noise), and a gyro's or accelerometer's floor (even over a smoothed or
//!   noise-free record: a low-pass leaves a white noise's mean's standard
//!   error as it was) are white noise, one draw a sample, `floor²/n`; the
//!   floor of a sideslip that reads as an estimator's output, smooth
//!   (assumed) or stated by the user, stands for the estimator's drift and
//!   misalignment, slow error, one draw for the whole run, the whole
//!   `floor²` added to the noise's part (an offset moves the residual's
//!   mean, not its scatter, so no scatter covers it): a mean is then a
//!   bias only beyond [`SLOW_BIAS_STANDARD_ERRORS`] of it, about three
//!   floors, the whole-run test's line, and beyond
//!   [`BIAS_STANDARD_ERRORS`] of the noise's part alone. The windows count
//!   the floor the same way: a slow floor is not averaged down by a
//!   window's samples either, so a window is a gap only beyond
//!   [`SLOW_BIAS_STANDARD_ERRORS`] floors with the residual's fast noise on
//!   top (`window_threshold`), and a run never reads "a gap along the run"
//!   in every window for an offset its bias test calls no bias. The
//!   counting used is reported per channel (`bias_counting`, and in the
//!   words).
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

/// The threshold of a window's RMS, noise floors, from `quantile`, the
/// F quantile of its mean square over a white floor's square. With a slow
/// floor (`slow`: the residual's fast scatter in floors), the floor is one
/// draw for the run, which no window's samples average down: a window is
/// beyond it only past [`SLOW_BIAS_STANDARD_ERRORS`] floors, the bias
/// test's slow line, with the residual's own fast noise, white, on top
/// (`√(3² + q·(σ_fast/floor)²)`; the quantiles added, conservatively, as
/// the two parts are independent). A slow floor that only the white count
/// averaged down made a sideslip half a floor off read "a gap along the
/// run" in every window beside "no bias" (Putnam).
fn window_threshold(quantile: f64, slow: Option<f64>) -> f64 {
    match slow {
        None => quantile.sqrt(),
        Some(fast) => (SLOW_BIAS_STANDARD_ERRORS.powi(2) + quantile * fast * fast).sqrt(),
    }
}

/// The residual's fast scatter in floors of `floor` where the floor counts
/// slow ([`window_threshold`]): the standard deviation of `e` less its
/// quarter-second moving mean, the noise the window test's `tau` is read
/// from. None for a white floor.
fn slow_part(t: &[f64], e: &[f64], floor: f64, counting: FloorCounting) -> Option<f64> {
    match counting {
        FloorCounting::White => None,
        FloorCounting::Slow => {
            let fast = super::drift::less_moving_mean(e, super::drift::quarter_window_samples(t));
            let var = fast.iter().map(|x| x * x).sum::<f64>() / fast.len().max(1) as f64;
            Some(var.sqrt() / floor)
        }
    }
}

/// The sliding window of the residual `e` at times `t` whose RMS is the
/// most noise floors above its threshold, the noise's autocorrelation time
/// `tau` samples and the floor (`floor`: its value and how it counts,
/// [`window_threshold`]) estimated from `floor_samples` samples (its
/// effective count `floor_samples/tau`); `resolved` false (noise-free data: a zero floor) makes
/// no window significant. The first window starts at `from` ([`scored_from`]
/// of the replay's start: one [`WINDOW`] into it).
/// None on a run shorter than two windows.
pub(super) fn worst_window(
    t: &[f64],
    from: f64,
    e: &[f64],
    (floor, counting): (f64, FloorCounting),
    tau: f64,
    floor_samples: usize,
    resolved: bool,
) -> Option<WindowGap> {
    let tau = tau.max(1.0);
    let k2 = (floor_samples as f64 / tau).max(1.0);
    let slow = slow_part(t, e, floor, counting);
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
            let threshold = window_threshold(f_quantile(k, k2, z), slow);
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
mod tests;
