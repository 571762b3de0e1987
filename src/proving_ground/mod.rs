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
//!   25 Hz with `ax` and `bank` channels and no sideslip (`programme`'s
//!   doc). Noise as above, ax 0.05 m/s², bank 0.002 rad. On these the
//!   truth can switch on the longitudinal and bank-profile effects; without
//!   `bank_profile` the truth drives a flat track whose logger still
//!   records the banking (a control: the channel alone is no effect);
//! - a slow banked oval ([`Programme::SlowOval`]) with another car (the
//!   Putnam log's light racing car with a little downforce of its own,
//!   `truth_vehicle`, `truth_downforce`), logged at 25 Hz with `ax`,
//!   `beta` and `bank` and no `ay`, no rig data (the diagnosis identifies
//!   the axles from the runs), its runs cut into 20 s pieces; the same
//!   without `beta`, or with a `beta` as a state estimator gives it
//!   (`estimator`);
//! - the analogues of real logs (`analogues`): a heavy sedan driven by hand
//!   on a winding track with a logger's offsets and quirks, and the
//!   Putnam log's car with a rear axle that steers with roll, each driven
//!   by a closed-loop driver (`closed_loop`) on a track of `winding`.
//!
//! The augmented truth is the diagnosis's model with each effect of the
//! specification applied on the base model's effects
//! ([`EffectKind::apply`]), as a fit applies them. The steer path
//! ([`EffectKind::SteerPath`]) acts on the logged steer: the truth replays
//! the path's output, the logger records the command.
//!
//! A cornering-stiffness or friction truth means the car's tyres differ
//! from the rig's: the rig data are generated without it. Units: SI, rad.
//!
//! Two truths ([`Truth`]): the augmented model of the diagnosis itself with
//! effects switched on (the default), or the independent four-wheel model
//! of `proving_ground` with its own Magic-Formula tyre and effects
//! of its own, whose campaign's `[roll]` settings deliberately differ from
//! the truth's roll (the diagnosis is not handed the truth).
//!
//! Files: the two truths and their effect values (`truth`); the
//! programmes (`programme`), their laps (`laps`) and the open-loop driver
//! who drives them (`driver`); the analogues (`analogues`), their tracks
//! (`winding`) and closed-loop driver (`closed_loop`); the estimated
//! sideslip (`estimator`); the generated campaign as the diagnosis reads
//! it and as `handling synth` writes it (`campaign`).

pub mod four_wheel;

use crate::diagnose::effects::{EffectKind, RollModel};
use crate::diagnose::model::{Augmented, Drive};
use crate::error::ParamError;
use crate::identify::data::gauss;
use crate::manoeuvre::Manoeuvre;
use crate::measured::MeasuredRun;
use crate::proving_ground::four_wheel::{FourWheel, FourWheelEffects, FourWheelVehicle};
use crate::tyre::{SlipState, Tyre, TyreModel};
use crate::vehicle::{Vehicle, VehicleModel};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

mod analogues;
pub use analogues::analogue_duration;
mod campaign;
mod duration;
pub use duration::{check_duration, MAX_DURATION};
mod closed_loop;
mod drive;
mod driver;
mod estimator;
mod laps;
mod programme;
mod truth;
mod winding;

pub use drive::{drive, dropped_channels, DrivenRun};
use driver::LoggedInputs;
pub use programme::Programme;
use programme::{handling_programme, logged_runs, truth_downforce, truth_vehicle};
pub(crate) use truth::truth_tyre;
use truth::{four_wheel_campaign_roll, four_wheel_effects};
pub use truth::{truth_values, Truth};

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
    /// What the driver does.
    pub programme: Programme,
}

/// A generated campaign.
#[derive(Debug, Clone)]
pub struct Synthetic {
    /// Vehicle.
    pub vehicle: Vehicle,
    /// Rig samples: fz, alpha, fy.
    pub(crate) rig: Vec<[f64; 3]>,
    /// Runs with their names.
    pub runs: Vec<MeasuredRun>,
    /// The specification.
    spec: SynthSpec,
    /// The model that played the car.
    truth: Truth,
    /// The four-wheel truth's vehicle (its roll, said in `vehicle.toml`).
    four_wheel: FourWheelVehicle,
    /// The roll the campaign file states (for the four-wheel truth it
    /// differs from the truth's).
    roll: RollModel,
    /// The runs' total duration asked for (`synth --duration`), s; None
    /// for the programme's own.
    duration: Option<f64>,
}

