//! `diagnose --batch`: every campaign of a folder diagnosed (a fleet of logs,
//! a confusion matrix), each written to its own folder as `diagnose` writes
//! it, and one table of the verdict per campaign with the effects that recur
//! across them (`fleet.csv`, `fleet.json`, and `fleet.html` to share). A campaign that cannot be read
//! or diagnosed is listed with its error, not dropped. Sharded like sweeps
//! ([`super::shard`]): shard K of N diagnoses the campaigns with index mod
//! N = K − 1 (in name order) and writes their folders and its table rows;
//! `handling merge` writes the fleet table.

use super::diagnose::{self, DiagnoseReport};
use super::shard::{
    plural, read_shards, write_shard, InputCopy, Shard, ShardFile, ShardJob, ShardReport,
};
use crate::diagnose::effects::{joined, EffectKind};
use crate::error::{
    CampaignFileProblem, Error, InputError, InputProblem, OptionsError, SelectionProblem,
};
use crate::report::{write_csv, write_json, OutputLock};

mod page;
mod rows;
pub use rows::FleetRow;
use rows::{
    confounded_with, distinct_diagnosed, failed_runs, first_of_its_runs, runs_digest,
    runs_folder_of, shared_runs_notes,
};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// An effect across the fleet.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Recurring {
    /// The effect.
    pub effect: EffectKind,
    /// Campaigns whose verdict names it.
    pub verdicts: usize,
    /// Campaigns where it is the best single candidate, none of its
    /// parameters on a bound.
    pub best: usize,
    /// Of the campaigns whose verdict names it, those whose diagnosis
    /// leaves it confounded with another effect: a verdict the runs do not
    /// tell from a look-alike, not a finding to count as settled.
    #[serde(default)]
    pub confounded: usize,
}

/// The fleet report: every campaign's row and the recurring effects.
#[derive(Debug, Clone, Serialize)]
pub struct FleetReport {
    /// One row per campaign, in name order.
    pub campaigns: Vec<FleetRow>,
    /// Effects named by a verdict or best in a campaign, most frequent first.
    pub recurring: Vec<Recurring>,
    /// The output folder.
    #[serde(skip)]
    pub out_dir: PathBuf,
    /// The fleet table's files, held for this run until the report is
    /// dropped (the shards of a job array write their own files beside
    /// them and do not take it).
    #[serde(skip)]
    pub lock: OutputLock,
    /// What the terminal says of the inputs (shard files given twice).
    #[serde(skip)]
    pub notes: Vec<String>,
}

/// The fleet table's files in `out_dir`, held for this run.
fn fleet_lock(out_dir: &Path) -> Result<OutputLock, Error> {
    OutputLock::acquire_outputs(out_dir, "fleet")
}

/// The campaigns of a batch folder: its sub-folders and `.toml` files (the
/// extension in any case, as a runs folder's `.csv`), in name order; and
/// the names of its other entries, skipped (each said: a campaign saved
/// as `.toml.txt` must not vanish from the fleet without a word).
pub fn campaigns(dir: &Path) -> Result<(Vec<PathBuf>, Vec<String>), Error> {
    let entries = std::fs::read_dir(dir).map_err(|source| InputError::Io {
        path: dir.to_path_buf(),
        source,
    })?;
    let is_campaign = |p: &Path| {
        p.is_dir()
            || p.extension()
                .is_some_and(|x| x.eq_ignore_ascii_case("toml"))
    };
    let (mut out, skipped): (Vec<PathBuf>, Vec<PathBuf>) = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .partition(|p| is_campaign(p));
    out.sort();
    let mut skipped: Vec<String> = skipped.iter().map(|p| name_of(p)).collect();
    skipped.sort();
    // A sub-folder holding a campaign file's runs is that campaign's data,
    // not a campaign that fails for want of vehicle.toml.
    let held = runs_holders(&out);
    out.retain(|p| !held.iter().any(|(folder, _)| folder == p));
    skipped.extend(
        held.iter()
            .map(|(folder, by)| format!("{}{RUNS_OF}{by})", name_of(folder))),
    );
    if out.is_empty() {
        return Err(InputError::NoCampaign {
            path: dir.to_path_buf(),
            skipped,
        }
        .into());
    }
    // `z/` and `z.toml` would write one output folder, `z/`.
    let mut stems: Vec<(String, String)> = out.iter().map(|p| (stem_of(p), name_of(p))).collect();
    stems.sort();
    if let Some(w) = stems.windows(2).find(|w| w[0].0 == w[1].0) {
        return Err(InputError::CampaignStemTwice {
            path: dir.to_path_buf(),
            first: w[0].1.clone(),
            second: w[1].1.clone(),
            stem: w[0].0.clone(),
        }
        .into());
    }
    Ok((out, skipped))
}

