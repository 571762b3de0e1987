//! The runs of a test campaign: the run files a campaign names (`[runs]
//! files`, the `*.csv` of `[runs] dir` or of a campaign folder's `runs/`),
//! each read, checked (long enough; the steer's sign and unit judged against
//! the yaw rate it gives, ISO 8855 signs), calibrated on its standstills and
//! straights as read ([`crate::measured::calibration`]) and cleaned
//! ([`crate::measured::clean`]), cut into segments if asked, `ay` levelled
//! by a logged roll ([`super::levelled`]). Units: SI, rad.

use super::pieces::{pieces_note, top_speeds, uncut_note, Cutting};
use super::run_checks::{
    checked_run, file_error, in_degrees_refusal, Judged, RunContext, RunRefusal, SteerInDegrees,
};
use crate::error::{
    CampaignFileProblem, DeclaredRun, InputError, InputProblem, OtherRun, SelectionProblem,
};
use crate::io::paths::beside;
use crate::io::toml_file::TomlSource;
use crate::io::AngleColumn;
use crate::measured::calibration::{calibrate, CalibrationReport};
use crate::measured::clean::{clean_run, CleanSettings, CleaningReport};
use crate::measured::MeasuredRun;
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// The `[runs]` table.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RunSpec {
    /// Run files.
    #[serde(default)]
    pub files: Vec<PathBuf>,
    /// A folder whose `*.csv` files are runs.
    pub dir: Option<PathBuf>,
    /// Cut every run into pieces of this length, s (long logs).
    pub segment: Option<f64>,
    /// Angle columns the files hold in degrees (deg/s for the yaw rate),
    /// converted to radians on reading: a logger's unit, stated once.
    #[serde(default)]
    pub degrees: Vec<AngleColumn>,
}

/// The run files: `[runs] files` and the `*.csv` of `[runs] dir` (of
/// `runs/` in a campaign folder without a list), sorted by name.
pub(super) fn run_files(
    src: &TomlSource,
    runs: Option<&RunSpec>,
    base: &Path,
    path: &Path,
    folder: bool,
    notes: &mut Vec<String>,
) -> Result<Vec<PathBuf>, InputError> {
    let file = &src.path;
    let run_spec = runs.cloned().unwrap_or_default();
    super::glob::refuse_globs(src, &run_spec.files, base)?;
    let mut files: Vec<PathBuf> = run_spec.files.iter().map(|p| beside(base, p)).collect();
    for p in &files {
        src.referenced_file("runs.files", p)?;
    }
    super::glob::refuse_dir_glob(src, run_spec.dir.as_ref(), base)?;
    if let Some(d) = &run_spec.dir {
        src.referenced_folder("runs.dir", &beside(base, d))?;
    }
    if let Some(d) = super::runs_folder(runs, base, path, folder) {
        files.extend(folder_runs(&d, file, notes)?);
    }
    // A run listed twice would be held out and trained on at once (a copy
    // of one too: [`read_runs`] refuses it, having read both).
    if let Some((first, second)) = selected_twice(&files) {
        return Err(refuse_pair(
            src,
            Some(&run_spec),
            (first, second),
            |a, b| SelectionProblem::SelectedTwice {
                run: files[second].clone(),
                first: a,
                second: b,
            },
        ));
    }
    if files.is_empty() {
        // The vehicle file of a campaign folder, passed for the folder.
        let campaign_folder = (!folder && base.join("runs").is_dir()).then(|| {
            if base.as_os_str().is_empty() {
                PathBuf::from(".")
            } else {
                base.to_path_buf()
            }
        });
        return Err(file_error(file, InputProblem::NoRuns { campaign_folder }));
    }
    Ok(files)
}

/// The first pair of indices of `files` that name one file (the same file
/// however spelt), in order.
fn selected_twice(files: &[PathBuf]) -> Option<(usize, usize)> {
    let same = |p: &PathBuf, q: &PathBuf| match (p.canonicalize(), q.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => p == q,
    };
    (0..files.len()).find_map(|i| {
        files[..i]
            .iter()
            .position(|q| same(&files[i], q))
            .map(|k| (k, i))
    })
}

