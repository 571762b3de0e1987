//! Single cells of a rig or points file in another unit than the rest of
//! their column: a pressure of a few units (220 for 220 kPa) among
//! pressures in Pa, a load of a few units (2.5 for 2.5 kN) among loads in
//! N. A whole column so written is refused by its median (`super::rig`);
//! one cell among others passes that, and would be held at a `.tir`'s
//! range or counted as a sample between levels: refused here at its
//! cell, with the reading that lands among the column's values. Rig
//! `fy` and `mz` columns exchanged are refused as such, not as an `mz` in
//! N·mm (`refuse_swapped_fy_mz`). A rig pressure above any tyre's (a
//! column a thousand times too large, whose median passes) is refused at
//! each cell by the limit `tyre-eval` applies
//! ([`crate::constants::MOST_PRESSURE`]).

use super::Columns;
use crate::constants::MOST_PRESSURE;
use crate::error::{unit_slips, InputError, PressureMeant, UnitSlip, Variable};
use crate::error::{RigPressureAboveAny, MAX_RIG_ARM, MIN_MEDIAN_LOAD, MIN_MEDIAN_PRESSURE};
use std::path::Path;

/// Pressures (Pa) and what they are.
pub(crate) type Known = ([f64; 2], &'static str);

/// The pressures a pneumatic tyre is inflated to, Pa, where the file
/// names no tyre's: a racing slick's 55 kPa (8 psi) to a truck's 900 kPa,
/// rounded outwards. A median that lands here in one of kPa, bar and psi
/// (in that order) is said in it: 83 reads as 83 kPa, 2.2 as 2.2 bar, 30
/// as 30 psi.
pub(crate) const INFLATION: Known = (
    crate::error::INFLATION_PRESSURES,
    "a pneumatic tyre's inflation pressures",
);

/// Refuses every positive pressure of `p` below [`MIN_MEDIAN_PRESSURE`]
/// at its cell of `file` (the points file `path`), each with the reading
/// in kPa, bar or psi that lands among the pressures `known` (of the
/// tyre, else near the column's median). Run once the median has passed.
pub(crate) fn refuse_rows_not_in_pa(
    path: &Path,
    file: &Columns,
    p: &[f64],
    known: Option<Known>,
) -> Result<(), InputError> {
    let errors = rows_not_in_pa(p, known)
        .into_iter()
        .map(|(i, slip)| file.error_at(path, i, "pressure", slip.into()))
        .collect();
    InputError::all_of(path, errors).map_or(Ok(()), Err)
}

/// Every positive pressure of `p` below [`MIN_MEDIAN_PRESSURE`] (its
/// index, 0-based) and why: a value written in kPa, bar or psi among
/// pressures in Pa, with the reading that lands among the pressures
/// `known` (of the tyre, else half to twice the median of `p`). The rule
/// of [`refuse_rows_not_in_pa`], for a caller holding arrays rather than
/// a file (the Python `Tyre.forces`). Run once the median has passed.
pub(crate) fn rows_not_in_pa(p: &[f64], known: Option<Known>) -> Vec<(usize, UnitSlip)> {
    let mut sorted: Vec<f64> = p.iter().copied().filter(|v| *v > 0.0).collect();
    sorted.sort_by(f64::total_cmp);
    let Some(&median) = sorted.get(sorted.len() / 2) else {
        return Vec::new();
    };
    let known = known.unwrap_or(([0.5 * median, 2.0 * median], "half to twice the median"));
    p.iter()
        .enumerate()
        .filter(|(_, v)| **v > 0.0 && **v < MIN_MEDIAN_PRESSURE)
        .map(|(i, &value)| {
            let slip = UnitSlip::PressureRowNotInPa {
                value,
                median,
                limit: MIN_MEDIAN_PRESSURE,
                // Where no unit lands it among the tyre's own pressures (2.2
                // bar is 220 kPa, above an FSAE file's PRESMAX), the unit
                // that lands it among any pneumatic tyre's is still said.
                meant: nearest(value, known, median).or_else(|| meant(value, INFLATION)),
            };
            (i, slip)
        })
        .collect()
}

/// Refuses every pressure of `p` above [`MOST_PRESSURE`] at its cell of
/// `file` (the rig file `path`): no tyre is tested there, and a column
/// written a thousand or a hundred times too large has a median that the
/// unit rule of too small a one passes.
pub(crate) fn refuse_pressures_above_any(
    path: &Path,
    file: &Columns,
    p: &[f64],
) -> Result<(), InputError> {
    let errors = (0..p.len())
        .filter(|&i| p[i] > MOST_PRESSURE)
        .map(|i| {
            let above = RigPressureAboveAny {
                value: p[i],
                limit: MOST_PRESSURE,
            };
            file.error_at(path, i, "pressure", above.into())
        })
        .collect();
    InputError::all_of(path, errors).map_or(Ok(()), Err)
}

/// The reading of `value` in kPa, bar or psi that lands among the
/// pressures `known` nearest (by ratio) the column's `median` where that
/// median is a pressure in Pa, else the first: a cell of 32 among 220000
/// Pa is 32 psi (220.6 kPa), not 32 kPa, which also lands among a .tir's
/// PRESMIN to PRESMAX and was offered first.
fn nearest(value: f64, (among, what): Known, median: f64) -> Option<PressureMeant> {
    if median < MIN_MEDIAN_PRESSURE {
        return meant(value, (among, what));
    }
    unit_slips(Variable::Pressure)
        .iter()
        .map(|&(unit, factor)| (unit, value * factor))
        .filter(|(_, pa)| (among[0]..=among[1]).contains(pa))
        .min_by(|a, b| {
            (a.1 / median)
                .ln()
                .abs()
                .total_cmp(&(b.1 / median).ln().abs())
        })
        .map(|(unit, pa)| PressureMeant {
            pa,
            unit,
            among,
            what,
        })
}

/// The first reading of `value` in kPa, bar or psi that lands among the
/// pressures `known`.
pub(crate) fn meant(value: f64, (among, what): Known) -> Option<PressureMeant> {
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

/// Refuses every load of `fz` below [`MIN_MEDIAN_LOAD`] whose rows on
/// both sides carry at least that (a lone cell among loaded rows, not a
/// ramp from zero) and whose reading in kN lands among the file's loads
/// above it: a load written in kN. Run once the median has passed.
pub(crate) fn refuse_loads_in_kn(
    path: &Path,
    file: &Columns,
    fz: &[f64],
) -> Result<(), InputError> {
    let loaded = fz.iter().copied().filter(|v| *v >= MIN_MEDIAN_LOAD);
    let (lo, hi) = loaded.fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(v), b.max(v)));
    let lone = |i: usize| {
        i > 0 && i + 1 < fz.len() && fz[i - 1] >= MIN_MEDIAN_LOAD && fz[i + 1] >= MIN_MEDIAN_LOAD
    };
    let errors = (0..fz.len())
        .filter(|&i| fz[i] > 0.0 && fz[i] < MIN_MEDIAN_LOAD && lone(i))
        .filter(|&i| (lo..=hi).contains(&(1e3 * fz[i])))
        .map(|i| {
            let slip = UnitSlip::LoadRowInKn {
                value: fz[i],
                neighbours: [fz[i - 1], fz[i + 1]],
                limit: MIN_MEDIAN_LOAD,
            };
            file.error_at(path, i, "fz", slip.into())
        })
        .collect();
    InputError::all_of(path, errors).map_or(Ok(()), Err)
}

