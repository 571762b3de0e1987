//! Tests of the held channels (`held.rs`).
use super::super::test_signals::gauss_noise;
use super::*;

/// A run at 15 m/s with `steer` over `t` and a still gyro, nothing else
/// logged.
fn straight_at_15(t: Vec<f64>, steer: Vec<f64>) -> MeasuredRun {
    let n = t.len();
    MeasuredRun::new("r.csv", t, vec![15.0; n], steer, vec![0.0; n])
}

/// A steer held at 20 Hz in a 100 Hz log whose quantised value repeats
/// across updates on a straight: its rate is the logger's, 20 Hz, as
/// "every 5 samples" says, not the rate of its changes.
#[test]
fn a_held_channel_is_reported_at_its_updates_rate_not_its_changes() {
    let n = 3000;
    let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.01).collect();
    let update = |i: usize| {
        let s = t[i - i % 5];
        // A straight for the first 10 s: the quantised value repeats.
        let v = if s < 10.0 {
            0.0
        } else {
            0.05 * (0.7 * s).sin()
        };
        (v / 2e-4).round() * 2e-4
    };
    let mut run = straight_at_15(t.clone(), (0..n).map(update).collect());
    let mut report = CleaningReport::default();
    treat_held(&mut run, 5.0, &mut report);
    let h = &report.held[0];
    assert_eq!(h.every, 5);
    assert!((h.update_rate - 20.0).abs() < 1e-9, "{}", h.update_rate);
}

#[test]
fn a_channel_held_at_a_tenth_of_the_rate_is_interpolated_between_updates() {
    // A 0.5 Hz sine with noise, updated every 10th sample of 100 Hz.
    let n = 2000;
    let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.01).collect();
    let noise = gauss_noise(n, 1e-4, 3);
    let truth: Vec<f64> = t
        .iter()
        .map(|&s| 0.01 * (std::f64::consts::PI * s).sin())
        .collect();
    let mut x: Vec<f64> = (0..n)
        .map(|i| truth[i - i % 10] + noise[i - i % 10])
        .collect();
    let h = holds(&t, &x).expect("held");
    assert!((h.period - 0.1).abs() < 1e-9 && h.starts.len() == 200);
    let changed = interpolate(&t, &mut x, &h, &[]);
    let starts = h.starts;
    assert_eq!(changed, 199 * 9);
    // Between updates the value now follows the signal to its noise and
    // the curvature over 0.1 s (about 1e-5), where the hold was off by
    // up to its change over an interval (3e-3).
    let worst = (0..1990)
        .map(|i| (x[i] - truth[i]).abs())
        .fold(0.0, f64::max);
    assert!(worst < 6e-4, "{worst}");
    // The updates themselves are unchanged.
    assert!(starts.iter().all(|&i| x[i] == truth[i] + noise[i]));
}

#[test]
fn noise_a_quantised_channel_and_a_constant_are_not_held() {
    let x = gauss_noise(3000, 0.01, 4);
    let t: Vec<f64> = (0..3000).map(|i| i as f64 * 0.01).collect();
    assert!(holds(&t, &x).is_none());
    // A steer encoder of 0.001 rad on a slow irregular sine: holds of
    // every length.
    let q: Vec<f64> = (0..3000)
        .map(|i| {
            let s = i as f64 * 0.01;
            (0.02 * (0.3 * s).sin() * (1.0 + 0.5 * (0.07 * s).sin()) / 0.001).round() * 0.001
        })
        .collect();
    assert!(holds(&t, &q).is_none());
    assert!(holds(&t, &[0.5; 3000]).is_none());
}

#[test]
fn a_smooth_channel_repeating_or_dithering_in_its_last_digit_is_not_held() {
    let t: Vec<f64> = (0..3000).map(|i| i as f64 * 0.01).collect();
    // A slow ramp written to its last digit (1e-5), crossing one every
    // 2.2 samples or so: holds of 2 and 3 samples, as regular as a
    // channel updated every 2.
    let ramp: Vec<f64> = (0..3000)
        .map(|i| {
            let i = i as f64;
            (0.45 * i + 40.0 * (i / 700.0).sin()).round() * 1e-5
        })
        .collect();
    assert!(holds(&t, &ramp).is_none());
    // A slow exponential so written: holds of 1, 2, 3 samples and more
    // (at 1 m/s, 83 % of a simulated sideslip's holds were within one
    // sample of 2, a third of them of 1 sample).
    let slow: Vec<f64> = (0..3000)
        .map(|i| {
            let v = 0.0113 * (1.0 - (-(i as f64) / 900.0).exp()) + 0.01;
            (v * 1e5).round() / 1e5
        })
        .collect();
    assert!(holds(&t, &slow).is_none());
    // A steady value dithering by one unit of its last digit, 4 samples
    // a side: regular holds, every update a return.
    let dither: Vec<f64> = (0..3000)
        .map(|i| 0.003_138_641_3 + if (i / 4) % 2 == 0 { 0.0 } else { 1e-11 })
        .collect();
    assert!(holds(&t, &dither).is_none());
}

