//! The yaw-rate peak of a step steer, and how far the run's own noise
//! moves it.
//!
//! The peak (GB/T 6323, ISO 7401: the time of the response's maximum) is
//! the highest sample of the normalised yaw rate r̂'s first stretch above
//! a level after its 90 % crossing ([`super`]'s module notes). It was the
//! first local maximum there, which on a noisy record can be a noise bump
//! on the rising flank: 1 % noise moved a 0.435 s peak time to 0.359–0.423
//! s over four seeds, 10 % to 0.298 s, and TB (peak time × steady
//! sideslip) with it, while the run said nothing. A peak a little above
//! the steady state is flat, too: within the noise, many samples could
//! have been its maximum.
//!
//! The spread is measured, not modelled: white noise of the run's own
//! deviation (estimated from its samples' differences, share of the step)
//! is added again to r̂ [`DRAWS`] times (seed [`SEED`], so a run gives the
//! same figure every time), each copy filtered as the run was, and its
//! peak found by the same rule. The standard deviation of the peak times
//! found, and the share of copies that find a peak at all, say how far the
//! reported peak can be trusted. A copy's maximum more than the peak time
//! away from the reported peak (before the step, or after twice the peak
//! time) is not this peak moved: a second-order step response's maxima
//! fall at π/ω_d, 3π/ω_d, …, so a maximum past twice the first is the
//! next one or a noise bump of the steady state. Such copies are counted
//! apart ([`PeakSpread::stray`]) and said, not averaged in: on a 25 Hz log
//! with 1.3 % noise, filtered at 5 Hz, they made a 0.349 s peak time
//! "move by ±1.0 s"; the copies that find it scatter by ±0.027 s. A copy carries the run's noise twice
//! (its own and the one added); the figure is the scatter of a run with
//! that noise, not a bound on the error of this one. Times in s; r̂
//! dimensionless.

use rand::SeedableRng;

/// Noisy copies of the record drawn.
pub const DRAWS: usize = 32;
/// Seed of the copies' noise.
pub const SEED: u64 = 6323;

/// The index of the peak of `v` from time `from` on: the highest sample of
/// the first stretch above `level` (the first overshoot; it ends where `v`
/// falls to `level − dip` or below, so that a dip of the noise alone does
/// not cut it short and leave the rising flank's top as the peak), where it is a
/// local maximum; none where that highest sample is the record's last. The
/// highest of the stretch, not its first local maximum: on a noisy record
/// the first sample that noise lifts above the level and its neighbours
/// stands on the rising flank (10 % noise made a 0.435 s peak 0.298 s),
/// where the stretch's highest is the overshoot's top. On a smooth record
/// the two are one.
pub(super) fn peak_index(
    t: &[f64],
    v: &[f64],
    from: f64,
    (level, dip): (f64, f64),
) -> Option<usize> {
    let n = v.len();
    let first = (0..n).find(|&i| t[i] >= from && v[i] > level)?;
    let end = (first..n).find(|&i| v[i] <= level - dip).unwrap_or(n);
    let top = (first..end).max_by(|&a, &b| v[a].total_cmp(&v[b]).then(b.cmp(&a)))?;
    // A quantised record (a logger's resolution) holds its maximum over
    // several equal samples: the flat top is one maximum, its time the
    // middle of it (the earlier of two middles), where a smooth response
    // under the quantisation peaks; a top only falling ends it.
    let last = (top..n).take_while(|&i| v[i] == v[top]).last()?;
    let middle = top + (last - top) / 2;
    (top > 0 && last + 1 < n && v[top] >= v[top - 1] && v[top] > v[last + 1]).then_some(middle)
}

/// How far noise moves a peak: the peak time's standard deviation over
/// the copies that find it (s), the overshoot's (share of the step), the
/// share of copies that do, and the share that find a maximum only far
/// from it (another maximum, left out of the deviations).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct PeakSpread {
    /// Standard deviation of the peak times found, s.
    pub sd: f64,
    /// Standard deviation of the overshoots found, share of the step.
    pub overshoot_sd: f64,
    /// Share of the copies that find the peak (within the window).
    pub found: f64,
    /// Share of the copies whose maximum lies outside the window: another
    /// maximum, not this one moved.
    pub stray: f64,
}

/// The [`PeakSpread`] of the peak of `v` (filtered r̂ at times `t`) found
/// from `from` above `level` (with its `dip`), with white noise of deviation `noise` (raw,
/// share of the step) added before `filter`; a copy's peak counts where it
/// lies within `half` s of `centre` (the reported peak's time, and the
/// peak time from the step). `None` without noise.
pub(super) fn peak_spread(
    t: &[f64],
    v: &[f64],
    (from, level): (f64, (f64, f64)),
    noise: f64,
    filter: &dyn Fn(&[f64]) -> Vec<f64>,
    (centre, half): (f64, f64),
) -> Option<PeakSpread> {
    if noise <= 0.0 || !noise.is_finite() {
        return None;
    }
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(SEED);
    let mut z = vec![0.0; v.len()];
    let mut times = Vec::with_capacity(DRAWS);
    let mut heights = Vec::with_capacity(DRAWS);
    let mut stray = 0;
    for _ in 0..DRAWS {
        z.iter_mut()
            .for_each(|x| *x = noise * crate::optim::stats::gauss(&mut rng));
        // The filter is linear: the copy is v plus the filtered noise.
        let copy: Vec<f64> = v.iter().zip(filter(&z)).map(|(a, b)| a + b).collect();
        match peak_index(t, &copy, from, level) {
            Some(i) if (t[i] - centre).abs() <= half.abs() => {
                times.push(t[i]);
                heights.push(copy[i]);
            }
            Some(_) => stray += 1,
            None => {}
        }
    }
    Some(PeakSpread {
        sd: deviation(&times),
        overshoot_sd: deviation(&heights),
        found: times.len() as f64 / DRAWS as f64,
        stray: stray as f64 / DRAWS as f64,
    })
}

