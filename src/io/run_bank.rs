//! Whether a measured run's `bank` column is in radians, as `FORMATS.md`
//! asks, told by the run's own lateral acceleration.
//!
//! **Why.** A body-fixed accelerometer reads the specific force, so on a
//! road banked by θ (positive with the left edge higher) `a_y = u·r +
//! d(u·β)/dt + g·sin θ + b_ay` (ISO 8855; `measured/calibration` has the
//! derivation). The size check of `run_units` refuses a bank whose 99th
//! percentile passes 1 rad, but a bank of a degree or less written in
//! degrees passes it: 0.5 meaning 0.5° reads as 28.6°, and the
//! calibration took g·sin(0.5) = 4.7 m/s² out of `ay` and called what was
//! left (−4.4 m/s²) the accelerometer's offset.
//!
//! **Rule.** The offset `b_ay` is one number for the run; the bank's
//! term need not be all of `g·sin θ`: the logged bank acts on the car with
//! a share (`bank_profile_scale`, 0 to 2, `docs/src/conventions.md`), 0
//! where the road under the car is not the logged one. That is the
//! proving ground's control (`synth --programme oval` without
//! `bank_profile`: the truth drives a flat track, `ay` = u·r, while the
//! logger records the 20° banking) and a common log fault
//! (`calibration/bank.rs`: "the logged bank does not act on the car"). Over
//! the run's 0.5 s means ([`stretches`]: parked and moving
//! alike; the β term where the run has `beta`), the residual `e = ay −
//! u·r − d(u·β)/dt` is then `b_ay + s·g·sin θ` (and the tilt of the body's
//! roll). Two cases:
//!
//! - **The bank varies**: the standard deviation of `g·sin θ` (θ read in
//!   radians) over the means is [`BANK_VARIES`] or more, more than any
//!   offset could stand for. The share and the offset are then two numbers
//!   the means tell apart, and the diagnosis (`bank_profile`) and the
//!   calibration's standstills (as logged, not acting, reversed) judge
//!   them; the unit is not: a share of π/180 (the column in degrees) is
//!   one of 0 within the fit's error, since the size check of `run_units`
//!   leaves |θ| ≤ 1 as read, whose `g·θ·π/180` stays under 0.17 m/s². Not
//!   judged here. (A median over the means, as this check once took, reads
//!   the oval's banked turns, +3.2 m/s², as the offset.)
//! - **The bank holds** (a spread below [`BANK_VARIES`]): the share and
//!   the offset are one level, and the level judges. Each reading of the
//!   column implies an offset, the median of `e − g·sin θ` with θ read in
//!   radians or in degrees. A reading in radians that implies an offset
//!   beyond [`PLAUSIBLE_AY_OFFSET`] (g·sin 6°, `calibration/bank.rs`) where
//!   the reading in degrees implies one within it is refused: "is the
//!   column in degrees?" A held bank the car does not feel implies the
//!   same offsets as one in degrees of a degree or less (they are one mean
//!   apart at most g·sin 1° = 0.17 m/s²), and the refusal says that too:
//!   such a column is not this road's, and the calibration's straights
//!   would take its `g·sin θ` out of `ay` as an offset.
//!
//! Not judged: fewer than [`MIN_BINS`] means, or an `ay` that holds one
//! value throughout (a dead channel written as 0 tells no bank).
//!
//! **Steep.** No road is banked beyond [`STEEPEST_BANK`] (35°; Daytona's
//! banking is 31°, Talladega's 33°): a bank beyond it in radians is said
//! in a note, where the size check leaves it.
//!
//! Units: SI, rad.

use super::columns::Columns;
use super::run_slope::{fit, slope_slip, stretches, Lateral, Stretch, MIN_BINS, MIN_R2, SI_RANGE};
use crate::constants::{G, STEEPEST_BANK};
use crate::error::{BankInDegrees, BankReversed, InputError, UnitSlip};
use crate::measured::calibration::PLAUSIBLE_AY_OFFSET;
use crate::measured::clean::median;
use crate::measured::MeasuredRun;
use std::path::Path;