/// A steer updated at 20 Hz in a log at 100 Hz for 30 s, then at
/// 50 Hz: holds of 5 samples, then of 3 and 2 (0.06 s, 0.04 s).
#[test]
fn a_channel_held_at_20_hz_in_a_log_whose_rate_halves_is_held_throughout() {
    let mut t: Vec<f64> = (0..3000).map(|i| i as f64 * 0.01).collect();
    t.extend((0..1500).map(|i| 30.0 + i as f64 * 0.02));
    // The update each sample holds: every 5th sample, then every 2.5th.
    let update = |i: usize| {
        if i < 3000 {
            i / 5
        } else {
            600 + 2 * (i - 3000) / 5
        }
    };
    let x: Vec<f64> = (0..t.len())
        .map(|i| 0.05 * (0.6 * std::f64::consts::PI * update(i) as f64 * 0.05).sin())
        .collect();
    let h = holds(&t, &x).expect("held");
    // The mean of the holds near the median (0.05 s, 0.06 s, 0.04 s): as
    // many of 3 samples as of 2, to one.
    assert!((h.period / 0.05 - 1.0).abs() < 5e-4, "{}", h.period);
    assert!(rate_changes(&t, super::super::median_interval(&t)));
    assert!(!rate_changes(&t[..3000], 0.01));
    let mut run = straight_at_15(t.clone(), x);
    let mut report = CleaningReport::default();
    treat_held(&mut run, 5.0, &mut report);
    let h = &report.held[0];
    assert!(h.log_rate_changes && (h.update_rate / 20.0 - 1.0).abs() < 5e-4);
    // Interpolated in time between the updates' instants: update 900
    // read at 45.00 s, 901 first read at 45.06 s but made at 45.05 s,
    // so 45.02 s is two fifths of the way.
    let k = 3000 + 750;
    assert!((run.t[k] - 45.0).abs() < 1e-9);
    let (a, b) = (
        0.05 * (0.6 * std::f64::consts::PI * 45.0).sin(),
        0.05 * (0.6 * std::f64::consts::PI * 45.05).sin(),
    );
    // To the clock's period's error over the window (2e-4 s, 2e-5 rad),
    // where a third of the way is (b − a)/15 = 3e-4 rad off.
    assert!((run.steer[k + 1] - (3.0 * a + 2.0 * b) / 5.0).abs() < 5e-5);
}

/// A 1.3 Hz sine updated at `rate` Hz (from `phase` s) read in a log at
/// `log` Hz for 20 s: the rate and the true signal between updates.
fn held_sine(rate: f64, log: f64, phase: f64) -> (f64, f64) {
    let n = (20.0 * log) as usize;
    let t: Vec<f64> = (0..n).map(|i| i as f64 / log).collect();
    let truth = |s: f64| 0.05 * (2.6 * std::f64::consts::PI * s).sin();
    // The last update at or before each sample.
    let steer = t
        .iter()
        .map(|&s| truth(((s - phase) * rate + 1e-9).floor() / rate + phase))
        .collect();
    let mut run = straight_at_15(t.clone(), steer);
    let mut report = CleaningReport::default();
    treat_held(&mut run, 5.0, &mut report);
    // Linear between updates: off by the curvature over an update,
    // below 0.05·(2.6π)²/8·(1/rate)² (0.0026 rad at 20 Hz).
    let worst = (n / 10..n - n / 10)
        .map(|i| (run.steer[i] - truth(t[i])).abs())
        .fold(0.0, f64::max);
    (report.held[0].update_rate, worst)
}

/// A 20 Hz steer in a 50 Hz log, held for 3 samples and 2 in turn, was
/// read at 16.7 Hz (the median hold, 0.06 s) and interpolated between
/// the samples where it changed, half of them 0.01 s after the update:
/// now 20 Hz, and the signal between the updates' instants. So a 30 Hz
/// steer in a 100 Hz log (holds of 3, 3 and 4) and one whose updates
/// fall between samples.
#[test]
fn a_steer_at_20_hz_in_a_50_hz_log_is_at_20_hz_and_interpolated_at_its_instants() {
    let bound = |rate: f64| 0.05 * (2.6 * std::f64::consts::PI).powi(2) / 8.0 / rate / rate;
    for (rate, log) in [(20.0, 50.0), (30.0, 100.0)] {
        let (r, worst) = held_sine(rate, log, 0.0);
        assert!((r / rate - 1.0).abs() < 2e-3, "{rate} in {log}: {r}");
        assert!(worst < 1.05 * bound(rate), "{rate} in {log}: {worst}");
    }
    // Updates 0.007 s before a sample, then 0.017 s: the clock's phase
    // is known to the cycle's step in lateness (0.01 s), and the
    // instants put up to that late, no later.
    let (r, worst) = held_sine(20.0, 50.0, 0.013);
    let step = 0.05 * 2.6 * std::f64::consts::PI * 0.007;
    assert!((r / 20.0 - 1.0).abs() < 2e-3, "{r}");
    assert!(worst < 1.05 * (bound(20.0) + step), "{worst}");
    // Between the changes' samples the error was the signal's change
    // over up to a sample interval late (0.05·2.6π·0.01 = 0.004 rad).
    assert!(0.05 * 2.6 * std::f64::consts::PI * 0.01 > 1.5 * bound(20.0));
}

