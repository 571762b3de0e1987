//! Column-wise CSV reading for the measured-data formats of `FORMATS.md`:
//! one header line naming the columns, any column order, unknown columns
//! ignored; a missing required column, a non-numeric cell, a NaN or an
//! infinite value is an error naming the file, the line and the column.

mod aliases;
mod bytes;
mod records;
mod units;
pub(crate) use units::unit_of;

use bytes::{header_further_down, not_utf8};

use crate::error::{one_column_separator, DeclaredBy, DuplicateAt, InputError, InputProblem};
use std::collections::BTreeMap;
use std::path::Path;

/// Numeric columns read from a CSV file, with the line number of each row.
#[derive(Debug, Clone, Default)]
pub struct Columns {
    /// Column name → values.
    pub data: BTreeMap<String, Vec<f64>>,
    /// 1-based file line of each row.
    pub lines: Vec<usize>,
    /// Column name → its 1-based position in the header, for errors found
    /// after parsing (a negative load, time running backwards).
    pub positions: BTreeMap<String, usize>,
    /// The 1-based line of the header, for what a header lacks.
    pub header_line: usize,
    /// The header's names, in the file's order: what a reader left unread
    /// is named from it.
    pub header: Vec<String>,
    /// The columns whose header states their own SI unit (`alpha [rad]`):
    /// the user's word that the values are in it, which a reader's guess
    /// of another unit from the values gives way to.
    pub stated_si: Vec<String>,
}

impl Columns {
    /// A column that was required (present by construction).
    pub fn take(&mut self, name: &str) -> Vec<f64> {
        self.data.remove(name).unwrap_or_default()
    }
    /// Multiplies a column, where read, by `factor` (a unit the file
    /// declares elsewhere, converted before any check).
    pub(crate) fn scale(&mut self, name: &str, factor: f64) {
        if let Some(v) = self.data.get_mut(name) {
            v.iter_mut().for_each(|x| *x *= factor);
        }
    }
    /// A column, where read, left in place.
    pub(crate) fn get(&self, name: &str) -> Option<&[f64]> {
        self.data.get(name).map(Vec::as_slice)
    }
    /// An optional column.
    pub(crate) fn take_optional(&mut self, name: &str) -> Option<Vec<f64>> {
        self.data.remove(name)
    }
    /// 1-based header position of a column that was read (1 if unknown).
    pub fn column(&self, name: &str) -> usize {
        self.positions.get(name).copied().unwrap_or(1)
    }
    /// An error at row `row` (0-based) of column `name`: file, line, the
    /// column's real position and the problem.
    pub(crate) fn error_at(
        &self,
        path: &Path,
        row: usize,
        name: &str,
        problem: InputProblem,
    ) -> InputError {
        InputError::problem_at(
            path,
            self.lines.get(row).copied().unwrap_or(0),
            self.column(name),
            problem,
        )
    }
    /// Number of rows.
    pub fn len(&self) -> usize {
        self.lines.len()
    }
    /// True with no rows.
    pub fn is_empty(&self) -> bool {
        self.lines.is_empty()
    }
}

/// The 1-based line of the record at `p` in `bytes`. The csv crate counts a
/// line at its `\n`, and in a CRLF file a record ends at the `\r`: the next
/// record's position then sits on the `\n` not yet counted, one line short
/// (a NaN on line 3 was reported on line 2, a bad first row on the header's).
///
/// The reader's position of a record may also sit before the comment and
/// blank lines it skipped to reach it (seen on a file's last record: a bad
/// cell on line 805 was reported on line 803): those lines are stepped
/// over to the record's own.
fn line_of(bytes: &[u8], p: &csv::Position) -> usize {
    let mut at = p.byte() as usize;
    let mut line = p.line() as usize;
    if bytes.get(at) == Some(&b'\n') {
        line += 1;
        at += 1;
    }
    loop {
        let skipped = match bytes.get(at) {
            Some(b'\r') if bytes.get(at + 1) == Some(&b'\n') => 2,
            Some(b'\n' | b'\r') => 1,
            Some(b'#') => match bytes[at..].iter().position(|&b| b == b'\n') {
                Some(end) => end + 1,
                None => break,
            },
            _ => break,
        };
        at += skipped;
        line += 1;
    }
    line
}

