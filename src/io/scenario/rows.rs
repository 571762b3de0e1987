//! The history's size: a run whose rows every `step` s would pass
//! [`MAX_ROWS`] is refused. Where the scenario writes its `step`, at that
//! key; where a replayed run is long and the step is the default, at the
//! scenario's `run` key, with what the user can do ([`LongReplay`]): the
//! key the scenario does not write is not cited as if it did.

use super::SimulationSettings;
use crate::error::{
    InputError, InputProblem, LongReplay, ParamError, ParamReason, ScenarioProblem, TooManyRows,
};
use crate::io::toml_file::{line_col, param_error, TomlSource};
use crate::manoeuvre::Manoeuvre;
use crate::measured::MeasuredRun;

/// The most rows (after the first) a history holds: a run ten times longer than an hour of
/// logging at 1 kHz would need a step the user meant; beyond, a slip of
/// the step (1e-6 s for 1e-3) writes gigabytes.
pub const MAX_ROWS: f64 = 2.0e6;

/// The integration table's name as the file writes it: `[integrator]`
/// where it is the one given, else `[simulation]` (also where neither is).
pub(super) fn integration_table(src: &TomlSource) -> &'static str {
    match src.key_span("simulation").is_none() && src.key_span("integrator").is_some() {
        true => "integrator",
        false => "simulation",
    }
}

/// Refuses a history beyond [`MAX_ROWS`] rows for manoeuvre `m` at the
/// settings `s`; `measured` is a replay's run.
pub(super) fn check(
    src: &TomlSource,
    s: &SimulationSettings,
    m: &Manoeuvre,
    measured: Option<&MeasuredRun>,
) -> Result<(), InputError> {
    let duration = m.end_time() - m.start_time();
    // Intervals, not rows: the least step the refusal suggests then runs
    // (a hair of slack for its rounding).
    if duration / s.step <= MAX_ROWS * (1.0 + 1e-9) {
        return Ok(());
    }
    let table = integration_table(src);
    let written = src.key_span(&format!("{table}.step")).is_some();
    if let (Some(run), false, Some(at)) = (measured, written, src.key_span("manoeuvre.run")) {
        let (line, column) = line_col(&src.text, at.start);
        let long = LongReplay {
            duration,
            samples: run.t.len(),
            step: s.step,
            max_rows: MAX_ROWS,
        };
        let problem = InputProblem::Scenario(Box::new(ScenarioProblem::LongReplay(long)));
        return Err(InputError::problem_at(&src.path, line, column, problem));
    }
    let reason = ParamReason::TooManyRows(Box::new(TooManyRows {
        step: s.step,
        duration,
        max_rows: MAX_ROWS,
        table,
    }));
    let e = ParamError::new("step", s.step, reason);
    Err(param_error(src, Some(table), e))
}

#[cfg(test)]
mod tests {
    /// The longest run `end` may ask for is the most rows at the coarsest
    /// step a scenario may set (`[simulation] step` ≤ 0.05 s): no `end`
    /// passes its own check only to be refused for a step no scenario
    /// may set.
    #[test]
    fn the_longest_run_is_the_most_rows_at_the_coarsest_step() {
        assert_eq!(crate::constants::LONGEST_RUN, super::MAX_ROWS * 0.05);
        let coarsest = super::SimulationSettings {
            step: 0.05,
            ..Default::default()
        };
        assert!(coarsest.method().is_ok());
        let coarser = super::SimulationSettings {
            step: 0.050001,
            ..Default::default()
        };
        assert!(coarser.method().is_err());
    }
}
