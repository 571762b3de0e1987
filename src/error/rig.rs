//! The rig file's grouping variables (load, camber, pressure), named by the
//! errors of a request no level matches and by the grouping of rig data
//! into test conditions. Units: SI inside (N, rad, Pa); printed in the
//! units people read them in (N, degrees, kPa).

use crate::format::fixed;
use serde::Serialize;

/// A grouping variable of rig data.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Variable {
    /// Vertical load, N.
    Load,
    /// Inclination angle, rad.
    Camber,
    /// Inflation pressure, Pa.
    Pressure,
}

impl Variable {
    /// Column name in the rig file.
    pub fn column(self) -> &'static str {
        match self {
            Variable::Load => "fz",
            Variable::Camber => "camber",
            Variable::Pressure => "pressure",
        }
    }
    /// A value in the unit people read it in.
    pub fn display(self, v: f64) -> String {
        match self {
            Variable::Load => format!("{} N", fixed(v, 0)),
            Variable::Camber => format!("{}°", fixed(v.to_degrees(), 2)),
            Variable::Pressure => format!("{} kPa", fixed(v / 1000.0, 1)),
        }
    }
}