/// Long names of the time column that a logger writes, in English and in
/// the German and French of European loggers' exports (`Zeit`, `temps`),
/// matched with a unit after them too (`Time [s]`).
const TIME_NAMES: [&str; 7] = [
    "time",
    "timestamp",
    "time_s",
    "t_s",
    "elapsed",
    "zeit",
    "temps",
];

/// Symbols of the textbooks that loggers and exports write for a run's
/// columns, and the column each stands for: `r` for the yaw rate and `δ`
/// (`delta`) for the road-wheel steer. Hinted at (a did-you-mean), never
/// taken silently: a `delta` may be the handwheel's angle, which a run does
/// not log (FORMATS.md: the road wheels').
const SYMBOLS: [(&str, &str); 2] = [("r", "yaw_rate"), ("delta", "steer")];

/// Whether the header's `h` is a textbook symbol of the column `name`.
fn symbol_of(h: &str, name: &str) -> bool {
    let lower = h.to_lowercase();
    SYMBOLS.iter().any(|(s, n)| *s == lower && *n == name)
}

/// The channel names of the Tire Test Consortium's rig files (and loggers
/// that copy them), lower-cased, and the column each means here: `SA` is
/// no slip of spelling of `alpha`, so a header of them was refused one
/// column at a time or, `SA` unnamed, as "no lateral data". Their units
/// (degrees, kPa, km/h, SAE axes) are said by the checks of the values
/// once renamed.
const RIG_NAMES: [(&str, &str); 17] = [
    ("et", "t"),
    ("sa", "alpha"),
    ("sl", "kappa"),
    ("ia", "camber"),
    ("p", "pressure"),
    ("v", "speed"),
    // TYDEX's channel names (ISO-W forces and moments: `FYW`): a file
    // converted from TYDEX kept its `INCLANGL` and `INFLPRES` unread and
    // its three cambers pooled as 0 without a word.
    ("inclangl", "camber"),
    ("inflpres", "pressure"),
    ("slipangl", "alpha"),
    ("longslip", "kappa"),
    ("fzw", "fz"),
    ("fyw", "fy"),
    ("fxw", "fx"),
    ("mzw", "mz"),
    ("mxw", "mx"),
    ("myw", "my"),
    ("runspeed", "speed"),
];

/// A header's name lower-cased, without a unit written after it
/// (`FZ_kN`, `SA_deg`, `P [kPa]`: `fz`, `sa`, `p`).
fn first_word(h: &str) -> String {
    let lower = h.to_lowercase();
    lower
        .split(['_', '-', ' ', '[', '('])
        .next()
        .unwrap_or_default()
        .to_string()
}

/// The column a header's rig channel name means ([`RIG_NAMES`]), by its
/// [`first_word`], or that it is another name of (`gamma`), where `among` holds it.
fn rig_name<'a>(h: &str, among: &[&'a str]) -> Option<&'a str> {
    let first = first_word(h);
    let rig = RIG_NAMES.iter().find(|(rig, _)| *rig == first);
    rig.and_then(|(_, ours)| among.iter().copied().find(|n| n == ours))
        .or_else(|| aliases::alias_of(h, among))
}

/// The header column that likely means the missing `name`: one that is no
/// known column and a slip of spelling away from it (`yawrate`, `Yaw_Rate`,
/// [`crate::format::nearest_name`]), or the time under a long name; of
/// several, the nearest (the first of equals): in a capitalised header
/// `Speed` is two edits from `steer`, and was named for it where `Steer`
/// stood after it. A column holding `;` or a tab is a whole header of
/// another separator (its advice says so), no name.
fn meant(
    name: &str,
    headers: &csv::StringRecord,
    required: &[&str],
    optional: &[&str],
) -> Option<(usize, String)> {
    let time = |h: &str| {
        name == "t"
            && (TIME_NAMES.contains(&h.to_lowercase().as_str())
                || TIME_NAMES.contains(&first_word(h).as_str()))
    };
    // The name in capitals (`FZ`), then with a unit after it (`FZ_kN`) or
    // as a rig's channel (`SA`), then the nearest spelling: `MZ` is one
    // letter from `fz` in capitals but means `mz`, and was named for `fz`
    // where `FZ_kN` stood.
    let rank = |h: &str| {
        let lower = h.to_lowercase();
        if time(h) || lower == name {
            0
        } else if first_word(h) == name || rig_name(h, &[name]).is_some() || symbol_of(h, name) {
            1
        } else {
            2 + crate::format::edit_distance(&lower, name)
        }
    };
    headers
        .iter()
        .enumerate()
        .filter(|(_, h)| !required.contains(h) && !optional.contains(h))
        .filter(|(_, h)| !h.contains([';', '\t']))
        .filter(|(_, h)| {
            crate::format::nearest_name(h, &[name]).is_some()
                || time(h)
                || rig_name(h, &[name]).is_some()
                || symbol_of(h, name)
        })
        .min_by_key(|(_, h)| rank(h))
        .map(|(i, h)| (i + 1, h.to_string()))
}

