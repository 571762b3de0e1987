//! Where a `.tir` file puts its tyre's rim: `RIM_RADIUS` plus
//! `BOTTOM_OFFST` (MF-Tyre 6.x's bottoming: the tread meets the rim's
//! flange that far outside the rim radius), else, without `RIM_RADIUS`,
//! `UNLOADED_RADIUS` less the section height `WIDTH·ASPECT_RATIO` (the
//! size code's: a 205/60 tyre stands 0.6 × 205 mm off its rim). In SI,
//! the file's `[UNITS]` LENGTH converted. `tyre-eval` refuses a load
//! that, by the file's own vertical stiffness, pushes the tyre past it
//! (`jobs/tyre_eval/bottoming.rs`).

use super::{TirDocument, TirValue};
use crate::error::RimFrom;
use crate::tyre::mf::MfCoefficients;

impl TirDocument {
    /// The radius (m) at which the tyre of this file, read as `c`,
    /// bottoms on its rim, and the keys that give it; `None` where the
    /// file states neither `RIM_RADIUS` nor `WIDTH` and `ASPECT_RATIO`,
    /// or the radius is not below `UNLOADED_RADIUS`.
    pub fn rim(&self, c: &MfCoefficients) -> Option<RimFrom> {
        let length = self.units().ok()?.factor("WIDTH");
        let number = |key: &str| match self.get(key).map(|(_, e)| &e.value) {
            Some(TirValue::Number(x)) if x.is_finite() && *x >= 0.0 => Some(x * length),
            _ => None,
        };
        let from = match number("RIM_RADIUS").filter(|r| *r > 0.0) {
            Some(rim_radius) => RimFrom::RimRadius {
                rim_radius,
                bottom_offset: number("BOTTOM_OFFST").unwrap_or(0.0),
            },
            None if c.WIDTH > 0.0 && c.ASPECT_RATIO > 0.0 => RimFrom::SectionHeight {
                width: c.WIDTH,
                aspect_ratio: c.ASPECT_RATIO,
            },
            None => return None,
        };
        let deflection = from.deflection(c.UNLOADED_RADIUS);
        (deflection > 0.0 && deflection < c.UNLOADED_RADIUS).then_some(from)
    }
}
