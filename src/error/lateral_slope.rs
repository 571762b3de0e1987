//! A measured run whose lateral acceleration disagrees with its speed and
//! yaw rate by the factor of a unit: `ay` regressed on the kinematic
//! lateral acceleration `u·r + d(u·β)/dt (+ g·sin bank)` over the run's
//! half-second means has a slope of 1/3.6 (speed in km/h), 1/2.237 (mph),
//! 1/9.81 (`ay` in g), 3.281 (ft/s²) or π/180 (yaw rate in deg/s), or the
//! `ay` and `yaw_rate` columns are each other's. Judged by
//! `io/run_slope.rs`; units SI (FORMATS.md), signs ISO 8855.

use super::number::Num;
use crate::format::fixed;
use thiserror::Error;

/// The unit (or the swap) a slope points to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlopeUnit {
    /// `speed` in km/h (slope 1/3.6).
    SpeedKmh,
    /// `speed` in mph (slope 1/2.237).
    SpeedMph,
    /// `ay` in g (slope 1/9.81).
    AyInG,
    /// `ay` in ft/s² (slope 3.281).
    AyInFeet,
    /// `yaw_rate` in deg/s (slope π/180).
    YawRateInDegrees,
    /// `ay` holds the yaw rate and `yaw_rate` the lateral acceleration:
    /// the swapped columns fit with a slope near 1.
    Swapped,
}

impl SlopeUnit {
    /// The column the refusal points at.
    pub fn column(self) -> &'static str {
        match self {
            SlopeUnit::SpeedKmh | SlopeUnit::SpeedMph => "speed",
            SlopeUnit::AyInG | SlopeUnit::AyInFeet | SlopeUnit::Swapped => "ay",
            SlopeUnit::YawRateInDegrees => "yaw_rate",
        }
    }

    /// The slope a run in this unit shows (a car's is 1).
    pub fn factor(self) -> f64 {
        match self {
            SlopeUnit::SpeedKmh => 1.0 / 3.6,
            SlopeUnit::SpeedMph => 1.0 / 2.23694,
            SlopeUnit::AyInG => 1.0 / crate::constants::G,
            SlopeUnit::AyInFeet => 1.0 / 0.3048,
            SlopeUnit::YawRateInDegrees => std::f64::consts::PI / 180.0,
            // Not a factor: the swapped fit's slope is near 1.
            SlopeUnit::Swapped => 1.0,
        }
    }

    /// The question the refusal ends on.
    fn hint(self) -> &'static str {
        match self {
            SlopeUnit::SpeedKmh => "is `speed` in km/h? divide it by 3.6 (FORMATS.md: m/s)",
            SlopeUnit::SpeedMph => "is `speed` in mph? divide it by 2.237 (FORMATS.md: m/s)",
            SlopeUnit::AyInG => "is `ay` in g? multiply it by 9.81 (FORMATS.md: m/s²)",
            SlopeUnit::AyInFeet => "is `ay` in ft/s²? multiply it by 0.3048 (FORMATS.md: m/s²)",
            SlopeUnit::YawRateInDegrees => {
                "is `yaw_rate` in deg/s? multiply it by 0.01745 (FORMATS.md: rad/s)"
            }
            SlopeUnit::Swapped => {
                "are the `ay` and `yaw_rate` columns swapped? speed × `ay` follows `yaw_rate` instead; swap their names in the header"
            }
        }
    }
}

/// The numbers of the refusal.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("column `{}`: over {bins} half-second means of the run turning at speed (R² {}), `ay` regressed on speed × yaw_rate{}{} has a slope of {}, where a car's is about 1 (between {} and {} with an unmeasured road bank or body roll){}: {}", unit.column(), fixed(*r2, 3), if *with_beta { " + d(speed·beta)/dt" } else { "" }, if *with_bank { " + g·sin(bank)" } else { "" }, Num(crate::format::significant(*slope, 3).parse().unwrap_or(*slope)), Num(range.0), Num(range.1), swapped_words(*unit, *swapped, *with_beta), unit.hint())]
pub struct LateralSlope {
    /// The unit the slope names.
    pub unit: SlopeUnit,
    /// The fitted slope of `ay` on the kinematic lateral acceleration.
    pub slope: f64,
    /// The fit's R² (through the origin).
    pub r2: f64,
    /// The half-second means fitted.
    pub bins: usize,
    /// Whether the d(u·β)/dt term was in the regressor (a `beta` column).
    pub with_beta: bool,
    /// Whether g·sin(bank) was in the regressor (a `bank` column).
    pub with_bank: bool,
    /// The slopes a run in SI units is taken to lie within.
    pub range: (f64, f64),
    /// The swapped fit's slope (speed × `ay` against `yaw_rate`).
    pub swapped: f64,
}

/// The swapped fit's words, for a swap only.
fn swapped_words(unit: SlopeUnit, swapped: f64, with_beta: bool) -> String {
    if unit == SlopeUnit::Swapped {
        let beta = if with_beta {
            " + d(speed·beta)/dt"
        } else {
            ""
        };
        format!(
            ", and `yaw_rate` regressed on speed × `ay`{beta} has a slope of {}",
            fixed(swapped, 3)
        )
    } else {
        format!(
            " = 1/{}",
            crate::format::significant(1.0 / unit.factor(), 3)
        )
    }
}

/// A `beta` column whose changes are about 100 times the sideslip its
/// run's kinematics gives (β̇ = a_y/u − r on a flat road): in percent of a
/// radian, where degrees would be 57.3 times. Judged by
/// `io/run_slope.rs`'s `beta_factor`.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("column `beta`: {} as read, and over the run's half-second means its changes are {}× what ∫(ay/speed − yaw_rate) dt gives (R² {}), where a sideslip in radians is about 1×, in degrees 57.3×, in percent of a radian 100× (this check reads 97–121× for percent, 55–69× for degrees): is `beta` in percent? divide it by 100 (FORMATS.md: rad)", Num(*value), fixed(*factor, 0), fixed(*r2, 2))]
pub struct BetaInPercent {
    /// The sideslip at the first moving sample, as read.
    pub value: f64,
    /// The fitted factor of `beta` over the kinematic sideslip.
    pub factor: f64,
    /// The fit's R².
    pub r2: f64,
}
