//! Tyre rig files (`docs/FORMATS.md`): a CSV with the load `fz` and a
//! lateral sweep (`alpha`, `fy`, optionally `mz`), a longitudinal sweep
//! (`kappa`, `fx`) or both, plus optional `camber`, `pressure` and `speed`.
//! Read into [`RigData`] with every error located in the file; the data's
//! sense is checked here (positive loads, angles in radians).
//!
//! Units: N, N·m, rad, Pa, m/s; slip ratio dimensionless. Signs as in
//! `tyre/mod.rs` (a positive slip angle gives a positive `fy`).

use super::read_columns;
use crate::error::InputError;
use crate::identify::data::RigData;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};
use std::path::Path;

/// Reads rig data: lateral (`alpha`, `fy`) and/or longitudinal (`kappa`,
/// `fx`) sweeps; a file with neither pair is refused.
pub fn read_rig(path: &Path) -> Result<RigData, InputError> {
    let mut c = read_columns(
        path,
        &["fz"],
        &[
            "alpha", "fy", "mz", "camber", "pressure", "speed", "kappa", "fx",
        ],
    )?;
    let fz = c.take("fz");
    for (i, v) in fz.iter().enumerate() {
        if *v < 0.0 {
            return Err(c.error_at(
                path,
                i,
                "fz",
                format!("column `fz`: {v} N is negative (loads are positive in FORMATS.md)"),
            ));
        }
    }
    let n = fz.len();
    let lateral = match (c.take_optional("alpha"), c.take_optional("fy")) {
        (Some(a), Some(f)) => Some((a, f)),
        _ => None,
    };
    let longitudinal = match (c.take_optional("kappa"), c.take_optional("fx")) {
        (Some(k), Some(f)) => Some((k, f)),
        _ => None,
    };
    if lateral.is_none() && longitudinal.is_none() {
        return Err(InputError::File {
            path: path.to_path_buf(),
            message: "no lateral data (columns `alpha` and `fy`) and no longitudinal data (`kappa` and `fx`)".into(),
        });
    }
    let camber = c.take_optional("camber");
    // Angles in degrees are the commonest slip of a hand-made file: a slip
    // angle past ±90° or a camber past ±45° is not a tyre test in radians.
    let angles = [
        ("alpha", lateral.as_ref().map(|l| &l.0), FRAC_PI_2),
        ("camber", camber.as_ref(), FRAC_PI_4),
    ];
    for (name, values, limit) in angles {
        let Some(values) = values else { continue };
        if let Some(i) = values.iter().position(|v| v.abs() > limit) {
            return Err(c.error_at(
                path,
                i,
                name,
                format!(
                    "column `{name}`: {} rad is beyond ±{:.0}°: angles are in radians (FORMATS.md); is the column in degrees?",
                    values[i],
                    limit.to_degrees()
                ),
            ));
        }
    }
    let (alpha, fy) = lateral.unwrap_or_else(|| (vec![0.0; n], vec![f64::NAN; n]));
    Ok(RigData {
        camber_measured: camber.is_some(),
        camber: camber.unwrap_or_else(|| vec![0.0; n]),
        mz: c.take_optional("mz"),
        pressure: c.take_optional("pressure"),
        speed: c.take_optional("speed"),
        longitudinal,
        fz,
        alpha,
        fy,
    })
}

/// Reads rig data and refuses a file without lateral data.
pub fn read_lateral(path: &Path) -> Result<RigData, InputError> {
    let d = read_rig(path)?;
    if d.fy.iter().all(|v| v.is_nan()) {
        return Err(InputError::File {
            path: path.to_path_buf(),
            message: "no lateral data: a lateral fit needs the columns `alpha` and `fy`".into(),
        });
    }
    Ok(d)
}
