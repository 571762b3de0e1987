//! The limits every manoeuvre keeps to, wherever it is written (a
//! scenario's `[manoeuvre]` of any kind, a schedule's elements): a
//! road-wheel steer, a speed on a road, a steer frequency, a start in the
//! run. Units: rad, m/s, Hz, s.

use crate::constants::LONGEST_RUN;
use crate::error::{Limit, ParamError};

/// The largest front road-wheel steer a manoeuvre may ask for, rad (45°):
/// above a car's lock (a mean road-wheel steer of about 35–40°), and the
/// angle beyond which a steer in radians is likely one in degrees.
pub(crate) const MAX_ROAD_WHEEL_STEER: f64 = std::f64::consts::FRAC_PI_4;

/// A steer angle a manoeuvre reaches, within ±[`MAX_ROAD_WHEEL_STEER`].
pub(super) fn road_wheel_steer(key: &str, steer: f64) -> Result<(), ParamError> {
    ParamError::in_range(
        key,
        steer,
        -MAX_ROAD_WHEEL_STEER,
        MAX_ROAD_WHEEL_STEER,
        Limit::RoadWheelSteer,
    )
}

/// A front road-wheel steer angle given in degrees at `key` (a sweep's
/// `unit = "deg"`): the limit of [`road_wheel_steer`], said in degrees.
pub(super) fn road_wheel_steer_degrees(key: &str, steer: f64) -> Result<(), ParamError> {
    // 45°, as MAX_ROAD_WHEEL_STEER is π/4.
    let limit = 45.0;
    ParamError::in_range(key, steer, -limit, limit, Limit::RoadWheelSteerDegrees)
}

/// The fastest manoeuvre, m/s ([`Limit::ManoeuvreSpeed`]).
pub(crate) const MAX_SPEED: f64 = 150.0;

/// The fastest steer frequency, Hz ([`Limit::SteerFrequency`]): a sine of
/// 1 MHz asked 20 million integration steps before it was refused.
const MAX_FREQUENCY: f64 = 50.0;

/// A manoeuvre's speed: positive, above the model's lowest speed
/// ([`crate::vehicle::MIN_SPEED`]: a slower one ran at that speed, its
/// gains printed as the car's at a crawl) and at most [`MAX_SPEED`],
/// refused at its own key (an absurd speed otherwise hangs the integration,
/// or surfaces as a non-finite straight-running steer blamed on `steer`).
pub(super) fn speed(speed: f64) -> Result<(), ParamError> {
    // The range, not "positive": 0.3 m/s is positive and still refused.
    let lo = crate::vehicle::MIN_SPEED;
    ParamError::in_range("speed", speed, lo, MAX_SPEED, Limit::ManoeuvreSpeed)
}

/// A steer frequency at `key`: at most [`MAX_FREQUENCY`], above `lo`.
pub(super) fn frequency(key: &str, f: f64, lo: f64) -> Result<(), ParamError> {
    ParamError::in_range(key, f, lo, MAX_FREQUENCY, Limit::SteerFrequency)
}

/// A manoeuvre's `start`, refused at its own key where no end can follow
/// it (else the end is blamed for a start it cannot lie after).
pub(super) fn run_start(start: f64) -> Result<(), ParamError> {
    ParamError::in_range("start", start, -1e-12, LONGEST_RUN, Limit::StartBeforeEnd)?;
    ParamError::non_negative("start", start)
}
