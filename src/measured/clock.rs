//! A measured run's clock, as its reader takes it (`FORMATS.md`: `t` in s,
//! strictly increasing).
//!
//! - A wall clock (Unix-epoch seconds, 1.7e9 s; GPS time; a counter of
//!   days) is rebased to the run's first sample when read ([`rebase`]):
//!   an f64 holds 1.7e9 s to 0.24 µs only, every interval and every
//!   interpolation of such times carries that rounding, and the tolerances
//!   downstream are in absolute seconds (a residual's sampling at 1e-9 s:
//!   a diagnosis of a sensor delay found 0.0496 s on a log's own clock and
//!   nothing on the same log at 1.7e9 s). The rebased times are rounded to
//!   the finest decimal the parsed clock resolves (1e-6 s at 1.7e9 s), so
//!   that a log written to that many decimals is read as the same times,
//!   to the bit, whatever its origin. A clock below [`WALL_CLOCK`] keeps
//!   its times (to 1.5e-11 s): they are those of the file, which a user
//!   reads beside the output.
//! - A clock that falls back mid-file is told apart ([`fall_of`]): a
//!   counter's wrap (the fall is a counter's period less one step, or the
//!   clock resumes its step with every channel running on across the
//!   fall) from a new recording in the same file (the channels jump).

use crate::error::{ClockFall, Counter};
use crate::measured::MeasuredRun;
use serde::Serialize;

/// A run file whose wall clock was rebased to its first sample, as the
/// cleaning reports it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RebasedClock {
    /// The run's file.
    pub run: String,
    /// The log's clock at the run's first sample, s.
    pub origin: f64,
}

impl RebasedClock {
    /// Lists the clock of the run file `file` in `clocks` where its reader
    /// rebased it to `origin` (once per file: its pieces and segments
    /// share it).
    pub(crate) fn note(clocks: &mut Vec<RebasedClock>, file: String, origin: Option<f64>) {
        let Some(origin) = origin else {
            return;
        };
        if !clocks.iter().any(|c| c.run == file) {
            clocks.push(RebasedClock { run: file, origin });
        }
    }

    /// The cleaning's line of the runs `clocks` lists, if any: one for
    /// them all (a campaign of eight files logged on one wall clock).
    pub fn line(clocks: &[RebasedClock]) -> Option<String> {
        let each: Vec<String> = clocks
            .iter()
            .map(|c| format!("{} from {} s", c.run, crate::format::fixed(c.origin, 3)))
            .collect();
        (!each.is_empty()).then(|| {
            format!(
                "clock: {} on a wall clock, its time rebased to 0 at its first sample when read, so that the clock's origin does not matter (the times said are from that sample): {}",
                crate::format::plural(each.len(), "run", "runs"),
                each.join(", ")
            )
        })
    }
}

/// A run's first time from which its clock is a wall clock's and is
/// rebased, s (27.8 h: beyond any time of day, where no logger's own clock
/// of a test day starts).
pub const WALL_CLOCK: f64 = 1e5;

/// `t` rebased to its first sample where its clock reads a wall clock
/// ([`WALL_CLOCK`] or more), with the clock's reading at that sample, s;
/// `None` (and `t` as read) otherwise.
pub fn rebase(t: &mut [f64]) -> Option<f64> {
    let t0 = *t.first()?;
    if !(t0.abs() >= WALL_CLOCK && t0.is_finite()) {
        return None;
    }
    let largest = t.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    let scale = decimal_scale(largest);
    for x in t.iter_mut() {
        // Both times within a factor 2 of each other: the difference is
        // exact, and off the file's decimals by their parsing alone (at
        // most one unit in the last place of the clock), a quarter of the
        // decimal step it is rounded to. An integer over a power of ten
        // is the double nearest that decimal, as a parse of it gives.
        *x = ((*x - t0) * scale).round() / scale;
    }
    Some(t0)
}

/// `run` back on its log's own clock where its reader rebased it: a
/// replay (`simulate`) steps a run from its start itself and writes its
/// history in the log's own time, to be laid beside the log. The rebased
/// times plus the origin are the doubles the file's decimals give.
pub fn on_logs_clock(run: &mut MeasuredRun) {
    if let Some(origin) = run.clock.take() {
        for t in &mut run.t {
            *t += origin;
        }
    }
}

/// 10^k for the finest decimal step at least four units in the last
/// place of `largest` (1e6 at 1.7e9 s, whose unit is 2.4e-7 s).
fn decimal_scale(largest: f64) -> f64 {
    let ulp = 2f64.powf(largest.log2().floor() - 52.0);
    let k = (-(4.0 * ulp).log10()).floor();
    10f64.powi(k as i32)
}

/// A channel's jump at the fall beyond this many of its largest change
/// between neighbouring samples on each side is a new recording's.
const JUMP: f64 = 10.0;

/// Samples on each side of the fall whose changes show a channel's run.
const SIDE: usize = 5;

