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

mod ranges;
mod spelling;
use handling::error::{
    DiagnosisError as LibDiagnosisError, Error, FitError as LibFitError,
    InputError as LibInputError, InputProblem, OptionsError as LibOptionsError, UnitSlip,
};
use handling::io::tir::{read_tir_text, set_tyre_mode};
use handling::io::{load_scenario, load_tyre};
use handling::jobs;
use handling::jobs::identify::{IdentifyModel, IdentifyReport, Options, Polish, StartArg};
use handling::jobs::shard::{shard_job, FileJob, Shard, ShardJob};
use handling::jobs::synth::{truth_named, EffectName};
use handling::metrics::MetricSettings;
use handling::study::{Sample, StiffnessUnit, Study};
use handling::tyre::{model_names, Tyre, TyreModel};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use pyo3::IntoPyObjectExt;
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::time::Instant;

mod points;

create_exception!(
    handling,
    HandlingError,
    PyException,
    "Any failure of the handling library (its one `Error` type); `kind` names the group."
);
create_exception!(
    handling,
    InputError,
    HandlingError,
    "An input file that cannot be read or holds wrong content: `path`, and `line`, `column` (1-based) where known; `key` and `value` for a wrong value (a CSV cell: the column's name and the cell's text); `problem`: the name of what is wrong with the content, where typed."
);
create_exception!(
    handling,
    PointError,
    HandlingError,
    "A point no tyre is evaluated at (`tyre-eval` refuses it in a points file): `argument` (`fz`, `kappa`, `alpha`, `camber`, `speed`, `pressure`), `index` (0-based, in the flattened broadcast arrays), `value`, `reason`, `problem` (the name of what is wrong, None for a NaN or infinity) of the first; `refused`: every one as (argument, index, value)."
);
create_exception!(
    handling,
    ParamError,
    HandlingError,
    "A parameter value that is not physical: `key` (dotted), `value` (a number or None), `reason`."
);
create_exception!(
    handling,
    OptionsError,
    HandlingError,
    "Options that name nothing known or contradict each other: `name`, `known` for an unknown name; `path` where a file is named."
);
create_exception!(
    handling,
    FitError,
    HandlingError,
    "A fit that cannot be made or failed: `path` of the data where known."
);
create_exception!(
    handling,
    MetricsError,
    HandlingError,
    "Step-steer metrics that cannot be computed from a response."
);
create_exception!(
    handling,
    DiagnosisError,
    HandlingError,
    "A diagnosis that could not be made: `path` of the input where known."
);
create_exception!(
    handling,
    OutputError,
    HandlingError,
    "An output that may not or could not be written: `path`."
);

/// An attribute value for Python.
fn py_obj<'py, T: IntoPyObject<'py>>(py: Python<'py>, x: T) -> Py<PyAny> {
    x.into_py_any(py).unwrap_or_else(|_| py.None())
}

/// The key (the column or dotted key named) and the value (the number
/// read) of an input problem, where it has them.
fn problem_key_value(p: &InputProblem) -> (Option<&str>, Option<f64>) {
    match p {
        InputProblem::MissingFile { key, .. } => (Some(key), None),
        InputProblem::TirStringUnclosed { key, .. }
        | InputProblem::TirNoValue { key }
        | InputProblem::TirNotANumber { key, .. } => (Some(key), None),
        InputProblem::TirNotFinite { key, value } => (Some(key), Some(*value)),
        InputProblem::TirUnknownUnit { key, .. } => (Some(key), None),
        InputProblem::TirMissingKey { key } => (Some(key), None),
        InputProblem::TirValue(e) => (Some(&e.key), e.value.number()),
        InputProblem::TimeNotIncreasing { value, .. } => (Some("t"), Some(*value)),
        InputProblem::SteerBeyondQuarterTurn { value, .. } => (Some("steer"), Some(*value)),
        InputProblem::NegativeLoad { value, .. } => (Some("fz"), Some(*value)),
        InputProblem::NonPositivePressure { value } => (Some("pressure"), Some(*value)),
        InputProblem::AngleInDegrees { column, value, .. } => (Some(column), Some(*value)),
        InputProblem::WrongSign { channel, slope, .. } => {
            (Some(channel.column()), Some(slope.slope))
        }
        InputProblem::NoLevelNear {
            variable,
            requested,
            ..
        } => (Some(variable.column()), Some(*requested)),
        InputProblem::NoCamberColumn { camber } => (Some("camber"), Some(*camber)),
        InputProblem::NegativeSpeed { value } => (Some("speed"), Some(*value)),
        InputProblem::NotPhysical { column, value, .. } => (Some(column), Some(*value)),
        InputProblem::NonFiniteOutput { output, .. } => (Some(output), None),
        InputProblem::LoadNotCarried { fz, .. } => (Some("fz"), Some(*fz)),
        InputProblem::DeadChannel { channel, value, .. } => (Some(channel), Some(*value)),
        InputProblem::DeadSteer { value, .. } => (Some("steer"), Some(*value)),
        InputProblem::UnitSlip(u) => unit_slip_key_value(u),
        _ => (None, None),
    }
}

