//! Measured vehicle runs (`FORMATS.md`): t, speed, steer, yaw_rate required;
//! ay, beta, roll, bank, ax optional. SI units, radians, ISO 8855 signs. A
//! channel whose size says it is in another unit (a time in ms, a steer in
//! degrees, a yaw rate in deg/s, `ay` in g or ft/s², a speed in km/h) is refused at its
//! column ([`super::run_units`]), as is an `ay` of the other sign
//! ([`super::run_ay_sign`]).

use super::columns::{read_columns_with_slips, Columns, Layout, Slip};
use super::run_ay_sign::check_ay_sign;
use super::run_bank::{check_bank_degrees, check_slope_reading};
use super::run_slope::{check_beta_percent, Lateral};
use super::run_units::{
    beyond, check_ay, check_beta, check_beta_declared, check_roll_or_bank, check_speed,
    check_speed_by_ax, check_time_step, check_yaw_rate,
};
use crate::error::{CellProblem, InputError, InputProblem};
use crate::measured::clock::fall_of;
use crate::measured::MeasuredRun;
use std::path::Path;

/// An angle (or angular rate) column of a run that a logger may write in
/// degrees (deg/s): a campaign names those of its files ([`read_run_with`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum AngleColumn {
    /// Road-wheel steer.
    Steer,
    /// Yaw rate (deg/s).
    YawRate,
    /// Sideslip.
    Beta,
    /// Body roll.
    Roll,
    /// Road bank.
    Bank,
}

impl AngleColumn {
    /// Every angle column, in a run file's order.
    pub const ALL: [AngleColumn; 5] = [
        AngleColumn::Steer,
        AngleColumn::YawRate,
        AngleColumn::Beta,
        AngleColumn::Roll,
        AngleColumn::Bank,
    ];

    /// The angle columns `metrics` reads in degrees when asked (a run's
    /// `bank` it does not read; `roll` levels `ay`): one list for the
    /// command line and the Python package alike.
    pub const READ_BY_METRICS: [AngleColumn; 4] = [
        AngleColumn::Steer,
        AngleColumn::YawRate,
        AngleColumn::Beta,
        AngleColumn::Roll,
    ];

    /// The names of [`AngleColumn::READ_BY_METRICS`].
    pub fn read_by_metrics_names() -> [&'static str; 4] {
        Self::READ_BY_METRICS.map(AngleColumn::name)
    }

    /// The column named `name`, if it is an angle column.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|c| c.name() == name)
    }

    /// A run column `name` that is no angle, said with what it holds and
    /// its unit (`speed is no angle: a run's speed is in m/s`): answered
    /// by the nearest angle's name, `--degrees speed` was offered `steer`.
    pub fn not_an_angle(name: &str) -> Option<String> {
        let (what, unit) = match name {
            "t" => ("time", "s"),
            "speed" => ("forward speed", "m/s"),
            "ay" => ("lateral acceleration", "m/s²"),
            "ax" => ("longitudinal acceleration", "m/s²"),
            _ => return None,
        };
        Some(format!(
            "`{name}` is no angle: a run's {what} is in {unit}, never in degrees"
        ))
    }

    /// The column's name in a run file.
    pub fn name(self) -> &'static str {
        match self {
            AngleColumn::Steer => "steer",
            AngleColumn::YawRate => "yaw_rate",
            AngleColumn::Beta => "beta",
            AngleColumn::Roll => "roll",
            AngleColumn::Bank => "bank",
        }
    }
}

pub use crate::error::DeclaredBy;

/// Reads and checks a measured run.
pub fn read_run(path: &Path) -> Result<MeasuredRun, InputError> {
    read_run_with(path, &[], DeclaredBy::CampaignRuns)
}

/// The optional channels of a run file, in `FORMATS.md`'s order.
pub const OPTIONAL_CHANNELS: [&str; 5] = ["ay", "beta", "roll", "bank", "ax"];

