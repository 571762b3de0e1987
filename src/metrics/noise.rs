//! The white-noise deviation of a channel and its gain through the
//! zero-phase low-pass. Units: the channel's own; s; Hz.

use super::filter::zero_phase_low_pass;

/// White-noise deviation of `x`, from the median absolute difference of
/// neighbours (insensitive to the step and to slow trends), and at least
/// step/√12 for a channel on a logger's grid (its smallest non-zero
/// difference, the step, spanning its range in at most [`GRID_LEVELS`]):
/// rounding to a step of q adds a deviation of q/√12 that the median
/// difference, 0 when most neighbours repeat, does not show.
pub(super) fn noise_deviation(x: &[f64]) -> f64 {
    let mut d: Vec<f64> = x.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    if d.len() < 5 {
        return 0.0;
    }
    let step = d
        .iter()
        .copied()
        .filter(|v| *v > 0.0)
        .fold(f64::INFINITY, f64::min);
    let (lo, hi) = x
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(*v), b.max(*v))
        });
    let grid = step.is_finite() && (hi - lo) / step <= GRID_LEVELS;
    d.sort_by(f64::total_cmp);
    let from_differences = d[d.len() / 2] / (0.6745 * std::f64::consts::SQRT_2);
    match grid {
        true => from_differences.max(step / 12f64.sqrt()),
        false => from_differences,
    }
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
