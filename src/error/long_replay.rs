//! A replayed run too long for a history at the scenario's row interval,
//! where the scenario does not write that interval (`[simulation] step`
//! absent: the default): refused at the scenario's `run` key with the
//! run's length, the rows it would make, the limit and what the user can
//! do — cut the run, or write the history coarser. Resampling the log does
//! not help: the history's rows follow the step, not the log's rate.

use super::number::Num;
use crate::format::{rounded, rounded_up};
use std::fmt;

/// The run's numbers. s, counts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LongReplay {
    /// The replayed piece's length, s.
    pub duration: f64,
    /// Its samples.
    pub samples: usize,
    /// The history's row interval (the default), s.
    pub step: f64,
    /// The most rows (after the first) a history holds.
    pub max_rows: f64,
}

impl fmt::Display for LongReplay {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "the replayed run lasts {} s ({} samples): its history, a row every {} s (the default row interval; this scenario sets none), {}; cut the run into pieces of at most {} s, each replayed by its own scenario, or write its history coarser: `step = {}` (s) or more under [simulation] in this scenario (resampling the log does not help: the history's rows follow the step, not the log's rate)",
            Num(self.duration),
            self.samples,
            Num(self.step),
            super::too_many_rows::over(self.duration, self.step, self.max_rows),
            rounded(self.max_rows * self.step, 3),
            rounded_up(self.duration / self.max_rows, 2)
        )
    }
}
