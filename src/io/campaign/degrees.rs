//! A campaign's `[runs] degrees` checked against its run files' headers
//! before they are read: a column declared in degrees that none of them
//! has (`degrees = ["bank"]` for logs without a bank) is refused at the
//! key, with the angle columns the runs have and the values the key
//! takes, not at the first run file's header, which the user did not
//! write wrong.

use crate::error::{InputError, InputProblem, KindProblem};
use crate::io::toml_file::TomlSource;
use crate::io::AngleColumn;
use std::path::PathBuf;

/// The header's columns of the CSV file at `path` (its first line that is
/// neither blank nor a comment), `None` where it cannot be read.
fn header(path: &std::path::Path) -> Option<Vec<String>> {
    let text = std::fs::read_to_string(path).ok()?;
    let first = text
        .lines()
        .find(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))?;
    Some(first.split(',').map(|c| c.trim().to_string()).collect())
}

/// Refuses at `runs.degrees[i]` a column none of `files` has, nor a
/// column named nearly so (a `Bank` the file's reader names for renaming):
/// every such column in one refusal (refused one at a time, `degrees =
/// ["roll", "bank"]` was mended and rerun to hear of `bank`).
pub(super) fn check_declared(
    src: &TomlSource,
    degrees: &[AngleColumn],
    files: &[PathBuf],
) -> Result<(), InputError> {
    let headers: Option<Vec<Vec<String>>> = files.iter().map(|p| header(p)).collect();
    let Some(headers) = headers.filter(|h| !h.is_empty()) else {
        // No runs, or one unreadable: its reader says so.
        return Ok(());
    };
    let has = |name: &str| headers.iter().any(|h| h.iter().any(|c| c == name));
    let near = |name: &str| {
        headers.iter().any(|h| {
            let h: Vec<&str> = h.iter().map(String::as_str).collect();
            crate::format::nearest_name(name, &h).is_some()
        })
    };
    let mut refused = Vec::new();
    for (i, column) in degrees.iter().enumerate() {
        let name = column.name();
        if has(name) || near(name) {
            continue;
        }
        let problem = KindProblem::DegreesNowhere {
            column: name,
            files: files.len(),
            present: AngleColumn::ALL
                .iter()
                .map(|a| a.name())
                .filter(|a| has(a))
                .collect(),
            allowed: AngleColumn::ALL.iter().map(|a| a.name()).collect(),
        };
        let span = src.key_span(&format!("runs.degrees[{i}]"));
        refused.push(src.located(span, InputProblem::Kind(Box::new(problem))));
    }
    let path = refused.first().map(|e| e.path().to_path_buf());
    match path.and_then(|p| InputError::all_in_file_order(&p, refused)) {
        Some(e) => Err(e),
        None => Ok(()),
    }
}
