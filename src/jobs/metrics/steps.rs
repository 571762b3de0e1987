//! A run that holds several steer steps (a step and its return, or a step
//! on a step): `metrics` measures the first, cut before the second, where
//! the whole run's windows read no step at all (the initial and steady
//! steer equal) or a "ramp" spanning both.

use crate::measured::MeasuredRun;

/// A steer change counts as a step where it covers this share of the
/// run's steer range within [`STEP_SPAN`]: a step back to the start, or a
/// second of two equal steps, is a half or more.
const STEP_SHARE: f64 = 0.25;
/// The time a step takes at most, s (GB/T 6323: 0.2 s).
const STEP_SPAN: f64 = 0.2;
/// A level between steps is held for at least this long, s, within
/// [`HELD_SHARE`] of the range: a sine or a sweep is never held.
const HELD_FOR: f64 = 0.5;
/// How far a held level may wander, as a share of the steer range.
const HELD_SHARE: f64 = 0.1;

/// The steps of a run that holds two or more, each steer held before and
/// after: each step's start time (s), and the index the run is cut at
/// to keep the first step alone (the second step's start). `None` for a
/// run of one step or of no held steps.
pub(super) fn several_steps(run: &MeasuredRun) -> Option<(Vec<f64>, usize)> {
    let (t, s) = (&run.t, &run.steer);
    let (lo, hi) = s
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let range = hi - lo;
    if range.is_nan() || range <= 0.0 {
        return None;
    }
    // The samples from which the steer moves by a step within STEP_SPAN,
    // grouped into one event per step: [first, last] indices.
    let mut events: Vec<(usize, usize)> = Vec::new();
    for i in 0..s.len() {
        let j = t.partition_point(|&x| x <= t[i] + STEP_SPAN).min(s.len()) - 1;
        if (s[j] - s[i]).abs() < STEP_SHARE * range {
            continue;
        }
        match events.last_mut() {
            Some((_, last)) if *last + 1 == i => *last = i,
            _ => events.push((i, i)),
        }
    }
    if events.len() < 2 {
        return None;
    }
    // Between steps, before the first and after the last, the steer is
    // held: the stretch from an event's end (plus its span) to the next's
    // start.
    let mut bounds = vec![0];
    for &(a, b) in &events {
        bounds.push(a);
        bounds.push(
            t.partition_point(|&x| x <= t[b] + STEP_SPAN)
                .min(s.len() - 1),
        );
    }
    bounds.push(s.len() - 1);
    let held = bounds.chunks(2).all(|w| {
        let (a, b) = (w[0], w[1]);
        let (l, h) = s[a..=b.max(a)]
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(x, y), &v| {
                (x.min(v), y.max(v))
            });
        b > a && t[b] - t[a] >= HELD_FOR && h - l <= HELD_SHARE * range
    });
    // Each step said at the sample where the steer has made half its
    // change, not where the look-ahead first saw it coming.
    let at = |&(a, b): &(usize, usize)| {
        let end = t
            .partition_point(|&x| x <= t[b] + STEP_SPAN)
            .min(s.len() - 1);
        let half = 0.5 * (s[end] - s[a]).abs();
        (a..=end)
            .find(|&i| (s[i] - s[a]).abs() >= half)
            .map_or(t[a], |i| t[i])
    };
    held.then(|| (events.iter().map(at).collect(), events[1].0))
}