/// Refuses every aligning moment of `mz` beyond [`MAX_RIG_ARM`] times its
/// load `fz` (plus a twentieth of the `median` load), at its row: a column
/// in N·mm fitted a tyre of 25 m trail without a word. Run once the loads
/// and moments have passed their own checks.
pub(crate) fn refuse_moments_beyond_any_arm(
    path: &Path,
    file: &Columns,
    mz: &[f64],
    fz: &[f64],
    median: f64,
) -> Result<(), InputError> {
    let arm = |i: usize| mz[i].abs() / (fz[i] + 0.05 * median);
    let errors = (0..mz.len())
        .filter(|&i| fz[i] >= 0.0 && mz[i].is_finite() && arm(i) > MAX_RIG_ARM)
        .map(|i| {
            let slip = UnitSlip::RigMomentAboveLoad {
                value: mz[i],
                fz: fz[i],
                arm: arm(i),
                median,
            };
            file.error_at(path, i, "mz", slip.into())
        })
        .collect();
    InputError::all_of(path, errors).map_or(Ok(()), Err)
}

/// The least share of the median load the `mz` column's 90th percentile
/// must reach to be read as a lateral force: a sweep past
/// [`SWAP_SWEEP`] reaches 0.3–1.8 of the load on any tyre.
const SWAP_FORCE_SHARE: f64 = 0.2;