/// The column and the value read of a column in another unit than
/// FORMATS.md's: a run's channel (yaw rate in deg/s, `ay` in g, a speed in
/// km/h, …), a rig's or tyre-eval's load in kN or pressure in kPa, a rig
/// force no tyre carries. `TimeStep`'s value is the median step.
fn unit_slip_key_value(u: &UnitSlip) -> (Option<&str>, Option<f64>) {
    match u {
        UnitSlip::YawRate { value, .. }
        | UnitSlip::YawRateInDegPerS { value, .. }
        | UnitSlip::YawRateTooSmall { value, .. } => (Some("yaw_rate"), Some(*value)),
        UnitSlip::AyTooLarge { value, .. } | UnitSlip::AyInG { value, .. } => {
            (Some("ay"), Some(*value))
        }
        UnitSlip::TimeStep { step, .. } => (Some("t"), Some(*step)),
        UnitSlip::LoadInKn { value, .. } | UnitSlip::LoadRowInKn { value, .. } => {
            (Some("fz"), Some(*value))
        }
        UnitSlip::PressureNotInPa { value, .. } | UnitSlip::PressureRowNotInPa { value, .. } => {
            (Some("pressure"), Some(*value))
        }
        UnitSlip::SpeedBeyondAnyCar { value, .. }
        | UnitSlip::SpeedPerHour { value, .. }
        | UnitSlip::SpeedBackwards { value, .. } => (Some("speed"), Some(*value)),
        UnitSlip::BetaInDegrees { value, .. } | UnitSlip::BetaDeclaredInDegrees { value, .. } => {
            (Some("beta"), Some(*value))
        }
        UnitSlip::RollInDegrees { column, value, .. }
        | UnitSlip::RigBeyondAnyTyre { column, value, .. }
        | UnitSlip::RigForceAboveLoad { column, value, .. } => (Some(column), Some(*value)),
        // `UnitSlip` may grow (non-exhaustive): a new slip has no key here
        // until it is named above.
        _ => (None, None),
    }
}

