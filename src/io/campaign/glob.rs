//! A wildcard in `[runs] files` (`runs/*.csv`) or in `[runs] dir`: the list
//! names files and `dir` a folder as written, and a shell's glob is no
//! file name, so the entry is answered with what selects the same runs
//! (`dir` where it matches every `*.csv` of its folder, else the list of
//! the files it matches), not with "does not exist", and never with a
//! `dir` that reads more runs than the pattern meant.

use crate::error::{
    folder_of, CampaignFileProblem, GlobMatch, InputError, InputProblem, SelectionProblem,
};
use crate::io::toml_file::TomlSource;
use std::path::{Path, PathBuf};

/// Refuses the first entry of `files` (as written, resolved beside `base`)
/// that holds a wildcard and names no file.
pub(super) fn refuse_globs(
    src: &TomlSource,
    files: &[PathBuf],
    base: &Path,
) -> Result<(), InputError> {
    for (i, f) in files.iter().enumerate() {
        let Some(pattern) = wildcard(f, base) else {
            continue;
        };
        let folder = folder_of(&pattern);
        let problem = CampaignFileProblem::RunsGlob {
            found: matches(base, &pattern),
            folder: folder.into(),
            pattern: pattern.as_str().into(),
        };
        return Err(src.located(
            src.key_span(&format!("runs.files[{i}]")),
            InputProblem::Campaign(Box::new(problem)),
        ));
    }
    Ok(())
}

/// Refuses a `dir` (as written, resolved beside `base`) that holds a
/// wildcard and names no folder.
pub(super) fn refuse_dir_glob(
    src: &TomlSource,
    dir: Option<&PathBuf>,
    base: &Path,
) -> Result<(), InputError> {
    let Some(pattern) = dir.and_then(|d| wildcard(d, base)) else {
        return Ok(());
    };
    let folder = folder_of(&pattern);
    let problem = SelectionProblem::GlobInDir {
        found: matches(base, &pattern),
        folder: folder.into(),
        pattern: pattern.as_str().into(),
    };
    Err(src.located(
        src.key_span("runs.dir"),
        InputProblem::Campaign(Box::new(CampaignFileProblem::Selection(problem))),
    ))
}

/// The path as written when it holds a wildcard and names nothing.
fn wildcard(p: &Path, base: &Path) -> Option<String> {
    let written = p.to_string_lossy();
    (written.contains(['*', '?']) && !crate::io::paths::beside(base, p).exists())
        .then(|| written.into_owned())
}

/// The files of its folder that `pattern` (as written, relative to
/// `base`) matches, named as written.
fn matches(base: &Path, pattern: &str) -> GlobMatch {
    let folder = folder_of(pattern);
    let (written_folder, name) = match pattern.rfind(['/', '\\']) {
        Some(i) => (&pattern[..i], &pattern[i + 1..]),
        None => ("", pattern),
    };
    if written_folder.contains(['*', '?']) || name.is_empty() {
        return GlobMatch::InFolderName;
    }
    let Ok(entries) = std::fs::read_dir(crate::io::paths::beside(base, Path::new(folder))) else {
        return GlobMatch::NoFolder;
    };
    let mut files: Vec<String> = entries
        .filter_map(|e| e.ok())
        .filter(|e| e.path().is_file())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    files.sort();
    // What `dir` reads: the `.csv` (or `.CSV`) files.
    let is_csv = |f: &String| {
        Path::new(f)
            .extension()
            .is_some_and(|x| x.eq_ignore_ascii_case("csv"))
    };
    let csvs: Vec<&String> = files.iter().filter(|f| is_csv(f)).collect();
    let hit: Vec<&String> = files.iter().filter(|f| wild_match(name, f)).collect();
    let whole_folder = !hit.is_empty() && hit == csvs;
    let joined = |f: &String| match folder {
        "." if !pattern.starts_with("./") => f.clone(),
        "/" => format!("/{f}"),
        _ => format!("{folder}/{f}"),
    };
    GlobMatch::Files {
        matched: hit.into_iter().map(joined).collect(),
        whole_folder,
        csvs: csvs.len(),
    }
}

/// Whether `name` matches `pattern`, `*` standing for any characters and
/// `?` for one, as a shell reads them.
fn wild_match(pattern: &str, name: &str) -> bool {
    let (p, n): (Vec<char>, Vec<char>) = (pattern.chars().collect(), name.chars().collect());
    let (mut i, mut j) = (0, 0);
    // The last `*` and the name's position it stood for: backtracked to.
    let mut star: Option<(usize, usize)> = None;
    while j < n.len() {
        match p.get(i) {
            Some('*') => {
                star = Some((i, j));
                i += 1;
            }
            Some(&c) if c == '?' || c == n[j] => {
                i += 1;
                j += 1;
            }
            _ => match star {
                Some((si, sj)) => {
                    star = Some((si, sj + 1));
                    i = si + 1;
                    j = sj + 1;
                }
                None => return false,
            },
        }
    }
    p[i..].iter().all(|&c| c == '*')
}

#[cfg(test)]
mod tests {
    use super::wild_match;

    #[test]
    fn a_wildcard_matches_as_a_shell_reads_it() {
        assert!(wild_match("*.csv", "a.csv"));
        assert!(wild_match("step_*.csv", "step_040kph.csv"));
        assert!(!wild_match("step_*.csv", "ramp_080kph.csv"));
        assert!(wild_match("run?.csv", "run1.csv"));
        assert!(!wild_match("run?.csv", "run10.csv"));
        assert!(wild_match("*_*_*", "a_b_c"));
        assert!(!wild_match("*.csv", "a.csv.bak"));
    }
}
