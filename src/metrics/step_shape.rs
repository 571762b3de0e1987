//! Whether a measured record is a step steer the metrics can read
//! ([`check_step_shape`]): the steer held at its initial value over the
//! initial window (else the initial values mix the step in: a record
//! that starts just before the step), held at its step once it has
//! reached 90 % of it (else it is a sweep or a sine, whose "step" is the
//! difference of two windows' means), and risen within [`MAX_RISE`] (else
//! it is a ramp, whose response times are those of a car following its
//! input, about zero).

use super::{first_crossing, noise_deviation, noise_gain, window_mean, zero_phase_low_pass};
use super::{MetricSettings, StepMetrics};
use crate::error::{MetricsError, HELD_STEP};

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
    let (from, to) = (t[0], t[0] + s.pre_window);
    let (d0, _) = window_mean(t, &steer, from, to);
    let d: Vec<f64> = steer.iter().map(|x| (x - d0) / m.steer_step).collect();
    let initial = t.partition_point(|x| *x <= to);
    // Whether the steer moves inside the initial window is judged against
    // the window's mean; where it moves, against its first value: a step
    // inside the window pulls the mean, so the first sample already stands
    // 5 % off it and "moves at 0.00 s" said nothing of where the step is.
    let moved = d[..initial].iter().any(|v| v.abs() > onset).then(|| {
        let i = d[..initial]
            .iter()
            .position(|v| (v - d[0]).abs() > onset)
            .unwrap_or(0);
        t[i]
    });
    let (lo, hi) = HELD_STEP;
    let not_held = first_crossing(t, &d, 0.9, from).and_then(|reached| {
        (0..t.len())
            .find(|&i| t[i] > reached && !(lo..=hi).contains(&d[i]))
            .map(|i| (reached, t[i], d[i]))
    });
    match (moved, not_held) {
        // Neither held before nor after: no step at all (a log of driving).
        (Some(moved), Some((_, time, _))) => Err(MetricsError::NeverHeld { moved, time }),
        (Some(moved), None) => Err(MetricsError::StepInInitialWindow { moved, from, to }),
        (None, Some((reached, time, share))) => Err(MetricsError::SteerNotHeld {
            reached,
            time,
            share,
        }),
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

/// The initial window's test mirrored: the steer (filtered as the metrics
/// were) must stay within 5 % of its step of its held value over the
/// steady window, else the steady means mix the step in (a window that
/// reaches back over it reads a smaller step and hides the overshoot).
/// The held value is the median of the steer once it has crossed half of
/// its change, not the steady window's mean, which the step itself pulls.
fn check_steady_window(
    t: &[f64],
    steer: &[f64],
    d0: f64,
    onset: f64,
    s: &MetricSettings,
) -> Result<(), MetricsError> {
    let (from, to) = (t[t.len() - 1] - s.steady_window, t[t.len() - 1]);
    let end = steer[steer.len() - 1];
    let half = d0 + 0.5 * (end - d0);
    let sign = (end - d0).signum();
    let Some(reached) = steer.iter().position(|x| sign * (x - half) >= 0.0) else {
        return Ok(());
    };
    let mut after = steer[reached..].to_vec();
    after.sort_by(f64::total_cmp);
    let held = after[after.len() / 2];
    let band = onset * (held - d0).abs();
    let last_off = (reached..t.len())
        .rev()
        .find(|&i| (steer[i] - held).abs() > band);
    let first_off = (0..t.len()).find(|&i| t[i] >= from && (steer[i] - held).abs() > band);
    match first_off {
        None => Ok(()),
        Some(_) => Err(MetricsError::StepInSteadyWindow {
            settles: match last_off {
                None => Some(t[reached]),
                Some(i) => t.get(i + 1).copied(),
            },
            from,
            to,
        }),
    }
}
