//! A sideslip as a state estimator gives it: what a real log's `beta`
//! channel often is (an inertial unit's or a racing car's observer output,
//! computed from accelerations, rates and GNSS velocities), not a direct
//! measurement with white noise.
//!
//! The estimate follows the true sideslip through a first-order low-pass
//! of time constant [`LAG`] (its bandwidth, 0.4 Hz), carries a slowly
//! drifting bias (a first-order Gauss–Markov process of standard deviation
//! [`DRIFT`] and correlation time [`DRIFT_TIME`]: the estimator's error
//! as its GNSS aiding and heading wander) and a little white scatter
//! ([`SCATTER`], its output's rounding and jitter). So its sample-to-sample
//! scatter is about 0.0002 rad, while its error against the truth is
//! several mrad: a noise floor estimated from the high-frequency scatter
//! is ten times too small, and a fit weighting the channel by it leans on
//! it. Units: rad, s.

use crate::identify::data::gauss;
use rand_chacha::ChaCha8Rng;

/// The estimator's lag time constant, s.
pub(super) const LAG: f64 = 0.4;
/// Standard deviation of the drifting bias, rad.
pub(super) const DRIFT: f64 = 0.004;
/// Correlation time of the drifting bias, s.
pub(super) const DRIFT_TIME: f64 = 40.0;
/// Standard deviation of the white scatter, rad.
pub(super) const SCATTER: f64 = 0.0002;

/// The estimate at times `t` of the true sideslip `beta` (at the same
/// times), with the drift and the scatter drawn from `rng` (two draws a
/// sample, in time order).
pub(super) fn estimated(t: &[f64], beta: &[f64], rng: &mut ChaCha8Rng) -> Vec<f64> {
    let mut out = Vec::with_capacity(t.len());
    let (mut lagged, mut drift) = (beta.first().copied().unwrap_or(0.0), 0.0);
    for (k, (&tk, &b)) in t.iter().zip(beta).enumerate() {
        let dt = if k == 0 { 0.0 } else { tk - t[k - 1] };
        lagged += (b - lagged) * (1.0 - (-dt / LAG).exp());
        let keep = (-dt / DRIFT_TIME).exp();
        let w = gauss(rng);
        drift = if k == 0 {
            DRIFT * w
        } else {
            keep * drift + DRIFT * (1.0 - keep * keep).sqrt() * w
        };
        out.push(lagged + drift + SCATTER * gauss(rng));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn the_estimate_is_smooth_but_off_by_several_mrad() {
        // A true sideslip swinging ±0.03 rad every 20 s, at 25 Hz for
        // 600 s.
        let t: Vec<f64> = (0..15_000).map(|k| k as f64 * 0.04).collect();
        let beta: Vec<f64> = t
            .iter()
            .map(|&s| 0.03 * (std::f64::consts::TAU * s / 20.0).sin())
            .collect();
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let e = estimated(&t, &beta, &mut rng);
        let n = t.len() as f64;
        let scatter = (e.windows(2).map(|w| (w[1] - w[0]).powi(2)).sum::<f64>() / n / 2.0).sqrt();
        let error = (e
            .iter()
            .zip(&beta)
            .map(|(a, b)| (a - b).powi(2))
            .sum::<f64>()
            / n)
            .sqrt();
        assert!((1.5e-4..4e-4).contains(&scatter), "scatter {scatter}");
        assert!(error > 10.0 * scatter, "error {error}, scatter {scatter}");
        assert!((0.002..0.008).contains(&error), "error {error}");
    }
}
