//! `design` as one job: a diagnosis folder in (its `diagnosis.json`, and
//! the campaign it names); the manoeuvres that best separate each
//! confounded set (or the candidates asked for) out ([`crate::design`]):
//! `design.json`, the best manoeuvres as scenario files a user runs with
//! `simulate` and drives on a track (`scenarios/*.toml`, with the base
//! model's tyres beside them), and the candidates' predicted responses to
//! the best one overlaid (`separation.png`). With `--measured` runs driven
//! afterwards, each run's measured separation against the prediction.

mod diagnosis_file;
mod figure;
mod summary;

pub use diagnosis_file::{read_diagnosis, Diagnosed};

use crate::design::{
    compare, design, measured, Design, DesignRequest, FittedOn, Measured, SameRun,
};
use crate::diagnose::campaign::Campaign;
use crate::diagnose::effects::EffectKind;
use crate::error::{DesignError, Error, OutputError, WriteStep};
use crate::io::campaign::load_campaign;
use crate::io::read_run;
use crate::manoeuvre::Manoeuvre;
use crate::report::{create_dir, refuse_overwrites, write_bytes, write_json, OutputLock};
use crate::tyre::Tyre;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// The report of `design`.
#[derive(Debug, Clone, Serialize)]
pub struct DesignReport {
    /// The diagnosis read.
    pub diagnosis: PathBuf,
    /// Its campaign.
    pub campaign: PathBuf,
    /// The design.
    #[serde(flatten)]
    pub design: Design,
    /// The runs driven afterwards, measured against the first set.
    pub measured: Vec<Measured>,
    /// Scenario files of an earlier design in the output folder, removed
    /// on writing.
    pub stale: Vec<PathBuf>,
    /// The output folder.
    #[serde(skip)]
    pub out_dir: PathBuf,
    /// The base tyres and the vehicle, for the scenario files.
    #[serde(skip)]
    scenario: ScenarioParts,
    /// The output folder, held until the report is dropped.
    #[serde(skip)]
    pub lock: OutputLock,
}

#[derive(Debug, Clone)]
struct ScenarioParts {
    vehicle: String,
    front: Tyre,
    rear: Tyre,
    friction: f64,
}

/// Refuses a driven run whose steer its yaw rate contradicts (a yaw rate
/// in the other sign convention, a steer in degrees), by the rule
/// `diagnose` and `metrics` refuse one
/// ([`crate::metrics::measured::steer_problem`], the campaign's wheelbase):
/// measured against the candidates, a negated yaw rate reads as a
/// separation favouring whichever fits it worse, not as a unit slip.
fn steer_against_yaw(c: &Campaign, run: &crate::measured::MeasuredRun) -> Result<(), Error> {
    use crate::metrics::measured::{steer_problem, yaw_per_neutral, Wheelbase};
    let l = c.vehicle.wheelbase();
    let problem = yaw_per_neutral(run, l, c.settings.min_speed)
        .and_then(|y| steer_problem(&y, Wheelbase::Known(l)));
    match problem {
        Some(p) => Err(crate::error::InputError::problem(&run.path, p).into()),
        None => Ok(()),
    }
}

/// The campaign's own run file that the driven run `path` is: the same
/// file, else one byte for byte the same (a copy); None for a new run.
/// The candidates were fitted to the campaign's runs, so one of them
/// measured again is no new evidence between them.
fn fitted_on(c: &Campaign, path: &Path) -> Option<FittedOn> {
    let mut files: Vec<&Path> = c.runs.iter().map(|r| r.path.as_path()).collect();
    files.dedup();
    let canonical = |p: &Path| std::fs::canonicalize(p).ok();
    let same = |by: SameRun, f: &&Path| FittedOn {
        run: f.display().to_string(),
        by,
    };
    let this = canonical(path);
    if let Some(f) = files
        .iter()
        .find(|f| this.is_some() && canonical(f) == this)
    {
        return Some(same(SameRun::Path, f));
    }
    let bytes = std::fs::read(path).ok()?;
    files
        .iter()
        .find(|f| std::fs::read(f).is_ok_and(|b| b == bytes))
        .map(|f| same(SameRun::Content, f))
}