/// The exception class of an error's kind and its attributes (only typed
/// fields of the error, never its message text).
fn py_class_attrs(py: Python<'_>, e: &Error) -> (PyErr, Vec<(&'static str, Py<PyAny>)>) {
    // The command line's options as Python's keywords.
    let message = spelling::pythonic(&e.to_string());
    let text = |s: &str| py_obj(py, s);
    let path = |p: &Path| py_obj(py, p.display().to_string());
    let opt = |n: Option<usize>| n.map_or_else(|| py.None(), |n| py_obj(py, n));
    let kind = ("kind", text(e.kind().as_str()));
    let (err, mut attrs): (PyErr, Vec<(&'static str, Py<PyAny>)>) = match e {
        Error::Param(p) => (
            ParamError::new_err(message),
            vec![
                ("key", text(&p.key)),
                (
                    "value",
                    p.value
                        .number()
                        .map_or_else(|| py.None(), |v| py_obj(py, v)),
                ),
                ("reason", text(&p.reason.to_string())),
            ],
        ),
        Error::Input(i) => {
            let at = i.location();
            let (key, value, reason) = match i {
                LibInputError::Value { source: p, .. } => (
                    text(&p.key),
                    p.value
                        .number()
                        .map_or_else(|| py.None(), |v| py_obj(py, v)),
                    text(&p.reason.to_string()),
                ),
                LibInputError::Key { key, detail, .. } => (text(key), py.None(), text(detail)),
                LibInputError::Invalid { problem, .. } => {
                    let (key, value) = problem_key_value(problem);
                    let value = value.map_or_else(|| py.None(), |v| py_obj(py, v));
                    (
                        key.map_or_else(|| py.None(), text),
                        value,
                        text(&problem.to_string()),
                    )
                }
                LibInputError::Cell { name, cell, .. } => (text(name), text(cell), text(&message)),
                LibInputError::MissingColumn { name, .. } => {
                    (text(name), py.None(), text(&message))
                }
                _ => (py.None(), py.None(), text(&message)),
            };
            let problem = match i {
                LibInputError::Invalid { problem, .. } => text(problem.name()),
                _ => py.None(),
            };
            (
                InputError::new_err(message),
                vec![
                    ("problem", problem),
                    ("path", path(i.path())),
                    ("line", opt(at.map(|a| a.line))),
                    ("column", opt(at.map(|a| a.column))),
                    ("key", key),
                    ("value", value),
                    ("reason", reason),
                ],
            )
        }
        Error::Options(o) => {
            let mut attrs = Vec::new();
            match o {
                LibOptionsError::UnknownName { what, given, known } => {
                    attrs.push(("what", text(what.as_str())));
                    attrs.push(("name", text(given)));
                    attrs.push(("known", py_obj(py, known.clone())));
                }
                LibOptionsError::UnknownHold {
                    model,
                    given,
                    known,
                } => {
                    attrs.push(("what", text(&format!("{model} parameter"))));
                    attrs.push(("name", text(given)));
                    attrs.push(("known", py_obj(py, known.clone())));
                }
                LibOptionsError::UnknownLocalMethod { given }
                | LibOptionsError::ShardText { given } => attrs.push(("name", text(given))),
                LibOptionsError::ShardsDiffer { path: p, .. }
                | LibOptionsError::ShardUnits { path: p, .. }
                | LibOptionsError::ShardTwice { path: p, .. }
                | LibOptionsError::InputChanged { path: p }
                | LibOptionsError::CampaignsChanged { path: p }
                | LibOptionsError::MergeCount { path: p, .. } => attrs.push(("path", path(p))),
                _ => {}
            }
            (OptionsError::new_err(message), attrs)
        }
        Error::Fit(f) => {
            let data = match f {
                LibFitError::NoLateralData { data, .. }
                | LibFitError::NoData { data }
                | LibFitError::NoCondition { data, .. }
                | LibFitError::NoSmallSlip { data, .. }
                | LibFitError::InData { data, .. } => path(data),
                _ => py.None(),
            };
            (FitError::new_err(message), vec![("path", data)])
        }
        Error::Metrics(_) => (MetricsError::new_err(message), Vec::new()),
        Error::Diagnosis(d) => {
            let rig = match d {
                LibDiagnosisError::NoRigCondition { rig }
                | LibDiagnosisError::RigFit { rig, .. } => path(rig),
                _ => py.None(),
            };
            (DiagnosisError::new_err(message), vec![("path", rig)])
        }
        Error::Output(o) => (
            OutputError::new_err(message),
            vec![("path", path(o.path()))],
        ),
        _ => (HandlingError::new_err(message), Vec::new()),
    };
    attrs.push(kind);
    (err, attrs)
}

/// The library's error as the Python exception of its kind, carrying its
/// typed fields (file, line, key, value) as attributes.
fn py_err(e: Error) -> PyErr {
    Python::attach(|py| {
        let (err, attrs) = py_class_attrs(py, &e);
        let v = err.value(py);
        for (k, x) in attrs {
            // Setting an attribute on a fresh exception instance cannot
            // fail short of memory exhaustion.
            let _ = v.setattr(k, x);
        }
        err
    })
}

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

/// K of N, checked (1 ≤ K ≤ N).
fn shard(index: usize, count: usize) -> PyResult<Shard> {
    Shard::new(index, count).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// A tyre of any model (Gim, simplified Magic Formula, UniTire, PAC89,
/// linear, Magic Formula 5.2/6.1/6.2 from a .tir file).
#[pyclass(name = "Tyre", module = "handling._handling", frozen)]
struct PyTyre {
    tyre: Tyre,
}

#[pymethods]
impl PyTyre {
    /// Loads and validates a tyre file (`.toml`, or `.tir` for the Magic Formula).
    #[staticmethod]
    fn load(py: Python<'_>, path: PathBuf) -> PyResult<Self> {
        let tyre = detached(py, || load_tyre(&path).map_err(Error::from))?;
        Ok(Self { tyre })
    }

    /// The tyre from its JSON form ([`PyTyre::to_json`]).
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Self> {
        let tyre: Tyre = serde_json::from_str(text)
            .map_err(|e| HandlingError::new_err(format!("tyre from JSON: {e}")))?;
        tyre.validate().map_err(|e| py_err(e.into()))?;
        Ok(Self { tyre })
    }

    /// The tyre as JSON text (serde form of the tyre file, `model` tag included).
    fn to_json(&self) -> PyResult<String> {
        json(&self.tyre)
    }

    /// The model name (`gim`, `pac89`, `magic-formula`, ...).
    #[getter]
    fn model(&self) -> &'static str {
        self.tyre.model_name()
    }

    /// Cornering stiffness ∂Fy/∂α at α = 0, N/rad, at load `fz` (N).
    /// A load `tyre-eval` refuses raises `PointError`.
    fn cornering_stiffness(&self, py: Python<'_>, fz: f64) -> PyResult<f64> {
        points::check_loads(py, &self.tyre, &[fz], PointError::new_err)?;
        Ok(self.tyre.cornering_stiffness(fz))
    }

    /// Cornering stiffness, N/rad, at each load of a 1-D float64 array
    /// (N), evaluated in one call with the GIL released.
    fn cornering_stiffness_1d<'py>(
        &self,
        py: Python<'py>,
        fz: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let fz = fz.as_slice()?;
        let tyre = &self.tyre;
        points::check_loads(py, tyre, fz, PointError::new_err)?;
        let k: Vec<f64> = py.detach(|| fz.iter().map(|&f| tyre.cornering_stiffness(f)).collect());
        Ok(PyArray1::from_vec(py, k))
    }

    /// The tyre as the text of a tyre file: `(extension, text)`, `toml`
    /// (the serde form, `model` tag included) for every model, which
    /// `load` reads back to an equal tyre.
    fn to_file_text(&self) -> PyResult<(&'static str, String)> {
        let text = toml::to_string(&self.tyre)
            .map_err(|e| HandlingError::new_err(format!("tyre to TOML: {e}")))?;
        Ok(("toml", text))
    }

    /// Forces at points given as parallel 1-D float64 arrays (SI, rad, Pa);
    /// `pressure` empty for the file's inflation pressure; `mode` MFeval's
    /// `useMode` as `tyre-eval --mode` takes it (None: the tyre's own, 121
    /// as a file is read), refused as it refuses it. Returns
    /// `(fx, fy, mz, mx, my)`, `mx`/`my` None unless the Magic Formula.
    #[allow(clippy::too_many_arguments, clippy::type_complexity)]
    #[pyo3(signature = (fz, kappa, alpha, camber, speed, pressure, mode=None))]
    fn forces_1d<'py>(
        &self,
        py: Python<'py>,
        fz: PyReadonlyArray1<'py, f64>,
        kappa: PyReadonlyArray1<'py, f64>,
        alpha: PyReadonlyArray1<'py, f64>,
        camber: PyReadonlyArray1<'py, f64>,
        speed: PyReadonlyArray1<'py, f64>,
        pressure: PyReadonlyArray1<'py, f64>,
        mode: Option<u32>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        // The mode set on a copy, by `tyre-eval`'s own function: the
        // `Tyre` object is immutable (frozen, hashed by its JSON).
        let moded = match mode {
            Some(code) => {
                let mut t = self.tyre.clone();
                set_tyre_mode(&mut t, code).map_err(|e| py_err(Error::Options(e.into())))?;
                Some(t)
            }
            None => None,
        };
        let tyre = moded.as_ref().unwrap_or(&self.tyre);
        let n = fz.len()?;
        let cols = [&fz, &kappa, &alpha, &camber, &speed];
        if cols.iter().any(|c| c.len().ok() != Some(n)) {
            return Err(PyValueError::new_err(
                "fz, kappa, alpha, camber and speed must have the same length",
            ));
        }
        let p = pressure.len()?;
        if p != 0 && p != n {
            return Err(PyValueError::new_err(
                "pressure must be empty or as long as fz",
            ));
        }
        let s = [
            fz.as_slice()?,
            kappa.as_slice()?,
            alpha.as_slice()?,
            camber.as_slice()?,
            speed.as_slice()?,
            pressure.as_slice()?,
        ];
        // The points `tyre-eval` refuses, refused; its warnings, warned.
        let inputs = [s[0], s[1], s[2], s[3], s[4]];
        points::check_points(py, tyre, inputs, s[5], PointError::new_err)?;
        ranges::warn_ranges(py, tyre, inputs, s[5])?;
        let pts = py.detach(|| tyre.evaluate_points(s[0], s[1], s[2], s[3], s[4], s[5]));
        let col = |f: &dyn Fn(&handling::tyre::PointForces) -> f64| {
            PyArray1::from_iter(py, pts.iter().map(f)).into_any()
        };
        let opt = |f: &dyn Fn(&handling::tyre::PointForces) -> Option<f64>| {
            if pts.first().is_some_and(|p| f(p).is_some()) {
                PyArray1::from_iter(py, pts.iter().map(|p| f(p).unwrap_or(f64::NAN))).into_any()
            } else {
                py.None().into_bound(py)
            }
        };
        PyTuple::new(
            py,
            [
                col(&|p| p.fx),
                col(&|p| p.fy),
                col(&|p| p.mz),
                opt(&|p| p.mx),
                opt(&|p| p.my),
            ],
        )
    }

    /// Whether the Magic Formula's overturning and rolling-resistance moments exist.
    #[getter]
    fn has_wheel_moments(&self) -> bool {
        self.tyre.has_wheel_moments()
    }

    fn __eq__(&self, other: &Self) -> bool {
        self.tyre == other.tyre
    }

    fn __repr__(&self) -> String {
        format!("Tyre(model={:?})", self.tyre.model_name())
    }

    /// Pickles through the JSON form.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let ctor = slf.get_type().getattr("from_json")?;
        let args = PyTuple::new(py, [slf.get().to_json()?])?;
        PyTuple::new(py, [ctor.into_any(), args.into_any()])
    }
}

