//! A load far below any a tyre was measured at, counted and said: a Magic
//! Formula point at a positive load below a stated floor is evaluated at
//! the load given (its forces, about `μ·Fz`, are then next to nothing: a
//! load of 1e-300 N gives an `fy` of 4e-302 N), so a load that small is
//! more likely a slip of the data (a gap filled with zeros and noise, a
//! wheel lifting) than a state of the tyre, and the user is told which
//! points are there.
//!
//! The floor is the file's `FZMIN` where it gives one above 0. A file
//! that gives none, or `FZMIN = 0` (the public MF 6.1 / 6.2 samples),
//! states no floor, and [`LIGHT_LOAD_SHARE`] of `FNOMIN` is taken: a tyre
//! rig's lightest loads are a tenth of `FNOMIN` or more (the public
//! Hoosier cornering data's lightest 405 N against the 2750 N of its MF 6.1
//! fit, 15 %), so 1 % is an order of
//! magnitude below any load a Magic Formula's load terms were fitted at,
//! and above the noise of a load cell reading a wheel off the ground.
//! Where the limit checks are on and `FZMIN` is given, the points below it
//! are already among the ranges left (`ranges.rs`) and are not said twice.
//! Loads in N.

use crate::format::{plural, readable, rounded};
use crate::tyre::Tyre;
use serde::Serialize;

/// The share of `FNOMIN` below which a positive load is said, where the
/// file states no `FZMIN` above 0.
pub const LIGHT_LOAD_SHARE: f64 = 0.01;

/// Where the floor of the loads said comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LoadFloor {
    /// The file's `FZMIN` (its limit checks off: the ranges do not say it).
    Fzmin,
    /// [`LIGHT_LOAD_SHARE`] of the file's `FNOMIN` (no `FZMIN` above 0).
    ShareOfFnomin,
}

/// The points at a positive load below the floor.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LightLoad {
    /// The floor, N.
    pub floor: f64,
    /// Where it comes from.
    pub source: LoadFloor,
    /// The file's `FNOMIN`, N.
    pub fnomin: f64,
    /// Points below it.
    pub points: usize,
    /// The first such point's line in the points file (1-based).
    pub first_line: usize,
    /// Its load, N.
    pub first_value: f64,
    /// The lightest load among them, N.
    pub lightest: f64,
}

/// The points of load `fz` (at file lines `lines`) that a Magic Formula
/// `tyre` evaluates below its floor; `None` for another model, where
/// there are none, or where the file's ranges already say them.
pub(crate) fn light_load(tyre: &Tyre, fz: &[f64], lines: &[usize]) -> Option<LightLoad> {
    let Tyre::MagicFormula(t) = tyre else {
        return None;
    };
    let fnomin = t.coefficients.FNOMIN;
    let said_by_ranges = t
        .input_ranges()
        .iter()
        .any(|r| r.column == "fz" && r.lo.is_some_and(|lo| lo > 0.0));
    let (floor, source) = match t.limits.fz_min.filter(|m| *m > 0.0) {
        Some(_) if said_by_ranges => return None,
        Some(m) => (m, LoadFloor::Fzmin),
        None => (LIGHT_LOAD_SHARE * fnomin, LoadFloor::ShareOfFnomin),
    };
    let below: Vec<usize> = (0..fz.len())
        .filter(|&i| fz[i] > 0.0 && fz[i] < floor)
        .collect();
    let first = *below.first()?;
    Some(LightLoad {
        floor,
        source,
        fnomin,
        points: below.len(),
        first_line: lines.get(first).copied().unwrap_or(0),
        first_value: fz[first],
        lightest: below.iter().map(|&i| fz[i]).fold(f64::INFINITY, f64::min),
    })
}

impl LightLoad {
    /// The points in words, of `count` points.
    pub fn line(&self, count: usize) -> String {
        let floor = match self.source {
            LoadFloor::Fzmin => format!(
                "the file's FZMIN = {} N; its limit checks are off",
                rounded(self.floor, 4)
            ),
            LoadFloor::ShareOfFnomin => format!(
                "{} % of FNOMIN = {} N: the file states no FZMIN above 0",
                rounded(100.0 * LIGHT_LOAD_SHARE, 2),
                rounded(self.fnomin, 4)
            ),
        };
        format!(
            "{} of {} at a load above 0 but below {} N ({floor}), the lightest {} N: evaluated at the load given, where the forces are next to nothing; a load that small is no state of a tyre on the road but a wheel lifting or a slip of the data; the first at line {}, fz = {} N",
            self.points,
            plural(count, "point", "points"),
            rounded(self.floor, 4),
            readable(self.lightest, 3),
            self.first_line,
            readable(self.first_value, 3)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The MF 6.1 sample (FNOMIN 6752 N, FZMIN 0) with `FZMIN` set to `fz_min`.
    fn sample(fz_min: Option<f64>) -> Tyre {
        let mut t = crate::io::tir::read_tir_text(
            "MagicFormula61_Parameters.tir",
            include_str!("../../../tests/fixtures/tir/MagicFormula61_Parameters.tir"),
        )
        .expect("the sample reads");
        t.limits.fz_min = fz_min;
        Tyre::MagicFormula(Box::new(t))
    }

    #[test]
    fn a_load_below_a_hundredth_of_fnomin_is_said_where_no_fzmin_is_given() {
        let t = sample(None);
        let fnomin = match &t {
            Tyre::MagicFormula(m) => m.coefficients.FNOMIN,
            _ => unreachable!(),
        };
        let fz = [4000.0, 1e-300, 0.0, 0.5 * LIGHT_LOAD_SHARE * fnomin];
        let l = light_load(&t, &fz, &[2, 3, 4, 5]).expect("said");
        assert_eq!(
            (l.points, l.first_line, l.source),
            (2, 3, LoadFloor::ShareOfFnomin)
        );
        assert_eq!(l.lightest, 1e-300);
        let s = l.line(4);
        assert!(
            s.starts_with("2 of 4 points at a load above 0 but below "),
            "{s}"
        );
        assert!(s.contains("the first at line 3, fz = 1e-300 N"), "{s}");
        // FZMIN = 0 states no floor either; off the road (fz ≤ 0) is not said.
        assert_eq!(
            light_load(&sample(Some(0.0)), &fz, &[2, 3, 4, 5]).map(|l| l.points),
            Some(2)
        );
        assert!(light_load(&t, &[4000.0, 0.0, -1.0], &[2, 3, 4]).is_none());
    }

    #[test]
    fn a_load_below_fzmin_is_left_to_the_ranges_where_the_limit_checks_say_it() {
        let t = sample(Some(100.0));
        assert!(light_load(&t, &[50.0], &[2]).is_none());
        let Tyre::MagicFormula(mut m) = t else {
            unreachable!()
        };
        let mut mode = m.mode();
        mode.limit_checks = false;
        m.set_mode(mode);
        let l = light_load(&Tyre::MagicFormula(m), &[50.0], &[2]).expect("said");
        assert_eq!((l.floor, l.source), (100.0, LoadFloor::Fzmin));
    }
}
