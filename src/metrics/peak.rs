//! The yaw-rate peak of a step steer, and how far the run's own noise
//! moves it.
//!
//! The peak (GB/T 6323, ISO 7401) is the first local maximum of the
//! normalised yaw rate r̂ after its 90 % crossing above a level
//! ([`super`]'s module notes). A peak a little above the steady state is
//! flat: within the noise, many samples could have been its maximum, and
//! the first one a noisy record lifts above the level can stand on the
//! rising flank. A 1 % noise moved a 0.435 s peak time to 0.359–0.423 s
//! over four seeds, and TB (peak time × steady sideslip) with it, while
//! the run said nothing.
//!
//! The spread is measured, not modelled: white noise of the run's own
//! deviation (estimated from its samples' differences, share of the step)
//! is added again to r̂ [`DRAWS`] times (seed [`SEED`], so a run gives the
//! same figure every time), each copy filtered as the run was, and its
//! peak found by the same rule. The standard deviation of the peak times
//! found, and the share of copies that find a peak at all, say how far the
//! reported peak can be trusted. A copy carries the run's noise twice
//! (its own and the one added), so the figure is an upper estimate, by up
//! to √2. Times in s; r̂ dimensionless.

use rand::SeedableRng;

/// Noisy copies of the record drawn.
pub const DRAWS: usize = 32;
/// Seed of the copies' noise.
pub const SEED: u64 = 6323;

/// The index of the first local maximum of `v` at or after time `from`
/// above `level`; a maximum at the record's end is none.
pub(super) fn peak_index(t: &[f64], v: &[f64], from: f64, level: f64) -> Option<usize> {
    let n = v.len();
    (1..n.saturating_sub(1))
        .find(|&i| t[i] >= from && v[i] > level && v[i] >= v[i - 1] && v[i] > v[i + 1])
}

/// How far noise moves a peak: the peak time's standard deviation over
/// the copies that find one (s), and the share of copies that do.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct PeakSpread {
    /// Standard deviation of the peak times found, s.
    pub sd: f64,
    /// Share of the copies that find a peak.
    pub found: f64,
}

/// The [`PeakSpread`] of the peak of `v` (filtered r̂ at times `t`) found
/// from `from` above `level`, with white noise of deviation `noise` (raw,
/// share of the step) added before `filter`. `None` without noise.
pub(super) fn peak_spread(
    t: &[f64],
    v: &[f64],
    (from, level): (f64, f64),
    noise: f64,
    filter: &dyn Fn(&[f64]) -> Vec<f64>,
) -> Option<PeakSpread> {
    if noise <= 0.0 || !noise.is_finite() {
        return None;
    }
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(SEED);
    let mut z = vec![0.0; v.len()];
    let mut times = Vec::with_capacity(DRAWS);
    for _ in 0..DRAWS {
        z.iter_mut()
            .for_each(|x| *x = noise * crate::optim::stats::gauss(&mut rng));
        // The filter is linear: the copy is v plus the filtered noise.
        let copy: Vec<f64> = v.iter().zip(filter(&z)).map(|(a, b)| a + b).collect();
        if let Some(i) = peak_index(t, &copy, from, level) {
            times.push(t[i]);
        }
    }
    let found = times.len() as f64 / DRAWS as f64;
    let mean = times.iter().sum::<f64>() / times.len().max(1) as f64;
    let var = times.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / times.len().max(2) as f64;
    Some(PeakSpread {
        sd: var.sqrt(),
        found,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A second-order step response sampled at 100 Hz: overshoot set by
    /// the damping ratio `zeta`, natural frequency 2π rad/s.
    fn response(zeta: f64) -> (Vec<f64>, Vec<f64>) {
        let wn = std::f64::consts::TAU;
        let wd = wn * (1.0 - zeta * zeta).sqrt();
        let t: Vec<f64> = (0..400).map(|i| i as f64 * 0.01).collect();
        let v = t
            .iter()
            .map(|&s| {
                1.0 - (-zeta * wn * s).exp() * ((wd * s).cos() + zeta * wn / wd * (wd * s).sin())
            })
            .collect();
        (t, v)
    }

    /// Filtered as `metrics` filters a run (10 Hz), a sharp peak (30 %
    /// overshoot) moves under 1 % noise by under 3 % of its time; a flat
    /// one (2 % overshoot) by a twentieth of its time or more, or is lost in
    /// some copies. Same seed, same figure; no noise, none.
    #[test]
    fn a_flat_peak_moves_with_noise_and_a_sharp_one_does_not() {
        let filter = |x: &[f64]| super::super::zero_phase_low_pass(x, 0.01, 10.0);
        let (t, sharp) = response(0.36);
        let i = peak_index(&t, &sharp, 0.0, 1.05).unwrap();
        let s = peak_spread(&t, &sharp, (0.0, 1.05), 0.01, &filter).unwrap();
        assert!(s.sd < 0.03 * t[i] && s.found == 1.0, "{s:?} of {}", t[i]);
        let (t, flat) = response(0.78);
        let i = peak_index(&t, &flat, 0.0, 1.01).unwrap();
        let f = peak_spread(&t, &flat, (0.0, 1.01), 0.01, &filter).unwrap();
        assert!(f.sd > 0.05 * t[i] || f.found < 0.75, "{f:?} of {}", t[i]);
        assert_eq!(Some(f), peak_spread(&t, &flat, (0.0, 1.01), 0.01, &filter));
        assert_eq!(None, peak_spread(&t, &flat, (0.0, 1.01), 0.0, &filter));
    }
}
