//! What a file handed to a command is, recognised in one place for every
//! reader (a scenario's, a campaign's, the CSV readers'): by its name, its
//! first bytes, a CSV's header or a TOML file's tables. Asked only once a
//! file fails to read as what the command wants, so a file is never
//! refused for its name; each reader says the kind in its own words
//! ([`crate::error::FileKind`]).

use crate::error::{FileKind, InputError, InputProblem, KindProblem, Wanted};
use std::path::Path;

/// What the file or folder at `path` is, where it can be told: `None` for
/// a file that reads as nothing known (its reader's own error stands).
pub(crate) fn recognise(path: &Path) -> Option<FileKind> {
    if path.is_dir() {
        let campaign = path.join("vehicle.toml").is_file();
        return Some(FileKind::Folder { campaign });
    }
    let bytes = std::fs::read(path).ok()?;
    let head = &bytes[..bytes.len().min(8192)];
    if let Some(format) = crate::error::ForeignFormat::of(head) {
        return Some(FileKind::Foreign(format));
    }
    if let Some(at) = head.iter().position(|&b| b == 0) {
        return Some(FileKind::Binary { at });
    }
    let text = String::from_utf8_lossy(&bytes);
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    // The first line that is neither blank nor a comment (a scenario's
    // opening comment may hold a comma).
    let first = text
        .lines()
        .find(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .unwrap_or("");
    if text.lines().any(|l| l.trim_start().starts_with("[MODEL]")) {
        return Some(FileKind::Tir);
    }
    // A `.tir` name on a file without [MODEL] that reads as one of the
    // project's TOML files (a TOML tyre saved as `.tir`) is that file; one
    // whose first line is a CSV header (a rig file copied under a tyre's
    // name) is that CSV, not a `.tir` missing its keys.
    if ext == "tir" {
        let toml = text.parse::<toml::Table>().ok();
        let csv = first.contains(',') && !first.contains(['=', '[']);
        let kind = toml.and_then(|t| toml_kind(&t));
        return Some(kind.unwrap_or_else(|| match csv {
            true => csv_kind(first),
            false => FileKind::Tir,
        }));
    }
    if ext == "json" || first.trim_start().starts_with('{') {
        return Some(FileKind::Json);
    }
    let header = ext != "toml" && first.contains(',') && !first.contains(['=', '[']);
    if ext == "csv" || header {
        return Some(csv_kind(first));
    }
    match text.parse::<toml::Table>() {
        Ok(table) => toml_kind(&table),
        Err(_) => not_toml(&text, first),
    }
}

/// The most characters of a text file's first line a refusal quotes.
const QUOTED_CHARS: usize = 60;

/// A text that failed to read as TOML and has no line a TOML file has (a
/// `key = value` or a `[table]`): a README or notes given in a TOML
/// file's place. A TOML file with a slip (a key without its `=`) keeps
/// its reader's error, at the slip's line: its other lines are TOML.
fn not_toml(text: &str, first: &str) -> Option<FileKind> {
    // A key is bare (letters, digits, `_`, `-`), quoted or dotted: prose
    // with an `=` in it (`QSY7 = 0` in a sentence) is no key's line.
    let key = |k: &str| {
        let k = k.trim();
        !k.is_empty()
            && k.chars()
                .all(|c| c.is_ascii_alphanumeric() || "_-.\"'".contains(c))
    };
    let tomlish = |l: &str| {
        let l = l.trim();
        (l.starts_with('[') && l.ends_with(']')) || l.split_once('=').is_some_and(|(k, _)| key(k))
    };
    let lines = text
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'));
    if first.is_empty() || lines.clone().any(tomlish) {
        return None;
    }
    let first = first.trim();
    let quoted: String = first.chars().take(QUOTED_CHARS).collect();
    let ellipsis = if first.chars().count() > QUOTED_CHARS {
        "…"
    } else {
        ""
    };
    Some(FileKind::Text {
        first: format!("{quoted}{ellipsis}").into(),
    })
}

/// A TOML file by its tables: a study (`[stiffness]`) or sweep
/// (`[sweep]`), a campaign (`[runs]`, `[diagnose]`), before a scenario
/// (a study has a `[manoeuvre]` too), a tyre file (a `model` name and
/// no vehicle).
fn toml_kind(table: &toml::Table) -> Option<FileKind> {
    let has = |k: &str| table.get(k).is_some_and(toml::Value::is_table);
    if has("stiffness") {
        return Some(FileKind::Study);
    }
    if has("sweep") {
        return Some(FileKind::Sweep);
    }
    if has("runs") || has("diagnose") {
        return Some(FileKind::Campaign);
    }
    if has("manoeuvre") {
        return Some(FileKind::Scenario);
    }
    let model = table.get("model")?.as_str()?;
    let vehicle = ["vehicle", "tyres"].iter().any(|k| table.contains_key(*k));
    (!vehicle).then(|| FileKind::TyreToml {
        model: model.into(),
    })
}

/// The columns of a CSV header line, trimmed, unquoted, lower case.
fn header_columns(first: &str) -> Vec<String> {
    first
        .split(',')
        .map(|c| c.trim().trim_matches('"').to_ascii_lowercase())
        .collect()
}

/// A CSV file by its header `first`: a simulation history, a run, rig
/// data, or another.
pub(crate) fn csv_kind(first: &str) -> FileKind {
    let columns = header_columns(first);
    let has = |c: &str| columns.iter().any(|x| x == c);
    if has("t") && has("steer") && has("fy_front") && has("alpha_front") {
        FileKind::HistoryCsv
    } else if has("t") && has("speed") && has("steer") {
        FileKind::RunCsv
    } else if has("fz") && (has("alpha") || has("kappa")) {
        FileKind::RigCsv
    } else {
        FileKind::Csv {
            first: columns.first().cloned().unwrap_or_default().into(),
        }
    }
}

/// What a CSV reader requiring `required` wants: tyre data where it needs
/// `fz`, a run where it needs `steer` or `yaw_rate`.
fn wanted(required: &[&str]) -> Option<Wanted> {
    if required.contains(&"fz") {
        Some(Wanted::Tyre)
    } else if required.iter().any(|c| ["steer", "yaw_rate"].contains(c)) {
        Some(Wanted::Run)
    } else {
        None
    }
}

/// The refusal of the file at `path`, given to a CSV reader requiring
/// `required` and lacking some of them, where it is plainly of another
/// kind (rig data given as a run, a run or a scenario as rig data, a
/// folder): one sentence naming the kind and its command, in place of a
/// complaint per column; `None` where the file may be what was wanted.
pub(crate) fn not_wanted(path: &Path, required: &[&str]) -> Option<InputError> {
    let wanted = wanted(required)?;
    let kind = recognise(path)?;
    let fits = matches!(
        (&kind, wanted),
        (FileKind::Csv { .. }, _)
            | (FileKind::RunCsv | FileKind::HistoryCsv, Wanted::Run)
            | (FileKind::RigCsv, Wanted::Tyre)
    );
    if fits {
        return None;
    }
    Some(refusal(path, kind, wanted))
}

/// The refusal of the file or folder at `path` given to a reader of
/// TOML files of `wanted`'s kind (`equilibria`'s sweep, `study`'s study)
/// that failed to read it, where it is plainly of another kind (a
/// campaign, a run or history CSV, a `.tir`, a tyre file); `None` where it
/// may be one of `own` (its reader's own error stands).
pub(crate) fn not_this_toml(path: &Path, wanted: Wanted, own: &[FileKind]) -> Option<InputError> {
    let kind = recognise(path)?;
    (!own.contains(&kind)).then(|| refusal(path, kind, wanted))
}

/// The refusal of the file at `path` given as a Magic Formula `.tir`
/// (`wanted`: `identify --template`'s, or any reader's of a `.tir` name)
/// that failed to read as one, where it is plainly another kind (a TOML
/// tyre, a scenario, a rig CSV): said as what it is and which command
/// reads it, in place of the `.tir` reader's "missing key FITTYP";
/// `None` where it may be a `.tir` with a slip (its reader's error stands).
pub(crate) fn not_a_tir(path: &Path, wanted: Wanted) -> Option<InputError> {
    not_this_toml(path, wanted, &[FileKind::Tir])
}

/// The refusal of the file at `path`, of `kind`, where `wanted` was
/// wanted: the kind and its command, with a CSV's header.
fn refusal(path: &Path, kind: FileKind, wanted: Wanted) -> InputError {
    let columns = match kind {
        FileKind::RunCsv | FileKind::HistoryCsv | FileKind::RigCsv => {
            let text = std::fs::read_to_string(path).unwrap_or_default();
            let first = text
                .lines()
                .find(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
                .unwrap_or("");
            first.split(',').map(|c| c.trim().to_string()).collect()
        }
        _ => Vec::new(),
    };
    let problem = KindProblem::NotWanted {
        kind,
        wanted,
        columns,
    };
    InputError::problem(path, InputProblem::Kind(Box::new(problem)))
}

/// The refusal of the file or folder at `path` given as a tyre file
/// (`tyre-eval`'s tyre) where it is plainly of another kind (a scenario,
/// a campaign, a study, a history, a run, a folder); `None` where it may
/// be a tyre file, or is a CSV of `tyre-eval`'s points (`points`: the
/// arguments' order is then the likelier slip, said by the caller).
pub(crate) fn not_a_tyre(path: &Path, points: &[&str]) -> Option<InputError> {
    let kind = recognise(path)?;
    let is_points = |first: &str| {
        let columns = header_columns(first);
        points.iter().all(|c| columns.iter().any(|x| x == c))
    };
    match &kind {
        FileKind::Tir | FileKind::TyreToml { .. } => None,
        FileKind::RigCsv | FileKind::Csv { .. }
            if first_line(path).is_some_and(|f| is_points(&f)) =>
        {
            None
        }
        _ => Some(refusal(path, kind, Wanted::TyreFile)),
    }
}

/// The refusal of a tyre rig file given as `tyre-eval`'s points that lacks
/// some of their columns `points` and has a measured force (`fy`, `fx`,
/// `mz`, which points do not need): said as a rig file, which `identify`
/// reads. A points file with a column misspelt keeps its column errors.
pub(crate) fn rig_as_points(path: &Path, points: &[&str]) -> Option<InputError> {
    if recognise(path)? != FileKind::RigCsv {
        return None;
    }
    let columns = header_columns(&first_line(path)?);
    let has = |c: &str| columns.iter().any(|x| x == c);
    let lacking = points.iter().any(|c| !has(c));
    let measured = ["fy", "fx", "mz"].iter().any(|c| has(c));
    (lacking && measured).then(|| refusal(path, FileKind::RigCsv, Wanted::Points))
}

/// The first line of the file at `path` that is neither blank nor a
/// comment.
fn first_line(path: &Path) -> Option<String> {
    let text = std::fs::read_to_string(path).ok()?;
    let first = text
        .lines()
        .find(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))?;
    Some(first.to_string())
}
