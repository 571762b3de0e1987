//! The lateral acceleration `metrics` reads: the body frame's, as
//! `simulate`'s own metrics and `diagnose` read it. Units: m/s², rad.
//!
//! - A history `simulate` wrote with roll carries in `ay` what an
//!   accelerometer on the rolled body reads, `a_y·cos φ + g·sin φ` (ISO
//!   8855, φ positive right side down;
//!   [`crate::sim::TimeHistory::accelerometer_ay`]), 7 % above the body
//!   frame's at 4°/g of roll, and the body frame's value in `ay_body`:
//!   where a run carries that column it is read as `ay`, and said so.
//! - A run that logs its body roll (`roll`, relative to the road) and no
//!   `ay_body` has its `ay` levelled by it, `(a_y − g·sin φ)/cos φ`, by the
//!   function `diagnose` levels a campaign's runs with
//!   ([`crate::measured::calibration::roll::levelled`], the roll sensor's
//!   own offset measured at the run's standstills, where it has any). Read
//!   unlevelled, a history of roll steer with its `ay_body` removed gave a
//!   steady ay of 2.4542 m/s² against the body's 2.2943 (+7 %), which
//!   `simulate` reports and `diagnose` reads.
//! - Any other run's `ay` is read as logged.

use crate::error::Error;
use crate::measured::calibration::roll::{gravity_term, levelled, roll_offset, RollOffset};
use crate::measured::MeasuredRun;
use serde::Serialize;
use std::path::Path;

/// The column of the body frame's lateral acceleration in a history.
pub const BODY_AY: &str = "ay_body";

/// Which column the metrics' lateral acceleration was read from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AyColumn {
    /// The run's `ay` as logged (an accelerometer's reading, or a history
    /// without roll).
    Ay,
    /// `ay_body`: the body frame's, beside an accelerometer's `ay` on a
    /// rolled body.
    AyBody,
    /// The run's `ay` levelled by its logged `roll` ([`RollLevelling`]).
    AyLevelledByRoll,
}

/// How a run's `ay` was levelled by its logged roll.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RollLevelling {
    /// The roll sensor's own offset, removed from φ first: its mean at the
    /// run's standstills (None without a standstill: φ as logged).
    pub roll_offset: Option<RollOffset>,
    /// The largest gravity term taken out, `|g·sin φ|`, m/s² (99.5th
    /// percentile of the samples).
    pub gravity_term: f64,
}

/// The lateral acceleration read: its column, and the levelling where
/// there was one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AyRead {
    /// The column.
    pub column: AyColumn,
    /// The levelling by the logged roll.
    pub levelling: Option<RollLevelling>,
}

impl AyRead {
    /// The note beside the table (None for the run's own `ay`).
    pub fn note(&self) -> Option<String> {
        match (self.column, self.levelling) {
            (AyColumn::AyBody, _) => Some(format!(
                "ay read from {BODY_AY}: the body frame's lateral acceleration, as simulate's own metrics read it; the run's ay is what an accelerometer on the rolled body reads (ay·cos φ + g·sin φ), left unread"
            )),
            (AyColumn::AyLevelledByRoll, Some(l)) => Some(levelling_note(&l)),
            _ => None,
        }
    }
}

/// The words of a levelling: how, by what, how much.
fn levelling_note(l: &RollLevelling) -> String {
    let offset = match l.roll_offset {
        Some(o) => format!(
            "the logged roll less its own offset, {} ± {} rad, its mean at {} ({} s) where a body does not roll",
            crate::format::readable(o.mean, 3),
            crate::format::readable(o.std_error, 2),
            crate::format::plural(o.spans, "standstill", "standstills"),
            crate::format::fixed(o.seconds, 0)
        ),
        None => "the roll as logged (no standstill to measure its own offset)".to_string(),
    };
    format!(
        "roll: ay levelled by it before the metrics, as diagnose levels it: (ay − g·sin φ)/cos φ with φ {offset} (a body-fixed accelerometer rolled by φ reads g·sin φ of gravity: known from the log); g·sin φ reaches {} m/s² (99.5th percentile of the samples); the metrics' ay is the body frame's",
        crate::format::fixed(l.gravity_term, 3)
    )
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

/// `run` with its `ay` levelled by its logged roll where it has both and
/// its `ay` is the run's own (`column`, not `ay_body`), and what was read.
/// After the dead channels are left out: a dead accelerometer levelled by
/// a live roll would hold more than one value.
pub fn level_by_roll(run: &mut MeasuredRun, column: AyColumn) -> AyRead {
    let unlevelled = AyRead {
        column,
        levelling: None,
    };
    let (Some(roll), Some(_)) = (&run.roll, &run.ay) else {
        return unlevelled;
    };
    if column != AyColumn::Ay {
        return unlevelled;
    }
    let offset = roll_offset(std::slice::from_ref(run));
    let phi0 = offset.map_or(0.0, |o| o.mean);
    let mut terms: Vec<f64> = gravity_term(roll, phi0)
        .into_iter()
        .map(f64::abs)
        .filter(|g| g.is_finite())
        .collect();
    terms.sort_by(f64::total_cmp);
    let gravity_term = crate::measured::clean::quantile(&terms, 0.995).unwrap_or(0.0);
    *run = levelled(run.clone(), phi0);
    AyRead {
        column: AyColumn::AyLevelledByRoll,
        levelling: Some(RollLevelling {
            roll_offset: offset,
            gravity_term,
        }),
    }
}
