//! Rig columns scaled by a unit's factor against the loads: loads in lbf
//! beside forces in N (`error/rig_load_lbf.rs`), judged on the median
//! |force|/fz of the samples past [`LBF_SLIP`], where a tyre's force is
//! most of its grip, so a spike or a lifted wheel does not decide it; an
//! aligning moment in kN·m (`error/rig_moment_knm.rs`), judged on its
//! largest |mz|/fz over a sweep reaching [`MZ_REACH`]. Units: N, N·m, rad.

use super::columns::Columns;
use crate::error::{
    InputError, RigLoadInLbf, RigMomentInKnm, UnitSlip, LBF_SLIP, MAX_MEDIAN_GRIP, MIN_RIG_ARM,
};
use std::path::Path;

/// The fewest samples past [`LBF_SLIP`] a median is taken of: fewer are
/// no sweep.
const MIN_SAMPLES: usize = 10;

/// Refuses loads `fz` whose sweep (`force`, named `column`, along `slip`)
/// has a median |force|/fz past [`LBF_SLIP`] above [`MAX_MEDIAN_GRIP`],
/// at the `fz` of the median sample's row.
pub(super) fn refuse_loads_in_lbf(
    path: &Path,
    c: &Columns,
    column: &'static str,
    (slip, force): (&[f64], &[f64]),
    fz: &[f64],
) -> Result<(), InputError> {
    let mut judged: Vec<(f64, usize)> = (0..fz.len())
        .filter(|&i| fz[i] > 0.0 && force[i].is_finite() && slip[i].abs() >= LBF_SLIP)
        .map(|i| ((force[i] / fz[i]).abs(), i))
        .collect();
    if judged.len() < MIN_SAMPLES {
        return Ok(());
    }
    judged.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (median, i) = judged[judged.len() / 2];
    if median <= MAX_MEDIAN_GRIP {
        return Ok(());
    }
    let slip = RigLoadInLbf {
        force: column,
        fz: fz[i],
        median,
        samples: judged.len(),
        slip: LBF_SLIP,
    };
    Err(c.error_at(path, i, "fz", UnitSlip::from(slip).into()))
}

/// The slip angle a cornering sweep must reach for its aligning moment to
/// be judged, rad (2°: past where a tyre's `mz` rises to near its peak).
const MZ_REACH: f64 = 0.035;

/// Refuses an aligning moment `mz` whose largest |mz|/fz, over a sweep
/// `alpha` reaching [`MZ_REACH`], is below [`MIN_RIG_ARM`] (and above 0:
/// a column of zeros is no unit's), at that sample's row.
pub(super) fn refuse_moments_in_knm(
    path: &Path,
    c: &Columns,
    alpha: &[f64],
    mz: &[f64],
    fz: &[f64],
) -> Result<(), InputError> {
    let reach = alpha
        .iter()
        .filter(|a| a.is_finite())
        .fold(0.0_f64, |m, a| m.max(a.abs()));
    let arm = |i: &usize| (mz[*i] / fz[*i]).abs();
    let judged = (0..mz.len()).filter(|&i| fz[i] > 0.0 && mz[i].is_finite());
    let Some(i) = judged.max_by(|a, b| arm(a).total_cmp(&arm(b))) else {
        return Ok(());
    };
    if reach < MZ_REACH || arm(&i) >= MIN_RIG_ARM || arm(&i) == 0.0 {
        return Ok(());
    }
    let slip = RigMomentInKnm {
        value: mz[i],
        fz: fz[i],
        slip: reach,
    };
    Err(c.error_at(path, i, "mz", UnitSlip::from(slip).into()))
}
