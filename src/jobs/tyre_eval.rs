//! `tyre-eval` as one job: a tyre file (.tir or .toml) and a CSV of points
//! (`fz, kappa, alpha, camber, speed` and optionally `pressure`; SI, rad,
//! Pa) in; the same points with `fx, fy, mz` (and `mx, my` for the Magic
//! Formula) out.

use crate::error::Error;
use crate::io::{load_tyre, read_columns};
use crate::report::{refuse_overwrite, write_columns};
use crate::tyre::PointForces;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// The report of `tyre-eval`: the points with their forces and moments.
#[derive(Debug, Clone, Serialize)]
pub struct TyreEvalReport {
    /// The points file.
    pub points: String,
    /// Points evaluated.
    pub count: usize,
    /// The tyre model.
    pub model: &'static str,
    /// Output columns, named, in file order.
    #[serde(skip)]
    pub columns: Vec<(&'static str, Vec<f64>)>,
    /// The output file.
    #[serde(skip)]
    pub out: PathBuf,
}

/// Evaluates the tyre of `tyre_path` at the points of `points`, for the
/// output file `out` (never one of the inputs).
pub fn run(tyre_path: &Path, points: &Path, out: &Path) -> Result<TyreEvalReport, Error> {
    refuse_overwrite(out, &[tyre_path.to_path_buf(), points.to_path_buf()])?;
    let tyre = load_tyre(tyre_path)?;
    let mut c = read_columns(
        points,
        &["fz", "kappa", "alpha", "camber", "speed"],
        &["pressure"],
    )?;
    let pressure = c.take_optional("pressure");
    if let Some(p) = &pressure {
        if let Some(i) = p.iter().position(|v| *v <= 0.0) {
            return Err(c
                .error_at(
                    points,
                    i,
                    "pressure",
                    crate::error::InputProblem::NonPositivePressure { value: p[i] },
                )
                .into());
        }
    }
    let mut columns: Vec<(&'static str, Vec<f64>)> = ["fz", "kappa", "alpha", "camber", "speed"]
        .into_iter()
        .map(|n| (n, c.take(n)))
        .collect();
    let f = {
        let col = |i: usize| &columns[i].1;
        let p = pressure.clone().unwrap_or_default();
        tyre.evaluate_points(col(0), col(1), col(2), col(3), col(4), &p)
    };
    let count = columns[0].1.len();
    if let Some(p) = pressure {
        columns.push(("pressure", p));
    }
    let of = |g: fn(&PointForces) -> f64| f.iter().map(g).collect::<Vec<_>>();
    columns.extend([
        ("fx", of(|x| x.fx)),
        ("fy", of(|x| x.fy)),
        ("mz", of(|x| x.mz)),
    ]);
    if tyre.has_wheel_moments() {
        columns.push(("mx", of(|x| x.mx.unwrap_or(f64::NAN))));
        columns.push(("my", of(|x| x.my.unwrap_or(f64::NAN))));
    }
    Ok(TyreEvalReport {
        points: points.display().to_string(),
        count,
        model: tyre.model_name(),
        columns,
        out: out.to_path_buf(),
    })
}

impl TyreEvalReport {
    /// Writes the output CSV.
    pub fn write(&self) -> Result<(), Error> {
        let cols: Vec<(&str, &[f64])> = self.columns.iter().map(|(n, v)| (*n, &v[..])).collect();
        write_columns(&self.out, &cols)
    }

    /// The closing line.
    pub fn wrote(&self) -> String {
        format!(
            "{} points of {} ({} tyre) evaluated; wrote {}",
            self.count,
            self.points,
            self.model,
            self.out.display()
        )
    }
}
