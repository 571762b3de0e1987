//! The scan's tests: the quantiles against tables, the window test's false
//! alarms, the bias test's closed forms, the time shift.

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
        let w = worst_window(
            &t,
            scored_from(t[0]),
            &e,
            (floor, FloorCounting::White),
            tau,
            100,
            true,
        )
        .unwrap();
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
    let w = worst_window(
        t1,
        scored_from(t1[0]),
        e1,
        (1.0, FloorCounting::White),
        tau,
        100,
        true,
    )
    .unwrap();
    assert!(w.significant && (2.75..=3.25).contains(&w.start), "{w:?}");
    let whole = correlation_time(&e);
    let hidden = worst_window(
        t1,
        scored_from(t1[0]),
        e1,
        (1.0, FloorCounting::White),
        whole,
        100,
        true,
    )
    .unwrap();
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
