//! Whether a points column of `tyre-eval` is written in another unit than
//! FORMATS.md's SI: a slip angle or a camber in degrees. One rule, one
//! place, for both columns ([`RULES`]): a column reads as written in
//! degrees where, read in radians,
//! 1. some value lies beyond `reach`, where no rig sweeps (a slip angle
//!    past 34°, where every tyre's force has peaked; a camber past 20°,
//!    steeper than any `.tir`'s range);
//! 2. no value other than 0 lies within `small`, the small slips a sweep
//!    in radians puts beside its far ones (0.05 rad = 2.9° of slip; for
//!    the camber, 20°: a car's camber beside steep ones says radians); in
//!    degrees such a value is finer than any sweep's step (0.05°);
//! 3. where the far values are a state a tyre reaches (a sliding tyre's
//!    slip angle), every value is a round number of degrees, a multiple
//!    of 0.05 (the steps people sweep by: 0.1, 0.25, 0.5, 1), and more
//!    than half of the non-zero ones lie past 20° (0.35 rad), where every
//!    tyre has peaked: points in radians ask most of their slips short of
//!    it (MFeval's reference points 0, 0.1, −0.35, 1.2 rad). A camber
//!    past 20° is no car's state: a column of them all is degrees, round
//!    or not.
//!
//! So a sweep written in degrees (−1.5 to 1.5 by 0.1, read in radians
//! ±86°) and 0.25, 0.5, 1, 1.5, −1 meant as degrees are refused, while
//! points asked only in the sliding range, computed in radians (0.698 and
//! 1.047 rad for 40° and 60°: `pac89_bounds`), and a small slip beside far
//! ones (0.05 and 1.2 rad, probing a `.tir`'s `ALPMAX`) are read. Values
//! beyond the physical range (`physical.rs`) are refused at their cells
//! there and not judged here.
//!
//! A slip ratio in percent is not refused by this rule: round slip ratios
//! past lock with no small one beside are asked on purpose (10, a wheel
//! spinning up: `trips_s72_tyre`; MFeval's reference points to ±1.8), so
//! such a column is warned of (`slip_ratio.rs`), not refused.
//!
//! A header that states the column's SI unit (`alpha [rad]`, `camber
//! [rad]`), or a column beside it stating its own unit that agrees with it
//! on every row (`sa_deg`: `beside.rs`), is the user's word: the column is
//! read as written. The slip angle is refused as a column, at the row of
//! the value farthest from 0; the camber at each steep cell, as `identify`
//! refuses a rig's.

use crate::error::{InputProblem, PointsUnit, Unit, STEEP_CAMBER};

/// How a column reads in its other unit: the column, that unit, the SI
/// `reach` beyond which no rig sweeps, the SI `small` within which a
/// sweep in SI puts its small slips, and whether the values must be round
/// in the other unit (their far values a state a tyre reaches).
pub(super) struct Rule {
    pub(super) column: &'static str,
    unit: Unit,
    reach: f64,
    small: f64,
    round: bool,
}

/// The rules of the columns a unit slips in.
pub(super) const RULES: [Rule; 2] = [
    Rule {
        column: "alpha",
        unit: Unit::Degree,
        reach: 0.6,
        small: 0.05,
        round: true,
    },
    Rule {
        column: "camber",
        unit: Unit::Degree,
        reach: STEEP_CAMBER,
        small: STEEP_CAMBER,
        round: false,
    },
];

/// The step a round number in the other unit is a multiple of.
const ROUND_STEP: f64 = 0.05;

/// The rule of `column`, where it has one.
pub(super) fn rule_of(column: &str) -> Option<&'static Rule> {
    RULES.iter().find(|r| r.column == column)
}

/// The slip angle, rad (20°), past which every tyre's lateral force has
/// peaked: a set of points in radians asks most of its slips short of it
/// (MFeval's reference points 0, 0.1, −0.35 and 1.2 rad: one of three
/// non-zero past it), a sweep in degrees read in radians lies mostly past
/// it (−1.5 to 1.5 by 0.1: 24 of 30).
const PEAKED: f64 = 0.35;

/// Whether more than half of the non-zero `values` lie past [`PEAKED`].
fn mostly_peaked(values: &[f64]) -> bool {
    let nonzero = values.iter().filter(|v| **v != 0.0).count();
    let past = values.iter().filter(|v| v.abs() > PEAKED).count();
    2 * past > nonzero
}

/// Whether `v` is a multiple of [`ROUND_STEP`], to the rounding of a
/// decimal text read into binary (0.30000000000000004 is 0.3).
fn round(v: f64) -> bool {
    let steps = v / ROUND_STEP;
    (steps - steps.round()).abs() <= 1e-6
}

impl Rule {
    /// Whether `values` (finite, within the physical range) read as
    /// written in the other unit (the module's rule).
    pub(super) fn reads_other(&self, values: &[f64]) -> bool {
        let beyond = values.iter().any(|v| v.abs() > self.reach);
        let small = values.iter().any(|v| *v != 0.0 && v.abs() <= self.small);
        beyond
            && !small
            && (!self.round || (values.iter().all(|v| round(*v)) && mostly_peaked(values)))
    }

