//! `diagnose` as one job: a campaign (file or folder) in; the sim-to-real
//! gap of its runs, the candidate effects ranked on held-out runs and the
//! verdict ([`crate::diagnose`]) out, as `diagnosis.json`, the gap map
//! (`gap_map.png`: held-out RMS over the noise floor against time window,
//! |ay| level and speed band) and the overlays of the worst runs
//! (`overlays.png`), and all of it on one self-contained page to share
//! (`report.html`, [`super::diagnose_page`]).

#[cfg(test)]
use super::diagnose_gap_map::{gap_figure, GapPoint};
use super::diagnose_gap_map::{gap_map, quantity};
use super::diagnose_overlays::{overlay_figure, overlay_panels, write_overlays_csv};
use crate::diagnose::effects::joined;
use crate::diagnose::pipeline::{work_units, Diagnosis};
use crate::diagnose::report::left_in::runs_left_in;
use crate::diagnose::report::outcome::SIGNIFICANT_NOISE_FLOORS;
use crate::diagnose::report::{words, GapFinding, Note, Part, Reduction, Verdict};
use crate::error::Error;
use crate::format::fixed;
use crate::io::campaign::load_campaign;
use crate::optim::local::Derivatives;
#[cfg(test)]
use crate::report::plot::Style;
use crate::report::progress::Progress;
use crate::report::{create_dir, refuse_overwrites, write_json, OutputLock};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// The report of `diagnose`: the diagnosis (`diagnosis.json`) and how the
/// campaign was read.
#[derive(Debug, Clone, Serialize)]
pub struct DiagnoseReport {
    /// The diagnosis.
    #[serde(flatten)]
    pub diagnosis: Diagnosis,
    /// Runs in the campaign.
    #[serde(skip)]
    pub runs: usize,
    /// The files they were read from.
    #[serde(skip)]
    pub run_files: usize,
    /// Candidate effects fitted (the runs could show them).
    #[serde(skip)]
    pub effects: usize,
    /// How the runs were cleaned, in lines.
    #[serde(skip)]
    pub cleaning: Vec<String>,
    /// The output folder.
    #[serde(skip)]
    pub out_dir: PathBuf,
    /// The output folder, held for this run until the report is dropped.
    #[serde(skip)]
    pub lock: OutputLock,
}

const FILES: [&str; 5] = [
    "diagnosis.json",
    "gap_map.png",
    "overlays.png",
    "report.html",
    "overlays.csv",
];

/// What `simulate` notes of a car's `.tir` files, said of a campaign's
/// given tyre files too: a peak friction no tyre has (a nominal load of
/// another class of vehicle is a warning: [`far_from_load`]).
fn given_tyre_notes(c: &crate::diagnose::Campaign) -> Vec<String> {
    use crate::jobs::simulate::checks;
    let crate::diagnose::campaign::BaseTyres::Given(f, r, _) = &c.tyres else {
        return Vec::new();
    };
    checks::tir_friction_of([f, r])
}

/// What `simulate` warns of a campaign's given tyre files whose `FNOMIN`
/// the car's wheels load far from: its words, and each axle's load share
/// where far (None, None: none is).
fn far_from_load(c: &crate::diagnose::Campaign) -> (Vec<String>, [Option<f64>; 2]) {
    use crate::jobs::simulate::{checks, nominal_load};
    let crate::diagnose::campaign::BaseTyres::Given(f, r, _) = &c.tyres else {
        return (Vec::new(), [None, None]);
    };
    let [front, rear] = nominal_load::far_from_nominal_of(&c.vehicle, [f, r]);
    (
        checks::per_axle_tir(front, rear),
        nominal_load::nominal_shares_of(&c.vehicle, [f, r]),
    )
}

