//! A point's inflation pressure of a few units among pressures in Pa: a
//! value written in kPa, bar or psi (220 for 220 kPa), which a `.tir`
//! would hold at its `PRESMIN` without a word of the unit. A whole column
//! so written is refused by its median (`crate::io::rig`); one row among
//! others in Pa passes that, and is refused here at its cell, with the
//! reading that lands among the tyre's own pressures where one does, as
//! `identify` answers a level requested in another unit
//! (`crate::error::LevelSlip`).

use crate::error::{unit_slips, InputError, PressureMeant, UnitSlip, Variable};
use crate::io::fitted_ranges::FittedRanges;
use crate::io::rig::MIN_MEDIAN_PRESSURE;
use crate::io::Columns;
use crate::tyre::Tyre;
use std::path::Path;

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

/// Pressures (Pa) and what they are.
pub(super) type Known = ([f64; 2], &'static str);

/// Refuses every positive pressure of `p` below [`MIN_MEDIAN_PRESSURE`]
/// at its cell of `file` (the points file `path`), each with the reading
/// in kPa, bar or psi that lands among the pressures `known` (of the
/// tyre, else near the column's median). Run once the median has passed.
pub(super) fn refuse_rows_not_in_pa(
    path: &Path,
    file: &Columns,
    p: &[f64],
    known: Option<Known>,
) -> Result<(), InputError> {
    let mut sorted: Vec<f64> = p.iter().copied().filter(|v| *v > 0.0).collect();
    sorted.sort_by(f64::total_cmp);
    let Some(&median) = sorted.get(sorted.len() / 2) else {
        return Ok(());
    };
    let known = known.unwrap_or(([0.5 * median, 2.0 * median], "half to twice the median"));
    let errors = p
        .iter()
        .enumerate()
        .filter(|(_, v)| **v > 0.0 && **v < MIN_MEDIAN_PRESSURE)
        .map(|(i, &value)| {
            let slip = UnitSlip::PressureRowNotInPa {
                value,
                median,
                limit: MIN_MEDIAN_PRESSURE,
                meant: meant(value, known),
            };
            file.error_at(path, i, "pressure", slip.into())
        })
        .collect();
    InputError::all_of(path, errors).map_or(Ok(()), Err)
}

/// The first reading of `value` in kPa, bar or psi that lands among the
/// pressures `known`.
fn meant(value: f64, (among, what): Known) -> Option<PressureMeant> {
    unit_slips(Variable::Pressure)
        .iter()
        .map(|&(unit, factor)| (unit, value * factor))
        .find(|(_, pa)| (among[0]..=among[1]).contains(pa))
        .map(|(unit, pa)| PressureMeant {
            pa,
            unit,
            among,
            what,
        })
}
