//! `design` as one job: a diagnosis folder in (its `diagnosis.json`, and
//! the campaign it names); the manoeuvres that best separate each
//! confounded set (or the candidates asked for) out ([`crate::design`]):
//! `design.json`, the best manoeuvres as scenario files a user runs with
//! `simulate` and drives on a track (`scenarios/*.toml`, with the base
//! model's tyres beside them), and the candidates' predicted responses to
//! the best one overlaid (`separation.png`). With `--measured` runs driven
//! afterwards, each run's measured separation against the prediction.

use crate::design::{
    compare, design, measured, Design, DesignRequest, Fitted, FittedCandidate, FittedValue,
    Measured, ScreenedOut,
};
use crate::diagnose::campaign::Campaign;
use crate::diagnose::effects::EffectKind;
use crate::diagnose::Channel;
use crate::error::{DesignError, Error, InputError, InputProblem};
use crate::io::campaign::load_campaign;
use crate::io::read_run;
use crate::manoeuvre::Manoeuvre;
use crate::report::plot::{Figure, Panel, Series, Style};
use crate::report::{create_dir, refuse_overwrites, write_bytes, write_json, OutputLock};
use crate::tyre::Tyre;
use serde::{Deserialize, Serialize};
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

/// `diagnosis.json` as the design reads it.
#[derive(Deserialize)]
struct DiagnosisFile {
    source: PathBuf,
    base: BaseFile,
    gap: GapFile,
    ranking: Vec<CandidateFile>,
    combinations: Vec<CandidateFile>,
    confounded: Vec<ConfoundedFile>,
    #[serde(default)]
    screened: Vec<ScreenedFile>,
}

#[derive(Deserialize)]
struct ScreenedFile {
    effects: Vec<String>,
    insample_reduction_percent: f64,
    threshold_percent: f64,
    margin_percent: f64,
}

#[derive(Deserialize)]
struct BaseFile {
    front: Tyre,
    rear: Tyre,
}

#[derive(Deserialize)]
struct GapFile {
    noise: Vec<NoiseFile>,
    noise_level: f64,
}

#[derive(Deserialize)]
struct NoiseFile {
    channel: String,
    noise_floor: f64,
    scale: f64,
}

#[derive(Deserialize)]
struct CandidateFile {
    effects: Vec<String>,
    heldout_error_after: f64,
    parameters: Vec<ParameterFile>,
    axles: Option<Vec<AxleFile>>,
}

#[derive(Deserialize)]
struct ParameterFile {
    name: String,
    value: f64,
    std_error: Option<f64>,
    at_bound: bool,
    determined: bool,
}

#[derive(Deserialize)]
struct AxleFile {
    name: String,
    value: f64,
    std_error: Option<f64>,
    limit: Option<serde_json::Value>,
    held: bool,
}

#[derive(Deserialize)]
struct ConfoundedFile {
    effects: Vec<String>,
}

fn kinds(path: &Path, names: &[String]) -> Result<Vec<EffectKind>, Error> {
    names
        .iter()
        .map(|n| {
            EffectKind::from_name(n).ok_or_else(|| {
                InputError::problem(
                    path,
                    InputProblem::Json {
                        detail: format!("`{n}` is no effect of this release"),
                    },
                )
                .into()
            })
        })
        .collect()
}

fn candidate(path: &Path, c: &CandidateFile) -> Result<FittedCandidate, Error> {
    let nan = |se: Option<f64>| se.unwrap_or(f64::NAN);
    Ok(FittedCandidate {
        effects: kinds(path, &c.effects)?,
        parameters: c
            .parameters
            .iter()
            .map(|p| {
                FittedValue::new(
                    &p.name,
                    p.value,
                    nan(p.std_error),
                    p.determined && !p.at_bound,
                )
            })
            .collect(),
        axles: c.axles.as_ref().map(|a| {
            a.iter()
                .map(|x| {
                    let free = x.limit.as_ref().is_none_or(|l| l.is_null()) && !x.held;
                    FittedValue::new(&x.name, x.value, nan(x.std_error), free)
                })
                .collect()
        }),
        heldout_error: c.heldout_error_after,
    })
}

