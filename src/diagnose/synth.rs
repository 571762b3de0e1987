//! The virtual proving ground: campaigns generated from a richer truth model
//! with chosen effects switched on, measurement noise, and a tyre model
//! different from the one the diagnosis fits (model-form error, as with a
//! real car).
//!
//! The truth: the seed-004 sedan on the bundled UniTire tyre (225/55R17
//! class), its rig data from the same tyre (loads 2.5–7 kN, ±12°, noise
//! 1 % of the force + 20 N); the diagnosis fits PAC89 to that rig. The test
//! programme (100 Hz, 1 s before every input): step steers at 40, 60, 100,
//! 100 (high level), 120 km/h and a right-hand step at 80 km/h (GB/T 6323,
//! 0.15 s rise), a ramp steer toward the limit at 80 km/h, a 0.1–3 Hz sweep
//! at 80 km/h. Every run starts 3 s before its first sample from straight
//! running, so the recorded part starts settled (on a bank too). Noise:
//! yaw rate 0.003 rad/s, ay 0.05 m/s², β 0.002 rad (Gaussian, seeded).
//!
//! A cornering-stiffness or friction truth means the car's tyres differ
//! from the rig's: the rig data are generated without it. Units: SI, rad.

use super::effects::{EffectKind, EffectSet, RollModel};
use super::model::{Augmented, Drive};
use crate::identify::data::gauss;
use crate::io::campaign::{BaseTyres, Campaign, DiagnoseSettings};
use crate::io::MeasuredRun;
use crate::manoeuvre::{Manoeuvre, RampSteer, StepSteer, SweepSteer};
use crate::tyre::{SlipState, Tyre, TyreModel};
use crate::vehicle::{Vehicle, VehicleModel};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::path::PathBuf;

/// Noise standard deviations of the synthetic measurements.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Noise {
    /// Yaw rate, rad/s.
    pub yaw_rate: f64,
    /// Lateral acceleration, m/s².
    pub ay: f64,
    /// Sideslip, rad.
    pub beta: f64,
}

impl Default for Noise {
    fn default() -> Self {
        Self {
            yaw_rate: 0.003,
            ay: 0.05,
            beta: 0.002,
        }
    }
}

/// What to generate.
#[derive(Debug, Clone, PartialEq)]
pub struct SynthSpec {
    /// Effects of the truth with their parameter values.
    pub effects: Vec<(EffectKind, Vec<f64>)>,
    /// Noise seed.
    pub seed: u64,
    /// Measurement noise.
    pub noise: Noise,
}

/// The truth value of each effect used by the checks: realistic, and large
/// enough to matter in a handling test.
pub fn truth_values(kind: EffectKind) -> Vec<f64> {
    match kind {
        EffectKind::RelaxationLength => vec![0.8],
        EffectKind::SteeringCompliance => vec![0.003],
        EffectKind::RollSteer => vec![-0.15, 0.0],
        EffectKind::RollCamber => vec![-1.5, 0.0],
        EffectKind::LoadTransferDistribution => vec![0.85],
        EffectKind::AeroLoad => vec![1.5, 2.0],
        EffectKind::RoadFriction => vec![0.75],
        EffectKind::RoadBank => vec![0.03],
        EffectKind::CorneringStiffness => vec![0.8, 1.0],
        EffectKind::YawInertia => vec![1.3],
        EffectKind::SensorDelay => vec![0.05],
        EffectKind::SensorBias => vec![0.008, 0.2, 0.004],
        EffectKind::AccelerometerRoll => vec![RollModel::default().gradient],
        EffectKind::AccelerometerPosition => vec![0.8],
    }
}

/// A generated campaign.
#[derive(Debug, Clone)]
pub struct Synthetic {
    /// Vehicle.
    pub vehicle: Vehicle,
    /// Truth tyre (all wheels).
    pub tyre: Tyre,
    /// Rig samples: fz, alpha, fy.
    pub rig: Vec<[f64; 3]>,
    /// Runs with their names.
    pub runs: Vec<MeasuredRun>,
    /// The specification.
    pub spec: SynthSpec,
}

/// The bundled UniTire of the truth.
pub fn truth_tyre() -> Tyre {
    toml::from_str(include_str!("../../tyres/unitire.toml")).expect("the bundled UniTire file")
}