    /// The refusal of a column of `values` (at rows `rows` of the file)
    /// read as written in the other unit: its row and problem, at the
    /// value farthest from 0 (the first of equals). `None` where the rule
    /// refuses at each cell (the camber: `physical.rs`) or reads it.
    pub(super) fn refusal(&self, values: &[f64], rows: &[usize]) -> Option<(usize, InputProblem)> {
        if !self.round || !self.reads_other(values) {
            return None;
        }
        let far = (0..values.len()).reduce(|a, b| match values[b].abs() > values[a].abs() {
            true => b,
            false => a,
        })?;
        let problem = PointsUnit::OtherUnit {
            column: self.column,
            unit: self.unit,
            value: values[far],
            values: values.len(),
            reach: self.reach,
            small: self.small,
        };
        Some((rows[far], problem.into()))
    }
}

/// The physical range (`lo`, `hi`) of a column, by its name.
pub(super) type RangeOf = fn(&str) -> Option<(f64, f64)>;

/// The refusals of the points' slip angle and slip ratio `inputs` read as
/// written in another unit, each at its row; the columns `stated` in SI
/// (by the header, or by a column beside agreeing) are read as written.
/// Only the values within each column's physical range (`range_of`:
/// `physical.rs`'s) are judged: the others are refused at their cells
/// already.
pub(super) fn refusals(
    inputs: &[(&'static str, Vec<f64>)],
    stated: &[&str],
    range_of: RangeOf,
) -> Vec<(usize, &'static str, InputProblem)> {
    inputs
        .iter()
        .filter(|(name, _)| !stated.contains(name))
        .filter_map(|(name, values)| {
            let rule = rule_of(name)?;
            let (lo, hi) = range_of(name)?;
            let rows: Vec<usize> = (0..values.len())
                .filter(|&i| values[i].is_finite() && (lo..=hi).contains(&values[i]))
                .collect();
            let kept: Vec<f64> = rows.iter().map(|&i| values[i]).collect();
            let (row, problem) = rule.refusal(&kept, &rows)?;
            Some((row, rule.column, problem))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn alpha() -> &'static Rule {
        rule_of("alpha").unwrap()
    }

    /// The tester's sweep −1.5 to 1.5 by 0.1 (±86° in radians) and 0.25,
    /// 0.5, 1, 1.5, −1 read as degrees; the points of `pac89_bounds`
    /// (5°, 40°, 60°, 80° in radians) and a small slip beside far ones
    /// (0.05 and 1.2: a `.tir`'s `ALPMAX` probed) as radians; a sweep
    /// within 34° too.
    #[test]
    fn a_slip_angle_column_reads_as_degrees_only_as_a_round_sweep_reaching_past_34_degrees() {
        let sweep: Vec<f64> = (-15..=15).map(|k| f64::from(k) * 0.1).collect();
        assert!(alpha().reads_other(&sweep));
        assert!(alpha().reads_other(&[0.5, 1.0, 1.5, -1.0, 0.25]));
        let pac89: Vec<f64> = [5.0f64, 40.0, 60.0, 80.0]
            .iter()
            .flat_map(|d| [d.to_radians(), -d.to_radians()])
            .collect();
        assert!(!alpha().reads_other(&pac89));
        assert!(!alpha().reads_other(&[0.05, 0.05, 1.2, -1.5, 0.0]));
        assert!(!alpha().reads_other(&[0.0, 0.1, 0.2, 0.3, 0.5, -0.5]));
        // One value off the round steps (0.33) is no sweep in degrees.
        assert!(!alpha().reads_other(&[0.0, 0.33, 1.0]));
        // MFeval's reference points past the limits, in radians: one of
        // three non-zero slips past 20°.
        assert!(!alpha().reads_other(&[0.0, 0.1, -0.35, 1.2]));
        assert!(!alpha().reads_other(&[0.0, -0.1, 0.35, -1.2]));
        let (row, problem) = alpha()
            .refusal(&sweep, &(0..31).collect::<Vec<_>>())
            .unwrap();
        assert_eq!(row, 0, "the first of ±1.5");
        assert!(matches!(
            problem,
            InputProblem::PointsUnit(PointsUnit::OtherUnit { value, values: 31, .. }) if value == -1.5
        ));
    }

    /// The camber's row is `identify`'s rule: every tilt but 0 past 20°,
    /// round or not; a car's camber beside a steep one says radians.
    #[test]
    fn a_camber_column_reads_as_degrees_where_every_tilt_is_past_20_degrees() {
        let camber = rule_of("camber").unwrap();
        for values in [&[0.0, 0.5, -0.4][..], &[0.0, 0.57], &[0.4]] {
            assert_eq!(
                camber.reads_other(values),
                crate::io::camber_in_degrees(values),
                "{values:?}"
            );
            assert!(camber.reads_other(values), "{values:?}");
        }
        for values in [&[0.1, 0.5, -0.4][..], &[0.0, 0.3, -0.3], &[0.0, 0.0]] {
            assert!(!camber.reads_other(values), "{values:?}");
            assert!(!crate::io::camber_in_degrees(values), "{values:?}");
        }
        assert!(camber.refusal(&[0.0, 0.5], &[0, 1]).is_none());
    }

    /// Within ±90°, as `physical.rs` bounds a slip angle.
    fn within_90(_: &str) -> Option<(f64, f64)> {
        Some((-std::f64::consts::FRAC_PI_2, std::f64::consts::FRAC_PI_2))
    }

    /// A column stated in SI is read as written.
    #[test]
    fn a_column_stated_in_si_is_read_as_written() {
        let inputs = vec![("alpha", vec![0.0, 0.5, 1.0, 1.5])];
        assert_eq!(refusals(&inputs, &[], within_90).len(), 1);
        assert!(refusals(&inputs, &["alpha"], within_90).is_empty());
    }
}
