//! What a file handed to a command is, when it is not what the command
//! reads (recognised once, by `crate::io::file_kind`, for every reader):
//! a tyre rig CSV given as a vehicle run, a scenario given as rig data, a
//! folder given as a file. Said as what the file is and which command
//! reads it, in place of the reader's column-by-column complaints (a rig's
//! `fy` read as a slip of a run's `ay`). Also a campaign's `[runs]
//! degrees` naming a column none of its run files has, said at the key.

use std::fmt;

/// What a file is, as far as its name, header or tables tell.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum FileKind {
    /// A measured run (`FORMATS.md`: `t`, `speed`, `steer`, `yaw_rate`).
    RunCsv,
    /// The history `simulate` writes (a run's columns and the axles').
    HistoryCsv,
    /// Tyre rig data (`fz` with `alpha` or `kappa`).
    RigCsv,
    /// Another CSV file; its header's first column.
    Csv {
        /// The header's first column.
        first: Box<str>,
    },
    /// A Magic Formula `.tir` file.
    Tir,
    /// A tyre parameter file of the project (`model = "…"`).
    TyreToml {
        /// Its `model`.
        model: Box<str>,
    },
    /// A scenario (a `[manoeuvre]`), which `simulate` runs.
    Scenario,
    /// A campaign (`[runs]` or `[diagnose]`), which `diagnose` reads.
    Campaign,
    /// An equilibrium sweep (`[sweep]`), which `equilibria` reads.
    Sweep,
    /// A stiffness study (`[stiffness]`), which `study` reads.
    Study,
    /// A JSON file (a report `handling` writes: `diagnosis.json`,
    /// `metrics.json`, `gap.json`).
    Json,
    /// A file of a known binary format (an image, a PDF, an archive).
    Foreign(super::ForeignFormat),
    /// Text that is neither TOML nor CSV: no line of it is a TOML
    /// `key = value` or `[table]` (a README, notes, a Markdown file), and
    /// it is named `.toml` or its first line has no comma.
    Text {
        /// Its first line that is neither blank nor a comment, shortened.
        first: Box<str>,
    },
    /// Not text: a NUL byte at this byte offset.
    Binary {
        /// Byte offset of the first NUL.
        at: usize,
    },
    /// A folder; `campaign`: one with a `vehicle.toml` (a campaign folder).
    Folder {
        /// Whether it holds a `vehicle.toml`.
        campaign: bool,
    },
}

impl FileKind {
    /// The file as a noun phrase (`tyre rig data`, `a scenario (…)`).
    pub fn what(&self) -> String {
        match self {
            FileKind::RunCsv => "a measured vehicle run".into(),
            FileKind::HistoryCsv => {
                "a simulation history (history.csv, which `handling simulate` writes)".into()
            }
            FileKind::RigCsv => "a tyre rig file".into(),
            FileKind::Csv { first } => format!("a CSV file (its header starts with `{first}`)"),
            FileKind::Tir => "a Magic Formula tyre property file (.tir)".into(),
            FileKind::TyreToml { model } => format!("a tyre file (`model = \"{model}\"`)"),
            FileKind::Scenario => "a scenario (a TOML file with [manoeuvre])".into(),
            FileKind::Campaign => "a campaign (a TOML file with [runs] or [diagnose])".into(),
            FileKind::Sweep => "an equilibrium sweep (a TOML file with [sweep])".into(),
            FileKind::Study => "a stiffness study (a TOML file with [stiffness])".into(),
            FileKind::Json => "a JSON report (diagnosis.json, metrics.json, gap.json)".into(),
            FileKind::Binary { at } => format!("not a text file (a NUL byte at byte {at})"),
            FileKind::Text { first } => format!(
                "a text file that is not TOML (no line of it is a `key = value` or a `[table]`; its first reads \"{first}\")"
            ),
            FileKind::Foreign(format) => format.what().into(),
            FileKind::Folder { campaign: true } => {
                "a campaign folder (vehicle.toml and runs/*.csv)".into()
            }
            FileKind::Folder { campaign: false } => "a folder".into(),
        }
    }

    /// Which command reads the file, as a clause.
    pub fn reader(&self) -> &'static str {
        match self {
            FileKind::RunCsv => "`handling metrics` measures it; a campaign lists it under [runs], and a scenario replays it (`[manoeuvre] kind = \"replay\"`)",
            FileKind::HistoryCsv => "`handling metrics` measures it",
            FileKind::RigCsv => "`handling identify` reads it (fits a tyre to it), and a campaign takes it as `[tyres] rig`",
            FileKind::Csv { .. } => "see FORMATS.md for the columns each command reads",
            FileKind::Tir | FileKind::TyreToml { .. } => "`handling tyre-eval` reads it, and a scenario or campaign names it under [tyres]",
            FileKind::Scenario => "`handling simulate` runs it",
            FileKind::Campaign | FileKind::Folder { campaign: true } => "`handling diagnose` reads it",
            FileKind::Sweep => "`handling equilibria` reads it",
            FileKind::Study => "`handling study` reads it",
            FileKind::Json => "`handling` writes it, and no command reads it",
            FileKind::Binary { .. } | FileKind::Foreign(_) | FileKind::Text { .. } => {
                "no command reads it"
            }
            FileKind::Folder { campaign: false } => "give one of its files",
        }
    }
}

