//! A tyre fitted to longitudinal data only: its `[fitted_ranges]` (what
//! `identify` writes) give a slip-ratio range and no slip angle, so its
//! lateral block is what the fit started from (a PAC89's the Adams
//! example's), never fitted to data. `simulate` says so of such a tyre;
//! `tyre-eval` says it once of the points it gives a lateral force at
//! (a slip angle or camber ≠ 0), or its `fy` reads as a fitted one.
//! Slip ratio dimensionless, angles rad.

use crate::format::{plural, readable};
use crate::io::fitted_ranges::FittedRanges;
use serde::Serialize;

/// The points whose lateral force comes from an unfitted block.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct UnfittedLateral {
    /// The slip-ratio range the tyre was fitted over.
    pub kappa: [f64; 2],
    /// Points at a slip angle or camber ≠ 0.
    pub points: usize,
    /// The first of them, by its line in the points file.
    pub first_line: usize,
}

impl UnfittedLateral {
    /// The warning, one line.
    pub fn line(&self, count: usize) -> String {
        format!(
            "{} of {} at a slip angle or camber ≠ 0 (the first at line {}): the tyre was fitted to longitudinal data only (its `[fitted_ranges]` give a slip ratio of {} to {} and no slip angle), so its lateral block is unfitted, the model's starting (template) coefficients: the fy and mz written there are no fit's; fit it to cornering data (`identify` on a file with `alpha` and `fy`)",
            self.points,
            plural(count, "point", "points"),
            self.first_line,
            readable(self.kappa[0], 4),
            readable(self.kappa[1], 4),
        )
    }
}

/// The points (`alpha`, `camber`, at file lines `lines`) a tyre fitted to
/// longitudinal data only (`ranges`) gives an unfitted lateral force at.
pub(crate) fn unfitted_lateral(
    ranges: Option<&FittedRanges>,
    alpha: &[f64],
    camber: &[f64],
    lines: &[usize],
) -> Option<UnfittedLateral> {
    let r = ranges.filter(|r| r.alpha.is_none())?;
    let kappa = r.kappa?;
    let at: Vec<usize> = (0..alpha.len())
        .filter(|&i| alpha[i] != 0.0 || camber[i] != 0.0)
        .collect();
    let &i = at.first()?;
    Some(UnfittedLateral {
        kappa,
        points: at.len(),
        first_line: lines.get(i).copied().unwrap_or(i + 2),
    })
}
