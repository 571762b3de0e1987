//! `identify`: a tyre model fitted to rig data (the swarm models, the
//! staged Magic Formula fit), with the command line's options as
//! keywords; the report as JSON and the fitted tyre as a `Tyre`.

use crate::errors::py_err;
use crate::tyre::PyTyre;
use crate::{detached, json};
use handling::io::tir::read_tir_text;
use handling::jobs;
use handling::jobs::identify::{
    check_given, FitOption, IdentifyModel, IdentifyReport, Options, Polish, StartArg,
};
use handling::tyre::Tyre;
use pyo3::prelude::*;
use std::path::PathBuf;

/// Fits a tyre model to rig data; `(report JSON, fitted tyre)`.
#[pyfunction]
#[pyo3(signature = (data, model, seed=None, out=None, pressure=None, camber=None, local=None, bin_deg=0.25, bin_kappa=None, start=None, template=None, max_iterations=None, hold=Vec::new(), load=None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn identify(
    py: Python<'_>,
    data: PathBuf,
    model: &str,
    seed: Option<u64>,
    out: Option<PathBuf>,
    pressure: Option<f64>,
    camber: Option<f64>,
    local: Option<&str>,
    bin_deg: f64,
    bin_kappa: Option<f64>,
    start: Option<&str>,
    template: Option<PathBuf>,
    max_iterations: Option<usize>,
    hold: Vec<(String, f64)>,
    load: Option<f64>,
) -> PyResult<(String, PyTyre)> {
    let model: IdentifyModel = model.parse().map_err(py_err)?;
    // The keywords given (not None) that only some fits read: refused by
    // the command line's table when the model's fit would ignore them.
    let given = [
        (FitOption::Seed, seed.is_some()),
        (FitOption::Load, load.is_some()),
        (FitOption::Pressure, pressure.is_some()),
        (FitOption::Camber, camber.is_some()),
        (FitOption::Local, local.is_some()),
        (FitOption::BinKappa, bin_kappa.is_some()),
        (FitOption::Start, start.is_some()),
        (FitOption::Template, template.is_some()),
        (FitOption::MaxIterations, max_iterations.is_some()),
    ];
    let given: Vec<FitOption> = given.iter().filter(|g| g.1).map(|g| g.0).collect();
    check_given(model, &given).map_err(py_err)?;
    let local: Polish = local.unwrap_or("lm").parse().map_err(py_err)?;
    let start: StartArg = start.unwrap_or("data").parse().map_err(py_err)?;
    let write = out.is_some();
    let o = Options {
        data,
        model,
        seed: seed.unwrap_or(1),
        out,
        load,
        pressure,
        camber,
        local,
        alpha_bin_deg: bin_deg,
        kappa_bin: bin_kappa.unwrap_or(0.0025),
        start,
        template,
        max_iterations,
        hold,
    };
    let (r, tyre) = detached(py, || {
        let r = jobs::identify::run(&o)?;
        if write {
            r.write()?;
        }
        let tyre = match &r {
            IdentifyReport::Swarm(s) => s.tyre.clone(),
            IdentifyReport::Staged(s) => {
                Tyre::MagicFormula(Box::new(read_tir_text("identified.tir", &s.tir)?))
            }
        };
        Ok((r, tyre))
    })?;
    Ok((json(&r)?, PyTyre { tyre }))
}
