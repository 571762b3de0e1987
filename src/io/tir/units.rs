//! The `[UNITS]` of a `.tir` file: the factor to SI of each dimensional
//! key the model reads (`FORCE`, `LENGTH`, `TIME`, `PRESSURE`; a file
//! without `PRESSURE` has its pressures in `FORCE/LENGTH²`), and where a
//! unit other than SI is declared, so that a value that is no tyre's once
//! converted but is one as written is said as the `[UNITS]` slip it is
//! (values in N under `FORCE = 'kilonewton'`), not as a value in the
//! wrong unit at its own line.

use super::TirDocument;
use crate::error::{
    DeclaredHow, InputError, InputProblem, Limit, NoPressureLine, ParamError, ParamReason,
};
use crate::tyre::mf::MagicFormula;
use crate::tyre::ModelParameters;

/// Where a `[UNITS]` key declares a unit other than SI: the key, its line
/// and the unit's usual name.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Declared {
    key: &'static str,
    line: usize,
    unit: &'static str,
}

/// Unit factors to SI of a file's `[UNITS]` section.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Units {
    length: f64,
    force: f64,
    time: f64,
    pressure: Option<f64>,
    /// The declarations of force, length and pressure other than SI.
    declared: [Option<Declared>; 3],
}

/// A `[UNITS]` key's table: the names a file may give a unit, its factor
/// to SI and its usual name.
type Table = [(&'static [&'static str], f64, &'static str)];

impl Units {
    /// SI throughout (a fresh file).
    pub(super) const SI: Units = Units {
        length: 1.0,
        force: 1.0,
        time: 1.0,
        pressure: None,
        declared: [None; 3],
    };

    /// The force unit values are read in: its usual name and N.
    fn force_unit(&self) -> (&'static str, f64) {
        (self.declared[0].map_or("N", |d| d.unit), self.force)
    }

    pub(super) fn factor(&self, key: &str) -> f64 {
        match key {
            "FNOMIN" | "FZMIN" | "FZMAX" => self.force,
            "UNLOADED_RADIUS" | "WIDTH" => self.length,
            "VERTICAL_STIFFNESS" => self.force / self.length,
            "Q_FYS1" | "Q_FYS2" | "Q_FYS3" => self.force,
            // Q_CAM1·Rl and Q_CAM2·Rl² are numbers.
            "Q_CAM1" => 1.0 / self.length,
            "Q_CAM2" => 1.0 / (self.length * self.length),
            "LONGVL" | "VXLOW" => self.length / self.time,
            "NOMPRES" | "INFLPRES" | "PRESMIN" | "PRESMAX" => self
                .pressure
                .unwrap_or(self.force / (self.length * self.length)),
            _ => 1.0,
        }
    }

    /// The one declaration other than SI that converts `key`'s value
    /// (none for a key converted by two, or by none), and how the key's
    /// unit follows from it: a stiffness is FORCE/LENGTH, and so is a
    /// pressure (per LENGTH²) where the file has no `PRESSURE` line.
    fn declaration(&self, key: &str) -> Option<(Declared, DeclaredHow)> {
        let how = |si, (before, after), no_pressure_line| DeclaredHow {
            si,
            around: (before, after),
            factor: self.factor(key),
            no_pressure_line,
        };
        // The one of FORCE and LENGTH declared other than SI, and what the
        // other puts around it (kN/m, N/mm, kN/m², N/mm²).
        let one = |over: &'static str, squared: &'static str| match self.declared[..2] {
            [Some(f), None] => Some((f, ("", over))),
            [None, Some(l)] => Some((l, ("N/", squared))),
            _ => None,
        };
        match key {
            "FNOMIN" | "FZMIN" | "FZMAX" | "Q_FYS1" | "Q_FYS2" | "Q_FYS3" => {
                self.declared[0].map(|d| (d, how("N", ("", ""), false)))
            }
            "UNLOADED_RADIUS" | "WIDTH" => self.declared[1].map(|d| (d, how("m", ("", ""), false))),
            "VERTICAL_STIFFNESS" => one("/m", "").map(|(d, a)| (d, how("N/m", a, false))),
            "NOMPRES" | "INFLPRES" | "PRESMIN" | "PRESMAX" => match self.pressure {
                Some(_) => self.declared[2].map(|d| (d, how("Pa", ("", ""), false))),
                None => one("/m²", "²").map(|(d, a)| (d, how("Pa", a, true))),
            },
            _ => None,
        }
    }

    /// The names of the force and length units values are read in.
    fn force_and_length(&self) -> (&'static str, &'static str) {
        (
            self.declared[0].map_or("N", |d| d.unit),
            self.declared[1].map_or("m", |d| d.unit),
        )
    }
}

/// The share of `FNOMIN` a `.tir`'s load range (`FZMIN`, `FZMAX`) lies
/// within: published files' `FZMAX` is 2–3.4 times it (all thirteen public
/// files and the fixtures), their `FZMIN` 0 or at least 1/300 of it; a load
/// written in N under `FORCE = 'kN'` (or in kN under N) lies 1000 times
/// off, beyond.
pub const LOAD_OVER_NOMINAL: (f64, f64) = (1e-3, 20.0);

impl TirDocument {
    /// Ok when the file's reference speed `LONGVL` (SI in `tyre`) is one a
    /// rig runs at, within [`crate::io::MAX_SPEED`] (the limit of a rig
    /// file's and a run's speed): a fit to a rig file in mm/s wrote
    /// `LONGVL = 11169.9`, which `tyre-eval` then read silently. Refused at
    /// the key's line.
    pub(super) fn reference_speed(&self, tyre: &MagicFormula) -> Result<(), InputError> {
        let v = tyre.coefficients.LONGVL;
        let limit = crate::io::MAX_SPEED;
        ParamError::in_range("LONGVL", v, 0.0, limit, Limit::ReferenceSpeed)
            .map_err(|e| self.value_error(e))
    }

    /// Ok when the file's load range (`FZMIN`, `FZMAX`, SI in `tyre`) lies
    /// within [`LOAD_OVER_NOMINAL`] of its `FNOMIN` (0 is no floor): a
    /// `FZMAX = 8000` (N) beside `FNOMIN = 4` under `FORCE = 'kN'` passes
    /// every size check (8 MN is only a range) yet is no tyre's; refused
    /// at the key's line with the value, the unit it is read in, and the
    /// factor it lies off `FNOMIN`.
    pub(super) fn loads_against_nominal(
        &self,
        tyre: &MagicFormula,
        units: &Units,
    ) -> Result<(), InputError> {
        let fnomin = tyre.coefficients.FNOMIN;
        let (lo, hi) = LOAD_OVER_NOMINAL;
        for key in ["FZMIN", "FZMAX"] {
            let (Some(v), Some((line, _))) = (tyre.limits.get(key), self.get(key)) else {
                continue;
            };
            let ratio = v / fnomin;
            if ratio == 0.0 || (lo..=hi).contains(&ratio) {
                continue;
            }
            let (unit, factor) = units.force_unit();
            let reason = ParamReason::tir_load_off_nominal(
                v / factor,
                (unit, factor),
                (fnomin / factor, ratio),
                ((lo, hi), key == "FZMAX"),
            );
            let e = ParamError::new(key, v / factor, reason);
            return Err(self.at(line, InputProblem::TirValue(e)));
        }
        Ok(())
    }

    /// The unit of `[UNITS]` key `key` by `table`: its factor, and where it
    /// is other than SI, its declaration; `None` when the file gives none.
    fn unit(
        &self,
        key: &'static str,
        table: &Table,
    ) -> Result<Option<(f64, Option<Declared>)>, InputError> {
        let Some((line, name)) = self.text(key) else {
            return Ok(None);
        };
        let name = name.replace(' ', "_");
        let (_, factor, unit) = table
            .iter()
            .find(|(names, _, _)| names.contains(&name.as_str()))
            .ok_or_else(|| self.at(line, InputProblem::TirUnknownUnit { key, unit: name }))?;
        let declared = (*factor != 1.0).then_some(Declared { key, line, unit });
        Ok(Some((*factor, declared)))
    }

    pub(super) fn units(&self) -> Result<Units, InputError> {
        let (length, at_length) = self
            .unit(
                "LENGTH",
                &[
                    (&["meter", "metre", "m", "meters"], 1.0, "m"),
                    (&["mm", "millimeter", "millimetre"], 1e-3, "mm"),
                    (&["cm", "centimeter", "centimetre"], 1e-2, "cm"),
                    (&["km", "kilometer"], 1e3, "km"),
                    (&["inch", "in"], 0.0254, "inches"),
                    (&["foot", "feet", "ft"], 0.3048, "feet"),
                ],
            )?
            .unwrap_or((1.0, None));
        let (force, at_force) = self
            .unit(
                "FORCE",
                &[
                    (&["newton", "n", "newtons"], 1.0, "N"),
                    (&["kn", "kilonewton", "kilo_newton"], 1e3, "kN"),
                    (&["pound_force", "lbf", "pound"], 4.448_221_615_260_5, "lbf"),
                    (&["kg_force", "kgf"], 9.806_65, "kgf"),
                ],
            )?
            .unwrap_or((1.0, None));
        let (time, _) = self
            .unit(
                "TIME",
                &[
                    (&["second", "sec", "s", "seconds"], 1.0, "s"),
                    (&["millisecond", "ms"], 1e-3, "ms"),
                    (&["minute", "min"], 60.0, "minutes"),
                    (&["hour", "h"], 3600.0, "hours"),
                ],
            )?
            .unwrap_or((1.0, None));
        let pressure = self.unit(
            "PRESSURE",
            &[
                (&["pascal", "pa", "n/m2", "n/m^2"], 1.0, "Pa"),
                (&["kpa", "kilopascal"], 1e3, "kPa"),
                (&["mpa", "megapascal"], 1e6, "MPa"),
                (&["bar"], 1e5, "bar"),
                (&["psi"], 6_894.757_293_168, "psi"),
            ],
        )?;
        if let Some((line, a)) = self.text("ANGLE") {
            if !["radians", "radian", "rad"].contains(&a.as_str()) {
                return Err(self.at(line, InputProblem::TirAngleNotRadians { unit: a }));
            }
        }
        Ok(Units {
            length,
            force,
            time,
            pressure: pressure.map(|p| p.0),
            declared: [at_force, at_length, pressure.and_then(|p| p.1)],
        })
    }

    /// `e`, a refusal of `tyre`'s value at `e.key` that is out of its
    /// range, said as the `[UNITS]` slip it is where the key's unit is
    /// declared other than SI and the value as written passes the checks
    /// of its key read in SI (values in N under `FORCE = 'kilonewton'`,
    /// in metres under `LENGTH = 'mm'`); else `e` as it is (a file that
    /// declares metres and writes millimetres keeps the value's own hint).
    pub(super) fn declared_slip(
        &self,
        tyre: &MagicFormula,
        units: &Units,
        e: ParamError,
    ) -> ParamError {
        let (Some((d, how)), Some(v), ParamReason::OutOfRange { lo, hi, .. }) =
            (units.declaration(&e.key), e.value.number(), &e.reason)
        else {
            return no_pressure_line(units, e);
        };
        let written = v / units.factor(&e.key);
        let mut as_written = tyre.clone();
        if !as_written.coefficients.set(&e.key, written) {
            as_written.limits.set(&e.key, written);
        }
        let still = as_written
            .validate()
            .and_then(|()| ModelParameters::check_sizes(&as_written))
            .is_err_and(|f| f.key == e.key);
        if still {
            return no_pressure_line(units, e);
        }
        let reason =
            ParamReason::tir_declared_unit(written, d.line, (d.key, d.unit), (*lo, *hi), how);
        ParamError::new(&e.key, v, reason)
    }
}

/// `e`, a pressure refused with no unit it is likely in, said as read in
/// `FORCE/LENGTH²` for want of a `[UNITS] PRESSURE` line where the file
/// has none (the refusal's own words blame that line); else `e`.
fn no_pressure_line(units: &Units, e: ParamError) -> ParamError {
    let ParamReason::OutOfRange {
        lo,
        hi,
        why: Limit::TyrePressure { unit: None, .. },
    } = e.reason
    else {
        return e;
    };
    let key = match e.key.as_str() {
        "NOMPRES" => "NOMPRES",
        "INFLPRES" => "INFLPRES",
        _ => return e,
    };
    if units.pressure.is_some() {
        return e;
    }
    let reason = ParamReason::TirPressureNoLine(Box::new(NoPressureLine {
        key,
        units: units.force_and_length(),
        pa: units.factor(key),
        range: (lo, hi),
    }));
    let v = e.value.number().unwrap_or(f64::NAN);
    ParamError::new(key, v, reason)
}
