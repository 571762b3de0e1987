use super::*;
use approx::assert_relative_eq;

fn grid(dt: f64, end: f64) -> Vec<f64> {
    (0..=((end / dt).round() as usize))
        .map(|i| i as f64 * dt)
        .collect()
}

/// An ideal step at t = 1 s and a response built from `f(t − 1)`.
fn record(f: impl Fn(f64) -> f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let t = grid(1e-4, 12.0);
    let steer: Vec<f64> = t
        .iter()
        .map(|&x| if x >= 1.0 { 0.02 } else { 0.0 })
        .collect();
    let y: Vec<f64> = t
        .iter()
        .map(|&x| if x >= 1.0 { f(x - 1.0) } else { 0.0 })
        .collect();
    (t, steer, y)
}

#[test]
fn pure_delay_gives_total_variance_equal_to_the_delay() {
    let d = 0.3;
    let (t, steer, y) = record(|s| if s >= d { 0.4 } else { 0.0 });
    let m = step_metrics(&t, &steer, &y, Some(&y), None, &MetricSettings::default()).unwrap();
    assert_relative_eq!(m.yaw_rate_total_variance, d, max_relative = 1e-3);
    assert_relative_eq!(m.er.unwrap(), 2.0 * d, max_relative = 1e-3);
    assert_relative_eq!(m.yaw_rate_gain, 20.0, max_relative = 1e-12);
    assert!(m.yaw_rate_peak_time.is_none() && m.yaw_rate_overshoot.is_none());
}

#[test]
fn first_order_lag_gives_half_its_time_constant() {
    let tau = 0.25;
    let (t, steer, y) = record(|s| 1.0 - (-s / tau).exp());
    let m = step_metrics(&t, &steer, &y, Some(&y), None, &MetricSettings::default()).unwrap();
    assert_relative_eq!(m.yaw_rate_total_variance, tau / 2.0, max_relative = 1e-3);
    // 90 % of a first-order lag is reached at τ·ln 10.
    assert_relative_eq!(m.yaw_rate_response_time, tau * 10f64.ln(), epsilon = 2e-4);
}

