//! A measured piece whose logger changed its rate (`FORMATS.md` allows a
//! varying rate) is put on one uniform grid before its metrics: the
//! low-pass filter and the windows are designed for one sample interval,
//! and at the median interval of a log at 100 Hz, then 1000 Hz, the filter
//! ran ten times too slow over the first part (a response time of 0.261 s
//! read for 0.132 s, without a word). The grid is the piece's finest
//! local interval; each channel is interpolated linearly between samples,
//! which adds no information to the slower part and keeps the faster part's.
//! A rate is a change when the local median intervals (over
//! `holes::LOCAL` intervals each side) differ by more than a factor [`CHANGE`]:
//! a logger's jitter, even ±3 ms at 100 Hz, moves them by less.
//!
//! A hole in time shorter than a time gap (which splits the run: five
//! intervals) is put on the grid too: an interval of at least
//! `holes::HOLE` local intervals, within a quarter of a whole number of them (a
//! logger's jitter of ±3 ms at 100 Hz reaches 1.6 intervals, between
//! whole numbers). Read as it is, the filter took the hole for one sample
//! step and moved the response around it: 4 samples missing during the
//! rise read an ay response time of 0.3618 s for the intact log's 0.3448 s.
//! The missing samples are counted and said. Times in s.

use crate::measured::clean::holes::{holes, local_intervals, pattern};
use crate::measured::clean::median;
use crate::measured::MeasuredRun;

/// Ratio of the longest to the shortest local interval above which the
/// rate is said to change.
const CHANGE: f64 = 2.0;

/// The warning of the holes of the measured piece of times `t`, none
/// without; `log` the cleaning's count for the whole log (samples, holes),
/// whose excess over the piece's lies in parts not measured and is said,
/// so that two counts of one file are not read as one contradicting the
/// other (30 samples in 29 holes and 29 in 28, one hole in a piece
/// dropped).
fn holes_said(t: &[f64], dt: f64, log: Option<(usize, usize)>) -> Option<String> {
    let h = holes(t);
    let longest = h.iter().max_by(|a, b| a.1.total_cmp(&b.1))?;
    let missing: usize = h.iter().map(|x| x.2).sum();
    let plural = crate::format::plural;
    let outside = match log {
        Some((samples, count)) if samples > missing && count > h.len() => format!(
            "; the cleaning's count, {} in {}, is the whole log's, {} of them in {} outside this piece (in parts of the log not measured)",
            plural(samples, "sample", "samples"),
            plural(count, "hole", "holes"),
            samples - missing,
            plural(count - h.len(), "hole", "holes"),
        ),
        _ => String::new(),
    };
    Some(format!(
        "in the measured piece the log misses {} in {} in time{} (the longest {} s after t = {} s), too short to split the run: its samples are interpolated linearly across them onto one {} Hz grid for the filter, the windows and the metrics{outside}",
        plural(missing, "sample", "samples"),
        plural(h.len(), "hole", "holes"),
        pattern(&h, dt).map_or(String::new(), |(m, every)| format!(
            ", {m} of every {every} rows throughout (rows dropped in a regular pattern, by a logger or an export)"
        )),
        crate::format::readable(longest.1, 3),
        crate::format::readable(longest.0, 3),
        crate::format::readable(1.0 / dt, 3)
    ))
}

/// The shortest and longest local intervals of `t`, where they differ by
/// more than [`CHANGE`].
fn rate_change(t: &[f64]) -> Option<(f64, f64)> {
    let (lo, hi) = local_intervals(t)
        .into_iter()
        .fold((f64::INFINITY, 0.0_f64), |(lo, hi), m| {
            (lo.min(m), hi.max(m))
        });
    (lo > 0.0 && hi > CHANGE * lo).then_some((lo, hi))
}

/// What [`uniform`] did to a piece of times `t`, said: nothing where its
/// rate does not change.
pub(super) fn said(t: &[f64]) -> Option<String> {
    let (lo, hi) = rate_change(t)?;
    Some(format!(
        "the log's rate changes within the piece (from {:.0} Hz to {:.0} Hz): its samples are interpolated linearly onto one {:.0} Hz grid for the filter, the windows and the metrics",
        1.0 / hi,
        1.0 / lo,
        1.0 / lo
    ))
}

/// `p` on a uniform grid at its shortest local interval, where its rate
/// changes, or at its median interval, where it has holes (and the
/// warning of them, `log` the whole log's count as [`holes_said`] takes
/// it); else `p` itself.
pub(super) fn uniform(
    p: MeasuredRun,
    log: Option<(usize, usize)>,
) -> (MeasuredRun, Option<String>) {
    if p.t.len() < 3 {
        return (p, None);
    }
    let (dt, holes) = match rate_change(&p.t) {
        Some((dt, _)) => (dt, None),
        None => {
            // The holes' own interval: where every third row is missing
            // the run's median interval is the hole's 0.02 s, not 0.01 s.
            let dt = median(&mut local_intervals(&p.t));
            match holes_said(&p.t, dt, log) {
                Some(w) => (dt, Some(w)),
                None => return (p, None),
            }
        }
    };
    (on_grid(&p, dt), holes)
}

