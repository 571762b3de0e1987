//! Measured vehicle runs (`FORMATS.md`): t, speed, steer, yaw_rate required;
//! ay, beta, roll, bank, ax optional. SI units, radians, ISO 8855 signs.

use super::columns::read_columns;
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
    Ok(MeasuredRun {
        path: path.to_path_buf(),
        t,
        speed: c.take("speed"),
        steer,
        yaw_rate: c.take("yaw_rate"),
        ay: c.take_optional("ay"),
        beta: c.take_optional("beta"),
        roll: c.take_optional("roll"),
        bank: c.take_optional("bank"),
        ax: c.take_optional("ax"),
        masked: Vec::new(),
    })
}