/// A stiffness study's model: one (front, rear) cornering-stiffness pair
/// simulated at a time (Wang & Liang), as `handling study` does for each.
#[pyclass(name = "Study", module = "handling._handling", frozen)]
struct PyStudy {
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

/// Simulates a scenario file; `(report JSON, [(column, array)])`, writing
/// the CLI's outputs to `out` when given.
#[pyfunction]
#[pyo3(signature = (scenario, out=None))]
fn simulate<'py>(
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
fn _bench_simulate(py: Python<'_>, scenario: PathBuf, n: usize) -> PyResult<f64> {
    detached(py, || {
        let t0 = Instant::now();
        for _ in 0..n {
            std::hint::black_box(jobs::simulate::run(&scenario, None)?);
        }
        Ok(t0.elapsed().as_secs_f64())
    })
}

/// The angle columns `metrics` reads in degrees (its CLI's `--degrees`
/// takes these alone).
const METRICS_ANGLES: [&str; 3] = ["steer", "yaw_rate", "beta"];

/// `degrees`' names as the run's angle columns (the package refuses any
/// other name first, as an `OptionsError` with `name` and `known`).
fn angle_columns(degrees: &[String]) -> PyResult<Vec<handling::io::AngleColumn>> {
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
fn metrics(
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

/// Steering equilibria over a sweep file; report JSON (`summary.json`'s content).
#[pyfunction]
#[pyo3(signature = (sweep, out=None))]
fn equilibria(py: Python<'_>, sweep: PathBuf, out: Option<PathBuf>) -> PyResult<String> {
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
fn run_shard(
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
fn merge(py: Python<'_>, shards: Vec<PathBuf>, out: Option<PathBuf>) -> PyResult<String> {
    let first = shards
        .first()
        .ok_or_else(|| PyValueError::new_err("merge: no shard files"))?
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
fn study(py: Python<'_>, study_file: PathBuf, out: Option<PathBuf>) -> PyResult<String> {
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

/// Fits a tyre model to rig data; `(report JSON, fitted tyre)`.
#[pyfunction]
#[pyo3(signature = (data, model, seed=1, out=None, pressure=None, camber=None, local="lm", bin_deg=0.25, bin_kappa=0.0025, start="data", template=None, max_iterations=handling::identify::mf_staged::LM_ITERATIONS, hold=Vec::new(), load=None))]
#[allow(clippy::too_many_arguments)]
fn identify(
    py: Python<'_>,
    data: PathBuf,
    model: &str,
    seed: u64,
    out: Option<PathBuf>,
    pressure: Option<f64>,
    camber: Option<f64>,
    local: &str,
    bin_deg: f64,
    bin_kappa: f64,
    start: &str,
    template: Option<PathBuf>,
    max_iterations: usize,
    hold: Vec<(String, f64)>,
    load: Option<f64>,
) -> PyResult<(String, PyTyre)> {
    let model: IdentifyModel = model.parse().map_err(py_err)?;
    let local: Polish = local.parse().map_err(py_err)?;
    let start: StartArg = start
        .parse()
        .map_err(|e: Error| PyValueError::new_err(e.to_string()))?;
    let write = out.is_some();
    let o = Options {
        data,
        model,
        seed,
        out,
        load,
        pressure,
        camber,
        local,
        alpha_bin_deg: bin_deg,
        kappa_bin: bin_kappa,
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

/// The sim-to-real gap of a campaign (file or folder); report JSON
/// (`diagnosis.json`'s content).
#[pyfunction]
#[pyo3(signature = (campaign, out=None))]
fn diagnose(py: Python<'_>, campaign: PathBuf, out: Option<PathBuf>) -> PyResult<String> {
    let r = run_job(
        py,
        out.is_some(),
        || jobs::diagnose::run(&campaign, out.as_deref()),
        |r| r.write(),
    )?;
    json(&r)
}

/// The cases a diagnosis's verdict can be (`verdict.kind` in
/// `diagnosis.json`), as the library names them.
#[pyfunction]
fn verdict_kinds() -> Vec<&'static str> {
    handling::diagnose::VerdictKind::ALL
        .iter()
        .map(|k| k.name())
        .collect()
}

/// The virtual proving ground: writes a campaign folder `out` measured on
/// a truth model with the named effects on, driving `programme`
/// (`handling`, `oval` or `road-course`); report JSON.
#[pyfunction]
#[pyo3(signature = (out, effects=Vec::new(), seed=1, truth="augmented", programme="handling", drive=Vec::new(), duration=None))]
#[allow(clippy::too_many_arguments)]
fn synth(
    py: Python<'_>,
    out: PathBuf,
    effects: Vec<String>,
    seed: u64,
    truth: &str,
    programme: &str,
    drive: Vec<PathBuf>,
    duration: Option<f64>,
) -> PyResult<String> {
    let programme = programme.parse().map_err(py_err)?;
    let effects = effects
        .iter()
        .map(|e| e.parse::<EffectName>())
        .collect::<Result<Vec<_>, _>>()
        .map_err(py_err)?;
    let truth = truth_named(truth).map_err(py_err)?;
    let r = detached(py, || {
        let mut r = jobs::synth::run(&effects, seed, truth, programme, duration, &out)?;
        r.drive(&drive)?;
        r.write()?;
        Ok(r)
    })?;
    json(&r)
}

/// The next test to drive for the diagnosis in folder `diagnosis`
/// (`handling design`): `effects` names the candidates to separate (the
/// reference first, `a+b` a combination; default the confounded sets);
/// runs `measured` driven afterwards are measured against the first set.
/// Writes the outputs to `out` (default `<diagnosis>/design`); report JSON.
#[pyfunction]
#[pyo3(signature = (diagnosis, campaign=None, effects=Vec::new(), ay_share=0.8, max_ax=3.0, top=3, measured=Vec::new(), out=None))]
#[allow(clippy::too_many_arguments)]
fn design(
    py: Python<'_>,
    diagnosis: PathBuf,
    campaign: Option<PathBuf>,
    effects: Vec<String>,
    ay_share: f64,
    max_ax: f64,
    top: usize,
    measured: Vec<PathBuf>,
    out: Option<PathBuf>,
) -> PyResult<String> {
    let set = effects
        .iter()
        .map(|c| {
            c.split('+')
                .map(|n| {
                    n.trim().parse::<EffectName>().and_then(|e| {
                        e.0.ok_or_else(|| {
                            handling::error::OptionsError::UnknownName {
                                what: handling::error::NameKind::Effect,
                                given: n.trim().to_string(),
                                known: handling::diagnose::effects::EffectKind::ALL
                                    .iter()
                                    .map(|k| k.name())
                                    .collect(),
                            }
                            .into()
                        })
                    })
                })
                .collect::<Result<Vec<_>, Error>>()
        })
        .collect::<Result<Vec<_>, _>>()
        .map_err(py_err)?;
    let request = handling::design::DesignRequest {
        sets: (!set.is_empty()).then(|| vec![set]),
        ay_share,
        ax: max_ax,
        top,
        ..Default::default()
    };
    let r = detached(py, || {
        let r = jobs::design::run(
            &diagnosis,
            campaign.as_deref(),
            &request,
            &measured,
            out.as_deref(),
        )?;
        r.write()?;
        Ok(r)
    })?;
    json(&r)
}

/// The `[vehicle]` table of TOML `text`, read and validated as a scenario
/// file's (`path` names the text in errors); JSON of the vehicle (SI).
#[pyfunction]
fn vehicle_from_toml(text: &str, path: PathBuf) -> PyResult<String> {
    let v = handling::io::scenario::vehicle_from_text(&path, text).map_err(|e| py_err(e.into()))?;
    json(&v)
}

/// The tables of a TOML file as JSON text (the file as written: relative
/// paths unresolved), for `Scenario.load` after `check_scenario` has read
/// and validated it with the library's reader.
#[pyfunction]
fn toml_file_json(py: Python<'_>, path: PathBuf) -> PyResult<String> {
    let table: toml::Table = detached(py, || {
        let src = handling::io::TomlSource::read(&path)?;
        src.parse().map_err(Error::from)
    })?;
    json(&table)
}

/// Checks a scenario file (reads and validates it, simulates nothing).
#[pyfunction]
fn check_scenario(py: Python<'_>, scenario: PathBuf) -> PyResult<String> {
    let sc = detached(py, || load_scenario(&scenario).map_err(Error::from))?;
    Ok(sc.name)
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
    m.add_class::<PyTyre>()?;
    m.add_class::<PyStudy>()?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(_bench_simulate, m)?)?;
    m.add_function(wrap_pyfunction!(metrics, m)?)?;
    m.add_function(wrap_pyfunction!(equilibria, m)?)?;
    m.add_function(wrap_pyfunction!(run_shard, m)?)?;
    m.add_function(wrap_pyfunction!(merge, m)?)?;
    m.add_function(wrap_pyfunction!(study, m)?)?;
    m.add_function(wrap_pyfunction!(identify, m)?)?;
    m.add_function(wrap_pyfunction!(diagnose, m)?)?;
    m.add_function(wrap_pyfunction!(verdict_kinds, m)?)?;
    m.add_function(wrap_pyfunction!(synth, m)?)?;
    m.add_function(wrap_pyfunction!(design, m)?)?;
    m.add_function(wrap_pyfunction!(check_scenario, m)?)?;
    m.add_function(wrap_pyfunction!(toml_file_json, m)?)?;
    m.add_function(wrap_pyfunction!(vehicle_from_toml, m)?)?;
    // The registry's lists: the `model` keys of tyre files and the models
    // `identify` fits (a model registered in Rust appears in both).
    let names: Vec<&str> = model_names().iter().map(|n| n.as_str()).collect();
    m.add("MODEL_NAMES", names)?;
    m.add("IDENTIFY_MODELS", IdentifyModel::names())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
