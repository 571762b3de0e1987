//! A hold of a response channel that is a settled response, not a stuck
//! sensor. A noise-free response (a simulation, a filtered channel)
//! logged coarsely (20 Hz) relaxes onto its steady value within a few
//! samples and then repeats it exactly to its written digits; the stretch
//! before the hold then bends by as much as it moves (a decaying
//! oscillation sampled every 0.05 s), which the stuck-value tests in
//! `glitches.rs` read as noise cut off by a logger. Such a hold is
//! released when both hold:
//!
//! - the channel approached the held value smoothly: its last
//!   [`APPROACH`] differences, the one onto the held value included, are
//!   each within [`APPROACH_SHARE`] of the channel's 1–99 % range (a noisy
//!   channel moves by its noise on every sample, a logger's jump onto a
//!   frozen value by the jump, a frozen transient by its rate);
//! - every other response channel present (yaw rate, ay, beta) is steady
//!   over the hold: the means of the hold's first, middle and last thirds
//!   are within [`STEADY_SHARE`] of that channel's 1–99 % range (a sensor
//!   frozen while the car still responds is stuck).
//!
//! Units: each channel's own; shares are fractions of a range.

/// Differences before a hold, the one onto it included, judged for a
/// smooth approach.
const APPROACH: usize = 3;

/// Largest difference of a smooth approach, as a share of the channel's
/// 1–99 % range: a noise-free response at rest moves by its last written
/// digits; noise of a tenth of a percent of the range already exceeds it.
const APPROACH_SHARE: f64 = 1e-3;

/// Largest spread of the thirds' means of another channel over the hold,
/// as a share of its 1–99 % range, for it to be steady: three times the
/// spread of such a mean under a noise of 5 % of the range over a hold of
/// 50 samples, well under the move of a transient.
const STEADY_SHARE: f64 = 0.05;

/// The 1–99 % range of `x` (nearest rank, as the glitch thresholds'
/// range; computed here so that `glitches.rs`, which asks this file, is
/// not asked back).
fn range(x: &[f64]) -> f64 {
    let mut s = x.to_vec();
    s.sort_by(f64::total_cmp);
    let Some(last) = s.len().checked_sub(1) else {
        return 0.0;
    };
    let q = |p: f64| s[(last as f64 * p).round() as usize];
    q(0.99) - q(0.01)
}

/// Whether `x` reached the value it holds from `start` smoothly: its last
/// [`APPROACH`] differences, the one onto the hold included, are within
/// [`APPROACH_SHARE`] of its range.
fn approached_smoothly(x: &[f64], start: usize) -> bool {
    if start < APPROACH {
        return false;
    }
    let bound = APPROACH_SHARE * range(x);
    (start + 1 - APPROACH..=start).all(|k| (x[k] - x[k - 1]).abs() <= bound)
}

/// Whether `y` is steady over samples `start..end`: the means of the
/// span's thirds within [`STEADY_SHARE`] of its range.
fn steady(y: &[f64], start: usize, end: usize) -> bool {
    let third = ((end - start) / 3).max(1);
    let mean = |from: usize| {
        let to = (from + third).min(end);
        y[from..to].iter().sum::<f64>() / (to - from) as f64
    };
    let means = [
        mean(start),
        mean(start + (end - start - third) / 2),
        mean(end - third),
    ];
    let (lo, hi) = means
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), m| {
            (a.min(*m), b.max(*m))
        });
    hi - lo <= STEADY_SHARE * range(y)
}

/// Whether the hold of `x` at samples `start..start + len` is a settled
/// response: approached smoothly while every channel of `others` (the
/// other response channels of the run) is steady over it.
pub(super) fn settled_hold(x: &[f64], start: usize, len: usize, others: &[&[f64]]) -> bool {
    let end = start + len;
    approached_smoothly(x, start) && others.iter().all(|y| steady(y, start, end))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A damped response sampled at 20 Hz, written to 9 digits: exact from
    /// where its decay falls below the last digit.
    fn settle(n: usize, gain: f64) -> Vec<f64> {
        (0..n)
            .map(|i| {
                let s = i as f64 * 0.05;
                let v = gain * (1.0 - (-s / 0.15).exp() * (8.0 * s).cos());
                format!("{v:.9e}").parse().unwrap()
            })
            .collect()
    }

    #[test]
    fn a_settled_hold_is_released_and_a_frozen_one_is_not() {
        let (r, ay) = (settle(120, 0.09), settle(120, 2.0));
        let start = (1..120)
            .find(|&i| ay[i..].iter().all(|v| *v == ay[i]))
            .unwrap();
        assert!(start < 100, "{start}");
        assert!(settled_hold(&ay, start, 120 - start, &[&r]));
        // Frozen at 0.3 s, in the rise, while the yaw rate still moves.
        let mut frozen = ay.clone();
        frozen[6..30].iter_mut().for_each(|v| *v = ay[6]);
        assert!(!settled_hold(&frozen, 6, 24, &[&r]));
        // Jumped onto a value off the response, in the steady part.
        let mut jumped = ay.clone();
        jumped[80..100].iter_mut().for_each(|v| *v = 1.9);
        assert!(!settled_hold(&jumped, 80, 20, &[&r]));
        // Settled, but the yaw rate steps meanwhile.
        let mut moved = r.clone();
        moved[start + 10..].iter_mut().for_each(|v| *v *= 0.5);
        assert!(!settled_hold(&ay, start, 120 - start, &[&moved]));
    }
}
