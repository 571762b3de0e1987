//! The lateral acceleration `metrics` reads from a history `simulate`
//! wrote with roll: there `ay` is what an accelerometer on the rolled body
//! reads, `a_y·cos φ + g·sin φ` (ISO 8855, φ positive right side down;
//! [`crate::sim::TimeHistory::accelerometer_ay`]), 7 % above the body
//! frame's at 4°/g of roll, and the body frame's value, the one
//! `simulate`'s own metrics read, follows in the column `ay_body`. Where a
//! run carries that column it is read as `ay` and said so; a logged run
//! without it is read as before. Units: m/s².

use crate::error::Error;
use crate::measured::MeasuredRun;
use serde::Serialize;
use std::path::Path;

/// The column of the body frame's lateral acceleration in a history.
pub const BODY_AY: &str = "ay_body";

/// Which column the metrics' lateral acceleration was read from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AyColumn {
    /// The run's `ay` (an accelerometer's reading, or a history without
    /// roll).
    Ay,
    /// `ay_body`: the body frame's, beside an accelerometer's `ay` on a
    /// rolled body.
    AyBody,
}

impl AyColumn {
    /// The note beside the table (None for the run's own `ay`).
    pub fn note(self) -> Option<String> {
        match self {
            AyColumn::Ay => None,
            AyColumn::AyBody => Some(format!(
                "ay read from {BODY_AY}: the body frame's lateral acceleration, as simulate's own metrics read it; the run's ay is what an accelerometer on the rolled body reads (ay·cos φ + g·sin φ), left unread"
            )),
        }
    }
}

/// `run` (read from `path`) with its `ay` replaced by the file's
/// [`BODY_AY`] column where it has one of the run's length, and which
/// column was read.
pub fn body_frame_ay(path: &Path, run: &mut MeasuredRun) -> Result<AyColumn, Error> {
    let mut columns = crate::io::read_columns(path, &["t"], &[BODY_AY])?;
    match columns.take_optional(BODY_AY) {
        Some(ay) if ay.len() == run.t.len() => {
            run.ay = Some(ay);
            Ok(AyColumn::AyBody)
        }
        _ => Ok(AyColumn::Ay),
    }
}
