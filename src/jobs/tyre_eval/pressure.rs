//! A point's inflation pressure of a few units among pressures in Pa: a
//! value written in kPa, bar or psi (220 for 220 kPa), which a `.tir`
//! would hold at its `PRESMIN` without a word of the unit. A whole column
//! so written is refused by its median (`crate::io::rig`); one row among
//! others in Pa passes that, and is refused at its cell
//! (`crate::io::rig_rows`, shared with `identify`'s rig files), with the
//! reading that lands among the pressures this module says the tyre runs
//! at where one does, as `identify` answers a level requested in another
//! unit (`crate::error::LevelSlip`).

use crate::io::fitted_ranges::FittedRanges;
pub(super) use crate::io::rig_rows::{refuse_rows_not_in_pa, Known};
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
