//! A run whose history would pass the rows a history holds, as
//! [`super::ParamReason::TooManyRows`] and [`super::LongReplay`] say it:
//! the rows counted whole against the limit (2,000,002 rows were said as
//! "2000000 rows, beyond the 2000000 a history holds"), the size of
//! `history.csv` they make (quoted at [`HISTORY_ROW_BYTES`], measured on
//! written histories), and the key the user can change. s, counts.

use super::number::Num;
use crate::format::rounded_up;
use std::fmt;

/// The size of a row of `history.csv` as written, bytes: 14 columns of
/// about 10 characters, 16 with roll (`roll`, `ay_body`; a step steer's
/// history wrote 140 bytes a row, a sine's with roll steer 169 before its
/// `ay_body`). It was 280, twice the written size.
pub const HISTORY_ROW_BYTES: f64 = 150.0;

/// The rows (the first and one per `step` after it) a run of `duration`
/// s makes, counted as the refusal counts the intervals (a hair of slack
/// for the step's rounding).
pub(crate) fn rows(duration: f64, step: f64) -> f64 {
    (duration / step * (1.0 - 1e-9)).ceil() + 1.0
}

/// "makes 2000002 rows (about 0.3 GB of history.csv), 1 more than the
/// 2000001 a history holds (a first row and 2000000 steps after it)".
pub(crate) fn over(duration: f64, step: f64, max_rows: f64) -> String {
    let rows = rows(duration, step);
    let limit = max_rows + 1.0;
    format!(
        "makes {rows} rows (about {} of history.csv), {} more than the {limit} a history holds (a first row and {max_rows} steps after it)",
        size(rows * HISTORY_ROW_BYTES),
        rows - limit,
    )
}

/// A size in bytes as MB or GB, two significant digits.
fn size(bytes: f64) -> String {
    match bytes < 1e9 {
        true => format!("{} MB", crate::format::significant(bytes / 1e6, 2)),
        false => format!("{} GB", crate::format::significant(bytes / 1e9, 2)),
    }
}

/// The run's numbers. s, counts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TooManyRows {
    /// The recorded rows' interval, s.
    pub step: f64,
    /// The run's length, s.
    pub duration: f64,
    /// The most rows after the first a history holds.
    pub max_rows: f64,
    /// The table the step is set in (`simulation`, or `integrator` where
    /// the file writes that name).
    pub table: &'static str,
}

impl fmt::Display for TooManyRows {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "the run lasts {} s: a row every {} s ([{}] step) {}; set `step` under [{}] to at least {} s, or shorten the run (the manoeuvre's `end`)",
            Num(self.duration),
            Num(self.step),
            self.table,
            over(self.duration, self.step, self.max_rows),
            self.table,
            rounded_up(self.duration / self.max_rows, 2)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_interval_over_the_limit_is_counted_whole() {
        let said = over(6.0, 6.0 / 2_000_001.0, 2e6);
        assert!(
            said.starts_with(
                "makes 2000002 rows (about 300 MB of history.csv), 1 more than the 2000001"
            ),
            "{said}"
        );
        assert_eq!(rows(6.0, 1e-3), 6001.0);
    }
}
