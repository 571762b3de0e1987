//! A measured run whose yaw rate explains a small share of a steady
//! lateral acceleration the steer also gives: at a steady state `ay =
//! u·r` (ISO 8855, `β̇ = 0`), so a yaw rate
//! 57.3 times too small is a yaw rate in rad/s read as deg/s (declared in
//! degrees, or divided by 57.3 twice), another small factor a gyro's gain.
//! Judged by `io/run_yaw_scale.rs` over the run's half-second means where
//! `|ay|` holds at 1 m/s² or more; units SI (FORMATS.md).

use super::number::Num;
use crate::format::{fixed, significant};
use thiserror::Error;

/// The numbers of the refusal.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("column `yaw_rate`: {} rad/s where `ay` holds at {} m/s²: over {bins} half-second means of the run at a steady |ay| of {} m/s² or more, speed × yaw_rate is {} of `ay`{} (R² {}), where a car's is about 1, while the steer turns the car as `ay` says (steer × speed²/ay = {} m, a car's wheelbase or more with its understeer): the yaw rate reads {}× too small; {}", Num(*value), fixed(*ay, 2), Num(*steady_ay), significant(*share, 3), if *with_bank { " − g·sin(bank)" } else { "" }, fixed(*r2, 3), fixed(*wheelbase, 1), significant(1.0 / share, 3), hint(*in_degrees))]
pub struct YawScale {
    /// The yaw rate at the row named (the first of the first mean judged),
    /// as read.
    pub value: f64,
    /// That mean's `ay`, m/s².
    pub ay: f64,
    /// The share of `ay` the kinematic lateral acceleration is (the slope
    /// of a fit through the origin over the means).
    pub share: f64,
    /// The fit's R² (through the origin).
    pub r2: f64,
    /// The means fitted.
    pub bins: usize,
    /// The least |ay| of a mean judged, m/s².
    pub steady_ay: f64,
    /// The median of steer × speed² / ay over the means, m: a neutral
    /// car's wheelbase, more with understeer.
    pub wheelbase: f64,
    /// The share lies in the band of a yaw rate in rad/s read as deg/s
    /// (1/57.3 within a factor of 1.25).
    pub in_degrees: bool,
    /// Whether g·sin(bank) was taken out of `ay` (a `bank` column).
    pub with_bank: bool,
}

/// The question the refusal ends on.
fn hint(in_degrees: bool) -> &'static str {
    match in_degrees {
        true => "57.3× is a yaw rate in rad/s read as deg/s: was `yaw_rate` declared in degrees (`degrees = [\"yaw_rate\"]` under a campaign's [runs] or a replay's [manoeuvre], `--degrees yaw_rate` to `metrics`) while the file logs rad/s? Take it out of `degrees`; else the column was divided by 57.3 twice (FORMATS.md: rad/s)",
        false => "not a unit's factor (57.3× would be a yaw rate in rad/s read as deg/s): is the gyro's gain or range set wrong, or `ay` scaled (FORMATS.md: rad/s, m/s²)?",
    }
}
