//! Paths that one file gives relative to itself (a campaign's runs, a
//! scenario's tyres), joined to its folder and normalised lexically: `.`
//! dropped and `..` taken back against the component before it, without
//! asking the file system, so that messages and reports show
//! `../logs/run.csv`, not `campaigns/../../logs/run.csv`.

use std::path::{Component, Path, PathBuf};

/// `relative` as seen from the folder `dir` (as it is when absolute),
/// normalised lexically.
pub fn beside(dir: &Path, relative: &Path) -> PathBuf {
    normalised(&dir.join(relative))
}

/// `path` with `.` dropped and each `..` taken back against a folder before
/// it; a `..` at the start of a relative path stays, one at the root is the
/// root. Links are not followed (the path is not looked up).
pub fn normalised(path: &Path) -> PathBuf {
    let mut out: Vec<Component> = Vec::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => match out.last() {
                Some(Component::Normal(_)) => {
                    out.pop();
                }
                Some(Component::RootDir | Component::Prefix(_)) => {}
                _ => out.push(c),
            },
            _ => out.push(c),
        }
    }
    if out.is_empty() {
        return PathBuf::from(".");
    }
    out.iter().collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dots_are_resolved_lexically() {
        let cases = [
            ("campaigns", "../../logs/r.csv", "../logs/r.csv"),
            ("campaigns/a", "./runs/../r.csv", "campaigns/a/r.csv"),
            ("", "tyre.toml", "tyre.toml"),
            ("/data/x", "../../../y.csv", "/y.csv"),
            ("a", "..", "."),
            ("../a", "../b.csv", "../b.csv"),
            ("a", "/abs/./t.tir", "/abs/t.tir"),
        ];
        for (dir, rel, want) in cases {
            assert_eq!(
                beside(Path::new(dir), Path::new(rel)),
                PathBuf::from(want),
                "{dir} + {rel}"
            );
        }
    }
}
