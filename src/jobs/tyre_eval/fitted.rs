//! The points past the ranges of the rig data a TOML tyre was fitted to
//! (its `[fitted_ranges]`, which `identify` writes), range by range and
//! side by side: how many, the farthest and by how much of the range's
//! span, and the first one's line and value. Units as the file holds
//! them: N, rad, Pa. A point past an end by at most
//! [`crate::io::fitted_ranges::SLACK`] of the span is read as within the
//! data (a rig holds its load and slip angle to about that); such points
//! are counted apart, not warned of: one count over every range alone
//! said "2 of 3 points outside" for a load 0.5 N past the data's end.
//!
//! A range whose span is under [`ONE_LEVEL`]'s width for its key is one
//! level of the data (a camber held at 0°, a pressure at 83.4 kPa), its
//! span the rig's spread about that level: a point past it is said by its
//! distance in the range's unit, not as a share of a span that is noise
//! ("4117 % of the range's span" for a camber of 0.03 rad past ±0.00036).
//! A camber at one level (a rig file without a `camber` column is at 0,
//! and `identify` writes `camber = [0.0, 0.0]`) is said as the fit having
//! seen no other camber, so that no data fixed the tyre's camber terms:
//! the range is kept, not dropped, as a point at another camber is
//! evaluated by terms the fit held at their start values.
//! A range of an input the model does not read (`reads.rs`: a Gim
//! tyre's camber, pressure, a linear tyre's load) is not checked: the
//! points are evaluated as at any value of it, which `unread.rs` says,
//! and an extrapolation in it would contradict that.

use crate::format::{plural, readable, rounded};
use crate::io::fitted_ranges::{FittedRanges, RangePoint};
use serde::Serialize;

/// The span under which a fitted range is one level of the data, by key:
/// 0.5° of camber or slip angle (a rig holds an angle to a few hundredths
/// of a degree; a sweep spans degrees), 5 kPa of pressure (the TTC's
/// levels lie 14 kPa apart, each held to about ±1.5 kPa) and 0.01 of slip
/// ratio (a cornering test's, at 0). The load has none: a rig's load
/// levels are each a sweep's step and a share of the span reads right.
pub const ONE_LEVEL: [(&str, f64); 4] = [
    ("alpha", 0.008_726_646_259_971_648),
    ("kappa", 0.01),
    ("camber", 0.008_726_646_259_971_648),
    ("pressure", 5000.0),
];

/// How far `v` lies past the nearer end of the fitted range `[lo, hi]` of
/// `key` (unit `unit`, with its leading space), in words: by its distance
/// where the range is one level of the data (or is open at an end), else
/// as a share of its span. One rule for `tyre-eval`'s points and
/// `simulate`'s rows.
pub fn past_end(key: &str, [lo, hi]: [f64; 2], v: f64, unit: &str) -> String {
    let past = if v < lo { lo - v } else { v - hi };
    if one_level(key, [lo, hi]) || !(hi - lo).is_finite() {
        return format!("{}{unit} past the range's end", readable(past, 4));
    }
    format!(
        "{} % of the range's span past its end",
        readable(100.0 * past / (hi - lo), 3)
    )
}

/// Whether the range `[lo, hi]` of `key` is one level of the data: any
/// range of one value (`identify` at one load writes `fz = [4000, 4000]`,
/// whose span no distance is a share of).
pub fn one_level(key: &str, [lo, hi]: [f64; 2]) -> bool {
    hi <= lo
        || ONE_LEVEL
            .iter()
            .any(|(k, width)| *k == key && hi - lo < *width)
}

/// One side of one fitted range some points lie past.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FittedLeft {
    /// The range's key (`fz`, `alpha`, `kappa`, `camber`, `pressure`).
    pub key: &'static str,
    /// Its unit.
    #[serde(skip)]
    pub unit: &'static str,
    /// The range, `[low, high]`.
    pub range: [f64; 2],
    /// The points lie below it (else above).
    pub below: bool,
    /// How many.
    pub points: usize,
    /// The farthest value past the end.
    pub farthest: f64,
    /// The first such point's line in the points file (1-based) and value.
    pub first_line: usize,
    /// The first such point's value.
    pub first_value: f64,
}

/// What the points do against a tyre's fitted ranges.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct BeyondFitted {
    /// The points past some range by more than the slack, evaluated by
    /// extrapolation.
    pub points: usize,
    /// The points past an end by no more than the slack (read as within).
    pub within_slack: usize,
    /// The ranges left, in key order, below before above.
    pub ranges: Vec<FittedLeft>,
}

