//! The virtual proving ground: campaigns generated from a richer truth model
//! with chosen effects switched on, measurement noise, and a tyre model
//! different from the one the diagnosis fits (model-form error, as with a
//! real car).
//!
//! The truth: Wang & Liang's compact sedan on the bundled UniTire tyre
//! (225/55R17 class), its rig data from the same tyre (loads 2.5–7 kN,
//! ±12°, noise 1 % of the force + 20 N); the diagnosis fits PAC89 to that
//! rig. Three programmes ([`Programme`]):
//! - handling (100 Hz, 1 s before every input): step steers at 40, 60,
//!   100, 100 (high level), 120 km/h and a right-hand step at 80 km/h
//!   (GB/T 6323, 0.15 s rise), a ramp steer toward the limit at 80 km/h, a
//!   0.1–3 Hz sweep at 80 km/h. Every run starts 3 s before its first
//!   sample from straight running, so the recorded part starts settled (on
//!   a bank too). Noise: yaw rate 0.003 rad/s, ay 0.05 m/s², β 0.002 rad
//!   (Gaussian, seeded);
//! - a banked oval and a road course driven like a racing car, logged at
//!   25 Hz with `ax` and `bank` channels and no sideslip ([`programme`]'s
//!   doc). Noise as above, ax 0.05 m/s², bank 0.002 rad. On these the
//!   truth can switch on the longitudinal and bank-profile effects; without
//!   `bank_profile` the truth drives a flat track whose logger still
//!   records the banking (a control: the channel alone is no effect);
//! - a slow banked oval ([`Programme::SlowOval`]) with another car (the
//!   Putnam log's light racing car with a little downforce of its own,
//!   [`truth_vehicle`], [`truth_downforce`]), logged at 25 Hz with `ax`,
//!   `beta` and `bank` and no `ay`, no rig data (the diagnosis identifies
//!   the axles from the runs), its runs cut into 20 s pieces.
//!
//! The steer path ([`EffectKind::SteerPath`]) acts on the logged steer:
//! the truth replays the path's output, the logger records the command.
//!
//! A cornering-stiffness or friction truth means the car's tyres differ
//! from the rig's: the rig data are generated without it. Units: SI, rad.
//!
//! Two truths ([`Truth`]): the augmented model of the diagnosis itself with
//! effects switched on (the default), or the independent four-wheel model
//! of [`super::proving_ground`] with its own Magic-Formula tyre and effects
//! of its own, whose campaign's `[roll]` settings deliberately differ from
//! the truth's roll (the diagnosis is not handed the truth).

use super::campaign::{BaseTyres, Campaign, DiagnoseSettings};
use super::effects::{EffectKind, EffectSet, Needs, RollModel};
use super::model::{Augmented, Drive};
use super::proving_ground::{FourWheel, FourWheelEffects, FourWheelVehicle};
use crate::error::ParamError;
use crate::identify::data::gauss;
use crate::identify::data::RigData;
use crate::manoeuvre::{Manoeuvre, RampSteer, StepSteer, SweepSteer};
use crate::measured::clean::{clean_runs, segments, CleanSettings};
use crate::measured::MeasuredRun;
use crate::tyre::ModelName;
use crate::tyre::{SlipState, Tyre, TyreModel};
use crate::vehicle::{Vehicle, VehicleModel};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use std::path::PathBuf;

mod programme;
pub use programme::{
    logged_runs, truth_downforce, truth_vehicle, LoggedInputs, Programme, LOG_RATE,
};

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

/// The model that plays the car.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Truth {
    /// The diagnosis's own augmented 2-DOF model on the UniTire tyre.
    #[default]
    Augmented,
    /// The independent four-wheel model with roll and its own tyre.
    FourWheel,
}

