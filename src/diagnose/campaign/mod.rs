//! A test campaign as the sim-to-real diagnosis takes it: the vehicle, its
//! road, where the base tyres come from, the measured runs (already checked
//! and cleaned), the sensor offsets their standstills and straights showed
//! before the cleaning, and the diagnosis's settings. `crate::io::campaign` reads
//! and checks campaign files and folders into it (`FORMATS.md`); the
//! virtual proving ground ([`crate::proving_ground`]) builds one in memory.
//! Units: SI, rad.

pub mod prior;
pub mod swarm;

use crate::diagnose::effects::{EffectKind, RollModel};
use crate::identify::data::RigData;
use crate::measured::calibration::CalibrationReport;
use crate::measured::clean::{CleaningReport, DEFAULT_MIN_SPEED};
use crate::measured::MeasuredRun;
use crate::optim::local::Derivatives;
use crate::tyre::{ModelName, Tyre};
use crate::vehicle::Vehicle;
use prior::AxlePrior;
use serde::{Deserialize, Serialize};
use std::path::PathBuf;

/// The `[diagnose]` table: settings of the diagnosis.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct DiagnoseSettings {
    /// Seed of every random search.
    pub seed: u64,
    /// Candidate effects (default: the whole library).
    pub effects: Option<Vec<String>>,
    /// Step of the replays (RK4, or ROS34PW2 for a model too stiff for it), s.
    pub step: f64,
    /// Rate at which residuals are sampled for the fits, Hz.
    pub sample_rate: f64,
    /// Largest number of effects combined.
    pub max_effects: usize,
    /// PSO swarm size and iterations of each effect fit (1 to
    /// [`swarm::MAX_SWARM`]).
    #[serde(deserialize_with = "swarm::swarm_size")]
    pub particles: usize,
    /// PSO iterations (1 to [`swarm::MAX_SWARM`]).
    #[serde(deserialize_with = "swarm::swarm_size")]
    pub iterations: usize,
    /// Lowest speed replayed and scored, m/s (standstills and crawling
    /// below it are excluded).
    pub min_speed: f64,
    /// Screen the single effects before their cross-validation: one whose
    /// fit on all runs removes too little of the gap to pass on held-out
    /// runs is not refitted fold by fold (it is listed as screened).
    pub screening: bool,
    /// How the fits take their Jacobians: forward differences (the
    /// default: one replay per parameter) or exact (one replay in dual
    /// numbers, which on this model costs more than the differences of up
    /// to about 14 parameters; see the book's benchmarks chapter).
    pub derivatives: Derivatives,
}

impl Default for DiagnoseSettings {
    fn default() -> Self {
        Self {
            seed: 1,
            effects: None,
            step: 0.01,
            sample_rate: 25.0,
            max_effects: 3,
            particles: 10,
            iterations: 12,
            min_speed: DEFAULT_MIN_SPEED,
            screening: true,
            derivatives: Derivatives::Differences,
        }
    }
}

/// The `[channels]` table: a measurement uncertainty (one standard
/// deviation) the user trusts per channel, in the channel's unit. A stated
/// uncertainty is the channel's scale in every fit and its noise floor; a
/// channel without one takes its estimate (`crate::diagnose::model::scale`).
#[derive(Debug, Clone, Copy, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct StatedUncertainty {
    /// Yaw rate, rad/s.
    pub yaw_rate: Option<f64>,
    /// Lateral acceleration, m/s².
    pub ay: Option<f64>,
    /// Sideslip, rad.
    pub beta: Option<f64>,
}

/// The `[sensors]` table: where the campaign states its measurements are
/// taken, m ahead of the centre of gravity (ISO 8855 x, negative behind).
/// Every replay, the base model's and every candidate's, takes its outputs
/// at the stated points: the accelerometer's `ay + x·ṙ`, the sideslip's
/// `β + x·r/u` (`crate::vehicle::Sensors`). Without `beta_x` the sideslip
/// is taken at the accelerometer (an inertial unit's); the
/// `accelerometer_position` candidate then fits a correction to the stated
/// `accelerometer_x`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SensorPositions {
    /// The accelerometer's position, m ahead of the centre of gravity.
    pub accelerometer_x: Option<f64>,
    /// The sideslip sensor's position, m ahead of the centre of gravity.
    pub beta_x: Option<f64>,
}

impl SensorPositions {
    /// How far ahead of the accelerometer the sideslip is measured, m: 0
    /// where no `beta_x` is stated (an inertial unit gives both).
    pub fn beta_ahead_of_accelerometer(&self) -> f64 {
        self.beta_x
            .map_or(0.0, |b| b - self.accelerometer_x.unwrap_or(0.0))
    }