/// Reads what the design needs of the diagnosis in `dir` and the path of
/// its campaign.
pub fn read_diagnosis(dir: &Path) -> Result<(Fitted, PathBuf), Error> {
    let path = dir.join("diagnosis.json");
    let text = std::fs::read_to_string(&path).map_err(|source| InputError::Io {
        path: path.clone(),
        source,
    })?;
    let f: DiagnosisFile = serde_json::from_str(&text).map_err(|e| {
        InputError::problem_at(
            &path,
            e.line(),
            e.column(),
            InputProblem::Json {
                detail: e.to_string(),
            },
        )
    })?;
    let mut noise_floors = [0.0; 3];
    let mut scales = [1.0; 3];
    for n in &f.gap.noise {
        if let Some(c) = Channel::ALL.into_iter().find(|c| c.name() == n.channel) {
            noise_floors[c.index()] = n.noise_floor;
            scales[c.index()] = n.scale;
        }
    }
    let fitted = Fitted {
        front: f.base.front,
        rear: f.base.rear,
        noise_floors,
        scales,
        noise_level: f.gap.noise_level,
        candidates: f
            .ranking
            .iter()
            .chain(&f.combinations)
            .map(|c| candidate(&path, c))
            .collect::<Result<_, _>>()?,
        confounded: f
            .confounded
            .iter()
            .map(|c| kinds(&path, &c.effects))
            .collect::<Result<_, _>>()?,
        screened: f
            .screened
            .iter()
            .map(|s| {
                Ok(ScreenedOut {
                    effects: kinds(&path, &s.effects)?,
                    insample_reduction_percent: s.insample_reduction_percent,
                    screen_percent: s.threshold_percent - s.margin_percent,
                })
            })
            .collect::<Result<_, Error>>()?,
    };
    Ok((fitted, f.source))
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
    let (fitted, source) = read_diagnosis(dir)?;
    let campaign_path = match campaign {
        Some(p) => p.to_path_buf(),
        None if !source.exists() => {
            return Err(DesignError::CampaignNotFound {
                campaign: source,
                diagnosis: dir.join("diagnosis.json"),
            }
            .into())
        }
        None => source,
    };
    let c = load_campaign(&campaign_path)?;
    let out_dir = out.map_or_else(|| dir.join("design"), Path::to_path_buf);
    let mut inputs = c.inputs.clone();
    inputs.push(dir.join("diagnosis.json"));
    inputs.extend(driven.iter().cloned());
    refuse_overwrites(
        &[out_dir.join("design.json"), out_dir.join("separation.png")],
        &inputs,
    )?;
    let lock = OutputLock::acquire(&out_dir)?;
    let d = design(&c, &fitted, request)?;
    let first: Vec<Vec<EffectKind>> = match &request.sets {
        Some(s) => s[0].clone(),
        None => fitted.confounded[0].iter().map(|e| vec![*e]).collect(),
    };
    let measured = driven
        .iter()
        .map(|p| {
            let run = read_run(p)?;
            let mut m = measured(&c, &fitted, &first, &run)?;
            if let Some(set) = d.sets.first() {
                compare(&mut m, set, &run);
            }
            Ok(m)
        })
        .collect::<Result<Vec<_>, Error>>()?;
    Ok(DesignReport {
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
    })
}

fn vehicle_table(c: &Campaign) -> String {
    toml::to_string(&c.vehicle).unwrap_or_default()
}

