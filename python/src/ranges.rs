//! The points of `Tyre.forces` outside a `.tir` file's ranges (load, slip
//! ratio, slip angle, camber, pressure), warned of as `tyre-eval` warns of
//! them, in its words (`handling::jobs::tyre_eval::ranges_left`, the CLI's
//! own function): with the file's limit checks on (its mode), such points
//! are evaluated at the range's end, and a 40 kN load of an 18 kN file
//! returned the forces at 18 kN without a word. A Python `UserWarning` per
//! range left; the first point named by its index in the flattened
//! broadcast arrays, where the CLI names a file's line. Units: N, rad, Pa.

use handling::jobs::tyre_eval::{mf_inputs, ranges_left, FirstAt};
use handling::tyre::Tyre;
use pyo3::exceptions::PyUserWarning;
use pyo3::prelude::*;

/// Warns of the points (`inputs`: fz, kappa, alpha, camber, speed, equal
/// lengths; `pressure` empty for the tyre's own) outside a Magic Formula
/// tyre's file ranges; nothing for another model.
pub(crate) fn warn_ranges(
    py: Python<'_>,
    tyre: &Tyre,
    inputs: [&[f64]; 5],
    pressure: &[f64],
) -> PyResult<()> {
    let Tyre::MagicFormula(mf) = tyre else {
        return Ok(());
    };
    let points = mf_inputs(inputs, pressure);
    let index: Vec<usize> = (0..points.len()).collect();
    let left = py.detach(|| ranges_left(mf, &points, &index));
    let category = py.get_type::<PyUserWarning>();
    for r in left {
        let message = r.said(points.len(), FirstAt::Index);
        let text = std::ffi::CString::new(message).unwrap_or_default();
        // Stack level 2: the caller of `Tyre.forces` (level 1 is its Python body).
        PyErr::warn(py, category.as_any(), &text, 2)?;
    }
    Ok(())
}
