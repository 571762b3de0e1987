//! The longitudinal acceleration of a measured run: its `ax` channel when
//! it has one, else the derivative of its logged speed, smoothed
//! ([`speed_derivative`]). Every job that replays a measured run takes its
//! acceleration from here ([`crate::sim::Drive::replay`]), never from a raw
//! difference of the speed.
//!
//! Why smoothed: a speed logged with noise σ at sample interval h has a
//! first difference whose noise is `√2·σ/h` — 0.03 m/s at 100 Hz is
//! 4.2 m/s² RMS of acceleration that never happened, which the
//! longitudinal effects (load transfer `m·ax·h/l`, the friction circle's
//! `m·ax`) would turn into force. The physics needs a few hertz at most:
//! the model's longitudinal effects are quasi-static in ax, the body's
//! pitch mode (1–2 Hz) filters the load transfer of a real car above that,
//! and brake applications and releases take 0.2–0.5 s.
//!
//! The derivative chosen: a local quadratic least-squares fit of the speed
//! against time over a window of [`SPEED_DERIVATIVE_WINDOW`] (0.5 s)
//! centred on each sample, whose slope at the sample is the estimate — the
//! Savitzky–Golay derivative (Savitzky & Golay, *Anal. Chem.* 36(8),
//! 1627–1639, 1964; its frequency response: Schafer, *IEEE Signal
//! Processing Magazine* 28(4), 111–117, 2011), written as a fit in time so
//! that it takes any (irregular) sampling. Quadratic rather than linear:
//! for a first derivative an odd order difference `p − ν = 1` keeps the
//! bias at the ends of a run of the same order as inside it (Fan &
//! Gijbels, *Local Polynomial Modelling and Its Applications*, 1996,
//! §3.3); within half a window of either end the window is shifted to lie
//! inside the run (its full width kept), not shortened.
//!
//! What it does, inside a run sampled evenly (the slope of the centred fit
//! equals the centred linear fit's, `Σ τ·u / Σ τ²`):
//! - noise: `σ·√(12/(n·W²))` for n samples over W — 0.03 m/s at 100 Hz
//!   (n = 51) gives 0.029 m/s² RMS (about four times that within half a
//!   window of the ends, where the fit extrapolates to its edge);
//! - band: gain `3(sin x − x·cos x)/x³` (x = π·f·W) on the true
//!   derivative: 0.94 at 0.5 Hz, 0.77 at 1 Hz, −3 dB at 1.15 Hz, zero at
//!   2.86 Hz, sidelobes below 9 %; zero phase (a symmetric fit);
//! - exact for a speed that is quadratic in time over the window (a
//!   constant acceleration, a linear change of it).

use super::MeasuredRun;
use crate::stats::least_squares_parabola;

/// Width of the local fit of [`speed_derivative`], s.
pub(crate) const SPEED_DERIVATIVE_WINDOW: f64 = 0.5;

impl MeasuredRun {
    /// The run's longitudinal acceleration at its samples, m/s²: its `ax`
    /// channel when it has one, else [`speed_derivative`] of its speed.
    pub(crate) fn longitudinal_acceleration(&self) -> Vec<f64> {
        match &self.ax {
            Some(ax) => ax.clone(),
            None => speed_derivative(&self.t, &self.speed),
        }
    }
}

/// The derivative of `speed` (sampled at increasing times `t`) at each
/// sample, m/s²: the slope there of the least-squares quadratic in time
/// over the [`SPEED_DERIVATIVE_WINDOW`] centred on it (shifted to lie
/// inside the run near its ends; the whole run when it is shorter). A
/// window of two samples gives their slope, of one sample zero.
pub(crate) fn speed_derivative(t: &[f64], speed: &[f64]) -> Vec<f64> {
    assert_eq!(t.len(), speed.len(), "one speed per time");
    let n = t.len();
    if n < 2 {
        return vec![0.0; n];
    }
    (0..n).map(|k| slope_at_sample(t, speed, k)).collect()
}