/// The sub-folders of `entries` without a `vehicle.toml` that hold the
/// runs folder a campaign file of `entries` names (`[runs] dir`), each
/// with that file's name: a batch of `campA.toml` and `dataA/runs` read
/// `dataA` as a second campaign, failed.
fn runs_holders(entries: &[PathBuf]) -> Vec<(PathBuf, String)> {
    let runs: Vec<(PathBuf, String)> = entries
        .iter()
        .filter(|p| p.is_file())
        .filter_map(|p| Some((PathBuf::from(runs_folder_of(p)?), name_of(p))))
        .collect();
    entries
        .iter()
        .filter(|p| p.is_dir() && !p.join("vehicle.toml").is_file())
        .filter_map(|p| {
            let folder = p.canonicalize().ok()?;
            let (_, by) = runs.iter().find(|(r, _)| r.starts_with(&folder))?;
            Some((p.clone(), by.clone()))
        })
        .collect()
}

/// How a skipped runs folder is named in the list of skipped entries:
/// `dataA (the runs of campA.toml)`.
const RUNS_OF: &str = " (the runs of ";

/// The note of a batch folder's entries that are not campaigns (None:
/// every entry is one): those neither a sub-folder nor a `.toml` file,
/// then the sub-folders that hold a campaign file's runs.
fn skipped_note(skipped: &[String]) -> Option<String> {
    let (runs, other): (Vec<&String>, Vec<&String>) =
        skipped.iter().partition(|s| s.contains(RUNS_OF));
    let join = |v: &[&String]| v.iter().map(|s| s.as_str()).collect::<Vec<_>>().join(", ");
    let mut said = Vec::new();
    if !other.is_empty() {
        said.push(format!(
            "{} of the batch folder skipped, not a campaign (neither a sub-folder nor a .toml file): {}",
            plural(other.len(), "entry", "entries"),
            join(&other)
        ));
    }
    if !runs.is_empty() {
        said.push(format!(
            "{} of the batch folder skipped, a campaign file's runs, not a campaign of its own: {}",
            plural(runs.len(), "sub-folder", "sub-folders"),
            join(&runs)
        ));
    }
    (!said.is_empty()).then(|| said.join("; "))
}

/// Refuses a file or a campaign folder given as the batch folder: it
/// would be read as a batch of its own entries, each failing.
fn refuse_one_campaign(dir: &Path) -> Result<(), Error> {
    let problem = if dir.is_file() {
        SelectionProblem::BatchOfAFile {
            path: dir.to_path_buf(),
        }
    } else if dir.join("vehicle.toml").is_file() && dir.join("runs").is_dir() {
        SelectionProblem::BatchOfOneCampaign {
            path: dir.to_path_buf(),
        }
    } else {
        return Ok(());
    };
    Err(selection_error(dir, problem))
}

fn selection_error(path: &Path, problem: SelectionProblem) -> Error {
    let problem = InputProblem::Campaign(Box::new(CampaignFileProblem::Selection(problem)));
    InputError::problem(path, problem).into()
}

fn name_of(p: &Path) -> String {
    p.file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
}

/// A campaign's output folder name: a folder's name, a file's stem
/// (`out/a/`, not `out/a.toml/`, a folder named as a file).
fn stem_of(p: &Path) -> String {
    if p.is_dir() {
        name_of(p)
    } else {
        p.file_stem()
            .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
    }
}

