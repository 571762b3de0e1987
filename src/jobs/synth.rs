//! `synth` as one job: the virtual proving ground ([`crate::proving_ground`])
//! writes a campaign folder (`vehicle.toml`, `tyre_rig.csv`, `runs/*.csv`)
//! measured on a truth model with chosen effects on. The folder is written
//! under a temporary name and renamed when complete, so a failed run leaves
//! no half-written campaign, and an existing folder is never written over.

use crate::diagnose::effects::EffectKind;
use crate::error::{Error, NameKind, NoneWithEffects, OptionsError, OutputError, WriteStep};
use crate::measured::MeasuredRun;
use crate::proving_ground::{
    check_duration, drive, generate_lasting, DrivenRun, Noise, Programme, SynthSpec, Synthetic,
    Truth,
};
use crate::report::{create_dir, write_bytes, write_columns};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// An effect named on the command line: a candidate effect, or `none`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct EffectName(pub Option<EffectKind>);

impl std::str::FromStr for EffectName {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self, Error> {
        if s == "none" {
            return Ok(EffectName(None));
        }
        EffectKind::from_name(s)
            .map(|k| EffectName(Some(k)))
            .ok_or_else(|| {
                let names = EffectKind::ALL.iter().map(|k| k.name());
                Error::Options(OptionsError::UnknownName {
                    what: NameKind::Effect,
                    given: s.to_string(),
                    known: std::iter::once("none").chain(names).collect(),
                })
            })
    }
}

/// The truth named `name` (`augmented` or `four-wheel`).
pub fn truth_named(name: &str) -> Result<Truth, Error> {
    Truth::from_name(name).ok_or_else(|| {
        Error::Options(OptionsError::UnknownName {
            what: NameKind::Truth,
            given: name.to_string(),
            known: Truth::ALL.iter().map(|t| t.name()).collect(),
        })
    })
}

/// The report of `synth`: the campaign generated (written by
/// [`SynthReport::write`]).
#[derive(Debug, Clone, Serialize)]
pub struct SynthReport {
    /// The campaign folder.
    pub out: PathBuf,
    /// Runs generated.
    pub runs: usize,
    /// The model that played the car.
    pub truth: Truth,
    /// What the driver did.
    pub programme: Programme,
    /// The effects on, in words.
    pub name: String,
    /// Noise seed.
    pub seed: u64,
    /// Of the runs, those driven from scenario files (`--drive`).
    pub driven: usize,
    /// What the driven runs leave out of a replayed run (its `bank` or
    /// `ax` where the programme logs none).
    pub notes: Vec<String>,
    /// The campaign.
    #[serde(skip)]
    pub campaign: Synthetic,
}

/// Generates a campaign of `programme` on `truth` with `effects` on and
/// noise seed `seed`, for the new folder `out`; an analogue programme's
/// runs lengthened to `duration` s together where given.
pub fn run(
    effects: &[EffectName],
    seed: u64,
    truth: Truth,
    programme: Programme,
    duration: Option<f64>,
    out: &Path,
) -> Result<SynthReport, Error> {
    if let Some(given) = duration {
        check_duration(programme, given)?;
    }
    let kinds = effects.iter().filter_map(|e| e.0);
    if effects.iter().any(|e| e.0.is_none()) && kinds.clone().next().is_some() {
        let with = kinds.map(|k| k.name()).collect();
        return Err(OptionsError::NoneWithEffects(NoneWithEffects { with }).into());
    }
    let mut spec = SynthSpec {
        effects: Vec::new(),
        seed,
        noise: Noise::default(),
        programme,
    };
    // Before the effects: a truth that cannot drive the programme has none.
    truth.drives(programme)?;
    for k in kinds {
        if spec.effects.iter().any(|(e, _)| *e == k) {
            return Err(OptionsError::EffectTwice { effect: k.name() }.into());
        }
        let values = truth.values(programme, k).ok_or_else(|| {
            Error::Options(OptionsError::EffectNotShown {
                effect: k.name(),
                truth: truth.name(),
                programme: programme.name(),
                known: truth.effects(programme).iter().map(|k| k.name()).collect(),
            })
        })?;
        spec.effects.push((k, values));
    }
    if out.exists() {
        return Err(OutputError::CampaignExists {
            path: out.to_path_buf(),
        }
        .into());
    }
    let s = generate_lasting(&spec, truth, duration)?;
    Ok(SynthReport {
        driven: 0,
        notes: Vec::new(),
        out: out.to_path_buf(),
        runs: s.runs.len(),
        truth,
        programme,
        name: s.name(),
        seed,
        campaign: s,
    })
}