/// [`speed_derivative`] at sample `k` (of at least two).
fn slope_at_sample(t: &[f64], speed: &[f64], k: usize) -> f64 {
    let n = t.len();
    let half = 0.5 * SPEED_DERIVATIVE_WINDOW;
    let lo_t = (t[k] - half).min(t[n - 1] - 2.0 * half).max(t[0]);
    let hi_t = lo_t + 2.0 * half;
    // A small tolerance keeps the window's edge samples of an even grid in
    // it whatever the round-off of their times.
    let eps = 1e-9 * SPEED_DERIVATIVE_WINDOW;
    let lo = t.partition_point(|&x| x < lo_t - eps);
    let hi = t.partition_point(|&x| x <= hi_t + eps);
    local_slope(&t[lo..hi], &speed[lo..hi], t[k], speed[k])
}

/// [`speed_derivative`] linearly interpolated at time `x` (clamped to the
/// run), computed from the two samples around `x` alone: what a replay
/// evaluated at arbitrary times (an adaptive integrator's stages) reads.
/// Between samples at least [`SPARSE_SEGMENT`] apart it is the straight
/// line's slope between them.
pub(crate) fn speed_derivative_at(t: &[f64], speed: &[f64], x: f64) -> f64 {
    assert_eq!(t.len(), speed.len(), "one speed per time");
    let n = t.len();
    if n < 2 {
        return 0.0;
    }
    let at = |k: usize| slope_at_sample(t, speed, k);
    let k = t.partition_point(|&v| v <= x);
    if k == 0 {
        return at(0);
    }
    if k >= n {
        return at(n - 1);
    }
    let span = t[k] - t[k - 1];
    if span >= SPARSE_SEGMENT {
        // Samples this far apart are a drive's breakpoints (a schedule, a
        // designed run), between which the speed is linear by definition:
        // its slope is exact there, where a window of one or two samples
        // would give zero or smear a braking into the straights beside it.
        return (speed[k] - speed[k - 1]) / span;
    }
    crate::manoeuvre::interpolate(&t[k - 1..=k], &[at(k - 1), at(k)], x)
}

/// Sample interval from which [`speed_derivative_at`] takes the segment's
/// own slope, s: half the window, below which a window holds three samples
/// at least (a log at 4 Hz or faster is smoothed).
const SPARSE_SEGMENT: f64 = 0.5 * SPEED_DERIVATIVE_WINDOW;