/// Designs for the diagnosis in `dir` (its campaign at `campaign`, else
/// where the diagnosis read it), measures the runs `driven` against the
/// first set, for the output folder `out` (default `<dir>/design`).
pub fn run(
    dir: &Path,
    campaign: Option<&Path>,
    request: &DesignRequest,
    driven: &[PathBuf],
    out: Option<&Path>,
) -> Result<DesignReport, Error> {
    request.validate()?;
    let (fitted, diagnosed) = read_diagnosis(dir)?;
    let runs = &diagnosed.runs;
    let campaign_path = match campaign {
        Some(p) => p.to_path_buf(),
        None => diagnosed_campaign(&diagnosed, dir)?,
    };
    let c = load_campaign(&campaign_path)?;
    same_runs(&c, &campaign_path, runs, &dir.join("diagnosis.json"))?;
    let out_dir = out.map_or_else(|| dir.join("design"), Path::to_path_buf);
    let mut inputs = c.inputs.clone();
    inputs.push(dir.join("diagnosis.json"));
    inputs.extend(driven.iter().cloned());
    refuse_overwrites(
        &[out_dir.join("design.json"), out_dir.join("separation.png")],
        &inputs,
    )?;
    let lock = OutputLock::acquire(&out_dir)?;
    // A run driven from any manoeuvre of the family, not only the best,
    // is compared with its prediction.
    let request = DesignRequest {
        also: driven
            .iter()
            .filter_map(|p| p.file_stem())
            .map(|s| s.to_string_lossy().into_owned())
            .collect(),
        ..request.clone()
    };
    let d = design(&c, &fitted, &request)?;
    let first: Vec<Vec<EffectKind>> = match &request.sets {
        Some(s) => s[0].clone(),
        None => fitted.confounded[0].iter().map(|e| vec![*e]).collect(),
    };
    let measured = driven
        .iter()
        .map(|p| {
            let run = read_run(p)?;
            steer_against_yaw(&c, &run)?;
            let mut m = measured(&c, &fitted, &first, &run)?;
            m.fitted_on = fitted_on(&c, p);
            if let Some(set) = d.sets.first() {
                compare(&mut m, set, &run, &d.logging);
            }
            Ok(m)
        })
        .collect::<Result<Vec<_>, Error>>()?;
    let mut report = DesignReport {
        diagnosis: dir.to_path_buf(),
        campaign: campaign_path,
        design: d,
        measured,
        out_dir,
        scenario: ScenarioParts {
            vehicle: vehicle_table(&c),
            front: fitted.front.clone(),
            rear: fitted.rear.clone(),
            friction: c.friction,
        },
        lock,
        stale: Vec::new(),
    };
    report.stale = report.stale_scenarios();
    Ok(report)
}

/// Ok when campaign `c` (read from `path`) holds every run the diagnosis
/// read (`runs`, by file name): a design replays the candidates as fitted
/// to those runs, and its limits are theirs.
/// The campaign the diagnosis in `dir` read: its path as given where that
/// is found from here (relative paths are read from where `diagnose` ran),
/// else its absolute path as written then.
fn diagnosed_campaign(d: &Diagnosed, dir: &Path) -> Result<PathBuf, Error> {
    match &d.source_absolute {
        _ if d.source.exists() => Ok(d.source.clone()),
        Some(a) if a.exists() => Ok(a.clone()),
        _ => Err(DesignError::CampaignNotFound {
            campaign: d.source.clone(),
            absolute: d.source_absolute.clone(),
            diagnosis: dir.join("diagnosis.json"),
        }
        .into()),
    }
}

fn same_runs(c: &Campaign, path: &Path, runs: &[PathBuf], diagnosis: &Path) -> Result<(), Error> {
    let have: std::collections::HashSet<_> =
        c.runs.iter().filter_map(|r| r.path.file_name()).collect();
    let missing: Vec<String> = runs
        .iter()
        .filter_map(|r| r.file_name())
        .filter(|n| !have.contains(n))
        .map(|n| n.to_string_lossy().into_owned())
        .collect();
    match missing.first() {
        None => Ok(()),
        Some(run) => Err(DesignError::OtherCampaign {
            campaign: path.to_path_buf(),
            diagnosis: diagnosis.to_path_buf(),
            run: run.clone(),
            missing: missing.len(),
            diagnosed: runs.len(),
        }
        .into()),
    }
}

fn vehicle_table(c: &Campaign) -> String {
    toml::to_string(&c.vehicle).unwrap_or_default()
}

/// How every scenario file a design writes begins.
const DESIGNED_HEADER: &str = "# Designed by `handling design ";

/// A number of a designed schedule as TOML reads it back (always with its
/// decimal point or exponent), to the nine significant digits a schedule
/// carries ([`crate::format::carried`]): its breakpoints are a search's
/// arithmetic, `20.899999998637263` is 20.9 m/s.
fn num(v: f64) -> String {
    let s = crate::format::carried(v, 9);
    if s.contains(['.', 'e', 'E']) || !v.is_finite() {
        s
    } else {
        s + ".0"
    }
}

fn list(v: &[f64]) -> String {
    v.iter().map(|x| num(*x)).collect::<Vec<_>>().join(", ")
}

