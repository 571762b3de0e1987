//! `Tyre`: a tyre of any model loaded from its file, evaluated at numpy
//! arrays of points (SI units, radians, Pa) as `tyre-eval` evaluates a
//! points file: the same refusals and warnings, its `--mode` as `mode=`.

use crate::errors::{py_err, HandlingError, OptionsError, PointError};
use crate::{detached, json, points, ranges, spelling};
use handling::error::{Error, ModeError};
use handling::io::load_tyre;
use handling::io::tir::set_tyre_mode;
use handling::tyre::{Tyre, TyreModel};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::{PyOverflowError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use std::path::PathBuf;

/// A tyre of any model (Gim, simplified Magic Formula, UniTire, PAC89,
/// linear, Magic Formula 5.2/6.1/6.2 from a .tir file).
#[pyclass(name = "Tyre", module = "handling._handling", frozen)]
pub(crate) struct PyTyre {
    pub(crate) tyre: Tyre,
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
        mode: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let moded = mode.map(|m| self.in_mode(&m)).transpose()?;
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

impl PyTyre {
    /// A copy of the tyre in MFeval mode `mode`, set by `tyre-eval`'s own
    /// function (the `Tyre` object is immutable: frozen, hashed by its
    /// JSON), refused as it refuses the code.
    fn in_mode(&self, mode: &Bound<'_, PyAny>) -> PyResult<Tyre> {
        let code = mode_code(mode)?;
        let mut t = self.tyre.clone();
        set_tyre_mode(&mut t, code).map_err(|e| py_err(Error::Options(e.into())))?;
        Ok(t)
    }
}

/// `mode=` as a `useMode` code. An integer no code holds (negative, or
/// past 2³² − 1) is refused as `tyre-eval` refuses a code of other than
/// three digits, in its words, which name the value and the digits
/// allowed (as a `u32` argument, `mode=-5` raised Python's
/// `OverflowError`); a value that is not an integer raises `TypeError`,
/// as before.
fn mode_code(mode: &Bound<'_, PyAny>) -> PyResult<u32> {
    let py = mode.py();
    match mode.extract::<u32>() {
        Ok(code) => Ok(code),
        Err(e) if e.is_instance_of::<PyOverflowError>(py) => {
            let words = Error::Options(ModeError::NotThreeDigits { code: 0 }.into())
                .to_string()
                .replacen("mode 0 ", &format!("mode {} ", mode.str()?), 1);
            let err = OptionsError::new_err(spelling::pythonic(&words));
            err.value(py).setattr("kind", "options")?;
            Err(err)
        }
        Err(e) => Err(PyTypeError::new_err(format!(
            "argument 'mode': {}",
            e.value(py)
        ))),
    }
}
