//! A scenario's replay of a measured run (`[manoeuvre] kind = "replay"`):
//! the run file read as `FORMATS.md` gives it (SI, rad, ISO 8855), its
//! angle columns in degrees where the scenario says so, cleaned of
//! standstills and glitches, and replayed from its first unmasked sample,
//! its initial yaw rate and sideslip a robust line through the first
//! [`INITIAL_STRETCH`] s ([`initial_value`]).

use crate::error::{
    InputError, InputProblem, ParamError, PieceRefusal, ReplayRunProblem, ScenarioProblem, UnitSlip,
};
use crate::io::toml_file::{param_error, TomlSource};
use crate::io::{read_run_with, AngleColumn, DeclaredBy, MeasuredRun};
use crate::manoeuvre::Replay;
use crate::measured::clean::{clean_run, clean_single_with, CleanSettings, CleaningReport};
use crate::metrics::measured::{dead_steer, steer_problem, yaw_per_neutral, Wheelbase};
use crate::metrics::MIN_STEP;
use crate::vehicle::State;
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// Replay of a measured run's steer and speed.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReplaySpec {
    /// The run file (`FORMATS.md`), relative to the scenario.
    pub run: PathBuf,
    /// Lowest speed replayed, m/s (default 5): the longest piece at or
    /// above it is replayed, glitches repaired or masked (`measured::clean`).
    #[serde(default = "default_min_speed")]
    pub min_speed: f64,
    /// The run's angle columns a logger wrote in degrees (deg/s for the
    /// yaw rate), converted before any check, as a campaign's
    /// `[runs] degrees` does.
    #[serde(default)]
    pub degrees: Vec<AngleColumn>,
}

fn default_min_speed() -> f64 {
    crate::measured::clean::DEFAULT_MIN_SPEED
}

/// A replay resolved: the manoeuvre, the state it starts from, the cleaned
/// run and what cleaning found.
pub(super) struct ResolvedReplay {
    pub replay: Replay,
    pub initial: State,
    pub run: MeasuredRun,
    pub cleaning: CleaningReport,
}

/// Reads and cleans the run at `run_path` (the spec's `run`, resolved
/// beside the scenario), started from its first unmasked sample. Its steer
/// is judged against its yaw rate with the scenario's `wheelbase` (m), by
/// the rule `metrics` and `diagnose` apply ([`steer_problem`]).
pub(super) fn resolve(
    src: &TomlSource,
    r: &ReplaySpec,
    run_path: &Path,
    wheelbase: f64,
) -> Result<ResolvedReplay, InputError> {
    ParamError::non_negative("min_speed", r.min_speed)
        .map_err(|e| param_error(src, Some("manoeuvre"), e))?;
    let settings = CleanSettings::single(r.min_speed);
    let mut cleaning = CleaningReport::new(r.min_speed);
    src.referenced_file("manoeuvre.run", run_path)?;
    let mut read = read_run_with(run_path, &r.degrees, DeclaredBy::ReplayManoeuvre)
        .map_err(|e| at_degrees(src, r, e))?;
    crate::measured::clock::on_logs_clock(&mut read);
    if let Some(p) = dead_steer(&read, wheelbase, r.min_speed) {
        return Err(InputError::problem(run_path, p));
    }
    if let Some(problem) = unit_problem(&read, wheelbase, r.min_speed) {
        if let Some(e) = declared_wrong(src, r, &problem) {
            return Err(e);
        }
        if let InputProblem::SteerAboveYaw {
            median,
            samples,
            at_speed,
            ..
        } = problem
        {
            let p = ReplayRunProblem::SteerAboveYaw {
                run: r.run.display().to_string().into(),
                median,
                samples,
                at_speed,
            };
            return Err(at_key(src, "manoeuvre.run", p));
        }
        return Err(InputError::problem(run_path, problem));
    }
    let top = read.speed.iter().copied().fold(0.0, f64::max);
    let run = replayed_piece(read, &settings, &mut cleaning).ok_or_else(|| {
        let stated = src.key_span("manoeuvre.min_speed").is_some();
        let p = ReplayRunProblem::TooSlow {
            run: r.run.display().to_string().into(),
            min_speed: r.min_speed,
            stated,
            slow: cleaning.samples_slow,
            read: cleaning.samples_read,
            top,
        };
        let key = if stated {
            "manoeuvre.min_speed"
        } else {
            "manoeuvre.run"
        };
        at_key(src, key, p)
    })?;
    // A masked sample is a glitch, not the initial state.
    let start: Vec<usize> = (0..run.t.len())
        .filter(|i| !run.masked.contains(i))
        .collect();
    let start = if start.is_empty() { vec![0] } else { start };
    Ok(ResolvedReplay {
        replay: Replay {
            ax: run.ax.clone(),
            bank: run.bank.clone(),
            ..Replay::of_inputs(run.t.clone(), run.steer.clone(), run.speed.clone())
        },
        initial: State {
            beta: run
                .beta
                .as_ref()
                .map_or(0.0, |b| initial_value(&run.t, b, &start)),
            yaw_rate: initial_value(&run.t, &run.yaw_rate, &start),
        },
        run,
        cleaning,
    })
}

