//! The slope of [`super`] and its standard error on closed-form data: an
//! exact line, alternating residuals (`σ/√S_xx` exactly), residuals held
//! for `m` samples (`√m` times the white error), and the campaign's rule
//! on scales read alike, apart, within the noise and on a banked oval.

use super::*;

/// A step in the turning: `n/2` samples at `lo`, `n/2` at `hi` (m/s²).
fn step(n: usize, lo: f64, hi: f64) -> Vec<f64> {
    (0..n).map(|k| if k < n / 2 { lo } else { hi }).collect()
}

/// `S_xx` of a series.
fn sxx(x: &[f64]) -> f64 {
    let m = x.iter().sum::<f64>() / x.len() as f64;
    x.iter().map(|v| (v - m).powi(2)).sum()
}

/// A gyro reading ×1.15 on a flat road with a 0.05 m/s² `ay` offset: the
/// residual is `0.05 + (1/1.15 − 1)·x` exactly, and the scale comes back
/// with no error.
#[test]
fn an_exact_line_gives_its_scale_back_with_no_error() {
    let x: Vec<f64> = (0..400).map(|k| 4.0 * (k as f64 / 400.0)).collect();
    let s = 1.0 / 1.15 - 1.0;
    let e: Vec<f64> = x.iter().map(|x| 0.05 + s * x).collect();
    let f = line_fit(&x, &e).unwrap();
    assert!((f.slope - s).abs() < 1e-12, "{f:?}");
    assert!((f.intercept - 0.05).abs() < 1e-12, "{f:?}");
    assert!(f.slope_error < 1e-12, "{f:?}");
    let k = YawScale::of(&x, &e).unwrap();
    assert!((k.scale - 1.15).abs() < 1e-12, "{k:?}");
    // NaN samples (masked, or beside one) are left out, not read as 0.
    let mut holed = e.clone();
    holed[10] = f64::NAN;
    assert_eq!(line_fit(&x, &holed).unwrap().samples, 399);
    // A straight (u·r spread 0.1 m/s²) reads no scale.
    let straight: Vec<f64> = x.iter().map(|x| 0.025 * x).collect();
    assert_eq!(YawScale::of(&straight, &e), None);
}

/// Residuals alternating ±σ about the line over a step: their projection on
/// the step is 0, so the slope is exact, and the score's autocovariance is
/// negative at lag 1, so the error is the white one, `σ/√S_xx`, exactly.
#[test]
fn alternating_residuals_give_the_white_error() {
    let (n, sigma) = (1000, 0.05);
    let x = step(n, 0.0, 3.0);
    let e: Vec<f64> = (0..n)
        .map(|k| -0.1 * x[k] + if k % 2 == 0 { sigma } else { -sigma })
        .collect();
    let f = line_fit(&x, &e).unwrap();
    assert!((f.slope + 0.1).abs() < 1e-12, "{f:?}");
    let white = sigma / sxx(&x).sqrt();
    assert!(
        (f.slope_error - white).abs() < 1e-9 * white,
        "{f:?} vs {white}"
    );
    assert!((f.independent_samples - n as f64).abs() < 1e-6, "{f:?}");
}

/// A deterministic sequence of signs (a linear congruential generator's
/// top bit): noise the test can repeat.
fn signs(n: usize, seed: u64) -> Vec<f64> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            if s >> 63 == 1 {
                1.0
            } else {
                -1.0
            }
        })
        .collect()
}

/// Residuals of random sign held for `m` samples are `m` times fewer
/// independent samples: the slope's error is `√m` times the white one
/// (`σ·√(m/S_xx)`), within the estimate's own scatter (15 %), where the
/// white formula (`Σz²` alone) would claim `√m` times too little. White
/// residuals of random sign give the white error.
#[test]
fn residuals_held_for_m_samples_count_m_times_fewer() {
    let (n, sigma, m) = (40_000, 0.05, 16);
    let x = step(n, 0.0, 3.0);
    let white = sigma / sxx(&x).sqrt();
    let random = signs(n, 7);
    let e: Vec<f64> = (0..n).map(|k| sigma * random[k]).collect();
    let f = line_fit(&x, &e).unwrap();
    assert!(
        (f.slope_error / white - 1.0).abs() < 0.15,
        "{} vs {white}",
        f.slope_error
    );
    let blocks = signs(n / m + 1, 11);
    let held: Vec<f64> = (0..n).map(|k| sigma * blocks[k / m]).collect();
    let f = line_fit(&x, &held).unwrap();
    let honest = white * (m as f64).sqrt();
    assert!(
        (f.slope_error / honest - 1.0).abs() < 0.15,
        "{} vs {honest}",
        f.slope_error
    );
    let worth = n as f64 / m as f64;
    assert!(
        (f.independent_samples / worth - 1.0).abs() < 0.3,
        "{} vs {worth}",
        f.independent_samples
    );
}

fn scale(k: f64, standard_error: f64) -> Option<YawScale> {
    Some(YawScale {
        scale: k,
        standard_error,
        slope: 1.0 / k - 1.0,
        slope_error: standard_error,
        samples: 600,
        independent_samples: 30.0,
    })
}

/// One run at ×1.15 among runs at ×0.99–1.01 is set apart with the factor
/// over their median; at ×1.02 it is not (under 3 %), nor at ×1.15 ± 0.05
/// (under four standard errors), nor with one other run only; a run
/// without a scale is none and counts for none.
#[test]
fn a_run_whose_scale_the_others_do_not_share_is_set_apart() {
    let runs = |k: f64, se: f64| {
        vec![
            scale(1.0, 0.004),
            scale(0.99, 0.004),
            None,
            scale(k, se),
            scale(1.01, 0.004),
        ]
    };
    let apart = set_apart(&runs(1.15, 0.004));
    assert_eq!(apart.iter().filter(|a| a.is_some()).count(), 1, "{apart:?}");
    let a = apart[3].unwrap();
    assert_eq!((a.others, a.other_runs), (1.0, 3));
    assert!((a.factor - 1.15).abs() < 1e-12, "{a:?}");
    assert!(set_apart(&runs(1.02, 0.001)).iter().all(Option::is_none));
    assert!(set_apart(&runs(1.15, 0.05)).iter().all(Option::is_none));
    assert!(set_apart(&[scale(1.0, 0.004), scale(1.2, 0.004)])
        .iter()
        .all(Option::is_none));
    let said = words(&a);
    assert!(
        said.starts_with("; its yaw rate reads ×1.150 ± 0.004 of what ay/u says, the other 3 runs' ×1.000 (their median): a scale error of ×1.150 of the gyro (or of ×0.870 of the accelerometer), not a bank"),
        "{said}"
    );
}

/// A banked oval's runs at three paces: its turns' bank reads as a slope
/// `g·sin θ·R/u²` that differs with the speed (×1.3 to ×1.6 here). No run
/// is set apart: the others do not read the yaw rate as `ay/u` says, so a
/// departure among them is no one gyro's.
#[test]
fn a_banked_ovals_runs_are_not_set_apart() {
    let oval = [scale(1.6, 0.004), scale(1.45, 0.004), scale(1.3, 0.004)];
    assert!(set_apart(&oval).iter().all(Option::is_none));
    // The same runs at one pace read alike: none apart either.
    let alike = [scale(1.45, 0.004), scale(1.45, 0.004), scale(1.46, 0.004)];
    assert!(set_apart(&alike).iter().all(Option::is_none));
}