/// Diagnoses every campaign of `dir` (or shard `shard`'s) into
/// `<out>/<campaign>/`; with a shard, writes `<out>/shard-K-of-N.json`,
/// else `fleet.csv` and `fleet.json`. `out` defaults to `out/<folder name>`.
pub fn run_batch(
    dir: &Path,
    out: Option<&Path>,
    shard: Option<Shard>,
) -> Result<(Vec<DiagnoseReport>, BatchOutcome), Error> {
    refuse_one_campaign(dir)?;
    let (all, skipped) = campaigns(dir)?;
    let out_dir = out.map_or_else(
        || PathBuf::from("out").join(name_of(dir)),
        Path::to_path_buf,
    );
    // Without `--shard` the batch writes its fleet table; with one, even
    // 1/1 (a job array of one), a shard file for `handling merge`, as the
    // other sharded jobs do.
    let whole = shard.is_none();
    let shard = shard.unwrap_or(Shard { index: 1, count: 1 });
    let owned = shard.units(all.len());
    let lock = if whole {
        fleet_lock(&out_dir)?
    } else {
        OutputLock::default()
    };
    let mut reports = Vec::new();
    let mut rows = Vec::new();
    for &i in &owned {
        // Named as its output folder is (`carB`, not `carB.toml`).
        let name = stem_of(&all[i]);
        let to = out_dir.join(stem_of(&all[i]));
        let done = diagnose::run(&all[i], Some(&to)).and_then(|r| r.write().map(|()| r));
        match done {
            Ok(r) => {
                let runs_folder = runs_folder_of(&all[i]);
                let runs_digest = runs_folder
                    .as_deref()
                    .and_then(|f| runs_digest(Path::new(f)));
                rows.push(FleetRow {
                    runs_folder,
                    runs_digest,
                    // The folder `diagnose` wrote it to, as the page links it.
                    report: Some(format!("{}/report.html", stem_of(&all[i]))),
                    ..row_of(&name, &r)
                });
                reports.push(r);
            }
            Err(e) => rows.push(failed_row(name, &all[i], &e)),
        }
    }
    if whole {
        let mut report = fleet(rows, out_dir, lock);
        report.notes.extend(skipped_note(&skipped));
        report.write()?;
        return Ok((reports, BatchOutcome::Fleet(report)));
    }
    let outcome = shard_outcome(dir, &all, &out_dir, shard, owned, rows)?;
    Ok((reports, outcome))
}

/// The fleet row of a campaign `name` (at `path`) whose diagnosis failed
/// with `e`, with the runs it kept and the run files it read where known.
fn failed_row(name: String, path: &Path, e: &Error) -> FleetRow {
    let (runs, runs_read) = failed_runs(path, e);
    FleetRow {
        campaign: name,
        name: None,
        runs,
        runs_read,
        verdict: Vec::new(),
        kind: None,
        heldout_error_before: None,
        heldout_error_after: None,
        noise_level: None,
        best: None,
        best_on_bound: false,
        statement: e.to_string(),
        failed: true,
        confounded_with: Vec::new(),
        report: None,
        runs_folder: None,
        runs_digest: None,
    }
}

/// Writes shard `shard`'s file (the campaigns `owned` of `all` in `dir`,
/// their fleet rows `rows`) into `out_dir` for `handling merge`.
fn shard_outcome(
    dir: &Path,
    all: &[PathBuf],
    out_dir: &Path,
    shard: Shard,
    owned: Vec<usize>,
    rows: Vec<FleetRow>,
) -> Result<BatchOutcome, Error> {
    let file = out_dir.join(shard.file_name());
    let names: Vec<String> = all.iter().map(|p| stem_of(p)).collect();
    write_shard(
        &file,
        &ShardFile {
            job: ShardJob::Diagnose,
            shard,
            input: dir.to_path_buf(),
            inputs: vec![InputCopy {
                path: dir.to_path_buf(),
                text: names.join("\n"),
            }],
            units: all.len(),
            owned: owned.clone(),
            results: rows,
        },
    )?;
    Ok(BatchOutcome::Shard(ShardReport {
        job: ShardJob::Diagnose,
        shard,
        units: all.len(),
        owned: owned.len(),
        conditions: owned.len(),
        path: file,
    }))
}

/// What a batch run wrote last: the fleet table, or a shard of it.
#[derive(Debug, Clone)]
pub enum BatchOutcome {
    /// The whole fleet.
    Fleet(FleetReport),
    /// One shard's rows.
    Shard(ShardReport),
}