/// The most share of the median load the `fy` column's 90th percentile
/// may reach to be read as a moment: a pneumatic trail (0.005–0.1 m)
/// times a force within twice the load is below 0.1 of it in N·m per N.
const SWAP_MOMENT_SHARE: f64 = 0.1;

/// The pneumatic trails (m) the `fy` column's size over the `mz` column's
/// must land among: 5 to 150 mm (a car tyre's is 20–60 mm).
const SWAP_TRAILS: [f64; 2] = [0.005, 0.15];

/// The slip angle a sweep must reach for the sizes to be judged, rad
/// (3°: past the linear range, where the force is a share of the load).
const SWAP_SWEEP: f64 = 0.05;

/// Refuses rig data whose `fy` and `mz` columns look exchanged: the `mz`
/// column as large against the load as a lateral force
/// ([`SWAP_FORCE_SHARE`]), the `fy` column as small as a moment
/// ([`SWAP_MOMENT_SHARE`]), and their ratio a pneumatic trail
/// ([`SWAP_TRAILS`]), over a sweep past [`SWAP_SWEEP`]. Said at the `mz`
/// column's largest value, naming both columns: read as a moment in N·mm
/// the `mz` column was asked to be divided by 1000, which leaves a force
/// fitted as a moment and a moment as a force.
pub(crate) fn refuse_swapped_fy_mz(
    path: &Path,
    file: &Columns,
    (alpha, fy): (&[f64], &[f64]),
    mz: &[f64],
    fz: &[f64],
    median: f64,
) -> Result<(), InputError> {
    let rows: Vec<usize> = (0..fz.len())
        .filter(|&i| fz[i] > 0.0 && fy[i].is_finite() && mz[i].is_finite())
        .collect();
    let reach = rows.iter().map(|&i| alpha[i].abs()).fold(0.0, f64::max);
    if rows.is_empty() || reach < SWAP_SWEEP || median <= 0.0 {
        return Ok(());
    }
    let p90 = |v: &[f64]| {
        let mut a: Vec<f64> = rows.iter().map(|&i| v[i].abs()).collect();
        a.sort_by(f64::total_cmp);
        a[(a.len() - 1) * 9 / 10]
    };
    let (fy_p90, mz_p90) = (p90(fy), p90(mz));
    let ratio = fy_p90 / mz_p90.max(f64::MIN_POSITIVE);
    let swapped = mz_p90 >= SWAP_FORCE_SHARE * median
        && fy_p90 <= SWAP_MOMENT_SHARE * median
        && (SWAP_TRAILS[0]..=SWAP_TRAILS[1]).contains(&ratio);
    if !swapped {
        return Ok(());
    }
    let Some(&i) = rows
        .iter()
        .max_by(|&&a, &&b| mz[a].abs().total_cmp(&mz[b].abs()))
    else {
        return Ok(());
    };
    let slip = UnitSlip::RigFyMzSwapped {
        value: mz[i],
        fz: fz[i],
        fy_p90,
        mz_p90,
        ratio,
        fy_column: file.column("fy"),
    };
    Err(file.error_at(path, i, "mz", slip.into()))
}