/// The points `[fz, kappa, alpha, camber]` (with their pressures, where
/// given) at file lines `lines` against the ranges `r`.
pub(crate) fn beyond(
    r: &FittedRanges,
    [fz, kappa, alpha, camber]: [&[f64]; 4],
    pressure: &[f64],
    lines: &[usize],
) -> BeyondFitted {
    let mut out = BeyondFitted::default();
    for i in 0..fz.len() {
        let p = RangePoint {
            fz: fz[i],
            alpha: alpha[i],
            kappa: kappa[i],
            camber: camber[i],
            pressure: pressure.get(i).copied(),
        };
        let left = r.left(&p);
        if left.is_empty() {
            // Past an end at all, by no more than the slack.
            out.within_slack += usize::from(r.outside(&p, 0.0));
            continue;
        }
        out.points += 1;
        for l in left {
            let same = |f: &&mut FittedLeft| f.key == l.key && f.below == l.below;
            match out.ranges.iter_mut().find(same) {
                Some(f) => {
                    f.points += 1;
                    let further = if l.below {
                        l.value < f.farthest
                    } else {
                        l.value > f.farthest
                    };
                    if further {
                        f.farthest = l.value;
                    }
                }
                None => out.ranges.push(FittedLeft {
                    key: l.key,
                    unit: l.unit,
                    range: l.range,
                    below: l.below,
                    points: 1,
                    farthest: l.value,
                    first_line: lines.get(i).copied().unwrap_or(0),
                    first_value: l.value,
                }),
            }
        }
    }
    let order = ["fz", "alpha", "kappa", "camber", "pressure"];
    let rank = |f: &FittedLeft| (order.iter().position(|k| *k == f.key), !f.below);
    out.ranges.sort_by_key(rank);
    out
}

impl FittedLeft {
    /// The range in words, of `count` points.
    pub fn line(&self, count: usize) -> String {
        let unit = match self.unit {
            "" => String::new(),
            u => format!(" {u}"),
        };
        let [lo, hi] = self.range;
        let (side, end) = match self.below {
            true => ("below", lo),
            false => ("above", hi),
        };
        let past = past_end(self.key, self.range, self.farthest, &unit);
        if one_level(self.key, self.range) {
            // One camber level fixes no camber term: said as such, the
            // same whether the rig held the camber or gave no column.
            let (spread, evaluated) = match self.key {
                "camber" => (
                    "",
                    "the fit saw no other camber (a rig file without a `camber` column is at camber 0, FORMATS.md), so no data fixed the tyre's camber terms: evaluated with camber terms no data fitted",
                ),
                _ => (
                    ", the rig's spread about that level, no sweep",
                    "evaluated by extrapolation from that one level",
                ),
            };
            return format!(
                "{} of {} {side} the rig data's {}, one level at {}{unit} (its [fitted_ranges]: {} to {}{unit}{spread}): {evaluated}, the farthest at {}{unit}, {past}; the first at line {}, {} = {}{unit}",
                self.points,
                plural(count, "point", "points"),
                self.key,
                readable(0.5 * (lo + hi), 4),
                readable(lo, 4),
                readable(hi, 4),
                rounded(self.farthest, 6),
                self.first_line,
                self.key,
                rounded(self.first_value, 6)
            );
        }
        format!(
            "{} of {} {side} the rig data's {} = {}{unit} the tyre was fitted to (its [fitted_ranges]: {} to {}{unit}): evaluated by extrapolation, the farthest at {}{unit}, {past}; the first at line {}, {} = {}{unit}",
            self.points,
            plural(count, "point", "points"),
            self.key,
            readable(end, 4),
            readable(lo, 4),
            readable(hi, 4),
            rounded(self.farthest, 6),
            self.first_line,
            self.key,
            rounded(self.first_value, 6)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Four points: inside, 0.5 N past the top load (within 1 % of the
    /// span), 500 N past it, and at 0 N (off the road: never counted).
    #[test]
    fn points_within_the_slack_are_counted_apart_from_those_past_it() {
        let r = FittedRanges {
            fz: Some([2000.0, 6000.0]),
            ..Default::default()
        };
        let fz = [4000.0, 6000.5, 6500.0, 0.0];
        let zeros = [0.0; 4];
        let b = beyond(&r, [&fz, &zeros, &zeros, &zeros], &[], &[2, 3, 4, 5]);
        assert_eq!((b.points, b.within_slack), (1, 1));
        let f = &b.ranges[0];
        assert_eq!(
            (f.key, f.below, f.points, f.first_line),
            ("fz", false, 1, 4)
        );
        assert_eq!(f.farthest, 6500.0);
    }
}
