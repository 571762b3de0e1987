//! A request for a rig file's level (`identify --load`, `--camber`,
//! `--pressure`) that no level lies near, but that would select one read
//! in the unit people write the variable in: a load in kN, a camber in
//! degrees, a pressure in kPa, bar or psi, where the options take N, rad
//! and Pa. A conversion is offered where it selects a level, or where
//! the request is no tyre test's in the option's unit (`--camber 2`, 115°):
//! then saying it selects no level either, so the hint never points at a
//! value the file does not have.

use super::rig::Variable;

/// A request no level lies near that would select one in the unit people
/// write the variable in: a load in kN, a camber in degrees, a pressure in
/// kPa, bar or psi, where the option takes N, rad and Pa.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelSlip {
    /// The request converted to SI from `unit`.
    pub meant: f64,
    /// The unit the request reads as: `kN`, `°`, `kPa`, `bar`, `psi`.
    pub unit: &'static str,
    /// The nominal value (SI) of the level `meant` selects (`None`: it
    /// selects none, offered because the request is no test's in SI).
    pub level: Option<f64>,
}

/// The units a request of `variable` may have been written in, each with
/// its factor to SI, most likely first.
pub fn unit_slips(variable: Variable) -> &'static [(&'static str, f64)] {
    match variable {
        Variable::Load => &[("kN", 1e3)],
        Variable::Camber => &[("°", std::f64::consts::PI / 180.0)],
        Variable::Pressure => &[("kPa", 1e3), ("bar", 1e5), ("psi", 6894.757)],
    }
}

/// The request as typed, in SI, and in the unit people read it in where
/// that differs: `1.65 N`, `2 rad (114.59°)`, `83 Pa (0.1 kPa)`.
pub(super) fn requested(variable: Variable, v: f64) -> String {
    let (si, shown) = (super::number::number(v), variable.display(v));
    match variable {
        Variable::Load => format!("{si} N"),
        Variable::Camber => format!("{si} rad ({shown})"),
        // Three significant digits in kPa: 12 Pa is 0.012 kPa, not the
        // level lines' "0.0 kPa".
        Variable::Pressure => format!("{si} Pa ({} kPa)", crate::format::rounded(v / 1e3, 3)),
    }
}

/// The levels a request was not near, in the option's unit; a file with
/// none said so ("levels: ;" read as a word left out).
pub(super) fn level_list(variable: Variable, levels: &[f64]) -> String {
    if levels.is_empty() {
        return format!(
            "none, too few samples at any one {} to make one",
            variable.column()
        );
    }
    let listed: Vec<String> = levels.iter().map(|v| variable.in_option_unit(*v)).collect();
    listed.join(", ")
}

/// The question whether the request was written in another unit, where
/// it would then select a level ([`LevelSlip`]); else nothing.
pub(super) fn unit_slip(variable: Variable, requested: f64, slip: &Option<LevelSlip>) -> String {
    let Some(s) = slip else {
        return String::new();
    };
    let si = match variable {
        Variable::Load => "N",
        Variable::Camber => "rad",
        Variable::Pressure => "Pa",
    };
    let gap = if s.unit == "°" { "" } else { " " };
    let selects = match s.level {
        Some(level) => format!(", which selects the {} level?", variable.display(level)),
        None => "? no level lies near that either".into(),
    };
    // A pressure converted from psi to whole pascals (12 psi is 82737 Pa,
    // not 82737.084): finer than any rig's pressure reading.
    let meant = match variable {
        Variable::Pressure => crate::format::fixed(s.meant, 0),
        _ => super::number::number(s.meant),
    };
    format!(
        "; the value is read in {si}: did you mean {meant} {si} ({}{gap}{}){selects}",
        super::number::number(requested),
        s.unit,
    )
}

/// The question whether a request of `variable` for a file without its
/// column was written in another unit, where the request is no tyre
/// test's in the option's (`--camber 2`, 114.59°): the hint a request
/// between a file's levels gets, naming no level (the file has none).
pub(super) fn no_column_slip(variable: Variable, requested: f64) -> String {
    let (unit, factor) = unit_slips(variable)[0];
    let slip = variable.implausible(requested).then_some(LevelSlip {
        meant: requested * factor,
        unit,
        level: None,
    });
    unit_slip(variable, requested, &slip)
}
