//! The checks `tyre-eval` makes of its points, made of the arrays given to
//! `Tyre.forces` and `Tyre.cornering_stiffness`
//! (`handling::jobs::tyre_eval::refused_points`, the CLI's own rules, not
//! a copy): every value refused raises the `PointError` made by the
//! `new_err` given (the first's
//! `argument`, `index` and `value`; `refused`, every one), and slip ratios
//! beyond ±1 are warned of through Python's `warnings`, as the CLI warns.
//! Units: SI, rad, Pa.

use handling::error::{InputProblem, PressureMeant, UnitSlip};
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
    let shown: Vec<String> = refused.iter().take(10).map(said).collect();
    let more = refused.len().saturating_sub(shown.len());
    let mut message = format!(
        "{} refused (as tyre-eval refuses them in a points file): {}",
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
        Some(p) => reason(p, first.argument),
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

/// A refused point in the words of arrays given to a function:
/// `fz[3] = -4000: …`.
fn said(r: &PointRefused) -> String {
    match &r.problem {
        Some(p) => format!("{}[{}]: {}", r.argument, r.index, reason(p, r.argument)),
        None => format!(
            "{}[{}]: {} is not a finite value",
            r.argument, r.index, r.value
        ),
    }
}

/// Why `argument`'s value is refused, said of the array given (its median,
/// every value of it), not of a file's column as the CLI says it; the
/// numbers and the advice are the problem's own.
fn reason(p: &InputProblem, argument: &str) -> String {
    let n = handling::format::exact;
    match p {
        InputProblem::NegativeLoad { value, every } => format!(
            "{} N is negative (loads are positive){}",
            n(*value),
            if *every {
                "; every load given is: a rig whose z axis points down (SAE's axes) logs them so; negate `fz`"
            } else {
                ""
            }
        ),
        InputProblem::NegativeSpeed { value } => format!(
            "{} m/s is negative: `speed` is the wheel's forward speed, 0 or more: a slip angle within ±90° already has the wheel rolling forwards (ISO 8855 measures it from the wheel's heading to its travel), and the models differ on a negative speed (a Magic Formula flips fy and my, the others ignore it); give the speed's size",
            n(*value)
        ),
        InputProblem::AngleInDegrees { value, limit, .. } => format!(
            "{} rad is beyond ±{:.0}°: angles are in radians; is `{argument}` in degrees? convert it with numpy.radians",
            n(*value),
            limit.to_degrees()
        ),
        InputProblem::NotPhysical {
            value,
            lo,
            hi,
            unit,
            why,
            ..
        } => {
            let u = |x: f64| match *unit {
                "" => n(x),
                _ => format!("{} {unit}", n(x)),
            };
            format!(
                "{} lies outside {} to {}, where a tyre is evaluated ({why})",
                u(*value),
                n(*lo),
                u(*hi)
            )
        }
        InputProblem::NonPositivePressure { value } => {
            format!("{} Pa is not a positive pressure", n(*value))
        }
        InputProblem::UnitSlip(UnitSlip::LoadInKn { value, median, limit }) => format!(
            "{} N, among loads whose median is {} N: no tyre is tested at a median load below {} N (a car tyre carries 2,000–8,000 N): `fz` is in N; is it in kN? multiply it by 1000",
            n(*value),
            n(*median),
            n(*limit)
        ),
        InputProblem::UnitSlip(UnitSlip::PressureNotInPa {
            value,
            median,
            limit,
            meant,
        }) => format!(
            "{} Pa, among pressures whose median is {} Pa: no inflated tyre runs below {} Pa (0.1 bar): `pressure` is in Pa; {}",
            n(*value),
            n(*median),
            n(*limit),
            pressure_unit(meant, *median)
        ),
        InputProblem::UnitSlip(UnitSlip::PressureRowNotInPa {
            value,
            median,
            limit,
            meant,
        }) => format!(
            "{} Pa among pressures whose median is {} Pa: no inflated tyre runs below {} Pa (0.1 bar): `pressure` is in Pa; {}",
            n(*value),
            n(*median),
            n(*limit),
            pressure_unit(meant, *value)
        ),
        other => other.to_string(),
    }
}

/// The unit a pressure `read` of a few Pa is in, where one lands it among
/// the tyre's pressures; else every unit it may be in.
fn pressure_unit(meant: &Option<PressureMeant>, read: f64) -> String {
    match meant {
        Some(m) => format!(
            "is it in {unit}? {} {unit} is {} Pa, within {} ({} to {} Pa): multiply by {}",
            handling::format::exact(read),
            handling::format::significant(m.pa, 4),
            m.what,
            handling::format::exact(m.among[0]),
            handling::format::exact(m.among[1]),
            handling::format::significant(m.pa / read, 4),
            unit = m.unit,
        ),
        None => "is it in kPa (multiply it by 1000), bar (by 100000) or psi (by 6895)?".into(),
    }
}
