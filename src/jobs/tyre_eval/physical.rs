//! The range each input of `tyre-eval` must lie in ([`PHYSICAL`]): a
//! value outside it is no tyre's state (a load beyond ±1 MN, a slip ratio
//! beyond ±10, a slip angle beyond ±90° or a camber beyond ±45°, said as
//! degrees where it reads as an angle in degrees, a speed beyond 300 m/s
//! or below 0, a pressure above 5 MPa), and is refused at its cell before
//! anything is evaluated; and every negative load, at its cell, as
//! `identify` refuses a rig file's (a file whose every load is negative
//! said as a rig in SAE's axes); a point at zero load is a wheel off the
//! road, evaluated with no force.
//!
//! A camber is refused by the one rule `identify` refuses a rig's by, in
//! the same words (`error/camber.rs`): beyond ±45° ([`MOST_CAMBER`],
//! steeper than any car tyre runs; 1.2 meant as degrees reads as 69°),
//! and beyond ±20° ([`STEEP_CAMBER`]) where every camber of the column
//! other than 0 lies there — no car tyre is tested only at cambers steeper
//! than any public `.tir`'s range (the steepest, `CAMMAX` 0.264 rad =
//! 15.1°), as a column in degrees reads (0.5 meant as 0.5° reads as
//! 28.6°). A column with a camber within ±20° beside steeper ones is in
//! radians: its steep points are evaluated, a `.tir` holding them to its
//! `CAMMIN`/`CAMMAX` with a warning as MFeval does (`ranges.rs`), a model
//! with no camber range saying them (`camber.rs`).
//!
//! That camber rule is one row of the rule a column read in another unit
//! is told by (`other_unit.rs`), whose header stating radians (`camber
//! [rad]`) reads it as written. A slip angle is not asked by the camber's
//! row: points only in the sliding range (30–80°, where a curvature makes
//! the force reverse) are a tyre's state as much as a sweep through 0 is;
//! its own row asks a round sweep in degrees (`other_unit.rs`).

use crate::constants::MOST_PRESSURE;
use crate::error::{InputProblem, MOST_CAMBER, STEEP_CAMBER};
use std::f64::consts::FRAC_PI_2;

/// The range each input column of `tyre-eval` must lie in: (column, low
/// end, high end, unit, what the ends are). Ends included.
pub const PHYSICAL: [(&str, f64, f64, &str, &str); 6] = [
    ("fz", -1e6, 1e6, "N", "1 MN, above any tyre's load"),
    (
        "kappa",
        -10.0,
        10.0,
        "",
        "±10: a wheel spinning forwards at eleven times the road speed, or backwards at nine times it",
    ),
    (
        "alpha",
        -FRAC_PI_2,
        FRAC_PI_2,
        "rad",
        "beyond it the wheel rolls backwards",
    ),
    (
        "camber",
        -MOST_CAMBER,
        MOST_CAMBER,
        "rad",
        "steeper than any car tyre runs, as `identify` refuses a rig's",
    ),
    (
        "speed",
        0.0,
        300.0,
        "m/s",
        "1080 km/h, above any pneumatic tyre's speed",
    ),
    (
        "pressure",
        0.0,
        MOST_PRESSURE,
        "Pa",
        "5 MPa, above any pneumatic tyre's inflation",
    ),
];

/// The low and high ends of column `name`'s [`PHYSICAL`] range.
pub(super) fn range_of(name: &str) -> Option<(f64, f64)> {
    PHYSICAL.iter().find(|p| p.0 == name).map(|p| (p.1, p.2))
}

