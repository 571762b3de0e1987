//! The points outside a `.tir` file's ranges, range by range: which range
//! each leaves (load, slip ratio, slip angle, camber, pressure), how many
//! points leave it, its ends and the first such point's line and value. A
//! count over all ranges alone left a user to find which one the points
//! left. Each range in the points' frame (a left-side file's slip angle
//! range negated); units N, rad, Pa.

use crate::format::{plural, rounded};
use crate::tyre::mf::{InputRange, MfInput};
use crate::tyre::MagicFormula;
use serde::Serialize;

/// A range some points leave.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RangeLeft {
    /// The range, in the points' frame.
    pub range: InputRange,
    /// Points outside it.
    pub points: usize,
    /// The first such point's line in the points file (1-based).
    pub first_line: usize,
    /// Its value there (the pressure it is evaluated at).
    pub first_value: f64,
}

/// The ranges of `tyre` the points `inputs` (at file lines `lines`) leave,
/// in [`MagicFormula::input_ranges`]'s order.
pub fn ranges_left(tyre: &MagicFormula, inputs: &[MfInput], lines: &[usize]) -> Vec<RangeLeft> {
    let mut out: Vec<RangeLeft> = Vec::new();
    for (i, q) in inputs.iter().enumerate() {
        for (range, value) in tyre.ranges_left(q) {
            match out.iter_mut().find(|r| r.range.keys == range.keys) {
                Some(r) => r.points += 1,
                None => out.push(RangeLeft {
                    range,
                    points: 1,
                    first_line: lines.get(i).copied().unwrap_or(0),
                    first_value: value,
                }),
            }
        }
    }
    let order = |r: &RangeLeft| {
        let all = tyre.input_ranges();
        all.iter().position(|a| a.keys == r.range.keys)
    };
    out.sort_by_key(order);
    out
}

impl RangeLeft {
    /// The range in words, of `count` points.
    pub fn line(&self, count: usize) -> String {
        let r = &self.range;
        let unit = match r.unit {
            "" => String::new(),
            u => format!(" {u}"),
        };
        let end = |v: Option<f64>| v.map_or("unbounded".to_string(), |v| rounded(v, 4));
        format!(
            "{} of {} outside {}–{} ({} to {}{unit}{}): evaluated at its end; the first at line {}, {} = {}{unit}",
            self.points,
            plural(count, "point", "points"),
            r.keys[0],
            r.keys[1],
            end(r.lo),
            end(r.hi),
            match r.column {
                "alpha" | "camber" => ", in the points' frame",
                _ => "",
            },
            self.first_line,
            r.column,
            rounded(self.first_value, 6)
        )
    }
}
