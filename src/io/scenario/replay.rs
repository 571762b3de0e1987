//! A scenario's replay of a measured run (`[manoeuvre] kind = "replay"`):
//! the run file read as `FORMATS.md` gives it (SI, rad, ISO 8855), its
//! angle columns in degrees where the scenario says so, cleaned of
//! standstills and glitches, and replayed from its first unmasked sample.

use crate::error::{InputError, InputProblem, ParamError};
use crate::io::toml_file::{param_error, TomlSource};
use crate::io::{read_run_with, AngleColumn, DeclaredBy, MeasuredRun};
use crate::manoeuvre::Replay;
use crate::measured::clean::{clean_single, CleanSettings, CleaningReport};
use crate::metrics::measured::{steer_problem, yaw_per_neutral, Wheelbase};
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
    let read = read_run_with(run_path, &r.degrees, DeclaredBy::ReplayManoeuvre)?;
    if let Some(y) = yaw_per_neutral(&read, wheelbase, r.min_speed) {
        if let Some(p) = steer_problem(&y, Wheelbase::Known(wheelbase)) {
            return Err(InputError::problem(run_path, p));
        }
    }
    let run = clean_single(read, &settings, &mut cleaning).ok_or_else(|| {
        InputError::problem(
            run_path,
            InputProblem::NoMovingSamples {
                min_speed: r.min_speed,
                slow: cleaning.samples_slow,
                read: cleaning.samples_read,
            },
        )
    })?;
    // A masked first sample is a glitch, not the initial state.
    let first = (0..run.t.len())
        .find(|i| !run.masked.contains(i))
        .unwrap_or(0);
    Ok(ResolvedReplay {
        replay: Replay {
            t: run.t.clone(),
            steer: run.steer.clone(),
            speed: run.speed.clone(),
        },
        initial: State {
            beta: run.beta.as_ref().map_or(0.0, |b| b[first]),
            yaw_rate: run.yaw_rate[first],
        },
        run,
        cleaning,
    })
}
