//! What is wrong with a scenario file beyond one key's value, and what
//! `simulate` says of a table it reads and sets aside: the wrong kind of
//! file given as a scenario (a run or rig CSV, a `.tir`, a tyre TOML, a
//! JSON report, a binary file), the two names of the integration table
//! (`[simulation]`, `[integrator]`) both written, an effect of the
//! measurement (a sensor's delay, the steer path) among the car's
//! `[model.effects]`, a diagnosis effect's name where the scenario has
//! its own key, and `[metrics]` under a manoeuvre that has no step-steer
//! metrics. The file, line and column come from the caller's
//! [`crate::error::InputError`]; the sentences are made here.

use super::FileKind;
use std::fmt;

/// Why a scenario file is refused as a whole or at a table.
#[derive(Debug, Clone, PartialEq)]
pub enum ScenarioProblem {
    /// The file is not a scenario.
    NotAScenario(FileKind),
    /// `[simulation]` and `[integrator]` both given: they are one table
    /// under two names. `first` is the earlier's name and line.
    TwoIntegrationTables {
        /// The earlier table's name and line.
        first: (&'static str, usize),
        /// The later table's name (where the error is).
        second: &'static str,
    },
    /// An effect of the measurement system in `[model.effects]`: only
    /// `diagnose` models a measurement.
    MeasurementEffect {
        /// The key as written.
        key: Box<str>,
    },
    /// A diagnosis effect's name in `[model.effects]` whose number a
    /// scenario gives under another key.
    EffectElsewhere {
        /// The key as written.
        key: Box<str>,
        /// Where the scenario takes it.
        home: &'static str,
    },
    /// A replayed run too long for a history at the default row interval.
    LongReplay(super::LongReplay),
    /// A replayed run refused for what the scenario's keys mend.
    ReplayRun(super::ReplayRunProblem),
    /// An RK4 step beyond the method's stability limit for the model.
    UnstableStep(super::UnstableStep),
    /// An error-controlled integration that spent its step budget before
    /// the manoeuvre's end.
    Stalled {
        /// Where it stopped, s.
        at: f64,
        /// The manoeuvre's end, s.
        end: f64,
        /// The steps it took.
        steps: usize,
        /// Why, as far as the scenario tells.
        cause: super::StallCause,
    },
    /// A step steer above the car's critical speed whose divergence
    /// stalled the integration (a wheel lifting off under load transfer):
    /// said as the critical speed, which `simulate` says of the same step
    /// run through (RK4, or no load transfer).
    StalledAboveCritical {
        /// Where it stopped, s.
        at: f64,
        /// The manoeuvre's end, s.
        end: f64,
        /// The understeer gradient at the static axle loads, rad/(m/s²).
        gradient: f64,
        /// The critical speed √(−l/K), m/s.
        critical: f64,
        /// The step's speed, m/s.
        speed: f64,
        /// The static axle loads the stiffness is taken at, N (front, rear).
        loads: [f64; 2],
    },
    /// A study's cornering stiffness in the other unit than its `unit`.
    StiffnessUnit(super::StiffnessSlip),
    /// A `name` that is no folder name: `simulate` writes into
    /// `out/<name>` where no `--out` is given.
    NameNotAFolder {
        /// The name as written.
        name: Box<str>,
    },
}

impl fmt::Display for FileKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FileKind::RunCsv => f.write_str("is a measured run (a CSV with `t`, `speed`, `steer`, `yaw_rate`), not a scenario: replay it from a scenario's `[manoeuvre] kind = \"replay\"` with `run = \"<this file>\"`, or measure it with `handling metrics`"),
            FileKind::RigCsv => f.write_str("is tyre rig data (a CSV with `fz` and `alpha` or `kappa`), not a scenario: fit a tyre to it with `handling identify`, and give the tyre file it writes as `[tyres] front = \"…\"` in a scenario"),
            FileKind::Csv { first } => write!(f, "is a CSV file (its header starts with `{first}`), not a scenario: a scenario is a TOML file with [vehicle], [tyres] and [manoeuvre] tables"),
            FileKind::Tir => f.write_str("is a .tir tyre file, not a scenario: give it as `[tyres] front = \"<this file>\"` in a scenario"),
            FileKind::TyreToml { model } => write!(f, "is a tyre file (`model = \"{model}\"`), not a scenario: give it as `[tyres] front = \"<this file>\"` in a scenario"),
            FileKind::Json => f.write_str("is a JSON file (a report `handling` writes: diagnosis.json, metrics.json, gap.json), not a scenario: a scenario is a TOML file with [vehicle], [tyres] and [manoeuvre] tables"),
            FileKind::Binary { at } => write!(f, "is not a text file (a NUL byte at byte {at}), not a scenario: a scenario is a TOML file with [vehicle], [tyres] and [manoeuvre] tables"),
            FileKind::HistoryCsv => f.write_str("is a simulation history (history.csv, which `handling simulate` writes), not a scenario: measure it with `handling metrics`"),
            FileKind::Text { .. } => write!(f, "is {}, not a scenario: a scenario is a TOML file with [vehicle], [tyres] and [manoeuvre] tables", self.what()),
            FileKind::Scenario | FileKind::Campaign | FileKind::Sweep | FileKind::Study | FileKind::Folder { .. } | FileKind::Foreign(_) => {
                write!(f, "is {}, not a scenario: {}", self.what(), self.reader())
            }
        }
    }
}

