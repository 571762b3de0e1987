//! The rig file's grouping variables (load, camber, pressure), named by the
//! errors of a request no level matches and by the grouping of rig data
//! into test conditions. Units: SI inside (N, rad, Pa); printed in the
//! units people read them in (N, degrees, kPa).

use crate::format::fixed;
use serde::Serialize;

/// The smallest median load of a tyre test, N: a bicycle tyre carries
/// 300–800 N, a car tyre's loads written in kN are 1–10.
pub const MIN_MEDIAN_LOAD: f64 = 100.0;

/// The smallest median inflation pressure of a tyre test, Pa (0.1 bar):
/// a pressure written in kPa, bar or psi reads 1–1000.
pub const MIN_MEDIAN_PRESSURE: f64 = 1e4;

/// The pressures a pneumatic tyre is inflated to, Pa: a racing slick's
/// 55 kPa (8 psi) to a truck's 900 kPa, rounded outwards. A value of a
/// few units is read in the first of kPa, bar and psi that lands it here
/// (`io/rig_rows.rs`, and a `--pressure` no level lies near).
pub const INFLATION_PRESSURES: [f64; 2] = [50e3, 1e6];

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

    /// A value in the unit its option takes, with the unit people read it
    /// in beside where they differ: `0.0279 rad (1.60°)`, `2193 N`.
    pub fn in_option_unit(self, v: f64) -> String {
        match self {
            Variable::Camber => format!("{} rad ({})", fixed(v, 4), self.display(v)),
            _ => self.display(v),
        }
    }

    /// Whether a request (SI) is no tyre test's in the option's unit at
    /// all: a load under any test's, a camber past ±45°, a pressure under
    /// 0.1 bar. Such a request is answered with its likeliest other unit
    /// even where that selects no level.
    pub fn implausible(self, v: f64) -> bool {
        match self {
            Variable::Load => v.abs() < MIN_MEDIAN_LOAD,
            Variable::Camber => v.abs() > std::f64::consts::FRAC_PI_4,
            Variable::Pressure => v.abs() < MIN_MEDIAN_PRESSURE,
        }
    }
}
