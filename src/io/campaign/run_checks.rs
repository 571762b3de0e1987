//! The checks each run of a campaign passes before it is cleaned: long
//! enough, no dead channel, a steer that moves, and the steer's sign and
//! unit judged against the yaw rate it gives (ISO 8855 signs; SI, rad). A
//! run that fails is refused by itself and the others are still checked,
//! so that every refused run is said at once, runs in degrees among runs
//! in radians as one refusal naming them all.

use super::swept::swept_per_neutral;
use crate::error::{CampaignFileProblem, DeclaredRun, InputError, InputProblem, OtherRun};
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
}

/// Why a run was not taken.
pub(super) enum RunRefusal {
    /// Refused by itself: before its steer's unit was judged, or by what
    /// judging it found (another sign convention, a yaw rate that ignores
    /// the steer). Never counted among the runs that read in radians:
    /// only runs taken are (round 49).
    Run(InputError),
    /// Its steer reads in degrees (or as a steering-wheel angle) where
    /// none is declared so: a refusal of the campaign where other runs
    /// read in radians ([`in_degrees_refusal`]), else the run's own.
    InDegrees(Box<SteerInDegrees>),
    /// Its steer, declared in degrees, reads 57× small where as logged it
    /// reads as a car's: refused at that `degrees` entry with the others
    /// so (`steer_unit.rs`).
    SteerDeclared(Box<DeclaredRun>),
}

/// A run whose yaw rate is far smaller than a neutral car's for its steer.
pub(super) struct SteerInDegrees {
    /// The run's file, as said.
    pub run: String,
    /// Its median `r·l/(u·δ)`.
    pub median: f64,
    /// Its refusal where no run reads in radians, advising `degrees`.
    pub own: InputError,
}

/// The runs taken whose held steer reads in radians (their files), and
/// the others not in degrees with what judged them ([`OtherRun`]), a run
/// refused for another reason among them.
pub(super) type Judged = (Vec<String>, Vec<(String, OtherRun)>);

/// A declared angle column a run lacks, with its refusal were no run to
/// have it.
type Lacking = Vec<(AngleColumn, InputError)>;

/// A run taken: the run, the declared columns it lacks, its notes and
/// how its steer was judged against its yaw rate (`None`: on held
/// steered samples, read as radians; else what the campaign's refusal of
/// runs in degrees says of it).
pub(super) type Checked = (MeasuredRun, Lacking, Vec<String>, Option<OtherRun>);

/// Run `i` of `ctx.files` read and checked against the runs taken before it
/// (`raw`, for copies; `copied(earlier, i)` words one).
pub(super) fn checked_run(
    ctx: &RunContext,
    i: usize,
    raw: &[MeasuredRun],
    copied: &dyn Fn(usize, usize) -> InputError,
) -> Result<Checked, RunRefusal> {
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
    // Where other runs read in radians, `degrees` under [runs] is the
    // wrong advice for a run in degrees: the campaign decides its words.
    // So too where `degrees` declares the yaw rate, which then reads 57×
    // small: the campaign refuses that entry (`yaw_unit.rs`).
    let yaw_declared = ctx.degrees.contains(&AngleColumn::YawRate);
    let in_degrees = match (ctx.files.len() > 1 || yaw_declared) && !declared {
        true => steer_in_degrees(&run, wheelbase, min_speed),
        false => None,
    };
    let judged = steer_against_yaw(&run, wheelbase, min_speed, declared);
    let note = match (judged, in_degrees) {
        (Err(own), Some(median)) => {
            let run = run.path.display().to_string();
            return Err(RunRefusal::InDegrees(Box::new(SteerInDegrees {
                run,
                median,
                own,
            })));
        }
        (judged, _) => judged.map_err(|e| match declared {
            true => declared_small(&run, e, wheelbase, min_speed),
            false => RunRefusal::Run(e),
        })?,
    };
    let judged = match yaw_per_neutral(&run, wheelbase, min_speed) {
        Some(_) => None,
        None => Some(match swept_per_neutral(&run, wheelbase, min_speed) {
            Some(_) => OtherRun::Swept,
            None => OtherRun::Unjudged,
        }),
    };
    let mut notes: Vec<String> = Vec::new();
    notes.extend(note);
    notes.extend(crate::io::unchecked_speed_unit(&run));
    notes.extend(crate::io::steep_bank(&run));
    notes.extend(super::ax_check::ax_note(&run));
    Ok((run, lacks, notes, judged))
}