/// Reads and checks a measured run whose columns `degrees` are in degrees
/// (deg/s for the yaw rate), converted to radians before any check; a
/// declared column the file does not have is refused, naming `by`.
pub fn read_run_with(
    path: &Path,
    degrees: &[AngleColumn],
    by: DeclaredBy,
) -> Result<MeasuredRun, InputError> {
    read_run_reading(path, (degrees, by), &OPTIONAL_CHANNELS).map(|(run, _)| run)
}

/// A declared column a run file does not have, with the refusal a job
/// that reads that file alone gives.
pub type AbsentColumn = (AngleColumn, InputError);

/// [`read_run_with`] for one file of several (a campaign's `[runs]
/// degrees`, where a sensor may be on some runs only): a declared column
/// the file lacks is left out and returned with its refusal, for the
/// caller to refuse where every file lacks it.
pub fn read_run_declared(
    path: &Path,
    degrees: &[AngleColumn],
) -> Result<(MeasuredRun, Vec<AbsentColumn>), InputError> {
    read_run_lacking(
        path,
        (degrees, DeclaredBy::CampaignRuns),
        &OPTIONAL_CHANNELS,
        true,
    )
    .map(|(run, _, absent)| (run, absent))
}

/// What a run's header holds beside the channels read, for a job to say.
#[derive(Debug, Clone, Default)]
pub struct RunHeader {
    /// The optional channels the file has and the job does not read.
    pub unread: Vec<&'static str>,
    /// The header's columns that are slips of spelling of an optional
    /// channel read and absent (`bta` for `beta`): a run may carry
    /// columns of its own (`FORMATS.md`), so they are not refused.
    pub slips: Vec<Slip>,
}

/// [`read_run_with`] reading of the optional channels only `optional` (a
/// job that uses no more): the others are neither read nor checked, and
/// are returned by name where the file has them, with the header's slips,
/// for the job to say.
pub fn read_run_reading(
    path: &Path,
    declared_by: (&[AngleColumn], DeclaredBy),
    optional: &[&str],
) -> Result<(MeasuredRun, RunHeader), InputError> {
    read_run_lacking(path, declared_by, optional, false).map(|(run, header, _)| (run, header))
}

/// [`read_run_reading`], with a declared column the file lacks refused
/// (`lacking` false) or left out and returned ([`read_run_declared`]).
fn read_run_lacking(
    path: &Path,
    declared_by: (&[AngleColumn], DeclaredBy),
    optional: &[&str],
    lacking: bool,
) -> Result<(MeasuredRun, RunHeader, Vec<AbsentColumn>), InputError> {
    // The channels not read are known names all the same, never slips.
    let others: Vec<&str> = OPTIONAL_CHANNELS
        .into_iter()
        .filter(|n| !optional.contains(n))
        .collect();
    let layout = Layout {
        required: &["t", "speed", "steer", "yaw_rate"],
        optional,
        also_read: Some(&others),
    };
    let names: Vec<&str> = declared_by.0.iter().map(|a| a.name()).collect();
    let (mut c, slips) =
        read_columns_with_slips(path, layout, (declared_by.1, &names)).map_err(dropouts)?;
    let (declared, absent) = declared_columns(path, &c, declared_by, optional, lacking)?;
    let unread: Vec<&'static str> = OPTIONAL_CHANNELS
        .into_iter()
        .filter(|n| !optional.contains(n) && c.header.iter().any(|h| h == n))
        .collect();
    for a in &declared {
        c.scale(a.name(), std::f64::consts::PI / 180.0);
    }
    let mut t = c.take("t");
    check_times(path, &c, &t)?;
    // After the checks of the clock as logged, whose refusals name its
    // times as the file writes them.
    let clock = crate::measured::clock::rebase(&mut t);
    let steer = c.take("steer");
    check_steer(path, &c, &steer, declared_by.1)?;
    let (speed, yaw_rate) = (c.take("speed"), c.take("yaw_rate"));
    let run = MeasuredRun::new(path, t, speed, steer, yaw_rate)
        .with_ay(c.take_optional("ay"))
        .with_ax(c.take_optional("ax"))
        .with_roll(c.take_optional("roll"))
        .with_bank(c.take_optional("bank"))
        .with_beta(c.take_optional("beta"));
    let run = MeasuredRun { clock, ..run };
    // The checks read the columns' positions and lines only, not their
    // values: every channel is taken first and checked on the run.
    check_speed_and_rates(path, &c, &run, declared_by.1)?;
    check_angles(path, &c, &run, declared.contains(&AngleColumn::Beta))?;
    check_lateral(path, &c, &run)?;
    // After the units, which name a column in another unit first.
    super::run_response::check_responses(path, &c, &run)?;
    Ok((run, RunHeader { unread, slips }, absent))
}

