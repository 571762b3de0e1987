//! What a campaign's `[runs]` selects wrongly (a wildcard where a file or
//! folder is named, one run selected by two entries) and what
//! a run selected again as a copy of its file, and what
//! `diagnose --batch` is handed wrongly (a file, a folder that is itself one
//! campaign) or cannot do (no campaign of the folder diagnosed). Each says
//! what to write instead, with the same selection.

use std::path::PathBuf;
use thiserror::Error;

/// What the files a wildcard matches are, beside its folder's runs.
#[derive(Debug, Clone, PartialEq)]
pub enum GlobMatch {
    /// A wildcard in a folder's name, which is not expanded.
    InFolderName,
    /// The folder does not exist.
    NoFolder,
    /// The files of the folder it matches (as written: the folder as in
    /// the pattern, joined to each name), and how many `*.csv` files the
    /// folder holds.
    Files {
        /// The entries it matches, in name order.
        matched: Vec<String>,
        /// Whether they are exactly the folder's `*.csv` files (what
        /// `dir` reads).
        whole_folder: bool,
        /// The folder's `*.csv` files.
        csvs: usize,
    },
}

/// A problem of what a campaign or a batch selects.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SelectionProblem {
    /// A wildcard in `runs.dir` (`runs/*.csv`): `dir` names a folder.
    #[error(
        "`runs.dir` = \"{pattern}\" names a folder, not a pattern (no folder is named so): {}",
        instead(folder, found, true)
    )]
    GlobInDir {
        /// The value as written.
        pattern: Box<str>,
        /// Its folder part, as written.
        folder: Box<str>,
        /// What it matches.
        found: GlobMatch,
    },
    /// One run selected by two entries of `[runs]`.
    #[error("the run {} is listed twice: by {first} and by {second}: each run is held out once, so select it once", run.display())]
    SelectedTwice {
        /// The run.
        run: PathBuf,
        /// The first entry that selects it, with its place.
        first: String,
        /// The second.
        second: String,
    },
    /// A run whose file holds the samples of another selected run's (a
    /// copy, byte for byte or with other line endings or number formats).
    #[error("the run {} is a copy of {} (the same samples), {}: held out, a copy is scored on the samples its twin was fitted on, so it counts the same evidence twice; select one of them", run.display(), copy_of.display(), selected_by(first, second))]
    CopiedRun {
        /// The copy (the later of the two).
        run: PathBuf,
        /// The run it copies.
        copy_of: PathBuf,
        /// The entry that selects the run it copies, with its place.
        first: String,
        /// The entry that selects the copy, with its place.
        second: String,
    },
    /// A file given to `--batch`.
    #[error("--batch reads a folder of campaigns (its sub-folders and .toml files), and this is a file: drop --batch to diagnose it, `handling diagnose {}`", path.display())]
    BatchOfAFile {
        /// The file as given.
        path: PathBuf,
    },
    /// A campaign folder given to `--batch`.
    #[error("--batch reads a folder of campaigns (its sub-folders and .toml files), and this folder is itself one campaign (vehicle.toml and runs/): drop --batch to diagnose it, `handling diagnose {}`", path.display())]
    BatchOfOneCampaign {
        /// The folder as given.
        path: PathBuf,
    },
    /// A batch none of whose campaigns was diagnosed.
    #[error("{}: no fleet to compare", match count {
        1 => format!("its one campaign could not be diagnosed (its reason is listed above and in {})", table.display()),
        n => format!("none of its {n} campaigns could be diagnosed (each one's reason is listed above and in {})", table.display()),
    })]
    BatchAllFailed {
        /// Campaigns in the batch (or the shard).
        count: usize,
        /// The fleet table that lists the reasons.
        table: PathBuf,
    },
}

/// Which `[runs]` entries select two runs: both by one (a folder), or each
/// by its own.
fn selected_by(first: &str, second: &str) -> String {
    match first == second {
        true => format!("both selected by {first}"),
        false => format!("selected by {first} and by {second}"),
    }
}

/// What to write instead of a wildcard in `[runs]` (`dir` when `in_dir`),
/// selecting the same runs.
pub(crate) fn instead(folder: &str, found: &GlobMatch, in_dir: bool) -> String {
    let dir = format!("`dir = \"{folder}\"`");
    match found {
        GlobMatch::InFolderName => {
            "a wildcard in a folder's name is not expanded: list the runs by name under `files`"
                .into()
        }
        GlobMatch::NoFolder => format!("the folder `{folder}` does not exist"),
        GlobMatch::Files {
            whole_folder: true,
            csvs,
            ..
        } => match in_dir {
            true => format!("give the folder, {dir}, which reads its *.csv files, the same {csvs}"),
            false => format!(
                "to read every *.csv of a folder, give it as {dir} instead, which reads the same {csvs} files"
            ),
        },
        GlobMatch::Files { matched, csvs, .. } if matched.is_empty() => format!(
            "no file of `{folder}` matches it: list the runs by name under `files` ({dir} reads all {csvs} *.csv files of the folder)"
        ),
        GlobMatch::Files { matched, csvs, .. } => {
            let list: Vec<String> = matched.iter().map(|m| format!("\"{m}\"")).collect();
            let them = if matched.len() == 1 { "it" } else { "them" };
            format!(
                "it matches {} of the folder's {csvs} *.csv files: list {them}, `files = [{}]` ({dir} would read all {csvs})",
                matched.len(),
                list.join(", ")
            )
        }
    }
}
