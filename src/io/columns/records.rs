//! The records under a CSV header (see [`super`]): every wanted cell read
//! as a number at its true line, every cell that is not a finite number
//! refused (all of them, not only the first), a row of units under the
//! header said once, and a row that repeats the header (a logger's second
//! header mid-file) said once as that, not as a cell per column that is
//! not a number.

use super::bytes::not_utf8;
use super::{line_of, Columns};
use crate::error::{CellProblem, InputError};
use std::path::Path;

/// Reads every record of `rdr` into `out` (the `wanted` columns: header
/// position, name), the refusals of its cells into `bad`; a record the
/// reader cannot split is refused at its line.
pub(super) fn read_records(
    path: &Path,
    bytes: &[u8],
    headers: &csv::StringRecord,
    mut rdr: csv::Reader<&[u8]>,
    wanted: &[(usize, String)],
    out: &mut Columns,
    bad: &mut Vec<InputError>,
) -> Result<(), InputError> {
    for rec in rdr.records() {
        let rec = rec.map_err(|e| record_error(path, bytes, headers, &e))?;
        let line = rec.position().map_or(0, |p| line_of(bytes, p));
        if out.lines.is_empty() {
            if let Some(e) = units_row(path, line, &rec, wanted) {
                bad.push(e);
                for (_, name) in wanted {
                    out.data
                        .get_mut(name)
                        .expect("inserted by the reader")
                        .push(f64::NAN);
                }
                out.lines.push(line);
                continue;
            }
        }
        if let Some(e) = header_again(path, (out.header_line, headers), line, &rec, wanted) {
            bad.push(e);
            for (_, name) in wanted {
                let column = out.data.get_mut(name).expect("inserted by the reader");
                column.push(f64::NAN);
            }
            out.lines.push(line);
            continue;
        }
        for (idx, name) in wanted {
            let cell = rec.get(*idx).unwrap_or("");
            let at = |problem| InputError::Cell {
                path: path.to_path_buf(),
                line,
                column: idx + 1,
                name: name.clone(),
                cell: cell.to_string(),
                problem,
            };
            // Every bad cell is said, not only the first: a user fixing a
            // file learns of them all at once.
            let v = match cell.parse::<f64>() {
                Err(_) => {
                    bad.push(at(CellProblem::NotANumber));
                    f64::NAN
                }
                Ok(v) if !v.is_finite() => {
                    bad.push(at(CellProblem::NotFinite));
                    v
                }
                Ok(v) => v,
            };
            out.data
                .get_mut(name)
                .expect("inserted by the reader")
                .push(v);
        }
        out.lines.push(line);
    }
    Ok(())
}

/// A record the reader could not read: a byte that is not UTF-8 at its
/// cell, else the row at its line with what is wrong.
fn record_error(
    path: &Path,
    bytes: &[u8],
    headers: &csv::StringRecord,
    e: &csv::Error,
) -> InputError {
    if let Some(at) = not_utf8(bytes, e) {
        return InputError::Cell {
            path: path.to_path_buf(),
            line: at.line,
            column: at.column,
            name: headers.get(at.column - 1).unwrap_or("").to_string(),
            cell: String::new(),
            problem: CellProblem::NotUtf8 { byte: at.byte },
        };
    }
    let line = e.position().map_or(0, |p| line_of(bytes, p));
    // The reader's own message repeats its line, one short in a CRLF file:
    // only what is wrong is kept.
    let detail = match e.kind() {
        csv::ErrorKind::UnequalLengths {
            expected_len, len, ..
        } => {
            format!("found a record with {len} fields, but the previous record has {expected_len}")
        }
        _ => e.to_string(),
    };
    InputError::MalformedRow {
        path: path.to_path_buf(),
        line,
        detail,
    }
}

/// The first row under the header read as a row of units (`s, m/s, rad`):
/// no cell read is empty or a number, and there are two or more; one
/// refusal for the row, not one per cell.
fn units_row(
    path: &Path,
    line: usize,
    rec: &csv::StringRecord,
    wanted: &[(usize, String)],
) -> Option<InputError> {
    let cells: Vec<&str> = wanted
        .iter()
        .map(|(i, _)| rec.get(*i).unwrap_or("").trim())
        .collect();
    // A number with a decimal comma (`"0,01"`, quoted) is no unit: the
    // first data row is told of its commas as the rows after it are.
    let word = |c: &str| {
        !c.is_empty()
            && c.parse::<f64>().is_err()
            && c.replacen(',', ".", 1).parse::<f64>().is_err()
    };
    let words = cells.len() >= 2 && cells.iter().all(|c| word(c));
    // Quoted as the file has it: every cell, in its own column order (the
    // wanted columns are in the tool's, and a column the tool does not
    // read, a rig's `t` first, would be left out of the quote).
    let quoted: Vec<&str> = rec.iter().map(str::trim).collect();
    words.then(|| InputError::Cell {
        path: path.to_path_buf(),
        line,
        column: wanted[0].0 + 1,
        name: wanted[0].1.clone(),
        cell: quoted.join(", "),
        problem: CellProblem::UnitsRow,
    })
}

/// A row that repeats the header, cell by cell (trimmed, any case): one
/// refusal for the row at its first wanted column, naming the header's
/// line.
fn header_again(
    path: &Path,
    (header, headers): (usize, &csv::StringRecord),
    line: usize,
    rec: &csv::StringRecord,
    wanted: &[(usize, String)],
) -> Option<InputError> {
    let same = rec.len() == headers.len()
        && rec
            .iter()
            .zip(headers.iter())
            .all(|(a, b)| !a.trim().is_empty() && a.trim().eq_ignore_ascii_case(b.trim()));
    let quoted: Vec<&str> = rec.iter().map(str::trim).collect();
    (same && !wanted.is_empty()).then(|| InputError::Cell {
        path: path.to_path_buf(),
        line,
        column: wanted[0].0 + 1,
        name: wanted[0].1.clone(),
        cell: quoted.join(", "),
        problem: CellProblem::HeaderAgain { header },
    })
}
