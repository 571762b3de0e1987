//! A column beside a points column of `tyre-eval` that states its own unit
//! (`sa_deg`, `SA [deg]` or `alpha [rad]` beside `alpha`; `ia_deg` beside
//! `camber`; `kappa [%]` beside `kappa`). `tyre-eval` reads the column
//! under its own name, in SI (rad, a fraction), and does not carry the
//! other to its output; but the two say one thing twice, so they are
//! checked against each other, row by row. A row where the other column,
//! converted to SI by its stated unit, is not the column's value within
//! the rounding the other column is written to (half the coarsest decimal
//! step all its values are multiples of: 0.5° for whole degrees, 0.005°
//! for 2.86) is refused at that row and the other column's cell, with both
//! values: one of them is wrong (a slip angle in degrees under `alpha`, a
//! label of another test). A column beside that agrees on every row is
//! the user's word on the column's unit: it is not asked as written in
//! another unit (`other_unit.rs`).

use crate::error::{unit_factor, InputError, PointsUnit};
use crate::io::{read_columns_with_bad_cells, unit_of, Columns, Layout};
use std::path::Path;

/// The checks of the columns beside the points' inputs: the refusals of
/// the rows where they disagree, and the inputs a column beside confirms
/// on every row.
#[derive(Default)]
pub(super) struct Besides {
    pub(super) refused: Vec<InputError>,
    pub(super) confirmed: Vec<&'static str>,
}

/// The coarsest decimal step (1 down to 1e-6) that every value of
/// `values` is a multiple of, halved: the rounding they are written to;
/// 0 where none is (a value written to every digit).
fn rounding(values: &[f64]) -> f64 {
    let multiple = |v: f64, step: f64| ((v / step) - (v / step).round()).abs() <= 1e-6;
    (0..=6)
        .map(|k| 10f64.powi(-k))
        .find(|&step| values.iter().all(|v| multiple(*v, step)))
        .map_or(0.0, |step| step / 2.0)
}

/// The rows of `beside` (in `unit`) that are not `values` (SI) within the
/// rounding `beside` is written to: each row with the problem.
fn disagreements(
    (column, values): (&'static str, &[f64]),
    (header, beside): (&str, &[f64]),
    unit: crate::error::Unit,
) -> Vec<(usize, PointsUnit)> {
    let finite: Vec<f64> = beside.iter().copied().filter(|v| v.is_finite()).collect();
    let rounding = rounding(&finite);
    let factor = unit_factor(unit);
    (0..values.len().min(beside.len()))
        .filter(|&i| values[i].is_finite() && beside[i].is_finite())
        .filter(|&i| {
            let apart = (beside[i] - values[i] / factor).abs();
            apart > rounding * (1.0 + 1e-6) + 1e-9 * beside[i].abs().max(1.0)
        })
        .map(|i| {
            let problem = PointsUnit::BesideDisagrees {
                column,
                beside: header.into(),
                unit,
                value: values[i],
                beside_value: beside[i],
                rounding,
            };
            (i, problem)
        })
        .collect()
}

/// Every column of the points file `points` (read as `c`) beside one of
/// the `inputs` and stating its own unit, checked against it.
pub(super) fn check(points: &Path, c: &Columns, inputs: &[(&'static str, Vec<f64>)]) -> Besides {
    let mut out = Besides::default();
    for header in &c.header {
        // The angles and the slip ratio, whose units are degrees,
        // radians, percent, none (`unit_factor`).
        let judged = inputs
            .iter()
            .filter(|(n, _)| matches!(*n, "alpha" | "camber" | "kappa"));
        for (column, values) in judged {
            let Some(unit) = unit_of(header, column) else {
                continue;
            };
            // Read apart: the points' reader does not read it.
            let layout = Layout {
                required: &[],
                optional: &[header.as_str()],
                also_read: None,
            };
            let Ok((other, _)) = read_columns_with_bad_cells(points, layout) else {
                continue;
            };
            let Some(beside) = other.get(header) else {
                continue;
            };
            let wrong = disagreements((column, values), (header, beside), unit);
            if wrong.is_empty() {
                out.confirmed.push(column);
            }
            out.refused.extend(
                wrong
                    .into_iter()
                    .map(|(i, p)| other.error_at(points, i, header, p.into())),
            );
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Unit;

    #[test]
    fn a_column_s_rounding_is_half_its_coarsest_decimal_step() {
        assert_eq!(rounding(&[5.0, -3.0]), 0.5);
        assert_eq!(rounding(&[2.86, 5.73]), 0.005);
        assert_eq!(rounding(&[2.9, 5.7]), 0.05);
        assert_eq!(rounding(&[std::f64::consts::PI]), 0.0);
    }

    /// 2.86° and 5.73° beside 0.05 and 0.1 rad agree within their
    /// rounding; 5 beside 0.05 (2.86°) and −3 beside 0.1 do not, and
    /// 0.5 beside 0.5 rad (28.6°) is the same number in another unit.
    #[test]
    fn a_column_beside_agrees_within_its_rounding_or_is_refused_at_its_row() {
        let alpha = ("alpha", &[0.05, 0.1][..]);
        assert!(disagreements(alpha, ("sa_deg", &[2.86, 5.73]), Unit::Degree).is_empty());
        assert!(disagreements(alpha, ("sa_deg", &[3.0, 6.0]), Unit::Degree).is_empty());
        let wrong = disagreements(alpha, ("sa_deg", &[5.0, -3.0]), Unit::Degree);
        assert_eq!(wrong.len(), 2);
        assert!(matches!(
            &wrong[0],
            (0, PointsUnit::BesideDisagrees { value, beside_value, rounding, .. })
                if *value == 0.05 && *beside_value == 5.0 && *rounding == 0.5
        ));
        let same = disagreements(("alpha", &[0.5]), ("sa_deg", &[0.5]), Unit::Degree);
        assert!(
            same[0].1.to_string().contains("holds the same number"),
            "{}",
            same[0].1
        );
        let kappa = ("kappa", &[0.05, -0.1][..]);
        assert!(disagreements(kappa, ("kappa [%]", &[5.0, -10.0]), Unit::Percent).is_empty());
    }
}
