//! The points outside what the linear tyre model means: `Fy = Cα·α` is the
//! tangent of a tyre's curve at zero slip, which a road tyre follows to
//! within a few percent up to about 0.1 rad (6°; its force then bends
//! over to a peak near 0.1–0.15 rad): beyond, the line's force grows
//! without bound where a tyre's saturates. And a cornering stiffness per
//! load `Cα/Fz` below 4 /rad at a point's load is no road tyre's (a car
//! tyre's is 10–25 /rad near its rated load, a truck tyre's 5–8): the
//! stiffness was meant for a lighter wheel, or is in other units. Both
//! said as warnings, counted, with the first point's line and value.
//! Units: rad, N, N/rad.

use crate::format::{plural, readable};
use crate::tyre::Tyre;
use serde::Serialize;

/// The largest |α| the linear model means, rad.
pub const LINEAR_MAX_SLIP: f64 = 0.1;

/// The least cornering coefficient `Cα/Fz` of a road tyre, 1/rad.
pub const MIN_CORNERING_COEFFICIENT: f64 = 4.0;

/// Points of one kind outside the model's meaning.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NotMeant {
    /// The points beyond `LINEAR_MAX_SLIP` (else below the coefficient).
    pub slip: bool,
    /// How many.
    pub points: usize,
    /// The first one's line in the points file.
    pub first_line: usize,
    /// Its value: |α|, rad, or `Cα/Fz`, 1/rad.
    pub first_value: f64,
}

/// A point's value beyond what the model means (None: within it).
type Beyond<'a> = dyn Fn(usize) -> Option<f64> + 'a;

/// The points at slip `alpha` and load `fz` (at file lines `lines`) a
/// linear `tyre` is not meant for; none for another model.
pub(super) fn not_meant(tyre: &Tyre, fz: &[f64], alpha: &[f64], lines: &[usize]) -> Vec<NotMeant> {
    let Tyre::Linear(l) = tyre else {
        return Vec::new();
    };
    let coefficient = |i: usize| l.cornering_stiffness / fz[i];
    let checks: [(bool, &Beyond); 2] = [
        (true, &|i| {
            (alpha[i].abs() > LINEAR_MAX_SLIP).then(|| alpha[i].abs())
        }),
        (false, &|i| {
            (fz[i] > 0.0 && coefficient(i) < MIN_CORNERING_COEFFICIENT).then(|| coefficient(i))
        }),
    ];
    checks
        .into_iter()
        .filter_map(|(slip, beyond)| {
            let rows: Vec<(usize, f64)> = (0..fz.len())
                .filter_map(|i| beyond(i).map(|v| (i, v)))
                .collect();
            let &(first, value) = rows.first()?;
            Some(NotMeant {
                slip,
                points: rows.len(),
                first_line: lines.get(first).copied().unwrap_or(0),
                first_value: value,
            })
        })
        .collect()
}

impl NotMeant {
    /// The points in words, of `count` points.
    pub fn line(&self, count: usize) -> String {
        let of = plural(count, "point", "points");
        match self.slip {
            true => format!(
                "{} of {of} at a slip angle beyond ±{LINEAR_MAX_SLIP} rad (5.7°), outside what the linear tyre means: Fy = Cα·α is a tyre's slope at zero slip, and a tyre's force bends over to its peak by about 0.1 rad where the line's grows on; the first at line {}, |alpha| = {} rad ({}°)",
                self.points,
                self.first_line,
                crate::error::Num(self.first_value),
                readable(self.first_value.to_degrees(), 3)
            ),
            false => format!(
                "{} of {of} at a load where the cornering coefficient Cα/Fz is below {MIN_CORNERING_COEFFICIENT} /rad, which no road tyre's is (a car tyre's is 10–25 /rad, a truck tyre's 5–8): is the cornering stiffness meant for a lighter wheel, or in other units? the first at line {}, Cα/Fz = {} /rad",
                self.points,
                self.first_line,
                readable(self.first_value, 3)
            ),
        }
    }
}
