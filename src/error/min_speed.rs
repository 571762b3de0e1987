//! A campaign's `min_speed` above the top speed of all its runs but at
//! most one: every sample of theirs is left out of the replays, and
//! "0 runs after checking … set [runs] segment" sent the user to cut logs
//! that were never too long. It names the key, each run's top speed, and a
//! value that keeps them all.

use super::Num;
use crate::format::fixed;

/// `min_speed` removed every run, or all but one.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("min_speed = {} m/s{} removed {}: {} (their top speeds: {}); held-out scoring needs at least two runs: set `min_speed = {}` under [diagnose], below every run's top speed", Num(*min_speed), if *stated { "" } else { " (the default)" }, if self.removed == self.runs.len() { "every run".to_string() } else { format!("{} of the {} runs", self.removed, self.runs.len()) }, if self.removed == self.runs.len() { "no sample of theirs reaches it" } else { "no sample of theirs but one run's reaches it" }, self.runs.iter().map(|(run, top)| format!("{run} {} m/s", fixed(*top, 1))).collect::<Vec<_>>().join(", "), Num(*suggested))]
pub struct MinSpeedRemoved {
    /// The speed threshold, m/s.
    pub min_speed: f64,
    /// Whether the campaign states it (else the default).
    pub stated: bool,
    /// Each run file (its name) and its top speed, m/s.
    pub runs: Vec<(String, f64)>,
    /// The runs whose top speed is below `min_speed`.
    pub removed: usize,
    /// A threshold that keeps every run, m/s.
    pub suggested: f64,
}
