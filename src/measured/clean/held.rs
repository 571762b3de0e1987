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
//! hold, with no next update, stays. Every such channel and the samples
//! changed are reported, with its mean update rate.
//!
//! An update is seen at the first sample at or after its instant: up to a
//! sample interval late, by an amount that cycles when the rates are not
//! multiples (20 Hz in a 50 Hz log: on time, then 0.01 s late, holds of
//! 3 and 2 samples). Interpolated between the samples where the value
//! changes, such a channel lags by half the cycle's lateness on average
//! (0.005 s for a steer: axle stiffnesses 9 standard errors off on a
//! 10-minute log). The instants are put back on a regular update clock
//! ([`instants`]), and the rate is the mean update period's, not the
//! median hold's (0.06 s).
//!
//! The holds are judged in time, not in samples: a log whose rate changes
//! within a run (100 Hz, then 50 Hz) holds a 20 Hz steer for 5 samples,
//! then for 2 or 3, and every hold is one update period, 0.05 s, within a
//! sample interval of its stretch of the log.
//!
//! A held channel can stick too (a logger repeating its last update): a
//! hold of at least [`MIN_STUCK_UPDATES`] update periods among holds of one
//! period ([`REGULAR_SHARE`] of the [`STUCK_CONTEXT`] on each side, none
//! of them slow), that ends with a step of at least half the channel's
//! change over the hold (its neighbours' median change per update times
//! the hold's updates) is stuck: a signal that moved at every update and
//! then stopped, where a steer held on its stop or at a peak leaves its
//! hold with an ordinary step. The stuck repeats are reported as stuck
//! glitches, an input's repaired (interpolated between its updates) and a
//! response's masked, and not counted as held samples.
//! Units: the channel's SI unit; times in s.

use super::report::{CleaningReport, Glitch, GlitchKind, HeldChannel, Treatment};
use super::{SEARCHED, STUCK_CONTEXT};
use crate::measured::MeasuredRun;

/// Fewest complete holds to call a channel held.
const MIN_HOLDS: usize = 20;

/// Share of the holds at least 2 samples long and within one sample
/// interval of the median hold's duration.
const REGULAR_SHARE: f64 = 0.8;

/// Fewest update periods a hold of a held channel lasts to be stuck.
pub(crate) const MIN_STUCK_UPDATES: usize = 5;

/// The holds of a held channel: where each starts (the samples where its
/// value changes, and the first) and the mean update period, s.
struct Holds {
    starts: Vec<usize>,
    period: f64,
}

impl Holds {
    /// Hold `i`'s duration in update periods, at least 1.
    fn updates(&self, t: &[f64], i: usize) -> usize {
        let d = t[self.starts[i + 1]] - t[self.starts[i]];
        (d / self.period).round().max(1.0) as usize
    }
}

/// The holds of `x` (sampled at `t`), when the channel is held at a lower
/// rate.
fn holds(t: &[f64], x: &[f64]) -> Option<Holds> {
    let starts: Vec<usize> = (0..x.len())
        .filter(|&i| i == 0 || x[i] != x[i - 1])
        .collect();
    if starts.len() <= MIN_HOLDS {
        return None;
    }
    let mut durations: Vec<f64> = starts.windows(2).map(|w| t[w[1]] - t[w[0]]).collect();
    durations.sort_by(f64::total_cmp);
    let median = durations[durations.len() / 2];
    // Within one sample interval of the hold's own stretch of the log (a
    // hair more: the times are written to a few digits).
    let near = |w: &[usize]| {
        let (len, d) = (w[1] - w[0], t[w[1]] - t[w[0]]);
        (d - median).abs() <= d / len as f64 * (1.0 + 1e-6)
    };
    let regular = starts
        .windows(2)
        .filter(|w| w[1] - w[0] >= 2 && near(w))
        .count();
    let held = median > 0.0
        && regular as f64 >= REGULAR_SHARE * durations.len() as f64
        && !by_resolution(x, &starts);
    held.then(|| Holds {
        period: mean_period(t, &starts, near),
        starts,
    })
}

/// The mean update period of a held channel, s, from its holds `near` the
/// median one: a 20 Hz update read at 50 Hz is held for 2 samples, then 3
/// (0.04 s, 0.06 s), and the median hold, either, is no update's period.
fn mean_period(t: &[f64], starts: &[usize], near: impl Fn(&[usize]) -> bool) -> f64 {
    let regular: Vec<f64> = starts
        .windows(2)
        .filter(|w| near(w))
        .map(|w| t[w[1]] - t[w[0]])
        .collect();
    regular.iter().sum::<f64>() / regular.len() as f64
}

