//! Input errors: a file that cannot be read, or whose content is wrong,
//! located in the file (path, 1-based line and column) where a place is
//! known.

use super::decimal::decimal_comma;
use super::param::ParamError;
use super::problem::InputProblem;
use std::path::PathBuf;
use thiserror::Error;

/// A place in a text file: 1-based line and column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Location {
    /// 1-based line.
    pub line: usize,
    /// 1-based column.
    pub column: usize,
}

/// `path` and, where known, `:line:column`, as the messages show them.
fn place(path: &std::path::Path, at: &Option<Location>) -> String {
    match at {
        Some(l) => format!("{}:{}:{}", path.display(), l.line, l.column),
        None => path.display().to_string(),
    }
}

/// What is wrong with a CSV cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CellProblem {
    /// It does not parse as a number.
    NotANumber,
    /// It is NaN or infinite.
    NotFinite,
    /// NaN or empty in a measured channel of a run (not its time): a
    /// logger's dropout, which `FORMATS.md` makes an error.
    Dropout,
    /// The first row under the header holds no number in any column
    /// read (the cell is the row's cells, joined): a row of units, as
    /// loggers and spreadsheets write one.
    UnitsRow,
    /// The row repeats the header (the cell is the row's cells, joined),
    /// a header line mid-file, as a logger writes one where it restarts
    /// or two logs are joined: one refusal for the row, not one per cell.
    HeaderAgain {
        /// The header's line.
        header: usize,
    },
    /// It holds a byte that is not UTF-8 (a file saved as Latin-1).
    NotUtf8 {
        /// The first such byte.
        byte: u8,
    },
}

impl CellProblem {
    fn describe(self, cell: &str) -> String {
        match self {
            CellProblem::NotANumber if cell.is_empty() => "empty cell: a number is needed".into(),
            CellProblem::NotANumber => match decimal_comma(cell) {
                Some(point) => format!("`{cell}` is not a number: a decimal comma? write {point} (a CSV number takes a decimal point)"),
                None => format!("`{cell}` is not a number"),
            },
            CellProblem::NotFinite => format!("{cell} is not a finite value"),
            CellProblem::Dropout => format!("{} is a logger's dropout, which FORMATS.md makes an error in a run (a NaN or a cell without a number is refused, never masked or guessed); mark a dropout by leaving its rows out of the file: the hole in time is read as one (run across where short, the run split at it where long) and said", if cell.is_empty() { "an empty cell".to_string() } else { format!("`{cell}`") }),
            CellProblem::UnitsRow => format!("no cell of this row is a number (`{cell}`): a row of units under the header? Delete it: the columns hold numbers in the units FORMATS.md gives them"),
            CellProblem::HeaderAgain { header } => format!("this row repeats the header of line {header} (`{cell}`): a second header mid-file, as a logger writes where it restarts or where two logs were joined? Delete it, and check that the rows after it are of the same test"),
            CellProblem::NotUtf8 { byte } => InputProblem::NotUtf8 { byte }.to_string(),
        }
    }
}