/// The refusal of runs `first` and `second` of the selection (indices into
/// the files [`run_files`] returns of `spec`), `problem` made of the
/// entries that select them, with their places; located at the entry in
/// `[runs] files`: the second listing where both are there, else the
/// first, which `dir` finds again (the folder's files come after the list).
fn refuse_pair(
    src: &TomlSource,
    spec: Option<&RunSpec>,
    (first, second): (usize, usize),
    problem: impl FnOnce(String, String) -> SelectionProblem,
) -> InputError {
    let default = RunSpec::default();
    let spec = spec.unwrap_or(&default);
    let listed = spec.files.len();
    let at = |k: usize| match (k < listed, &spec.dir) {
        (true, _) => entry(src, &format!("runs.files[{k}]"), &spec.files[k]),
        (false, Some(d)) => entry(src, "runs.dir", d),
        (false, None) => "the campaign folder's `runs/`".to_string(),
    };
    let problem = problem(at(first), at(second));
    let k = if second < listed { second } else { first };
    let span = match k < listed {
        true => src.key_span(&format!("runs.files[{k}]")),
        false => src.key_span("runs.dir"),
    };
    src.located(
        span,
        InputProblem::Campaign(Box::new(CampaignFileProblem::Selection(problem))),
    )
}

/// The refusal of run `second` of `files` (selected by `spec`), whose
/// samples are run `first`'s: a copy under another name.
pub(super) fn refuse_copy(
    src: &TomlSource,
    spec: Option<&RunSpec>,
    files: &[PathBuf],
    (first, second): (usize, usize),
) -> InputError {
    refuse_pair(src, spec, (first, second), |a, b| {
        SelectionProblem::CopiedRun {
            run: files[second].clone(),
            copy_of: files[first].clone(),
            first: a,
            second: b,
        }
    })
}

/// The `[runs]` entry at `key`, written `value`, with its place in the
/// file: "`runs.files[0]` = "runs/a.csv" (c.toml:12:10)".
fn entry(src: &TomlSource, key: &str, value: &Path) -> String {
    let place = src.key_span(key).map_or_else(
        || src.path.display().to_string(),
        |s| {
            let (line, column) = crate::io::toml_file::line_col(&src.text, s.start);
            format!("{}:{line}:{column}", src.path.display())
        },
    );
    let reads = match key {
        "runs.dir" => ", which reads every *.csv of the folder",
        _ => "",
    };
    format!("`{key}` = \"{}\" ({place}){reads}", value.display())
}

/// The runs read: the pieces to replay, notes on what was done, the
/// cleaning report, the calibration of the raw runs and each run file's
/// top speed (m/s, for a `min_speed` that removes them).
pub(super) type ReadRuns = (
    Vec<MeasuredRun>,
    Vec<String>,
    CleaningReport,
    CalibrationReport,
    Vec<(String, f64)>,
);

/// The runs of folder `d`: its `*.csv` files (`.CSV` as Windows loggers
/// write it), sorted; anything else in it is named in a note, not passed
/// over in silence, and a folder without runs is refused in `file`. Apart
/// from [`run_files`] so that it reads on a screen.
fn folder_runs(d: &Path, file: &Path, notes: &mut Vec<String>) -> Result<Vec<PathBuf>, InputError> {
    let entries = std::fs::read_dir(d).map_err(|source| InputError::Io {
        path: d.to_path_buf(),
        source,
    })?;
    let (mut found, mut skipped): (Vec<PathBuf>, Vec<PathBuf>) = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .partition(|p| p.is_file() && p.extension().is_some_and(|x| x.eq_ignore_ascii_case("csv")));
    found.sort();
    skipped.sort();
    let names: Vec<String> = skipped
        .iter()
        .map(|p| {
            let name = p.file_name().unwrap_or_default().to_string_lossy();
            if p.is_dir() {
                format!("{name}/")
            } else {
                name.into_owned()
            }
        })
        .collect();
    if !skipped.is_empty() {
        notes.push(format!(
            "{}: {} entr{} not read ({}): the runs are the *.csv files of the folder itself",
            d.display(),
            skipped.len(),
            if skipped.len() == 1 { "y" } else { "ies" },
            names.join(", ")
        ));
    }
    if found.is_empty() {
        return Err(file_error(
            file,
            InputProblem::EmptyRunsFolder {
                folder: d.to_path_buf(),
                holds: names,
            },
        ));
    }
    Ok(found)
}