impl fmt::Display for ScenarioProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ScenarioProblem::NotAScenario(kind) => write!(f, "the file {kind}"),
            ScenarioProblem::LongReplay(r) => r.fmt(f),
            ScenarioProblem::ReplayRun(r) => r.fmt(f),
            ScenarioProblem::UnstableStep(u) => u.fmt(f),
            ScenarioProblem::Stalled { at, end, steps, cause } => write!(
                f,
                "the integration (Dormand–Prince) stalled at t = {at:.3} s of {end:.3} s: {steps} steps, its step driven towards zero by a model that is not smooth there ({}); nothing is written. {}; `method = \"rk4\"` with a fixed `step` runs through and its rows show where the run leaves it",
                cause.cause(),
                cause.advice()
            ),
            ScenarioProblem::StalledAboveCritical { at, end, gradient, critical, speed, loads } => write!(
                f,
                "the car oversteers (understeer gradient K = {} rad/(m/s²), {} deg/g, from the tyres' cornering stiffness at the static axle loads, {:.0} N front and {:.0} N rear) and the step is at {speed:.1} m/s, above its critical speed √(−l/K) = {critical:.1} m/s: its straight running is unstable there and the response diverges, until the integration (Dormand–Prince) stalled at t = {at:.3} s of {end:.3} s, its step driven towards zero where the diverging car leaves the model's smooth range (a wheel lifting off under load transfer); nothing is written. A step below {critical:.1} m/s measures the handling",
                crate::format::significant(*gradient, 3),
                crate::format::significant((gradient * crate::constants::G).to_degrees(), 3),
                loads[0],
                loads[1],
            ),
            ScenarioProblem::StiffnessUnit(s) => s.fmt(f),
            ScenarioProblem::NameNotAFolder { name } => write!(
                f,
                "`name` = {name:?} is no folder name: `simulate` writes the run into `out/<name>` where no `--out` is given, so a name is one folder's name, not empty, without `/` or `\\`, and not `.` or `..`"
            ),
            ScenarioProblem::TwoIntegrationTables { first: (name, line), second } => write!(
                f,
                "[{second}] and [{name}] (line {line}) are one table under two names (the method, step and tolerances of the integration): give one of them"
            ),
            ScenarioProblem::MeasurementEffect { key } => write!(
                f,
                "`model.effects.{key}` is a property of the measurement (the sensors and the steer they log), not of the car: a scenario simulates the car alone; `{key}` belongs to `handling diagnose`, which fits it to measured runs (a campaign's `[diagnose] effects`)"
            ),
            ScenarioProblem::EffectElsewhere { key, home } => write!(
                f,
                "`{key}` is the name of a `diagnose` effect; a scenario sets it as {home}"
            ),
        }
    }
}