impl Synthetic {
    /// What it was generated from.
    pub fn spec(&self) -> &SynthSpec {
        &self.spec
    }
}

/// Generates a campaign with the augmented truth.
pub fn generate(spec: &SynthSpec) -> Synthetic {
    generate_with(spec, Truth::Augmented).expect("every effect is one of the augmented truth")
}

/// The models that play the car for `spec` on `truth`: the augmented
/// truth (the diagnosis's model with the effects set), the four-wheel
/// truth, and the base vehicle model the programmes' drivers steer for.
pub(crate) struct TruthModels {
    pub(crate) augmented: Augmented,
    pub(crate) four_wheel: FourWheel,
    pub(crate) base: VehicleModel,
    pub(crate) vehicle: Vehicle,
    pub(crate) tyre: Tyre,
}

impl TruthModels {
    /// The truth of `spec` on `truth`; an error when `truth` lacks one of
    /// the effects asked for or cannot drive the programme.
    pub(crate) fn new(spec: &SynthSpec, truth: Truth) -> Result<Self, ParamError> {
        Self::with_four_wheel(spec, truth, FourWheelVehicle::sedan())
    }

    /// [`TruthModels::new`] with `car` as the four-wheel truth's vehicle.
    fn with_four_wheel(
        spec: &SynthSpec,
        truth: Truth,
        car: FourWheelVehicle,
    ) -> Result<Self, ParamError> {
        truth.drives(spec.programme)?;
        let vehicle = truth_vehicle(spec.programme);
        let tyre = truth_tyre();
        let mut base = VehicleModel::new(vehicle.clone(), tyre.clone(), tyre.clone());
        base.options.effects.aero_load = truth_downforce(spec.programme);
        let mut augmented = Augmented::new(base.clone(), 1.0);
        for (k, p) in &spec.effects {
            k.apply(p, augmented.effects_mut());
        }
        let asked: Vec<EffectKind> = spec.effects.iter().map(|(k, _)| *k).collect();
        analogues::build_in(spec.programme, &mut augmented, &asked);
        let four_wheel = FourWheel {
            vehicle: car,
            effects: match truth {
                Truth::FourWheel => four_wheel_effects(&spec.effects)?,
                Truth::Augmented => FourWheelEffects::default(),
            },
        };
        Ok(Self {
            augmented,
            four_wheel,
            base,
            vehicle,
            tyre,
        })
    }

    /// The noise-free yaw rate, ay and sideslip `truth` measures at `times`
    /// driving the open-loop manoeuvre `m` from straight running.
    pub(crate) fn measure(
        &self,
        truth: Truth,
        m: &Manoeuvre,
        times: &[f64],
    ) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        match truth {
            Truth::Augmented => {
                // The steer path (if on) filters the manoeuvre's steer as
                // sampled on the 1 ms grid.
                let drive = Drive::new(m, 1e-3);
                let drive = self
                    .augmented
                    .steered(&drive, &drive.stage_times(), drive.steer_samples())
                    .into_owned();
                let response = self.augmented.simulate(&drive, [0.0; 6]);
                let o = self.augmented.observe(&response, times);
                (o.yaw_rate, o.ay, o.beta)
            }
            Truth::FourWheel => {
                let response = self.four_wheel.simulate(m, 1e-3);
                let o = self.four_wheel.observe(&response, times);
                (o.yaw_rate, o.ay, o.beta)
            }
        }
    }
}

/// Generates a campaign with `truth`; an error when `truth` lacks one of
/// the effects asked for or cannot drive the programme.
pub fn generate_with(spec: &SynthSpec, truth: Truth) -> Result<Synthetic, ParamError> {
    let models = TruthModels::new(spec, truth)?;
    generate_from(spec, truth, models, None)
}

/// [`generate_with`] with the runs of an analogue programme lengthened to
/// `duration` s together (None: the programme's own; [`check_duration`]
/// refuses a duration no programme of fixed runs takes, one shorter than
/// [`analogue_duration`], beyond [`MAX_DURATION`] or not whole).
pub fn generate_lasting(
    spec: &SynthSpec,
    truth: Truth,
    duration: Option<f64>,
) -> Result<Synthetic, crate::error::Error> {
    if let Some(d) = duration {
        check_duration(spec.programme, d)?;
    }
    let models = TruthModels::new(spec, truth)?;
    let mut s = generate_from(spec, truth, models, duration)?;
    s.duration = duration;
    Ok(s)
}