/// Run `i`'s refusal filed with the others (`refused`, the runs of a
/// steer's unit slip `slips`), a run refused by itself counted among the
/// others as refused, never among those that read in radians: a run
/// refused after its steer read so (another sign convention) was counted
/// there, and other runs' refusals said "5 read in radians" of 4 taken
/// (round 49). Apart from [`read_runs`] so that it reads on a screen.
fn file_refusal(
    (i, file): (usize, &Path),
    refusal: RunRefusal,
    refused: &mut Vec<(usize, InputError)>,
    slips: &mut SteerSlips,
    judged: &mut Judged,
) {
    match refusal {
        RunRefusal::Run(e) => {
            refused.push((i, e));
            judged.taken(file, Some(OtherRun::Refused));
        }
        RunRefusal::InDegrees(d) => slips.0.push((i, d)),
        RunRefusal::SteerDeclared(d) => slips.1.push((i, d)),
    }
}

/// The runs refused for their steer's unit, each with its index, which
/// the campaign refuses together: those that read in degrees undeclared
/// ([`in_degrees_refusal`]), those a declared `steer` makes 57× small
/// (`steer_unit.rs`).
type SteerSlips = (
    Vec<(usize, Box<SteerInDegrees>)>,
    Vec<(usize, Box<DeclaredRun>)>,
);

/// Counting a run in [`Judged`].
trait Taken {
    /// Run file `p` judged as `other` (`None`: taken, its held steer in
    /// radians).
    fn taken(&mut self, p: &Path, other: Option<OtherRun>);
}

impl Taken for Judged {
    fn taken(&mut self, p: &Path, other: Option<OtherRun>) {
        match other {
            None => self.0.push(p.display().to_string()),
            Some(o) => self.1.push((p.display().to_string(), o)),
        }
    }
}

/// The declared columns run file `p` lacks filed in `absent` (each with
/// the files lacking it and the first one's error). Apart from
/// [`read_runs`] so that it reads on a screen.
fn file_lacking(
    absent: &mut Vec<(AngleColumn, Vec<String>, InputError)>,
    lacks: Vec<(AngleColumn, InputError)>,
    p: &Path,
) {
    for (a, e) in lacks {
        match absent.iter_mut().find(|x| x.0 == a) {
            Some(x) => x.1.push(p.display().to_string()),
            None => absent.push((a, vec![p.display().to_string()], e)),
        }
    }
}

/// How a refusal is placed in the campaign file: a run whose samples an
/// earlier one holds, by `copied(earlier, run)` ([`refuse_copy`]); a
/// problem of what a `degrees` entry declares, at that entry.
pub(super) type Placed<'a> = (
    &'a dyn Fn(usize, usize) -> InputError,
    &'a dyn Fn(AngleColumn, InputProblem) -> InputError,
);

/// Reads, checks, calibrates and cleans every run, cut into segments if
/// asked; refusals placed in the campaign file by `placed` ([`Placed`]).
pub(super) fn read_runs(
    files: &[PathBuf],
    (segment, degrees): (Option<f64>, &[AngleColumn]),
    min_speed: f64,
    wheelbase: f64,
    inputs: &mut Vec<PathBuf>,
    (copied, at_degrees): Placed,
) -> Result<ReadRuns, InputError> {
    let (mut raw, mut runs, mut notes) = (Vec::new(), Vec::new(), Vec::new());
    let clean = CleanSettings::diagnosis(min_speed);
    let mut cleaning = CleaningReport::new(min_speed);
    // A declared column some files lack (a sideslip sensor on some runs)
    // is converted where it is and said where it is not; one no file has
    // is refused, as `metrics` and a replay refuse it.
    let mut absent: Vec<(AngleColumn, Vec<String>, InputError)> = Vec::new();
    let mut cut = Cutting::default();
    // Every run is checked before any is refused: a campaign of eight runs
    // with three bad ones is mended in one pass, not three.
    let (mut refused, mut slips): (_, SteerSlips) = (Vec::new(), Default::default());
    let mut judged: Judged = (Vec::new(), Vec::new());
    let ctx = RunContext {
        files,
        degrees,
        wheelbase,
        min_speed,
    };
    for (i, p) in files.iter().enumerate() {
        let (run, lacks, run_notes, other) = match checked_run(&ctx, i, &raw, copied) {
            Ok(checked) => checked,
            Err(refusal) => {
                let at = (i, p.as_path());
                file_refusal(at, refusal, &mut refused, &mut slips, &mut judged);
                continue;
            }
        };
        judged.taken(p, other);
        file_lacking(&mut absent, lacks, p);
        notes.extend(run_notes);
        inputs.push(p.clone());
        let name = run.path.display().to_string();
        let (listed, kept) = (cleaning.glitches.len(), cleaning.pieces.len());
        // The standstills the cleaning leaves out are the calibration's
        // evidence: it reads the run as logged.
        raw.push(run.clone());
        let pieces = clean_run(run, &clean, &mut cleaning);
        notes.extend(pieces_note(
            &name,
            &cleaning,
            (listed, kept),
            clean.min_speed,
        ));
        // Cut into segments, the report lists the segments replayed (with
        // their times), not the pieces they were cut from.
        if segment.is_some() {
            cleaning.pieces.truncate(kept);
        }
        for piece in pieces {
            match segment {
                Some(seg) => cut.cut(piece, seg, &mut cleaning, &mut runs),
                None => runs.push(piece),
            }
        }
    }
    let declared = (degrees, at_degrees);
    let (refused, count) = all_refused(refused, (slips, judged), declared, files.len(), &raw);
    let passed = raw.iter().map(|r| r.path.display().to_string()).collect();
    if let Some(e) = InputError::runs_refused(refused, (count, files.len()), passed) {
        return Err(e);
    }
    if let Some(seg) = segment.filter(|_| !cut.was_cut && !runs.is_empty()) {
        notes.push(uncut_note(seg, cut.longest));
    }
    // A logged roll levels ay: gravity's part of it is known, not fitted.
    let (runs, roll_note) =
        super::levelled::level_by_roll(&raw, runs, degrees.contains(&AngleColumn::Roll));
    notes.extend(roll_note);
    notes.extend(absent_notes(absent, files.len())?);
    Ok((runs, notes, cleaning, calibrate(&raw), top_speeds(&raw)))
}

