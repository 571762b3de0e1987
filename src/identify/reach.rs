//! Whether a fit's points reach the tyre's peak: a sweep short of it (a
//! slip angle within ±4°, a slip ratio within ±0.1) sees the force's
//! slope and little of how it bends over, so a sliding term driven past
//! its search box on it is driven by the slope's noise or an offset the
//! model lacks, not by sliding the data show. Gim's `friction_decay` went
//! to 2523 (box 0 to 1) on a ±0.29° sweep with a 110 N offset at zero
//! slip, and the tyre written gave 31 N at 0.05 rad where the data's
//! slope gives 4900 N. The local polish of such a fit stays in the box
//! (`within_box` in `identify/mod.rs`). Units: rad, slip ratio.

use super::data::Sweep;
use super::FitProblem;

/// The slip angle past which a tyre's lateral force peaks, rad (4°).
pub(crate) const PEAK_ALPHA: f64 = 0.0698;

/// The slip ratio past which a tyre's longitudinal force peaks.
pub(crate) const PEAK_KAPPA: f64 = 0.1;

/// Whether the points of `problem` stay short of the peak along their
/// sweep (module notes): every lateral point within [`PEAK_ALPHA`] and
/// every longitudinal one within [`PEAK_KAPPA`].
pub(super) fn short_of_peak(problem: &FitProblem) -> bool {
    problem.points.iter().all(|p| match p.sweep {
        Sweep::Lateral { alpha, .. } => alpha.abs() < PEAK_ALPHA,
        Sweep::Longitudinal { kappa, .. } => kappa.abs() < PEAK_KAPPA,
    })
}
