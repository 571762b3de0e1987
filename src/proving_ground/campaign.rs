//! A generated campaign as the diagnosis reads it: in memory
//! ([`Synthetic::campaign`]: the logged programmes' runs cleaned and cut as
//! `diagnose` cleans and cuts runs read from files, the rig data fitted
//! with PAC89) and as the files of the folder `handling synth` writes (its
//! `vehicle.toml`, the rig data's columns). Units: SI, rad.

use super::analogues::truth_lines;
use super::programme::truth_downforce;
use super::truth::Truth;
use super::Synthetic;
use crate::diagnose::campaign::{BaseTyres, Campaign, DiagnoseSettings};
use crate::diagnose::effects::{EffectKind, RollModel};
use crate::identify::data::RigData;
use crate::measured::calibration::calibrate;
use crate::measured::clean::{clean_runs, segments, CleanSettings};
use crate::tyre::ModelName;
use std::path::PathBuf;

impl Synthetic {
    /// The rig data as columns (fz, alpha, fy).
    pub(crate) fn rig_columns(&self) -> [Vec<f64>; 3] {
        [0, 1, 2].map(|j| self.rig.iter().map(|r| r[j]).collect())
    }

    /// The rig data, as a campaign file would hold them.
    fn rig_data(&self) -> RigData {
        let [fz, alpha, fy] = self.rig_columns();
        RigData {
            camber: vec![0.0; fz.len()],
            fz,
            alpha,
            fy,
            ..RigData::default()
        }
    }

    /// The campaign in memory, diagnosed against `effects`: its rig data
    /// fitted with PAC89, as the folder `handling synth` writes says. The
    /// logged programmes' runs are cleaned as `diagnose` cleans runs read
    /// from files (the oval's standstill is left out); the handling
    /// programme's runs are moving and clean throughout and go in as
    /// generated. Every programme's runs are calibrated as generated, before
    /// any cleaning, as `diagnose` calibrates runs read from files.
    pub fn campaign(&self, effects: Vec<EffectKind>, settings: DiagnoseSettings) -> Campaign {
        let source = PathBuf::from(format!("synthetic campaign {}", self.name()));
        let calibration = calibrate(&self.runs);
        let (runs, cleaning) = if self.spec.programme.logged() {
            clean_runs(
                self.runs.clone(),
                &CleanSettings::diagnosis(settings.min_speed),
            )
        } else {
            (self.runs.clone(), Default::default())
        };
        // The slow oval's pieces cut as its `[runs] segment` cuts them,
        // replayed at the step its `[diagnose]` states.
        let mut settings = settings;
        if let Some(h) = self.spec.programme.replay_step() {
            settings.step = h;
        }
        let runs = match self.spec.programme.segment() {
            Some(length) => runs.into_iter().flat_map(|r| segments(r, length)).collect(),
            None => runs,
        };
        let tyres = if self.spec.programme.has_rig() {
            BaseTyres::Rig {
                path: source.join("tyre_rig.csv"),
                data: Box::new(self.rig_data()),
                model: ModelName::Pac89,
            }
        } else {
            BaseTyres::FromRuns
        };
        Campaign {
            name: self.name(),
            inputs: Vec::new(),
            runs_folder: None,
            vehicle: self.vehicle.clone(),
            friction: 1.0,
            friction_at: None,
            tyres,
            prior: Default::default(),
            uncertainty: Default::default(),
            sensors: Default::default(),
            source,
            run_files: self.runs.len(),
            runs,
            roll: self.roll,
            roll_gradient_at: None,
            settings,
            effects,
            notes: Vec::new(),
            cleaning,
            calibration,
        }
    }

    /// A name from the effects switched on.
    pub fn name(&self) -> String {
        if self.spec.effects.is_empty() {
            "none".into()
        } else {
            self.spec
                .effects
                .iter()
                .map(|(k, _)| k.name())
                .collect::<Vec<_>>()
                .join("+")
        }
    }

