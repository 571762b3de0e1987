//! A `tyre-eval` points column read in another unit than FORMATS.md's: a
//! slip angle in degrees or a slip ratio in percent, told from the values
//! by the rule of `jobs/tyre_eval/other_unit.rs`, and a column beside it
//! that states its own unit (`sa_deg` beside `alpha`) holding another
//! value on a row. Values as read; SI (rad, a fraction) where the format
//! asks for it; the messages print degrees where people read them so.

use super::header_unit::Unit;
use super::number::Num;
use crate::format::{readable, rounded};
use thiserror::Error;

/// A points column whose values read as written in another unit, or
/// disagree with a column beside it that states its unit.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum PointsUnit {
    /// Every value a round number in the other unit, reaching where no
    /// rig sweeps in SI, with none of the small values a sweep in SI puts
    /// beside its far ones.
    #[error("column `{column}`: {} here, the column's largest |{column}|, {}, while every one of its {values} values is a round number of {} (a multiple of 0.05) and none but 0 is within {} ({}), where a sweep in {} puts its small slips: read in {}, it reaches {}. {}", Num(*value), beyond(column, *value, *reach), unit_words(*unit), Num(*small), small_words(column, *small), si_words(column), unit_words(*unit), written(*value, *unit), advice(column, *unit))]
    OtherUnit {
        /// The column (`alpha`, `kappa`).
        column: &'static str,
        /// The unit its values read in (degrees, percent).
        unit: Unit,
        /// Its value of the largest magnitude, as read.
        value: f64,
        /// The values judged.
        values: usize,
        /// The SI value beyond which no rig sweeps (rad, a fraction).
        reach: f64,
        /// The SI value within which a sweep in SI puts its small slips.
        small: f64,
    },
    /// A column stating its unit (`sa_deg`) beside the column itself,
    /// whose value on a row is not the column's within its rounding.
    #[error("column `{beside}`: {} beside `{column}` = {} on this row ({} in `{beside}`'s unit): they differ by more than the {} `{beside}` is written to{}; `tyre-eval` reads `{column}` ({}, FORMATS.md) and not `{beside}`: which one holds the {}? Mend the one that is wrong, or leave `{beside}` out", written(*beside_value, *unit), written(*value, column_unit(column)), written(*value / unit_factor(*unit), *unit), written(*rounding, *unit), same_number(column, beside, *value, *beside_value), si_words(column), quantity_words(column))]
    BesideDisagrees {
        /// The column read (`alpha`, `camber`, `kappa`).
        column: &'static str,
        /// The header of the column beside it.
        beside: Box<str>,
        /// The unit the header states for it.
        unit: Unit,
        /// The column's value on the row, as read (SI).
        value: f64,
        /// The beside column's value on the row, as read.
        beside_value: f64,
        /// The rounding the beside column is written to, in its unit.
        rounding: f64,
    },
}

/// The factor from `unit` to SI (rad, a fraction): 1 for an SI unit.
pub fn unit_factor(unit: Unit) -> f64 {
    match unit {
        Unit::Degree => 1f64.to_radians(),
        Unit::Percent => 0.01,
        _ => 1.0,
    }
}

/// The SI unit of `column`: rad for an angle, none for a slip ratio.
fn column_unit(column: &str) -> Unit {
    match column {
        "kappa" => Unit::One,
        _ => Unit::Radian,
    }
}

/// `v` with its unit as a user writes it: `5°`, `5 %`, `0.05 rad`, `0.05`.
fn written(v: f64, unit: Unit) -> String {
    let n = rounded(v, 4);
    match unit {
        Unit::Degree => format!("{n}°"),
        Unit::Percent => format!("{n} %"),
        Unit::Radian => format!("{n} rad"),
        _ => n,
    }
}

/// The other unit, plural.
fn unit_words(unit: Unit) -> &'static str {
    match unit {
        Unit::Percent => "percent",
        _ => "degrees",
    }
}

/// The SI unit of `column`, in words.
fn si_words(column: &str) -> &'static str {
    match column {
        "kappa" => "fractions",
        _ => "radians",
    }
}

/// What `column` holds, in words.
fn quantity_words(column: &str) -> &'static str {
    match column {
        "kappa" => "slip ratio",
        "camber" => "camber",
        _ => "slip angle",
    }
}

/// The small value `small` of `column` read in SI, in words.
fn small_words(column: &str, small: f64) -> String {
    match column {
        "kappa" => format!("{} %", readable(100.0 * small, 3)),
        _ => format!("{}°", readable(small.to_degrees(), 3)),
    }
}

/// Where `value` of `column` lies read in SI, beyond `reach`.
fn beyond(column: &str, value: f64, reach: f64) -> String {
    match column {
        "kappa" => format!("is beyond ±{} read as a slip ratio (below −1 the wheel turns backwards while the car rolls forwards, above 1 it spins at more than twice the road speed; rigs sweep to about ±0.3)", Num(reach)),
        _ => format!(
            "is {}° read in radians, beyond the {}° ({} rad) past which no rig sweeps and every tyre's force has peaked",
            readable(value.to_degrees(), 3),
            readable(reach.to_degrees(), 2),
            Num(reach)
        ),
    }
}

/// What to do with a column in `unit`, or in SI.
fn advice(column: &str, unit: Unit) -> String {
    let (si, header) = match column {
        "kappa" => ("a slip ratio is a fraction", "kappa [-]"),
        _ => ("angles are in radians", "alpha [rad]"),
    };
    format!(
        "{} (FORMATS.md): is the column in {}? Convert it ({}); if it is in {}, say so in the header: `{header}`",
        capital(si),
        unit_words(unit),
        unit.conversion(),
        si_words(column)
    )
}

/// `s` with its first letter in capitals.
fn capital(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map_or_else(String::new, |f| f.to_uppercase().chain(c).collect())
}

/// Where the two values are the same number: the column holds the beside
/// column's unit too.
fn same_number(column: &str, beside: &str, value: f64, beside_value: f64) -> String {
    match (value - beside_value).abs() <= 1e-9 * value.abs().max(1.0) {
        true => format!(" (`{column}` holds the same number as `{beside}`: is `{column}` in `{beside}`'s unit too?)"),
        false => String::new(),
    }
}
