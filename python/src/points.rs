//! The checks `tyre-eval` makes of its points, made of the arrays given to
//! `Tyre.forces` and `Tyre.cornering_stiffness`
//! (`handling::jobs::tyre_eval::refused_points`, the CLI's own rules, not
//! a copy): every value refused raises the `PointError` made by the
//! `new_err` given (the first's
//! `argument`, `index` and `value`; `refused`, every one), and slip ratios
//! beyond ±1 are warned of through Python's `warnings`, as the CLI warns.
//! Units: SI, rad, Pa.

use handling::jobs::tyre_eval::{refused_points, slip_past_lock, PointRefused};
use handling::tyre::Tyre;
use pyo3::exceptions::PyUserWarning;
use pyo3::prelude::*;
use pyo3::IntoPyObjectExt;

/// Refuses the points (`inputs`: fz, kappa, alpha, camber, speed, equal
/// lengths; `pressure` empty for the tyre's own) that `tyre-eval` refuses,
/// and warns of slip ratios beyond ±1 as it does.
pub(crate) fn check_points(
    py: Python<'_>,
    tyre: &Tyre,
    inputs: [&[f64]; 5],
    pressure: &[f64],
    new_err: fn(String) -> PyErr,
) -> PyResult<()> {
    let refused = py.detach(|| refused_points(tyre, inputs, pressure));
    if let Some(first) = refused.first() {
        return Err(point_error(py, first, &refused, new_err));
    }
    if let Some(p) = slip_past_lock(inputs[1]) {
        let message = format!(
            "{} of {} points at a slip ratio beyond ±1 (the first at index {}, kappa = {}; the farthest {}): below −1 the wheel turns backwards while the car rolls forwards, above 1 it spins at more than twice the road speed, where no braking or traction test goes (rigs sweep to about ±0.3) and the forces are the saturated tail of the curve: `kappa` is a fraction; is it in percent? divide it by 100",
            p.points,
            inputs[1].len(),
            p.first_line,
            p.first_value,
            p.farthest
        );
        let category = py.get_type::<PyUserWarning>();
        let text = std::ffi::CString::new(message).unwrap_or_default();
        // Stack level 2: the caller of `Tyre.forces` (level 1 is its Python body).
        PyErr::warn(py, category.as_any(), &text, 2)?;
    }
    Ok(())
}

/// Refuses a load (N) of `cornering_stiffness` that `tyre-eval` refuses.
pub(crate) fn check_loads(
    py: Python<'_>,
    tyre: &Tyre,
    fz: &[f64],
    new_err: fn(String) -> PyErr,
) -> PyResult<()> {
    let zero = vec![0.0; fz.len()];
    check_points(py, tyre, [fz, &zero, &zero, &zero, &zero], &[], new_err)
}

/// The `PointError` of `refused`, its first one's fields as attributes.
fn point_error<'py>(
    py: Python<'py>,
    first: &PointRefused,
    refused: &[PointRefused],
    new_err: fn(String) -> PyErr,
) -> PyErr {
    let shown: Vec<String> = refused.iter().take(10).map(|r| r.to_string()).collect();
    let more = refused.len().saturating_sub(shown.len());
    let mut message = format!(
        "{} refused (tyre-eval refuses them in a points file): {}",
        match refused.len() {
            1 => "1 point".to_string(),
            n => format!("{n} points"),
        },
        shown.join("; ")
    );
    if more > 0 {
        message.push_str(&format!("; and {more} more (`refused` lists every one)"));
    }
    let err = new_err(message);
    let v = err.value(py);
    let every: Vec<(&str, usize, f64)> = refused
        .iter()
        .map(|r| (r.argument, r.index, r.value))
        .collect();
    let reason = match &first.problem {
        Some(p) => p.to_string(),
        None => format!("{} is not a finite value", first.value),
    };
    let problem = first.problem.as_ref().map(|p| p.name());
    let obj = |x: PyResult<Bound<'py, PyAny>>| x.unwrap_or_else(|_| py.None().into_bound(py));
    let attrs = [
        ("argument", obj(first.argument.into_bound_py_any(py))),
        ("index", obj(first.index.into_bound_py_any(py))),
        ("value", obj(first.value.into_bound_py_any(py))),
        ("reason", obj(reason.into_bound_py_any(py))),
        ("problem", obj(problem.into_bound_py_any(py))),
        ("refused", obj(every.into_bound_py_any(py))),
        ("kind", obj("input".into_bound_py_any(py))),
    ];
    for (k, x) in attrs {
        // Setting an attribute on a fresh exception cannot fail short of
        // memory exhaustion.
        let _ = v.setattr(k, x);
    }
    err
}