/// Every value of `values` (column `name`) outside its [`PHYSICAL`]
/// range, a speed within it below 0, and every negative load: its row
/// and the problem. A camber column whose header `stated` radians is not
/// asked as degrees within ±45°.
pub(super) fn not_physical(name: &str, values: &[f64], stated: bool) -> Vec<(usize, InputProblem)> {
    let Some(&(column, lo, hi, unit, why)) = PHYSICAL.iter().find(|p| p.0 == name) else {
        return Vec::new();
    };
    // Every load below 0 is a sign convention, not wheels off the road: a
    // rig whose z axis points down (SAE's, TTC's) logs them so, and
    // evaluating them would write all-zero forces and exit 0. Said as
    // `identify` says it of a rig file (`io/rig.rs`).
    let finite = || values.iter().filter(|v| v.is_finite());
    let every = name == "fz" && finite().count() > 0 && finite().all(|v| *v < 0.0);
    let camber_degrees = name == "camber" && !stated && steep_only(values);
    let refused = |(i, &value): (usize, &f64)| {
        let problem = if name == "speed" && value < 0.0 {
            // A slip angle within ±90° already says the wheel rolls
            // forwards (ISO 8855): the speed is its size.
            InputProblem::NegativeSpeed { value }
        } else if unit == "rad" && in_degrees(value, hi) {
            InputProblem::AngleInDegrees {
                column,
                value,
                limit: hi,
            }
        } else if camber_degrees && (STEEP_CAMBER..=hi).contains(&value.abs()) {
            InputProblem::AngleInDegrees {
                column,
                value,
                limit: STEEP_CAMBER,
            }
        } else if !(lo..=hi).contains(&value) {
            InputProblem::NotPhysical {
                column,
                value,
                lo,
                hi,
                unit,
                why,
            }
        } else if name == "fz" && value < 0.0 {
            // A load below 0 is no wheel's: one off the road is at 0. A
            // row of -4000 N among positive loads was evaluated as off the
            // road, with zero forces, and only counted.
            InputProblem::NegativeLoad { value, every }
        } else {
            return None;
        };
        Some((i, problem))
    };
    // A cell that is no finite number is said as such by the reader.
    values
        .iter()
        .enumerate()
        .filter(|(_, v)| v.is_finite())
        .filter_map(refused)
        .collect()
}

/// Whether a camber column reads as degrees by its row of the rule
/// (`other_unit.rs`: every tilt other than 0 steeper than 20°, as
/// `identify`'s `camber_in_degrees`), its finite values judged.
fn steep_only(values: &[f64]) -> bool {
    let finite: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
    super::other_unit::rule_of("camber").is_some_and(|r| r.reads_other(&finite))
}

/// Whether an angle beyond `limit` (rad) reads as one in degrees: more
/// than 1° past it (a hair past 90° is 90° rounded, said as such) and
/// within it in degrees, as `identify` says of its rig files.
fn in_degrees(value: f64, limit: f64) -> bool {
    let v = value.abs();
    v > limit + 1f64.to_radians() && v.to_radians() <= limit
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 0.5 and −0.4 beside 0 read as degrees; beside 0.1 (5.7°, a car's
    /// camber) they are steep cambers in radians; 0.3 rad (17°, just past
    /// a `.tir`'s range) alone, too.
    #[test]
    fn a_camber_column_reads_as_degrees_only_where_no_camber_is_a_cars() {
        let asked = not_physical("camber", &[0.0, 0.5, -0.4], false);
        assert_eq!(asked.len(), 2, "{asked:?}");
        assert!(matches!(
            asked[0],
            (1, InputProblem::AngleInDegrees { value: 0.5, .. })
        ));
        assert!(not_physical("camber", &[0.1, 0.5, -0.4], false).is_empty());
        assert!(not_physical("camber", &[0.0, 0.3, -0.3], false).is_empty());
        assert!(not_physical("camber", &[0.0, 0.0], false).is_empty());
        // Stated in radians (`camber [rad]`): read as written.
        assert!(not_physical("camber", &[0.0, 0.5, -0.4], true).is_empty());
        // A slip angle is not asked by the camber's rule: points past 20° are read.
        assert!(not_physical("alpha", &[0.0, 0.05, 0.5], false).is_empty());
    }
}