/// Errors from reading input files, located in the file.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum InputError {
    /// The file could not be read.
    #[error("{path}: cannot read: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The OS error.
        source: std::io::Error,
    },
    /// Wrong content, typed: the problem, at its place in the file where
    /// one is known.
    #[error("{}: {problem}", place(path, at))]
    Invalid {
        /// The file.
        path: PathBuf,
        /// The place, where one is known.
        at: Option<Location>,
        /// What is wrong (boxed: the error stays small on the happy path).
        problem: Box<InputProblem>,
    },
    /// A CSV file without a column the reader needs.
    #[error("{path}:{line}:{}: missing required column `{name}` (the header has: {}){}{}{}", meant.as_ref().map_or(1, |m| m.0), header.join(", "), meant.as_ref().map_or(String::new(), |(c, m)| format!("; header column {c}, `{m}`: did you mean `{name}`?")), separator_hint(header), below_hint(*header_below))]
    MissingColumn {
        /// The file.
        path: PathBuf,
        /// 1-based line of the header (u32: with [`Self::MissingColumn`]'s
        /// `header_below` it fits where one usize did, and the error stays
        /// small).
        line: u32,
        /// The column.
        name: String,
        /// The header's columns.
        header: Vec<String>,
        /// The header column that likely means it (`yawrate`, `time`),
        /// with its 1-based position.
        meant: Option<(usize, String)>,
        /// A 1-based line further down that names the column: the header
        /// under lines of metadata (a MoTeC export's).
        header_below: Option<std::num::NonZeroU32>,
    },
    /// A CSV row that the CSV reader cannot read.
    #[error("{path}:{line}:1: malformed CSV row: {detail}")]
    MalformedRow {
        /// The file.
        path: PathBuf,
        /// 1-based line.
        line: usize,
        /// What the CSV reader found wrong.
        detail: String,
    },
    /// A CSV cell that is not a finite number.
    #[error("{path}:{line}:{column}: column `{name}`: {}", problem.describe(cell))]
    Cell {
        /// The file.
        path: PathBuf,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// The column's name.
        name: String,
        /// The cell as written.
        cell: String,
        /// What is wrong with it.
        problem: CellProblem,
    },
    /// A CSV file with nothing in it (zero bytes, or blank lines only).
    #[error("{path}: the file is empty: a CSV file needs a header line naming its columns, then rows of data")]
    EmptyFile {
        /// The file.
        path: PathBuf,
    },
    /// A CSV file with a header and no data row.
    #[error("{path}: no data rows (the file has its header line only)")]
    NoRows {
        /// The file.
        path: PathBuf,
    },
    /// A value in the file that is not physical: the parameter error, at
    /// its key's place where the key is found.
    #[error("{}: {source}", place(path, at))]
    Value {
        /// The file.
        path: PathBuf,
        /// The key's place.
        at: Option<Location>,
        /// The key (dotted), its value and why it is wrong.
        source: ParamError,
    },
    /// An equilibrium sweep's value beyond its physical range
    /// ([`super::SweepLimit`]), at its key's place.
    #[error("{}: `{key}` = {}: {why}", place(path, at), super::Num(*value))]
    Sweep {
        /// The file.
        path: PathBuf,
        /// The key's place.
        at: Option<Location>,
        /// The key, dotted.
        key: String,
        /// The value as read.
        value: f64,
        /// The range it left.
        why: super::SweepLimit,
    },
    /// A value of the wrong type or shape for its key (the TOML reader's
    /// own description of what it expected).
    #[error("{}: `{key}`: {detail}", place(path, at))]
    Key {
        /// The file.
        path: PathBuf,
        /// The value's place.
        at: Option<Location>,
        /// Dotted key.
        key: String,
        /// What the reader expected and found.
        detail: String,
    },
    /// A study's RBF network with fewer training pairs that reached a
    /// steady state (an Er) than it needs.
    #[error("{path}: the [rbf] network has {usable} of its {training} training pairs with an Er (the others reached no steady state: they spun, or the run failed), and it needs at least {min}: widen the pairs' range toward stiffer axles, or lengthen the run")]
    TooFewRbfPairs {
        /// The study file.
        path: PathBuf,
        /// Training pairs with an Er.
        usable: usize,
        /// Training pairs.
        training: usize,
        /// The least it needs.
        min: usize,
    },
    /// A study that names nothing to simulate.
    #[error("{path}: nothing to simulate: give a [stiffness] map or [rbf] pairs")]
    NothingToSimulate {
        /// The study file.
        path: PathBuf,
    },
    /// A fleet folder that holds no campaign.
    #[error("{path}: no campaign in the folder (sub-folders or .toml files){}", match skipped.len() { 0 => String::from(": it is empty"), n => format!(": its {} {} not a campaign: {}", crate::format::plural(n, "entry", "entries"), if n == 1 { "is" } else { "are" }, skipped.join(", ")) })]
    NoCampaign {
        /// The folder.
        path: PathBuf,
        /// The names of its entries, none a campaign.
        skipped: Vec<String>,
    },
    /// Two campaigns of a batch folder whose output folders would be one:
    /// a folder and a `.toml` file of the same stem.
    #[error("{path}: the campaigns `{first}` and `{second}` would both write to `{stem}/` of the output folder: rename one")]
    CampaignStemTwice {
        /// The batch folder.
        path: PathBuf,
        /// The first campaign's name in the folder.
        first: String,
        /// The second's.
        second: String,
        /// The stem they share.
        stem: String,
    },
    /// Several places of one file refused at once, in file order (built by
    /// [`InputError::all_of`]): a user mends them in one pass rather than
    /// one per run.
    #[error("{path}: {} {}:{}", errors.iter().map(|e| e.1).sum::<usize>() + more, counted.refused(), listed(errors, *more, counted.noun()))]
    Several {
        /// The file.
        path: PathBuf,
        /// The places refused, in file order, each with how many places it
        /// stands for: 1, or the count of a rule that refused more than
        /// [`SAID_EACH`] places, listed at its first (the first
        /// [`SEVERAL_SHOWN`] entries): a column in degrees is one line,
        /// not a screenful of lines alike.
        errors: Vec<(InputError, usize)>,
        /// How many places the rules not shown refused.
        more: usize,
        /// What each refusal is of: a place in the file, or a channel
        /// (two dead sensors of a run said "2 places refused").
        counted: Counted,
    },
    /// Runs of a campaign refused, every run checked before any was
    /// refused (built by [`InputError::runs_refused`]): a campaign of eight
    /// runs with three bad ones is mended in one pass. Grouped as
    /// [`InputError::Several`] groups places.
    #[error("{refused} of {of} runs refused, in run order:{}{}", listed(errors, *more, "runs"), passed_line(errors, *more, passed))]
    RunsRefused {
        /// The first refused run's file.
        path: PathBuf,
        /// The runs refused: one refusal may name several (runs with the
        /// steer in degrees among runs in radians).
        refused: usize,
        /// The runs of the campaign.
        of: usize,
        /// The refusals, in run order, each with how many runs it stands
        /// for (as [`InputError::Several`]'s).
        errors: Vec<(InputError, usize)>,
        /// How many runs the rules not shown refused.
        more: usize,
        /// The runs that passed the checks, as said: named where a line
        /// stands for several runs refused alike (the others unnamed).
        passed: Vec<String>,
    },
}

