//! A load far below any a tyre was measured at, counted and said: a Magic
//! Formula point at a positive load below a hundredth of `FNOMIN`
//! ([`LIGHT_LOAD_SHARE`]) is evaluated at the load given (its forces,
//! about `μ·Fz`, are then a hundredth or less of those at `FNOMIN`: a load
//! of 1e-300 N gives an `fy` of 4e-302 N), so a load that small is more
//! likely a slip of the data (a gap filled with zeros and noise, a wheel
//! lifting) than a state of the tyre, and the user is told which points
//! are there.
//!
//! A tyre rig's lightest loads are a tenth of `FNOMIN` or more (the
//! public Hoosier cornering data's lightest 405 N against the 2750 N of
//! its MF 6.1 fit, 15 %), so 1 % is an order of magnitude below any load
//! a Magic Formula's load terms were fitted at, and above the noise of a
//! load cell reading a wheel off the ground. The file's `FZMIN` is not
//! the floor: 99 N under an `FZMIN` of 100 N gives 63 N of `fy` at 0.05
//! rad, no "next to nothing". A point below a positive `FZMIN` is said by
//! the ranges (`ranges.rs`, limit checks on or off), once, and is left out
//! here. Loads in N.

use crate::format::{plural, readable, rounded};
use crate::tyre::Tyre;
use serde::Serialize;

/// The share of `FNOMIN` below which a positive load is said, where the
/// file states no `FZMIN` above 0.
pub const LIGHT_LOAD_SHARE: f64 = 0.01;

/// The points at a positive load below the floor.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LightLoad {
    /// The floor, [`LIGHT_LOAD_SHARE`] of `FNOMIN`, N.
    pub floor: f64,
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
/// `tyre` evaluates below its floor and the ranges do not say (below a
/// positive `FZMIN`); `None` for another model or where there are none.
pub(crate) fn light_load(tyre: &Tyre, fz: &[f64], lines: &[usize]) -> Option<LightLoad> {
    let Tyre::MagicFormula(t) = tyre else {
        return None;
    };
    let fnomin = t.coefficients.FNOMIN;
    let floor = LIGHT_LOAD_SHARE * fnomin;
    let fz_min = t.limits.fz_min.filter(|m| *m > 0.0).unwrap_or(0.0);
    let below: Vec<usize> = (0..fz.len())
        .filter(|&i| fz[i] > 0.0 && fz[i] < floor && fz[i] >= fz_min)
        .collect();
    let first = *below.first()?;
    Some(LightLoad {
        floor,
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
        format!(
            "{} of {} at a load above 0 but below {} N ({} % of FNOMIN = {} N), the lightest {} N: evaluated at the load given, where the forces, about μ·Fz, are a hundredth or less of those at FNOMIN; a load that small is no state of a tyre on the road but a wheel lifting or a slip of the data; the first at line {}, fz = {} N",
            self.points,
            plural(count, "point", "points"),
            rounded(self.floor, 4),
            rounded(100.0 * LIGHT_LOAD_SHARE, 2),
            rounded(self.fnomin, 4),
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
    fn a_load_below_a_hundredth_of_fnomin_is_said() {
        let t = sample(None);
        let fnomin = match &t {
            Tyre::MagicFormula(m) => m.coefficients.FNOMIN,
            _ => unreachable!(),
        };
        let fz = [4000.0, 1e-300, 0.0, 0.5 * LIGHT_LOAD_SHARE * fnomin];
        let l = light_load(&t, &fz, &[2, 3, 4, 5]).expect("said");
        assert_eq!((l.points, l.first_line), (2, 3));
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

    /// Below a positive `FZMIN` the ranges say the points, with the limit
    /// checks on or off; between it and the floor, the light load does.
    #[test]
    fn a_load_below_fzmin_is_left_to_the_ranges() {
        let t = sample(Some(30.0));
        assert!(light_load(&t, &[20.0], &[2]).is_none());
        let l = light_load(&t, &[20.0, 50.0], &[2, 3]).expect("said");
        assert_eq!((l.points, l.first_line), (1, 3));
        // 99 N under an FZMIN of 100 N is no light load (the floor 67.52 N).
        assert!(light_load(&sample(Some(100.0)), &[99.0], &[2]).is_none());
    }
}