/// What `simulate` says of a scenario as it reads it: a table the run
/// does not use (a warning), a measured channel it applies (a note).
#[derive(Debug, Clone, PartialEq)]
pub enum ScenarioRemark {
    /// `[metrics]` under a manoeuvre with no step-steer metrics.
    MetricsUnused {
        /// The table's line.
        line: usize,
        /// The manoeuvre's kind as the file names it.
        kind: &'static str,
    },
    /// A replayed run's `bank` column left out, the scenario giving no
    /// `bank_profile_scale`. Rad.
    BankNotApplied {
        /// The smallest and largest bank of the run, rad.
        range: [f64; 2],
    },
    /// `bank_profile_scale` given (at `line`) for a run with no `bank`
    /// column, or under a manoeuvre that replays no run.
    BankScaleWithoutBank {
        /// The key's line.
        line: usize,
        /// The manoeuvre's kind as the file names it.
        kind: &'static str,
    },
    /// A replayed run's `ax` whose unit or sign its speed contradicts.
    /// `Δu ≈ slope·∫ax dt` over its windows: a slope near g reads `ax` in
    /// g, a negative one reversed (`measured::ax_agreement`).
    AxAgainstSpeed {
        /// Slope of the change of speed on the integral of `ax`.
        slope: f64,
        /// Their correlation over the windows.
        correlation: f64,
        /// Windows counted.
        windows: usize,
    },
}

impl ScenarioRemark {
    /// A fact of the run (a note), not a doubt about it (a warning).
    pub fn is_note(&self) -> bool {
        matches!(self, ScenarioRemark::BankNotApplied { .. })
    }
}

impl fmt::Display for ScenarioRemark {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ScenarioRemark::MetricsUnused { line, kind } => write!(
                f,
                "[metrics] (line {line}) is ignored: its windows and filter set the step-steer metrics, and a {kind} has none (measure its history with `handling metrics` if it holds a step)"
            ),
            ScenarioRemark::BankNotApplied { range: [lo, hi] } => {
                let angle = |a: f64| {
                    format!(
                        "{} rad ({}°)",
                        super::number::Num(a),
                        crate::format::fixed(a.to_degrees(), 2)
                    )
                };
                let bank = match lo == hi {
                    true => angle(*lo),
                    false => format!("{} to {}", angle(*lo), angle(*hi)),
                };
                write!(
                    f,
                    "the run's `bank` column (road bank {bank}) does not act on the replay: the road is flat, as in `diagnose`'s base model, where whether the car felt a logged bank is the `bank_profile` effect's to fit; give `[model.effects] bank_profile_scale = 1` to drive on it as measured (gravity's g·sin(bank) across the car)"
                )
            }
            ScenarioRemark::BankScaleWithoutBank { line, kind } => {
                let none = match *kind {
                    "replay" => "this run has none".to_string(),
                    kind => format!("a {kind} replays no run"),
                };
                write!(
                    f,
                    "`model.effects.bank_profile_scale` (line {line}) acts on nothing: it scales a replayed run's `bank` column, and {none} (a constant bank is `road_bank`)"
                )
            }
            ScenarioRemark::AxAgainstSpeed {
                slope,
                correlation,
                windows,
            } => {
                let (says, fix) = match *slope < 0.0 {
                    false => ("reads in g, not m/s²", "multiply the column by 9.81"),
                    true => (
                        "is positive rearward, not forward (ISO 8855)",
                        "change its sign",
                    ),
                };
                write!(
                    f,
                    "the run's `ax` {says}: over its {} one-second windows whose speed changes by more than 0.5 m/s, the change of speed is {} × the integral of `ax` (1 where they agree; correlation {}); the replay takes `ax` as m/s² forward for its longitudinal load transfer: {fix}",
                    windows,
                    crate::format::fixed(*slope, 2),
                    crate::format::fixed(*correlation, 2),
                )
            }
        }
    }
}
