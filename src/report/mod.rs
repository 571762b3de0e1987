//! Outputs: CSV, JSON and PNG files, each written to a temporary file in the
//! destination folder and renamed into place, so a failed run never leaves a
//! half-written file; a refusal to write over any input file; and one run
//! at a time per output folder ([`lock`]). Every CSV of every command goes
//! through [`write_csv`].

pub mod branches;
mod cells;
pub mod colour;
mod encode;
pub mod html;
mod legend;
pub mod lock;
pub mod plot;
pub mod plot_grid;
pub mod progress;
pub mod series;
pub mod stability;
pub mod stale;
mod typeset;

pub use lock::OutputLock;

use crate::error::{Error, OutputError, WriteStep};
use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Temporary sibling of `path`, keeping its extension (image encoders pick
/// the format from it).
fn temp_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy().into_owned());
    let ext = path
        .extension()
        .map_or(String::new(), |e| format!(".{}", e.to_string_lossy()));
    path.with_file_name(format!(".{name}.partial-{}{ext}", std::process::id()))
}

/// Serialises a number that may be undefined (a standard error the data
/// do not pin: NaN inside) as `null`, so that a report holds no NaN and a
/// `null` there says "not defined" by design, not by accident. For
/// `#[serde(serialize_with = "crate::report::finite_or_null")]`.
pub fn finite_or_null<S: serde::Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    if v.is_finite() {
        s.serialize_f64(*v)
    } else {
        s.serialize_none()
    }
}

/// Creates `dir` and its parents.
pub fn create_dir(dir: &Path) -> Result<(), Error> {
    fs::create_dir_all(dir).map_err(|e| OutputError::io(dir, WriteStep::Create, e).into())
}

/// Writes through `fill` into a temporary file, then renames it to `path`.
pub fn write_atomic(
    path: &Path,
    fill: impl FnOnce(&Path) -> Result<(), Error>,
) -> Result<(), Error> {
    if let Some(dir) = path.parent() {
        if !dir.as_os_str().is_empty() {
            fs::create_dir_all(dir)
                .map_err(|e| OutputError::io(dir, WriteStep::CreateFolder, e))?;
        }
    }
    let tmp = temp_path(path);
    let result = fill(&tmp).and_then(|()| {
        fs::rename(&tmp, path)
            .map_err(|e| OutputError::io(path, WriteStep::MoveIntoPlace, e).into())
    });
    if result.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    result
}

/// Writes bytes atomically.
pub fn write_bytes(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    write_atomic(path, |tmp| {
        let mut f =
            fs::File::create(tmp).map_err(|e| OutputError::io(tmp, WriteStep::Create, e))?;
        f.write_all(bytes)
            .and_then(|()| f.sync_all())
            .map_err(|e| OutputError::io(path, WriteStep::Write, e).into())
    })
}

/// Writes a value as pretty JSON, its fields in their declared order.
pub fn write_json<T: serde::Serialize>(path: &Path, value: &T) -> Result<(), Error> {
    let text = serde_json::to_string_pretty(value).map_err(|e| OutputError::encode(path, e))?;
    let mut text = unsigned_zeros(&text);
    text.push('\n');
    write_bytes(path, text.as_bytes())
}

/// `text` (pretty JSON) with every number `-0.0` written `0.0`: a camber
/// level a hair below 0, rounded to zero, is no negative camber (a value
/// is a number where it ends at `,`, `]`, `}` or a line's end).
fn unsigned_zeros(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(i) = rest.find("-0.0") {
        let after = &rest[i + 4..];
        let number = after
            .chars()
            .next()
            .is_none_or(|c| matches!(c, ',' | ']' | '}' | '\n'));
        let before = rest[..i].chars().next_back();
        let starts = before.is_none_or(|c| matches!(c, ' ' | '[' | ':'));
        out.push_str(&rest[..i]);
        out.push_str(if number && starts { "0.0" } else { "-0.0" });
        rest = after;
    }
    out.push_str(rest);
    out
}

/// Writes a value as pretty JSON with the keys of every object in
/// alphabetical order: the layout of the reports that are read back as
/// generic JSON trees.
pub fn write_json_sorted<T: serde::Serialize>(path: &Path, value: &T) -> Result<(), Error> {
    let tree = serde_json::to_value(value).map_err(|e| OutputError::encode(path, e))?;
    write_json(path, &tree)
}

/// Writes a CSV file: a header line and one line per row, each row as many
/// cells as the header (quoted only where a cell holds a comma, a quote or a
/// line break).
pub fn write_csv<R, C>(path: &Path, header: &[&str], rows: R) -> Result<(), Error>
where
    R: IntoIterator<Item = C>,
    C: IntoIterator<Item = String>,
{
    let fail = |e: csv::Error| OutputError::encode(path, e);
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(header).map_err(fail)?;
    for row in rows {
        let row: Vec<String> = row.into_iter().collect();
        if row.len() != header.len() {
            return Err(OutputError::RowLength {
                path: path.to_path_buf(),
                cells: row.len(),
                columns: header.len(),
            }
            .into());
        }
        w.write_record(&row).map_err(fail)?;
    }
    let bytes = w
        .into_inner()
        .map_err(|e| OutputError::encode(path, e.into_error()))?;
    write_bytes(path, &bytes)
}

/// Writes named columns of equal length as CSV with a header line.
pub fn write_columns(path: &Path, columns: &[(&str, &[f64])]) -> Result<(), Error> {
    write_columns_to(path, columns, None)
}