/// What the refusals of an [`InputError::Several`] are each of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Counted {
    /// A place in the file (a cell, a row, a header column).
    Places,
    /// A channel of a run, as a whole.
    Channels,
}

impl Counted {
    /// Its noun, plural.
    fn noun(self) -> &'static str {
        match self {
            Counted::Places => "places",
            Counted::Channels => "channels",
        }
    }

    /// The heading's words after the count.
    fn refused(self) -> &'static str {
        match self {
            Counted::Places => "places refused, in file order",
            Counted::Channels => "channels refused",
        }
    }
}

/// The places an [`InputError::Several`] lists before it counts the rest.
pub const SEVERAL_SHOWN: usize = 20;

/// The places of one rule an [`InputError::Several`] lists each; a rule
/// that refuses more is listed once, at its first place, with its count.
pub const SAID_EACH: usize = 3;

impl InputError {
    /// A problem at line `line`, column `column` (1-based) of `path`.
    pub(crate) fn problem_at(
        path: &std::path::Path,
        line: usize,
        column: usize,
        problem: InputProblem,
    ) -> Self {
        InputError::Invalid {
            path: path.to_path_buf(),
            at: Some(Location { line, column }),
            problem: Box::new(problem),
        }
    }

    /// A problem with the whole of `path`.
    pub fn problem(path: &std::path::Path, problem: InputProblem) -> Self {
        InputError::Invalid {
            path: path.to_path_buf(),
            at: None,
            problem: Box::new(problem),
        }
    }

    /// The refusals of a campaign's runs (in run order, standing for
    /// `refused` of its `of` runs) as one: none, the one, or
    /// [`InputError::RunsRefused`].
    pub(crate) fn runs_refused(
        mut errors: Vec<InputError>,
        (refused, of): (usize, usize),
        passed: Vec<String>,
    ) -> Option<Self> {
        if errors.len() < 2 {
            return errors.pop();
        }
        let path = errors[0].path().to_path_buf();
        let (errors, more) = grouped(errors);
        Some(InputError::RunsRefused {
            path,
            refused,
            of,
            errors,
            more,
            passed,
        })
    }