/// The refusals of the runs (`refused`, with the runs of a steer's unit
/// slip and how the others were `judged`, [`in_degrees_refusal`]) of the
/// `of` run files, and how many runs they stand for; with them, where one
/// is of a sign, the note that the `beta` of the runs taken (`raw`) is not
/// checked yet: that check needs the base model fitted to every run, and a
/// second sign slip was heard only once the first was mended (round 39).
fn all_refused(
    mut refused: Vec<(usize, InputError)>,
    ((in_degrees, declared_small), judged): (SteerSlips, Judged),
    (degrees, at_degrees): (
        &[AngleColumn],
        &dyn Fn(AngleColumn, InputProblem) -> InputError,
    ),
    of: usize,
    raw: &[MeasuredRun],
) -> (Vec<InputError>, usize) {
    // A yaw rate in deg/s among runs in rad/s, and runs a declared
    // `yaw_rate` reads 57× small: `yaw_unit.rs`.
    super::yaw_unit::own_file_advice(&mut refused, &judged, degrees, of);
    let runs = refused.len() + in_degrees.len() + declared_small.len();
    // Runs a declared `steer` reads 57× small: `steer_unit.rs`.
    let taken: Vec<String> = raw.iter().map(|r| r.path.display().to_string()).collect();
    let small = (declared_small, &taken[..]);
    super::steer_unit::declared_refusal(small, (&judged, &mut refused), at_degrees, of);
    let in_degrees = super::yaw_unit::declared_refusal(
        in_degrees,
        (&judged, &mut refused),
        (degrees, at_degrees),
        of,
    );
    let (mut refused, _) = in_degrees_refusal(refused, in_degrees, judged, of);
    let count = runs;
    if refused.iter().any(sign_refused) {
        refused.extend(beta_unchecked(raw));
    }
    (refused, count)
}

/// Whether refusal `e` (or one it lists) is of a channel in another sign
/// convention: a yaw rate against the steer, an `ay` reversed.
fn sign_refused(e: &InputError) -> bool {
    match e {
        InputError::Invalid { problem, .. } => matches!(
            **problem,
            InputProblem::YawAgainstSteer { .. }
                | InputProblem::UnitSlip(crate::error::UnitSlip::AyReversed(_))
        ),
        InputError::Several { errors, .. } | InputError::RunsRefused { errors, .. } => {
            errors.iter().any(|(e, _)| sign_refused(e))
        }
        _ => false,
    }
}

/// The note, among the refusals, that the `beta` of the runs taken
/// (`raw`) is not checked yet ([`crate::error::BetaUnchecked`]), at the
/// first of them; None where none logs `beta`.
fn beta_unchecked(raw: &[MeasuredRun]) -> Option<InputError> {
    let mut with = raw.iter().filter(|r| r.beta.is_some());
    let first = with.next()?;
    let others = with.map(|r| r.path.display().to_string()).collect();
    let problem = InputProblem::BetaUnchecked(crate::error::BetaUnchecked { others });
    Some(file_error(&first.path, problem))
}

