//! The rows a run misses in holes in time shorter than a time gap, as the
//! cleaning reports and says them (found by `holes.rs`): how many, in how
//! many holes, the longest, and the regular pattern they make where there
//! is one. Times in s.

use crate::format::plural;
use serde::Serialize;

/// The rows a run misses in holes in time shorter than a time gap.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MissingRows {
    /// The run (file).
    pub run: String,
    /// Holes in time shorter than a gap.
    pub holes: usize,
    /// Samples missing in them, counted on the run's local interval.
    pub samples: usize,
    /// The longest hole, s.
    pub longest: f64,
    /// The last sample before it, s.
    pub longest_after: f64,
    /// The regular pattern the holes make, where they make one.
    pub pattern: Option<RowPattern>,
}

/// Rows dropped in a regular pattern: `missing` of every `every` rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct RowPattern {
    /// Rows missing in each hole.
    pub missing: usize,
    /// Rows from one hole to the next, the missing counted.
    pub every: usize,
}

/// What reads a run across its holes: the cleaning's line says what that
/// reader does there (`metrics` runs no replay).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum ReadAcross {
    /// A replay (`simulate`, `diagnose`): it integrates across a hole and
    /// scores the rows present.
    #[default]
    Replay,
    /// The step's metrics: the piece is interpolated linearly onto one
    /// grid (`metrics::measured::uniform`).
    Metrics,
}

impl MissingRows {
    /// The cleaning's line: how many rows, in how many holes, the pattern,
    /// and what `reader` does across them.
    pub fn line(&self, reader: ReadAcross) -> String {
        let across = match reader {
            ReadAcross::Replay => "the replay runs across them and scores the rows present",
            ReadAcross::Metrics => {
                "the metrics interpolate the piece linearly across them onto one grid"
            }
        };
        format!(
            "missing rows: {} misses {} in {} in time{} (the longest {} s after t = {} s), each shorter than a time gap, so not split: {across}",
            self.run,
            plural(self.samples, "sample", "samples"),
            plural(self.holes, "hole", "holes"),
            self.pattern.map_or(String::new(), |p| format!(
                ", {} of every {} rows throughout (rows dropped in a regular pattern, by a logger or an export)",
                p.missing, p.every
            )),
            crate::format::readable(self.longest, 3),
            crate::format::readable(self.longest_after, 3),
        )
    }
}