impl Truth {
    /// Every truth.
    pub const ALL: [Truth; 2] = [Truth::Augmented, Truth::FourWheel];

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Truth::Augmented => "augmented",
            Truth::FourWheel => "four-wheel",
        }
    }

    /// The truth of a name, if it is one.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|t| t.name() == name)
    }

    /// Whether this truth can drive `programme`: the four-wheel truth holds
    /// its speed on a flat road, so it drives the handling programme only.
    pub fn drives(self, programme: Programme) -> Result<(), ParamError> {
        if self == Truth::FourWheel && programme.logged() {
            return Err(ParamError::without_value(
                "programme",
                &format!(
                    "the four-wheel truth holds its speed on a flat road: it drives the handling programme, not `{}`",
                    programme.name()
                ),
            ));
        }
        Ok(())
    }

    /// The effects this truth can switch on in `programme`.
    pub fn effects(self, programme: Programme) -> Vec<EffectKind> {
        EffectKind::ALL
            .into_iter()
            .filter(|k| self.values(programme, *k).is_some())
            .collect()
    }

    /// The truth value of `kind` in this truth's own parameters (None: the
    /// truth has no such effect). For the four-wheel truth: relaxation
    /// length m; steering compliance rad/kN of front axle force; roll steer
    /// (front, rear) rad/rad; roll camber (front, rear) wheel lean per body
    /// roll, rad/rad; aero (front, rear) N/(m/s)²; friction and stiffness
    /// scales; yaw-inertia scale; delay s; offsets as the diagnosis's; a
    /// rolling accelerometer 1. The four-wheel truth holds its speed and
    /// drives the handling programme only.
    pub fn values(self, programme: Programme, kind: EffectKind) -> Option<Vec<f64>> {
        match self {
            // The handling programme (steps and sweeps at constant speed on
            // a flat road, no ax or bank channel) cannot show the
            // longitudinal and bank-profile effects; the logged ones can.
            Truth::Augmented => {
                (programme.logged() || kind.needs() == Needs::Nothing).then(|| truth_values(kind))
            }
            Truth::FourWheel if programme.logged() => None,
            Truth::FourWheel => match kind {
                EffectKind::RelaxationLength => Some(vec![0.7]),
                EffectKind::SteeringCompliance => Some(vec![0.003]),
                EffectKind::RollSteer => Some(vec![-0.12, 0.05]),
                EffectKind::RollCamber => Some(vec![0.8, 0.6]),
                EffectKind::AeroLoad => Some(vec![1.5, 2.0]),
                EffectKind::RoadFriction => Some(vec![0.75]),
                EffectKind::CorneringStiffness => Some(vec![0.8, 1.0]),
                EffectKind::YawInertia => Some(vec![1.3]),
                EffectKind::SensorDelay => Some(vec![0.05]),
                EffectKind::SensorBias => Some(vec![0.008, 0.2, 0.004]),
                EffectKind::AccelerometerRoll => Some(vec![1.0]),
                EffectKind::LoadTransferDistribution
                | EffectKind::RoadBank
                | EffectKind::AccelerometerPosition
                | EffectKind::LongitudinalLoadTransfer
                | EffectKind::CombinedSlip
                | EffectKind::BankProfile
                | EffectKind::SteerPath => None,
            },
        }
    }
}

/// The four-wheel truth's effects from (kind, parameters) pairs.
fn four_wheel_effects(effects: &[(EffectKind, Vec<f64>)]) -> Result<FourWheelEffects, ParamError> {
    let mut e = FourWheelEffects::default();
    for (k, p) in effects {
        let need = Truth::FourWheel
            .values(Programme::Handling, *k)
            .ok_or_else(|| {
                ParamError::without_value(k.name(), "not an effect of the four-wheel truth")
            })?;
        if p.len() != need.len() {
            return Err(ParamError::new(
                k.name(),
                p.len() as f64,
                &format!("takes {} parameters", need.len()),
            ));
        }
        match k {
            EffectKind::RelaxationLength => e.relaxation_length = p[0],
            EffectKind::SteeringCompliance => e.steering_compliance = p[0] * 1e-3,
            EffectKind::RollSteer => e.roll_steer = [p[0], p[1]],
            EffectKind::RollCamber => e.roll_camber = [p[0], p[1]],
            EffectKind::AeroLoad => e.aero_load = [p[0], p[1]],
            EffectKind::RoadFriction => e.friction_scale = p[0],
            EffectKind::CorneringStiffness => e.stiffness_scale = [p[0], p[1]],
            EffectKind::YawInertia => e.yaw_inertia_scale = p[0],
            EffectKind::SensorDelay => e.sensor_delay = p[0],
            EffectKind::SensorBias => e.sensor_bias = [p[0], p[1], p[2]],
            EffectKind::AccelerometerRoll => e.accelerometer_rolls = p[0] != 0.0,
            EffectKind::LoadTransferDistribution
            | EffectKind::RoadBank
            | EffectKind::AccelerometerPosition
            | EffectKind::LongitudinalLoadTransfer
            | EffectKind::CombinedSlip
            | EffectKind::BankProfile
            | EffectKind::SteerPath => {}
        }
    }
    Ok(e)
}

