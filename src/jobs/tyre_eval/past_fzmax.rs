//! The loaded radius `rl` of the points past a Magic Formula file's
//! `FZMAX` with the limit checks on, said: MFeval (and this evaluation,
//! which follows it to stay comparable) takes the tyre's deflection at the
//! load held at `FZMAX` and the free radius at the load given, whose
//! effective rolling radius shrinks with it, so the wheel speed `Vx/Re`
//! and the free radius grow: past `FZMAX`, `rl` does not fall with the
//! load, it rises (0.304431 m at 10 kN, 0.304468 m at 24 kN on the public
//! `car205_60R19.tir` at 16.7 m/s, as MFeval's June 2020 C++ build gives
//! them). The formula's extrapolation, not a deflection at the load
//! given: said, with the first point's `rl` against its `rl` at `FZMAX`.
//! Loads past the rim are refused (`bottoming.rs`). Units: N, m.

use crate::format::{plural, rounded, significant};
use crate::tyre::mf::{MagicFormula, MfInput};
use serde::Serialize;

/// The points past `FZMAX` whose `rl` holds the deflection at `FZMAX`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RadiusPastFzmax {
    /// Points past `FZMAX` with a loaded radius.
    pub points: usize,
    /// The file's `FZMAX`, N.
    pub fz_max: f64,
    /// The first such point's line in the points file (1-based).
    pub first_line: usize,
    /// Its load, N.
    pub first_fz: f64,
    /// Its `rl`, m.
    pub first_rl: f64,
    /// Its `rl` at `FZMAX`, the point otherwise the same, m.
    pub rl_at_fz_max: f64,
}

/// The points of `inputs` (at file lines `lines`, with loaded radii `rl`)
/// past the `FZMAX` of `t`, where the limit checks hold their deflection
/// there.
pub(super) fn past_fzmax(
    t: &MagicFormula,
    rl: &[f64],
    inputs: &[MfInput],
    lines: &[usize],
) -> Option<RadiusPastFzmax> {
    let fz_max = t.limits.fz_max.filter(|_| t.mode().limit_checks)?;
    let mut past = (0..inputs.len()).filter(|&i| inputs[i].fz > fz_max && rl[i].is_finite());
    let first = past.next()?;
    let q = &inputs[first];
    let rl_at_fz_max = t.loaded_radius(&MfInput { fz: fz_max, ..*q })?;
    Some(RadiusPastFzmax {
        points: 1 + past.count(),
        fz_max,
        first_line: lines[first],
        first_fz: q.fz,
        first_rl: rl[first],
        rl_at_fz_max,
    })
}

impl RadiusPastFzmax {
    /// The warning, of `count` points.
    pub fn line(&self, count: usize) -> String {
        format!(
            "{} of {} past FZMAX ({} N) with the limit checks on: their loaded radius `rl` is MFeval's, the tyre's deflection at FZMAX taken from the free radius at the load given (whose effective rolling radius shrinks with the load, so the wheel speed Vx/Re and the free radius grow): past FZMAX `rl` does not fall with the load (it holds, and rises with the wheel speed): the formula's extrapolation, not the tyre's deflection at its load (mode 2xx, the limit checks off, deflects it by the load given); the first at line {}, fz = {} N: rl = {} m, against {} m at FZMAX",
            self.points,
            plural(count, "point", "points"),
            rounded(self.fz_max, 6),
            self.first_line,
            rounded(self.first_fz, 6),
            significant(self.first_rl, 6),
            significant(self.rl_at_fz_max, 6)
        )
    }
}
