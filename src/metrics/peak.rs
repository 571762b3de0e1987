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
//!
//! The noise also biases the peak: the highest of a noisy curve lies above
//! the curve's. Copies at a quarter and a half of the run's noise variance, with those
//! at all of it, give the overshoot's bias by SIMEX (Cook & Stefanski
//! 1994): [`noise_bias`]. The peak time's shift is not estimated: its
//! extrapolation scattered more than the shift (round 48).

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
/// from it (another maximum, left out of the deviations); and how far the
/// noise lifts and shifts it on average ([`noise_bias`]).
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
    /// How far it lifts the peak's height on average, share of the step.
    pub height_bias: Option<f64>,
}

/// The extra noise variances of the copies, in units of the run's own
/// (SIMEX's λ, Cook & Stefanski 1994): the first level is the one whose
/// scatter [`PeakSpread::sd`] reports. Levels at or below the run's own:
/// the peak's rule (its threshold and dip set by the run's noise) reads a
/// copy with several times that noise otherwise than the run, and the
/// lift grew slower per λ there (1.76 points per λ at 0.25, 1.14 at 3 on
/// the sedan's step), so levels up to 3 extrapolated it past the truth.
pub const LEVELS: [f64; 3] = [1.0, 0.25, 0.5];

/// The [`PeakSpread`] of the peak of `v` (filtered r̂ at times `t`) found
/// from `from` above `level` (with its `dip`), with white noise of deviation `noise` (raw,
/// share of the step) added before `filter`; a copy's peak counts where it
/// lies within `half` s of `centre` (the reported peak's time, and the
/// peak time from the step). `None` without noise. The copies of each of
/// [`LEVELS`] draw the same noises, scaled (common random numbers: the
/// levels' means differ by the noise's level, not by its draw).
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
    let mut copy = vec![0.0; v.len()];
    // The peak times of the run's own level (the spread reported), and
    // every level's heights (the overshoot's bias).
    let mut times = Vec::with_capacity(DRAWS);
    let mut heights = vec![Vec::with_capacity(DRAWS); LEVELS.len()];
    let mut stray = 0;
    for _ in 0..DRAWS {
        z.iter_mut()
            .for_each(|x| *x = noise * crate::optim::stats::gauss(&mut rng));
        // The filter is linear: the copy is v plus the filtered noise.
        let filtered = filter(&z);
        for (k, lambda) in LEVELS.iter().enumerate() {
            for ((c, a), b) in copy.iter_mut().zip(v).zip(&filtered) {
                *c = a + lambda.sqrt() * b;
            }
            match peak_index(t, &copy, from, level) {
                Some(i) if (t[i] - centre).abs() <= half.abs() => {
                    if k == 0 {
                        times.push(t[i]);
                    }
                    heights[k].push(copy[i]);
                }
                Some(_) if k == 0 => stray += 1,
                _ => {}
            }
        }
    }
    let top = peak_index(t, v, from, level).map_or(f64::NAN, |i| v[i]);
    Some(PeakSpread {
        sd: deviation(&times),
        overshoot_sd: deviation(&heights[0]),
        found: times.len() as f64 / DRAWS as f64,
        stray: stray as f64 / DRAWS as f64,
        height_bias: noise_bias(top, &heights).filter(|b| b.is_finite()),
    })
}

/// How far the noise moves a reading `at` (the run's own, noise variance
/// σ²) on average: the run less the extrapolation to no noise of a line
/// through it and the means of its copies' readings (`levels`, one per λ
/// of [`LEVELS`], total noise variance (1 + λ)·σ²), fitted by least
/// squares against λ and read at λ = −1 (SIMEX, Cook & Stefanski 1994,
/// with its linear extrapolant). Over 50 seeds of round 47's noise on the
/// sedan's step (overshoot 16.90 % clean, 18.34 ± 0.21 % read) it gave
/// 16.90 ± 0.26 %; the quadratic extrapolant 16.21 ± 0.44 %, and lines in
/// the noise deviation √(1 + λ) 14.7–15.0 %. None where a level's copies
/// find no peak.
pub(super) fn noise_bias(at: f64, levels: &[Vec<f64>]) -> Option<f64> {
    let mut points = vec![(0.0, at)];
    for (lambda, x) in LEVELS.iter().zip(levels) {
        if x.is_empty() {
            return None;
        }
        points.push((*lambda, x.iter().sum::<f64>() / x.len() as f64));
    }
    let n = points.len() as f64;
    let (ml, my) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), p| (a + p.0 / n, b + p.1 / n));
    let sxy: f64 = points.iter().map(|p| (p.0 - ml) * (p.1 - my)).sum();
    let sxx: f64 = points.iter().map(|p| (p.0 - ml).powi(2)).sum();
    let at_none = my + sxy / sxx * (-1.0 - ml);
    Some(at - at_none)
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

    /// A reading lifted in proportion to the noise variance is
    /// extrapolated to none exactly: its lift at the run's noise is the
    /// bias; a reading the noise does not move has none; a level without
    /// copies gives none.
    #[test]
    fn a_lift_linear_in_the_noise_variance_is_recovered_as_the_bias() {
        let lift = |lambda: f64| 0.17 + 0.02 * (1.0 + lambda);
        let levels: Vec<Vec<f64>> = LEVELS
            .iter()
            .map(|l| vec![lift(*l) - 0.001, lift(*l) + 0.001])
            .collect();
        let b = noise_bias(lift(0.0), &levels).unwrap();
        assert!((b - 0.02).abs() < 1e-12, "{b}");
        let flat = vec![vec![0.17]; LEVELS.len()];
        assert!(noise_bias(0.17, &flat).unwrap().abs() < 1e-9);
        let mut lost = flat.clone();
        lost[2].clear();
        assert_eq!(noise_bias(0.17, &lost), None);
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
