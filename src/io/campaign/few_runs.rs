//! A campaign left with fewer than two runs for held-out scoring: refused
//! at a `min_speed` that removed them (speeds in m/s), else with what the
//! campaign can take, where it takes it: a run file in a campaign
//! folder's `runs/` or under `[runs]` of its file, and for a long log a
//! `segment` (s) under `[runs]` of the campaign file, a campaign folder's
//! `vehicle.toml` included ([`crate::error::TooFewRuns`]).

use super::run_checks::file_error;
use crate::error::{CampaignFileProblem, InputError, InputProblem};
use crate::io::toml_file::TomlSource;
use crate::measured::clean::CleaningReport;
use crate::measured::MeasuredRun;
use std::path::{Path, PathBuf};

/// The runs a campaign read: the pieces kept, the run files, the cleaning
/// report and each file's top speed (m/s).
type Read<'a> = (
    &'a [MeasuredRun],
    usize,
    &'a CleaningReport,
    &'a [(String, f64)],
);

/// The refusal of a campaign (file `file`; `runs_folder`, the folder whose
/// `*.csv` it reads as runs, if any) left with the `runs` (fewer than two)
/// of `files` run files, `cleaning` and `top_speeds` (m/s) of the runs
/// read: at the stated `min_speed` (m/s) where it removed them, else in
/// `file` with the counts and the advice.
pub(super) fn too_few_runs(
    src: &TomlSource,
    (file, runs_folder): (&Path, Option<PathBuf>),
    min_speed: f64,
    (runs, files, cleaning, top_speeds): Read,
) -> InputError {
    let stated = src.key_span("diagnose.min_speed");
    if let Some(p) = min_speed_removed(min_speed, stated.is_some(), top_speeds) {
        let p = CampaignFileProblem::MinSpeedRemoved(p);
        return src.located(stated, InputProblem::Campaign(Box::new(p)));
    }
    let longest = runs
        .iter()
        .map(|r| r.t[r.t.len() - 1] - r.t[0])
        .fold(0.0, f64::max);
    let few = crate::error::TooFewRuns {
        runs: runs.len(),
        kept: cleaning.samples_kept,
        read: cleaning.samples_read,
        min_speed,
        files,
        file: file.to_path_buf(),
        runs_folder,
        longest,
    };
    file_error(file, InputProblem::TooFewRuns { few: Box::new(few) })
}

/// The refusal of a `min_speed` (m/s, `stated` or the default) above the
/// `top` speed of all runs but at most one, with a threshold that keeps
/// every run: half the slowest run's top speed, at most the default.
pub(super) fn min_speed_removed(
    min_speed: f64,
    stated: bool,
    top: &[(String, f64)],
) -> Option<crate::error::MinSpeedRemoved> {
    let removed = top.iter().filter(|(_, v)| *v < min_speed).count();
    if removed == 0 || top.len() - removed >= 2 {
        return None;
    }
    let slowest = top.iter().map(|(_, v)| *v).fold(f64::INFINITY, f64::min);
    let half = (5.0 * slowest).floor() / 10.0;
    Some(crate::error::MinSpeedRemoved {
        min_speed,
        stated,
        runs: top.to_vec(),
        removed,
        suggested: half.min(crate::measured::clean::DEFAULT_MIN_SPEED),
    })
}
