//! How far a measured run's own noise moves its response times and its
//! yaw-rate gain.
//!
//! The response times (GB/T 6323, ISO 7401: from the steer's 50 % to the
//! response's 90 % crossing) are read where a noisy, filtered response
//! first crosses 0.9 of its step, and the noise moves that crossing: a
//! 1° step on the sedan logged with gyro noise of 7 % of the step read its
//! yaw-rate response time 0.145–0.229 s over seven seeds of noise about
//! the noise-free 0.188 s, its ay response time 0.417–0.539 s about 0.479 s,
//! printed to four digits without a word. The spread is measured as the
//! peak's is (`peak.rs`): the same [`DRAWS`] copies of the normalised
//! response with white noise of the run's own deviation added again (seed
//! [`SEED`]), each filtered as the run was, the crossing found by the same
//! rule. A crossing moves with the step it is a share of, too: the
//! initial and steady means carry their windows' noise, and a copy's 90 %
//! level is drawn with it (`L + L·e_s + (1 − L)·e_0`, `e` the noise over
//! √n of the window's samples): without it the copies' spread fell short
//! of the seeds' own scatter (ay: 0.059 s stated, 0.071 s over ten
//! seeds). A copy carries the filtered noise twice, so the figure leans
//! high.
//!
//! The gain is the steady window's mean over the initial window's, each a
//! mean of white noise over its samples: its relative deviation is
//! `√((σ_r² + σ_δ²)·(1/n_initial + 1/n_steady))` with σ the raw noise of
//! the yaw rate and of the steer as shares of their steps (closed form:
//! the means of independent samples). Times in s; shares dimensionless.

use super::peak::{DRAWS, SEED};
use super::Normalised;
use rand::SeedableRng;

/// The standard deviation of the time at which copies of `v` (a filtered
/// response normalised by its step, at times `t`) with white noise of raw
/// deviation `noise` (share of the step) added before `filter` first
/// cross `level`, itself moved by the noise of means over `samples`
/// samples, from `from` on; None without noise or where fewer than half
/// of the copies cross.
pub(super) fn crossing_spread(
    t: &[f64],
    v: &[f64],
    (from, level): (f64, f64),
    (noise, samples): (f64, usize),
    filter: &dyn Fn(&[f64]) -> Vec<f64>,
) -> Option<f64> {
    if noise <= 0.0 || !noise.is_finite() {
        return None;
    }
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(SEED);
    let mut z = vec![0.0; v.len()];
    let mut copy = vec![0.0; v.len()];
    let mut times = Vec::with_capacity(DRAWS);
    for _ in 0..DRAWS {
        z.iter_mut()
            .for_each(|x| *x = noise * crate::optim::stats::gauss(&mut rng));
        // The filter is linear: the copy is v plus the filtered noise.
        for ((c, a), b) in copy.iter_mut().zip(v).zip(filter(&z)) {
            *c = a + b;
        }
        let mean = noise / (samples.max(1) as f64).sqrt();
        let (e_s, e_0) = (
            mean * crate::optim::stats::gauss(&mut rng),
            mean * crate::optim::stats::gauss(&mut rng),
        );
        let moved = level + level * e_s + (1.0 - level) * e_0;
        times.extend(super::first_crossing(t, &copy, moved, from));
    }
    if 2 * times.len() < DRAWS {
        return None;
    }
    let mean = times.iter().sum::<f64>() / times.len() as f64;
    let var = times.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / times.len() as f64;
    Some(var.sqrt())
}

/// The yaw-rate gain's relative standard deviation from the noise of the
/// means it is the ratio of (the module notes); None without noise.
pub(super) fn gain_spread(r: &Normalised, d: &Normalised) -> Option<f64> {
    let var = r.noise.powi(2) + d.noise.powi(2);
    if var <= 0.0 || !var.is_finite() {
        return None;
    }
    // `samples` is the shorter window's count: both taken as that long,
    // an upper estimate where the other is longer.
    Some((2.0 * var / r.samples.min(d.samples).max(1) as f64).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A first-order step response (τ = 0.2 s from 1 s) at 100 Hz,
    /// normalised.
    fn response() -> (Vec<f64>, Vec<f64>) {
        let t: Vec<f64> = (0..600).map(|i| i as f64 * 0.01).collect();
        let v = t
            .iter()
            .map(|&x| {
                if x < 1.0 {
                    0.0
                } else {
                    1.0 - (-(x - 1.0) / 0.2).exp()
                }
            })
            .collect();
        (t, v)
    }

    /// Unfiltered, a crossing moves by the noise over the response's slope
    /// there: at 0.9 a first-order step's slope is 0.1/τ = 0.5 per second,
    /// so 0.5 % noise moves it by about 0.01 s; ten times the noise by more
    /// (a first crossing of noise is also early, so not ten times). Same
    /// seed, same figure; no noise, none.
    #[test]
    fn a_crossing_moves_with_the_noise_over_the_slope_there() {
        let (t, v) = response();
        let none = |x: &[f64]| x.to_vec();
        let small = crossing_spread(&t, &v, (1.0, 0.9), (0.005, 100), &none).unwrap();
        assert!(small > 0.004 && small < 0.02, "{small}");
        let large = crossing_spread(&t, &v, (1.0, 0.9), (0.05, 100), &none).unwrap();
        assert!(large > 3.0 * small, "{large} against {small}");
        assert_eq!(
            Some(small),
            crossing_spread(&t, &v, (1.0, 0.9), (0.005, 100), &none)
        );
        assert_eq!(None, crossing_spread(&t, &v, (1.0, 0.9), (0.0, 100), &none));
    }
}