/// The roll the four-wheel truth's campaign file states: a generic
/// passenger-car guess (3°/g, 1.2 Hz, ζ = 0.6), not the truth's 6°/g,
/// about 1.8 Hz, ζ = 0.35.
pub fn four_wheel_campaign_roll() -> RollModel {
    RollModel {
        gradient: 3f64.to_radians() / crate::vehicle::G,
        frequency: 1.2,
        damping: 0.6,
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
    /// What the driver does.
    pub programme: Programme,
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
        EffectKind::LongitudinalLoadTransfer => vec![1.0],
        EffectKind::CombinedSlip => vec![0.0, 0.65, 1.0],
        EffectKind::BankProfile => vec![1.0, 0.0],
        EffectKind::SteerPath => vec![0.05, 0.15],
    }
}

/// A generated campaign.
#[derive(Debug, Clone)]
pub struct Synthetic {
    /// Vehicle.
    pub vehicle: Vehicle,
    /// Truth tyre (all wheels) of the augmented truth; the four-wheel
    /// truth's own tyre is [`FourWheelVehicle::tyre`] (this field then holds
    /// the UniTire it replaces).
    pub tyre: Tyre,
    /// Rig samples: fz, alpha, fy.
    pub rig: Vec<[f64; 3]>,
    /// Runs with their names.
    pub runs: Vec<MeasuredRun>,
    /// The specification.
    pub spec: SynthSpec,
    /// The model that played the car.
    pub truth: Truth,
    /// The roll the campaign file states (for the four-wheel truth it
    /// differs from the truth's).
    pub roll: RollModel,
}

/// The bundled UniTire of the truth.
pub fn truth_tyre() -> Tyre {
    toml::from_str(include_str!("../../../tyres/unitire.toml")).expect("the bundled UniTire file")
}