/// The notes on a column declared in degrees that some of the `files`
/// runs lack (with the files); the refusal of those that all of them lack,
/// every such column in one (refused one at a time, `degrees = ["roll",
/// "bank"]` was mended twice).
fn absent_notes(
    absent: Vec<(AngleColumn, Vec<String>, InputError)>,
    files: usize,
) -> Result<Vec<String>, InputError> {
    let mut notes = Vec::new();
    let mut refused = Vec::new();
    for (column, lacking, first) in absent {
        if lacking.len() == files {
            refused.push(first);
            continue;
        }
        notes.push(format!(
            "`degrees` under [runs] names `{}`, a column {} of {files} files do not have: {}",
            column.name(),
            lacking.len(),
            lacking.join(", ")
        ));
    }
    let path = refused.first().map(|e| e.path().to_path_buf());
    match path.and_then(|p| InputError::all_in_file_order(&p, refused)) {
        Some(e) => Err(e),
        None => Ok(notes),
    }
}

#[cfg(test)]
mod tests {
    use super::super::run_checks::steer_against_yaw;
    use super::*;
    use crate::measured::clean::segments;

    fn run(t: Vec<f64>) -> MeasuredRun {
        let n = t.len();
        MeasuredRun::new("r.csv", t, vec![20.0; n], vec![0.0; n], vec![0.0; n])
    }

    #[test]
    fn the_steer_is_judged_against_the_yaw_rate_only_where_the_run_steers() {
        // 10 s at 20 m/s and 100 Hz, a neutral car: r = u·δ/l.
        let l = 2.78;
        let with = |steer: &dyn Fn(f64) -> f64, gain: f64| {
            let t: Vec<f64> = (0..1000).map(|i| i as f64 * 0.01).collect();
            let mut r = run(t.clone());
            r.steer = t.iter().map(|&s| steer(s)).collect();
            r.yaw_rate = t
                .iter()
                .enumerate()
                .map(|(i, &s)| gain * 20.0 * steer(s) / l + 1e-3 * ((i * 7919 % 13) as f64 - 6.0))
                .collect();
            steer_against_yaw(&r, l, 5.0, false)
        };
        // Turns held for 1–2 s, left and right.
        let turns = |s: f64| 0.03 * (2.0 * (s * 1.3).sin()).clamp(-1.0, 1.0);
        assert!(matches!(with(&turns, 0.8), Ok(None)));
        // Logged in degrees: the yaw rate is 57/0.8 times too small for it,
        // refused as `metrics` refuses it.
        let degrees = |s: f64| turns(s).to_degrees();
        let e = with(&degrees, 0.8 / 57.29578).unwrap_err().to_string();
        assert!(e.contains("72× smaller"), "{e}");
        // The other sign convention: refused.
        assert!(with(&turns, -0.8).is_err());
        // A steer that never holds (a sine of 1 Hz) is not judged, even
        // with a yaw rate that does not follow it: on a real car the yaw
        // rate lags such a steer, and the ratio would measure the lag, not
        // the units.
        let sweep = |s: f64| 0.03 * (s * std::f64::consts::TAU).sin();
        assert!(matches!(with(&sweep, -0.8), Ok(None)));
        // A straight run whose steer sensor sits 6 mrad off shows no gain:
        // not judged, whatever the yaw rate's noise.
        assert!(matches!(with(&|_| 0.006, 0.0), Ok(None)));
    }

    #[test]
    fn segments_cover_the_run() {
        let t: Vec<f64> = (0..4600).map(|i| i as f64 * 0.1).collect();
        let s = segments(run(t), 30.0);
        assert_eq!(s.len(), 15);
        assert_eq!(s.iter().map(|r| r.t.len()).sum::<usize>(), 4600);
        assert!(s[0].path.to_string_lossy().ends_with("[1]"));
        // 41.72 s in pieces of 2.1 s: 19 whole ones leave 1.82 s, more than
        // half a piece but less than a run must be: it joins the 19th.
        let t: Vec<f64> = (0..=4172).map(|i| i as f64 * 0.01).collect();
        let s = segments(run(t), 2.1);
        assert_eq!(s.len(), 19);
        let last = &s[18].t;
        assert!(
            (last[last.len() - 1] - last[0] - 3.92).abs() < 0.011,
            "{}",
            last[0]
        );
        assert_eq!(s.iter().map(|r| r.t.len()).sum::<usize>(), 4173);
    }
}
