//! Whether a measured record is a step steer the metrics can read
//! ([`check_step_shape`]): the steer held at its initial value over the
//! initial window (else the initial values mix the step in: a record
//! that starts just before the step), held at its step once it has
//! reached 90 % of it (else it is a sweep or a sine, whose "step" is the
//! difference of two windows' means), and risen within [`MAX_RISE`] (else
//! it is a ramp, whose response times are those of a car following its
//! input, about zero); and, before any of that, whether the record's steer
//! is a step at all ([`check_steer_is_a_step`]): a log of driving reverses
//! its steer again and again, and its windows' "step" is a step of nothing.

use super::{first_crossing, noise_deviation, noise_gain, window_mean, zero_phase_low_pass};
use super::{MetricSettings, StepMetrics};
use crate::error::{MetricsError, HELD_STEP, MIN_STRAIGHT};

/// The share of the step by which the steer has left its initial value
/// (the onset of the total-variance window).
const ONSET: f64 = 0.05;

/// White-noise deviations of the filtered steer within which a move in
/// the initial window is noise.
const NOISE_DEVIATIONS: f64 = 4.0;

/// The last time up to `to` at which `x` crosses `level` in the direction
/// of `sign` (linear interpolation between samples): the start of a rise
/// that a noisy signal crossed back and forth before.
pub(crate) fn last_crossing(t: &[f64], x: &[f64], level: f64, sign: f64, to: f64) -> Option<f64> {
    (1..t.len()).rev().find_map(|i| {
        let (a, b) = (sign * (x[i - 1] - level), sign * (x[i] - level));
        (t[i - 1] < to && a < 0.0 && b >= 0.0)
            .then(|| t[i - 1] + (t[i] - t[i - 1]) * a / (a - b))
            .filter(|&c| c <= to)
    })
}

/// The end of the initial window the shape is judged over: the stated
/// `pre_window` from the first sample, or where the steer first moves
/// within the window's last sample interval, the metrics' window cut at
/// the last sample before it (`initial.rs`). The stated end then falls
/// inside the interval in which the steer starts, which a slow log cannot
/// place: a 12.5 Hz record's sample 20 % up the ramp at 1.02 s, 0.02 s
/// before the window's end, was refused once a noise-free steer's ramp
/// samples were no longer read as a logger's grid (session 111), though
/// the metrics leave it out. A steer moving earlier is still refused.
fn window_end(t: &[f64], steer: &[f64], s: &MetricSettings) -> f64 {
    let nominal = t[0] + s.pre_window;
    let cut = super::initial::initial_end(t, steer, s);
    let dt = crate::measured::clean::median_interval(t);
    let moved = t.get(t.partition_point(|x| *x <= cut)).copied();
    match moved {
        Some(at) if cut < nominal && at > nominal - dt => cut,
        _ => nominal,
    }
}

/// Where the steer moves inside the initial window, s: None where its
/// normalised (filtered) values `d` stay within `onset` of the window's
/// mean. Judged against the window's mean; where it moves, against its
/// first value: a step inside the window pulls the mean, so the first
/// sample already stands 5 % off it and "moves at 0.00 s" said nothing of
/// where the step is. Where is read on the `raw` steer (its noise
/// `raw_noise`, a share of `step`): the zero-phase low-pass spreads a step
/// ahead of itself, and a step at 2.00 s read "moves at 1.96 s" once a
/// noise-free steer's threshold was 5 % (session 111).
fn moved_in_window(
    t: &[f64],
    (raw, d): (&[f64], &[f64]),
    onset: f64,
    raw_noise: f64,
    step: f64,
) -> Option<f64> {
    d.iter().any(|v| v.abs() > onset).then(|| {
        let raw_onset = ONSET.max(NOISE_DEVIATIONS * raw_noise);
        let i = (0..d.len())
            .find(|&i| ((raw[i] - raw[0]) / step).abs() > raw_onset)
            .or_else(|| (0..d.len()).find(|&i| (d[i] - d[0]).abs() > onset))
            .unwrap_or(0);
        t[i]
    })
}

