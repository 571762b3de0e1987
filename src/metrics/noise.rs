//! The white-noise deviation of a channel and its gain through the
//! zero-phase low-pass. Units: the channel's own; s; Hz.

use super::filter::zero_phase_low_pass;

/// White-noise deviation of `x`, from the median absolute difference of
/// neighbours (insensitive to the step and to slow trends), and at least
/// q/√12 for a channel on a logger's grid of q ([`held_resolution`]):
/// rounding to a step of q adds a deviation of q/√12 that the median
/// difference, 0 when most neighbours repeat, does not show.
pub(super) fn noise_deviation(x: &[f64]) -> f64 {
    let mut d: Vec<f64> = x.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    if d.len() < 5 {
        return 0.0;
    }
    d.sort_by(f64::total_cmp);
    let from_differences = d[d.len() / 2] / (0.6745 * std::f64::consts::SQRT_2);
    match held_resolution(x) {
        Some(q) => from_differences.max(q / 12f64.sqrt()),
        None => from_differences,
    }
}

/// The grid q a logger wrote `x` on, read where the grid shows and not
/// where a signal merely moves: its smallest non-zero change between two
/// levels each held for two samples or more, where it holds at least
/// three such levels (a staircase: a rounded ramp, or a held value
/// dithering between codes) or between a value and one it returns to at
/// once (a dither), spanning its range in at most [`GRID_LEVELS`] of it.
/// A steer's ramp sampled at 20–25 Hz takes one or two values on its way,
/// each once: it changed by 0.4°, 0.4° and 0.2° between 0 and 1° and was
/// read as a 0.2° grid (the gain "±10 %"), and a 20 Hz ramp's 0.5° halves
/// set a noise of 0.14° on a noise-free steer (the gain "±6.2 %"). Two
/// held levels alone (a step between its initial and its held value)
/// show no grid. None where nothing shows one.
pub(super) fn held_resolution(x: &[f64]) -> Option<f64> {
    // Runs of equal values: (value, length).
    let mut runs: Vec<(f64, usize)> = Vec::new();
    for &v in x.iter().filter(|v| v.is_finite()) {
        match runs.last_mut() {
            Some((last, n)) if *last == v => *n += 1,
            _ => runs.push((v, 1)),
        }
    }
    let held_levels = runs.iter().filter(|(_, n)| *n >= 2).count();
    let value = |k: usize| runs.get(k).map(|r| r.0);
    let q = (0..runs.len().saturating_sub(1))
        .filter(|&k| {
            let stair = held_levels >= 3 && runs[k].1 >= 2 && runs[k + 1].1 >= 2;
            let back =
                value(k + 2) == Some(runs[k].0) || (k > 0 && value(k - 1) == Some(runs[k + 1].0));
            stair || back
        })
        .map(|k| (runs[k + 1].0 - runs[k].0).abs())
        .fold(f64::INFINITY, f64::min);
    let (lo, hi) = runs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), r| {
            (a.min(r.0), b.max(r.0))
        });
    (q.is_finite() && q > 0.0 && (hi - lo) / q <= GRID_LEVELS).then_some(q)
}

/// Most steps of its resolution a logger's channel spans (16 bits); a
/// channel whose smallest change is finer is written to its digits (a
/// simulation), not quantised by a logger.
const GRID_LEVELS: f64 = 65536.0;

/// √Σh² of the zero-phase low-pass: the deviation of white noise after it
/// relative to before.
pub(super) fn noise_gain(dt: f64, cutoff_hz: f64) -> f64 {
    let n = (20.0 / (cutoff_hz * dt)).ceil() as usize + 1;
    let mut x = vec![0.0; 2 * n + 1];
    x[n] = 1.0;
    zero_phase_low_pass(&x, dt, cutoff_hz)
        .iter()
        .map(|h| h * h)
        .sum::<f64>()
        .sqrt()
}

