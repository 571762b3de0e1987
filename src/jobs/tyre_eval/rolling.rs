//! A Magic Formula rolling resistance moment `my` beyond any tyre's at the
//! points: `|my|` above [`MY_SPEED_TERMS`] of `R0·|Fz|` (a rolling
//! resistance coefficient of a tenth, where a car tyre's is about 0.01,
//! SAE J2452), at a speed its speed terms do not carry past that
//! (`checks.rs` says those). The rule the speed terms already had, applied
//! to the whole moment: a `.tir` with `QSY1 = 1e5` (for 0.01) gave
//! `my = −7.5e7 N·m` at 2 kN without a word. The constant term `QSY1` is
//! named where it alone exceeds the limit (TNO MF 6.1, eq. A48:
//! `My = −Fz0·R0·λMy·(QSY1 + QSY2·Fx/Fz0 + … )·(Fz/Fz0)^QSY7·(p/p0)^QSY8`;
//! MF 5.2: `−Fz·R0·λMy·(QSY1 + …)`).
//! Units: N, N·m.

use super::checks::MY_SPEED_TERMS;
use super::unread::Points;
use crate::format::{readable, rounded};
use crate::tyre::{PointForces, Tyre};
use serde::Serialize;

/// The points whose `my` is beyond any tyre's rolling resistance.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RollingBeyond {
    /// How many.
    pub points: usize,
    /// The first one's line (1-based), load (N) and `my` (N·m).
    pub first: (usize, f64, f64),
    /// The largest `|my|/(R0·|Fz|)` among them.
    pub largest: f64,
    /// The file's `QSY1·LMY`, where it alone exceeds the limit.
    pub constant: Option<f64>,
}

/// The points of `p` (outputs `f`, file lines `lines`) where a Magic
/// Formula `tyre`'s `my` exceeds [`MY_SPEED_TERMS`] of `R0·|Fz|` while its
/// speed terms stay within it; `None` for another model or no such point.
pub(super) fn rolling_beyond(
    tyre: &Tyre,
    p: &Points,
    f: &[PointForces],
    lines: &[usize],
) -> Option<RollingBeyond> {
    let Tyre::MagicFormula(t) = tyre else {
        return None;
    };
    let c = &t.coefficients;
    let r0 = c.UNLOADED_RADIUS.abs();
    let [fz, _, _, _, speed] = p.columns;
    let speed_terms = |v: f64| {
        let x = (v / c.LONGVL).abs();
        (c.QSY3 * x + c.QSY4 * x.powi(4)).abs() * c.LMY.abs()
    };
    let share = |i: usize| f[i].my.map_or(0.0, |my| my.abs() / (r0 * fz[i].abs()));
    let beyond: Vec<usize> = (0..fz.len())
        .filter(|&i| fz[i] > 0.0 && speed_terms(speed[i]) <= MY_SPEED_TERMS)
        .filter(|&i| share(i) > MY_SPEED_TERMS)
        .collect();
    let &i = beyond.first()?;
    let constant = c.QSY1 * c.LMY;
    Some(RollingBeyond {
        points: beyond.len(),
        first: (lines.get(i).copied().unwrap_or(0), fz[i], f[i].my?),
        largest: beyond.iter().map(|&i| share(i)).fold(0.0, f64::max),
        constant: (constant.abs() > MY_SPEED_TERMS).then_some(constant),
    })
}

impl RollingBeyond {
    /// The sentence on the terminal.
    pub fn line(&self, count: usize) -> String {
        let (line, fz, my) = self.first;
        let cause = match self.constant {
            Some(q) => format!(
                "its constant term QSY1·LMY = {} alone is beyond it: is a digit or a unit slipped in QSY1?",
                readable(q, 4)
            ),
            None => "its load, slip and pressure terms (QSY2, QSY5–QSY8) carry it there: check them".to_string(),
        };
        format!(
            "{} of {} with a rolling resistance moment `my` above {MY_SPEED_TERMS} of R0·Fz (a rolling resistance coefficient of a tenth; a car tyre's is about 0.01), at speeds its speed terms do not explain: up to {} times R0·Fz; the first at line {line}, fz = {} N, my = {} N·m: {cause}",
            self.points,
            crate::format::plural(count, "point", "points"),
            three_digits(self.largest),
            rounded(fz, 6),
            readable(my, 4),
        )
    }
}

/// `v` to three significant digits, its whole digits past the third
/// rounded too (`107000`, not the `107118` [`readable`] keeps below 1e6):
/// a share of R0·Fz read for its size, not its last unit.
fn three_digits(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return readable(v, 3);
    }
    let unit = 10f64.powi(v.abs().log10().floor() as i32 - 2);
    match unit > 1.0 {
        true => crate::format::exact((v / unit).round() * unit),
        false => readable(v, 3),
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn three_digits_round_whole_digits_too() {
        assert_eq!(super::three_digits(107118.0), "107000");
        assert_eq!(super::three_digits(12.345), "12.3");
        assert_eq!(super::three_digits(999.6), "1000");
        assert_eq!(super::three_digits(3.2e9), "3.2e9");
    }
}