impl SynthReport {
    /// Adds the runs the truth logs driving the manoeuvres of the scenario
    /// files `drives` (their vehicle, tyres and road are the scenario's
    /// own and not used: the truth plays the car): each run is named after
    /// its file and logged as the programme logs, with its own noise.
    pub fn drive(&mut self, drives: &[PathBuf]) -> Result<(), Error> {
        if drives.is_empty() {
            return Ok(());
        }
        let mut runs = Vec::new();
        for p in drives {
            let sc = crate::io::load_scenario(p)?;
            let name = p
                .file_stem()
                .map_or("driven".into(), |s| s.to_string_lossy().into_owned());
            let taken = |r: &MeasuredRun| r.path == Path::new(&format!("{name}.csv"));
            let programme = self.campaign.runs.iter().any(taken);
            if programme || runs.iter().any(|r: &DrivenRun| r.name == name) {
                return Err(OptionsError::DriveName {
                    path: p.clone(),
                    name,
                    programme,
                }
                .into());
            }
            self.notes.extend(unused_road(p, &sc));
            self.notes.extend(crate::proving_ground::dropped_channels(
                self.programme,
                p,
                &sc.manoeuvre,
            ));
            runs.push(DrivenRun {
                name,
                manoeuvre: sc.manoeuvre,
            });
        }
        let driven = drive(self.campaign.spec(), self.truth, &runs)?;
        self.driven += driven.len();
        self.runs += driven.len();
        self.campaign.runs.extend(driven);
        Ok(())
    }

    /// Writes the campaign folder: into a sibling temporary folder, renamed
    /// when complete.
    pub fn write(&self) -> Result<(), Error> {
        let out = &self.out;
        let parent = out
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        create_dir(parent)?;
        let name = out
            .file_name()
            .map_or("campaign".into(), |n| n.to_string_lossy().into_owned());
        let tmp = parent.join(format!(".{name}.synth-{}", std::process::id()));
        if let Err(e) = write_campaign(&self.campaign, &tmp) {
            let _ = std::fs::remove_dir_all(&tmp);
            return Err(e);
        }
        std::fs::rename(&tmp, out).map_err(|e| OutputError::io(out, WriteStep::Create, e).into())
    }

    /// The closing line.
    pub fn wrote(&self) -> String {
        format!(
            "wrote {} ({} {} runs{}, {}, {} truth with {}, noise seed {}); diagnose it with `handling diagnose {}`",
            self.out.display(),
            self.runs,
            self.programme.name(),
            if self.driven > 0 { format!(", {} of them driven from scenario files", self.driven) } else { String::new() },
            if self.campaign.rig.is_empty() { "no rig data" } else { "rig data" },
            self.truth.name(),
            self.name,
            self.seed,
            self.out.display()
        )
    }
}

/// What of the road of the scenario `sc` (file `path`) a driven run does
/// not use: the truth drives the programme's road with its own grip (flat
/// but for a replay's logged bank), as it drives the programme's runs;
/// only the manoeuvre is driven. Said where the scenario gives another, which was dropped
/// without a word.
fn unused_road(path: &Path, sc: &crate::io::Scenario) -> Vec<String> {
    use crate::error::Num;
    let friction = sc.integrator.friction;
    let bank = sc.model.options.effects.road_bank;
    let mut given = Vec::new();
    if friction != 1.0 {
        given.push(format!("friction {} (`[road] friction`)", Num(friction)));
    }
    if bank != 0.0 {
        given.push(format!("bank {} rad (`road_bank`)", Num(bank)));
    }
    if given.is_empty() {
        return Vec::new();
    }
    vec![format!(
        "{}: the scenario's road, {}, is not used: the truth drives the manoeuvre on the programme's road, as it drives the programme's runs (its grip the truth's own, flat but for a replay's logged bank): only the scenario's manoeuvre is taken",
        path.display(),
        given.join(" and ")
    )]
}

/// The campaign's files in `dir`.
fn write_campaign(s: &Synthetic, dir: &Path) -> Result<(), Error> {
    create_dir(&dir.join("runs"))?;
    write_bytes(&dir.join("vehicle.toml"), s.vehicle_toml().as_bytes())?;
    // A programme without rig data (the slow oval) writes no rig file.
    if !s.rig.is_empty() {
        let [fz, alpha, fy] = s.rig_columns();
        write_columns(
            &dir.join("tyre_rig.csv"),
            &[("fz", &fz), ("alpha", &alpha), ("fy", &fy)],
        )?;
    }
    for r in &s.runs {
        let mut cols: Vec<(&str, &[f64])> = vec![
            ("t", &r.t),
            ("speed", &r.speed),
            ("steer", &r.steer),
            ("yaw_rate", &r.yaw_rate),
        ];
        for (name, v) in [
            ("ay", &r.ay),
            ("ax", &r.ax),
            ("bank", &r.bank),
            ("beta", &r.beta),
        ] {
            if let Some(v) = v {
                cols.push((name, v));
            }
        }
        write_columns(&dir.join("runs").join(&r.path), &cols)?;
    }
    Ok(())
}
