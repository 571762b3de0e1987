//! A load past the one at which a Magic Formula tyre, by its own vertical
//! stiffness, deflects onto its rim: the rim, not the tyre, carries it
//! there, and MF-Tyre's bottoming (`BOTTOM_STIFF`), which MFeval does not
//! model, would take over. The rim is at `RIM_RADIUS + BOTTOM_OFFST`, or,
//! for a file without `RIM_RADIUS`, a section height `WIDTH·ASPECT_RATIO`
//! inside `UNLOADED_RADIUS` (`io/tir/rim.rs`). Units: N, m.

use crate::format::{rounded, significant};
use std::fmt;

/// Where a `.tir` puts the rim, with the keys that say it (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RimFrom {
    /// `RIM_RADIUS` and `BOTTOM_OFFST` (0 where absent), m.
    RimRadius {
        /// `RIM_RADIUS`, m.
        rim_radius: f64,
        /// `BOTTOM_OFFST`, m.
        bottom_offset: f64,
    },
    /// No `RIM_RADIUS`: the section height `WIDTH·ASPECT_RATIO`.
    SectionHeight {
        /// `WIDTH`, m.
        width: f64,
        /// `ASPECT_RATIO`.
        aspect_ratio: f64,
    },
}

impl RimFrom {
    /// The deflection (m) from `unloaded_radius` at which the tread
    /// meets the rim.
    pub fn deflection(&self, unloaded_radius: f64) -> f64 {
        match *self {
            RimFrom::RimRadius {
                rim_radius,
                bottom_offset,
            } => unloaded_radius - rim_radius - bottom_offset,
            RimFrom::SectionHeight {
                width,
                aspect_ratio,
            } => width * aspect_ratio,
        }
    }
}

impl fmt::Display for RimFrom {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            RimFrom::RimRadius {
                rim_radius,
                bottom_offset,
            } => write!(
                f,
                "its rim (RIM_RADIUS + BOTTOM_OFFST = {} + {} m)",
                rounded(rim_radius, 4),
                rounded(bottom_offset, 4)
            ),
            RimFrom::SectionHeight {
                width,
                aspect_ratio,
            } => write!(
                f,
                "its rim (a section height WIDTH·ASPECT_RATIO = {} m × {} inside UNLOADED_RADIUS; the file has no RIM_RADIUS)",
                rounded(width, 4),
                rounded(aspect_ratio, 4)
            ),
        }
    }
}

/// The load at which the tyre deflects onto its rim, standing and free of
/// force at the point's pressure, for a point whose load is past it (and
/// past the file's `FZMAX`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bottoming {
    /// Where the rim is.
    pub rim: RimFrom,
    /// `UNLOADED_RADIUS`, m.
    pub unloaded_radius: f64,
    /// The load at which the tread meets the rim, N.
    pub load: f64,
    /// The file's `FZMAX`, N, where it states one.
    pub fz_max: Option<f64>,
}

impl fmt::Display for Bottoming {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let deflection = self.rim.deflection(self.unloaded_radius);
        let fz_max = match self.fz_max {
            Some(m) if m > 0.0 => format!(
                ", {} × its FZMAX of {} N",
                significant(self.load / m, 3),
                rounded(m, 6)
            ),
            _ => String::new(),
        };
        write!(
            f,
            "by its own vertical stiffness, standing at this point's pressure, it reaches {} under {} N (a deflection of {} m from UNLOADED_RADIUS {} m){fz_max}; past it the rim, not the tyre, carries the load",
            self.rim,
            rounded(self.load, 4),
            rounded(deflection, 4),
            rounded(self.unloaded_radius, 5),
        )
    }
}
