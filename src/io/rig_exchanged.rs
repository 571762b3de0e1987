//! A rig file's negative loads: every load negative is a sign convention
//! (SAE's z axis points down), a good share of them beside an `fy`
//! positive throughout is the two columns exchanged, and a few among
//! positive loads are bad samples, each refused at its cell.

use super::columns::Columns;
use crate::error::{InputError, InputProblem, LoadAndForceExchanged, EXCHANGED_SHARE};
use std::path::Path;

/// The refusals of the negative loads of `fz` (read from `c`): one for
/// `fz` and `fy` exchanged, at the first negative load, or one per
/// negative load.
pub(super) fn negative_loads(path: &Path, c: &Columns, fz: &[f64]) -> Vec<InputError> {
    let finite: Vec<f64> = fz.iter().copied().filter(|v| v.is_finite()).collect();
    let negative = finite.iter().filter(|v| **v < 0.0).count();
    let Some(first) = fz.iter().position(|v| *v < 0.0) else {
        return Vec::new();
    };
    if let Some(e) = exchanged(c.get("fy"), &finite, negative) {
        return vec![c.error_at(path, first, "fz", e.into())];
    }
    let every = negative == finite.len();
    fz.iter()
        .enumerate()
        .filter(|(_, v)| v.is_finite() && **v < 0.0)
        .map(|(i, &value)| c.error_at(path, i, "fz", InputProblem::NegativeLoad { value, every }))
        .collect()
}

/// `fz` and `fy` exchanged: at least [`EXCHANGED_SHARE`] of the loads
/// negative, not all, and every `fy` finite and positive.
fn exchanged(fy: Option<&[f64]>, fz: &[f64], negative: usize) -> Option<LoadAndForceExchanged> {
    let fy = fy?;
    let share = negative as f64 / fz.len().max(1) as f64;
    if negative == fz.len() || share < EXCHANGED_SHARE || fy.iter().any(|v| v.is_nan() || *v <= 0.0)
    {
        return None;
    }
    let range = |v: &[f64]| {
        v.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
                (lo.min(*x), hi.max(*x))
            })
    };
    Some(LoadAndForceExchanged {
        negative,
        samples: fz.len(),
        fz: range(fz),
        fy: range(fy),
    })
}