/// The least standard deviation of `g·sin θ` (θ read in radians) over the
/// means at which the bank's share of `ay` is told apart from the offset,
/// m/s²: [`PLAUSIBLE_AY_OFFSET`], beyond what any offset stands for.
pub const BANK_VARIES: f64 = PLAUSIBLE_AY_OFFSET;

/// One mean's residual `e` (m/s²), its bank as read (rad) and `g·sin θ`
/// with θ in radians (m/s²).
struct Residual {
    e: f64,
    bank: f64,
    term: f64,
}

/// Each half-second mean's residual, where it is finite.
fn residuals(c: &Lateral) -> Vec<Residual> {
    stretches(c)
        .iter()
        .map(|s| Residual {
            e: s.ay - s.speed_yaw - s.v_dot,
            bank: s.bank,
            term: s.bank_term,
        })
        .filter(|r| r.e.is_finite() && r.bank.is_finite() && r.term.is_finite())
        .collect()
}

/// The standard deviation of `g·sin θ` over the means, m/s².
fn spread(bins: &[Residual]) -> f64 {
    let n = bins.len() as f64;
    let mean = bins.iter().map(|r| r.term).sum::<f64>() / n;
    (bins.iter().map(|r| (r.term - mean).powi(2)).sum::<f64>() / n).sqrt()
}

/// Refuses a held `bank` whose term `ay` shows in degrees, not radians
/// (the rule above), at the first sample where the two readings differ by
/// more than [`PLAUSIBLE_AY_OFFSET`].
pub(super) fn check_bank_degrees(
    path: &Path,
    cols: &Columns,
    c: &Lateral,
    bank: &[f64],
) -> Result<(), InputError> {
    // An `ay` that holds one value (a dead or unlogged channel written as
    // 0) says nothing of the bank.
    let held = c.ay.iter().all(|a| *a == c.ay[0]);
    let bins = residuals(c);
    if held || bins.len() < MIN_BINS {
        return Ok(());
    }
    // A varying bank's share is measured, not assumed (the rule above).
    let spread = spread(&bins);
    if spread >= BANK_VARIES {
        return Ok(());
    }
    let mut as_radians: Vec<f64> = bins.iter().map(|r| r.e - r.term).collect();
    let mut as_degrees: Vec<f64> = bins
        .iter()
        .map(|r| r.e - G * r.bank.to_radians().sin())
        .collect();
    let mut as_reversed: Vec<f64> = bins.iter().map(|r| r.e + r.term).collect();
    let (as_radians, as_degrees) = (median(&mut as_radians), median(&mut as_degrees));
    let as_reversed = median(&mut as_reversed);
    if as_radians.abs() <= PLAUSIBLE_AY_OFFSET {
        return Ok(());
    }
    // A bank of the other sign implies the smallest offset read reversed:
    // the sign, not the unit (a held bank in degrees or not acting implies
    // about `e`, reversed `e + g·sin θ`).
    if as_reversed.abs() <= PLAUSIBLE_AY_OFFSET && as_reversed.abs() < as_degrees.abs() {
        let row = bank.iter().position(|b| b.abs() > 0.0).unwrap_or(0);
        let slip = BankReversed::Held {
            as_logged: as_radians,
            as_degrees,
            as_reversed,
            plausible: PLAUSIBLE_AY_OFFSET,
            bins: bins.len(),
            with_beta: c.beta.is_some(),
        };
        return Err(cols.error_at(path, row, "bank", UnitSlip::from(slip).into()));
    }
    if as_degrees.abs() > PLAUSIBLE_AY_OFFSET {
        return Ok(());
    }
    let row = bank
        .iter()
        .position(|b| (G * (b.sin() - b.to_radians().sin())).abs() > PLAUSIBLE_AY_OFFSET)
        .unwrap_or(0);
    let slip = BankInDegrees {
        value: bank[row],
        as_radians,
        as_degrees,
        plausible: PLAUSIBLE_AY_OFFSET,
        spread,
        varies: BANK_VARIES,
        bins: bins.len(),
        with_beta: c.beta.is_some(),
    };
    Err(cols.error_at(path, row, "bank", UnitSlip::from(slip).into()))
}

