//! The library's one `Error` as Python's exceptions: a class per kind
//! (`Error::kind`) under `HandlingError`, each carrying the error's typed
//! fields as attributes (path, line, column, key, value, problem; the
//! argument, index and value of a refused tyre point), read from the
//! fields, never from the message, whose words name Python's keywords
//! where the command line's name its options (`spelling.rs`).

use crate::spelling;
use handling::error::{
    DiagnosisError as LibDiagnosisError, Error, FitError as LibFitError,
    InputError as LibInputError, InputProblem, OptionsError as LibOptionsError, UnitSlip,
};
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use pyo3::IntoPyObjectExt;
use std::path::Path;

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
        InputProblem::RigPressureAboveAny(e) => (Some("pressure"), Some(e.value)),
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
        // The column its header names: the header cell holds a unit, no value.
        InputProblem::UnitInHeader(h) => (Some(h.column), None),
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
fn py_class_attrs(py: Python<'_>, e: &Error) -> (PyErr, Attrs) {
    // The command line's options as Python's keywords.
    let message = spelling::pythonic(&e.to_string());
    let text = |s: &str| py_obj(py, s);
    let path = |p: &Path| py_obj(py, p.display().to_string());
    let kind = ("kind", text(e.kind().as_str()));
    let (err, mut attrs): (PyErr, Attrs) = match e {
        Error::Param(p) => (
            ParamError::new_err(message),
            vec![
                // A command-line option (`--top`) as Python's keyword
                // (`top`), as the message says it; a file's key as it is.
                (
                    "key",
                    if p.key.starts_with("--") {
                        text(&spelling::keyword(&p.key))
                    } else {
                        text(&p.key)
                    },
                ),
                (
                    "value",
                    p.value
                        .number()
                        .map_or_else(|| py.None(), |v| py_obj(py, v)),
                ),
                ("reason", text(&p.reason.to_string())),
            ],
        ),
        Error::Input(i) => input_attrs(py, i, message),
        Error::Options(o) => options_attrs(py, o, message),
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

/// An attribute list of an exception.
type Attrs = Vec<(&'static str, Py<PyAny>)>;

/// `InputError` and its attributes: path, line, column, key, value,
/// reason and the problem's name where typed.
fn input_attrs(py: Python<'_>, i: &LibInputError, message: String) -> (PyErr, Attrs) {
    let text = |s: &str| py_obj(py, s);
    let path = |p: &Path| py_obj(py, p.display().to_string());
    let opt = |n: Option<usize>| n.map_or_else(|| py.None(), |n| py_obj(py, n));
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
        LibInputError::MissingColumn { name, .. } => (text(name), py.None(), text(&message)),
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

/// `OptionsError` and its attributes: the unknown name, what it names
/// and the known ones; the file named.
fn options_attrs(py: Python<'_>, o: &LibOptionsError, message: String) -> (PyErr, Attrs) {
    let text = |s: &str| py_obj(py, s);
    let path = |p: &Path| py_obj(py, p.display().to_string());
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
        LibOptionsError::UnknownLocalMethod { given } | LibOptionsError::ShardText { given } => {
            attrs.push(("name", text(given)))
        }
        LibOptionsError::ShardsDiffer { path: p, .. }
        | LibOptionsError::ShardUnits { path: p, .. }
        | LibOptionsError::ShardTwice { path: p, .. }
        | LibOptionsError::InputChanged { path: p }
        | LibOptionsError::CampaignsChanged { path: p }
        | LibOptionsError::MergeCount { path: p, .. } => attrs.push(("path", path(p))),
        LibOptionsError::ShardOutOfRange { index, count } => {
            attrs.push(("index", py_obj(py, *index)));
            attrs.push(("count", py_obj(py, *count)));
        }
        _ => {}
    }
    (OptionsError::new_err(message), attrs)
}

/// The library's error as the Python exception of its kind, carrying its
/// typed fields (file, line, key, value) as attributes.
pub(crate) fn py_err(e: Error) -> PyErr {
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
