//! Measured vehicle runs (`FORMATS.md`): t, speed, steer, yaw_rate required;
//! ay, beta, roll, bank, ax optional. SI units, radians, ISO 8855 signs. A
//! channel whose size says it is in another unit (a time in ms, a steer in
//! degrees, a yaw rate in deg/s, `ay` in g or ft/s², a speed in km/h) is refused at its
//! column ([`super::run_units`]).

use super::columns::read_columns;
use super::run_units::{check_ay, check_speed, check_time_step, check_yaw_rate};
use crate::error::{InputError, InputProblem};
use crate::measured::clean::quantile;
use crate::measured::MeasuredRun;
use std::path::Path;

/// Reads and checks a measured run.
pub fn read_run(path: &Path) -> Result<MeasuredRun, InputError> {
    let mut c = read_columns(
        path,
        &["t", "speed", "steer", "yaw_rate"],
        &["ay", "beta", "roll", "bank", "ax"],
    )?;
    let t = c.take("t");
    for i in 1..t.len() {
        if t[i] <= t[i - 1] {
            return Err(c.error_at(
                path,
                i,
                "t",
                InputProblem::TimeNotIncreasing {
                    value: t[i],
                    previous: t[i - 1],
                },
            ));
        }
    }
    if t.len() < 2 {
        return Err(InputError::problem(path, InputProblem::TooFewSamples));
    }
    check_time_step(path, &c, &t)?;
    // A road-wheel angle beyond 90° is a unit slip, not a manoeuvre: judged
    // on the 99th percentile so that a logger's spike (repaired later) does
    // not refuse the file.
    let steer = c.take("steer");
    let mut size: Vec<f64> = steer.iter().map(|d| d.abs()).collect();
    size.sort_by(f64::total_cmp);
    let p99 = quantile(&size, 0.99).unwrap_or(0.0);
    if p99 > std::f64::consts::FRAC_PI_2 {
        let i = steer
            .iter()
            .position(|d| d.abs() > std::f64::consts::FRAC_PI_2)
            .unwrap_or(0);
        return Err(c.error_at(
            path,
            i,
            "steer",
            InputProblem::SteerBeyondQuarterTurn {
                value: steer[i],
                p99,
            },
        ));
    }
    let (speed, yaw_rate, ay) = (c.take("speed"), c.take("yaw_rate"), c.take_optional("ay"));
    check_speed(path, &c, &speed)?;
    check_yaw_rate(path, &c, &yaw_rate)?;
    if let Some(ay) = &ay {
        check_ay(path, &c, &speed, &yaw_rate, ay)?;
    }
    Ok(MeasuredRun {
        path: path.to_path_buf(),
        t,
        speed,
        steer,
        yaw_rate,
        ay,
        beta: c.take_optional("beta"),
        roll: c.take_optional("roll"),
        bank: c.take_optional("bank"),
        ax: c.take_optional("ax"),
        masked: Vec::new(),
    })
}
