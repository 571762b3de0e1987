//! The points whose load pushes a Magic Formula tyre onto its rim,
//! refused at their row in every mode. The bound: the load at which the
//! file's own vertical model, standing and free of force at the point's
//! pressure, deflects the tyre to its rim, `RIM_RADIUS + BOTTOM_OFFST`
//! (or a section height `WIDTH·ASPECT_RATIO` inside `UNLOADED_RADIUS`
//! without `RIM_RADIUS`: `io/tir/rim.rs`), never below the file's own
//! `FZMAX`. 24.0 kN on the public `car205_60R19.tir` (2.4 × FZMAX), 185
//! kN on `Truck_430_50R38.tir` (3.1 ×). Why there: past it the rim, not
//! the tyre, carries the load (MF-Tyre's bottoming, which MFeval does not
//! model); MFeval's `rl` there is the deflection at `FZMAX` taken from a
//! free radius grown by the load's effective rolling radius (0.30616 m at
//! 400 kN on `car205`, above the 0.30443 m at FZMAX: `rl` rising with the
//! load), or with the limit checks off the model's deflection extrapolated
//! past the rim (0.0039 m at 60 kN on `car205`, MFeval mode 221): no
//! deflection of a tyre either way. Standing and free of force, the bound
//! is the file's, the same at every speed and slip (speed stiffens the
//! tyre by `Q_V2`, a few per cent at road speeds; force softens it).
//! Units: N, m, Pa.

use crate::error::{Bottoming, RimFrom};
use crate::io::tir::TirDocument;
use crate::tyre::mf::{MagicFormula, MfInput};
use crate::tyre::Tyre;
use std::path::Path;

/// The rim of the Magic Formula tyre `tyre` read from the `.tir` at
/// `path`; `None` for another model, a file without a vertical model or
/// without the keys that place the rim.
pub(super) fn rim_of(path: &Path, tyre: &Tyre) -> Option<RimFrom> {
    let Tyre::MagicFormula(t) = tyre else {
        return None;
    };
    let is_tir = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("tir"));
    if !is_tir || !t.has_vertical_model() {
        return None;
    }
    TirDocument::read(path).ok()?.rim(&t.coefficients)
}

/// The points of `inputs` (by index) whose load is past the one that
/// pushes the tyre `t` onto its `rim` at their pressure, and past its
/// `FZMAX`, each with its load and the one at the rim.
pub(super) fn past_rim(
    t: &MagicFormula,
    rim: Option<RimFrom>,
    inputs: &[MfInput],
) -> Vec<super::not_carried::BottomedAt> {
    let Some(rim) = rim else {
        return Vec::new();
    };
    let r0 = t.coefficients.UNLOADED_RADIUS;
    let deflection = rim.deflection(r0);
    let fz_max = t.limits.fz_max;
    inputs
        .iter()
        .enumerate()
        .filter_map(|(i, q)| {
            let load = t.static_load_at(deflection, q.pressure)?;
            let bound = load.max(fz_max.unwrap_or(0.0));
            let b = Bottoming {
                rim,
                unloaded_radius: r0,
                load,
                fz_max,
            };
            (q.fz > bound).then_some((i, q.fz, b))
        })
        .collect()
}