impl DesignReport {
    /// The scenario file of manoeuvre `name` (`description` in its
    /// comment).
    fn scenario_text(
        &self,
        name: &str,
        description: &str,
        m: &Manoeuvre,
        separation: String,
    ) -> String {
        let Manoeuvre::Replay(r) = m else {
            unreachable!("the family is made of schedules")
        };
        format!(
            "{DESIGNED_HEADER}{}`: {description}.\n# {separation}\nname = \"{name}\"\n\n[vehicle]\n{}\n[tyres]\nfront = \"tyres/front.toml\"\nrear = \"tyres/rear.toml\"\n\n[road]\nfriction = {}\n\n[model]\nkinematics = \"exact\"\nload_transfer = true\n\n[manoeuvre]\nkind = \"schedule\"\nt = [{}]\nsteer = [{}]\nspeed = [{}]\n",
            self.diagnosis.display(),
            self.scenario.vehicle,
            num(self.scenario.friction),
            list(&r.t),
            list(&r.steer),
            list(&r.speed),
        )
    }

    /// The files written.
    pub fn outputs(&self) -> Vec<PathBuf> {
        let mut v = vec![
            self.out_dir.join("design.json"),
            self.out_dir.join("separation.png"),
        ];
        v.push(self.out_dir.join("scenarios/tyres/front.toml"));
        v.push(self.out_dir.join("scenarios/tyres/rear.toml"));
        for set in &self.design.sets {
            for s in &set.ranked {
                v.push(self.scenario_path(&s.name));
            }
        }
        v
    }

    /// The scenario files an earlier design wrote into this folder that
    /// this one does not write (they start with its header): a folder
    /// reused for another design would otherwise offer manoeuvres of the
    /// old one beside the new. [`DesignReport::write`] removes them.
    fn stale_scenarios(&self) -> Vec<PathBuf> {
        let keep = self.outputs();
        let Ok(entries) = std::fs::read_dir(self.out_dir.join("scenarios")) else {
            return Vec::new();
        };
        let mut stale: Vec<PathBuf> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| {
                p.extension().is_some_and(|x| x == "toml")
                    && !keep.contains(p)
                    && std::fs::read_to_string(p).is_ok_and(|t| t.starts_with(DESIGNED_HEADER))
            })
            .collect();
        stale.sort();
        stale
    }

    fn scenario_path(&self, name: &str) -> PathBuf {
        self.out_dir.join("scenarios").join(format!("{name}.toml"))
    }

    /// Writes `design.json`, the scenario files, the tyres and the figure.
    pub fn write(&self) -> Result<(), Error> {
        create_dir(&self.out_dir.join("scenarios/tyres"))?;
        write_json(&self.out_dir.join("design.json"), self)?;
        for (tyre, file) in [
            (&self.scenario.front, "front"),
            (&self.scenario.rear, "rear"),
        ] {
            let path = self.out_dir.join(format!("scenarios/tyres/{file}.toml"));
            let text = toml::to_string(tyre).map_err(|e| crate::error::OutputError::Tyre {
                path: path.clone(),
                source: e,
            })?;
            let header = "# The base model's tyre as the diagnosis identified it.\n";
            write_bytes(&path, format!("{header}{text}").as_bytes())?;
        }
        for path in &self.stale {
            std::fs::remove_file(path)
                .map_err(|e| OutputError::io(path, WriteStep::RemoveStale, e))?;
        }
        for set in &self.design.sets {
            for s in &set.ranked {
                let sep = match (s.expected, s.uncertainty) {
                    (Some(e), Some(u)) => format!(
                        "Separates {} by D = {:.1} noise floors; a driven run is expected to measure {e:.1} ± {u:.1}{}.",
                        set.members.join(" / "),
                        s.separation,
                        match s.worth {
                            _ if s.weak().is_some() => "; weak: within 2 of its own uncertainty, one run may show no separation or favour the wrong candidate",
                            Some(crate::design::Worth::Separates) | None => "",
                            Some(crate::design::Worth::WithinUncertainty) => "; not recommended: within its own uncertainty",
                            Some(crate::design::Worth::BelowCampaign) => "; not recommended: less than the campaign's runs separate them by",
                            Some(crate::design::Worth::AlreadyToldApart) => "; not needed: the diagnosis already tells them apart",
                        }
                    ),
                    _ => format!("Separates {} by D = {:.1} noise floors.", set.members.join(" / "), s.separation),
                };
                let text = self.scenario_text(&s.name, &s.description, &s.manoeuvre, sep);
                write_bytes(&self.scenario_path(&s.name), text.as_bytes())?;
            }
        }
        figure::figure(&self.design).save(&self.out_dir.join("separation.png"))
    }
}