/// How the time `t[i]` fails to follow `t[i - 1]`, `channels` the run's
/// other columns (speed, steer, yaw rate) that tell a wrap from a new
/// recording: a repeat, a counter's wrap, a fall with the same step after
/// it and the channels running on (a wrap of a period of its own), else
/// a new recording.
pub fn fall_of(t: &[f64], i: usize, channels: &[&[f64]]) -> ClockFall {
    let (value, previous) = (t[i], t[i - 1]);
    if value == previous {
        return ClockFall::Repeated;
    }
    let Some(step) = (i >= 2).then(|| t[i - 1] - t[i - 2]).filter(|s| *s > 0.0) else {
        return ClockFall::Restart;
    };
    let period = previous + step - value;
    if let Some(counter) = Counter::ALL
        .into_iter()
        .find(|c| (c.period() - period).abs() <= 0.5 * step)
    {
        return ClockFall::Counter { counter, step };
    }
    let after = t.get(i + 1).map(|n| n - value);
    let same_step = after.is_some_and(|a| (a - step).abs() <= 0.25 * step);
    if same_step && channels.iter().all(|c| runs_on(c, i)) {
        ClockFall::SameStep { period, step }
    } else {
        ClockFall::Restart
    }
}

/// Whether channel `x` runs on across row `i` (no jump there beyond
/// [`JUMP`] times its largest change between neighbours on either side).
fn runs_on(x: &[f64], i: usize) -> bool {
    let lo = i.saturating_sub(SIDE + 1);
    let hi = (i + SIDE + 1).min(x.len());
    let largest = (lo + 1..hi)
        .filter(|&k| k != i)
        .map(|k| (x[k] - x[k - 1]).abs())
        .fold(0.0_f64, f64::max);
    (x[i] - x[i - 1]).abs() <= JUMP * largest
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_epoch_clock_is_rebased_to_the_times_its_decimals_give() {
        // The times a log's own clock writes, and the same log at
        // 1701234567 s: rebased, the same doubles to the bit.
        let own: Vec<f64> = (0..2000)
            .map(|i| format!("{}.{:02}", i / 100, i % 100))
            .map(|s| s.parse().unwrap())
            .collect();
        let mut epoch: Vec<f64> = (0..2000)
            .map(|i| format!("{}.{:02}", 1701234567 + i / 100, i % 100))
            .map(|s| s.parse().unwrap())
            .collect();
        let parsed = epoch.clone();
        assert_eq!(rebase(&mut epoch), Some(1701234567.0));
        assert_eq!(epoch, own);
        // Set back on the log's clock (a replay's), the times as parsed.
        let n = epoch.len();
        let mut run = MeasuredRun::new("r.csv", epoch, vec![20.0; n], vec![0.0; n], vec![0.0; n]);
        run.clock = Some(1701234567.0);
        on_logs_clock(&mut run);
        assert_eq!((run.t, run.clock), (parsed, None));
        // A log's own clock is kept as read.
        let mut kept = own.clone();
        assert_eq!(rebase(&mut kept), None);
        assert_eq!(kept, own);
    }

    #[test]
    fn a_wrap_is_told_from_a_new_recording() {
        let ramp: Vec<f64> = (0..40).map(|i| f64::from(i) * 0.1).collect();
        // A 16-bit millisecond counter: 65.526 s, then 0.000 s.
        let t: Vec<f64> = (0..20)
            .map(|i| 65.436 + f64::from(i) * 0.01)
            .map(|x| if x >= 65.536 - 1e-9 { x - 65.536 } else { x })
            .collect();
        let i = t.windows(2).position(|w| w[1] < w[0]).unwrap() + 1;
        assert!(
            matches!(
                fall_of(&t, i, &[&ramp[..20]]),
                ClockFall::Counter {
                    counter: Counter::Millis16,
                    ..
                }
            ),
            "{:?}",
            fall_of(&t, i, &[])
        );
        // A period of its own (5 s), the channels running on: a wrap.
        let t: Vec<f64> = (0..40).map(|i| (f64::from(i) * 0.25) % 5.0).collect();
        let fall = fall_of(&t, 20, &[&ramp]);
        assert!(
            matches!(fall, ClockFall::SameStep { period, .. } if (period - 5.0).abs() < 1e-9),
            "{fall:?}"
        );
        // The same clock, a channel jumping at the fall: a new recording.
        let mut jump = ramp.clone();
        for x in &mut jump[20..] {
            *x += 100.0;
        }
        assert_eq!(fall_of(&t, 20, &[&jump]), ClockFall::Restart);
        // The same rows again: a steady channel that steps back.
        let twice: Vec<f64> = ramp[..20].iter().chain(&ramp[..20]).copied().collect();
        assert_eq!(fall_of(&t, 20, &[&twice]), ClockFall::Restart);
        let repeated = [0.0, 0.1, 0.1];
        assert_eq!(fall_of(&repeated, 2, &[]), ClockFall::Repeated);
    }
}