    /// The report's note of the positions used, where any is stated.
    pub fn note(&self) -> Option<String> {
        let at = |x: f64| {
            format!(
                "{} m ahead of the centre of gravity",
                crate::format::exact(x)
            )
        };
        let ay = self.accelerometer_x.map_or_else(
            || "at the centre of gravity (no accelerometer_x stated)".to_string(),
            at,
        );
        let beta = match (self.beta_x, self.accelerometer_x) {
            (Some(b), _) => at(b),
            (None, Some(_)) => "at the accelerometer (no beta_x stated)".to_string(),
            (None, None) => return None,
        };
        Some(format!(
            "[sensors]: every replay, the base model's and each candidate's, takes ay {ay} (ay + x·dr/dt) and beta {beta} (beta + x·r/u); accelerometer_position fits a correction to the accelerometer's stated position"
        ))
    }
}

/// A road friction a campaign states, and the line it is stated on: a
/// scale on the tyres' grip that a verdict on the axles names.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StatedFriction {
    /// The road friction scale.
    pub value: f64,
    /// Its line in the campaign file.
    pub line: usize,
}

/// A given tyre file: its path (as the campaign names it, resolved beside
/// the campaign) and the wheel loads a TOML tyre states it was fitted at
/// (`[fitted_ranges] fz`, N; None where it states none). A `.tir` carries
/// its own (`FZMIN`, `FZMAX`) in its tyre.
#[derive(Debug, Clone, PartialEq)]
pub struct TyreFile {
    /// The file.
    pub path: PathBuf,
    /// Its `[fitted_ranges] fz`, N.
    pub fitted_loads: Option<[f64; 2]>,
}

/// Where the base model's tyres come from.
#[derive(Debug, Clone)]
pub enum BaseTyres {
    /// Given tyre files (front, rear), and where each was read with the
    /// loads it states it was fitted at.
    Given(Box<Tyre>, Box<Tyre>, Box<[TyreFile; 2]>),
    /// Rig data and the model to fit to it.
    Rig {
        /// The data file (named in reports).
        path: PathBuf,
        /// Its samples.
        data: Box<RigData>,
        /// The model fitted.
        model: ModelName,
    },
    /// No tyre data: axle characteristics identified from the runs.
    FromRuns,
}

impl BaseTyres {
    /// Whether the base tyres are linear on both axles (given files of the
    /// linear model, or the linear model fitted to rig data): no limit for
    /// a friction to set or a friction scale to lower. Axles identified
    /// from the runs are not said linear here.
    pub fn linear(&self) -> bool {
        let linear = |t: &Tyre| matches!(t, Tyre::Linear(_));
        match self {
            BaseTyres::Given(f, r, _) => linear(f) && linear(r),
            BaseTyres::Rig { model, .. } => *model == ModelName::Linear,
            BaseTyres::FromRuns => false,
        }
    }
}

/// A loaded and checked campaign.
#[derive(Debug, Clone)]
pub struct Campaign {
    /// Name (the file stem or folder name unless given).
    pub name: String,
    /// The campaign file or folder.
    pub source: PathBuf,
    /// Every input file read (so outputs never overwrite one).
    pub inputs: Vec<PathBuf>,
    /// The folder whose every `*.csv` is a run (`[runs] dir`, or a
    /// campaign folder's `runs/`), if the runs are read so: no output may
    /// be written into it, or the next diagnosis reads it as a run.
    pub runs_folder: Option<PathBuf>,
    /// Mass and geometry.
    pub vehicle: Vehicle,
    /// Road friction scale.
    pub friction: f64,
    /// The line of the campaign file that states `[road] friction` (None:
    /// not stated, 1.0), for the verdicts that name it.
    pub friction_at: Option<usize>,
    /// The base tyres.
    pub tyres: BaseTyres,
    /// The prior of axle characteristics identified from the runs (used
    /// only without tyre data, `BaseTyres::FromRuns`).
    pub prior: AxlePrior,
    /// The measurement uncertainty the user trusts per channel
    /// (`[channels]`).
    pub uncertainty: StatedUncertainty,
    /// Where the measurements are taken (`[sensors]`).
    pub sensors: SensorPositions,
    /// The runs (after splitting at gaps and into segments).
    pub runs: Vec<MeasuredRun>,
    /// The run files (or logs) the runs were read from.
    pub run_files: usize,
    /// Roll degree of freedom.
    pub roll: RollModel,
    /// The campaign file and line that state `[roll] gradient` (None: not
    /// stated), for the roll-steer and roll-camber values said at it.
    pub roll_gradient_at: Option<(PathBuf, usize)>,
    /// Diagnosis settings.
    pub settings: DiagnoseSettings,
    /// The candidate effects.
    pub effects: Vec<EffectKind>,
    /// What was done to the inputs (split runs, …), for the report.
    pub notes: Vec<String>,
    /// Glitches, slow spans and pieces found while cleaning the runs.
    pub cleaning: CleaningReport,
    /// Sensor offsets from the standstills and straights of the raw runs.
    pub calibration: CalibrationReport,
}