/// The slope check (`run_slope.rs`) where the run logs a bank: a slope in
/// a unit's band with the bank as logged is first read without the bank
/// and reversed ([`bank_reading`]): a bank of the other sign (or one the
/// car does not feel) pulls the slope into a unit's band, and is named in
/// place of the unit. Where the slope judges nothing, a yaw rate too small
/// for its `u·r` to turn the means is judged by a steady `ay`
/// (`run_yaw_scale.rs`).
pub(super) fn check_slope_reading(
    path: &Path,
    cols: &Columns,
    c: &Lateral,
) -> Result<(), InputError> {
    let Some((row, slip)) = slope_slip(c) else {
        // A yaw rate too small for `u·r` to reach the slope's turning
        // means: judged where `ay` holds large.
        return match super::run_yaw_scale::yaw_scale_slip(path, c) {
            Some((row, s)) => Err(cols.error_at(path, row, "yaw_rate", UnitSlip::from(s).into())),
            None => Ok(()),
        };
    };
    match bank_reading(c) {
        Err(reversed) => Err(cols.error_at(path, row, "bank", UnitSlip::from(reversed).into())),
        Ok(true) => Ok(()),
        Ok(false) => {
            let column = slip.unit.column();
            Err(cols.error_at(path, row, column, UnitSlip::from(slip).into()))
        }
    }
}

/// The fits of the slope check (`run_slope.rs`) with the bank as logged,
/// without it and reversed, over the run's turning means: a
/// [`BankReversed::Slope`] where the reversed bank fits best (the highest
/// R², at least [`MIN_R2`]) with a car's slope ([`SI_RANGE`]); `Ok(true)`
/// where the fit without the bank does (a logged bank the car does not
/// feel, the diagnosis's `bank_profile` and the calibration's to judge:
/// it names no unit); `Ok(false)` where the bank as logged fits best, or
/// the run has none. Called where the slope as logged names a unit.
pub(super) fn bank_reading(c: &Lateral) -> Result<bool, BankReversed> {
    if c.bank.is_none() {
        return Ok(false);
    }
    let means: Vec<&Stretch> = stretches(c)
        .iter()
        .filter(|s| s.turning())
        .filter(|s| (s.speed_yaw + s.v_dot + s.bank_term).is_finite() && s.ay.is_finite())
        .collect();
    let with = |k: f64| {
        fit(means
            .iter()
            .map(|s| (s.speed_yaw + s.v_dot + k * s.bank_term, s.ay)))
    };
    let ((slope, r2), (without, without_r2), (reversed, reversed_r2)) =
        (with(1.0), with(0.0), with(-1.0));
    let car = |k: f64| (SI_RANGE.0..=SI_RANGE.1).contains(&k);
    if reversed_r2 >= MIN_R2 && reversed_r2 > r2.max(without_r2) && car(reversed) {
        return Err(BankReversed::Slope {
            slope,
            r2,
            without,
            without_r2,
            reversed,
            reversed_r2,
            range: SI_RANGE,
            bins: means.len(),
            with_beta: c.beta.is_some(),
        });
    }
    Ok(without_r2 >= MIN_R2 && without_r2 > r2 && car(without))
}

/// A note where `run`'s bank, read in radians, passes
/// [`STEEPEST_BANK`]: no road is that steep.
pub fn steep_bank(run: &MeasuredRun) -> Option<String> {
    let bank = run.bank.as_ref()?;
    let (i, b) = bank
        .iter()
        .enumerate()
        .filter(|(_, b)| b.is_finite())
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))?;
    (b.abs() > STEEPEST_BANK).then(|| {
        format!(
            "{}: `bank` reaches {} rad ({:.0}°) at t = {} s, steeper than any road ({:.0}°; Daytona's banking is 31°): bank is in radians (FORMATS.md); is the column in degrees, or scaled?",
            run.path.display(),
            crate::error::Num(*b),
            b.to_degrees(),
            crate::error::Num(run.t[i]),
            STEEPEST_BANK.to_degrees()
        )
    })
}