/// The longest 10–90 % rise of the steer taken as a step, s: five times
/// GB/T 6323's 0.2 s, room for a hand-driven step, none for a ramp.
pub(crate) const MAX_RISE: f64 = 1.0;

/// Checks the steer of a record whose metrics `m` were measured with
/// `s`: its normalised steer (filtered as the metrics were) must stay
/// within 5 % of its step over the initial window, and once at 90 % within
/// [`HELD_STEP`] to the end.
pub(crate) fn check_step_shape(
    t: &[f64],
    steer: &[f64],
    m: &StepMetrics,
    s: &MetricSettings,
) -> Result<(), MetricsError> {
    // The steer sensor's white noise left after the filter, as a share of
    // the step: a move within four of its deviations is noise, not the
    // step (a noise of 7.5 % of the step read as "the record starts too
    // close to the step").
    let raw_noise = noise_deviation(steer) / m.steer_step.abs();
    let end = window_end(t, steer, s);
    let raw = steer;
    let (steer, noise) = match m.filter_hz {
        Some(f) => {
            let dt = crate::measured::clean::median_interval(t);
            (
                zero_phase_low_pass(steer, dt, f),
                raw_noise * noise_gain(dt, f),
            )
        }
        None => (steer.to_vec(), raw_noise),
    };
    let onset = ONSET.max(NOISE_DEVIATIONS * noise);
    let (from, to) = (t[0], end);
    let (d0, _) = window_mean(t, &steer, from, to);
    let d: Vec<f64> = steer.iter().map(|x| (x - d0) / m.steer_step).collect();
    let initial = t.partition_point(|x| *x <= to);
    let moved = moved_in_window(t, (raw, &d[..initial]), onset, raw_noise, m.steer_step);
    let (lo, hi) = HELD_STEP;
    let not_held = first_crossing(t, &d, 0.9, from).and_then(|reached| {
        (0..t.len())
            .find(|&i| t[i] > reached && !(lo..=hi).contains(&d[i]))
            .map(|i| (reached, t[i], d[i]))
    });
    match (moved, not_held) {
        // Neither held before nor after: no step at all (a log of driving).
        (Some(moved), Some((_, time, _))) => Err(MetricsError::NeverHeld { moved, time }),
        // Moved within a tenth of a second of the first sample: no
        // straight running to shorten the window to (it advised a "0.01 s"
        // initial window for a record cut at its step).
        (Some(moved), None) if moved - from < MIN_STRAIGHT => Err(MetricsError::StartsInStep {
            moved,
            from,
            pre_window: s.pre_window,
        }),
        (Some(moved), None) => Err(MetricsError::StepInInitialWindow { moved, from, to }),
        // A steady window reaching back over the step reads a wrong step,
        // and the steer "leaves" it: the record is short, not the steer.
        (None, Some((reached, time, share))) => Err(short_for_steady_window(
            t, &steer, d0, onset, s,
        )
        .unwrap_or(MetricsError::SteerNotHeld {
            reached,
            time,
            share,
        })),
        (None, None) => {
            let t90 = first_crossing(t, &d, 0.9, from);
            let t10 = t90.and_then(|b| last_crossing(t, &d, 0.1, 1.0, b));
            match (t10, t90) {
                (Some(a), Some(b)) if b - a > MAX_RISE => Err(MetricsError::SteerRamp {
                    rise: b - a,
                    from: a,
                    limit: MAX_RISE,
                }),
                _ => check_steady_window(t, &steer, d0, onset, s),
            }
        }
    }
}