/// The run's steer judged against its yaw rate: where it holds a steer
/// ([`yaw_per_neutral`], [`steer_problem`]), else (a sine, a sweep) for a
/// unit slip either way on the lag-aligned ratio
/// ([`crate::io::campaign::swept::swept_unit_slip`]), as `diagnose` judges
/// a campaign's runs: a sine's steer in radians declared in degrees was
/// replayed 57× too large without a word.
fn unit_problem(read: &MeasuredRun, wheelbase: f64, min_speed: f64) -> Option<InputProblem> {
    match yaw_per_neutral(read, wheelbase, min_speed) {
        Some(y) => steer_problem(&y, Wheelbase::Known(wheelbase)),
        None => crate::io::campaign::swept::swept_unit_slip(read, wheelbase, min_speed),
    }
}

/// `p` at the scenario's key `key`.
fn at_key(src: &TomlSource, key: &str, p: ReplayRunProblem) -> InputError {
    let problem = InputProblem::Scenario(Box::new(ScenarioProblem::ReplayRun(p)));
    src.located(src.key_span(key), problem)
}

/// A yaw rate 57× off a neutral car's for the steer ([`steer_problem`])
/// where `degrees` declares the culprit (a yaw rate read 57× small, a
/// steer whose yaw rate reads 57× large), refused at that entry of the
/// scenario: it, not the run, is what to mend.
fn declared_wrong(src: &TomlSource, r: &ReplaySpec, p: &InputProblem) -> Option<InputError> {
    let (column, median, samples) = match *p {
        InputProblem::SteerAboveYaw {
            median, samples, ..
        } => (AngleColumn::YawRate, median, samples),
        InputProblem::YawAboveSteer {
            median, samples, ..
        } => (AngleColumn::Steer, median, samples),
        _ => return None,
    };
    let k = r.degrees.iter().position(|c| *c == column)?;
    let p = ReplayRunProblem::DeclaredInDegrees {
        run: r.run.display().to_string().into(),
        column: column.name(),
        median,
        samples,
    };
    Some(at_key(src, &format!("manoeuvre.degrees[{k}]"), p))
}

/// A `degrees` entry the run lacks, refused at that entry of the
/// scenario (the run's header has no place for what it does not hold);
/// other errors as they are.
fn at_degrees(src: &TomlSource, r: &ReplaySpec, e: InputError) -> InputError {
    if let Some(e) = in_degrees(src, r, &e) {
        return e;
    }
    let InputError::Invalid { problem, .. } = &e else {
        return e;
    };
    let InputProblem::DegreesColumnAbsent { column, header, .. } = problem.as_ref() else {
        return e;
    };
    let k = r.degrees.iter().position(|c| c.name() == *column);
    let key = k.map_or("manoeuvre.degrees".into(), |k| {
        format!("manoeuvre.degrees[{k}]")
    });
    let p = ReplayRunProblem::DegreesAbsent {
        run: r.run.display().to_string().into(),
        column,
        header: header.clone(),
    };
    at_key(src, &key, p)
}

/// A steer or yaw rate the run reader finds in degrees and the scenario
/// does not declare so, refused at the scenario's `run` with this
/// scenario's key to declare it: the reader alone leads with `metrics
/// --degrees` and a campaign's `[runs]`.
fn in_degrees(src: &TomlSource, r: &ReplaySpec, e: &InputError) -> Option<InputError> {
    let InputError::Invalid { problem, at, .. } = e else {
        return None;
    };
    let column = match problem.as_ref() {
        InputProblem::UnitSlip(UnitSlip::YawRate { .. } | UnitSlip::YawRateInDegPerS { .. }) => {
            AngleColumn::YawRate
        }
        InputProblem::SteerBeyondQuarterTurn { .. } => AngleColumn::Steer,
        _ => return None,
    };
    if r.degrees.contains(&column) {
        return None;
    }
    let at = at.as_ref().map_or_else(
        || "its rows".to_string(),
        |l| format!("line {}, column {}", l.line, l.column),
    );
    let p = ReplayRunProblem::InDegrees {
        run: r.run.display().to_string().into(),
        at: at.into(),
        column: column.name(),
        detail: problem.to_string().into(),
    };
    Some(at_key(src, "manoeuvre.run", p))
}

