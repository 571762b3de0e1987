//! Tests of the glitch detection (`glitches.rs`).
use super::super::test_signals::{gauss_noise, no_slow};
use super::*;

/// A noisy channel that holds its last value to the end of the record
/// is stuck from where the hold starts, and its noise before is no
/// spike; a noise-free smooth signal that ends level, a short hold at
/// the end and a parked end are not stuck.
#[test]
fn a_hold_to_the_end_of_a_noisy_channel_is_stuck_and_its_noise_no_spike() {
    for seed in 0..10 {
        let mut x = gauss_noise(600, 0.01, seed);
        let held = x[199];
        x[200..].iter_mut().for_each(|v| *v = held);
        let found = detect(&x, &no_slow(600));
        assert_eq!(found.len(), 1, "seed {seed}: {found:?}");
        assert_eq!((found[0].start, found[0].len), (199, 401), "seed {seed}");
        assert_eq!(found[0].kind, GlitchKind::Stuck);
        // Parked from where it holds: a stopped car, not a sensor.
        let slow: Vec<bool> = (0..600).map(|i| i >= 199).collect();
        assert!(detect(&x, &slow).is_empty(), "seed {seed}");
        // Three samples alike at the end are chance, not a hold.
        let mut y = gauss_noise(600, 0.01, seed);
        y[597..].iter_mut().for_each(|v| *v = 0.5);
        assert!(
            frozen_tail(&y, &no_slow(600), &[false; 600]).is_none(),
            "seed {seed}"
        );
    }
    // A first-order rise, noise-free, reaching its level in doubles.
    let smooth: Vec<f64> = (0..600)
        .map(|i| (1.0 - (-(i as f64) / 20.0).exp()).min(0.999))
        .collect();
    assert!(frozen_tail(&smooth, &no_slow(600), &[false; 600]).is_none());
}

#[test]
fn white_noise_a_step_and_a_sweep_have_no_glitch() {
    for seed in 0..20 {
        let x = gauss_noise(5000, 0.01, seed);
        assert!(detect(&x, &no_slow(5000)).is_empty(), "seed {seed}");
    }
    // A step steer with a 0.1 s ramp at 100 Hz, noise-free and noisy.
    let t: Vec<f64> = (0..1000).map(|i| i as f64 * 0.01).collect();
    let step: Vec<f64> = t
        .iter()
        .map(|&x| 0.03 * ((x - 2.0) / 0.1).clamp(0.0, 1.0))
        .collect();
    assert!(detect(&step, &no_slow(1000)).is_empty());
    let sharp: Vec<f64> = t
        .iter()
        .map(|&x| if x >= 2.0 { 0.03 } else { 0.0 })
        .collect();
    assert!(detect(&sharp, &no_slow(1000)).is_empty());
    let noise = gauss_noise(1000, 2e-4, 3);
    let noisy: Vec<f64> = step.iter().zip(&noise).map(|(a, b)| a + b).collect();
    assert!(detect(&noisy, &no_slow(1000)).is_empty());
    // A noise-free first-order response written with six decimals (it
    // settles to a held value) and a steer dwell between ramps.
    let settled: Vec<f64> = t
        .iter()
        .map(|&x| {
            let r = if x > 2.0 {
                0.2 * (1.0 - (-(x - 2.0) / 0.15).exp())
            } else {
                0.0
            };
            (r * 1e6).round() / 1e6
        })
        .collect();
    assert!(detect(&settled, &no_slow(1000)).is_empty());
    let dwell: Vec<f64> = t
        .iter()
        .map(|&x| 0.05 * (x - 1.0).clamp(0.0, 1.0) - 0.05 * (x - 4.0).clamp(0.0, 2.0))
        .collect();
    assert!(detect(&dwell, &no_slow(1000)).is_empty());
    // A spike after the dwell is a spike; the holds around it are not
    // made stuck by it.
    let mut spiked = dwell.clone();
    spiked[800] += 0.02;
    let f = detect(&spiked, &no_slow(1000));
    assert_eq!(
        f,
        vec![Found {
            start: 800,
            len: 1,
            kind: GlitchKind::Spike
        }]
    );
    // A sine sweep 0.1–4 Hz at 100 Hz (and at 25 Hz), with noise.
    for dt in [0.01, 0.04] {
        let n = (30.0 / dt) as usize;
        let noise = gauss_noise(n, 1e-3, 5);
        let sweep: Vec<f64> = (0..n)
            .map(|i| {
                let x = i as f64 * dt;
                0.05 * (std::f64::consts::TAU * (0.1 * x + 0.065 * x * x)).sin() + noise[i]
            })
            .collect();
        assert!(detect(&sweep, &no_slow(n)).is_empty(), "dt {dt}");
    }
}

#[test]
fn a_channel_held_at_zero_while_parked_leaves_the_driving_noise_alone() {
    // 6 s of driving, 30 s parked with the sideslip read as exactly 0
    // (as a GPS-derived one is), 6 s of driving, at 100 Hz: the
    // parked zeros once made the spread of the differences 0 and 800
    // ordinary noise samples "spikes".
    let (drive, parked) = (600, 3000);
    let n = 2 * drive + parked;
    let noise = gauss_noise(n, 0.002, 5);
    let slow: Vec<bool> = (0..n)
        .map(|i| (drive..drive + parked).contains(&i))
        .collect();
    let x: Vec<f64> = (0..n)
        .map(|i| if slow[i] { 0.0 } else { 0.01 + noise[i] })
        .collect();
    assert!(detect(&x, &slow).is_empty());
    // A real spike in the driving is still found, and a spike while
    // parked (excluded with its span) is not reported.
    let mut y = x.clone();
    y[300] += 0.05;
    y[drive + 100] = 0.05;
    let found = detect(&y, &slow);
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!((found[0].start, found[0].kind), (300, GlitchKind::Spike));
}

#[test]
fn each_glitch_kind_is_found_at_its_sample() {
    let n = 2000;
    let base: Vec<f64> = (0..n)
        .map(|i| 0.2 + 0.1 * (i as f64 * 0.01).sin())
        .zip(gauss_noise(n, 0.002, 9))
        .map(|(a, b)| a + b)
        .collect();
    let mut x = base.clone();
    x[400] = 0.0;
    x[900] += 0.1;
    for v in &mut x[1300..1306] {
        *v = 0.25;
    }
    x[n - 1] = 0.0;
    let f = detect(&x, &no_slow(n));
    let got: Vec<(usize, usize, GlitchKind)> = f.iter().map(|f| (f.start, f.len, f.kind)).collect();
    assert_eq!(
        got,
        vec![
            (400, 1, GlitchKind::ZeroRead),
            (900, 1, GlitchKind::Spike),
            (1300, 6, GlitchKind::Stuck),
            (n - 1, 1, GlitchKind::ZeroRead),
        ]
    );
    // A hold where the car stands still is not a stuck sensor.
    let mut slow = no_slow(n);
    slow[1300..1306].iter_mut().for_each(|s| *s = true);
    assert!(detect(&x, &slow)
        .iter()
        .all(|f| f.kind != GlitchKind::Stuck));
}