/// Where the steer settles at its step, with `d0` its initial value and
/// `onset` the band as a share of the step: the index where it first
/// comes within the band of its held value (the median of the steer once
/// it has crossed half of its change to the record's end: the steady
/// window's mean is pulled by the step itself) and the time from which it
/// stays within it (none: not before the record's end). None where the
/// steer never crosses half of its change.
fn settling_of_steer(
    t: &[f64],
    steer: &[f64],
    d0: f64,
    onset: f64,
) -> Option<(usize, Option<f64>)> {
    let end = steer[steer.len() - 1];
    let half = d0 + 0.5 * (end - d0);
    let sign = (end - d0).signum();
    let reached = steer.iter().position(|x| sign * (x - half) >= 0.0)?;
    let mut after = steer[reached..].to_vec();
    after.sort_by(f64::total_cmp);
    let held = after[after.len() / 2];
    let band = onset * (held - d0).abs();
    let first_in = (reached..t.len())
        .find(|&i| (steer[i] - held).abs() <= band)
        .unwrap_or(t.len() - 1);
    let last_off = (reached..t.len())
        .rev()
        .find(|&i| (steer[i] - held).abs() > band);
    let settles = match last_off {
        None => Some(t[reached]),
        Some(i) => t.get(i + 1).copied(),
    };
    Some((first_in, settles))
}

/// A record too short for its steady window (the record's last
/// `steady_window` seconds start before the steer first reaches its held
/// value: the window holds the step itself), else None. Such a window
/// reads a step of the windows' means that the steer then seems to leave
/// ("165 % of it"): said as the record's length, not blamed on the steer.
fn short_for_steady_window(
    t: &[f64],
    steer: &[f64],
    d0: f64,
    onset: f64,
    s: &MetricSettings,
) -> Option<MetricsError> {
    let (from, to) = (t[t.len() - 1] - s.steady_window, t[t.len() - 1]);
    let (first_in, settles) = settling_of_steer(t, steer, d0, onset)?;
    (t[first_in] > from).then(|| MetricsError::ShortForSteadyWindow {
        advice: crate::error::SteadyAdvice::SteerOnly,
        settles: settles.unwrap_or(to),
        from,
        to,
    })
}

/// The initial window's test mirrored: the steer (filtered as the metrics
/// were) must stay within 5 % of its step of its held value over the
/// steady window, else the steady means mix the step in (a window that
/// reaches back over it reads a smaller step and hides the overshoot; a
/// window that starts before the steer reaches its step is a record too
/// short for it: [`short_for_steady_window`]).
fn check_steady_window(
    t: &[f64],
    steer: &[f64],
    d0: f64,
    onset: f64,
    s: &MetricSettings,
) -> Result<(), MetricsError> {
    if let Some(short) = short_for_steady_window(t, steer, d0, onset, s) {
        return Err(short);
    }
    let (from, to) = (t[t.len() - 1] - s.steady_window, t[t.len() - 1]);
    let Some((_, settles)) = settling_of_steer(t, steer, d0, onset) else {
        return Ok(());
    };
    let first_off = (0..t.len()).find(|&i| t[i] >= from && settles.is_none_or(|x| t[i] < x));
    match first_off {
        None => Ok(()),
        Some(_) => Err(MetricsError::StepInSteadyWindow { settles, from, to }),
    }
}

/// The least swing of the steer, as a share of its span, that counts as a
/// reversal: a driver's wobble on a held step is far less, a step and its
/// return swing by all of it.
const REVERSAL_SHARE: f64 = 0.25;

/// The least swing counted as a reversal, in the steer sensor's white-noise
/// deviations: neighbours of such noise differ by 8σ (5.7 deviations of
/// their difference) about once in 10⁸ samples.
const REVERSAL_NOISE: f64 = 8.0;

/// The band of a held steer, as a share of its span (the evidence's
/// longest steady stretch).
const HELD_SHARE: f64 = 0.1;

/// The most reversals a step-steer record makes: one, a step and its
/// return (`metrics` measures the first of several held steps itself).
const MAX_REVERSALS: usize = 1;

/// Refuses a record whose steer reverses more than [`MAX_REVERSALS`]
/// times by more than a quarter of its span (or [`REVERSAL_NOISE`] of
/// its noise): no step steer (a log of driving, a sine, a sweep), said with
/// its span, reversals and longest steady stretch instead of a "step"
/// that the windows' means made up (a racing log's was "377 % of it").
pub(crate) fn check_steer_is_a_step(t: &[f64], steer: &[f64]) -> Result<(), MetricsError> {
    let (lo, hi) = steer
        .iter()
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let span = hi - lo;
    if span.is_nan() || span <= 0.0 || t.len() != steer.len() {
        return Ok(());
    }
    let noise = noise_deviation(steer);
    let swing = (REVERSAL_SHARE * span).max(REVERSAL_NOISE * noise);
    let reversals = reversals(steer, swing);
    if reversals <= MAX_REVERSALS {
        return Ok(());
    }
    let band = (HELD_SHARE * span).max(NOISE_DEVIATIONS * noise);
    let (longest, longest_from) = longest_held(t, steer, band);
    Err(MetricsError::NoStepSteer {
        lo,
        hi,
        reversals,
        swing,
        longest,
        longest_from,
        band,
    })
}

