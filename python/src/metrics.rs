//! `metrics`: step-steer metrics of a measured run file (ISO 7401), with
//! the command line's settings as keywords and its `--degrees` as
//! `degrees=`; the report as JSON. SI units and radians.

use crate::{detached, json};
use handling::jobs;
use handling::metrics::MetricSettings;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use std::path::PathBuf;

/// The angle columns `metrics` reads in degrees (its CLI's `--degrees`
/// takes these alone).
pub(crate) const METRICS_ANGLES: [&str; 4] = ["steer", "yaw_rate", "beta", "roll"];

/// `degrees`' names as the run's angle columns (the package refuses any
/// other name first, as an `OptionsError` with `name` and `known`).
pub(crate) fn angle_columns(degrees: &[String]) -> PyResult<Vec<handling::io::AngleColumn>> {
    degrees
        .iter()
        .map(|d| {
            handling::io::AngleColumn::from_name(d.trim())
                .filter(|c| METRICS_ANGLES.contains(&c.name()))
                .ok_or_else(|| {
                    PyValueError::new_err(format!(
                        "metrics: `{d}` is not an angle column metrics reads: one of {}",
                        METRICS_ANGLES.join(", ")
                    ))
                })
        })
        .collect()
}

/// Step-steer metrics of a measured run (`degrees`: its columns in
/// degrees, deg/s for the yaw rate, as `metrics --degrees`); report JSON.
#[pyfunction]
#[pyo3(signature = (run, pre_window=0.5, steady_window=1.0, min_speed=5.0, filter_hz=handling::metrics::MEASURED_FILTER_HZ, variance_window=4.0, min_overshoot=handling::metrics::DEFAULT_MIN_OVERSHOOT, degrees=Vec::new()))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn metrics(
    py: Python<'_>,
    run: PathBuf,
    pre_window: f64,
    steady_window: f64,
    min_speed: f64,
    filter_hz: f64,
    variance_window: f64,
    min_overshoot: f64,
    degrees: Vec<String>,
) -> PyResult<String> {
    let degrees = angle_columns(&degrees)?;
    let settings = MetricSettings {
        pre_window,
        steady_window,
        variance_window,
        filter_hz: (filter_hz > 0.0).then_some(filter_hz),
        min_overshoot,
        ..MetricSettings::default()
    };
    let r = detached(py, || {
        jobs::metrics::run_with_degrees(&run, &settings, min_speed, &degrees)
    })?;
    json(&r)
}
