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
//! hold, with no next update, stays. A hold of several update periods is
//! updates that repeated one value (a quantised steer on a straight or at
//! its stop): the value stays until the last of them and moves to the next
//! over one period, not over the whole hold. Every such channel and the
//! samples changed are reported, with its mean update rate.
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
/// A hold of several update periods is updates that repeated its value (a
/// quantised steer on a straight or at its stop): the value stays until the
/// last of them, one period before the next change, and moves over that
/// period only — a ramp over the whole hold (1.3 s of a steer at its
/// 0.3 rad stop, seconds of a straight) runs ahead of the signal by up to
/// the next change. A stuck hold (`stuck`, indices into `h.starts`) is a
/// logger that stopped updating, its values unknown: it is repaired by
/// the ramp over its whole length.
/// Returns the held samples (not the starts) changed.
fn interpolate(t: &[f64], x: &mut [f64], h: &Holds, stuck: &[usize]) -> usize {
    let at = instants(t, h);
    let values: Vec<f64> = h.starts.iter().map(|&i| x[i]).collect();
    let last = h.starts.len() - 1;
    // Where each hold's move to the next update starts.
    let from: Vec<f64> = (0..last)
        .map(|k| {
            if h.updates(t, k) > 1 && !stuck.contains(&k) {
                at[k].max(at[k + 1] - h.period)
            } else {
                at[k]
            }
        })
        .collect();
    let mut k = 0;
    for (i, xi) in x.iter_mut().enumerate().take(h.starts[last]) {
        while k + 1 < last && at[k + 1] <= t[i] {
            k += 1;
        }
        let f = (t[i] - from[k]) / (at[k + 1] - from[k]);
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
        let stuck = stuck_holds(&t, x, &h, &slow);
        for &i in &stuck {
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
        let samples = interpolate(&t, x, &h, &stuck) - stuck_samples;
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
#[path = "held_tests.rs"]
mod tests;
