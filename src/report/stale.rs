//! An output folder that an earlier run wrote into: the files of this
//! command's own set that this run does not write (a step steer's
//! `metrics.json` beside a replay's outputs, a fourth phase portrait beside
//! a sweep that draws three) are an earlier run's, and left there they mix
//! two runs in one folder. They are removed once this run's outputs are
//! written (a failed run leaves the earlier run whole), each one said.
//! Files of no command's set of this one (another command's outputs, the
//! user's own) are left as they are, and said as not this run's.

use crate::error::{Error, OutputError, WriteStep};
use std::fs;
use std::path::{Path, PathBuf};

/// The names a command's outputs take in its folder.
#[derive(Debug, Clone, Copy)]
pub struct OwnSet {
    /// Fixed names (`history.csv`).
    pub names: &'static [&'static str],
    /// Numbered or named families: a prefix and a suffix
    /// (`phase_portrait_`, `.png`).
    pub families: &'static [(&'static str, &'static str)],
}

impl OwnSet {
    fn holds(&self, name: &str) -> bool {
        self.names.contains(&name)
            || self.families.iter().any(|(p, s)| {
                name.len() > p.len() + s.len() && name.starts_with(p) && name.ends_with(s)
            })
    }
}

/// What an output folder holds besides the files a run writes.
#[derive(Debug, Clone, Default)]
pub struct Leftovers {
    /// Files of the command's own set this run does not write: removed
    /// after its outputs are written.
    pub stale: Vec<PathBuf>,
    /// Other files (names), left as they are.
    pub foreign: Vec<String>,
}

/// The files of folder `dir` besides `written` (the files this run
/// writes), by `own`. Hidden files (the lock, a write's partial file) and
/// a sharded run's `shard-K-of-N.json` (the inputs of a merge) are no
/// run's outputs and are not listed.
pub fn leftovers(dir: &Path, own: &OwnSet, written: &[PathBuf]) -> Leftovers {
    let mut out = Leftovers::default();
    let Ok(entries) = fs::read_dir(dir) else {
        return out;
    };
    let mut names: Vec<String> = entries
        .flatten()
        .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| !n.starts_with('.'))
        .filter(|n| !(n.starts_with("shard-") && n.ends_with(".json")))
        .filter(|n| !written.iter().any(|w| w.file_name() == Some(n.as_ref())))
        .collect();
    names.sort();
    for n in names {
        match own.holds(&n) {
            true => out.stale.push(dir.join(n)),
            false => out.foreign.push(n),
        }
    }
    out
}

impl Leftovers {
    /// Removes the stale files.
    pub fn remove(&self) -> Result<(), Error> {
        for path in &self.stale {
            match fs::remove_file(path) {
                Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                    return Err(OutputError::io(path, WriteStep::RemoveStale, e).into())
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// The lines a run's summary ends with: what was removed, and what
    /// the folder holds that this run did not write.
    pub fn lines(&self, command: &str) -> Vec<String> {
        let name = |p: &PathBuf| {
            p.file_name()
                .map_or(String::new(), |n| n.to_string_lossy().into_owned())
        };
        let mut out = Vec::new();
        if !self.stale.is_empty() {
            out.push(format!(
                "removed {} of an earlier `{command}` run into this folder, which this run does not write: {}",
                crate::format::plural(self.stale.len(), "file", "files"),
                self.stale.iter().map(name).collect::<Vec<_>>().join(", ")
            ));
        }
        if !self.foreign.is_empty() {
            out.push(format!(
                "the folder also holds {} that `{command}` does not write, left as they are: {} (give each run a folder of its own, with --out, to keep runs apart)",
                crate::format::plural(self.foreign.len(), "file", "files"),
                first_names(&self.foreign)
            ));
        }
        out
    }
}

/// The most names of other files a summary lists: a working folder given
/// as `--out .` held 187, said on one 3,029-character line.
const LISTED: usize = 5;

/// `names` joined, the first [`LISTED`] of them and how many more where
/// there are more.
fn first_names(names: &[String]) -> String {
    if names.len() <= LISTED {
        return names.join(", ");
    }
    format!(
        "{} and {} more",
        names[..LISTED].join(", "),
        names.len() - LISTED
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn own_files_not_written_are_stale_and_others_foreign() {
        let dir = tempfile::tempdir().unwrap();
        for n in [
            "history.csv",
            "metrics.json",
            "notes.txt",
            ".handling.lock",
            "shard-1-of-2.json",
            "phase_portrait_3.png",
        ] {
            fs::write(dir.path().join(n), "x").unwrap();
        }
        let own = OwnSet {
            names: &["history.csv", "metrics.json"],
            families: &[("phase_portrait_", ".png")],
        };
        let written = [dir.path().join("history.csv")];
        let l = leftovers(dir.path(), &own, &written);
        let stale: Vec<String> = l
            .stale
            .iter()
            .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
            .collect();
        assert_eq!(stale, ["metrics.json", "phase_portrait_3.png"]);
        assert_eq!(l.foreign, ["notes.txt"]);
        let many: Vec<String> = (1..=7).map(|i| format!("n{i}.txt")).collect();
        let said = Leftovers {
            foreign: many,
            ..Leftovers::default()
        }
        .lines("simulate");
        assert!(
            said[0].contains("7 files that `simulate` does not write, left as they are: n1.txt, n2.txt, n3.txt, n4.txt, n5.txt and 2 more ("),
            "{said:?}"
        );
        l.remove().unwrap();
        assert!(!dir.path().join("metrics.json").exists());
        assert!(dir.path().join("notes.txt").exists());
    }
}
