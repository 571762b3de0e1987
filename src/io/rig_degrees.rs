//! A rig `alpha` column in degrees whose sweep stays inside ±90° (so the
//! reader's `AngleInDegrees` passes it), refused at its largest |α|
//! (`error/slip_degrees.rs`). The rule, on the slope `s` of `fy/fz`
//! against `alpha` as written (least squares, samples with `fz > 0` and,
//! with a `kappa` column, |κ| ≤ [`SMALL_SLIP`]; at least
//! [`PER_SIDE`] on each side of zero, `s` more than [`STANDARD_ERRORS`]
//! standard errors above zero):
//! - read in degrees, `s·180/π` over |α| ≤ [`SMALL_SLIP_DEGREES`] (2) as
//!   written is a tyre's stiffness per unit load, within
//!   [`MIN_CORNERING_PER_LOAD`] (1.5 1/rad) and [`MOST_LOAD_STIFFNESS`]
//!   (100 1/rad);
//! - read in radians, `s` over |α| ≤ [`SMALL_SLIP`] (over |α| ≤ 2 as written when
//!   too few samples lie that near zero) is below any tyre's, under
//!   [`MIN_CORNERING_PER_LOAD`];
//! - the sweep reaches beyond [`MAX_RIG_SLIP_ANGLE`] (20°) read in radians.
//!
//! A tyre's `Cα/Fz` is 5–45 1/rad (Gillespie 1992; Pacejka 2012; the public
//! `.tir` files, `tyre/sizes.rs`), so read in radians a column in degrees
//! gives 0.09–0.8, and the factor of 57.3 carries one reading across the
//! floor. The near-zero window of the radian reading keeps a tyre in
//! radians whose sweep goes far past its peak (an ice tyre to 30°, whose
//! slope over the whole sweep is low) from being taken for one in degrees.
//!
//! A camber column reads as degrees where some camber is not 0 and every
//! one that is lies steeper than [`STEEP_CAMBER`] (20°) read in radians
//! ([`camber_in_degrees`]): a rig's cambers 0 and 0.5 meant as degrees
//! are 0 and 28.6° in radians, steeper than any car tyre's measured range.
//! `identify` (`rig_checks.rs`) and `tyre-eval` (`physical.rs`) ask the
//! same question of the same cells by this one rule.

use super::columns::Columns;
use crate::error::{
    InputError, InputProblem, SlipAngleInDegrees, UnitSlip, MAX_RIG_SLIP_ANGLE, MOST_LOAD_STIFFNESS,
};
use crate::tyre::sizes::MIN_CORNERING_PER_LOAD;
use std::path::Path;

/// The camber above which a point of a model with no stated camber range
/// is said, and past which a column whose every tilt lies reads as
/// degrees, rad (20°): one constant with the refusal's words.
pub use crate::error::STEEP_CAMBER;

/// Whether a camber column reads as degrees: some camber other than 0,
/// and every one beyond [`STEEP_CAMBER`] (20°) read in radians.
pub fn camber_in_degrees(values: &[f64]) -> bool {
    let mut tilted = values.iter().filter(|v| v.is_finite() && **v != 0.0);
    let first = tilted.next();
    first.is_some_and(|v| v.abs() > STEEP_CAMBER) && tilted.all(|v| v.abs() > STEEP_CAMBER)
}

/// The small-slip range, rad (2°: inside the linear range of any tyre).
const SMALL_SLIP: f64 = 0.035;
/// The small-slip range read in degrees, as written (2°).
const SMALL_SLIP_DEGREES: f64 = 2.0;
/// Samples needed on each side of zero before a slope is judged.
const PER_SIDE: usize = 5;
/// A slope is a tyre's only this many standard errors above zero.
const STANDARD_ERRORS: f64 = 3.0;

/// A least-squares slope of `y` on `x`, its samples and standard error,
/// or `None` with fewer than [`PER_SIDE`] samples on either side of zero.
fn slope(pairs: &[(f64, f64)]) -> Option<(f64, f64)> {
    let above = pairs.iter().filter(|p| p.0 > 0.0).count();
    let below = pairs.iter().filter(|p| p.0 < 0.0).count();
    if above < PER_SIDE || below < PER_SIDE {
        return None;
    }
    let m = pairs.len() as f64;
    let mx = pairs.iter().map(|p| p.0).sum::<f64>() / m;
    let my = pairs.iter().map(|p| p.1).sum::<f64>() / m;
    let sxx: f64 = pairs.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = pairs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let s = sxy / sxx;
    let rss: f64 = pairs
        .iter()
        .map(|p| (p.1 - my - s * (p.0 - mx)).powi(2))
        .sum();
    Some((s, (rss / (m - 2.0) / sxx).sqrt()))
}

/// Refuses a lateral sweep (`alpha`, `fy`) on loads `fz` whose `alpha`
/// reads as degrees by the module's rule, at its largest |α|.
pub(super) fn refuse_alpha_in_degrees(
    path: &Path,
    c: &Columns,
    (alpha, fy): (&[f64], &[f64]),
    kappa: Option<&[f64]>,
    fz: &[f64],
) -> Result<(), InputError> {
    let Some(far) = (0..alpha.len())
        .filter(|&i| alpha[i].is_finite())
        .max_by(|&a, &b| alpha[a].abs().total_cmp(&alpha[b].abs()))
    else {
        return Ok(());
    };
    if alpha[far].abs() <= MAX_RIG_SLIP_ANGLE {
        return Ok(());
    }
    let within = |reach: f64| -> Vec<(f64, f64)> {
        (0..alpha.len())
            .filter(|&i| fz[i] > 0.0 && fy[i].is_finite() && alpha[i].abs() <= reach)
            .filter(|&i| kappa.is_none_or(|k| k[i].abs() <= SMALL_SLIP))
            .map(|i| (alpha[i], fy[i] / fz[i]))
            .collect()
    };
    let in_degrees = within(SMALL_SLIP_DEGREES);
    let Some((s, se)) = slope(&in_degrees) else {
        return Ok(());
    };
    let per_deg = s.to_degrees();
    if s <= STANDARD_ERRORS * se
        || !(MIN_CORNERING_PER_LOAD..=MOST_LOAD_STIFFNESS).contains(&per_deg)
    {
        return Ok(());
    }
    let near = within(SMALL_SLIP);
    let (per_rad, samples, window) = match slope(&near) {
        Some((s, _)) => (s, near.len(), SMALL_SLIP),
        None => (s, in_degrees.len(), SMALL_SLIP_DEGREES),
    };
    if per_rad >= MIN_CORNERING_PER_LOAD {
        return Ok(());
    }
    let slip = SlipAngleInDegrees {
        per_rad,
        per_deg,
        samples,
        window,
        reach: alpha[far],
        least: MIN_CORNERING_PER_LOAD,
    };
    Err(c.error_at(path, far, "alpha", InputProblem::from(UnitSlip::from(slip))))
}
