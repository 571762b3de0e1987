//! A point's inflation pressure of a few units among pressures in Pa: a
//! value written in kPa, bar or psi (220 for 220 kPa), which a `.tir`
//! would hold at its `PRESMIN` without a word of the unit. A whole column
//! so written is refused by its median (`crate::io::rig`); one row among
//! others in Pa passes that, and is refused at its cell
//! (`crate::io::rig_rows`, shared with `identify`'s rig files), with the
//! reading that lands among the pressures this module says the tyre runs
//! at where one does, as `identify` answers a level requested in another
//! unit (`crate::error::LevelSlip`).

use crate::error::{UnitSlip, MIN_MEDIAN_PRESSURE};
use crate::io::fitted_ranges::FittedRanges;
use crate::io::rig::{pressure_not_in_pa, INFLATION};
pub(super) use crate::io::rig_rows::Known;
use crate::io::rig_rows::{meant, rows_not_in_pa};
use crate::tyre::Tyre;

/// The pressures a tyre is known to run at, Pa, and what they are: a
/// `.tir`'s `PRESMIN` to `PRESMAX`, else half to twice its `NOMPRES`; a
/// TOML tyre's fitted range; `None` for a tyre that says none.
pub(super) fn tyre_pressures(tyre: &Tyre, fitted: Option<&FittedRanges>) -> Option<Known> {
    if let Tyre::MagicFormula(t) = tyre {
        if let (Some(lo), Some(hi)) = (t.limits.pressure_min, t.limits.pressure_max) {
            if lo > 0.0 && hi > lo {
                return Some(([lo, hi], "the file's PRESMIN to PRESMAX"));
            }
        }
        let p = t.coefficients.NOMPRES;
        if p > 0.0 {
            return Some(([0.5 * p, 2.0 * p], "half to twice the file's NOMPRES"));
        }
    }
    let fitted = fitted.and_then(|r| r.pressure)?;
    Some((fitted, "the pressures the tyre was fitted to"))
}

/// Whether the pressures of `p` below [`MIN_MEDIAN_PRESSURE`] read in
/// more than one unit (the first of kPa, bar and psi that lands each among
/// the pressures `known`, else a pneumatic tyre's): 2.2 and 220 are
/// 2.2 bar and 220 kPa, which one unit for the column cannot say.
pub(super) fn mixed_units(p: &[f64], known: Option<Known>) -> bool {
    let mut units = p
        .iter()
        .filter(|v| **v > 0.0 && **v < MIN_MEDIAN_PRESSURE)
        .map(|&v| {
            known
                .and_then(|k| meant(v, k))
                .or_else(|| meant(v, INFLATION))
                .map(|m| m.unit)
        });
    let Some(first) = units.next() else {
        return false;
    };
    units.any(|u| u != first)
}

/// The pressures of `p` (Pa) that `tyre-eval` refuses as written in kPa,
/// bar or psi, read against the pressures `known` of the tyre, each at
/// its index (0-based) with why: a column in one such unit once, at its
/// first cell, by its median; else, or where its cells read in different
/// units (2.2 in bar beside 220 in kPa), every such cell with its own
/// reading — one cell in bar among pressures in Pa (`[2.2e5, 2.3e5,
/// 2.4]`) passes the median and is refused at its own index. The one
/// rule of the points file and of the Python `Tyre.forces`'s arrays.
pub(super) fn not_in_pa(p: &[f64], known: Option<Known>) -> Vec<(usize, UnitSlip)> {
    if !mixed_units(p, known) {
        if let Some(column) = pressure_not_in_pa(p, known) {
            return vec![column];
        }
    }
    rows_not_in_pa(p, known)
}