/// A header column that reads as a slip of spelling of an optional column
/// the file lacks (`presure` for `pressure`, `bta` for `beta`): a reader
/// refuses it ([`read_columns_with_bad_cells`]) or returns it for its job
/// to say ([`read_columns_with_slips`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Slip {
    /// The header's column.
    pub found: String,
    /// The optional column it likely means.
    pub meant: String,
    /// Its 1-based position in the header.
    pub column: usize,
}

/// The header columns that read as slips of an `optional` column the file
/// lacks (`Camber` for `camber`); columns in `known` (the reader's
/// others) are never taken for one.
fn slips(header: &[String], optional: &[&str], known: &[&str]) -> Vec<Slip> {
    let absent: Vec<&str> = optional
        .iter()
        .copied()
        .filter(|n| !header.iter().any(|h| h == n))
        .collect();
    header
        .iter()
        .enumerate()
        .filter(|(_, h)| !known.contains(&h.as_str()) && !optional.contains(&h.as_str()))
        .filter_map(|(i, h)| {
            let meant = crate::format::nearest_name(h, &absent).or_else(|| rig_name(h, &absent))?;
            Some(Slip {
                found: h.clone(),
                meant: meant.to_string(),
                column: i + 1,
            })
        })
        .collect()
}

/// The refusal of `slip`, at its place in the header (line `line`).
fn refusal(path: &Path, line: usize, slip: Slip) -> InputError {
    let problem = InputProblem::Misspelled {
        found: slip.found,
        meant: slip.meant.into(),
    };
    InputError::problem_at(path, line, slip.column, problem)
}

/// How a reader takes a CSV file's columns: those it needs, those it
/// reads where given, and (`Some`) the file's other columns it reads
/// elsewhere, which turns on the check of a header column that is a slip
/// of spelling from an optional one the file lacks, refused
/// ([`read_columns_with_bad_cells`]) or returned to be warned of
/// ([`read_columns_with_slips`]); `None`: a file's other columns are
/// ignored unseen, as `FORMATS.md` allows a log's.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Layout<'a> {
    /// Columns every file must have.
    pub required: &'a [&'a str],
    /// Columns read where given.
    pub optional: &'a [&'a str],
    /// Other columns read elsewhere, never taken for a slip; `None`: no
    /// slip refused.
    pub also_read: Option<&'a [&'a str]>,
}

/// Reads the `required` and `optional` columns of a CSV file; every cell
/// that is not a finite number refused at once.
pub fn read_columns(
    path: &Path,
    required: &[&str],
    optional: &[&str],
) -> Result<Columns, InputError> {
    let layout = Layout {
        required,
        optional,
        also_read: None,
    };
    let (columns, bad) = read_columns_with_bad_cells(path, layout)?;
    match InputError::all_of(path, bad) {
        Some(e) => Err(e),
        None => Ok(columns),
    }
}

/// [`read_columns`] by a [`Layout`], the cells that are not finite numbers
/// returned with the columns (as NaN, or the infinity read) rather than
/// refused: for a reader that refuses them together with its own checks
/// of the values, so that a file's every bad cell is said in one run. The
/// header's slips of spelling (where the layout asks) are among them; a
/// file without a required column is refused with every required column
/// it lacks and every slip at once.
pub(crate) fn read_columns_with_bad_cells(
    path: &Path,
    layout: Layout,
) -> Result<(Columns, Vec<InputError>), InputError> {
    read_layout(path, layout, (None, &[])).map(|(columns, bad, _)| (columns, bad))
}