/// A diagnosis on base tyres far from their load range warns of it, on
/// the inputs and on an explained verdict (round 29: a truck `.tir` on a
/// sedan was a note, and the verdict blamed steering_compliance at 78.5 %
/// without a caveat).
fn warn_far_from_load(d: &mut Diagnosis, words: Vec<String>, shares: [Option<f64>; 2]) {
    use crate::diagnose::report::outcome::VerdictWarning;
    d.notes.extend(
        words
            .into_iter()
            .map(|text| Note::TyresFarFromLoad { text }),
    );
    if let (Verdict::Explained(e), [front, rear]) = (&mut d.verdict, shares) {
        if front.is_some() || rear.is_some() {
            e.warnings
                .push(VerdictWarning::TyresFarFromLoad { front, rear });
        }
    }
}

/// Refuses an output folder that is the campaign's folder of runs
/// (compared after resolving links; one not yet made is none).
fn refuse_runs_folder(out: &Path, runs: Option<&Path>, default: PathBuf) -> Result<(), Error> {
    let canon = |p: &Path| std::fs::canonicalize(p).ok();
    match (canon(out), runs.and_then(canon)) {
        (Some(o), Some(r)) if o == r => Err(crate::error::OutputError::IntoRunsFolder {
            path: out.to_path_buf(),
            default,
        }
        .into()),
        _ => Ok(()),
    }
}

/// Diagnoses the campaign at `path`; `out` is the output folder (default
/// `out/<campaign name>`), checked against the inputs first.
pub fn run(path: &Path, out: Option<&Path>) -> Result<DiagnoseReport, Error> {
    let mut campaign = load_campaign(path)?;
    campaign.notes.extend(given_tyre_notes(&campaign));
    let (far_words, far_shares) = far_from_load(&campaign);
    let default = PathBuf::from("out").join(&campaign.name);
    let out_dir = out.map_or_else(|| default.clone(), Path::to_path_buf);
    refuse_runs_folder(&out_dir, campaign.runs_folder.as_deref(), default)?;
    refuse_overwrites(&FILES.map(|f| out_dir.join(f)), &campaign.inputs)?;
    let lock = OutputLock::acquire(&out_dir)?;
    let mut diagnosis = {
        let progress = Progress::start("diagnose", work_units(&campaign));
        crate::diagnose::diagnose(&campaign, Some(progress.counter()))?
    };
    diagnosis.source_absolute = std::fs::canonicalize(&campaign.source).ok();
    warn_far_from_load(&mut diagnosis, far_words, far_shares);
    crate::design::lacking::fill(&campaign, &mut diagnosis);
    Ok(DiagnoseReport {
        // The candidates fitted (those the runs can show): every one is
        // ranked or screened.
        effects: diagnosis.ranking.len() + diagnosis.screened_singles().count(),
        diagnosis,
        runs: campaign.runs.len(),
        run_files: campaign.run_files,
        cleaning: campaign.cleaning.summary(5),
        out_dir,
        lock,
    })
}

impl DiagnoseReport {
    /// The output files.
    pub fn outputs(&self) -> [PathBuf; 5] {
        FILES.map(|f| self.out_dir.join(f))
    }

    /// Writes the diagnosis, its two figures and the page that holds them
    /// all (`report.html`).
    pub fn write(&self) -> Result<(), Error> {
        let files = self.outputs();
        create_dir(&self.out_dir)?;
        write_json(&files[0], &self.diagnosis)?;
        let panels = overlay_panels(&self.diagnosis);
        let (gap, over) = (gap_map(&self.diagnosis), overlay_figure(&panels, quantity));
        gap.save(&files[1])?;
        over.save(&files[2])?;
        write_overlays_csv(&files[4], &panels)?;
        let inputs = super::diagnose_page::Inputs {
            runs: self.runs,
            run_files: self.run_files,
        };
        super::diagnose_page::page(&self.diagnosis, inputs, &gap, &over, &files[3])?.write(
            &format!("Diagnosis of {}", self.diagnosis.campaign),
            &files[3],
        )
    }

