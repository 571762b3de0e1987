//! Equilibria sweeps and stiffness studies from Python: the whole run,
//! one shard of it and the merge of shards (`handling equilibria`,
//! `study`, `--shard`, `merge`), and `Study`, whose (front, rear)
//! cornering-stiffness pairs (N/rad per tyre) are simulated one at a time
//! (Wang & Liang). Reports as JSON.

use crate::errors::py_err;
use crate::{detached, json, json_value, run_job, HandlingError};
use handling::error::Error;
use handling::jobs;
use handling::jobs::shard::{shard_job, FileJob, Shard, ShardJob};
use handling::study::{Sample, StiffnessUnit, Study};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use std::path::PathBuf;

/// K of N, checked (1 ≤ K ≤ N): outside it, the library's `OptionsError`
/// (a `HandlingError`, as the book says every error is), naming K/N and
/// carrying `index` and `count`; a plain `ValueError` said neither.
pub(crate) fn shard(index: usize, count: usize) -> PyResult<Shard> {
    Shard::new(index, count).map_err(py_err)
}

/// A stiffness study's model: one (front, rear) cornering-stiffness pair
/// simulated at a time (Wang & Liang), as `handling study` does for each.
#[pyclass(name = "Study", module = "handling._handling", frozen)]
pub(crate) struct PyStudy {
    path: PathBuf,
    study: Study,
    front: Vec<f64>,
    rear: Vec<f64>,
}

#[pymethods]
impl PyStudy {
    /// Loads a study file.
    #[staticmethod]
    fn load(py: Python<'_>, path: PathBuf) -> PyResult<Self> {
        let input = detached(py, || {
            handling::io::study::load_study(&path).map_err(Error::from)
        })?;
        let sc = &input.scenario;
        // The absolute path, so that a pickled study reloads in a worker
        // whose working directory differs (errors above name it as given).
        let path = std::path::absolute(&path).unwrap_or(path);
        Ok(Self {
            study: Study {
                model: sc.model.clone(),
                manoeuvre: sc.manoeuvre.clone(),
                integrator: sc.integrator,
                metrics: sc.metrics,
            },
            front: input.front.clone(),
            rear: input.rear.clone(),
            path,
        })
    }

    /// The file it was loaded from, absolute.
    #[getter]
    fn path(&self) -> PathBuf {
        self.path.clone()
    }

    /// The map's front stiffness values per tyre, N/rad.
    #[getter]
    fn front<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.front)
    }

    /// The map's rear stiffness values per tyre, N/rad.
    #[getter]
    fn rear<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.rear)
    }

    /// Simulates the pairs (per tyre, in `unit`: `N/deg` or `N/rad`), each
    /// value checked as a study file's; JSON list of samples as study.csv
    /// reports them (response, note, metrics of a handling response).
    fn evaluate_json(
        &self,
        py: Python<'_>,
        k_front: PyReadonlyArray1<'_, f64>,
        k_rear: PyReadonlyArray1<'_, f64>,
        unit: &str,
    ) -> PyResult<String> {
        let (f, r) = (k_front.as_slice()?, k_rear.as_slice()?);
        if f.len() != r.len() {
            return Err(PyValueError::new_err(
                "k_front and k_rear must have the same length",
            ));
        }
        let unit: StiffnessUnit = unit.parse().map_err(|e| py_err(Error::from(e)))?;
        let pairs: Vec<(f64, f64)> = f.iter().copied().zip(r.iter().copied()).collect();
        let st = &self.study;
        let samples = detached(py, || st.evaluate_in(&pairs, unit).map_err(Error::from))?;
        json(&samples.iter().map(Sample::reported).collect::<Vec<_>>())
    }

    fn __repr__(&self) -> String {
        format!("Study({:?})", self.path.display().to_string())
    }

    /// Pickles as its file path (reloaded where it is unpickled).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let ctor = slf.get_type().getattr("load")?;
        let args = PyTuple::new(py, [slf.get().path.clone()])?;
        PyTuple::new(py, [ctor.into_any(), args.into_any()])
    }
}

/// Steering equilibria over a sweep file; report JSON (`summary.json`'s content).
#[pyfunction]
#[pyo3(signature = (sweep, out=None))]
pub(crate) fn equilibria(py: Python<'_>, sweep: PathBuf, out: Option<PathBuf>) -> PyResult<String> {
    let r = run_job(
        py,
        out.is_some(),
        || jobs::equilibria::run(&sweep, out.as_deref()),
        |r| r.write(),
    )?;
    json(&r)
}

/// Shard `index` of `count` of an equilibria sweep or a study, written to
/// `out/shard-K-of-N.json`; report JSON.
#[pyfunction]
#[pyo3(signature = (job, path, index, count, out=None))]
pub(crate) fn run_shard(
    py: Python<'_>,
    job: &str,
    path: PathBuf,
    index: usize,
    count: usize,
    out: Option<PathBuf>,
) -> PyResult<String> {
    let s = shard(index, count)?;
    let r = match job.parse::<FileJob>().map_err(py_err)? {
        FileJob::Equilibria => {
            detached(py, || jobs::equilibria::run_shard(&path, s, out.as_deref()))?
        }
        FileJob::Study => detached(py, || jobs::study::run_shard(&path, s, out.as_deref()))?,
    };
    json(&r)
}

/// Merges shard files into the unsharded run's outputs (written to `out`,
/// default `out/<name>`); report JSON.
#[pyfunction]
#[pyo3(signature = (shards, out=None))]
pub(crate) fn merge(
    py: Python<'_>,
    shards: Vec<PathBuf>,
    out: Option<PathBuf>,
) -> PyResult<String> {
    let first = shards
        .first()
        .ok_or_else(|| py_err(Error::from(handling::error::OptionsError::NoShards)))?
        .clone();
    detached(py, || match shard_job(&first)? {
        ShardJob::Equilibria => {
            let r = jobs::equilibria::merge(&shards, out.as_deref())?;
            r.write()?;
            Ok(serde_json::to_string(&r))
        }
        ShardJob::Study => {
            let r = jobs::study::merge(&shards, out.as_deref())?;
            r.write()?;
            Ok(serde_json::to_string(&r))
        }
        // The fleet table is written by the merge itself.
        ShardJob::Diagnose => {
            let r = jobs::fleet::merge(&shards, out.as_deref())?;
            Ok(serde_json::to_string(&r))
        }
    })?
    .map_err(|e| HandlingError::new_err(format!("report to JSON: {e}")))
}

/// Cornering stiffness against handling; report JSON with the map's
/// samples added (`samples`, N/rad).
#[pyfunction]
#[pyo3(signature = (study_file, out=None))]
pub(crate) fn study(py: Python<'_>, study_file: PathBuf, out: Option<PathBuf>) -> PyResult<String> {
    let r = run_job(
        py,
        out.is_some(),
        || jobs::study::run(&study_file, out.as_deref()),
        |r| r.write(),
    )?;
    let mut v = json_value(&r)?;
    if let Some(o) = v.as_object_mut() {
        let samples: Vec<_> = r.samples.iter().map(Sample::reported).collect();
        o.insert("samples".into(), json_value(&samples)?);
    }
    json(&v)
}
