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

/// A log at least this long, s, is said to be cut by `[runs] segment`:
/// a step or a sine steer with its lead-in and settling is over in less
/// than [`SEGMENT_ADVISED`] (the synthetic programme's runs are 6 s), so
/// a log twice that holds more than one manoeuvre. A shorter run is one
/// manoeuvre: cut, its pieces would be parts of one response.
pub const LONG_LOG_SECONDS: f64 = 2.0 * SEGMENT_ADVISED;

/// The `segment` advised for a long log, s.
pub const SEGMENT_ADVISED: f64 = 10.0;

/// A campaign left with fewer than two runs after checking, and what its
/// user can do: add a run file where this campaign reads them (a campaign
/// folder's `runs/`, else `[runs]` of its file), and for a long log, cut
/// it with `segment` under `[runs]` of the campaign file (a campaign
/// folder's `vehicle.toml` takes a `[runs]` table too). Fresh-eyes round
/// 39: a folder campaign of one 6 s run was told to "set [runs] segment"
/// with no word of where, for a run too short to cut.
#[derive(Debug, Clone, PartialEq)]
pub struct TooFewRuns {
    /// Runs left (pieces after cleaning).
    pub runs: usize,
    /// Samples kept.
    pub kept: usize,
    /// Samples read.
    pub read: usize,
    /// The speed threshold, m/s.
    pub min_speed: f64,
    /// The run files read.
    pub files: usize,
    /// The campaign file (a campaign folder's `vehicle.toml`).
    pub file: std::path::PathBuf,
    /// A campaign folder's `runs/`, where its runs are its `*.csv` files
    /// (None: a campaign file, which lists its runs under `[runs]`).
    pub runs_folder: Option<std::path::PathBuf>,
    /// The longest piece kept, s (0 for none).
    pub longest: f64,
}

impl std::fmt::Display for TooFewRuns {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let runs = crate::format::plural(self.runs, "run", "runs");
        write!(
            f,
            "{runs} after checking ({} of {} samples at or above min_speed = {} m/s in pieces long enough): held-out scoring needs at least two: ",
            self.kept,
            self.read,
            Num(self.min_speed)
        )?;
        let file = self.file.display();
        match &self.runs_folder {
            Some(d) => write!(
                f,
                "add a run file to `{}` (the campaign reads every *.csv there as a run)",
                d.display()
            )?,
            None => write!(
                f,
                "add a run file to `files` under [runs] in {file} (or to its `dir` folder)"
            )?,
        }
        if self.longest < LONG_LOG_SECONDS {
            return Ok(());
        }
        let seg = Num(SEGMENT_ADVISED);
        let longest = crate::format::fixed(self.longest, 1);
        match &self.runs_folder {
            Some(_) => write!(f, "; or cut the {longest} s log into pieces of {seg} s: write a table `[runs]` holding `segment = {seg}` into {file} (a campaign folder's vehicle.toml takes one)"),
            None => write!(f, "; or cut the {longest} s log into pieces of {seg} s: `segment = {seg}` under [runs] in {file}"),
        }
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

    /// One 6 s run of a campaign folder is told to add a run file to its
    /// `runs/`, not to cut it; a 30 s log is told both, with the file
    /// `segment` goes into.
    #[test]
    fn too_few_runs_advises_what_the_campaign_can_take() {
        let mut few = TooFewRuns {
            runs: 1,
            kept: 601,
            read: 601,
            min_speed: 5.0,
            files: 1,
            file: "b/vehicle.toml".into(),
            runs_folder: Some("b/runs".into()),
            longest: 6.0,
        };
        let e = few.to_string();
        assert!(e.starts_with("1 run after checking (601 of 601 samples at or above min_speed = 5 m/s in pieces long enough): held-out scoring needs at least two: add a run file to `b/runs`"), "{e}");
        assert!(!e.contains("segment"), "{e}");
        few.longest = 30.0;
        let e = few.to_string();
        assert!(e.ends_with("; or cut the 30.0 s log into pieces of 10 s: write a table `[runs]` holding `segment = 10` into b/vehicle.toml (a campaign folder's vehicle.toml takes one)"), "{e}");
        few.runs_folder = None;
        few.file = "c.toml".into();
        let e = few.to_string();
        assert!(
            e.contains("add a run file to `files` under [runs] in c.toml")
                && e.ends_with("`segment = 10` under [runs] in c.toml"),
            "{e}"
        );
    }
}