    /// Where the time went, in words: the wall seconds, the CPU seconds,
    /// the threads and the largest phase (`13.4 s (25.8 s CPU on 2
    /// threads; 43 % in the candidate global stage …)`).
    pub fn time_spent(&self) -> String {
        let t = &self.diagnosis.timing;
        let cpu = t
            .cpu_seconds
            .map_or_else(String::new, |c| format!("{c:.1} s CPU on "));
        let s = if t.threads == 1 { "" } else { "s" };
        let largest = t.largest().map_or_else(String::new, |p| {
            format!("; {:.0} % in the {}", t.share_percent(p), p.phase.name())
        });
        format!(
            "{:.1} s ({cpu}{} thread{s}{largest})",
            t.wall_seconds, t.threads
        )
    }

    /// The campaign read and the short human report.
    pub fn summary(&self) -> Vec<String> {
        let d = &self.diagnosis;
        // Runs cut into pieces (a long log's segments, a run split where it
        // stopped) say so: the files are what the user handed in.
        let runs = if self.runs == self.run_files {
            format!("{} runs", self.runs)
        } else {
            let s = if self.run_files == 1 { "" } else { "s" };
            format!("{} runs (pieces of {} file{s})", self.runs, self.run_files)
        };
        let plural = if self.effects == 1 { "" } else { "s" };
        let exact = match d.derivatives {
            Derivatives::Exact => ", exact Jacobians",
            Derivatives::Differences => "",
        };
        let mut out = vec![format!(
            "{}: {runs}, {} candidate effect{plural}, seed {}{exact}",
            d.campaign, self.effects, d.seed
        )];
        out.extend(d.notes.iter().map(|n| match n.is_warning() {
            true => format!("  warning: {}", words::note(n)),
            false => format!("  note: {}", words::note(n)),
        }));
        out.extend(self.cleaning.iter().map(|l| format!("  cleaning: {l}")));
        let calibration = d.calibration.lines().into_iter();
        out.extend(calibration.map(|l| format!("  calibration: {l}")));
        let road: Vec<String> = d.road.iter().filter_map(|g| g.line()).collect();
        out.extend(road.iter().take(ROAD_LINES).map(|l| format!("  road: {l}")));
        if road.len() > ROAD_LINES {
            // A long log cut into pieces has a line per piece: the rest
            // are in the JSON report and on the page.
            out.push(format!(
                "  road: … and {} more (every one in the JSON report)",
                crate::format::plural(road.len() - ROAD_LINES, "run", "runs")
            ));
        }
        out.extend(findings(d));
        out
    }
}

/// Runs whose road geometry the terminal lists (a programme's runs); the
/// pieces of a long log beyond are counted.
const ROAD_LINES: usize = 8;

/// The findings: base model, gap, candidates, verdict, shrinkage.
fn findings(d: &Diagnosis) -> Vec<String> {
    let mut out = vec![format!("base model: {}", words::tyre_source(&d.base))];
    let rig = d.base.rig_grouping.iter().flat_map(|g| g.lines());
    out.extend(rig.map(|l| format!("  rig data: {l}")));
    out.push(words::channels_trusted(&d.gap.noise));
    out.push(format!("{}:", words::gap_heading(&d.gap.findings)));
    // A band off in many runs is said once, with its runs counted.
    let bands = words::band_lines(&d.gap.findings, d.gap.runs.len());
    out.extend(
        d.gap
            .findings
            .iter()
            .filter(|f| !matches!(f, GapFinding::Band { .. }))
            .map(|f| format!("  {}", words::finding(f)))
            .chain(bands.into_iter().map(|l| format!("  {l}"))),
    );
    out.extend(words::channel_shares(&d.gap.channel_shares).map(|l| format!("  {l}")));
    out.extend(candidate_lines(d));
    out.extend(verdict_lines(d));
    out
}