    /// The runs a campaign so refused kept (passed its checks) and the run
    /// files it read, where the refusal counts them: runs refused, too few
    /// runs, a `min_speed` that removed them (a fleet row says them).
    pub fn runs_counted(&self) -> Option<(usize, usize)> {
        match self {
            InputError::RunsRefused { refused, of, .. } => Some((of.saturating_sub(*refused), *of)),
            InputError::Invalid { problem, .. } => match &**problem {
                InputProblem::TooFewRuns { few } => Some((few.runs, few.files)),
                InputProblem::Campaign(c) => match &**c {
                    super::CampaignFileProblem::MinSpeedRemoved(p) => {
                        Some((p.runs.len() - p.removed, p.runs.len()))
                    }
                    _ => None,
                },
                _ => None,
            },
            _ => None,
        }
    }

    /// The errors of `path` (in file order) as one: none, the one, or
    /// [`InputError::Several`] listing the first [`SEVERAL_SHOWN`].
    pub(crate) fn all_of(path: &std::path::Path, mut errors: Vec<InputError>) -> Option<Self> {
        if errors.len() < 2 {
            return errors.pop();
        }
        let (errors, more) = grouped(errors);
        Some(InputError::Several {
            path: path.to_path_buf(),
            errors,
            more,
            counted: Counted::Places,
        })
    }

    /// [`Self::all_of`] for refusals each of a whole channel of `path` (a
    /// run's dead sensors): counted as channels.
    pub(crate) fn all_channels_of(path: &std::path::Path, errors: Vec<InputError>) -> Option<Self> {
        match Self::all_of(path, errors)? {
            InputError::Several {
                path, errors, more, ..
            } => Some(InputError::Several {
                path,
                errors,
                more,
                counted: Counted::Channels,
            }),
            one => Some(one),
        }
    }

    /// [`Self::all_of`] for errors gathered by several checks, put in file
    /// order first (by line, then column; an error without a place first).
    pub(crate) fn all_in_file_order(
        path: &std::path::Path,
        mut errors: Vec<InputError>,
    ) -> Option<Self> {
        errors.sort_by_key(|e| e.location().map(|l| (l.line, l.column)));
        Self::all_of(path, errors)
    }

    /// The file the error is in.
    pub fn path(&self) -> &std::path::Path {
        match self {
            InputError::Io { path, .. }
            | InputError::Invalid { path, .. }
            | InputError::MissingColumn { path, .. }
            | InputError::MalformedRow { path, .. }
            | InputError::Cell { path, .. }
            | InputError::NoRows { path }
            | InputError::EmptyFile { path }
            | InputError::Value { path, .. }
            | InputError::Sweep { path, .. }
            | InputError::Key { path, .. }
            | InputError::NothingToSimulate { path }
            | InputError::TooFewRbfPairs { path, .. }
            | InputError::NoCampaign { path, .. }
            | InputError::CampaignStemTwice { path, .. }
            | InputError::Several { path, .. }
            | InputError::RunsRefused { path, .. } => path,
        }
    }

    /// The place in the file, where known.
    pub fn location(&self) -> Option<Location> {
        match self {
            InputError::MissingColumn { line, meant, .. } => Some(Location {
                line: *line as usize,
                column: meant.as_ref().map_or(1, |m| m.0),
            }),
            InputError::MalformedRow { line, .. } => Some(Location {
                line: *line,
                column: 1,
            }),
            InputError::Cell { line, column, .. } => Some(Location {
                line: *line,
                column: *column,
            }),
            InputError::Value { at, .. }
            | InputError::Sweep { at, .. }
            | InputError::Key { at, .. }
            | InputError::Invalid { at, .. } => *at,
            InputError::Several { errors, .. } | InputError::RunsRefused { errors, .. } => {
                errors.first().and_then(|e| e.0.location())
            }
            _ => None,
        }
    }
}

/// `errors` grouped by rule, in their order: a rule that refuses more
/// than [`SAID_EACH`] places is one entry at its first with its count, a
/// few places of one rule each an entry; the first [`SEVERAL_SHOWN`]
/// entries, and how many places the rest stand for.
fn grouped(errors: Vec<InputError>) -> (Vec<(InputError, usize)>, usize) {
    // A rule that refuses more than SAID_EACH places is one line at
    // its first, with its count (a column in degrees); a few places
    // of one rule are each said, to be mended one by one.
    let mut counts: Vec<(Rule, usize)> = Vec::new();
    for e in &errors {
        let rule = e.rule();
        match counts.iter_mut().find(|(r, _)| *r == rule) {
            Some(r) => r.1 += 1,
            None => counts.push((rule, 1)),
        }
    }
    let count = |e: &InputError| {
        let rule = e.rule();
        counts.iter().find(|(r, _)| *r == rule).map_or(1, |r| r.1)
    };
    let mut shown: Vec<(InputError, usize)> = Vec::new();
    for e in errors {
        let n = count(&e);
        if n <= SAID_EACH {
            shown.push((e, 1));
        } else if !shown.iter().any(|(f, _)| f.rule() == e.rule()) {
            shown.push((e, n));
        }
    }
    let more = shown.iter().skip(SEVERAL_SHOWN).map(|r| r.1).sum();
    shown.truncate(SEVERAL_SHOWN);
    (shown, more)
}