#[test]
fn second_order_overshoot_and_peak_time() {
    let (zeta, wn): (f64, f64) = (0.4, 8.0);
    let wd = wn * (1.0 - zeta * zeta).sqrt();
    let (t, steer, y) = record(|s| {
        1.0 - (-zeta * wn * s).exp() * ((wd * s).cos() + zeta * wn / wd * (wd * s).sin())
    });
    let beta: Vec<f64> = y.iter().map(|v| -0.01 * v).collect();
    let m = step_metrics(
        &t,
        &steer,
        &y,
        Some(&y),
        Some(&beta),
        &MetricSettings::default(),
    )
    .unwrap();
    let os = 100.0 * (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
    let tp = std::f64::consts::PI / wd;
    assert_relative_eq!(m.yaw_rate_overshoot.unwrap(), os, max_relative = 1e-4);
    assert_relative_eq!(m.yaw_rate_peak_time.unwrap(), tp, epsilon = 2e-4);
    assert_relative_eq!(m.beta_steady.unwrap(), -0.01, max_relative = 1e-6);
    assert_relative_eq!(
        m.tb.unwrap(),
        tp * 0.01f64.to_degrees(),
        max_relative = 1e-3
    );
    assert!(m.settled);
}

#[test]
fn mirrored_step_gives_the_same_metrics() {
    let (t, steer, y) = record(|s| 1.0 - (-s / 0.2).exp() * (1.0 + 0.3 * (9.0 * s).sin()));
    let neg = |v: &[f64]| v.iter().map(|x| -x).collect::<Vec<_>>();
    let s = MetricSettings::default();
    let a = step_metrics(&t, &steer, &y, Some(&y), Some(&y), &s).unwrap();
    let b = step_metrics(
        &t,
        &neg(&steer),
        &neg(&y),
        Some(&neg(&y)),
        Some(&neg(&y)),
        &s,
    )
    .unwrap();
    assert_eq!(a.yaw_rate_response_time, b.yaw_rate_response_time);
    assert_eq!(a.er, b.er);
    assert_eq!(a.yaw_rate_gain, b.yaw_rate_gain);
    assert_eq!(a.beta_steady.map(|x| -x), b.beta_steady);
}

#[test]
fn refuses_records_without_a_step() {
    let t = grid(0.01, 5.0);
    let z = vec![0.0; t.len()];
    let e = step_metrics(&t, &z, &z, Some(&z), None, &MetricSettings::default()).unwrap_err();
    assert!(matches!(e, MetricsError::NoStep { .. }), "{e}");
    assert_eq!(e.to_string(), "no steer step: the steer stays at 0 rad (0.00°) from the initial window to the steady one; a step steer needs a change of at least 0.00017 rad (0.01°)");
    let small: Vec<f64> = t
        .iter()
        .map(|&x| if x > 1.0 { 1e-4 } else { 0.0 })
        .collect();
    let e = step_metrics(&t, &small, &z, Some(&z), None, &MetricSettings::default()).unwrap_err();
    assert_eq!(e.to_string(), "no steer step: the steer goes from 0 rad (0.000°) in the initial window to 0.00010 rad (0.006°) in the steady one, a change of 0.00010 rad (0.006°), less than the 0.00017 rad (0.010°) a step steer needs");
    // A mean of rounding is written 0, not 8.2e-16 nor with zeros.
    let rounding: Vec<f64> = small.iter().map(|s| s + 8.2e-16).collect();
    let e = step_metrics(
        &t,
        &rounding,
        &z,
        Some(&z),
        None,
        &MetricSettings::default(),
    )
    .unwrap_err();
    assert!(
        e.to_string()
            .contains("goes from 0 rad (0.000°) in the initial window"),
        "{e}"
    );
    let e = step_metrics(
        &t[..5],
        &z[..5],
        &z[..5],
        Some(&z[..5]),
        None,
        &MetricSettings::default(),
    );
    let e = e.unwrap_err();
    assert!(matches!(e, MetricsError::Shape { .. }));
    assert_eq!(
        e.to_string(),
        "a step-steer record needs at least 10 samples with equal-length channels; it has t 5, steer 5, yaw_rate 5, ay 5"
    );
}

#[test]
fn the_zero_phase_low_pass_halves_its_cutoff_and_moves_nothing() {
    // Forward-backward: the magnitude is |H|², ½ at the cut-off, and the
    // phase is zero, so a sine's peaks stay where they are.
    let dt = 0.001;
    let t = grid(dt, 20.0);
    for (f, gain) in [(10.0, 0.5), (1.0, 1.0)] {
        let x: Vec<f64> = t
            .iter()
            .map(|&s| (std::f64::consts::TAU * f * s).sin())
            .collect();
        let y = zero_phase_low_pass(&x, dt, 10.0);
        // Away from the ends.
        let mid = &y[5000..15000];
        let amp = mid.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        assert!((amp - gain).abs() < 2e-3, "{f} Hz: {amp}");
        let i = 5000 + mid.iter().position(|v| (v - amp).abs() < 1e-12).unwrap();
        let phase = (f * t[i]).fract();
        assert!(
            (phase - 0.25).abs() < 1e-3 * f.max(1.0),
            "{f} Hz peak at phase {phase}"
        );
    }
    // A constant passes unchanged, ends included.
    let c = zero_phase_low_pass(&vec![3.5; 500], dt, 10.0);
    assert!(c.iter().all(|v| (v - 3.5).abs() < 1e-12));
}

/// Unfiltered (`--filter-hz 0`), a steady yaw rate whose gyro noise is 3 %
/// of the step was called "not settled": noise is no motion, a drift is.
#[test]
fn noise_in_the_steady_window_is_no_motion_and_a_drift_is() {
    // A deterministic white sequence (an LCG), ±√3·σ uniform: σ = 3 % of
    // the 0.4 rad/s step.
    let mut state = 12345u64;
    let mut white = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let u = (state >> 11) as f64 / (1u64 << 53) as f64;
        (2.0 * u - 1.0) * 3f64.sqrt()
    };
    let s = MetricSettings {
        filter_hz: None,
        ..MetricSettings::default()
    };
    let (t, steer, clean) = record(|s| 0.4 * (1.0 - (-s / 0.2).exp()));
    let noisy: Vec<f64> = clean.iter().map(|v| v + 0.012 * white()).collect();
    let m = step_metrics(&t, &steer, &noisy, None, None, &s).unwrap();
    assert!(m.settled, "white noise of 3 % of the step");
    // A drift of 10 % of the step over the steady window (the last 1 s):
    // a spread of 10/√12 = 2.9 % beyond the noise.
    let drifting: Vec<f64> = t
        .iter()
        .zip(&noisy)
        .map(|(&x, v)| v + 0.04 * (x - 11.0).max(0.0))
        .collect();
    let m = step_metrics(&t, &steer, &drifting, None, None, &s).unwrap();
    assert!(!m.settled, "a drift of 10 % of the step");
    // The same drift without noise: not settled either.
    let smooth: Vec<f64> = t
        .iter()
        .zip(&clean)
        .map(|(&x, v)| v + 0.04 * (x - 11.0).max(0.0))
        .collect();
    assert!(
        !step_metrics(&t, &steer, &smooth, None, None, &s)
            .unwrap()
            .settled
    );
}

/// A measured step's response time is read where its filtered yaw rate
/// crosses 90 %: 32 copies of one first-order step (τ = 0.2 s, 100 Hz),
/// each with its own gyro noise of 3 % of the step, filtered at 10 Hz as
/// `handling metrics` does, give response times within a hundredth of a
/// second of the noise-free one on average, spread by under 0.03 s, and each copy is
/// judged settled (its steady window spreads by its noise alone).
#[test]
fn yaw_rate_response_time_spread() {
    let t = grid(0.01, 8.0);
    let steer: Vec<f64> = t
        .iter()
        .map(|&x| if x >= 1.0 { 0.02 } else { 0.0 })
        .collect();
    let clean: Vec<f64> = t
        .iter()
        .map(|&x| {
            if x >= 1.0 {
                0.4 * (1.0 - (-(x - 1.0) / 0.2).exp())
            } else {
                0.0
            }
        })
        .collect();
    let s = MetricSettings {
        filter_hz: Some(10.0),
        ..MetricSettings::default()
    };
    let exact = step_metrics(&t, &steer, &clean, None, None, &s)
        .unwrap()
        .yaw_rate_response_time;
    let times: Vec<f64> = (0..32)
        .map(|seed| {
            let noise = crate::identify::data::white_noise(t.len(), 0.012, seed);
            let noisy: Vec<f64> = clean.iter().zip(&noise).map(|(v, e)| v + e).collect();
            let m = step_metrics(&t, &steer, &noisy, None, None, &s).unwrap();
            assert!(m.settled, "seed {seed}");
            m.yaw_rate_response_time
        })
        .collect();
    let mean = times.iter().sum::<f64>() / 32.0;
    let sd = (times.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / 31.0).sqrt();
    // Measured: 0.020 s (two samples) about a mean 0.002 s from the
    // noise-free 0.466 s.
    assert!(sd < 0.03, "{sd}");
    assert!((mean - exact).abs() < 0.01, "{mean} vs {exact}");
}
