//! A rig aligning moment in kN·m beside loads in N: a thousand times too
//! small, it was fitted (GIM: σ 51 %, RMS 0.0121 N·m, its contact length
//! past its bound) without a word, where N·mm was refused as such.

use super::number::Num;
use crate::format::readable;
use thiserror::Error;

/// The least largest |mz|/fz of a tyre's cornering sweep, m: 1 mm. A
/// tyre's aligning moment peaks at a trail of centimetres times a force
/// of about its load (the Hoosier rig file's largest is 0.059 m, a
/// truck's about 0.025 m); in kN·m it reads 1e-5.
pub const MIN_RIG_ARM: f64 = 1e-3;

/// A rig file's aligning moments whose largest |mz|/fz, over a sweep
/// reaching `slip`, is below [`MIN_RIG_ARM`].
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("column `mz`: its largest aligning moment, {} N·m at fz {} N, is {} m times the load over a sweep reaching a slip angle of {}°, where a tyre's aligning moment peaks at its pneumatic trail (centimetres) times a force of about its load, above {MIN_RIG_ARM} m times it: is the column in kN·m? multiply it by 1000 ({} N·m); `mz` is in N·m (FORMATS.md)", Num(*value), Num(*fz), readable((value / fz).abs(), 3), readable(slip.to_degrees(), 3), readable(value * 1000.0, 4))]
pub struct RigMomentInKnm {
    /// The largest |mz| relative to its load, N·m as read.
    pub value: f64,
    /// That sample's load, N.
    pub fz: f64,
    /// The largest |alpha| of the sweep, rad.
    pub slip: f64,
}