/// The columns `degrees` declares in degrees that the file has, each once,
/// with those it lacks and their refusals (refused here unless `lacking`);
/// a declaration of a column the job does not read is refused first.
fn declared_columns(
    path: &Path,
    c: &Columns,
    (degrees, by): (&[AngleColumn], DeclaredBy),
    optional: &[&str],
    lacking: bool,
) -> Result<(Vec<AngleColumn>, Vec<AbsentColumn>), InputError> {
    // A column named twice is converted once: it is in degrees or not.
    let mut declared: Vec<AngleColumn> = Vec::new();
    for a in degrees {
        if !declared.contains(a) {
            declared.push(*a);
        }
    }
    // A declaration of a column the job does not read converts nothing
    // either (`metrics --degrees roll`): refused first, whether the file
    // has the column or not, with the columns it reads.
    let reads: Vec<&'static str> = AngleColumn::ALL
        .into_iter()
        .map(AngleColumn::name)
        .filter(|n| ["steer", "yaw_rate"].contains(n) || optional.contains(n))
        .collect();
    if let Some(a) = declared.iter().find(|a| !reads.contains(&a.name())) {
        let problem = InputProblem::DegreesColumnUnread {
            column: a.name(),
            by: by.words(),
            job: by.job(),
            reads,
        };
        return Err(InputError::problem_at(path, c.header_line, 1, problem));
    }
    // A declaration of a column the file does not have converts nothing:
    // a misspelt header would then be read as no channel at all.
    let mut absent: Vec<AbsentColumn> = Vec::new();
    declared.retain(|a| {
        let has = c.header.iter().any(|h| h == a.name());
        if !has {
            let problem = InputProblem::DegreesColumnAbsent {
                column: a.name(),
                by: by.words(),
                header: c.header.clone(),
            };
            absent.push((*a, InputError::problem_at(path, c.header_line, 1, problem)));
        }
        has
    });
    // A job that reads this file alone refuses the first it lacks.
    if !lacking && !absent.is_empty() {
        return Err(absent.swap_remove(0).1);
    }
    Ok((declared, absent))
}

/// A run's cells refused as NaN or empty in a measured channel (not `t`)
/// said as a logger's dropout, with how `FORMATS.md` has one marked.
fn dropouts(e: InputError) -> InputError {
    match e {
        InputError::Several {
            path,
            errors,
            more,
            counted,
        } => InputError::Several {
            path,
            errors: errors.into_iter().map(|(e, n)| (dropouts(e), n)).collect(),
            more,
            counted,
        },
        InputError::Cell {
            path,
            line,
            column,
            name,
            cell,
            problem,
        } if name != "t" && dropout(&cell, problem) => InputError::Cell {
            path,
            line,
            column,
            name,
            cell,
            problem: CellProblem::Dropout,
        },
        e => e,
    }
}

/// Whether a cell refused for `problem` is a dropout: NaN, or empty.
fn dropout(cell: &str, problem: CellProblem) -> bool {
    match problem {
        CellProblem::NotFinite => cell
            .trim_start_matches(['-', '+'])
            .eq_ignore_ascii_case("nan"),
        CellProblem::NotANumber => cell.is_empty(),
        _ => false,
    }
}

