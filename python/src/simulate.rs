//! Scenario files from Python: `simulate` (the report as JSON, the time
//! history's columns as numpy arrays, SI units and radians), its timing
//! baseline, and the checks and readers `Scenario` builds on
//! (`check_scenario`, `toml_file_json`, `vehicle_from_toml`).

use crate::errors::py_err;
use crate::{detached, json, run_job};
use handling::error::Error;
use handling::io::load_scenario;
use handling::jobs;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;
use std::time::Instant;

/// Simulates a scenario file; `(report JSON, [(column, array)])`, writing
/// the CLI's outputs to `out` when given.
#[pyfunction]
#[pyo3(signature = (scenario, out=None))]
pub(crate) fn simulate<'py>(
    py: Python<'py>,
    scenario: PathBuf,
    out: Option<PathBuf>,
) -> PyResult<(String, Bound<'py, PyDict>)> {
    let r = run_job(
        py,
        out.is_some(),
        || jobs::simulate::run(&scenario, out.as_deref()),
        |r| r.write(),
    )?;
    let text = json(&r)?;
    // The history's columns move into numpy arrays (no copy), named and
    // ordered as `TimeHistory::columns` (history.csv).
    let h = r.history;
    let [fz_fl, fz_fr, fz_rl, fz_rr] = h.fz;
    let mut columns = vec![
        ("t", h.t),
        ("steer", h.steer),
        ("speed", h.speed),
        ("beta", h.beta),
        ("yaw_rate", h.yaw_rate),
        ("ay", h.ay),
        ("alpha_front", h.alpha_front),
        ("alpha_rear", h.alpha_rear),
        ("fy_front", h.fy_front),
        ("fy_rear", h.fy_rear),
        ("fz_fl", fz_fl),
        ("fz_fr", fz_fr),
        ("fz_rl", fz_rl),
        ("fz_rr", fz_rr),
    ];
    if !h.roll.is_empty() {
        columns.push(("roll", h.roll));
    }
    let d = PyDict::new(py);
    for (name, v) in columns {
        d.set_item(name, PyArray1::from_vec(py, v))?;
    }
    Ok((text, d))
}

/// Runs the scenario `n` times in Rust (`jobs::simulate::run`, nothing
/// converted or written) and returns the wall time, s: the baseline of the
/// Python call's overhead.
#[pyfunction]
pub(crate) fn _bench_simulate(py: Python<'_>, scenario: PathBuf, n: usize) -> PyResult<f64> {
    detached(py, || {
        let t0 = Instant::now();
        for _ in 0..n {
            std::hint::black_box(jobs::simulate::run(&scenario, None)?);
        }
        Ok(t0.elapsed().as_secs_f64())
    })
}

/// The `[vehicle]` table of TOML `text`, read and validated as a scenario
/// file's (`path` names the text in errors); JSON of the vehicle (SI).
#[pyfunction]
pub(crate) fn vehicle_from_toml(text: &str, path: PathBuf) -> PyResult<String> {
    let v = handling::io::scenario::vehicle_from_text(&path, text).map_err(|e| py_err(e.into()))?;
    json(&v)
}

/// The tables of a TOML file as JSON text (the file as written: relative
/// paths unresolved), for `Scenario.load` after `check_scenario` has read
/// and validated it with the library's reader.
#[pyfunction]
pub(crate) fn toml_file_json(py: Python<'_>, path: PathBuf) -> PyResult<String> {
    let table: toml::Table = detached(py, || {
        let src = handling::io::TomlSource::read(&path)?;
        src.parse().map_err(Error::from)
    })?;
    json(&table)
}

/// Checks a scenario file (reads and validates it, simulates nothing).
#[pyfunction]
pub(crate) fn check_scenario(py: Python<'_>, scenario: PathBuf) -> PyResult<String> {
    let sc = detached(py, || load_scenario(&scenario).map_err(Error::from))?;
    Ok(sc.name)
}
