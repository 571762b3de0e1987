//! Measured vehicle runs (`FORMATS.md`): t, speed, steer, yaw_rate required;
//! ay, beta, roll, bank, ax optional. SI units, radians, ISO 8855 signs.

use super::columns::read_columns;
use crate::error::InputError;
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
                format!(
                    "column `t`: {} does not follow {} (time must be strictly increasing)",
                    t[i],
                    t[i - 1]
                ),
            ));
        }
    }
    if t.len() < 2 {
        return Err(InputError::File {
            path: path.to_path_buf(),
            message: "a run needs at least two samples".into(),
        });
    }
    Ok(MeasuredRun {
        path: path.to_path_buf(),
        t,
        speed: c.take("speed"),
        steer: c.take("steer"),
        yaw_rate: c.take("yaw_rate"),
        ay: c.take_optional("ay"),
        beta: c.take_optional("beta"),
        roll: c.take_optional("roll"),
        bank: c.take_optional("bank"),
        ax: c.take_optional("ax"),
        masked: Vec::new(),
    })
}