/// [`read_columns`] by a [`Layout`] whose header slips are warned of
/// rather than refused: a file whose other columns may be its own (a
/// vehicle run, `FORMATS.md`) is read, and the slips returned for the job
/// to say with what it goes without. They play no part in a refusal.
pub(crate) fn read_columns_with_slips(
    path: &Path,
    layout: Layout,
    (by, declared): (DeclaredBy, &[&str]),
) -> Result<(Columns, Vec<Slip>), InputError> {
    let (columns, bad, slips) = read_layout(path, layout, (Some(by), declared))?;
    match InputError::all_of(path, bad) {
        Some(e) => Err(e),
        None => Ok((columns, slips)),
    }
}

/// The reading behind [`read_columns_with_bad_cells`] (no `by`: the slips
/// among the refusals) and [`read_columns_with_slips`] (`by` the run's
/// declaration of angles in degrees, and the columns it declares so: the
/// slips returned apart).
fn read_layout(
    path: &Path,
    layout: Layout,
    (by, declared): (Option<DeclaredBy>, &[&str]),
) -> Result<(Columns, Vec<InputError>, Vec<Slip>), InputError> {
    // Read whole to find each record's true line (see [`line_of`]).
    let bytes = read_bytes(path, layout.required)?;
    let mut rdr = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .comment(Some(b'#'))
        .from_reader(bytes.as_slice());
    let headers = read_header(path, &bytes, &mut rdr, layout.required)?;
    // A column with its unit in the header is matched by its name.
    let checked: Vec<&str> = layout
        .required
        .iter()
        .chain(layout.optional)
        .copied()
        .collect();
    let known = layout.also_read.unwrap_or_default();
    let (named, units) = units::canonical(&headers, &checked, known, (by, declared));
    let mut out = Columns {
        header: named.iter().map(str::to_string).collect(),
        stated_si: units::stated_si(&headers, &named, &checked),
        header_line: headers.position().map_or(0, |p| line_of(&bytes, p)).max(1),
        ..Columns::default()
    };
    let (wanted, mut missing) = match_header(path, &named, out.header_line, &layout)?;
    for e in &mut missing {
        if let InputError::MissingColumn {
            name,
            header,
            header_below,
            ..
        } = e
        {
            *header = headers.iter().map(str::to_string).collect();
            *header_below = header_further_down(&bytes, out.header_line, name);
        }
    }
    let line = out.header_line;
    missing.extend(units.into_iter().map(|(column, unit)| {
        InputError::problem_at(path, line, column, InputProblem::UnitInHeader(unit))
    }));
    let (mut bad, slipped) = header_refusals(path, &out, missing, &layout, by.is_none())?;
    for (i, name) in &wanted {
        out.data.insert(name.clone(), Vec::new());
        out.positions.insert(name.clone(), i + 1);
    }
    records::read_records(path, &bytes, &headers, rdr, &wanted, &mut out, &mut bad)?;
    if out.is_empty() {
        return Err(InputError::NoRows {
            path: path.to_path_buf(),
        });
    }
    Ok((out, bad, slipped))
}

/// The file's bytes; a folder named as one (not as the OS's "Is a
/// directory") and a file of only white space refused.
fn read_bytes(path: &Path, required: &[&str]) -> Result<Vec<u8>, InputError> {
    let bytes = std::fs::read(path).map_err(|source| {
        crate::io::file_kind::not_wanted(path, required).unwrap_or(InputError::Io {
            path: path.to_path_buf(),
            source,
        })
    })?;
    // Nothing to name a column in: said as such, not as a missing `t`.
    if bytes.iter().all(u8::is_ascii_whitespace) {
        return Err(InputError::EmptyFile {
            path: path.to_path_buf(),
        });
    }
    Ok(bytes)
}

/// The header record; a byte that is not UTF-8 in it refused at its line
/// and column, an image or archive named as one (not asked whether it was
/// saved as Latin-1).
fn read_header(
    path: &Path,
    bytes: &[u8],
    rdr: &mut csv::Reader<&[u8]>,
    required: &[&str],
) -> Result<csv::StringRecord, InputError> {
    let file_err = |e: &csv::Error| {
        InputError::problem(
            path,
            InputProblem::Header {
                detail: e.to_string(),
            },
        )
    };
    rdr.headers()
        .cloned()
        .map_err(|e| match not_utf8(bytes, &e) {
            Some(_) if crate::error::ForeignFormat::of(bytes).is_some() => {
                crate::io::file_kind::not_wanted(path, required).unwrap_or_else(|| file_err(&e))
            }
            Some(at) => InputError::problem_at(
                path,
                at.line,
                at.column,
                InputProblem::NotUtf8 { byte: at.byte },
            ),
            None => file_err(&e),
        })
}

