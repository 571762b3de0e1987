//! Tests of the judgement of a steer's exact holds (`steer_hold.rs`).
use super::super::test_signals::{gauss_noise, no_slow};
use super::*;

/// Putnam's steer quantum, rad.
const Q: f64 = 0.000581;
/// Curvature per steer of the synthetic car, 1/m per rad (Putnam's
/// corners: 0.26).
const GAIN: f64 = 0.27;

fn quantised(v: f64) -> f64 {
    (v / Q).round() * Q
}

/// A steady turn at 13 m/s logged at 25 Hz: the true steer 0.035 rad
/// wandering by ±0.0004 rad with 0.00015 rad of noise, read by a sensor
/// of quantum [`Q`]; the yaw rate the steady response to the true steer
/// (`turn(k)` added to it from sample `k`) with 0.0008 rad/s of noise.
/// The logged steer holds its level at `hold` from its first sample.
fn steady_turn(hold: std::ops::Range<usize>, turn: impl Fn(usize) -> f64) -> MeasuredRun {
    let n = 600;
    let t: Vec<f64> = (0..n).map(|k| k as f64 * 0.04).collect();
    let (e, w) = (gauss_noise(n, 0.00015, 3), gauss_noise(n, 0.0008, 4));
    let truth: Vec<f64> = (0..n)
        .map(|k| 0.035 + 0.0004 * (0.7 * t[k]).sin() + e[k] + turn(k))
        .collect();
    let mut steer: Vec<f64> = truth.iter().map(|&v| quantised(v)).collect();
    let level = steer[hold.start];
    steer[hold].iter_mut().for_each(|v| *v = level);
    let yaw = (0..n).map(|k| GAIN * 13.0 * truth[k] + w[k]).collect();
    MeasuredRun::new("r.csv", t, vec![13.0; n], steer, yaw)
}

/// Six quanta more, reached linearly over the eight samples from 300.
fn turned_at_300(k: usize) -> f64 {
    6.0 * Q * ((k as f64 - 300.0) / 8.0).clamp(0.0, 1.0)
}

#[test]
fn the_quantum_is_the_common_step_and_noise_has_none() {
    // A quantised dither with a resampled log's values between levels on
    // two samples in five.
    let e = gauss_noise(3000, 0.0006, 7);
    let x: Vec<f64> = (0..3000)
        .map(|k| match k % 5 {
            0 | 1 => 0.03 + e[k],
            _ => quantised(0.03 + e[k]),
        })
        .collect();
    let q = quantum(&x);
    assert!((q / Q - 1.0).abs() < 0.01, "{q}");
    assert_eq!(quantum(&gauss_noise(3000, 0.0006, 8)), 0.0);
}

/// The steer read within its quantum in a steady corner, the car's
/// curvature where the held level puts it: no stuck sensor. The same hold
/// while the wheel turns by six quanta (the yaw rate follows, the sensor
/// resumes at the new level): stuck, by the car's state alone, its trend
/// (six quanta over the hold and its context, 2.7 over the hold) short of
/// [`TREND_QUANTA`].
#[test]
fn a_hold_within_the_quantum_in_a_steady_turn_is_no_stuck_sensor_but_one_the_car_turns_from_is() {
    let steady = steady_turn(300..308, |_| 0.0);
    let s = SteerScale::of(&steady, &no_slow(600));
    assert!((s.quantum / Q - 1.0).abs() < 0.01, "{s:?}");
    let g = s.gain.unwrap();
    assert!((g / GAIN - 1.0).abs() < 0.05, "{s:?}");
    assert!(!state_moves(&steady, &s, 300, 308));
    assert!(!long_against_trend(&steady.steer, 300, 308, s.quantum));
    assert!(!stuck_steer(&steady, &s, 300, 8));
    let turned = steady_turn(300..308, turned_at_300);
    let s = SteerScale::of(&turned, &no_slow(600));
    assert!(repair_exceeds(
        &turned.t,
        &turned.steer,
        300,
        308,
        s.quantum
    ));
    assert!(state_moves(&turned, &s, 300, 308));
    assert!(!long_against_trend(&turned.steer, 300, 308, s.quantum));
    assert!(stuck_steer(&turned, &s, 300, 8));
}

/// A quantised steer ramping through zero at 0.3 quanta a sample, the yaw
/// rate at 0 (the car's state says nothing of it): held for 12
/// samples, its trend crosses 3.6 quanta meanwhile, stuck; held for 6,
/// 1.8 quanta, a hold its own pace gives. The repair of either exceeds
/// the quantum.
#[test]
fn a_hold_long_against_the_steers_own_trend_is_stuck_and_a_short_one_is_not() {
    let n = 400;
    let t: Vec<f64> = (0..n).map(|k| k as f64 * 0.04).collect();
    let ramp = |hold: std::ops::Range<usize>| {
        let mut x: Vec<f64> = (0..n)
            .map(|k| quantised(0.3 * Q * (k as f64 - 200.0)))
            .collect();
        let level = x[hold.start];
        x[hold].iter_mut().for_each(|v| *v = level);
        MeasuredRun::new("r.csv", t.clone(), vec![25.0; n], x, vec![0.0; n])
    };
    for (len, stuck) in [(12, true), (6, false)] {
        let run = ramp(196..196 + len);
        let s = SteerScale::of(&run, &no_slow(n));
        assert!(!state_moves(&run, &s, 196, 196 + len), "{s:?}");
        assert!(repair_exceeds(
            &run.t,
            &run.steer,
            196,
            196 + len,
            s.quantum
        ));
        assert_eq!(
            long_against_trend(&run.steer, 196, 196 + len, s.quantum),
            stuck,
            "{len}"
        );
        assert_eq!(stuck_steer(&run, &s, 196, len), stuck, "{len}");
    }
}

/// A repair that moves no sample by more than the quantum is none: the
/// held level already reads the steer to its resolution.
#[test]
fn a_repair_within_the_quantum_is_no_repair() {
    let t: Vec<f64> = (0..12).map(|k| k as f64 * 0.04).collect();
    let x = |after: f64| {
        let mut v = vec![0.01 - 0.5 * Q; 2];
        v.extend([0.01; 8]);
        v.extend([0.01 + after; 2]);
        v
    };
    assert!(!repair_exceeds(&t, &x(0.9 * Q), 2, 10, Q));
    assert!(repair_exceeds(&t, &x(2.0 * Q), 2, 10, Q));
    // No quantum: any repair is one.
    assert!(repair_exceeds(&t, &x(0.1 * Q), 2, 10, 0.0));
}