/// The candidates' table on held-out runs, then the screened ones.
fn candidate_lines(d: &Diagnosis) -> Vec<String> {
    let mut out = Vec::new();
    out.push(format!(
        "candidates on held-out runs ({} folds; J before {:.3}, noise level {:.3}):",
        d.folds, d.gap.heldout_error, d.gap.noise_level
    ));
    // Tyres from rig data or files are held: what the candidates' standard
    // errors are conditional on (a bias of those tyres moves every value).
    if d.base.axles.is_none() {
        out.push(format!("  ({})", words::TYRES_HELD));
    }
    // Every candidate screened out: no table, which printed as a header
    // without rows.
    if d.ranking.is_empty() && d.combinations.is_empty() {
        out.push(format!("  {}", words::NONE_CROSS_VALIDATED));
        out.extend(screened_lines(d));
        return out;
    }
    let w = effect_width(d);
    out.push(format!("  ({})", words::bic_caveat(&d.gap.findings)));
    out.push(format!(
        "  {:<w$} {:>8} {:>11} {:>10} {:>12}  parameters",
        "effect", "J after", "held out", "in sample", "ΔBIC"
    ));
    for r in d.ranking.iter().chain(d.combinations.iter()) {
        let removes = matches!(d.reductions(r)[0], Reduction::Percent(_));
        let p: Vec<String> = r
            .parameters
            .iter()
            .map(|p| words::parameter_of(p, removes))
            .collect();
        out.push(format!(
            "  {:<w$} {:>8.3} {} {:>12}  {}",
            r.effect,
            r.heldout_error_after,
            reduction_cells(d.reductions(r)),
            crate::format::fixed(r.delta_bic, 0),
            p.join(", ")
        ));
        if let Some(said) = words::rank_warnings(&r.warnings) {
            out.push(format!("  {:<w$} warning: {said}", ""));
        }
    }
    out.extend(screened_lines(d));
    out
}

/// The verdict, what it stands on, its warnings, the confounded sets and
/// the held-out change per channel.
fn verdict_lines(d: &Diagnosis) -> Vec<String> {
    let mut out = Vec::new();
    out.push(format!("verdict: {}", d.verdict.statement()));
    // The verdict's own axles where they were refitted with it (no tyre
    // data): the base's line above is not what the verdict stands on.
    if let Some(a) = d.verdict_row().and_then(|r| r.axles.as_ref()) {
        out.push(format!(
            "  axles fitted with it: {}",
            words::axle_values(a).join(", ")
        ));
    }
    if let Verdict::Explained(e) = &d.verdict {
        out.extend(
            e.evidence
                .iter()
                .map(|x| format!("  {}", words::evidence(x))),
        );
    }
    out.extend(
        words::verdict_warnings(&d.verdict)
            .iter()
            .map(|w| format!("  warning: {w}")),
    );
    out.extend(d.confounded.iter().map(|c| {
        format!(
            "confounded: {} — {}",
            joined(&c.effects, ", "),
            c.separating_runs.as_ref().map_or_else(
                || format!("separate them with {}", words::separating_test(c)),
                |s| s.words()
            )
        )
    }));
    if !d.verdict.effects().is_empty() {
        out.extend(before_after_lines(d));
    }
    out
}

/// The held-out before → after block: each channel's row, and under it
/// the runs the verdict's effects leave significant alone in it
/// ([`runs_left_in`]; the page's section says the same), so that "80 % of
/// the gap above noise removed" does not hide a run left 3.4 floors off.
fn before_after_lines(d: &Diagnosis) -> Vec<String> {
    let mut out = vec![format!(
        "held-out before → after (all held-out samples; each channel alone against {SIGNIFICANT_NOISE_FLOORS} noise floors, the verdict's share is of all channels together):"
    )];
    let left = runs_left_in(&d.shrinkage);
    for s in d.shrinkage.iter().filter(|s| s.part == Part::All) {
        out.push(format!(
            "  {}",
            words::channel_change_judged(s, &d.gap.noise)
        ));
        let said = left
            .iter()
            .find(|c| c.channel == s.channel)
            .and_then(words::runs_left);
        if let Some((head, runs)) = said {
            out.push(format!("    {head}"));
            out.extend(runs.iter().map(|r| format!("      {r}")));
        }
    }
    out
}

