//! A study file's cornering stiffness whose size says it is written in the
//! other unit than its `[stiffness] unit`: N/rad values (20,000–70,000)
//! under `unit = "N/deg"` make tyres 57 times too stiff, N/deg values
//! (200–700) under `unit = "N/rad"` tyres 57 times too soft, and the study
//! ran either without a word. Judged on the stiffness per unit of the
//! tyre's static load (per rad): a road tyre's is about 5–20, a light
//! racing tyre's up to about 45; no tyre's is below 1 or above 100, and the
//! factor of 57.3 between the units carries a tyre's value across one of
//! those bounds.

use super::number::Num;
use crate::format::significant;
use std::fmt;

/// Below this stiffness per unit of static load, 1/rad, no tyre.
pub const LEAST_LOAD_STIFFNESS: f64 = 1.0;
/// Above this stiffness per unit of static load, 1/rad, no tyre.
pub const MOST_LOAD_STIFFNESS: f64 = 100.0;

/// The numbers of the refusal. N, N/rad.
#[derive(Debug, Clone, PartialEq)]
pub struct StiffnessSlip {
    /// The key, e.g. `stiffness.front`.
    pub key: Box<str>,
    /// The value as written, in the file's unit.
    pub value: f64,
    /// The file's unit as written (`N/deg` or `N/rad`).
    pub unit: &'static str,
    /// N/rad per file unit.
    pub to_si: f64,
    /// The axle (`front` or `rear`).
    pub axle: &'static str,
    /// The tyre's static load, N.
    pub load: f64,
}

impl StiffnessSlip {
    /// The stiffness per unit of static load, 1/rad.
    pub fn per_load(&self) -> f64 {
        self.value * self.to_si / self.load
    }
}

impl fmt::Display for StiffnessSlip {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let si = self.value * self.to_si;
        let per_load = self.per_load();
        let (other, other_to_si) = match self.unit {
            "N/deg" => ("N/rad", 1.0),
            _ => ("N/deg", 180.0 / std::f64::consts::PI),
        };
        let likely = self.value * other_to_si / self.to_si;
        let stiff = match per_load > MOST_LOAD_STIFFNESS {
            true => "stiffer",
            false => "softer",
        };
        let in_si = match self.to_si == 1.0 {
            true => ",".to_string(),
            false => format!(" is {} N/rad,", significant(si, 4)),
        };
        write!(
            f,
            "`{}` = {} {} per tyre{in_si} {} times the {} tyre's static load ({} N) per rad, {stiff} than any tyre (a tyre's cornering stiffness is {}–{} times its load per rad; a road tyre's about 5–20): is the value in {other}? write `unit = \"{other}\"`, or give it in {} as {} {}",
            self.key,
            Num(self.value),
            self.unit,
            significant(per_load, 3),
            self.axle,
            significant(self.load, 4),
            LEAST_LOAD_STIFFNESS,
            MOST_LOAD_STIFFNESS,
            self.unit,
            significant(likely, 4),
            self.unit
        )
    }
}
