//! `handling._handling`: the Python extension module of the `handling`
//! crate. A thin layer: every function calls one public library function
//! (`handling::jobs::*::run`, `Tyre::evaluate_points`, `Study::evaluate`)
//! with the GIL released, and hands back its typed report as JSON text
//! (the Python package parses it into dicts, the CLI's JSON content) and
//! its arrays as numpy arrays. Errors become the exception of their kind
//! (`Error::kind`): `HandlingError` > `InputError` (path, line, column, key,
//! value), `ParamError` (key, value, reason), `PointError` (argument, index,
//! value of a tyre's point), `OptionsError`, `FitError`,
//! `MetricsError`, `DiagnosisError`, `OutputError` (path where the kind has
//! one), read from the error's typed fields, never from its message. SI
//! units and radians throughout.

mod diagnose;
mod errors;
mod identify;
mod metrics;
mod points;
mod ranges;
mod simulate;
mod spelling;
mod sweeps;
mod tyre;

use errors::{
    py_err, DiagnosisError, FitError, HandlingError, InputError, MetricsError, OptionsError,
    OutputError, ParamError, PointError,
};
use handling::error::Error;
use handling::jobs::identify::IdentifyModel;
use handling::tyre::model_names;
use pyo3::prelude::*;
use serde::Serialize;

/// A report as JSON text (serde_json, as the CLI writes it).
fn json<T: Serialize>(r: &T) -> PyResult<String> {
    serde_json::to_string(r).map_err(|e| HandlingError::new_err(format!("report to JSON: {e}")))
}

/// A report as a JSON object, to add keys to.
fn json_value<T: Serialize>(r: &T) -> PyResult<serde_json::Value> {
    serde_json::to_value(r).map_err(|e| HandlingError::new_err(format!("report to JSON: {e}")))
}

/// Runs `f` with the GIL released and converts its error.
fn detached<T: Send>(py: Python<'_>, f: impl FnOnce() -> Result<T, Error> + Send) -> PyResult<T> {
    py.detach(f).map_err(py_err)
}

/// Runs a job with the GIL released and, when asked (`out` given), writes
/// its outputs.
fn run_job<R: Send>(
    py: Python<'_>,
    write: bool,
    run: impl FnOnce() -> Result<R, Error> + Send,
    outputs: impl FnOnce(&R) -> Result<(), Error> + Send,
) -> PyResult<R> {
    detached(py, || {
        let r = run()?;
        if write {
            outputs(&r)?;
        }
        Ok(r)
    })
}

#[pymodule]
fn _handling(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("HandlingError", py.get_type::<HandlingError>())?;
    m.add("InputError", py.get_type::<InputError>())?;
    m.add("ParamError", py.get_type::<ParamError>())?;
    m.add("PointError", py.get_type::<PointError>())?;
    m.add("OptionsError", py.get_type::<OptionsError>())?;
    m.add("FitError", py.get_type::<FitError>())?;
    m.add("MetricsError", py.get_type::<MetricsError>())?;
    m.add("DiagnosisError", py.get_type::<DiagnosisError>())?;
    m.add("OutputError", py.get_type::<OutputError>())?;
    // The angle columns `metrics` reads in degrees: the library's list, so
    // the package checks `degrees=` against the same set as the CLI.
    m.add(
        "METRICS_ANGLES",
        handling::io::AngleColumn::read_by_metrics_names().to_vec(),
    )?;
    m.add_class::<tyre::PyTyre>()?;
    m.add_class::<sweeps::PyStudy>()?;
    m.add_function(wrap_pyfunction!(simulate::simulate, m)?)?;
    m.add_function(wrap_pyfunction!(simulate::_bench_simulate, m)?)?;
    m.add_function(wrap_pyfunction!(spelling::_pythonic, m)?)?;
    m.add_function(wrap_pyfunction!(metrics::metrics, m)?)?;
    m.add_function(wrap_pyfunction!(sweeps::equilibria, m)?)?;
    m.add_function(wrap_pyfunction!(sweeps::run_shard, m)?)?;
    m.add_function(wrap_pyfunction!(sweeps::merge, m)?)?;
    m.add_function(wrap_pyfunction!(sweeps::study, m)?)?;
    m.add_function(wrap_pyfunction!(identify::identify, m)?)?;
    m.add_function(wrap_pyfunction!(diagnose::diagnose, m)?)?;
    m.add_function(wrap_pyfunction!(diagnose::verdict_kinds, m)?)?;
    m.add_function(wrap_pyfunction!(diagnose::synth, m)?)?;
    m.add_function(wrap_pyfunction!(diagnose::design, m)?)?;
    m.add_function(wrap_pyfunction!(simulate::check_scenario, m)?)?;
    m.add_function(wrap_pyfunction!(simulate::toml_file_json, m)?)?;
    m.add_function(wrap_pyfunction!(simulate::vehicle_from_toml, m)?)?;
    // The registry's lists: the `model` keys of tyre files and the models
    // `identify` fits (a model registered in Rust appears in both).
    let names: Vec<&str> = model_names().iter().map(|n| n.as_str()).collect();
    m.add("MODEL_NAMES", names)?;
    m.add("IDENTIFY_MODELS", IdentifyModel::names())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