/// How many times `x` turns back by more than `swing` from its last
/// extreme (a hysteresis: noise smaller than `swing` turns nothing).
fn reversals(x: &[f64], swing: f64) -> usize {
    let mut x = x.iter().copied().filter(|v| v.is_finite());
    let Some(first) = x.next() else {
        return 0;
    };
    // The direction (0 until the first swing), the extreme since the last
    // turn, and the range before the first swing.
    let (mut dir, mut extreme, mut lo, mut hi, mut n) = (0.0, first, first, first, 0);
    for v in x {
        if dir == 0.0 {
            (lo, hi) = (lo.min(v), hi.max(v));
            if v - lo > swing || hi - v > swing {
                (dir, extreme) = (if v - lo > swing { 1.0 } else { -1.0 }, v);
            }
        } else if dir * (v - extreme) > 0.0 {
            extreme = v;
        } else if dir * (extreme - v) > swing {
            (dir, extreme, n) = (-dir, v, n + 1);
        }
    }
    n
}

/// The longest stretch over which `x` stays within a band `band` wide:
/// its length and start, s (two pointers, the window's extremes kept in
/// monotonic queues).
fn longest_held(t: &[f64], x: &[f64], band: f64) -> (f64, f64) {
    use std::collections::VecDeque;
    let (mut lows, mut highs) = (VecDeque::<usize>::new(), VecDeque::<usize>::new());
    let (mut left, mut best) = (0, (0.0, t.first().copied().unwrap_or(0.0)));
    for right in 0..x.len() {
        while lows.back().is_some_and(|&i| x[i] >= x[right]) {
            lows.pop_back();
        }
        lows.push_back(right);
        while highs.back().is_some_and(|&i| x[i] <= x[right]) {
            highs.pop_back();
        }
        highs.push_back(right);
        while x[highs[0]] - x[lows[0]] > band {
            left += 1;
            while lows[0] < left {
                lows.pop_front();
            }
            while highs[0] < left {
                highs.pop_front();
            }
        }
        if t[right] - t[left] > best.0 {
            best = (t[right] - t[left], t[left]);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A step and its return turn once; a sine of five periods ten times;
    /// noise below the swing, never.
    #[test]
    fn reversals_are_counted_past_the_swing_only() {
        let t: Vec<f64> = (0..1000).map(|i| 0.01 * f64::from(i)).collect();
        let step_back: Vec<f64> = t
            .iter()
            .map(|&t| f64::from(u8::from((2.0..6.0).contains(&t))))
            .collect();
        assert_eq!(reversals(&step_back, 0.25), 1);
        let sine: Vec<f64> = t
            .iter()
            .map(|t| (std::f64::consts::TAU * 0.5 * t).sin())
            .collect();
        assert_eq!(reversals(&sine, 0.5), 10);
        let wobble: Vec<f64> = t
            .iter()
            .enumerate()
            .map(|(i, _)| 0.1 * f64::from(i as u8 % 2))
            .collect();
        assert_eq!(reversals(&wobble, 0.25), 0);
        assert!(check_steer_is_a_step(&t, &step_back).is_ok());
        let Err(MetricsError::NoStepSteer {
            reversals, longest, ..
        }) = check_steer_is_a_step(&t, &sine)
        else {
            panic!("a sine is no step steer");
        };
        assert_eq!(reversals, 10);
        // Within a tenth of its span of 2 about a crest: 2·acos(0.8)/π s.
        assert!((longest - 0.41).abs() < 0.02, "{longest}");
    }
}