/// The fleet table of a set of `diagnose --batch --shard` files.
pub fn merge(shards: &[PathBuf], out: Option<&Path>) -> Result<FleetReport, Error> {
    let read = read_shards::<FleetRow>(ShardJob::Diagnose, shards)?;
    let note = read.note();
    let (dir, rows) = (read.input, read.results);
    let (now, skipped) = campaigns(&dir)?;
    let now: Vec<String> = now.iter().map(|p| stem_of(p)).collect();
    let listed: Vec<&String> = rows.iter().map(|r| &r.campaign).collect();
    if now.iter().collect::<Vec<_>>() != listed {
        return Err(OptionsError::CampaignsChanged { path: dir }.into());
    }
    let out_dir = out.map_or_else(
        || PathBuf::from("out").join(name_of(&dir)),
        Path::to_path_buf,
    );
    let lock = fleet_lock(&out_dir)?;
    let mut report = fleet(rows, out_dir, lock);
    report.notes.extend(note);
    report.notes.extend(skipped_note(&skipped));
    report.write()?;
    Ok(report)
}

fn row_of(name: &str, r: &DiagnoseReport) -> FleetRow {
    let d = &r.diagnosis;
    let after = d
        .verdict_row()
        .map_or(d.gap.heldout_error, |c| c.heldout_error_after);
    // A best candidate only where there is a gap and it removes some of it
    // (to the table's 0.1 %).
    let gap = d.verdict.kind() != crate::diagnose::report::VerdictKind::NoSignificantGap;
    let best = d
        .ranking
        .first()
        .filter(|b| gap && b.reduction_percent >= 0.05);
    FleetRow {
        campaign: name.to_string(),
        name: (d.campaign != name).then(|| d.campaign.clone()),
        runs: d.runs.len(),
        runs_read: Some(r.run_files),
        verdict: d.verdict.effects().to_vec(),
        kind: Some(d.verdict.kind()),
        heldout_error_before: Some(d.gap.heldout_error),
        heldout_error_after: Some(after),
        noise_level: Some(d.gap.noise_level),
        best: best.and_then(|b| Some((*b.effects.first()?, b.reduction_percent))),
        best_on_bound: best.is_some_and(|b| b.parameters.iter().any(|p| p.at_bound)),
        statement: d.verdict.statement(),
        failed: false,
        confounded_with: confounded_with(d.verdict.effects(), &d.confounded),
        report: None,
        runs_folder: None,
        runs_digest: None,
    }
}

impl Recurring {
    /// How many of the verdicts naming it are confounded, in words after
    /// their count (nothing where none is).
    pub fn confounded_words(&self) -> String {
        match self.confounded {
            0 => String::new(),
            1 if self.verdicts == 1 => " (confounded with another effect)".to_string(),
            c if c == self.verdicts => " (each confounded with another effect)".to_string(),
            c => format!(" ({c} of them confounded with another effect)"),
        }
    }
}

/// The report of the rows: the effects that recur, most verdicts first.
fn fleet(campaigns: Vec<FleetRow>, out_dir: PathBuf, lock: OutputLock) -> FleetReport {
    // Campaigns reading the same run files count once.
    let distinct: Vec<&FleetRow> = (0..campaigns.len())
        .filter(|&i| first_of_its_runs(&campaigns, i))
        .map(|i| &campaigns[i])
        .collect();
    let recurring = EffectKind::ALL
        .into_iter()
        .map(|effect| Recurring {
            effect,
            verdicts: distinct
                .iter()
                .filter(|r| r.verdict.contains(&effect))
                .count(),
            best: distinct
                .iter()
                .filter(|r| !r.best_on_bound && r.best.is_some_and(|b| b.0 == effect))
                .count(),
            confounded: distinct
                .iter()
                .filter(|r| r.verdict.contains(&effect) && !r.confounded_with.is_empty())
                .count(),
        })
        .filter(|r| r.verdicts + r.best > 0)
        .collect::<Vec<_>>();
    let mut recurring = recurring;
    recurring.sort_by_key(|r| std::cmp::Reverse((r.verdicts, r.best)));
    FleetReport {
        campaigns,
        recurring,
        out_dir,
        lock,
        notes: Vec::new(),
    }
}