/// The test programme: (name, manoeuvre) with the steer sized on the truth
/// vehicle without effects.
fn programme(model: &VehicleModel) -> Vec<(String, Manoeuvre)> {
    let steer_for = |u: f64, ay: f64| {
        model
            .steady_state_for_lateral_acceleration(u, 1.0, ay)
            .map(|s| s.steer)
            .expect("the truth vehicle holds these levels")
    };
    let pre = 3.0;
    let step = |name: &str, kph: f64, ay: f64| {
        let u = kph / 3.6;
        (
            name.to_string(),
            Manoeuvre::StepSteer(StepSteer {
                speed: u,
                amplitude: steer_for(u, ay),
                trim: 0.0,
                start: pre + 1.0,
                rise_time: 0.15,
                end: pre + 6.0,
            }),
        )
    };
    let u80 = 80.0 / 3.6;
    vec![
        step("step_040kph_3ms2", 40.0, 3.0),
        step("step_060kph_2ms2", 60.0, 2.0),
        step("step_100kph_2ms2", 100.0, 2.0),
        step("step_100kph_6ms2", 100.0, 6.0),
        step("step_120kph_4ms2", 120.0, 4.0),
        step("step_080kph_right_4ms2", 80.0, -4.0),
        (
            "ramp_080kph".into(),
            Manoeuvre::RampSteer(RampSteer {
                speed: u80,
                rate: 1.4 * steer_for(u80, 7.0) / 8.0,
                start: pre + 1.0,
                end: pre + 9.0,
            }),
        ),
        (
            "sweep_080kph".into(),
            Manoeuvre::Sweep(SweepSteer {
                speed: u80,
                amplitude: steer_for(u80, 3.0),
                f_start: 0.1,
                f_end: 3.0,
                start: pre + 1.0,
                end: pre + 21.0,
            }),
        ),
    ]
}

/// Generates a campaign.
pub fn generate(spec: &SynthSpec) -> Synthetic {
    let vehicle = Vehicle::seed004_sedan();
    let tyre = truth_tyre();
    let base = VehicleModel::new(vehicle.clone(), tyre.clone(), tyre.clone());
    let mut truth = Augmented::new(base.clone(), 1.0);
    let mut effects = EffectSet::default();
    for (k, p) in &spec.effects {
        effects.set(*k, p);
    }
    truth.effects = effects;
    let mut rng = ChaCha8Rng::seed_from_u64(spec.seed);
    let n = spec.noise;
    let runs = programme(&base)
        .into_iter()
        .map(|(name, m)| {
            let drive = Drive::new(&m, 1e-3);
            let response = truth.simulate(&drive, [0.0; 6]);
            let times: Vec<f64> = (0..)
                .map(|i| 3.0 + 0.01 * i as f64)
                .take_while(|t| *t <= m.end_time() + 1e-9)
                .collect();
            let obs = truth.observe(&response, &times);
            let mut noisy = |v: &[f64], s: f64| -> Vec<f64> {
                v.iter().map(|x| x + s * gauss(&mut rng)).collect()
            };
            MeasuredRun {
                path: PathBuf::from(format!("{name}.csv")),
                speed: times.iter().map(|&t| m.speed(t)).collect(),
                steer: times.iter().map(|&t| m.steer(t)).collect(),
                yaw_rate: noisy(&obs.yaw_rate, n.yaw_rate),
                ay: Some(noisy(&obs.ay, n.ay)),
                beta: Some(noisy(&obs.beta, n.beta)),
                roll: None,
                bank: None,
                ax: None,
                masked: Vec::new(),
                t: times,
            }
        })
        .collect();
    let mut rig = Vec::new();
    for fz in [2500.0, 4000.0, 5500.0, 7000.0] {
        for k in -240..=240 {
            let alpha = (k as f64 * 0.05).to_radians();
            let fy = tyre.lateral_force(&SlipState::lateral(alpha, fz));
            let sigma = 0.01 * fy.abs() + 20.0;
            rig.push([fz, alpha, fy + sigma * gauss(&mut rng)]);
        }
    }
    Synthetic {
        vehicle,
        tyre,
        rig,
        runs,
        spec: spec.clone(),
    }
}

impl Synthetic {
    /// The rig data as columns (fz, alpha, fy).
    pub fn rig_columns(&self) -> [Vec<f64>; 3] {
        [0, 1, 2].map(|j| self.rig.iter().map(|r| r[j]).collect())
    }

    /// The campaign in memory, diagnosed against `effects` (the rig file is
    /// written to `rig_path`, which the diagnosis reads).
    pub fn campaign(
        &self,
        rig_path: PathBuf,
        effects: Vec<EffectKind>,
        settings: DiagnoseSettings,
    ) -> Campaign {
        Campaign {
            name: self.name(),
            source: rig_path.clone(),
            inputs: vec![rig_path.clone()],
            vehicle: self.vehicle.clone(),
            friction: 1.0,
            tyres: BaseTyres::Rig {
                path: rig_path,
                model: "pac89".into(),
            },
            runs: self.runs.clone(),
            roll: RollModel::default(),
            settings,
            effects,
            notes: Vec::new(),
            cleaning: Default::default(),
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
    pub fn vehicle_toml(&self) -> String {
        let v = &self.vehicle;
        let truth: Vec<String> = self
            .spec
            .effects
            .iter()
            .map(|(k, p)| format!("#   {} = {:?}", k.name(), p))
            .collect();
        format!(
            "# Synthetic campaign (handling synth), noise seed {}.\n# Truth (withheld from the diagnosis): UniTire tyres, effects:\n{}\n\
             [vehicle]\nmass = {}\nyaw_inertia = {}\na = {}\nb = {}\ntrack_front = {}\ntrack_rear = {}\ncg_height = {}\n\n\
             [tyres]\nrig = \"tyre_rig.csv\"\nmodel = \"pac89\"\n\n[diagnose]\nseed = {}\n",
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
}