/// A number as TOML writes it (always with its decimal point or exponent).
fn num(v: f64) -> String {
    format!("{v:?}")
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
            "# Designed by `handling design {}`: {description}.\n# {separation}\nname = \"{name}\"\n\n[vehicle]\n{}\n[tyres]\nfront = \"tyres/front.toml\"\nrear = \"tyres/rear.toml\"\n\n[road]\nfriction = {}\n\n[model]\nkinematics = \"exact\"\nload_transfer = true\n\n[manoeuvre]\nkind = \"schedule\"\nt = [{}]\nsteer = [{}]\nspeed = [{}]\n",
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
        for set in &self.design.sets {
            for s in &set.ranked {
                let sep = match (s.expected, s.uncertainty) {
                    (Some(e), Some(u)) => format!(
                        "Separates {} by D = {:.1} noise floors; a driven run is expected to measure {e:.1} ± {u:.1}.",
                        set.members.join(" / "),
                        s.separation
                    ),
                    _ => format!("Separates {} by D = {:.1} noise floors.", set.members.join(" / "), s.separation),
                };
                let text = self.scenario_text(&s.name, &s.description, &s.manoeuvre, sep);
                write_bytes(&self.scenario_path(&s.name), text.as_bytes())?;
            }
        }
        self.figure().save(&self.out_dir.join("separation.png"))
    }

    /// The predicted responses of each set's members to its best
    /// manoeuvre, overlaid per measured channel, with its steer and speed.
    pub fn figure(&self) -> Figure {
        let mut panels = Vec::new();
        let colours = [1, 2, 3, 4, 5, 6];
        for set in &self.design.sets {
            let Some(p) = &set.best else { continue };
            for ch in Channel::ALL {
                if !self.design.logging.channels[ch.index()] {
                    continue;
                }
                let series = p
                    .members
                    .iter()
                    .enumerate()
                    .map(|(k, (label, obs))| {
                        let y = crate::diagnose::pipeline::observed_channel(obs, ch);
                        let s = Series::line(label, &p.times, y, colours[k % colours.len()]);
                        // Solid, dashed, dotted: the look-alikes lie on the
                        // reference within a line's width.
                        s.styled([Style::Line, Style::Dashed, Style::Dotted][k.min(2)])
                    })
                    .collect();
                panels.push(Panel {
                    title: format!("{}: {} predicted", p.name, ch.name()),
                    x_label: "t, s".into(),
                    y_label: format!("{}, {}", ch.name(), ch.unit()),
                    series,
                    x_range: None,
                    y_range: None,
                });
            }
            // Where the separation lives: each look-alike minus the
            // reference, in noise floors, per measured channel.
            let floors = &self.design.noise_floors;
            let mut diff = Vec::new();
            for (k, (label, obs)) in p.members.iter().enumerate().skip(1) {
                for ch in Channel::ALL {
                    let i = ch.index();
                    if !self.design.logging.channels[i] || floors[i] <= 0.0 {
                        continue;
                    }
                    let a = crate::diagnose::pipeline::observed_channel(&p.members[0].1, ch);
                    let b = crate::diagnose::pipeline::observed_channel(obs, ch);
                    let d: Vec<f64> = a.iter().zip(b).map(|(x, y)| (y - x) / floors[i]).collect();
                    diff.push(Series::line(
                        &format!("{label} − {}: {}", p.members[0].0, ch.name()),
                        &p.times,
                        &d,
                        1 + (diff.len() + k) % 6,
                    ));
                }
            }
            // One noise floor either way: where a difference leaves the
            // band is where the separation is earned.
            let t_ends = [p.times[0], *p.times.last().unwrap_or(&p.times[0])];
            for (label, y) in [("±1 noise floor", 1.0), ("", -1.0)] {
                diff.push(Series::line(label, &t_ends, &[y, y], 7).styled(Style::Dotted));
            }
            let d = set.ranked.first().map_or(f64::NAN, |s| s.separation);
            panels.push(Panel {
                title: format!(
                    "{}: the look-alikes' responses less the reference's (D = {d:.1})",
                    p.name
                ),
                x_label: "t, s".into(),
                y_label: "difference, noise floors".into(),
                series: diff,
                x_range: None,
                y_range: None,
            });
            let deg: Vec<f64> = p.steer.iter().map(|d| d.to_degrees()).collect();
            panels.push(Panel {
                title: format!("{}: steer and speed", p.name),
                x_label: "t, s".into(),
                y_label: "steer, ° · speed, m/s".into(),
                series: vec![
                    Series::line("steer, °", &p.times, &deg, 7),
                    Series::line("speed, m/s", &p.times, &p.speed, 8).styled(Style::Dashed),
                ],
                x_range: None,
                y_range: None,
            });
        }
        Figure::stack(panels)
    }

    /// What the design found, in lines.
    pub fn summary(&self) -> Vec<String> {
        let l = &self.design.limits;
        let mut out = vec![format!(
            "limits: {:.1}–{:.1} m/s, |ay| ≤ {:.2} m/s² ({:.0} % of the {:.2} reached), steer rate ≤ {:.2} rad/s, |ax| ≤ {:.1} m/s²; {} manoeuvres in the family",
            l.speed.0, l.speed.1, l.ay_max(), 100.0 * l.ay_share, l.ay_reached, l.steer_rate, l.ax, self.design.family
        )];
        for set in &self.design.sets {
            out.push(format!(
                "{}: the campaign's runs separate them by D = {:.1} noise floors",
                set.members.join(" / "),
                set.campaign_separation
            ));
            for (k, s) in set.ranked.iter().enumerate() {
                let expected = match (s.expected, s.uncertainty) {
                    (Some(e), Some(u)) => {
                        format!("; a driven run is expected to measure {e:.1} ± {u:.1}")
                    }
                    _ => String::new(),
                };
                let enough = match s.repetitions {
                    Some(k) => format!(
                        "; the diagnosis tells them apart after {k} such run{}",
                        if k == 1 { "" } else { "s" }
                    ),
                    None if s.expected.is_some() => format!(
                        "; more than {} such runs before the diagnosis tells them apart",
                        crate::design::MAX_REPETITIONS
                    ),
                    None => String::new(),
                };
                out.push(format!(
                    "  {}. {} — D = {:.1}{expected}{enough}: {}",
                    k + 1,
                    s.name,
                    s.separation,
                    s.description
                ));
            }
            if !set.excluded.is_empty() {
                out.push(format!(
                    "  left out: {} beyond the limits or diverged (design.json lists them)",
                    set.excluded.len()
                ));
            }
        }
        for m in &self.measured {
            out.push(format!(
                "measured: {} separates them by {:.1} noise floors and favours {}",
                m.run, m.separation, m.favours
            ));
            out.push(match &m.predicted {
                Some(p) => format!(
                    "  predicted for {}: {:.1} ± {:.1}, measured {:+.1} σ from it{}",
                    p.manoeuvre,
                    p.expected,
                    p.uncertainty,
                    p.deviation,
                    if p.steer_difference > 0.1f64.to_radians() {
                        format!("; its steer departs from the design by up to {:.2}°: not driven as designed", p.steer_difference.to_degrees())
                    } else {
                        String::new()
                    }
                ),
                None => "  no prediction to compare: the design ranks no manoeuvre of this run's file name".into(),
            });
        }
        out.push(format!("wrote {}", self.out_dir.display()));
        out
    }
}
