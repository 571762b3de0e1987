//! The checks each run of a campaign passes before it is cleaned: long
//! enough, no dead channel, a steer that moves, and the steer's sign and
//! unit judged against the yaw rate it gives (ISO 8855 signs; SI, rad). A
//! run that fails is refused by itself and the others are still checked,
//! so that every refused run is said at once; a refusal about the whole
//! campaign (runs in degrees where others are in radians) ends the
//! reading.

use crate::error::{CampaignFileProblem, InputError, InputProblem};
use crate::io::{read_run_declared, AngleColumn};
use crate::measured::clean::{MIN_RUN_SAMPLES, MIN_RUN_SECONDS};
use crate::measured::MeasuredRun;
use crate::metrics::measured::{dead_steer, steer_problem, yaw_per_neutral, Wheelbase};
use std::path::{Path, PathBuf};

/// An error about a whole file (the campaign's, a run's).
pub(super) fn file_error(path: &Path, problem: InputProblem) -> InputError {
    InputError::problem(path, problem)
}

/// What the checks of one run read of the campaign.
pub(super) struct RunContext<'a> {
    /// Every run file, in order.
    pub files: &'a [PathBuf],
    /// The angle columns declared in degrees.
    pub degrees: &'a [AngleColumn],
    /// The campaign's wheelbase, m.
    pub wheelbase: f64,
    /// Below this speed samples are excluded, m/s.
    pub min_speed: f64,
    /// No run before this one was refused: a steer in degrees is then
    /// judged against runs whose steer read in radians (a campaign-wide
    /// refusal), else refused with the run alone.
    pub none_refused: bool,
}

/// Why a run was not taken.
pub(super) enum RunRefusal {
    /// The run alone: the others are still checked.
    Run(InputError),
    /// The campaign as a whole: reading ends.
    Campaign(InputError),
}

/// A declared angle column a run lacks, with its refusal were no run to
/// have it.
type Lacking = Vec<(AngleColumn, InputError)>;

/// Run `i` of `ctx.files` read and checked against the runs taken before it
/// (`raw`, for copies; `copied(earlier, i)` words one): the run, the
/// declared columns it lacks and its notes.
pub(super) fn checked_run(
    ctx: &RunContext,
    i: usize,
    raw: &[MeasuredRun],
    copied: &dyn Fn(usize, usize) -> InputError,
) -> Result<(MeasuredRun, Lacking, Vec<String>), RunRefusal> {
    let (wheelbase, min_speed) = (ctx.wheelbase, ctx.min_speed);
    let (run, lacks) = read_run_declared(&ctx.files[i], ctx.degrees).map_err(RunRefusal::Run)?;
    // Every earlier run passed the checks below: a copy of one would
    // too, and be held out on the samples its twin is fitted on.
    if let Some(k) = super::copies::copied_from(raw, &run) {
        return Err(RunRefusal::Run(copied(k, i)));
    }
    let alone = |e| RunRefusal::Run(e);
    check_length(&run).map_err(alone)?;
    check_live_channels(&run).map_err(alone)?;
    if let Some(problem) = dead_steer(&run, wheelbase, min_speed) {
        return Err(alone(file_error(&run.path, problem)));
    }
    let declared = ctx.degrees.contains(&AngleColumn::Steer);
    if ctx.files.len() > 1 && !declared && ctx.none_refused {
        if let Some(m) = steer_in_degrees(&run, wheelbase, min_speed) {
            let first = (run.path.display().to_string(), m);
            let later = &ctx.files[i + 1..];
            let some = runs_in_degrees(first, later, ctx.files.len(), wheelbase, min_speed);
            if let Some(e) = some {
                return Err(RunRefusal::Campaign(e));
            }
        }
    }
    let mut notes: Vec<String> = Vec::new();
    notes.extend(steer_against_yaw(&run, wheelbase, min_speed, declared).map_err(alone)?);
    notes.extend(crate::io::unchecked_speed_unit(&run));
    notes.extend(crate::io::steep_bank(&run));
    notes.extend(super::ax_check::ax_note(&run));
    Ok((run, lacks, notes))
}