/// `p` interpolated linearly onto the grid of `dt` from its first sample.
fn on_grid(p: &MeasuredRun, dt: f64) -> MeasuredRun {
    let (t0, t1) = (p.t[0], p.t[p.t.len() - 1]);
    let n = ((t1 - t0) / dt + 1e-6).floor() as usize;
    let grid: Vec<f64> = (0..=n).map(|i| t0 + i as f64 * dt).collect();
    let at = |x: &[f64]| -> Vec<f64> {
        grid.iter()
            .map(|&t| {
                let j = p.t.partition_point(|&s| s <= t).clamp(1, p.t.len() - 1);
                let (ta, tb) = (p.t[j - 1], p.t[j]);
                let w = ((t - ta) / (tb - ta)).clamp(0.0, 1.0);
                x[j - 1] + w * (x[j] - x[j - 1])
            })
            .collect()
    };
    let opt = |x: &Option<Vec<f64>>| x.as_deref().map(at);
    MeasuredRun {
        path: p.path.clone(),
        speed: at(&p.speed),
        steer: at(&p.steer),
        yaw_rate: at(&p.yaw_rate),
        ay: opt(&p.ay),
        beta: opt(&p.beta),
        roll: opt(&p.roll),
        bank: opt(&p.bank),
        ax: opt(&p.ax),
        // The masked samples were filled before.
        masked: Vec::new(),
        clock: p.clock,
        t: grid,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rate_that_changes_is_found_and_jitter_is_not() {
        let mut t: Vec<f64> = (0..200).map(|i| f64::from(i) * 0.01).collect();
        t.extend((1..=1000).map(|i| 1.99 + f64::from(i) * 0.001));
        let (lo, hi) = rate_change(&t).unwrap();
        assert!(
            (lo - 0.001).abs() < 1e-9 && (hi - 0.01).abs() < 1e-9,
            "{lo} {hi}"
        );
        // ±3 ms of jitter on a 100 Hz log: no change.
        let jittered: Vec<f64> = (0..500)
            .map(|i| f64::from(i) * 0.01 + 0.003 * (f64::from(i) * 2.39).sin())
            .collect();
        assert_eq!(rate_change(&jittered), None);
    }

    #[test]
    fn every_third_row_missing_is_no_rate_change_and_each_is_counted() {
        // 100 Hz for 8 s, rows 1, 4, 7, … dropped: 266 missing.
        let t: Vec<f64> = (0..801)
            .filter(|i| i % 3 != 1)
            .map(|i| f64::from(i) / 100.0)
            .collect();
        assert_eq!(rate_change(&t), None);
        let h = holes(&t);
        assert_eq!(h.iter().map(|x| x.2).sum::<usize>(), 267);
        assert_eq!(pattern(&h, 0.01), Some((1, 3)));
        let said = holes_said(&t, 0.01, None).unwrap();
        assert!(
            said.contains("267 samples in 267 holes in time, 1 of every 3 rows"),
            "{said}"
        );
        // A single hole is no pattern.
        assert_eq!(pattern(&h[..1], 0.01), None);
    }

    #[test]
    fn the_logs_count_beside_the_pieces_says_how_many_lie_outside_it() {
        // 100 Hz for 4 s, rows at 1 s and 2 s missing: 2 in 2 holes.
        let t: Vec<f64> = (0..401)
            .filter(|i| *i != 100 && *i != 200)
            .map(|i| f64::from(i) / 100.0)
            .collect();
        let said = holes_said(&t, 0.01, Some((3, 3))).unwrap();
        assert!(
            said.starts_with("in the measured piece the log misses 2 samples in 2 holes"),
            "{said}"
        );
        assert!(
            said.ends_with("; the cleaning's count, 3 samples in 3 holes, is the whole log's, 1 of them in 1 hole outside this piece (in parts of the log not measured)"),
            "{said}"
        );
        // The same count as the cleaning's: one count, said once.
        let same = holes_said(&t, 0.01, Some((2, 2))).unwrap();
        assert!(!same.contains("the cleaning's count"), "{same}");
    }

    #[test]
    fn a_line_is_resampled_onto_the_finest_grid_exactly() {
        let mut t: Vec<f64> = (0..100).map(|i| f64::from(i) * 0.05).collect();
        t.extend((1..=500).map(|i| 4.95 + f64::from(i) * 0.005));
        let line: Vec<f64> = t.iter().map(|t| 2.0 * t + 1.0).collect();
        let speed = vec![20.0; t.len()];
        let run = MeasuredRun::new("x.csv", t.clone(), speed, line.clone(), line.clone());
        let u = uniform(run, None).0;
        assert_eq!(u.t.len(), 1491);
        for (t, r) in u.t.iter().zip(&u.yaw_rate) {
            assert!((r - (2.0 * t + 1.0)).abs() < 1e-9, "{t} {r}");
        }
        assert!(u.t.windows(2).all(|w| ((w[1] - w[0]) - 0.005).abs() < 1e-9));
    }
}
