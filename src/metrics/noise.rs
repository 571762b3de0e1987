//! The white-noise deviation of a channel and its gain through the
//! zero-phase low-pass. Units: the channel's own; s; Hz.

use super::zero_phase_low_pass;

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