/// The held-out and in-sample reduction columns of a ranking row, by the
/// page's rule ([`Diagnosis::reductions`]): within noise, one "not
/// significant" across both, where a percentage would be a share of noise.
fn reduction_cells(r: [Reduction; 2]) -> String {
    match r {
        [Reduction::Percent(h), Reduction::Percent(i)] => {
            format!("{:>9} % {:>8} %", fixed(h, 1), fixed(i, 1))
        }
        [Reduction::WithinNoise, Reduction::WithinNoise] => {
            format!("{:>22}", words::reduction(Reduction::WithinNoise))
        }
        [h, i] => format!("{:>11} {:>10}", words::reduction(h), words::reduction(i)),
    }
}

/// The width of the candidate tables' effect column: 28, or the longest
/// name of a set, so that a long combination keeps the columns aligned.
fn effect_width(d: &Diagnosis) -> usize {
    let ranked = d.ranking.iter().chain(&d.combinations).map(|r| &r.effect);
    let screened = d.screened.iter().map(|s| &s.effect);
    ranked
        .chain(screened)
        .map(|e| e.chars().count())
        .fold(28, usize::max)
}

/// The single effects screened before their cross-validation, and the
/// sets the greedy additions screened, and why.
fn screened_lines(d: &Diagnosis) -> Vec<String> {
    let w = effect_width(d);
    let mut out = Vec::new();
    let singles: Vec<_> = d.screened_singles().collect();
    if let Some(first) = singles.first() {
        out.push(format!(
            "screened, not cross-validated (in sample below {:.0} % − {:.0} points, so below {:.0} % held out):",
            first.threshold_percent, first.margin_percent, first.threshold_percent
        ));
        // No held-out J: the column is the table's held-out one, so the
        // in-sample J is said apart, at the end (one column, one measure).
        out.extend(singles.iter().map(|s| {
            format!(
                "  {:<w$} {:>8} {:>11} {:>8} % {:>12}  J in sample {:.3}",
                s.effect,
                "—",
                "—",
                fixed(s.insample_reduction_percent, 1),
                crate::format::fixed(s.delta_bic, 0),
                s.insample_error_after,
            )
        }));
    }
    let sets: Vec<_> = d
        .screened_sets()
        .filter(|s| s.outranked.is_none())
        .collect();
    if let Some(first) = sets.first() {
        out.push(format!(
            "sets screened, not cross-validated (each removes in sample below {:.0} % − {:.0} points of the gap the set it extends leaves, so none could be added):",
            first.threshold_percent, first.margin_percent
        ));
        out.extend(sets.iter().map(|s| {
            format!(
                "{} (J in sample {:.3})",
                screened_row(s, w),
                s.insample_error_after
            )
        }));
    }
    out.extend(outranked_lines(d, w));
    out
}

/// The sets a greedy step did not cross-validate, its pick being unable to
/// read them: each with its least possible held-out J and the step's best.
fn outranked_lines(d: &Diagnosis, w: usize) -> Vec<String> {
    let sets: Vec<_> = d
        .screened_sets()
        .filter_map(|s| Some((s, s.outranked.as_ref()?)))
        .collect();
    if sets.is_empty() {
        return Vec::new();
    }
    let mut out = vec![format!(
        "sets not cross-validated (in sample plus {:.0} points, their least possible held-out J is beyond what the step's pick reads of its best set):",
        sets[0].0.margin_percent
    )];
    out.extend(sets.iter().map(|(s, o)| {
        format!(
            "{}, held-out J at least {:.3} against {}'s {:.3}",
            screened_row(s, w),
            o.floor,
            joined(&o.by, "+"),
            o.heldout_error,
        )
    }));
    out
}

/// A set not cross-validated as a row of the ranking's table: its name,
/// no held-out figures, its in-sample share of what the set it extends
/// leaves.
fn screened_row(s: &crate::diagnose::report::Screened, w: usize) -> String {
    format!(
        "  {:<w$} {:>8} {:>11} {:>8} % of what {} leaves",
        s.effect,
        "—",
        "—",
        fixed(s.insample_reduction_percent, 1),
        joined(&s.extends, "+"),
    )
}

#[cfg(test)]
#[path = "diagnose_tests.rs"]
mod tests;