/// The refusals of a campaign's runs in run order (`refused`, each with
/// its run's index) with its runs whose steer reads in degrees: where
/// `judged_radians` runs taken read in radians, `degrees = ["steer"]` under
/// [runs], which converts every run, is wrong for those, and the runs in
/// degrees are one refusal at the first of them naming them all; where
/// none does, each its own refusal (advising `degrees`). Returns the
/// refusals and how many runs they stand for.
pub(super) fn in_degrees_refusal(
    mut refused: Vec<(usize, InputError)>,
    in_degrees: Vec<(usize, Box<SteerInDegrees>)>,
    (judged_radians, others): (Vec<String>, Vec<(String, OtherRun)>),
    of: usize,
) -> (Vec<InputError>, usize) {
    let judged_radians = judged_radians.len();
    let runs = refused.len() + in_degrees.len();
    match (in_degrees.first(), judged_radians) {
        (None, _) => {}
        (Some(_), 0) => refused.extend(in_degrees.into_iter().map(|(i, d)| (i, d.own))),
        (Some((first, d)), _) => {
            let path = PathBuf::from(&d.run);
            let first = *first;
            let runs = in_degrees
                .into_iter()
                .map(|(_, d)| (d.run, d.median))
                .collect();
            let problem = crate::error::SteerInDegreesRuns {
                runs,
                of,
                radians: judged_radians,
                others,
            };
            let e = file_error(
                &path,
                InputProblem::Campaign(Box::new(CampaignFileProblem::SteerInDegreesRuns(problem))),
            );
            refused.push((first, e));
        }
    }
    refused.sort_by_key(|(i, _)| *i);
    (refused.into_iter().map(|(_, e)| e).collect(), runs)
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
        // No held steer: a sweep's or a sine's steer is judged for a unit
        // slip too, either way (a steer in degrees, or one in radians
        // declared in degrees).
        return match super::swept::swept_unit_slip(run, wheelbase, min_speed) {
            Some(problem) => Err(file_error(&run.path, problem)),
            None => Ok(None),
        };
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

/// Run `run`'s refusal `e` by its steer against its yaw rate, its steer
/// declared in degrees: where `e` is a yaw rate far larger than a neutral
/// car's for the steer ([`InputProblem::YawAboveSteer`], held or swept)
/// and the steer as logged (× 180/π, radians) reads as a car's, the run
/// that declaration makes small, with both ratios; else `e`, the run's own.
fn declared_small(run: &MeasuredRun, e: InputError, wheelbase: f64, min_speed: f64) -> RunRefusal {
    let declared = match &e {
        InputError::Invalid { problem, .. } => match **problem {
            InputProblem::YawAboveSteer { median, .. } => median,
            _ => return RunRefusal::Run(e),
        },
        _ => return RunRefusal::Run(e),
    };
    let mut logged = run.clone();
    logged.steer.iter_mut().for_each(|d| *d = d.to_degrees());
    let y = yaw_per_neutral(&logged, wheelbase, min_speed)
        .or_else(|| swept_per_neutral(&logged, wheelbase, min_speed));
    match y.filter(|y| steer_problem(y, Wheelbase::Known(wheelbase)).is_none()) {
        Some(y) => RunRefusal::SteerDeclared(Box::new(DeclaredRun {
            run: run.path.display().to_string(),
            declared,
            logged: y.median,
        })),
        None => RunRefusal::Run(e),
    }
}

/// The median `r·l/(u·δ)` of a run whose steer is far larger than its yaw
/// rate ([`InputProblem::SteerAboveYaw`]: in degrees, or a steering-wheel
/// angle).
fn steer_in_degrees(run: &MeasuredRun, wheelbase: f64, min_speed: f64) -> Option<f64> {
    let Some(y) = yaw_per_neutral(run, wheelbase, min_speed) else {
        return super::swept::swept_in_degrees(run, wheelbase, min_speed).map(|(_, m)| m);
    };
    match steer_problem(&y, Wheelbase::Known(wheelbase))? {
        InputProblem::SteerAboveYaw { median, .. } => Some(median),
        _ => None,
    }
}

/// Refuses a run whose yaw rate, `ay` or `beta` holds one value over the
/// whole run (a dead sensor logging zeros, [`MeasuredRun::dead_channels`]):
/// its noise floor would be zero and any gap to it infinitely significant.
/// Every dead channel in one refusal: naming the first, a run with `ay`
/// and `beta` dead was mended and rerun to hear of the second.
fn check_live_channels(run: &MeasuredRun) -> Result<(), InputError> {
    let each = run
        .dead_channels()
        .iter()
        .map(|d| file_error(&run.path, d.problem()))
        .collect();
    match InputError::all_channels_of(&run.path, each) {
        Some(e) => Err(e),
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
