//! A response sample of a measured run that no car produces, refused at
//! its cell ([`super::read_run`]), as a speed beyond any vehicle's is
//! (`run_units.rs`'s `ABSURD_SPEED`) and a steer beyond any sensor's
//! (`ABSURD_STEER`). The cleaning masks a lone spike of a response channel
//! from its neighbours; one of 1e308 (or an `ay` of 500 m/s²) was masked
//! as such a spike (round 51), though no glitch of a car's sensor reads
//! it: the cell is no reading of the car, and the user is the one to mend
//! it. Checked after the columns' units (`run_units.rs`, `run_slope.rs`),
//! so that a column logged in another unit (a yaw rate in deg/s, a
//! sideslip in degrees) is named as that first: the limits are for a
//! column in `FORMATS.md`'s SI unit. A spike within them is a glitch
//! of the car's sensors, the cleaning's to mask. Units: rad/s, m/s², rad
//! (ISO 8855; the limits bound |value|, either sign).

use super::columns::Columns;
use crate::error::{InputError, Response, ResponseBeyondAnyCar};
use crate::measured::MeasuredRun;
use std::path::Path;

/// The largest |yaw rate| a car produces, rad/s (573°/s, 1.6 turns a
/// second): a car spinning out turns at about 2 rad/s, and the unit check
/// judges a column beyond 3 rad/s over 1 % of the run as deg/s
/// (`MAX_YAW_RATE`); five times a spin is no car's.
pub const ABSURD_YAW_RATE: f64 = 10.0;

/// The largest |lateral acceleration| a car produces, m/s² (10 g): a road
/// car's tyres give about 1 g, a racing car's downforce about 4–5 g for
/// moments, and the unit check's `MAX_AY` (30 m/s², 3.1 g) bounds 99 % of a
/// run. A lone spike below it (40 m/s², a knock on the accelerometer) is
/// masked by the cleaning.
pub const ABSURD_AY: f64 = 100.0;

/// The largest |sideslip| there is, rad (π, 180°): the angle between the
/// car's heading and its velocity lies within half a turn either way.
pub const ABSURD_BETA: f64 = std::f64::consts::PI;

/// The limit of channel `r`'s |value|, in its unit.
pub fn absurd_limit(r: Response) -> f64 {
    match r {
        Response::YawRate => ABSURD_YAW_RATE,
        Response::Ay => ABSURD_AY,
        Response::Beta => ABSURD_BETA,
    }
}

/// Refuses the first response sample of `run` beyond its channel's
/// [`absurd_limit`], at its cell, in the order yaw rate, `ay`, sideslip.
pub(super) fn check_responses(
    path: &Path,
    c: &Columns,
    run: &MeasuredRun,
) -> Result<(), InputError> {
    let channels = [
        (Response::YawRate, Some(&run.yaw_rate)),
        (Response::Ay, run.ay.as_ref()),
        (Response::Beta, run.beta.as_ref()),
    ];
    for (channel, x) in channels {
        let Some(x) = x else { continue };
        let limit = absurd_limit(channel);
        if let Some(i) = x.iter().position(|v| v.abs() > limit) {
            let problem = ResponseBeyondAnyCar {
                channel,
                value: x[i],
                limit,
            };
            return Err(c.error_at(path, i, channel.column(), problem.into()));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The words of each channel's refusal: its column, value, limit in
    /// its unit and another, and what a car does.
    #[test]
    fn each_channel_is_refused_with_its_limit_and_why() {
        let said = |channel, value| {
            let limit = absurd_limit(channel);
            ResponseBeyondAnyCar {
                channel,
                value,
                limit,
            }
            .to_string()
        };
        let ay = said(Response::Ay, 500.0);
        assert!(
            ay.starts_with("column `ay`: 500 m/s² is beyond ±100 m/s² (±10 g), which no car's lateral acceleration reaches"),
            "{ay}"
        );
        let r = said(Response::YawRate, 1e308);
        assert!(
            r.starts_with("column `yaw_rate`: 1e308 rad/s is beyond ±10 rad/s (±573 deg/s, 1.6 turns a second)"),
            "{r}"
        );
        let b = said(Response::Beta, -4.0);
        assert!(
            b.starts_with("column `beta`: -4 rad is beyond ±3.14159 rad (±180 deg)"),
            "{b}"
        );
        for s in [ay, r, b] {
            assert!(s.ends_with("mend or remove this row"), "{s}");
        }
    }
}
