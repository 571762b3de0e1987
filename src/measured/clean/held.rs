//! Channels a logger samples slower than the log and holds between updates
//! (a 10 Hz GPS sideslip in a 100 Hz log): each value repeats for a fixed
//! number of samples, then steps. Replayed as they are, the steps are
//! residuals no model can close, of the size of the signal's change over an
//! update interval. Such a channel is found by its holds — at least
//! [`MIN_HOLDS`] of them, the median at least 2 samples long and
//! [`REGULAR_SHARE`] within one sample of it (a quantised channel holds
//! values too, but for irregular lengths) — and its held samples are
//! interpolated linearly in time between the updates (the value is taken
//! as the measurement at its update instant); the last hold, with no next
//! update, stays. Every such channel and the samples changed are reported.
//! Units: the channel's SI unit; times in s.

use super::glitches::repair;
use super::report::{CleaningReport, HeldChannel};
use super::SEARCHED;
use crate::measured::MeasuredRun;

/// Fewest complete holds to call a channel held.
const MIN_HOLDS: usize = 20;

/// Share of the holds within one sample of the median length.
const REGULAR_SHARE: f64 = 0.8;

/// The starts of the holds of `x` (the samples where its value changes,
/// and the first) and the median length of the complete holds, when the
/// channel is held at a lower rate.
fn holds(x: &[f64]) -> Option<(Vec<usize>, usize)> {
    let starts: Vec<usize> = (0..x.len())
        .filter(|&i| i == 0 || x[i] != x[i - 1])
        .collect();
    let mut lengths: Vec<usize> = starts.windows(2).map(|w| w[1] - w[0]).collect();
    if lengths.len() < MIN_HOLDS {
        return None;
    }
    lengths.sort_unstable();
    let every = lengths[lengths.len() / 2];
    let regular = lengths.iter().filter(|&&l| l.abs_diff(every) <= 1).count();
    (every >= 2 && regular as f64 >= REGULAR_SHARE * lengths.len() as f64)
        .then_some((starts, every))
}

/// Interpolates `x` (sampled at `t`) between the hold starts `starts`, as
/// a glitch is repaired ([`repair`]); returns the samples changed.
fn interpolate(t: &[f64], x: &mut [f64], starts: &[usize]) -> usize {
    let mut held = vec![false; x.len()];
    for w in starts.windows(2) {
        held[w[0] + 1..w[1]].iter_mut().for_each(|h| *h = true);
    }
    repair(t, x, &held);
    held.iter().filter(|&&h| h).count()
}

/// Finds the held channels of `run`, interpolates them between their
/// updates and reports each.
pub fn treat_held(run: &mut MeasuredRun, report: &mut CleaningReport) {
    let t = run.t.clone();
    let name = run.path.display().to_string();
    for ch in SEARCHED {
        let Some(x) = ch.of_mut(run) else { continue };
        let Some((starts, every)) = holds(x) else {
            continue;
        };
        let samples = interpolate(&t, x, &starts);
        let span = t[starts[starts.len() - 1]] - t[starts[0]];
        report.samples_interpolated += samples;
        report.held.push(HeldChannel {
            run: name.clone(),
            channel: ch,
            every,
            update_rate: (starts.len() - 1) as f64 / span,
            samples,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_signals::gauss_noise;
    use super::*;

    #[test]
    fn a_channel_held_at_a_tenth_of_the_rate_is_interpolated_between_updates() {
        // A 0.5 Hz sine with noise, updated every 10th sample of 100 Hz.
        let n = 2000;
        let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.01).collect();
        let noise = gauss_noise(n, 1e-4, 3);
        let truth: Vec<f64> = t
            .iter()
            .map(|&s| 0.01 * (std::f64::consts::PI * s).sin())
            .collect();
        let mut x: Vec<f64> = (0..n)
            .map(|i| truth[i - i % 10] + noise[i - i % 10])
            .collect();
        let (starts, every) = holds(&x).expect("held");
        assert_eq!((every, starts.len()), (10, 200));
        let changed = interpolate(&t, &mut x, &starts);
        assert_eq!(changed, 199 * 9);
        // Between updates the value now follows the signal to its noise and
        // the curvature over 0.1 s (about 1e-5), where the hold was off by
        // up to its change over an interval (3e-3).
        let worst = (0..1990)
            .map(|i| (x[i] - truth[i]).abs())
            .fold(0.0, f64::max);
        assert!(worst < 6e-4, "{worst}");
        // The updates themselves are unchanged.
        assert!(starts.iter().all(|&i| x[i] == truth[i] + noise[i]));
    }

    #[test]
    fn noise_a_quantised_channel_and_a_constant_are_not_held() {
        let x = gauss_noise(3000, 0.01, 4);
        assert!(holds(&x).is_none());
        // A steer encoder of 0.001 rad on a slow irregular sine: holds of
        // every length.
        let q: Vec<f64> = (0..3000)
            .map(|i| {
                let s = i as f64 * 0.01;
                (0.02 * (0.3 * s).sin() * (1.0 + 0.5 * (0.07 * s).sin()) / 0.001).round() * 0.001
            })
            .collect();
        assert!(holds(&q).is_none());
        assert!(holds(&[0.5; 3000]).is_none());
    }
}
