//! A cornering stiffness whose size no tyre has against its static load:
//! most often one written in the other unit than its `[stiffness] unit`
//! (N/rad values, 20,000–70,000, under `unit = "N/deg"` make tyres 57 times
//! too stiff, N/deg values, 200–700, under `unit = "N/rad"` tyres 57 times
//! too soft; the study ran either without a word), or one given to
//! `Study::evaluate` under the other unit's argument. Judged on the
//! stiffness per unit of the tyre's static load (per rad): a road tyre's is
//! about 5–20, a light racing tyre's up to about 45; no tyre's is below 1
//! or above 100, and the factor of 57.3 between the units carries a tyre's
//! value across one of those bounds. A value no tyre has in either unit
//! (1e-300, 1e9) is said so, with the range a tyre of that load has.

use super::number::Num;
use crate::format::significant;
use std::fmt;

/// Below this stiffness per unit of static load, 1/rad, no tyre.
pub const LEAST_LOAD_STIFFNESS: f64 = 1.0;
/// Above this stiffness per unit of static load, 1/rad, no tyre.
pub const MOST_LOAD_STIFFNESS: f64 = 100.0;

/// Where a stiffness was given: what the refusal advises to write instead.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StiffnessGiven {
    /// A study file's key, under its `[stiffness] unit`.
    File,
    /// An argument whose name carries its unit (`front_n_per_deg`,
    /// `rear_n_per_rad`: `Study::evaluate_in`, Python's `Study.evaluate`).
    Argument,
}

/// The numbers of the refusal. N, N/rad.
#[derive(Debug, Clone, PartialEq)]
pub struct StiffnessSlip {
    /// The key, e.g. `stiffness.front` or `front_n_per_deg`.
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
    /// Where the value was given.
    pub given: StiffnessGiven,
}

impl StiffnessSlip {
    /// The stiffness per unit of static load, 1/rad.
    pub fn per_load(&self) -> f64 {
        self.value * self.to_si / self.load
    }

    /// The other unit and its N/rad per unit.
    fn other(&self) -> (&'static str, f64) {
        match self.unit {
            "N/deg" => ("N/rad", 1.0),
            _ => ("N/deg", 180.0 / std::f64::consts::PI),
        }
    }

    /// The words after "`key` = value": what the value is against the
    /// load, and what to write instead.
    pub fn against_load(&self) -> String {
        let si = self.value * self.to_si;
        let per_load = self.per_load();
        let (other, other_to_si) = self.other();
        let stiff = match per_load > MOST_LOAD_STIFFNESS {
            true => "stiffer",
            false => "softer",
        };
        let in_si = match self.to_si == 1.0 {
            true => ",".to_string(),
            false => format!(" is {} N/rad,", significant(si, 4)),
        };
        format!(
            "{} {} per tyre{in_si} {} times the {} tyre's static load ({} N) per rad, {stiff} than any tyre (a tyre's cornering stiffness is {}–{} times its load per rad; a road tyre's about 5–20){}",
            Num(self.value),
            self.unit,
            significant(per_load, 3),
            self.axle,
            significant(self.load, 4),
            LEAST_LOAD_STIFFNESS,
            MOST_LOAD_STIFFNESS,
            self.advice(other, other_to_si)
        )
    }

    /// What to write instead: the value in the other unit where it is a
    /// tyre's there, else the range a tyre of this load has.
    fn advice(&self, other: &'static str, other_to_si: f64) -> String {
        let read_other = self.value * other_to_si / self.load;
        if !(LEAST_LOAD_STIFFNESS..=MOST_LOAD_STIFFNESS).contains(&read_other) {
            let [lo, hi] = [LEAST_LOAD_STIFFNESS, MOST_LOAD_STIFFNESS]
                .map(|k| significant(k * self.load / self.to_si, 4));
            return format!(
                ", nor is it one in {other}: the {} tyre's lies within {lo}–{hi} {}",
                self.axle, self.unit
            );
        }
        let likely = significant(self.value * other_to_si / self.to_si, 4);
        match self.given {
            StiffnessGiven::File => format!(
                ": is the value in {other}? write `unit = \"{other}\"`, or give it in {} as {likely} {}",
                self.unit, self.unit
            ),
            StiffnessGiven::Argument => format!(
                ": is the value in {other}? give it as `{}` = {}, or as `{}` = {likely}",
                argument(self.axle, other),
                Num(self.value),
                self.key
            ),
        }
    }
}

/// The argument of `axle`'s stiffness in `unit` (`front_n_per_deg`).
pub fn argument(axle: &str, unit: &str) -> String {
    format!("{axle}_{}", unit.to_ascii_lowercase().replace('/', "_per_"))
}

impl fmt::Display for StiffnessSlip {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}` = {}", self.key, self.against_load())
    }
}
