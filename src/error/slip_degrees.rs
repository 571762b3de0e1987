//! A rig file's slip angles in degrees, written where FORMATS.md asks for
//! radians, whose sweep stays inside ±90° (so that the reader's check,
//! `AngleInDegrees`, passes it): a linear tyre fitted to it came out 57
//! times too soft, on its search bound, with no word on the unit, and
//! `tyre-eval` later asked whether the stiffness was in N/deg. Judged on
//! the two together: a stiffness per unit load below any tyre's and slip
//! angles beyond any rig's sweep in radians.

use super::number::Num;
use crate::format::readable;
use thiserror::Error;

/// The largest |α| a rig sweeps in radians, rad (20°: the TTC sweeps
/// reach 12°, a Magic Formula grid 15°).
pub const MAX_RIG_SLIP_ANGLE: f64 = 0.35;

/// The numbers of the refusal. N, N/rad, rad.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("column `alpha`: a linear tyre fitted to it has a cornering stiffness of {} N/rad, {} N/rad per N of the median load fitted ({} N), below any tyre's {least} (a car tyre's is about 5–45), and its slip angles reach {} rad ({:.0}° read as radians), beyond the ±{MAX_RIG_SLIP_ANGLE} rad (20°) a rig sweeps: angles are in radians (FORMATS.md); is the column in degrees? Convert it (multiply by 0.01745) and fit again", Num(*stiffness), readable(stiffness / load, 3), Num(*load), Num(*reach), reach.to_degrees())]
pub struct SlipAngleInDegrees {
    /// The fitted cornering stiffness, N/rad.
    pub stiffness: f64,
    /// The median load of the conditions fitted, N.
    pub load: f64,
    /// The largest |α| of the file, as read (rad).
    pub reach: f64,
    /// The least stiffness per unit load any tyre has, 1/rad.
    pub least: f64,
}