/// Generates a campaign on the four-wheel truth with `car` as its vehicle
/// (for example [`FourWheelVehicle::with_roll_damping_ratio`]): the proving
/// ground's sedan made lighter or heavier damped than its own, to check
/// that a fit recovers the roll it did not assume. An error as
/// [`generate_with`]'s.
pub fn generate_on_four_wheel(
    spec: &SynthSpec,
    car: FourWheelVehicle,
) -> Result<Synthetic, ParamError> {
    let truth = Truth::FourWheel;
    generate_from(
        spec,
        truth,
        TruthModels::with_four_wheel(spec, truth, car)?,
        None,
    )
}

/// The campaign of `spec` measured on `models` (of `truth`), an analogue's
/// runs lasting `duration` s together where given.
fn generate_from(
    spec: &SynthSpec,
    truth: Truth,
    models: TruthModels,
    duration: Option<f64>,
) -> Result<Synthetic, ParamError> {
    let (augmented, base) = (&models.augmented, &models.base);
    let mut rng = ChaCha8Rng::seed_from_u64(spec.seed);
    let n = spec.noise;
    let analogue = analogues::analogue_runs(spec.programme, augmented, &mut rng, duration);
    let runs = if let Some(runs) = analogue {
        runs
    } else if let Some(logged) = logged_runs(spec.programme, base) {
        logged
            .iter()
            .map(|p| logged_run(augmented, spec.programme, p, &mut rng, n))
            .collect()
    } else {
        handling_programme(base)
            .into_iter()
            .map(|(name, m)| {
                let times: Vec<f64> = (0..)
                    .map(|i| 3.0 + HANDLING_INTERVAL * i as f64)
                    .take_while(|t| *t <= m.end_time() + 1e-9)
                    .collect();
                let (yaw_rate, ay, beta) = models.measure(truth, &m, &times);
                let mut noisy = |v: &[f64], s: f64| with_noise(v, s, &mut rng);
                let speed = times.iter().map(|&t| m.speed(t)).collect();
                let steer = times.iter().map(|&t| m.steer(t)).collect();
                // The noise drawn in this order: yaw rate, ay, beta.
                let yaw_rate = noisy(&yaw_rate, n.yaw_rate);
                MeasuredRun::new(format!("{name}.csv"), times, speed, steer, yaw_rate)
                    .with_ay(noisy(&ay, n.ay))
                    .with_beta(noisy(&beta, n.beta))
            })
            .collect()
    };
    Ok(finish(
        spec,
        truth,
        models.vehicle,
        &models.tyre,
        runs,
        &models.four_wheel,
        &mut rng,
    ))
}

/// The campaign from its runs: the rig data (noise after the runs') and
/// the roll the campaign file states.
fn finish(
    spec: &SynthSpec,
    truth: Truth,
    vehicle: Vehicle,
    tyre: &Tyre,
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
        rig,
        runs,
        spec: spec.clone(),
        truth,
        four_wheel: four_wheel.vehicle,
        roll: match truth {
            Truth::Augmented => analogues::campaign_roll(spec.programme),
            Truth::FourWheel => four_wheel_campaign_roll(),
        },
        duration: None,
    }
}

/// Sample interval of the handling programme's logger, s (100 Hz).
pub(crate) const HANDLING_INTERVAL: f64 = 0.01;

/// Noise of the logged `ax` (m/s²) and `bank` (rad) channels.
pub(crate) const AX_NOISE: f64 = 0.05;
pub(crate) const BANK_NOISE: f64 = 0.002;

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
    let o = truth.observe_driven(&truth.simulate(&drive, x0), &drive, &p.t);
    let (yaw_rate, ay, beta) = (o.yaw_rate, o.ay, o.beta);
    // Drawn in this order (the existing programmes' noise unchanged).
    let yaw_rate = with_noise(&yaw_rate, noise.yaw_rate, rng);
    let ay = with_noise(&ay, noise.ay, rng);
    let ax = with_noise(&p.ax, AX_NOISE, rng);
    let bank = with_noise(&p.bank, BANK_NOISE, rng);
    let beta = match programme {
        _ if !programme.logs_beta() => None,
        Programme::SlowOvalEstimatedBeta => Some(estimator::estimated(&p.t, &beta, rng)),
        _ => Some(with_noise(&beta, noise.beta, rng)),
    };
    let path = format!("{}.csv", p.name);
    MeasuredRun::new(
        path,
        p.t.clone(),
        p.speed.clone(),
        p.steer.clone(),
        yaw_rate,
    )
    .with_ay(programme.logs_ay().then_some(ay))
    .with_ax(ax)
    .with_bank(bank)
    .with_beta(beta)
}