/// The steer's least and largest values over `run`, rad.
fn steer_range(run: &MeasuredRun) -> (f64, f64) {
    run.steer
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &d| {
            (lo.min(d), hi.max(d))
        })
}

/// The steer's range over `run`, rad.
fn steer_span(run: &MeasuredRun) -> f64 {
    let (lo, hi) = steer_range(run);
    hi - lo
}

/// The piece of `read` a replay takes: the longest whose steer moves by a
/// step's worth ([`MIN_STEP`]) where any does, else the longest. A run
/// split by a time gap into a short piece holding its step and a longer
/// one held straight replayed the held one, which tests nothing of the
/// response; the other pieces are listed as dropped, with why.
fn replayed_piece(
    read: MeasuredRun,
    settings: &CleanSettings,
    cleaning: &mut CleaningReport,
) -> Option<MeasuredRun> {
    let mut probe = CleaningReport::new(settings.min_speed);
    let pieces = clean_run(read.clone(), settings, &mut probe);
    let any_moves = pieces.iter().any(|p| steer_span(p) >= MIN_STEP);
    let fits = |p: &MeasuredRun| {
        let (from, to) = steer_range(p);
        match any_moves && to - from < MIN_STEP {
            true => Err(PieceRefusal::SteerHeld {
                from,
                to,
                min: MIN_STEP,
            }),
            false => Ok(()),
        }
    };
    clean_single_with(read, settings, cleaning, fits).map(|(p, ())| p)
}

/// The stretch at a replay's start its initial yaw rate and sideslip are
/// estimated over, s: long enough to average a sensor's noise (10–20
/// samples at 50–100 Hz), short against a yaw response (0.1–0.3 s).
pub const INITIAL_STRETCH: f64 = 0.2;

/// The value of `x` at the first of the samples `idx` (unmasked, in time
/// order), from a robust line through those within [`INITIAL_STRETCH`] s
/// of it (at least three): the Theil–Sen slope (the median of the slopes
/// between pairs) and the median of `x − slope·(t − t₀)`. One noisy or
/// wild first sample sets off no transient, and a run that starts turning
/// starts on its trend, not on a stretch's mean. The first sample itself
/// where fewer than three fall within the stretch.
pub fn initial_value(t: &[f64], x: &[f64], idx: &[usize]) -> f64 {
    let i0 = idx[0];
    let near: Vec<usize> = idx
        .iter()
        .copied()
        .take_while(|&i| t[i] - t[i0] <= INITIAL_STRETCH + 1e-9)
        .collect();
    if near.len() < 3 {
        return x[i0];
    }
    let median = |mut v: Vec<f64>| crate::measured::clean::midpoint_median(&mut v);
    let mut slopes = Vec::new();
    for (a, &i) in near.iter().enumerate() {
        for &k in &near[a + 1..] {
            if t[k] > t[i] {
                slopes.push((x[k] - x[i]) / (t[k] - t[i]));
            }
        }
    }
    let slope = if slopes.is_empty() {
        0.0
    } else {
        median(slopes)
    };
    median(
        near.iter()
            .map(|&i| x[i] - slope * (t[i] - t[i0]))
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_wild_first_sample_does_not_set_the_initial_value() {
        let t: Vec<f64> = (0..50).map(|i| 0.01 * i as f64).collect();
        let idx: Vec<usize> = (0..50).collect();
        // A yaw rate rising at 0.1 rad/s² from 0.05, its first sample off
        // by 0.02: the line's value at the start, not the sample.
        let mut x: Vec<f64> = t.iter().map(|&t| 0.05 + 0.1 * t).collect();
        x[0] += 0.02;
        assert!((initial_value(&t, &x, &idx) - 0.05).abs() < 1e-9);
        // A masked first sample: the line at the first unmasked one.
        assert!((initial_value(&t, &x, &idx[1..]) - 0.051).abs() < 1e-9);
        // Two samples: the first.
        assert_eq!(initial_value(&t[..2], &x[..2], &[0, 1]), x[0]);
    }
}
