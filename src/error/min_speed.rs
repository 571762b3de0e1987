//! A campaign's `min_speed` above the top speed of all its runs but at
//! most one: every sample of theirs is left out of the replays, and
//! "0 runs after checking … set [runs] segment" sent the user to cut logs
//! that were never too long. Said as the campaign file's other key
//! refusals are (`` `diagnose.min_speed` = 50: must lie in [0, …] ``):
//! the key and its value, the range these runs allow (up to the top speed
//! of the second-fastest, for held-out scoring's two runs), each run's top
//! speed, and a value to write that keeps them all. Speeds in m/s.

use super::Num;
use crate::format::fixed_apart;

/// `min_speed` removed every run, or all but one.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", self.said())]
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

impl MinSpeedRemoved {
    /// The largest `min_speed` two runs reach: the second-fastest run's
    /// top speed, m/s; `None` for a campaign of one run.
    fn highest_kept(&self) -> Option<f64> {
        let mut tops: Vec<f64> = self.runs.iter().map(|(_, v)| *v).collect();
        tops.sort_by(|a, b| b.total_cmp(a));
        tops.get(1).copied()
    }

    fn said(&self) -> String {
        let v = self.min_speed;
        let default = if self.stated { "" } else { " (the default)" };
        let range = match self.highest_kept() {
            Some(hi) => format!(
                "must lie in [0, {}] for these runs, at most the top speed of the second-fastest (held-out scoring needs at least two runs)",
                // Rounded down: a bound printed above it is refused again.
                crate::format::rounded_down(hi, 4)
            ),
            None => "must lie below the run's top speed".to_string(),
        };
        let which = match self.removed == self.runs.len() {
            true => "every run: no sample of theirs reaches it".to_string(),
            false => format!(
                "{} of the {} runs: no sample of theirs but one run's reaches it",
                self.removed,
                self.runs.len()
            ),
        };
        // A top speed just below the threshold is not printed as it.
        let tops = self
            .runs
            .iter()
            .map(|(run, top)| format!("{run} {} m/s", fixed_apart(&[*top, v], 1)[0]))
            .collect::<Vec<_>>()
            .join(", ");
        format!(
            "`diagnose.min_speed` = {}{default}: {range}; it removes {which} (their top speeds: {tops}); write `min_speed = {}` under [diagnose] (m/s), below every run's top speed",
            Num(v),
            Num(self.suggested)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A top speed of 49.96 m/s under `min_speed = 50` read "50.0 m/s"
    /// beside "no sample of theirs reaches it"; the range is the
    /// second-fastest run's top speed, rounded down.
    #[test]
    fn the_refusal_states_the_range_and_never_rounds_a_top_speed_onto_the_threshold() {
        let e = MinSpeedRemoved {
            min_speed: 50.0,
            stated: true,
            runs: vec![
                ("a.csv".into(), 49.96),
                ("b.csv".into(), 22.07),
                ("c.csv".into(), 20.0),
            ],
            removed: 3,
            suggested: 5.0,
        }
        .to_string();
        assert!(
            e.starts_with("`diagnose.min_speed` = 50: must lie in [0, 22.07] for these runs"),
            "{e}"
        );
        assert!(
            e.contains("(their top speeds: a.csv 49.96 m/s, b.csv 22.1 m/s, c.csv 20.0 m/s); write `min_speed = 5` under [diagnose]"),
            "{e}"
        );
    }
}