    /// The campaign folder's `vehicle.toml`.
    pub(crate) fn vehicle_toml(&self) -> String {
        let v = &self.vehicle;
        let truth: Vec<String> = self
            .spec
            .effects
            .iter()
            .map(|(k, p)| format!("#   {} = {:?}", k.name(), p))
            .collect();
        let (model, roll) = self.truth_and_roll();
        let [front, rear] = truth_downforce(self.spec.programme);
        let model = if front != 0.0 || rear != 0.0 {
            format!("{model}, down-force {front}/{rear} N/(m/s)² front/rear")
        } else {
            model
        };
        let tyres = if self.spec.programme.has_rig() {
            "[tyres]\nrig = \"tyre_rig.csv\"\nmodel = \"pac89\"\n\n".to_string()
        } else {
            "# No tyre data: the base model identifies its axles from the runs.\n\n".to_string()
        };
        let step = self
            .spec
            .programme
            .replay_step()
            .map_or_else(String::new, |h| format!("step = {h}\n"));
        let runs = match self.spec.programme.segment() {
            Some(s) => format!("[runs]\nsegment = {s}\n\n"),
            None => String::new(),
        };
        let built_in = self.built_in_comment();
        format!(
            "# Synthetic campaign (handling synth --truth {} --programme {}{}), noise seed {}.\n# Truth (withheld from the diagnosis): {model}, effects:\n{}\n{built_in}\
             [vehicle]\nmass = {}\nyaw_inertia = {}\na = {}\nb = {}\ntrack_front = {}\ntrack_rear = {}\ncg_height = {}\n\n\
             {tyres}{roll}{runs}[diagnose]\nseed = {}\n{step}",
            self.truth.name(),
            self.spec.programme.name(),
            self.duration
                .map_or_else(String::new, |d| format!(" --duration {d}")),
            self.spec.seed,
            if truth.is_empty() { "#   none".to_string() } else { truth.join("\n") },
            v.mass,
            v.yaw_inertia,
            v.a,
            v.b,
            v.track_front,
            v.track_rear,
            v.cg_height,
            self.spec.seed
        )
    }

    /// The truth's model in words (withheld in a comment) and the `[roll]`
    /// table the campaign assumes, with a comment on how it differs from
    /// the truth's (empty where the campaign assumes the default).
    fn truth_and_roll(&self) -> (String, String) {
        match self.truth {
            Truth::Augmented if self.roll != RollModel::default() => (
                "UniTire tyres".to_string(),
                format!(
                    "# The roll below is the campaign's assumption, not the truth's.\n[roll]\ngradient = {}\nfrequency = {}\ndamping = {}\n\n",
                    self.roll.gradient, self.roll.frequency, self.roll.damping
                ),
            ),
            Truth::Augmented => ("UniTire tyres".to_string(), String::new()),
            Truth::FourWheel => {
                let t = &self.four_wheel;
                (
                    format!(
                        "four-wheel model with roll (roll gradient {:.2} deg/g, roll stiffness {:.0}/{:.0} N m/rad, \
                         damping {:.0}/{:.0} N m s/rad front/rear), its own Magic-Formula tyres",
                        (t.roll_gradient() * crate::vehicle::G).to_degrees(),
                        t.roll_stiffness[0],
                        t.roll_stiffness[1],
                        t.roll_damping[0],
                        t.roll_damping[1]
                    ),
                    format!(
                        "# The roll below is a generic guess that differs from the truth's.\n[roll]\ngradient = {}\nfrequency = {}\ndamping = {}\n\n",
                        self.roll.gradient, self.roll.frequency, self.roll.damping
                    ),
                )
            }
        }
    }

    /// The comment listing what the programme builds into its car, driver
    /// and logger (withheld too), or nothing.
    fn built_in_comment(&self) -> String {
        let built_in = truth_lines(self.spec.programme);
        if built_in.is_empty() {
            String::new()
        } else {
            let lines: Vec<String> = built_in.iter().map(|l| format!("#   {l}")).collect();
            format!(
                "# Built into the programme's car, driver and logger (withheld too):\n{}\n",
                lines.join("\n")
            )
        }
    }
}