/// Changes on each side whose phases on the update clock bound a change's
/// update instant ([`instants`]).
const PHASE_WINDOW: usize = 20;

/// The instant of each update of a held channel (its starts `h.starts`),
/// s. A sample reads an update at or after its instant, before the next
/// sample: the change is seen up to one sample interval late (a 20 Hz
/// update read at 50 Hz: on time, then 0.01 s late, in turn). On a regular
/// update clock (period `h.period`), the change seen least late among its
/// [`PHASE_WINDOW`] neighbours on each side fixes the clock's phase, and
/// each update is put at the latest instant on it at or before its change
/// was seen — exact when some updates fall on samples, never later than
/// the change, and never at or before the sample that still read the old
/// value. The first hold's start stays (nothing read before it).
fn instants(t: &[f64], h: &Holds) -> Vec<f64> {
    let (s, p) = (&h.starts, h.period);
    // A time difference on the clock, in (-p/2, p/2].
    let phase = |d: f64| d - p * (d / p).round();
    (0..s.len())
        .map(|k| {
            let seen = t[s[k]];
            if s[k] == 0 {
                return seen;
            }
            let near = k.saturating_sub(PHASE_WINDOW)..(k + PHASE_WINDOW + 1).min(s.len());
            let late = near
                .filter(|&j| s[j] > 0)
                .map(|j| -phase(t[s[j]] - seen))
                .fold(0.0, f64::max);
            let interval = seen - t[s[k] - 1];
            // Times written to a few digits: a lateness below a
            // thousandth of an interval is none.
            if late < 1e-3 * interval {
                seen
            } else {
                seen - late.min(interval * (1.0 - 1e-6))
            }
        })
        .collect()
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

/// The stuck holds of a held channel (module doc): each as the index of
/// its hold in `h.starts`.
fn stuck_holds(t: &[f64], x: &[f64], h: &Holds, slow: &[bool]) -> Vec<usize> {
    let complete = h.starts.len() - 1;
    let c = STUCK_CONTEXT;
    let step = |j: usize| (x[h.starts[j + 1]] - x[h.starts[j]]).abs();
    let mut out = Vec::new();
    for i in c..complete.saturating_sub(c) {
        let k = h.updates(t, i);
        if k < MIN_STUCK_UPDATES || slow[h.starts[i - c]..h.starts[i + c + 1]].contains(&true) {
            continue;
        }
        let around: Vec<usize> = (i - c..i + c + 1).filter(|&j| j != i).collect();
        let single = around.iter().filter(|&&j| h.updates(t, j) == 1).count();
        if (single as f64) < REGULAR_SHARE * around.len() as f64 {
            continue;
        }
        // The change per update between the neighbours (not into or out of
        // the hold).
        let mut per_update: Vec<f64> = (i - c..i - 1)
            .chain(i + 1..i + c)
            .map(|j| step(j) / h.updates(t, j) as f64)
            .collect();
        let m = super::median(&mut per_update);
        if m > 0.0 && step(i) >= 0.5 * k as f64 * m {
            out.push(i);
        }
    }
    out
}

/// Samples over which [`rate_changes`] takes a local median interval.
const RATE_BLOCK: usize = 100;

/// Whether the log's rate changes within `t`: the median interval of a
/// block of [`RATE_BLOCK`] samples differs from the whole log's `interval`
/// by more than a tenth (a logger's jitter moves single intervals, not a
/// block's median).
fn rate_changes(t: &[f64], interval: f64) -> bool {
    t.chunks(RATE_BLOCK)
        .filter(|b| b.len() > RATE_BLOCK / 2)
        .any(|b| (super::median_interval(b) / interval - 1.0).abs() > 0.1)
}

/// Interpolates `x` (sampled at `t`) linearly in time between its updates
/// (their values at the hold starts `h.starts`, at their [`instants`]),
/// as a glitch is repaired; the last hold, with no next update, stays.
/// Returns the held samples (not the starts) changed.
fn interpolate(t: &[f64], x: &mut [f64], h: &Holds) -> usize {
    let at = instants(t, h);
    let values: Vec<f64> = h.starts.iter().map(|&i| x[i]).collect();
    let last = h.starts.len() - 1;
    let mut k = 0;
    for (i, xi) in x.iter_mut().enumerate().take(h.starts[last]) {
        while k + 1 < last && at[k + 1] <= t[i] {
            k += 1;
        }
        let f = (t[i] - at[k]) / (at[k + 1] - at[k]);
        *xi = values[k] + (values[k + 1] - values[k]) * f.clamp(0.0, 1.0);
    }
    h.starts[last] - last
}

/// Finds the held channels of `run`, interpolates them between their
/// updates and reports each; the stuck holds among them (samples below
/// `min_speed` are never judged stuck) are reported as stuck glitches, a
/// response's masked.
pub fn treat_held(run: &mut MeasuredRun, min_speed: f64, report: &mut CleaningReport) {
    let t = run.t.clone();
    let slow: Vec<bool> = run.speed.iter().map(|u| *u < min_speed).collect();
    let name = run.path.display().to_string();
    let log_interval = super::median_interval(&t);
    let mut masked = Vec::new();
    for ch in SEARCHED {
        let Some(x) = ch.of_mut(run) else { continue };
        let Some(h) = holds(&t, x) else {
            continue;
        };
        let mut stuck_samples = 0;
        for i in stuck_holds(&t, x, &h, &slow) {
            // The hold's first sample is the update; the repeats after it
            // are the stuck ones.
            let (s, e) = (h.starts[i] + 1, h.starts[i + 1]);
            stuck_samples += e - s;
            report.push_glitch(Glitch {
                run: name.clone(),
                t: t[s],
                channel: ch,
                kind: GlitchKind::Stuck,
                value: x[s],
                samples: e - s,
                treatment: Treatment::of(ch),
                dropped_with: None,
            });
            if ch.is_input() {
                report.samples_repaired += e - s;
            } else {
                masked.extend(s..e);
            }
        }
        let samples = interpolate(&t, x, &h) - stuck_samples;
        report.samples_interpolated += samples;
        let log_rate = 1.0 / log_interval;
        let samples_per_update = h.period / log_interval;
        // The log's rate changes where its intervals do (beyond a tenth):
        // a hold is then a different count of samples in each stretch.
        let rate_changes = rate_changes(&t, log_interval);
        report.held.push(HeldChannel {
            run: name.clone(),
            channel: ch,
            every: samples_per_update.round().max(1.0) as usize,
            samples_per_update,
            // The logger's rate, from its mean regular hold in time:
            // counting the changes misses the updates that repeat a
            // quantised value (a steer held on a straight), and read a
            // 20 Hz steer as 15.1 Hz beside "every 5 samples of the 100 Hz
            // log"; the median hold read one at 20 Hz in a 50 Hz log, held
            // for 2 samples and 3 in turn, as 16.7 Hz.
            update_rate: 1.0 / h.period,
            log_rate,
            log_rate_changes: rate_changes,
            samples,
        });
    }
    run.masked.extend(masked);
    run.masked.sort_unstable();
    run.masked.dedup();
}

#[cfg(test)]
mod tests {
    use super::super::test_signals::gauss_noise;
    use super::*;

    /// A run at 15 m/s with `steer` over `t` and a still gyro, nothing else
    /// logged.
    fn straight_at_15(t: Vec<f64>, steer: Vec<f64>) -> MeasuredRun {
        let n = t.len();
        MeasuredRun::new("r.csv", t, vec![15.0; n], steer, vec![0.0; n])
    }

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
        let mut run = straight_at_15(t.clone(), (0..n).map(update).collect());
        let mut report = CleaningReport::default();
        treat_held(&mut run, 5.0, &mut report);
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
        let h = holds(&t, &x).expect("held");
        assert!((h.period - 0.1).abs() < 1e-9 && h.starts.len() == 200);
        let changed = interpolate(&t, &mut x, &h);
        let starts = h.starts;
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
        let t: Vec<f64> = (0..3000).map(|i| i as f64 * 0.01).collect();
        assert!(holds(&t, &x).is_none());
        // A steer encoder of 0.001 rad on a slow irregular sine: holds of
        // every length.
        let q: Vec<f64> = (0..3000)
            .map(|i| {
                let s = i as f64 * 0.01;
                (0.02 * (0.3 * s).sin() * (1.0 + 0.5 * (0.07 * s).sin()) / 0.001).round() * 0.001
            })
            .collect();
        assert!(holds(&t, &q).is_none());
        assert!(holds(&t, &[0.5; 3000]).is_none());
    }

    #[test]
    fn a_smooth_channel_repeating_or_dithering_in_its_last_digit_is_not_held() {
        let t: Vec<f64> = (0..3000).map(|i| i as f64 * 0.01).collect();
        // A slow ramp written to its last digit (1e-5), crossing one every
        // 2.2 samples or so: holds of 2 and 3 samples, as regular as a
        // channel updated every 2.
        let ramp: Vec<f64> = (0..3000)
            .map(|i| {
                let i = i as f64;
                (0.45 * i + 40.0 * (i / 700.0).sin()).round() * 1e-5
            })
            .collect();
        assert!(holds(&t, &ramp).is_none());
        // A slow exponential so written: holds of 1, 2, 3 samples and more
        // (at 1 m/s, 83 % of a simulated sideslip's holds were within one
        // sample of 2, a third of them of 1 sample).
        let slow: Vec<f64> = (0..3000)
            .map(|i| {
                let v = 0.0113 * (1.0 - (-(i as f64) / 900.0).exp()) + 0.01;
                (v * 1e5).round() / 1e5
            })
            .collect();
        assert!(holds(&t, &slow).is_none());
        // A steady value dithering by one unit of its last digit, 4 samples
        // a side: regular holds, every update a return.
        let dither: Vec<f64> = (0..3000)
            .map(|i| 0.003_138_641_3 + if (i / 4) % 2 == 0 { 0.0 } else { 1e-11 })
            .collect();
        assert!(holds(&t, &dither).is_none());
    }

    /// A steer updated at 20 Hz in a log at 100 Hz for 30 s, then at
    /// 50 Hz: holds of 5 samples, then of 3 and 2 (0.06 s, 0.04 s).
    #[test]
    fn a_channel_held_at_20_hz_in_a_log_whose_rate_halves_is_held_throughout() {
        let mut t: Vec<f64> = (0..3000).map(|i| i as f64 * 0.01).collect();
        t.extend((0..1500).map(|i| 30.0 + i as f64 * 0.02));
        // The update each sample holds: every 5th sample, then every 2.5th.
        let update = |i: usize| {
            if i < 3000 {
                i / 5
            } else {
                600 + 2 * (i - 3000) / 5
            }
        };
        let x: Vec<f64> = (0..t.len())
            .map(|i| 0.05 * (0.6 * std::f64::consts::PI * update(i) as f64 * 0.05).sin())
            .collect();
        let h = holds(&t, &x).expect("held");
        // The mean of the holds near the median (0.05 s, 0.06 s, 0.04 s): as
        // many of 3 samples as of 2, to one.
        assert!((h.period / 0.05 - 1.0).abs() < 5e-4, "{}", h.period);
        assert!(rate_changes(&t, super::super::median_interval(&t)));
        assert!(!rate_changes(&t[..3000], 0.01));
        let mut run = straight_at_15(t.clone(), x);
        let mut report = CleaningReport::default();
        treat_held(&mut run, 5.0, &mut report);
        let h = &report.held[0];
        assert!(h.log_rate_changes && (h.update_rate / 20.0 - 1.0).abs() < 5e-4);
        // Interpolated in time between the updates' instants: update 900
        // read at 45.00 s, 901 first read at 45.06 s but made at 45.05 s,
        // so 45.02 s is two fifths of the way.
        let k = 3000 + 750;
        assert!((run.t[k] - 45.0).abs() < 1e-9);
        let (a, b) = (
            0.05 * (0.6 * std::f64::consts::PI * 45.0).sin(),
            0.05 * (0.6 * std::f64::consts::PI * 45.05).sin(),
        );
        // To the clock's period's error over the window (2e-4 s, 2e-5 rad),
        // where a third of the way is (b − a)/15 = 3e-4 rad off.
        assert!((run.steer[k + 1] - (3.0 * a + 2.0 * b) / 5.0).abs() < 5e-5);
    }

    /// A 1.3 Hz sine updated at `rate` Hz (from `phase` s) read in a log at
    /// `log` Hz for 20 s: the rate and the true signal between updates.
    fn held_sine(rate: f64, log: f64, phase: f64) -> (f64, f64) {
        let n = (20.0 * log) as usize;
        let t: Vec<f64> = (0..n).map(|i| i as f64 / log).collect();
        let truth = |s: f64| 0.05 * (2.6 * std::f64::consts::PI * s).sin();
        // The last update at or before each sample.
        let steer = t
            .iter()
            .map(|&s| truth(((s - phase) * rate + 1e-9).floor() / rate + phase))
            .collect();
        let mut run = straight_at_15(t.clone(), steer);
        let mut report = CleaningReport::default();
        treat_held(&mut run, 5.0, &mut report);
        // Linear between updates: off by the curvature over an update,
        // below 0.05·(2.6π)²/8·(1/rate)² (0.0026 rad at 20 Hz).
        let worst = (n / 10..n - n / 10)
            .map(|i| (run.steer[i] - truth(t[i])).abs())
            .fold(0.0, f64::max);
        (report.held[0].update_rate, worst)
    }

    /// A 20 Hz steer in a 50 Hz log, held for 3 samples and 2 in turn, was
    /// read at 16.7 Hz (the median hold, 0.06 s) and interpolated between
    /// the samples where it changed, half of them 0.01 s after the update:
    /// now 20 Hz, and the signal between the updates' instants. So a 30 Hz
    /// steer in a 100 Hz log (holds of 3, 3 and 4) and one whose updates
    /// fall between samples.
    #[test]
    fn a_steer_at_20_hz_in_a_50_hz_log_is_at_20_hz_and_interpolated_at_its_instants() {
        let bound = |rate: f64| 0.05 * (2.6 * std::f64::consts::PI).powi(2) / 8.0 / rate / rate;
        for (rate, log) in [(20.0, 50.0), (30.0, 100.0)] {
            let (r, worst) = held_sine(rate, log, 0.0);
            assert!((r / rate - 1.0).abs() < 2e-3, "{rate} in {log}: {r}");
            assert!(worst < 1.05 * bound(rate), "{rate} in {log}: {worst}");
        }
        // Updates 0.007 s before a sample, then 0.017 s: the clock's phase
        // is known to the cycle's step in lateness (0.01 s), and the
        // instants put up to that late, no later.
        let (r, worst) = held_sine(20.0, 50.0, 0.013);
        let step = 0.05 * 2.6 * std::f64::consts::PI * 0.007;
        assert!((r / 20.0 - 1.0).abs() < 2e-3, "{r}");
        assert!(worst < 1.05 * (bound(20.0) + step), "{worst}");
        // Between the changes' samples the error was the signal's change
        // over up to a sample interval late (0.05·2.6π·0.01 = 0.004 rad).
        assert!(0.05 * 2.6 * std::f64::consts::PI * 0.01 > 1.5 * bound(20.0));
    }

    /// A steer at 20 Hz in a 100 Hz log (a 0.5 Hz sine of 0.05 rad,
    /// clipped at ±0.04 rad: stops of 8 updates, left with an ordinary
    /// step) stuck at its 20.00 s update for 8 updates: one stuck glitch,
    /// the 39 repeats, repaired; the stops at the limit are none.
    #[test]
    fn a_held_steer_stuck_for_eight_updates_is_stuck_and_its_stops_at_a_limit_are_not() {
        let n = 6000;
        let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.01).collect();
        let at = |u: usize| {
            let v = 0.05 * (std::f64::consts::PI * u as f64 * 0.05).sin();
            (v.clamp(-0.04, 0.04) / 2e-4).round() * 2e-4
        };
        let mut steer: Vec<f64> = (0..n).map(|i| at(i / 5)).collect();
        let frozen = steer[2000];
        steer[2000..2040].iter_mut().for_each(|s| *s = frozen);
        let mut run = straight_at_15(t.clone(), steer);
        let mut report = CleaningReport::default();
        treat_held(&mut run, 5.0, &mut report);
        assert_eq!(report.counts.stuck, 1, "{:?}", report.glitches);
        let g = &report.glitches[0];
        assert!((g.t - 20.01).abs() < 1e-9 && g.samples == 39, "{g:?}");
        assert_eq!(g.treatment, Treatment::Repaired);
        assert_eq!(report.samples_repaired, 39);
        // The stuck repeats counted as repaired, not as held samples.
        let mut x: Vec<f64> = (0..n).map(|i| at(i / 5)).collect();
        x[2000..2040].iter_mut().for_each(|s| *s = frozen);
        let h = holds(&t, &x).expect("held");
        let all = interpolate(&t, &mut x, &h);
        assert_eq!(report.held[0].samples, all - 39);
        assert_eq!(report.samples_interpolated, all - 39);
    }
}