/// Times strictly increasing, at least two of them, at a step that is a
/// time in seconds.
fn check_times(path: &Path, c: &Columns, t: &[f64]) -> Result<(), InputError> {
    // The required channels, which run on across a wrapped clock and jump
    // where a new recording starts.
    let channels: Vec<&[f64]> = ["speed", "steer", "yaw_rate"]
        .into_iter()
        .filter_map(|n| c.get(n))
        .collect();
    for i in 1..t.len() {
        if t[i] <= t[i - 1] {
            return Err(c.error_at(
                path,
                i,
                "t",
                InputProblem::TimeNotIncreasing {
                    value: t[i],
                    previous: t[i - 1],
                    fall: fall_of(t, i, &channels),
                },
            ));
        }
    }
    if t.len() < 2 {
        return Err(InputError::problem(path, InputProblem::TooFewSamples));
    }
    check_time_step(path, c, t)
}

/// A steer no steer sensor logs, in any unit a steer is written in, rad:
/// above a steering wheel logged in degrees (about ±1100 at full lock,
/// which the unit checks name as degrees), so that only a cell that is no
/// reading at all passes it. One such sample refuses the run at its cell,
/// as a speed beyond any vehicle's does; a spike below it is repaired by
/// the cleaning, which a sample of 1e10 defeated (its robust spread of a
/// quantised steer scales with the largest value).
pub const ABSURD_STEER: f64 = 1e4;

/// A road-wheel angle beyond 90° is a unit slip, not a manoeuvre: judged on
/// the 99th percentile so that a logger's spike (repaired later) does not
/// refuse the file. A single sample beyond [`ABSURD_STEER`] is refused
/// first, at its cell.
fn check_steer(path: &Path, c: &Columns, steer: &[f64], by: DeclaredBy) -> Result<(), InputError> {
    if let Some(i) = steer.iter().position(|v| v.abs() > ABSURD_STEER) {
        let problem = crate::error::SteerBeyondAnySensor {
            value: steer[i],
            limit: ABSURD_STEER,
        };
        return Err(c.error_at(path, i, "steer", problem.into()));
    }
    match beyond(steer, std::f64::consts::FRAC_PI_2) {
        Some((i, p99)) => Err(c.error_at(
            path,
            i,
            "steer",
            InputProblem::SteerBeyondQuarterTurn {
                value: steer[i],
                p99,
                by,
            },
        )),
        None => Ok(()),
    }
}

/// The speed's and the yaw rate's units, and `ay`'s against them (else the
/// speed's against `ax`).
fn check_speed_and_rates(
    path: &Path,
    c: &Columns,
    run: &MeasuredRun,
    by: DeclaredBy,
) -> Result<(), InputError> {
    let (speed, yaw_rate) = (&run.speed, &run.yaw_rate);
    check_speed(path, c, speed)?;
    check_yaw_rate(path, c, yaw_rate, by)?;
    match (&run.ay, &run.ax) {
        (Some(ay), _) => {
            let lateral = super::run_turning::Channels {
                t: &run.t,
                speed,
                r: yaw_rate,
                ay,
                beta: run.beta.as_deref(),
            };
            check_ay(path, c, &lateral, by)
        }
        // No lateral accelerometer to judge the speed's unit by: the
        // longitudinal one, against the speed's change.
        (None, Some(ax)) => check_speed_by_ax(path, c, &run.t, speed, ax),
        (None, None) => Ok(()),
    }
}

/// The angles' units: a sideslip in percent, then roll, bank and sideslip
/// in degrees (`beta_declared`: the file said its sideslip is in degrees).
fn check_angles(
    path: &Path,
    c: &Columns,
    run: &MeasuredRun,
    beta_declared: bool,
) -> Result<(), InputError> {
    if let (Some(ay), Some(beta)) = (&run.ay, &run.beta) {
        // Before the size checks, which would name degrees.
        let lateral = Lateral {
            beta: None,
            bank: None,
            ..lateral(run, ay)
        };
        check_beta_percent(path, c, &lateral, beta)?;
    }
    for (column, v) in [
        ("roll", &run.roll),
        ("bank", &run.bank),
        ("beta", &run.beta),
    ] {
        if let Some(v) = v {
            check_roll_or_bank(path, c, column, v)?;
        }
    }
    if let Some(beta) = &run.beta {
        check_beta(path, c, &run.speed, &run.yaw_rate, beta)?;
        if beta_declared {
            check_beta_declared(path, c, &run.speed, &run.yaw_rate, beta)?;
        }
    }
    Ok(())
}

