//! Holes in time shorter than a time gap: rows a logger or an export
//! dropped, too few to split a run ([`super::gaps`]: more than five
//! intervals), each found against the run's local interval and counted,
//! and the regular pattern they make where there is one ("1 of every 3
//! rows throughout"). The cleaning says them (a replay runs across them,
//! scored on the rows present), and the metrics put a piece with holes on
//! one grid (`metrics::measured::uniform`).
//!
//! A local interval is the median over [`LOCAL`] intervals each side; an
//! interval of at least [`HOLE`] local intervals, within a quarter of a
//! whole number of them, is a hole (a logger's jitter of ±3 ms at 100 Hz
//! reaches 1.6 intervals, between whole numbers). Times in s.

use super::median;
use super::missing::{MissingRows, RowPattern};

/// Intervals on each side of one whose median is its local interval.
pub(crate) const LOCAL: usize = 5;

/// Local intervals from which an interval is a hole of missing samples.
pub(crate) const HOLE: f64 = 1.5;

/// The local interval of each interval of `t`: the median over [`LOCAL`]
/// intervals each side, or the median of its intervals of at most
/// [`SHORT`] of that median where they lie on both sides of it (or at it)
/// and make [`SHORT_SHARE`] of the window or more. A log that misses every third
/// row alternates 0.02 and 0.01 s: its median flipped between them, and
/// the log was said to change its rate from 50 to 100 Hz, its 267
/// missing samples uncounted; a change of rate has its short intervals on
/// one side only.
pub(crate) fn local_intervals(t: &[f64]) -> Vec<f64> {
    let dt: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    let mut buf = Vec::with_capacity(2 * LOCAL + 1);
    (0..dt.len())
        .map(|k| {
            let (lo, hi) = (k.saturating_sub(LOCAL), (k + LOCAL + 1).min(dt.len()));
            buf.clear();
            buf.extend_from_slice(&dt[lo..hi]);
            let m = median(&mut buf);
            let short = |d: &f64| *d <= SHORT * m;
            // Each side with the interval itself (a run's end has one side).
            let side = |s: &[f64]| s.len() < 2 || s.iter().any(short);
            let both = side(&dt[lo..=k]) && side(&dt[k..hi]);
            buf.clear();
            buf.extend(dt[lo..hi].iter().copied().filter(short));
            if !both || (buf.len() as f64) < SHORT_SHARE * (hi - lo) as f64 {
                return m;
            }
            // Rows dropped leave whole multiples of the shorter interval; a
            // logger's jitter spreads between them and keeps the median.
            let short = median(&mut buf);
            let whole = |d: &f64| (d / short - (d / short).round()).abs() <= ON_GRID;
            if dt[lo..hi].iter().all(whole) {
                short
            } else {
                m
            }
        })
        .collect()
}

/// How near a whole multiple of the shorter interval every interval of
/// the window lies where rows were dropped, in shorter intervals.
const ON_GRID: f64 = 0.15;

/// An interval this share of the window's median or less is a shorter one
/// (a log missing rows between them: 0.01 s among 0.02 s).
const SHORT: f64 = 0.75;

/// The share of a window the shorter intervals make that gives its local
/// interval: a logger's jitter (±3 ms at 100 Hz) puts under a tenth there.
const SHORT_SHARE: f64 = 0.3;

/// The holes of `t`: for each, where it starts (s), its length (s) and the
/// samples missing in it.
pub(crate) fn holes(t: &[f64]) -> Vec<(f64, f64, usize)> {
    let local = local_intervals(t);
    t.windows(2)
        .zip(&local)
        .filter_map(|(w, &m)| {
            let ratio = (w[1] - w[0]) / m;
            let whole = ratio.round();
            (m > 0.0 && ratio >= HOLE && (ratio - whole).abs() < 0.25)
                .then(|| (w[0], w[1] - w[0], whole as usize - 1))
        })
        .collect()
}