/// Slope at `t0` of the least-squares quadratic through (`t`, `u`), in
/// coordinates centred on (`t0`, `u0`) and scaled by the window's span for
/// conditioning; the straight line's when there are two samples.
fn local_slope(t: &[f64], u: &[f64], t0: f64, u0: f64) -> f64 {
    let m = t.len();
    if m < 2 {
        return 0.0;
    }
    let span = (t[m - 1] - t[0]).max(f64::MIN_POSITIVE);
    if m == 2 {
        return (u[1] - u[0]) / span;
    }
    // y = c0 + c1·s + c2·s², s = (t − t0)/span.
    let points = t
        .iter()
        .zip(u)
        .map(|(&ti, &ui)| ((ti - t0) / span, ui - u0));
    match least_squares_parabola(points) {
        Some((c, _)) => c[1] / span,
        // Degenerate times (all equal): no slope to be had.
        None => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    use crate::identify::data::{rms, white_noise as noise};

    #[test]
    fn polynomials_of_degree_two_are_differentiated_exactly_even_at_the_ends() {
        // 3 s at an irregular 80–120 Hz.
        let mut t = vec![0.0];
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        while *t.last().unwrap() < 3.0 {
            let dt = rng.random_range(1.0 / 120.0..1.0 / 80.0);
            t.push(t.last().unwrap() + dt);
        }
        let u: Vec<f64> = t.iter().map(|&x| 20.0 - 1.5 * x + 0.4 * x * x).collect();
        for (k, a) in speed_derivative(&t, &u).iter().enumerate() {
            assert!((a - (-1.5 + 0.8 * t[k])).abs() < 1e-9, "t {}: {a}", t[k]);
        }
        // At any time, the samples' values interpolated, as a drive
        // samples them.
        let all = speed_derivative(&t, &u);
        for x in [-1.0, 0.0, 0.0123, 1.5, 2.99, t[t.len() - 1], 5.0] {
            let expected = crate::manoeuvre::interpolate(&t, &all, x);
            assert_eq!(speed_derivative_at(&t, &u, x), expected, "{x}");
        }
        // Too short for a window, and degenerate lengths.
        assert_eq!(speed_derivative(&[0.0, 0.1], &[1.0, 2.0]), [10.0, 10.0]);
        assert_eq!(speed_derivative(&[0.0], &[1.0]), [0.0]);
        assert!(speed_derivative(&[], &[]).is_empty());
    }

    #[test]
    fn noise_is_smoothed_and_a_sine_in_the_band_passes() {
        // 0.03 m/s of white noise at 100 Hz: the estimate's RMS as the
        // module's formula gives (0.029 inside, more at the ends).
        let t: Vec<f64> = (0..3001).map(|k| k as f64 * 0.01).collect();
        let u: Vec<f64> = noise(t.len(), 0.03, 7).iter().map(|e| 20.0 + e).collect();
        let a = speed_derivative(&t, &u);
        let inside = rms(&a[25..a.len() - 25]);
        assert!((0.022..0.036).contains(&inside), "{inside}");
        assert!(rms(&a) < 0.05, "{}", rms(&a));
        // A 0.5 Hz speed oscillation of 1 m/s² amplitude comes through
        // with the gain of the centred fit, Σ τ·sin(ωτ)/ω / Σ τ² over its
        // 51 samples (0.937), in phase; the continuous form of the module's
        // notes, 3(sin x − x cos x)/x³ (x = π·f·W), is within 0.003 of it.
        let w = std::f64::consts::TAU * 0.5;
        let u: Vec<f64> = t.iter().map(|&x| 20.0 + (w * x).sin() / w).collect();
        let a = speed_derivative(&t, &u);
        let taus: Vec<f64> = (-25..=25).map(|k| k as f64 * 0.01).collect();
        let gain = taus.iter().map(|s| s * (w * s).sin() / w).sum::<f64>()
            / taus.iter().map(|s| s * s).sum::<f64>();
        let x = std::f64::consts::PI * 0.5 * SPEED_DERIVATIVE_WINDOW;
        let continuous = 3.0 * (x.sin() - x * x.cos()) / x.powi(3);
        assert!((gain - 0.937).abs() < 1e-3 && (gain - continuous).abs() < 3e-3);
        for k in 25..t.len() - 25 {
            assert!((a[k] - gain * (w * t[k]).cos()).abs() < 1e-9, "t {}", t[k]);
        }
    }

    #[test]
    fn a_schedules_breakpoints_give_each_segments_own_slope() {
        // 25 m/s, braking to 15 m/s over 1.2–4 s, then held: the speed is
        // linear between breakpoints, so du/dt is each segment's slope.
        let t = [0.0, 1.0, 1.2, 4.0, 6.0];
        let u = [25.0, 25.0, 25.0, 15.0, 15.0];
        let braking = -10.0 / 2.8;
        for (x, want) in [(0.5, 0.0), (1.5, braking), (3.9, braking), (5.0, 0.0)] {
            let a = speed_derivative_at(&t, &u, x);
            assert!((a - want).abs() < 1e-12, "at {x} s: {a} against {want}");
        }
        // A dense log keeps the smoothed derivative: a constant
        // deceleration is still exact, a sample's noise is not followed.
        let t: Vec<f64> = (0..300).map(|k| k as f64 * 0.01).collect();
        let mut u: Vec<f64> = t.iter().map(|&x| 20.0 - 3.0 * x).collect();
        assert!((speed_derivative_at(&t, &u, 1.505) + 3.0).abs() < 1e-9);
        u[150] += 0.03;
        assert!((speed_derivative_at(&t, &u, 1.505) + 3.0).abs() < 0.1);
    }

    #[test]
    fn a_run_with_ax_keeps_it() {
        let t: Vec<f64> = (0..200).map(|k| k as f64 * 0.01).collect();
        let (speed, n) = (t.iter().map(|&x| 10.0 + 2.0 * x).collect(), t.len());
        let mut run =
            MeasuredRun::new("r.csv", t, speed, vec![0.0; n], vec![0.0; n]).with_ax(vec![-3.0; n]);
        assert_eq!(run.longitudinal_acceleration(), vec![-3.0; 200]);
        run.ax = None;
        for a in run.longitudinal_acceleration() {
            assert!((a - 2.0).abs() < 1e-9, "{a}");
        }
    }
}