/// The wanted columns a header has: each one's 0-based position and name.
type Wanted = Vec<(usize, String)>;

/// The header's position of each wanted column (`required`, then
/// `optional`) present, and the refusals of the required ones missing; a
/// column named twice refused at once: which one holds the signal is for
/// the user (a second would be dropped silently).
fn match_header(
    path: &Path,
    headers: &csv::StringRecord,
    header_line: usize,
    layout: &Layout,
) -> Result<(Wanted, Vec<InputError>), InputError> {
    let (required, optional) = (layout.required, layout.optional);
    let mut wanted: Wanted = Vec::new();
    let mut missing: Vec<InputError> = Vec::new();
    for name in required.iter().chain(optional) {
        match headers.iter().position(|h| h == *name) {
            Some(i) => {
                if let Some(j) = headers.iter().skip(i + 1).position(|h| h == *name) {
                    return Err(InputError::problem_at(
                        path,
                        header_line,
                        i + j + 2,
                        InputProblem::Duplicate {
                            name: name.to_string(),
                            first: DuplicateAt::Column(i + 1),
                        },
                    ));
                }
                wanted.push((i, name.to_string()));
            }
            None if required.contains(name) => missing.push(InputError::MissingColumn {
                path: path.to_path_buf(),
                line: u32::try_from(header_line).unwrap_or(u32::MAX),
                name: name.to_string(),
                header: headers.iter().map(str::to_string).collect(),
                meant: meant(name, headers, required, optional),
                header_below: None,
            }),
            None => {}
        }
    }
    Ok((wanted, missing))
}

/// What the header alone decides: the slips of column names (refused
/// where `refuse_slips`, else returned apart) and, where a required column
/// is `missing`, the file refused with every column to rename at once.
fn header_refusals(
    path: &Path,
    out: &Columns,
    mut missing: Vec<InputError>,
    layout: &Layout,
    refuse_slips: bool,
) -> Result<(Vec<InputError>, Vec<Slip>), InputError> {
    // A header column already said to mean a missing required one (`Fz`
    // for `fz`) is not also said to mean an optional one (`mz`).
    let taken: Vec<String> = missing
        .iter()
        .filter_map(|e| match e {
            InputError::MissingColumn { meant, .. } => meant.as_ref().map(|m| m.1.clone()),
            _ => None,
        })
        .collect();
    let mut slipped: Vec<Slip> = layout.also_read.map_or_else(Vec::new, |also| {
        let known: Vec<&str> = layout
            .required
            .iter()
            .chain(also)
            .copied()
            .chain(taken.iter().map(String::as_str))
            .collect();
        slips(&out.header, layout.optional, &known)
    });
    let line = out.header_line;
    let mut bad: Vec<InputError> = Vec::new();
    if refuse_slips {
        bad.extend(slipped.drain(..).map(|s| refusal(path, line, s)));
    }
    // A header of one column holding `;` or tabs is one problem, said once
    // (the first missing column's refusal carries what to do), not once
    // per column it hides.
    if one_column_separator(&out.header).is_some() {
        missing.truncate(1);
    }
    if missing.is_empty() {
        return Ok((bad, slipped));
    }
    // A file of another kind (rig data given as a run, a scenario as rig
    // data) is named as such: its columns read as slips of the wanted ones
    // (a rig's `fy` for a run's `ay`) would mislead.
    if let Some(e) = crate::io::file_kind::not_wanted(path, layout.required) {
        return Err(e);
    }
    missing.append(&mut bad);
    // A file refused for its header says every column to rename in that
    // one run, the slips a reader would only have warned of too (`ay
    // [m/s^2]` beside `t [s]`).
    missing.extend(slipped.iter().cloned().map(|s| refusal(path, line, s)));
    match InputError::all_in_file_order(path, missing) {
        Some(e) => Err(e),
        None => Ok((Vec::new(), slipped)),
    }
}