/// [`write_columns`] with each value rounded to `digits` significant
/// digits ([`crate::format::carried`]; `None`: the shortest text that
/// reads back the same `f64`, where exactness matters).
pub fn write_columns_to(
    path: &Path,
    columns: &[(&str, &[f64])],
    digits: Option<usize>,
) -> Result<(), Error> {
    let n = columns.first().map_or(0, |c| c.1.len());
    if columns.iter().any(|c| c.1.len() != n) {
        return Err(OutputError::UnequalColumns {
            path: path.to_path_buf(),
        }
        .into());
    }
    let header: Vec<&str> = columns.iter().map(|c| c.0).collect();
    // The time keeps its steps: `digits` relative to the run's span, not
    // to its origin (a log on Unix-epoch time, 1.69e9 s, written to nine
    // digits had its 1 ms rows collapse to duplicates).
    let digits: Vec<Option<usize>> = columns
        .iter()
        .map(|(name, v)| match *name == "t" {
            true => digits.map(|d| time_digits(v, d)),
            false => digits,
        })
        .collect();
    // The shortest text that reads back the same (no value of hundreds of
    // digits, 1e-300, no `-0`), or the digits the values carry.
    let text = move |v: f64, digits: Option<usize>| match digits {
        Some(d) => crate::format::carried(v, d),
        None => crate::format::exact(v),
    };
    let digits = &digits;
    let rows = (0..n).map(move |i| {
        columns
            .iter()
            .zip(digits)
            .map(move |(c, d)| text(c.1[i], *d))
    });
    write_csv(path, &header, rows)
}

/// The significant digits a time column `t` needs to carry `digits` of
/// its span: as many more as its largest |t| has decades over the span
/// (none for a run from zero), at most 17 (all an f64 has).
fn time_digits(t: &[f64], digits: usize) -> usize {
    let (lo, hi) = t
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    let (span, largest) = (hi - lo, lo.abs().max(hi.abs()));
    if !(span > 0.0 && largest > span) {
        return digits;
    }
    (digits + (largest / span).log10().ceil() as usize).min(17)
}

/// Refuses, before any work, when `out` is one of `inputs` (compared after
/// resolving links) or cannot be written: a file stands where its folder
/// would be.
pub fn refuse_overwrite(out: &Path, inputs: &[PathBuf]) -> Result<(), Error> {
    let mut above = out.parent();
    while let Some(p) = above.filter(|p| !p.as_os_str().is_empty()) {
        if p.exists() {
            if !p.is_dir() {
                return Err(OutputError::NotAFolder {
                    path: out.to_path_buf(),
                    file: p.to_path_buf(),
                }
                .into());
            }
            break;
        }
        above = p.parent();
    }
    let canon = |p: &Path| fs::canonicalize(p).ok();
    if let Some(o) = canon(out) {
        if inputs
            .iter()
            .any(|i| canon(i).as_deref() == Some(o.as_path()))
        {
            return Err(OutputError::Overwrite {
                path: out.to_path_buf(),
            }
            .into());
        }
    }
    Ok(())
}

/// [`refuse_overwrite`] for every output.
pub fn refuse_overwrites<'a>(
    outs: impl IntoIterator<Item = &'a PathBuf>,
    inputs: &[PathBuf],
) -> Result<(), Error> {
    outs.into_iter()
        .try_for_each(|o| refuse_overwrite(o, inputs))
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_negative_zero_is_written_as_zero_and_nothing_else_changes() {
        let text = serde_json::to_string_pretty(&serde_json::json!({
            "camber": -0.0, "levels": [-0.0, -0.05, 0.0], "name": "-0.0,x", "x": -0.001
        }))
        .unwrap();
        let fixed = super::unsigned_zeros(&text);
        let back: serde_json::Value = serde_json::from_str(&fixed).unwrap();
        assert!(
            back["camber"].as_f64().unwrap().is_sign_positive(),
            "{fixed}"
        );
        assert!(back["levels"][0].as_f64().unwrap().is_sign_positive());
        assert_eq!(back["levels"][1], -0.05);
        assert_eq!(back["name"], "-0.0,x");
        assert_eq!(back["x"], -0.001);
        assert!(
            !fixed.contains(": -0.0,") && !fixed.contains(" -0.0\n"),
            "{fixed}"
        );
    }

    use super::*;

    #[test]
    fn failed_write_leaves_no_file() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("a.csv");
        let r = write_atomic(&p, |tmp| {
            fs::write(tmp, "half").unwrap();
            Err(OutputError::UnequalColumns {
                path: tmp.to_path_buf(),
            }
            .into())
        });
        assert!(r.is_err());
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 0);
        write_columns(&p, &[("t", &[0.0, 1.0]), ("x", &[2.0, 3.5])]).unwrap();
        assert_eq!(fs::read_to_string(&p).unwrap(), "t,x\n0,2\n1,3.5\n");
        let e = refuse_overwrite(&p, std::slice::from_ref(&p)).unwrap_err();
        assert!(
            matches!(&e, Error::Output(OutputError::Overwrite { path }) if *path == p),
            "{e}"
        );
    }

    #[test]
    fn csv_rows_must_match_the_header() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("b.csv");
        let rows = vec![vec!["1".to_string(), "stable node".to_string()]];
        write_csv(&p, &["a", "kind"], rows).unwrap();
        assert_eq!(fs::read_to_string(&p).unwrap(), "a,kind\n1,stable node\n");
        let short = vec![vec!["1".to_string()]];
        let e = write_csv(&p, &["a", "kind"], short).unwrap_err();
        assert!(
            matches!(
                e,
                Error::Output(OutputError::RowLength {
                    cells: 1,
                    columns: 2,
                    ..
                })
            ),
            "{e}"
        );
    }
}