/// A steer at 20 Hz in a 100 Hz log, quantised to 1e-4 rad, that
/// leaves a straight (0) and its stop (±0.05 rad) along quarter sines
/// of 1 s: the hold of a straight or a stop is many updates of one
/// value, and the value stays until the last of them. Ramped over the
/// whole hold, the steer on a straight ran ahead by up to its next
/// update's value (0.05·sin(π/2·0.05) = 0.0039 rad).
#[test]
fn a_held_steer_stays_on_a_straight_and_at_its_stop_until_its_last_repeat() {
    let (a, res, p) = (0.05, 1e-4, 0.05);
    // Cycles of 6.05 s, the sign turning each: 2 s straight, a quarter
    // sine up to the stop, 2 s at it, a quarter sine back over 1.05 s
    // (the kinks, at the straight's ends, on update instants).
    let truth = |s: f64| {
        let (c, sign) = (
            s % 6.05,
            if ((s / 6.05) as usize).is_multiple_of(2) {
                a
            } else {
                -a
            },
        );
        let q = |x: f64| (std::f64::consts::FRAC_PI_2 * x).sin();
        sign * match c {
            c if c < 2.0 => 0.0,
            c if c < 3.0 => q(c - 2.0),
            c if c < 5.0 => 1.0,
            c => q((6.05 - c) / 1.05),
        }
    };
    let t: Vec<f64> = (0..4800).map(|i| i as f64 * 0.01).collect();
    let steer = t
        .iter()
        .map(|&s| (truth((s / p + 1e-9).floor() * p) / res).round() * res)
        .collect();
    let mut run = straight_at_15(t.clone(), steer);
    let mut report = CleaningReport::default();
    treat_held(&mut run, 5.0, &mut report);
    assert!((report.held[0].update_rate / 20.0 - 1.0).abs() < 2e-3);
    // Off by the quantisation at each end (res/2) and the curvature
    // over an update, a·(π/2)²/8·p² = 3.9e-5 rad.
    let bound = res + a * std::f64::consts::FRAC_PI_2.powi(2) / 8.0 * p * p;
    let (worst, at) = (0..4780)
        .map(|i| ((run.steer[i] - truth(t[i])).abs(), t[i]))
        .fold((0.0, 0.0), |m, e| if e.0 > m.0 { e } else { m });
    assert!(worst < bound, "{worst} rad at {at} s");
}

/// A steer at 20 Hz in a 100 Hz log (a 0.5 Hz sine of 0.05 rad,
/// clipped at ±0.04 rad: stops of 8 updates, left with an ordinary
/// step) stuck at its 20.00 s update for 8 updates: one stuck glitch,
/// the 39 repeats, repaired; the stops at the limit are none.
#[test]
fn a_held_steer_stuck_for_eight_updates_is_stuck_and_its_stops_at_a_limit_are_not() {
    let n = 6000;
    let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.01).collect();
    let at = |u: usize| {
        let v = 0.05 * (std::f64::consts::PI * u as f64 * 0.05).sin();
        (v.clamp(-0.04, 0.04) / 2e-4).round() * 2e-4
    };
    let mut steer: Vec<f64> = (0..n).map(|i| at(i / 5)).collect();
    let frozen = steer[2000];
    steer[2000..2040].iter_mut().for_each(|s| *s = frozen);
    let mut run = straight_at_15(t.clone(), steer);
    let mut report = CleaningReport::default();
    treat_held(&mut run, 5.0, &mut report);
    assert_eq!(report.counts.stuck, 1, "{:?}", report.glitches);
    let g = &report.glitches[0];
    assert!((g.t - 20.01).abs() < 1e-9 && g.samples == 39, "{g:?}");
    assert_eq!(g.treatment, Treatment::Repaired);
    assert_eq!(report.samples_repaired, 39);
    // The stuck repeats counted as repaired, not as held samples.
    let mut x: Vec<f64> = (0..n).map(|i| at(i / 5)).collect();
    x[2000..2040].iter_mut().for_each(|s| *s = frozen);
    let h = holds(&t, &x).expect("held");
    let all = interpolate(&t, &mut x, &h, &[]);
    assert_eq!(report.held[0].samples, all - 39);
    assert_eq!(report.samples_interpolated, all - 39);
}
