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
//! **Rule.** Over the run's [`BIN_SECONDS`] s means (parked and moving
//! alike; the β term where the run has `beta`), the residual `e = ay −
//! u·r − d(u·β)/dt` is the bank's term plus the offset (and the tilt of
//! the body's roll). Each reading of the column implies an offset, the
//! median of `e − g·sin θ` with θ read in radians or in degrees. A reading
//! in radians that implies an offset beyond
//! [`PLAUSIBLE_AY_OFFSET`] (g·sin 6°, `calibration/bank.rs`) where the
//! reading in degrees implies one within it is refused: "is the column in
//! degrees?". Where the bank varies enough that its term would show in
//! degrees (a standard deviation of g·θ·π/180 over the means of at least
//! [`BANK_SPREAD`]), `e` is also fitted on g·θ as read with an intercept
//! and the slope named in the refusal (π/180 in degrees, 1 in radians).
//! A logged bank that the car does not feel (`calibration/bank.rs`'s "not
//! acting") over most of the run implies the same offsets as one in
//! degrees of a degree or less, and is refused with the same question: the
//! two are one mean apart at most g·sin 1° = 0.17 m/s².
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
use super::run_slope::{Lateral, BIN_SECONDS, MIN_BINS};
use crate::constants::G;
use crate::error::{BankInDegrees, InputError, UnitSlip};
use crate::measured::calibration::PLAUSIBLE_AY_OFFSET;
use crate::measured::clean::median;
use crate::measured::MeasuredRun;
use std::path::Path;

/// The least standard deviation of g·θ·π/180 (the bank's term, were the
/// column in degrees) over the means for the slope to be fitted, m/s².
pub const BANK_SPREAD: f64 = 0.1;

/// The steepest road bank, rad (35°).
pub const STEEPEST_BANK: f64 = 0.61;

/// Each half-second mean's residual `e` and bank as read.
fn residuals(c: &Lateral, bank: &[f64]) -> Vec<(f64, f64)> {
    let n = c.t.len();
    let v: Option<Vec<f64>> = c
        .beta
        .map(|b| b.iter().zip(c.speed).map(|(b, u)| u * b.tan()).collect());
    let mut out = Vec::new();
    let mut i = 0;
    while i < n {
        let mut j = i;
        while j < n && c.t[j] - c.t[i] < BIN_SECONDS {
            j += 1;
        }
        let m = (j - i) as f64;
        let mean = |f: &dyn Fn(usize) -> f64| (i..j).map(f).sum::<f64>() / m;
        let v_dot = match &v {
            Some(v) if j - i >= 2 => (v[j - 1] - v[i]) / (c.t[j - 1] - c.t[i]),
            Some(_) => f64::NAN,
            None => 0.0,
        };
        let e = mean(&|k| c.ay[k] - c.speed[k] * c.yaw_rate[k]) - v_dot;
        let b = mean(&|k| bank[k]);
        if e.is_finite() && b.is_finite() {
            out.push((e, b));
        }
        i = j;
    }
    out
}

/// The slope of `e` on g·θ with an intercept, where the bank's term in
/// degrees would vary by [`BANK_SPREAD`] or more.
fn bank_slope(bins: &[(f64, f64)]) -> Option<f64> {
    let n = bins.len() as f64;
    let (me, mb) = bins
        .iter()
        .fold((0.0, 0.0), |(a, b), (e, t)| (a + e / n, b + G * t / n));
    let sxx: f64 = bins.iter().map(|(_, t)| (G * t - mb).powi(2)).sum();
    let sxy: f64 = bins.iter().map(|(e, t)| (G * t - mb) * (e - me)).sum();
    let spread = (sxx / n).sqrt() * std::f64::consts::PI / 180.0;
    (spread >= BANK_SPREAD).then(|| sxy / sxx)
}

/// Refuses a `bank` whose term `ay` shows in degrees, not radians (the
/// rule above), at the first sample where the two readings differ by more
/// than [`PLAUSIBLE_AY_OFFSET`].
pub(super) fn check_bank_degrees(
    path: &Path,
    cols: &Columns,
    c: &Lateral,
    bank: &[f64],
) -> Result<(), InputError> {
    // An `ay` that holds one value (a dead or unlogged channel written as
    // 0) says nothing of the bank.
    let held = c.ay.iter().all(|a| *a == c.ay[0]);
    let bins = residuals(c, bank);
    if held || bins.len() < MIN_BINS {
        return Ok(());
    }
    let implied = |scale: f64| {
        let mut o: Vec<f64> = bins
            .iter()
            .map(|(e, b)| e - G * (b * scale).sin())
            .collect();
        median(&mut o)
    };
    let (as_radians, as_degrees) = (implied(1.0), implied(std::f64::consts::PI / 180.0));
    if as_radians.abs() <= PLAUSIBLE_AY_OFFSET || as_degrees.abs() > PLAUSIBLE_AY_OFFSET {
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
        slope: bank_slope(&bins),
        bins: bins.len(),
        with_beta: c.beta.is_some(),
    };
    Err(cols.error_at(path, row, "bank", UnitSlip::from(slip).into()))
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
