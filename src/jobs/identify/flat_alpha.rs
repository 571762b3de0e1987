//! Rig data whose lateral columns carry no lateral slip: a `tyre-eval`
//! output at `alpha = 0` with its `fy` and `mz` columns (a longitudinal
//! sweep at three loads) was fitted as lateral data, three points for
//! PAC89's eleven lateral parameters, and refused, while the same file
//! without those columns fits its longitudinal force. With `alpha` 0
//! throughout (within [`FLAT_ALPHA`]) and longitudinal sweeps present,
//! the lateral columns are set aside, counted in a warning, and the
//! longitudinal force is fitted as from a file without them.
//!
//! Without longitudinal sweeps such a file is refused by every model
//! ([`refuse_flat_lateral`]): a lateral fit there moves nothing from its
//! start (`--model linear` wrote its start stiffness, 50000 N/rad, as
//! fitted; PAC89 wrote a file at σ 100 %).

use crate::error::{Error, FitError};
use crate::identify::data::RigData;
use std::path::Path;

/// The largest |alpha| of a file said to have no lateral slip, rad: the
/// staged fit's bound of a pure longitudinal row (1e-3 rad, 0.057°).
pub(super) const FLAT_ALPHA: f64 = 1e-3;

/// `data` with its lateral columns set aside where `alpha` stays within
/// [`FLAT_ALPHA`] and it has longitudinal sweeps, with the warning that
/// says so; `data` unchanged and `None` otherwise.
pub(super) fn without_flat_lateral(data: RigData) -> (RigData, Option<String>) {
    let flat = data.alpha.iter().all(|a| a.abs() <= FLAT_ALPHA);
    if !flat || !data.has_lateral() {
        return (data, None);
    }
    let Some(view) = data.longitudinal_view() else {
        return (data, None);
    };
    let fy = data.fy.iter().filter(|v| v.is_finite()).count();
    let mz = data
        .mz
        .as_ref()
        .map_or(0, |m| m.iter().filter(|v| v.is_finite()).count());
    let columns = match mz {
        0 => format!("its {fy} values of `fy` are"),
        _ => format!("its {fy} values of `fy` and {mz} of `mz` are"),
    };
    let said = format!(
        "alpha is 0 throughout (|alpha| ≤ {FLAT_ALPHA} rad in all {} rows): no lateral slip to fit, so {columns} not fitted, and the longitudinal force is fitted as from a file without them",
        data.len()
    );
    (view, Some(said))
}

/// Refuses `data` (read from `file`) whose lateral force has no slip angle
/// to be fitted against: `alpha` within [`FLAT_ALPHA`] in every row, and
/// no longitudinal sweep for [`without_flat_lateral`] to fit instead.
pub(super) fn refuse_flat_lateral(data: &RigData, file: &Path) -> Result<(), Error> {
    let flat = data.alpha.iter().all(|a| a.abs() <= FLAT_ALPHA);
    if flat && data.has_lateral() && data.longitudinal.is_none() {
        return Err(FitError::NoSlipAngleInFile {
            data: file.to_path_buf(),
            rows: data.len(),
        }
        .into());
    }
    Ok(())
}