/// The refusals of an [`InputError::Several`] or
/// [`InputError::RunsRefused`], one line each: a rule's first with how many
/// `what` (places, runs) it refused alike, and how many the rules not shown
/// refused.
fn listed(errors: &[(InputError, usize)], more: usize, what: &str) -> String {
    let mut out = String::new();
    for (e, n) in errors {
        out += &match n {
            1 => format!("\n  {e}"),
            _ => format!("\n  {e} (the first of {n} {what} refused alike)"),
        };
    }
    if more > 0 {
        out += &format!("\n  and {more} more");
    }
    out
}

/// The runs passed (the first five), where a line of an
/// [`InputError::RunsRefused`] stands for several runs refused alike or
/// rules are not shown: of eight runs with six refused alike, the two
/// taken were not told apart from the five unnamed.
fn passed_line(errors: &[(InputError, usize)], more: usize, passed: &[String]) -> String {
    let unnamed = more > 0 || errors.iter().any(|(_, n)| *n > 1);
    let (shown, rest) = (passed.len().min(5), passed.len().saturating_sub(5));
    match (unnamed && shown > 0, rest) {
        (false, _) => String::new(),
        (true, 0) => format!("\n  passed: {}", passed.join(", ")),
        (true, k) => format!("\n  passed: {} and {k} more", passed[..shown].join(", ")),
    }
}

/// The rule an error breaks, as [`InputError::all_of`] groups them: its
/// kind (and its problem's or cell's) and its column; its value and line
/// left out.
#[derive(PartialEq)]
struct Rule {
    kind: std::mem::Discriminant<InputError>,
    problem: Option<std::mem::Discriminant<InputProblem>>,
    cell: Option<std::mem::Discriminant<CellProblem>>,
    column: Option<usize>,
    /// A missing column's name: each is a column of its own to add or
    /// rename, never "alike".
    missing: Option<String>,
}

impl InputError {
    /// The rule it breaks (see [`Rule`]).
    fn rule(&self) -> Rule {
        Rule {
            kind: std::mem::discriminant(self),
            problem: match self {
                InputError::Invalid { problem, .. } => Some(std::mem::discriminant(&**problem)),
                _ => None,
            },
            cell: match self {
                InputError::Cell { problem, .. } => Some(std::mem::discriminant(problem)),
                _ => None,
            },
            column: self.location().map(|l| l.column),
            missing: match self {
                InputError::MissingColumn { name, .. } => Some(name.clone()),
                _ => None,
            },
        }
    }
}

/// The separator a header read as one column holds instead of commas
/// (a spreadsheet set to a decimal comma writes `;`), by name: such a
/// header is one problem, however many columns it hides.
pub(crate) fn one_column_separator(header: &[String]) -> Option<&'static str> {
    let [only] = header else {
        return None;
    };
    [(';', "semicolons"), ('\t', "tabs")]
        .iter()
        .find(|(c, _)| only.contains(*c))
        .map(|(_, name)| *name)
}

/// Where a header read as one column holds another separator, what to do
/// about it ([`one_column_separator`]).
fn separator_hint(header: &[String]) -> String {
    one_column_separator(header).map_or(String::new(), |name| {
        format!("; the header is one column separated by {name}: the file must be comma-separated with a decimal point (export it as CSV with `,` between values and `.` in numbers)")
    })
}

/// The hint of a header further down, under lines of metadata.
fn below_hint(line: Option<std::num::NonZeroU32>) -> String {
    line.map_or(String::new(), |l| {
        format!("; line {l} names it: the header is further down, under lines of metadata (a logger's export, as MoTeC's): start each line above it with `#` (a comment line, skipped) or delete them")
    })
}
