//! Channels a logger samples slower than the log and holds between updates
//! (a 10 Hz GPS sideslip in a 100 Hz log): each value repeats for a fixed
//! number of samples, then steps. Replayed as they are, the steps are
//! residuals no model can close, of the size of the signal's change over an
//! update interval. Such a channel is found by its holds — at least
//! [`MIN_HOLDS`] of them, the median at least 2 samples long and
//! [`REGULAR_SHARE`] of them at least 2 samples long and within one sample
//! of it (a quantised channel holds values too, but for irregular lengths;
//! a value that changes at the next sample is no hold, so a smooth channel
//! whose last written digit repeats at every other sample or so, holds of
//! 1, 2 and 3 samples, is not one updated every 2) — and whose updates
//! are not steps of its resolution: a channel that changes, at
//! [`REGULAR_SHARE`] of its updates, by no more than 1.5 times its
//! smallest change moves by its last written digit (a smooth slow ramp
//! crossing a digit every 2 or 3 samples; a simulated yaw rate at 0.5 m/s
//! dithering by ±1e-11 rad/s, 4 samples a side), where a logger's updates
//! carry the signal's change over the interval, of every size — and its
//! held samples are interpolated linearly in time between the updates (the
//! value is taken as the measurement at its update instant); the last
//! hold, with no next update, stays. Every such channel and the samples changed are reported.
//! Units: the channel's SI unit; times in s.

use super::repair::repair;
use super::report::{CleaningReport, HeldChannel};
use super::SEARCHED;
use crate::measured::MeasuredRun;

/// Fewest complete holds to call a channel held.
const MIN_HOLDS: usize = 20;

/// Share of the holds at least 2 samples long and within one sample of
/// the median length.
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
    let regular = lengths
        .iter()
        .filter(|&&l| l >= 2 && l.abs_diff(every) <= 1)
        .count();
    (every >= 2
        && regular as f64 >= REGULAR_SHARE * lengths.len() as f64
        && !by_resolution(x, &starts))
    .then_some((starts, every))
}

/// Whether `x`'s changes at the hold starts `starts` are, at
/// [`REGULAR_SHARE`] of them, within 1.5 times the smallest: a channel
/// moving by the last digit it is written with, not a held one.
fn by_resolution(x: &[f64], starts: &[usize]) -> bool {
    let steps: Vec<f64> = starts
        .windows(2)
        .map(|w| (x[w[1]] - x[w[0]]).abs())
        .collect();
    let least = steps.iter().copied().fold(f64::INFINITY, f64::min);
    let one = steps.iter().filter(|&&s| s <= 1.5 * least).count();
    one as f64 >= REGULAR_SHARE * steps.len() as f64
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
        report.samples_interpolated += samples;
        let log_rate = 1.0 / super::median_interval(&t);
        report.held.push(HeldChannel {
            run: name.clone(),
            channel: ch,
            every,
            // The logger's rate, from its median hold: counting the changes
            // misses the updates that repeat a quantised value (a steer
            // held on a straight), and read a 20 Hz steer as 15.1 Hz beside
            // "every 5 samples of the 100 Hz log".
            update_rate: log_rate / every as f64,
            log_rate,
            samples,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_signals::gauss_noise;
    use super::*;

    /// A steer held at 20 Hz in a 100 Hz log whose quantised value repeats
    /// across updates on a straight: its rate is the logger's, 20 Hz, as
    /// "every 5 samples" says, not the rate of its changes.
    #[test]
    fn a_held_channel_is_reported_at_its_updates_rate_not_its_changes() {
        let n = 3000;
        let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.01).collect();
        let update = |i: usize| {
            let s = t[i - i % 5];
            // A straight for the first 10 s: the quantised value repeats.
            let v = if s < 10.0 {
                0.0
            } else {
                0.05 * (0.7 * s).sin()
            };
            (v / 2e-4).round() * 2e-4
        };
        let mut run = crate::measured::MeasuredRun {
            path: "r.csv".into(),
            t: t.clone(),
            speed: vec![15.0; n],
            steer: (0..n).map(update).collect(),
            yaw_rate: vec![0.0; n],
            ay: None,
            beta: None,
            roll: None,
            bank: None,
            ax: None,
            masked: Vec::new(),
        };
        let mut report = CleaningReport::default();
        treat_held(&mut run, &mut report);
        let h = &report.held[0];
        assert_eq!(h.every, 5);
        assert!((h.update_rate - 20.0).abs() < 1e-9, "{}", h.update_rate);
    }

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

    #[test]
    fn a_smooth_channel_repeating_or_dithering_in_its_last_digit_is_not_held() {
        // A slow ramp written to its last digit (1e-5), crossing one every
        // 2.2 samples or so: holds of 2 and 3 samples, as regular as a
        // channel updated every 2.
        let ramp: Vec<f64> = (0..3000)
            .map(|i| {
                let i = i as f64;
                (0.45 * i + 40.0 * (i / 700.0).sin()).round() * 1e-5
            })
            .collect();
        assert!(holds(&ramp).is_none());
        // A slow exponential so written: holds of 1, 2, 3 samples and more
        // (at 1 m/s, 83 % of a simulated sideslip's holds were within one
        // sample of 2, a third of them of 1 sample).
        let slow: Vec<f64> = (0..3000)
            .map(|i| {
                let v = 0.0113 * (1.0 - (-(i as f64) / 900.0).exp()) + 0.01;
                (v * 1e5).round() / 1e5
            })
            .collect();
        assert!(holds(&slow).is_none());
        // A steady value dithering by one unit of its last digit, 4 samples
        // a side: regular holds, every update a return.
        let dither: Vec<f64> = (0..3000)
            .map(|i| 0.003_138_641_3 + if (i / 4) % 2 == 0 { 0.0 } else { 1e-11 })
            .collect();
        assert!(holds(&dither).is_none());
    }
}