/// The test programme: (name, manoeuvre) with the steer sized on the truth
/// vehicle without effects.
fn handling_programme(model: &VehicleModel) -> Vec<(String, Manoeuvre)> {
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

/// Generates a campaign with the augmented truth.
pub fn generate(spec: &SynthSpec) -> Synthetic {
    generate_with(spec, Truth::Augmented).expect("every effect is one of the augmented truth")
}

/// Generates a campaign with `truth`; an error when `truth` lacks one of
/// the effects asked for or cannot drive the programme.
pub fn generate_with(spec: &SynthSpec, truth: Truth) -> Result<Synthetic, ParamError> {
    truth.drives(spec.programme)?;
    let vehicle = truth_vehicle(spec.programme);
    let tyre = truth_tyre();
    let mut base = VehicleModel::new(vehicle.clone(), tyre.clone(), tyre.clone());
    base.options.effects.aero_load = truth_downforce(spec.programme);
    let mut augmented = Augmented::new(base.clone(), 1.0);
    let mut effects = EffectSet::default();
    for (k, p) in &spec.effects {
        effects.set(*k, p);
    }
    augmented.effects = effects;
    let four_wheel = FourWheel {
        vehicle: FourWheelVehicle::sedan(),
        effects: match truth {
            Truth::FourWheel => four_wheel_effects(&spec.effects)?,
            Truth::Augmented => FourWheelEffects::default(),
        },
    };
    let mut rng = ChaCha8Rng::seed_from_u64(spec.seed);
    let n = spec.noise;
    let runs = if let Some(logged) = logged_runs(spec.programme, &base) {
        logged
            .iter()
            .map(|p| logged_run(&augmented, spec.programme, p, &mut rng, n))
            .collect()
    } else {
        handling_programme(&base)
            .into_iter()
            .map(|(name, m)| {
                let times: Vec<f64> = (0..)
                    .map(|i| 3.0 + 0.01 * i as f64)
                    .take_while(|t| *t <= m.end_time() + 1e-9)
                    .collect();
                let (yaw_rate, ay, beta) = match truth {
                    Truth::Augmented => {
                        // The steer path (if on) filters the manoeuvre's
                        // steer as sampled on the 1 ms grid.
                        let drive = Drive::new(&m, 1e-3);
                        let drive = augmented
                            .steered(&drive, &drive.stage_times(), drive.steer_samples())
                            .into_owned();
                        let response = augmented.simulate(&drive, [0.0; 6]);
                        let o = augmented.observe(&response, &times);
                        (o.yaw_rate, o.ay, o.beta)
                    }
                    Truth::FourWheel => {
                        let response = four_wheel.simulate(&m, 1e-3);
                        let o = four_wheel.observe(&response, &times);
                        (o.yaw_rate, o.ay, o.beta)
                    }
                };
                let mut noisy = |v: &[f64], s: f64| with_noise(v, s, &mut rng);
                MeasuredRun {
                    path: PathBuf::from(format!("{name}.csv")),
                    speed: times.iter().map(|&t| m.speed(t)).collect(),
                    steer: times.iter().map(|&t| m.steer(t)).collect(),
                    yaw_rate: noisy(&yaw_rate, n.yaw_rate),
                    ay: Some(noisy(&ay, n.ay)),
                    beta: Some(noisy(&beta, n.beta)),
                    roll: None,
                    bank: None,
                    ax: None,
                    masked: Vec::new(),
                    t: times,
                }
            })
            .collect()
    };
    Ok(finish(
        spec,
        truth,
        vehicle,
        tyre,
        runs,
        &four_wheel,
        &mut rng,
    ))
}

/// The campaign from its runs: the rig data (noise after the runs') and
/// the roll the campaign file states.
fn finish(
    spec: &SynthSpec,
    truth: Truth,
    vehicle: Vehicle,
    tyre: Tyre,
    runs: Vec<MeasuredRun>,
    four_wheel: &FourWheel,
    rng: &mut ChaCha8Rng,
) -> Synthetic {
    let mut rig = Vec::new();
    let rig_tyre = four_wheel.vehicle.tyre;
    // The slow oval has no rig data (its base model identifies the axles).
    let loads: &[f64] = if spec.programme.has_rig() {
        &[2500.0, 4000.0, 5500.0, 7000.0]
    } else {
        &[]
    };
    for &fz in loads {
        for k in -240..=240 {
            let alpha = (k as f64 * 0.05).to_radians();
            let fy = match truth {
                Truth::Augmented => tyre.lateral_force(&SlipState::lateral(alpha, fz)),
                Truth::FourWheel => rig_tyre.lateral_force(alpha, fz, 0.0, 1.0, 1.0),
            };
            let sigma = 0.01 * fy.abs() + 20.0;
            rig.push([fz, alpha, fy + sigma * gauss(rng)]);
        }
    }
    Synthetic {
        vehicle,
        tyre,
        rig,
        runs,
        spec: spec.clone(),
        truth,
        roll: match truth {
            Truth::Augmented => RollModel::default(),
            Truth::FourWheel => four_wheel_campaign_roll(),
        },
    }
}

/// Noise of the logged `ax` (m/s²) and `bank` (rad) channels.
const AX_NOISE: f64 = 0.05;
const BANK_NOISE: f64 = 0.002;

/// `v` plus Gaussian noise of standard deviation `s`, drawn in order.
fn with_noise(v: &[f64], s: f64, rng: &mut ChaCha8Rng) -> Vec<f64> {
    v.iter().map(|x| x + s * gauss(rng)).collect()
}

/// One run of a logged programme on the augmented truth, with noise: the
/// channels `programme` logs.
fn logged_run(
    truth: &Augmented,
    programme: Programme,
    p: &LoggedInputs,
    rng: &mut ChaCha8Rng,
    noise: Noise,
) -> MeasuredRun {
    // The whole run in one replay, standstill included: the vehicle model
    // holds speeds below its minimum at that minimum, so a parked car on a
    // banking stands on its tyres' slip (the accelerometer reads the
    // bank's g·sin θ) as a real one does.
    let m = p.manoeuvre();
    let drive = Drive::new(&m, 1e-3).with_channels(&p.t, Some(&p.ax), Some(&p.bank));
    let drive = truth.steered(&drive, &p.t, &p.steer);
    let x0 = truth.initial_state(&drive, 0.0, 0.0);
    let o = truth.observe(&truth.simulate(&drive, x0), &p.t);
    let (yaw_rate, ay, beta) = (o.yaw_rate, o.ay, o.beta);
    let mut noisy = |v: &[f64], s: f64| with_noise(v, s, rng);
    // Drawn in this order (the existing programmes' noise unchanged).
    let yaw_rate = noisy(&yaw_rate, noise.yaw_rate);
    let ay = noisy(&ay, noise.ay);
    let ax = noisy(&p.ax, AX_NOISE);
    let bank = noisy(&p.bank, BANK_NOISE);
    let beta = programme.logs_beta().then(|| noisy(&beta, noise.beta));
    MeasuredRun {
        path: PathBuf::from(format!("{}.csv", p.name)),
        speed: p.speed.clone(),
        steer: p.steer.clone(),
        yaw_rate,
        ay: programme.logs_ay().then_some(ay),
        ax: Some(ax),
        bank: Some(bank),
        beta,
        roll: None,
        masked: Vec::new(),
        t: p.t.clone(),
    }
}

impl Synthetic {
    /// The rig data as columns (fz, alpha, fy).
    pub fn rig_columns(&self) -> [Vec<f64>; 3] {
        [0, 1, 2].map(|j| self.rig.iter().map(|r| r[j]).collect())
    }

    /// The rig data, as a campaign file would hold them.
    pub fn rig_data(&self) -> RigData {
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
    /// generated.
    pub fn campaign(&self, effects: Vec<EffectKind>, settings: DiagnoseSettings) -> Campaign {
        let source = PathBuf::from(format!("synthetic campaign {}", self.name()));
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
            vehicle: self.vehicle.clone(),
            friction: 1.0,
            tyres,
            source,
            run_files: self.runs.len(),
            runs,
            roll: self.roll,
            settings,
            effects,
            notes: Vec::new(),
            cleaning,
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
        let (model, roll) = match self.truth {
            Truth::Augmented => ("UniTire tyres".to_string(), String::new()),
            Truth::FourWheel => {
                let t = FourWheelVehicle::sedan();
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
        };
        let [front, rear] = truth_downforce(self.spec.programme);
        let model = if front != 0.0 || rear != 0.0 {
            format!("{model}, down-force {front}/{rear} N/(m/s)^2 front/rear")
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
        format!(
            "# Synthetic campaign (handling synth --truth {} --programme {}), noise seed {}.\n# Truth (withheld from the diagnosis): {model}, effects:\n{}\n\
             [vehicle]\nmass = {}\nyaw_inertia = {}\na = {}\nb = {}\ntrack_front = {}\ntrack_rear = {}\ncg_height = {}\n\n\
             {tyres}{roll}{runs}[diagnose]\nseed = {}\n{step}",
            self.truth.name(),
            self.spec.programme.name(),
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