/// What a CSV reader wanted, judged from the columns it requires.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Wanted {
    /// A measured run (`metrics`, a replay, a campaign's runs).
    Run,
    /// Tyre data (`identify`'s rig data, a campaign's rig, `tyre-eval`'s
    /// points).
    Tyre,
    /// A tyre file (`tyre-eval`'s tyre, a `.tir` or a TOML tyre).
    TyreFile,
    /// `tyre-eval`'s points (`fz`, `kappa`, `alpha`, `camber`, `speed`).
    Points,
    /// An equilibrium sweep (`equilibria`'s).
    Sweep,
    /// A stiffness study (`study`'s).
    Study,
    /// A Magic Formula `.tir` whose coefficients start the staged fit
    /// (`identify --template`).
    Template,
    /// A Magic Formula property file, which a `.tir` name promises (a
    /// TOML tyre saved under that name is read as one and fails at its
    /// first line).
    TirContent,
}

impl Wanted {
    fn what(self) -> &'static str {
        match self {
            Wanted::Run => "a vehicle run (a CSV with `t`, `speed`, `steer`, `yaw_rate`)",
            Wanted::Tyre => "tyre data (a CSV with `fz` and `alpha` or `kappa`)",
            Wanted::TyreFile => "a tyre file (a .tir, or a TOML file with `model = \"…\"`, which `handling identify` writes), which `handling tyre-eval <tyre> <points>` takes first",
            Wanted::Points => "the points `handling tyre-eval <tyre> <points>` evaluates (a CSV with `fz`, `kappa`, `alpha`, `camber`, `speed`)",
            Wanted::Sweep => "an equilibrium sweep (a TOML file with [vehicle], [tyres] and [sweep]), which `handling equilibria` reads",
            Wanted::Study => "a stiffness study (a TOML file with [vehicle], [tyres], [manoeuvre] and [stiffness] or [rbf]), which `handling study` reads",
            Wanted::Template => "a Magic Formula tyre property file (.tir, with [MODEL] and FITTYP), which `handling identify --template` takes: its coefficients start the staged fit and its layout is the written file's",
            Wanted::TirContent => "a Magic Formula tyre property file (.tir, with [MODEL] and FITTYP), which its .tir name promises",
        }
    }
}

/// What a file of `kind` read for its `.tir` name (`wanted`) is to become,
/// said after the wanted kind and after the reader: a TOML tyre renamed
/// `.toml`; any other file is no tyre, and a tyre is one of two kinds.
fn tir_content(kind: &FileKind, wanted: Wanted) -> (&'static str, &'static str) {
    match (wanted, kind) {
        (Wanted::TirContent, FileKind::TyreToml { .. }) => (": rename it .toml, and it is read as the tyre file it is", ""),
        (Wanted::TirContent, _) => ("", "; a tyre is a .tir (with [MODEL] and FITTYP) or a TOML tyre file (`model = \"…\"`, which `handling identify` writes)"),
        _ => ("", ""),
    }
}

/// A file of another kind than its reader's, or a key naming what none of
/// the files it acts on has.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum KindProblem {
    /// The file is `kind`, where the reader wanted `wanted`; `columns`,
    /// a CSV's header (empty for other kinds).
    NotWanted {
        /// What the file is.
        kind: FileKind,
        /// What the reader wanted.
        wanted: Wanted,
        /// The header's columns, for a CSV.
        columns: Vec<String>,
    },
    /// `[runs] degrees` names `column`, which none of the `files` run
    /// files has.
    DegreesNowhere {
        /// The column named.
        column: &'static str,
        /// How many run files the campaign reads.
        files: usize,
        /// The angle columns the files have (the values that would act).
        present: Vec<&'static str>,
        /// Every value `degrees` takes.
        allowed: Vec<&'static str>,
    },
    /// A tyre file key (`[tyres] front`) naming a file of another kind.
    NotATyre {
        /// The key's dotted path.
        key: String,
        /// Its value as written.
        written: String,
        /// What the file is.
        kind: FileKind,
        /// Whether the key is a campaign's (which takes rig data itself).
        campaign: bool,
    },
}

impl fmt::Display for KindProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            KindProblem::NotATyre {
                key,
                written,
                kind,
                campaign,
            } => {
                let rig = matches!(kind, FileKind::RigCsv);
                let kind = (rig, kind.what(), kind.reader());
                let said =
                    super::not_a_tyre::said(key, written, (kind.0, &kind.1, kind.2), *campaign);
                f.write_str(&said)
            }
            KindProblem::NotWanted {
                kind,
                wanted,
                columns,
            } => {
                let columns = match columns.is_empty() {
                    true => String::new(),
                    false => format!(" (columns {})", columns.join(", ")),
                };
                let (rename, tyre) = tir_content(kind, *wanted);
                write!(
                    f,
                    "this is {}{columns}, not {}{rename}: {}{tyre}",
                    kind.what(),
                    wanted.what(),
                    kind.reader(),
                )
            }
            KindProblem::DegreesNowhere {
                column,
                files,
                present,
                allowed,
            } => {
                let none = match files {
                    1 => "the run file does not have it".to_string(),
                    n => format!("none of the {n} run files has it"),
                };
                let present = match present.is_empty() {
                    true => "none".to_string(),
                    false => present.join(", "),
                };
                write!(
                    f,
                    "`{column}` is declared in degrees, and {none}: the angle columns the runs have are {present} (`degrees` takes {}); leave `{column}` out",
                    allowed.join(", ")
                )
            }
        }
    }
}