impl FleetReport {
    /// `fleet.csv`, `fleet.json` and `fleet.html` in the output folder.
    pub fn outputs(&self) -> [PathBuf; 3] {
        ["fleet.csv", "fleet.json", "fleet.html"].map(|f| self.out_dir.join(f))
    }

    /// Writes the table, the report and the page to share.
    pub fn write(&self) -> Result<(), Error> {
        let [csv, json, html] = self.outputs();
        let number = |v: Option<f64>| v.map_or_else(String::new, |v| format!("{v:.6}"));
        write_csv(
            &csv,
            &[
                "campaign",
                "runs",
                "runs_read",
                "verdict",
                "confounded_with",
                "heldout_error_before",
                "heldout_error_after",
                "noise_level",
                "best",
                "best_reduction_percent",
                "failed",
                "statement",
                "kind",
                "name",
            ],
            self.campaigns.iter().map(|r| {
                vec![
                    r.campaign.clone(),
                    r.runs.to_string(),
                    r.runs_read.map_or_else(String::new, |n| n.to_string()),
                    joined(&r.verdict, "+"),
                    joined(&r.confounded_with, "+"),
                    number(r.heldout_error_before),
                    number(r.heldout_error_after),
                    number(r.noise_level),
                    r.best.map_or_else(String::new, |b| b.0.name().to_string()),
                    r.best.map_or_else(String::new, |b| format!("{:.1}", b.1)),
                    r.failed.to_string(),
                    r.statement.clone(),
                    r.kind.map_or_else(String::new, |k| k.name().to_string()),
                    // The campaign's own name (its file's `name`), the
                    // name its report says; none for one that failed.
                    match (&r.name, r.failed) {
                        (_, true) => String::new(),
                        (Some(name), false) => name.clone(),
                        (None, false) => r.campaign.clone(),
                    },
                ]
            }),
        )?;
        write_json(&json, self)?;
        self.page().write("Fleet diagnosis", &html)
    }

    /// The campaigns diagnosed (not failed).
    pub fn diagnosed(&self) -> usize {
        self.campaigns.iter().filter(|r| !r.failed).count()
    }

    /// The error of batch folder `batch` when none of its campaigns was
    /// diagnosed (after its table, which lists why, is written): a run
    /// that diagnosed nothing does not end as a success.
    pub fn all_failed(&self, batch: &Path) -> Option<Error> {
        (self.diagnosed() == 0).then(|| {
            let problem = SelectionProblem::BatchAllFailed {
                count: self.campaigns.len(),
                table: self.outputs()[0].clone(),
            };
            selection_error(batch, problem)
        })
    }

    /// The table in lines of text.
    pub fn summary(&self) -> Vec<String> {
        let (n, diagnosed) = (self.campaigns.len(), self.diagnosed());
        let failed = match n - diagnosed {
            0 => String::new(),
            1 => ", 1 failed (its reason below)".into(),
            f => format!(", {f} failed (each one's reason below)"),
        };
        let mut out = vec![format!(
            "fleet: {diagnosed} of {} diagnosed{failed}",
            plural(n, "campaign", "campaigns")
        )];
        for r in &self.campaigns {
            out.push(if r.failed {
                format!("  {:<24} FAILED: {}", r.label(), r.statement)
            } else {
                format!(
                    "  {:<24} {:<32} J {:.3} → {:.3} (noise {:.3})",
                    r.label(),
                    r.verdict_or_kind_words("+"),
                    r.heldout_error_before.unwrap_or(f64::NAN),
                    r.heldout_error_after.unwrap_or(f64::NAN),
                    r.noise_level.unwrap_or(f64::NAN)
                )
            });
        }
        // Out of the campaigns diagnosed: a failed one has no verdict; of
        // those reading the same run files, one.
        out.extend(self.notes.iter().map(|n| format!("  note: {n}")));
        out.extend(shared_runs_notes(&self.campaigns));
        let n = distinct_diagnosed(&self.campaigns);
        for e in &self.recurring {
            out.push(format!(
                "  {}: in the verdict of {} of {n} diagnosed campaigns{}, the best single candidate in {} of {n}",
                e.effect.name(),
                e.verdicts,
                e.confounded_words(),
                e.best
            ));
        }
        out
    }
}
