//! The points file of `tyre-eval`, read and checked before anything is
//! evaluated: its five input columns and optional `pressure`, every value
//! no tyre is evaluated at refused at its cell in one run (`physical.rs`),
//! a pressure not in Pa (each implausible cell with the unit it likely
//! reads in: `pressure.rs`), loads in kN, a slip angle in degrees
//! (`other_unit.rs`) and a column beside an input
//! stating its own unit that disagrees with it (`beside.rs`).

use super::{physical, pressure};
use crate::error::{Error, InputProblem};
use crate::io::rig::load_in_kn;
use std::path::Path;

/// The points file's columns, checked: `fz, kappa, alpha, camber,
/// speed` in that order, the pressures where given, and the file's
/// columns for errors found later.
pub(super) struct PointColumns {
    pub(super) file: crate::io::Columns,
    pub(super) inputs: Vec<(&'static str, Vec<f64>)>,
    pub(super) pressure: Option<Vec<f64>>,
    /// The measured outputs the file carries (`fx`, `fy`, `mz`, `mx`,
    /// `my`), in that order, kept beside the model's (`measured.rs`).
    pub(super) measured: Vec<(&'static str, Vec<f64>)>,
}

/// Reads the points of `points`, refusing a value no tyre is evaluated
/// at (every one, in row order), a pressure not positive or not in Pa
/// (a row's read against the pressures `known` of the tyre) and loads in
/// kN, each at its cell.
pub(super) fn read_points(
    points: &Path,
    known: Option<pressure::Known>,
) -> Result<PointColumns, Error> {
    // The cells that are no finite numbers are said with the values no
    // tyre is evaluated at, in one run.
    let layout = crate::io::Layout {
        required: &["fz", "kappa", "alpha", "camber", "speed"],
        optional: &["pressure", "fx", "fy", "mz", "mx", "my"],
        also_read: Some(&[]),
    };
    // A rig file given as points is said as one (not column by column).
    let (mut c, bad_cells) =
        crate::io::read_columns_with_bad_cells(points, layout).map_err(|e| {
            crate::io::file_kind::rig_as_points(
                points,
                &["fz", "kappa", "alpha", "camber", "speed"],
            )
            .unwrap_or(e)
        })?;
    let pressure = c.take_optional("pressure");
    let measured = super::measured::MEASURED
        .into_iter()
        .filter_map(|n| c.take_optional(n).map(|v| (n, v)))
        .collect();
    let inputs: Vec<(&'static str, Vec<f64>)> = ["fz", "kappa", "alpha", "camber", "speed"]
        .into_iter()
        .map(|n| (n, c.take(n)))
        .collect();
    // A column whose header states its SI unit, or beside which a column
    // stating its own unit agrees on every row, is read as written.
    let besides = super::beside::check(points, &c, &inputs);
    let mut stated: Vec<&str> = c.stated_si.iter().map(String::as_str).collect();
    stated.extend(besides.confirmed.iter().copied());
    let mut errors = not_physical(points, &c, &inputs, (pressure.as_deref(), &stated));
    let other = super::other_unit::refusals(&inputs, &stated, physical::range_of).into_iter();
    errors.extend(other.map(|(i, name, p)| c.error_at(points, i, name, p)));
    errors.extend(besides.refused);
    errors.extend(bad_cells);
    // Pressures in another unit are said with the rest, in one run: a
    // file with 2.6, 260 and -1 was refused at -1 alone, and at the two
    // others only once it was mended.
    errors.extend(pressure_units(points, &c, pressure.as_deref(), known));
    // A car's loads written in kN (the points off the road do not count),
    // said with the rest: loads in kN beside pressures in bar were said
    // one at a time (round 48).
    if let Some((i, slip)) = load_in_kn(&inputs[0].1, |fz| fz > 0.0) {
        errors.push(c.error_at(points, i, "fz", slip.into()));
    }
    if let Some(e) = crate::error::InputError::all_in_file_order(points, errors) {
        return Err(e.into());
    }
    Ok(PointColumns {
        file: c,
        inputs,
        pressure,
        measured,
    })
}

/// Every point no tyre is evaluated at (`physical.rs`), in row order
/// (then column), each as the error at its cell of `c` (read from
/// `points`): the five `inputs` and the `pressure` where given, a
/// pressure at or below zero said as such, with the rest; the columns
/// `stated` in SI not asked as in degrees.
fn not_physical(
    points: &Path,
    c: &crate::io::Columns,
    inputs: &[(&'static str, Vec<f64>)],
    (pressure, stated): (Option<&[f64]>, &[&str]),
) -> Vec<crate::error::InputError> {
    let given = inputs
        .iter()
        .map(|(n, v)| (*n, &v[..]))
        .chain(pressure.map(|p| ("pressure", p)));
    let mut refused: Vec<(usize, usize, &str, InputProblem)> = given
        .enumerate()
        .flat_map(|(k, (name, values))| {
            physical::not_physical(name, values, stated.contains(&name))
                .into_iter()
                .map(move |(i, problem)| (i, k, name, problem))
        })
        .collect();
    if let Some(p) = pressure {
        refused.retain(|(i, _, name, _)| *name != "pressure" || p[*i] > 0.0);
        refused.extend(
            p.iter()
                .enumerate()
                .filter(|(_, v)| v.is_finite() && **v <= 0.0)
                .map(|(i, &value)| {
                    (
                        i,
                        5,
                        "pressure",
                        InputProblem::NonPositivePressure { value },
                    )
                }),
        );
    }
    refused
        .into_iter()
        .map(|(i, _, name, problem)| c.error_at(points, i, name, problem))
        .collect()
}

/// Every `pressure` written in kPa, bar or psi (a .tir clamps it to its
/// range without a word of the unit), read against the pressures `known`
/// of the tyre, as errors at their cells. One unit for the whole column is
/// said once, by its median; cells in different units (2.2 in bar beside
/// 220 in kPa) each with its own. Only the positive pressures within the
/// physical range are read so: the others are refused as such
/// ([`not_physical`]), and their indices are mapped back to the file's.
fn pressure_units(
    points: &Path,
    c: &crate::io::Columns,
    pressure: Option<&[f64]>,
    known: Option<pressure::Known>,
) -> Vec<crate::error::InputError> {
    let Some(p) = pressure else {
        return Vec::new();
    };
    let kept: Vec<usize> = (0..p.len())
        .filter(|&i| p[i].is_finite() && p[i] > 0.0 && p[i] <= crate::constants::MOST_PRESSURE)
        .collect();
    let values: Vec<f64> = kept.iter().map(|&i| p[i]).collect();
    pressure::not_in_pa(&values, known)
        .into_iter()
        .map(|(k, slip)| c.error_at(points, kept[k], "pressure", slip.into()))
        .collect()
}
