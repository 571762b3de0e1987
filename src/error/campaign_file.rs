//! What makes a file given to `diagnose` no campaign a user meant: a glob
//! in `[runs] files` (read as a name, not a pattern), or a file of another
//! kind (a measured run, a `.tir`, a scenario) given in the campaign's
//! place. Each says what the file is and what to give instead.

use super::FileKind;
use thiserror::Error;

/// The kind of file given to `diagnose` in a campaign's place.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum NotCampaignKind {
    /// A file recognised as another kind ([`FileKind`]).
    Seen(FileKind),
    /// A file not named `.toml` whose text is no TOML.
    NotToml,
}

/// A problem of a campaign file as a whole.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CampaignFileProblem {
    /// A wildcard in a `[runs] files` entry: the list names files as
    /// written, no file is named so, and `dir` reads a folder's runs.
    #[error("`runs.files` = \"{pattern}\": the list names files as written, not a pattern (no file is named so): {}", super::runs_selection::instead(folder, found, false))]
    RunsGlob {
        /// The entry as written.
        pattern: Box<str>,
        /// Its folder part, as written ([`folder_of`]).
        folder: Box<str>,
        /// What it matches.
        found: super::GlobMatch,
    },
    /// What `[runs]` or `--batch` selects wrongly.
    #[error(transparent)]
    Selection(super::SelectionProblem),
    /// `min_speed` above the top speed of all runs but at most one.
    #[error(transparent)]
    MinSpeedRemoved(super::MinSpeedRemoved),
    /// Some or all runs with a steer far larger than their yaw rate.
    #[error(transparent)]
    SteerInDegreesRuns(super::SteerInDegreesRuns),
    /// Runs whose yaw rate `degrees = ["yaw_rate"]` reads 57× small.
    #[error(transparent)]
    YawDeclaredRuns(super::YawDeclaredRuns),
    /// Runs whose steer `degrees = ["steer"]` reads 57× small.
    #[error(transparent)]
    SteerDeclaredRuns(super::SteerDeclaredRuns),
    /// A file of another kind given as the campaign.
    #[error("{}: `handling diagnose` reads a campaign, a TOML file with [vehicle] and [runs] (or a folder with vehicle.toml and runs/*.csv; see FORMATS.md)", what(kind))]
    NotACampaign {
        /// What the file is.
        kind: NotCampaignKind,
    },
}

/// What a file of `kind` is, in words.
fn what(kind: &NotCampaignKind) -> String {
    let seen = match kind {
        NotCampaignKind::Seen(seen) => seen,
        NotCampaignKind::NotToml => {
            return "this file is neither named .toml nor TOML, so not a campaign".into()
        }
    };
    match seen {
        FileKind::RunCsv | FileKind::Csv { .. } => "this is a CSV file (a measured run or rig data), not a campaign: list it under the campaign's [runs] files, or put it in its runs/ folder".into(),
        FileKind::RigCsv => "this is a tyre rig file (a CSV with `fz` and `alpha` or `kappa`), not a campaign: give it as the campaign's `[tyres] rig = \"<this file>\"` (or as tyre_rig.csv in a campaign folder); `handling identify` fits a tyre to it".into(),
        FileKind::Tir => "this is a tyre property file (.tir), not a campaign: give it under the campaign's [tyres] file (or front and rear)".into(),
        FileKind::Scenario => "this is a scenario (it has a [manoeuvre]), which `handling simulate` runs, not a campaign".into(),
        other => format!("this is {}, not a campaign: {}", other.what(), other.reader()),
    }
}

/// The folder part of a glob pattern (`runs` of `runs/*.csv`; `.` for a
/// bare `*.csv`).
pub(crate) fn folder_of(pattern: &str) -> &str {
    let cut = pattern
        .find(['*', '?', '['])
        .map_or(pattern, |i| &pattern[..i]);
    match cut.rfind(['/', '\\']) {
        Some(0) => "/",
        Some(i) => &cut[..i],
        None => ".",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_glob_is_answered_with_its_folder() {
        assert_eq!(folder_of("runs/*.csv"), "runs");
        assert_eq!(folder_of("*.csv"), ".");
        assert_eq!(folder_of("logs/day1/run?.csv"), "logs/day1");
    }
}