/// The steer judged against the yaw rate it gives where it is held
/// ([`yaw_per_neutral`]), by the rule `metrics` applies too
/// ([`steer_problem`]) with the campaign's wheelbase, as a replay judges
/// its run: a yaw rate turning against the steer (another sign
/// convention), far smaller than a neutral car's (a steer in degrees or a
/// steering-wheel angle) or far larger is refused; one above 3 a neutral
/// car's (a steer too small, or a wrong wheelbase) is noted, and the note
/// asks whether a steer `declared` in degrees under `[runs]` was in
/// radians.
pub(super) fn steer_against_yaw(
    run: &MeasuredRun,
    wheelbase: f64,
    min_speed: f64,
    declared: bool,
) -> Result<Option<String>, InputError> {
    let Some(y) = yaw_per_neutral(run, wheelbase, min_speed) else {
        return Ok(None);
    };
    let (m, n) = (y.median, y.samples);
    if let Some(problem) = steer_problem(&y, Wheelbase::Known(wheelbase)) {
        return Err(file_error(&run.path, problem));
    }
    let ask = match declared {
        true => " `steer` is declared in degrees under [runs]: was it already in radians?",
        false => "",
    };
    Ok((m > 3.0).then(|| {
        format!(
            "{}: the yaw rate is {m:.1}× a neutral car's for this steer (median r·l/(u·δ) over {n} held steered samples): is `steer` the road-wheel angle in radians, and the wheelbase right?{ask}",
            run.path.display()
        )
    }))
}

/// The median `r·l/(u·δ)` of a run whose steer is far larger than its yaw
/// rate ([`InputProblem::SteerAboveYaw`]: in degrees, or a steering-wheel
/// angle).
fn steer_in_degrees(run: &MeasuredRun, wheelbase: f64, min_speed: f64) -> Option<f64> {
    let y = yaw_per_neutral(run, wheelbase, min_speed)?;
    match steer_problem(&y, Wheelbase::Known(wheelbase))? {
        InputProblem::SteerAboveYaw { median, .. } => Some(median),
        _ => None,
    }
}

/// The refusal of a campaign of `of` run files whose run `first` (its file
/// and median `r·l/(u·δ)`) has a steer in degrees, with every `later` file
/// that has one too (read again here, only on this way out): the runs
/// before it were judged right, so `degrees` under [runs], which converts
/// every run, is wrong for them; `None` where all runs read so (the run's
/// own refusal, as `metrics` words it, advises `degrees` then).
fn runs_in_degrees(
    first: (String, f64),
    later: &[PathBuf],
    of: usize,
    wheelbase: f64,
    min_speed: f64,
) -> Option<InputError> {
    let path = PathBuf::from(&first.0);
    let mut runs = vec![first];
    for p in later {
        let Ok((run, _)) = read_run_declared(p, &[]) else {
            continue;
        };
        if let Some(m) = steer_in_degrees(&run, wheelbase, min_speed) {
            runs.push((run.path.display().to_string(), m));
        }
    }
    if runs.len() == of {
        return None;
    }
    let problem = crate::error::SteerInDegreesRuns { runs, of };
    Some(file_error(
        &path,
        InputProblem::Campaign(Box::new(CampaignFileProblem::SteerInDegreesRuns(problem))),
    ))
}

/// Refuses a run whose yaw rate, `ay` or `beta` holds one value over the
/// whole run (a dead sensor logging zeros, [`MeasuredRun::dead_channels`]):
/// its noise floor would be zero and any gap to it infinitely significant.
fn check_live_channels(run: &MeasuredRun) -> Result<(), InputError> {
    match run.dead_channels().first() {
        Some(d) => Err(file_error(&run.path, d.problem())),
        None => Ok(()),
    }
}

fn check_length(run: &MeasuredRun) -> Result<(), InputError> {
    let n = run.t.len();
    let span = run.t[n - 1] - run.t[0];
    if span < MIN_RUN_SECONDS || n < MIN_RUN_SAMPLES {
        return Err(file_error(
            &run.path,
            InputProblem::RunTooShort {
                span,
                samples: n,
                min_span: MIN_RUN_SECONDS,
                min_samples: MIN_RUN_SAMPLES,
            },
        ));
    }
    Ok(())
}
