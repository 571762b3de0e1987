//! A rig file's slip angles in degrees, written where FORMATS.md asks for
//! radians, whose sweep stays inside ±90° (so that the reader's check,
//! `AngleInDegrees`, passes it): every model fitted it 57 times too soft
//! (a PAC89 fit wrote 0.26 N/rad per N of load and `simulate` ran it
//! without a word; a Gim fit's refusal blamed its own parameter in N/deg).
//! Judged by the rig reader (`io/rig_degrees.rs`) on the slope of `fy/fz`
//! against the column near zero slip, read both ways: in radians below any
//! tyre's, in degrees a tyre's, with a sweep beyond any rig's in radians.

use super::number::Num;
use crate::format::readable;
use thiserror::Error;

/// The largest |α| a rig sweeps in radians, rad (20°: the TTC sweeps
/// reach 12°, a Magic Formula grid 15°).
pub const MAX_RIG_SLIP_ANGLE: f64 = 0.35;

/// The numbers of the refusal. 1/rad (N/rad per N of load), rad.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("column `alpha`: {} here, the sweep's largest |alpha|, is {:.0}° read in radians, beyond the ±{MAX_RIG_SLIP_ANGLE} rad (20°) a rig sweeps, and read in radians the slope of fy/fz against alpha over its {samples} samples with |alpha| ≤ {} is {} 1/rad (N/rad per N of load), below any tyre's {least} (a car tyre's is about 5–45); read in degrees the slope is {} 1/rad, a tyre's: angles are in radians (FORMATS.md); is the column in degrees? Convert it (multiply by 0.01745)", Num(*reach), reach.to_degrees(), Num(*window), readable(*per_rad, 3), readable(*per_deg, 3))]
pub struct SlipAngleInDegrees {
    /// The slope per unit load with the column read in radians, 1/rad.
    pub per_rad: f64,
    /// The slope per unit load with the column read in degrees, 1/rad.
    pub per_deg: f64,
    /// The samples the slope in radians is fitted to.
    pub samples: usize,
    /// The largest |α| those samples may have, as read.
    pub window: f64,
    /// The file's α of the largest magnitude, as read (rad).
    pub reach: f64,
    /// The least stiffness per unit load any tyre has, 1/rad.
    pub least: f64,
}