/// `ay` against the kinematic lateral acceleration over the whole run
/// (where single samples scatter on a transient): its sign, the bank's
/// unit, the slope's.
fn check_lateral(path: &Path, c: &Columns, run: &MeasuredRun) -> Result<(), InputError> {
    let Some(ay) = &run.ay else {
        return Ok(());
    };
    let lateral = lateral(run, ay);
    // Before the bank and the slope, which an `ay` of the other sign
    // distorts.
    check_ay_sign(path, c, &lateral)?;
    // Before the slope, which a bank in degrees distorts.
    if let Some(bank) = &run.bank {
        check_bank_degrees(path, c, &lateral, bank)?;
    }
    check_slope_reading(path, c, &lateral)
}

/// The run's channels as the lateral checks take them, with its `ay`.
fn lateral<'a>(run: &'a MeasuredRun, ay: &'a [f64]) -> Lateral<'a> {
    Lateral {
        t: &run.t,
        speed: &run.speed,
        steer: &run.steer,
        yaw_rate: &run.yaw_rate,
        ay,
        beta: run.beta.as_deref(),
        bank: run.bank.as_deref(),
        means: Default::default(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One steer cell beyond [`ABSURD_STEER`] is refused at its line and
    /// column with the value and the limit; a lone spike below it (10
    /// rad) is left to the cleaning, as the 99th percentile rule leaves it.
    #[test]
    fn one_steer_cell_beyond_any_sensor_is_refused_at_its_cell() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("r.csv");
        let write = |cell: &str| {
            let mut s = String::from("t,speed,steer,yaw_rate\n");
            for i in 0..200 {
                let steer = if i == 120 {
                    cell.to_string()
                } else {
                    "0.01".into()
                };
                s += &format!("{},20,{steer},0.07\n", f64::from(i) * 0.01);
            }
            std::fs::write(&path, s).unwrap();
        };
        for (cell, said) in [("1e308", "1e308"), ("-20000", "-20000")] {
            write(cell);
            let e = read_run(&path).unwrap_err().to_string();
            // Line 122: the header, then rows from 0.
            let at = format!("r.csv:122:3: column `steer`: {said} rad is beyond ±10000 rad");
            assert!(e.contains(&at), "{e}");
            assert!(!e.contains("inf"), "{e}");
        }
        for cell in ["10", "10000"] {
            write(cell);
            assert!(read_run(&path).is_ok(), "{cell}");
        }
    }

    #[test]
    fn a_column_declared_in_degrees_is_read_in_radians_and_then_passes_the_checks() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("r.csv");
        let mut s = String::from("t,speed,steer,yaw_rate,roll\n");
        for i in 0..50 {
            s += &format!("{},20,0,0,2.0\n", f64::from(i) * 0.01);
        }
        std::fs::write(&path, s).unwrap();
        assert!(read_run(&path).is_err());
        let run = read_run_with(&path, &[AngleColumn::Roll], DeclaredBy::CampaignRuns).unwrap();
        let roll = run.roll.unwrap();
        assert!((roll[7] - 2f64.to_radians()).abs() < 1e-15, "{}", roll[7]);
        // A declared column the file lacks is said, not dropped.
        let e = read_run_with(&path, &[AngleColumn::Bank], DeclaredBy::ReplayManoeuvre)
            .unwrap_err()
            .to_string();
        assert!(
            e.ends_with("r.csv:1:1: `degrees` under [manoeuvre] names `bank`, a column this file does not have (its columns: t, speed, steer, yaw_rate, roll)"),
            "{e}"
        );
    }
}