/// The standard deviation of `x` (over n; 0 for fewer than two).
fn deviation(x: &[f64]) -> f64 {
    let mean = x.iter().sum::<f64>() / x.len().max(1) as f64;
    let var = x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / x.len().max(2) as f64;
    var.sqrt()
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

    /// A yaw rate logged at a resolution of 0.001 rad/s holds its maximum
    /// over four equal samples: still one peak, at the middle of the flat
    /// top (the earlier middle), not "no overshoot" (a 17 % overshoot was
    /// lost so); a flat top that runs to the record's end is none.
    #[test]
    fn a_flat_quantised_top_is_one_peak_at_its_middle() {
        let (t, v) = response(0.5);
        let q: Vec<f64> = v.iter().map(|x| (x * 8.0).round() / 8.0).collect();
        let smooth = peak_index(&t, &v, 0.0, (1.05, 0.0)).unwrap();
        let top = q.iter().cloned().fold(f64::MIN, f64::max);
        let flat: Vec<usize> = (0..q.len()).filter(|&i| q[i] == top).collect();
        assert!(flat.len() >= 4, "{flat:?}");
        let i = peak_index(&t, &q, 0.0, (1.05, 0.0)).unwrap();
        assert_eq!(i, flat[0] + (flat[flat.len() - 1] - flat[0]) / 2);
        assert!(
            (t[i] - t[smooth]).abs() <= 0.5 * (flat.len() as f64) * 0.01,
            "{} {}",
            t[i],
            t[smooth]
        );
        let mut rising = q.clone();
        let n = rising.len();
        rising[flat[0]..].iter_mut().for_each(|x| *x = top);
        assert_eq!(peak_index(&t, &rising[..n], 0.0, (1.05, 0.0)), None);
    }

    /// Filtered as `metrics` filters a run (10 Hz), a sharp peak (30 %
    /// overshoot) moves under 1 % noise by under 3 % of its time; a flat
    /// one (2 % overshoot) by a twentieth of its time or more, or is lost in
    /// some copies. Same seed, same figure; no noise, none.
    #[test]
    fn a_flat_peak_moves_with_noise_and_a_sharp_one_does_not() {
        let filter = |x: &[f64]| super::super::zero_phase_low_pass(x, 0.01, 10.0);
        let (t, sharp) = response(0.36);
        let i = peak_index(&t, &sharp, 0.0, (1.05, 0.0)).unwrap();
        let s = peak_spread(&t, &sharp, (0.0, (1.05, 0.0)), 0.01, &filter, (t[i], t[i])).unwrap();
        assert!(s.sd < 0.03 * t[i] && s.found == 1.0, "{s:?} of {}", t[i]);
        let (t, flat) = response(0.78);
        let i = peak_index(&t, &flat, 0.0, (1.01, 0.0)).unwrap();
        let f = peak_spread(&t, &flat, (0.0, (1.01, 0.0)), 0.01, &filter, (t[i], t[i])).unwrap();
        assert!(f.sd > 0.05 * t[i] || f.found < 0.75, "{f:?} of {}", t[i]);
        assert_eq!(
            Some(f),
            peak_spread(&t, &flat, (0.0, (1.01, 0.0)), 0.01, &filter, (t[i], t[i]))
        );
        assert_eq!(
            None,
            peak_spread(&t, &flat, (0.0, (1.01, 0.0)), 0.0, &filter, (t[i], t[i]))
        );
    }

    /// A copy whose maximum lies outside the window is counted apart and
    /// left out of the deviation: with a window of one sample about the
    /// flat peak, the copies kept all sit on it (no spread) and the rest
    /// are strays; the shares add up to at most 1. A window of the whole
    /// record keeps every copy that finds a peak.
    #[test]
    fn a_copy_whose_maximum_lies_outside_the_window_is_counted_apart() {
        let filter = |x: &[f64]| super::super::zero_phase_low_pass(x, 0.01, 10.0);
        let (t, flat) = response(0.78);
        let level = (0.0, (1.01, 0.0));
        let i = peak_index(&t, &flat, 0.0, (1.01, 0.0)).unwrap();
        let narrow = peak_spread(&t, &flat, level, 0.01, &filter, (t[i], 0.001)).unwrap();
        let wide = peak_spread(&t, &flat, level, 0.01, &filter, (t[i], 10.0)).unwrap();
        assert!(narrow.stray > 0.0 && narrow.sd < 1e-12, "{narrow:?}");
        assert!(narrow.found + narrow.stray <= 1.0, "{narrow:?}");
        assert_eq!(wide.stray, 0.0, "{wide:?}");
        assert!((narrow.found + narrow.stray - wide.found).abs() < 1e-12);
    }
}
