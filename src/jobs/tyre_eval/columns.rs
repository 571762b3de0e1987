//! `tyre-eval`'s output columns: the points' inputs as read, then the
//! model's forces and moments (N, N·m), the wheel moments of a model that
//! has them and a Magic Formula's loaded radius (m); a point whose output is
//! not finite is refused at its row; the points file's other columns are
//! named as not written. Units: SI, as the points file's header states.

use super::checks;
use crate::error::{Error, InputProblem};
use crate::tyre::{PointForces, Tyre};
use std::path::Path;

/// What the columns are made of: the inputs (the five read first, in
/// order fz, kappa, alpha, camber, speed), the pressure where given, the
/// model's outputs at each point, a loaded radius where the model has one.
pub(super) struct Outputs<'a> {
    pub(super) inputs: Vec<(&'static str, Vec<f64>)>,
    pub(super) pressure: Option<Vec<f64>>,
    pub(super) forces: &'a [PointForces],
    pub(super) loaded_radius: Option<Vec<f64>>,
    pub(super) measured: Vec<(&'static str, Vec<f64>)>,
}

/// The columns written, in order: inputs, pressure, fx, fy, mz, then mx
/// and my (a model with wheel moments), then rl; with measured outputs
/// in the points file, those after the pressure under their own names and
/// the model's named `fx_model`, … (`measured.rs`).
pub(super) fn columns(tyre: &Tyre, o: Outputs) -> Vec<(&'static str, Vec<f64>)> {
    let mut columns = o.inputs;
    columns.extend(o.pressure.map(|p| ("pressure", p)));
    let renamed = !o.measured.is_empty();
    let first_model = columns.len() + o.measured.len();
    columns.extend(o.measured);
    let of = |g: fn(&PointForces) -> f64| o.forces.iter().map(g).collect::<Vec<_>>();
    columns.extend([
        ("fx", of(|x| x.fx)),
        ("fy", of(|x| x.fy)),
        ("mz", of(|x| x.mz)),
    ]);
    if tyre.has_wheel_moments() {
        columns.push(("mx", of(|x| x.mx.unwrap_or(f64::NAN))));
        let my = of(|x| x.my.unwrap_or(f64::NAN));
        columns.push(("my", checks::resolved_my(tyre, &columns[0].1, my)));
    }
    columns.extend(o.loaded_radius.map(|rl| ("rl", rl)));
    if renamed {
        for (name, _) in &mut columns[first_model..] {
            *name = super::measured::model_name(name);
        }
    }
    columns
}

/// The points file's other columns (a label, a measured force): not
/// evaluated and not written, named rather than dropped silently.
pub(super) fn not_written(
    file: &crate::io::Columns,
    columns: &[(&'static str, Vec<f64>)],
) -> Vec<String> {
    file.header
        .iter()
        .map(|h| h.trim().to_string())
        .filter(|h| !h.is_empty() && !columns.iter().any(|(n, _)| n == h))
        .collect()
}

/// Refuses the points where the model gave a non-finite output (`columns`
/// past the five inputs), at the point's row and the load's column.
pub(super) fn refuse_non_finite(
    points: &Path,
    file: &crate::io::Columns,
    columns: &[(&'static str, Vec<f64>)],
    model: &'static str,
) -> Result<(), Error> {
    let mut bad: Vec<(usize, &str)> = columns
        .iter()
        .skip(5)
        .flat_map(|(output, values)| {
            let rows = values.iter().enumerate().filter(|(_, v)| !v.is_finite());
            rows.map(move |(i, _)| (i, *output))
        })
        .collect();
    bad.sort_by_key(|(i, _)| *i);
    bad.dedup_by_key(|(i, _)| *i);
    let errors = bad
        .into_iter()
        .map(|(i, output)| {
            // A positive load whose square underflows is the cause, said.
            let fz = columns[0].1[i];
            let tiny_load = (fz > 0.0 && fz * fz < f64::MIN_POSITIVE).then_some(fz);
            let problem = InputProblem::NonFiniteOutput {
                model,
                output,
                tiny_load,
            };
            file.error_at(points, i, "fz", problem)
        })
        .collect();
    match crate::error::InputError::all_of(points, errors) {
        Some(e) => Err(e.into()),
        None => Ok(()),
    }
}
