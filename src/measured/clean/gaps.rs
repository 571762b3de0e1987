//! Time gaps of a measured run: where the logger stopped recording, so that
//! a replay must not bridge the interval. A logger's rate may change within
//! a run (`FORMATS.md`: "sampled at a constant or varying rate": 200 Hz
//! while a test runs, 20 Hz between tests), so an interval is judged
//! against the sampling on both sides of it, not against the run's median:
//! it is a gap when it is longer than [`GAP_INTERVALS`] times the median of
//! the [`NEIGHBOURS`] intervals before it and longer than that many times
//! the median of the [`NEIGHBOURS`] after it (one side at a run's end). A
//! change of rate is then no gap on either side of it, and a dropout is one
//! whatever the rate around it. The comparison carries a relative margin of
//! [`ROUNDING`]: a 20 Hz stretch after 100 Hz, its intervals written in
//! decimal, sits at exactly five intervals, which rounding must not decide.
//! Times in s.

use super::{median, GAP_INTERVALS};

/// Intervals on each side of an interval that give the sampling it is
/// judged against.
pub(crate) const NEIGHBOURS: usize = 10;

/// Relative margin of the comparison: times written in decimal differ from
/// their exact multiples by a few units in the last place.
const ROUNDING: f64 = 1e-6;

/// The indices `i` (from 1) whose interval `t[i] − t[i−1]` is a time gap.
pub(crate) fn gap_starts(t: &[f64]) -> Vec<usize> {
    let dt: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    let mut buf = Vec::with_capacity(NEIGHBOURS);
    let mut typical = |range: std::ops::Range<usize>| -> Option<f64> {
        if range.is_empty() {
            return None;
        }
        buf.clear();
        buf.extend_from_slice(&dt[range]);
        Some(median(&mut buf))
    };
    let mut out = Vec::new();
    for (k, &d) in dt.iter().enumerate() {
        let before = typical(k.saturating_sub(NEIGHBOURS)..k);
        let after = typical(k + 1..(k + 1 + NEIGHBOURS).min(dt.len()));
        let longer = |s: Option<f64>| s.is_none_or(|s| d > GAP_INTERVALS * s * (1.0 + ROUNDING));
        if (before.is_some() || after.is_some()) && longer(before) && longer(after) {
            out.push(k + 1);
        }
    }
    out
}

/// The index ranges `[lo, hi)` of a run between its time gaps.
pub(crate) fn gapless(t: &[f64]) -> Vec<(usize, usize)> {
    let mut bounds = vec![0];
    bounds.extend(gap_starts(t));
    bounds.push(t.len());
    bounds.windows(2).map(|w| (w[0], w[1])).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn times(stretches: &[(f64, usize)]) -> Vec<f64> {
        let mut t = vec![0.0];
        for &(dt, n) in stretches {
            for _ in 0..n {
                let last = *t.last().unwrap();
                // Written in decimal as a logger writes them.
                t.push(format!("{:.6}", last + dt).parse().unwrap());
            }
        }
        t
    }

    #[test]
    fn a_change_of_rate_is_no_gap() {
        // 200 Hz for 3 s, then 20 Hz for 5 s; and 100 Hz then 20 Hz, whose
        // intervals are exactly five of the first stretch's.
        assert!(gap_starts(&times(&[(0.005, 600), (0.05, 100)])).is_empty());
        assert!(gap_starts(&times(&[(0.01, 300), (0.05, 100)])).is_empty());
        // And back up: 20 Hz, then 200 Hz.
        assert!(gap_starts(&times(&[(0.05, 100), (0.005, 600)])).is_empty());
    }

    #[test]
    fn a_dropout_is_a_gap_whatever_the_rate_around_it() {
        let t = times(&[(0.01, 300), (0.5, 1), (0.01, 300)]);
        assert_eq!(gap_starts(&t), vec![301]);
        // At a change of rate: 0.5 s is more than five 20 Hz intervals.
        let t = times(&[(0.005, 600), (0.5, 1), (0.05, 100)]);
        assert_eq!(gap_starts(&t), vec![601]);
        // A dropout inside a fast stretch of a mostly slow log.
        let t = times(&[(0.05, 100), (0.005, 200), (0.04, 1), (0.005, 200)]);
        assert_eq!(gap_starts(&t), vec![301]);
        // At the run's last interval, judged by the side it has.
        let t = times(&[(0.01, 300), (0.2, 1)]);
        assert_eq!(gap_starts(&t), vec![301]);
    }

    #[test]
    fn five_intervals_exactly_is_no_gap_and_a_hair_more_is() {
        // Four missing samples of a 100 Hz log: the interval is five of its
        // neighbours', not longer, whatever the decimal rounding.
        let t = times(&[(0.01, 100), (0.05, 1), (0.01, 100)]);
        assert!(gap_starts(&t).is_empty());
        let t = times(&[(0.01, 100), (0.051, 1), (0.01, 100)]);
        assert_eq!(gap_starts(&t), vec![101]);
    }

    #[test]
    fn the_pieces_between_gaps_cover_the_run() {
        let t = times(&[(0.01, 50), (1.0, 1), (0.01, 50)]);
        assert_eq!(gapless(&t), vec![(0, 51), (51, 102)]);
        assert_eq!(gapless(&[0.0]), vec![(0, 1)]);
    }
}