/// The regular pattern of holes `h` on a grid of `dt`, where there is one:
/// at least 10 holes, nine in ten of them missing the same number of
/// samples as the middle one, and nine in ten of them that number of rows
/// after the last as the middle one (the missing counted; a log's ends may
/// break the pattern). That number missing, of every so many rows.
pub(crate) fn pattern(h: &[(f64, f64, usize)], dt: f64) -> Option<(usize, usize)> {
    if h.len() < 10 {
        return None;
    }
    let rows: Vec<usize> = h
        .windows(2)
        .map(|w| ((w[1].0 - w[0].0) / dt).round() as usize)
        .collect();
    let (missing, every) = (h[h.len() / 2].2, rows[rows.len() / 2]);
    let most = |n: usize| 10 * n >= 9 * h.len();
    let regular = most(h.iter().filter(|x| x.2 == missing).count())
        && most(rows.iter().filter(|r| **r == every).count() + 1);
    regular.then_some((missing, every))
}

/// The holes of run `run` (times `t`) within its stretches between time
/// gaps `parts` (index ranges `[lo, hi)`): None without any. A gap is no
/// hole (it splits the run, and is said as a gap).
pub(crate) fn missing_rows(run: &str, t: &[f64], parts: &[(usize, usize)]) -> Option<MissingRows> {
    let h: Vec<(f64, f64, usize)> = parts
        .iter()
        .flat_map(|&(lo, hi)| holes(&t[lo..hi]))
        .collect();
    let longest = h.iter().max_by(|a, b| a.1.total_cmp(&b.1))?;
    // The holes' own interval: where every third row is missing the run's
    // median interval is the hole's 0.02 s, not 0.01 s.
    let dt = median(&mut local_intervals(t));
    Some(MissingRows {
        run: run.to_string(),
        holes: h.len(),
        samples: h.iter().map(|x| x.2).sum(),
        longest: longest.1,
        longest_after: longest.0,
        pattern: pattern(&h, dt).map(|(missing, every)| RowPattern { missing, every }),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measured::clean::ReadAcross;

    #[test]
    fn every_third_row_missing_is_counted_as_a_pattern() {
        // 100 Hz for 8 s, rows 1, 4, 7, … dropped: 267 missing.
        let t: Vec<f64> = (0..801)
            .filter(|i| i % 3 != 1)
            .map(|i| f64::from(i) / 100.0)
            .collect();
        let h = holes(&t);
        assert_eq!(h.len(), 267);
        assert_eq!(h.iter().map(|x| x.2).sum::<usize>(), 267);
        assert_eq!(pattern(&h, 0.01), Some((1, 3)));
        // A single hole is no pattern; an intact log has no hole.
        assert_eq!(pattern(&h[..1], 0.01), None);
        let whole: Vec<f64> = (0..801).map(|i| f64::from(i) / 100.0).collect();
        assert!(holes(&whole).is_empty());
        assert_eq!(missing_rows("r.csv", &whole, &[(0, 801)]), None);
        let m = missing_rows("r.csv", &t, &[(0, t.len())]).unwrap();
        assert_eq!((m.holes, m.samples), (267, 267));
        assert_eq!(
            m.pattern,
            Some(RowPattern {
                missing: 1,
                every: 3
            })
        );
        let line = m.line(ReadAcross::Replay);
        assert!(
            line.starts_with("missing rows: r.csv misses 267 samples in 267 holes in time, 1 of every 3 rows throughout"),
            "{line}"
        );
        // The metrics run no replay: their line says what they do.
        let line = m.line(ReadAcross::Metrics);
        assert!(
            !line.contains("replay") && line.contains("interpolate"),
            "{line}"
        );
    }

    #[test]
    fn a_time_gap_is_no_hole() {
        // 100 Hz, a 1 s gap after 2 s: the gap splits, no row is missing.
        let mut t: Vec<f64> = (0..200).map(|i| f64::from(i) / 100.0).collect();
        t.extend((0..200).map(|i| 3.0 + f64::from(i) / 100.0));
        assert_eq!(missing_rows("r.csv", &t, &[(0, 200), (200, 400)]), None);
    }
}