/// `Σρ(k)²` over all lags k of white noise after the zero-phase low-pass,
/// ρ its autocorrelation (the impulse response's, normalised): a window
/// of N filtered samples tells the noise's variance as well as N/Σρ²
/// independent ones (1 unfiltered; about 5 at 10 Hz on 100 Hz).
pub(super) fn correlation_sum(dt: f64, cutoff_hz: f64) -> f64 {
    let n = (20.0 / (cutoff_hz * dt)).ceil() as usize + 1;
    let mut x = vec![0.0; 2 * n + 1];
    x[n] = 1.0;
    let h = zero_phase_low_pass(&x, dt, cutoff_hz);
    let lag = |k: usize| h.iter().zip(&h[k..]).map(|(a, b)| a * b).sum::<f64>();
    let zero = lag(0);
    let tail: f64 = (1..h.len()).map(|k| (lag(k) / zero).powi(2)).sum();
    1.0 + 2.0 * tail
}

/// Samples per update of each channel a logger held between updates (a
/// 50 Hz gyro in a 100 Hz log), which cleaning interpolated between them;
/// 0 or 1: a channel read at every sample.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct HeldEvery {
    pub steer: usize,
    pub yaw_rate: usize,
    pub ay: usize,
    pub beta: usize,
}

/// The factor that turns the noise read on the samples of a channel held
/// for `every` samples of `dt` s and interpolated between its updates into
/// the noise it carries, per sample of white noise of equal effect after
/// the low-pass at `filter_hz`. Interpolation divides each update's change
/// among `every` samples, so their neighbours' differences, the noise's
/// reading, are `every` times smaller than the updates' (a 50 Hz yaw rate
/// in a 100 Hz log read 0.61 % for the 1.74 % of the same data at 50 Hz);
/// and the interpolated noise is no white noise at `dt`: the low-pass
/// passes it as it passes white noise at the update interval `every·dt`
/// (its noise gain √Σh² at that interval). Unfiltered, each update's own
/// deviation.
pub(super) fn held_noise_scale(every: usize, dt: f64, filter_hz: Option<f64>) -> f64 {
    if every <= 1 {
        return 1.0;
    }
    let k = every as f64;
    let filtered = filter_hz.map_or(1.0, |f| {
        let at_updates = match super::filter::below_filter_limit(f, k * dt) {
            true => noise_gain(k * dt, f),
            false => 1.0,
        };
        at_updates / noise_gain(dt, f)
    });
    k * filtered
}

#[cfg(test)]
mod tests {
    use super::held_resolution;

    /// A 1° step whose ramp a 25 Hz log reads at 0.4° and 0.8°, each once,
    /// shows no grid; the same ramp rounded to 0.2° at 1 kHz, each level
    /// held, shows 0.2°; a held value dithering between two codes 0.2°
    /// apart shows 0.2°; a bare jump between two held values shows none.
    #[test]
    fn a_grid_is_read_from_held_levels_and_dithers_not_from_a_ramp() {
        let mut ramp = vec![0.0; 20];
        ramp.extend([0.4, 0.8]);
        ramp.extend(vec![1.0; 20]);
        assert_eq!(held_resolution(&ramp), None);
        let rounded: Vec<f64> = (0..200)
            .map(|i| ((i as f64 / 80.0).min(1.0) / 0.2).round() * 0.2)
            .collect();
        let q = held_resolution(&rounded).unwrap();
        assert!((q - 0.2).abs() < 1e-9, "{q}");
        let mut dither = vec![0.0; 20];
        dither.extend([1.0, 1.2, 1.0, 1.0, 1.2, 1.0, 1.2]);
        let q = held_resolution(&dither).unwrap();
        assert!((q - 0.2).abs() < 1e-9, "{q}");
        let mut jump = vec![0.0; 20];
        jump.extend(vec![1.0; 20]);
        assert_eq!(held_resolution(&jump), None);
    }
}
