//! Effects beyond the papers' model ([`Effects`]), and the body-roll degree
//! of freedom they act through: the one struct of every number an effect
//! sets — what a scenario's `[model.effects]` table deserialises, what the
//! vehicle model carries and its right-hand side reads (through
//! [`super::ModelScalars`]), and what the sim-to-real diagnosis's candidate
//! effects set (`crate::diagnose::effects`) and a fit lifts into dual
//! numbers ([`Effects::map`], written once: a new field fails to compile
//! until it is mapped). Every effect is off by default, and off it changes
//! nothing: the base model stays exactly Li, Jia & Zhao's / Wang &
//! Liang's. The struct is generic over the scalar ([`crate::scalar`]):
//! `Effects` is `Effects<f64>`, a fit's is `Effects<DualSVec64<N>>`.
//!
//! Signs follow ISO 8855 (x forward, y left, z up, positive steer left,
//! positive roll φ puts the right side down, as in a left turn). Units: SI,
//! rad.
//!
//! - tyre lag: the axle slip angles follow their kinematic values through a
//!   first-order lag of relaxation length σ, `α̇ = (u/σ)·(α_kin − α)`
//!   (Pacejka, *Tyre and Vehicle Dynamics*, §7.1);
//! - steering compliance: the front wheels lose `c·Fyf` of steer;
//! - roll steer: front steer `δ + ε_f·φ`, rear steer `ε_r·φ`;
//! - roll camber: each wheel gains `κ·φ·Fz` of camber thrust, outside the
//!   tyre's slip curve (camber thrust does not saturate with slip the way
//!   slip force does — what separates it from roll steer);
//! - cornering-stiffness scale: each axle's tyre sees `s·α` (stiffness
//!   scaled, peak force kept);
//! - aero load and road bank: see the fields; a measured bank profile comes
//!   in through [`super::Inputs::bank`], scaled by `bank_profile_scale`, on
//!   top of the constant bank;
//! - longitudinal load transfer: at longitudinal acceleration ax
//!   ([`super::Inputs::ax`]) each front wheel loses and each rear wheel gains
//!   a share of `m·ax·h/(2l)` (Gillespie, *Fundamentals of Vehicle
//!   Dynamics*, 1992, ch. 2), an axle's load never below zero;
//! - combined slip ([`CombinedSlip`]): a share `s` of the longitudinal
//!   force `m·ax` (the rest: what the tyres do not carry, drag and rolling
//!   resistance, grade, or an `ax` that is not the car's own) is
//!   shared between the axles by a drive split (ax > 0) or a brake balance
//!   (ax < 0), evenly between an axle's wheels, and each wheel's lateral
//!   force is reduced on the friction circle of its tyre,
//!   `Fy = Fy0·√(1 − (Fx/(μ·Fz))²)` (a friction ellipse with equal axes:
//!   the pure-slip models have no combined-slip law of their own; μ is
//!   [`crate::tyre::TyreModel::friction_coefficient`]). At `s = 0` no
//!   tyre carries a longitudinal force and the lateral forces are the pure
//!   ones exactly: the effect is nested in the base model;
//! - the numbers the diagnosis sets that a scenario file does not (no key
//!   in `[model.effects]`): a yaw-inertia scale and a road-friction scale
//!   on the vehicle's and the road's, the front share of the lateral load
//!   transfer replacing the vehicle's, the sensors ([`Sensors`], acting on
//!   the response, not the dynamics) and the steer path ([`SteerPath`],
//!   acting on the logged steer before the model sees it).
//!
//! Roll (the [`RollModel`]) is a second-order response of the body to the
//! lateral acceleration, `φ̈ = ω²·(k·ay − φ) − 2ζω·φ̇`.
//!
//! Adding a number: a field here (with its default, its check in
//! [`Effects::validate`], its line in [`Effects::map`] and its place in
//! [`Effects::beyond_equilibrium_residual`] — each names every field, so
//! the compiler asks for them), and the physics that reads it.

pub use super::sensors::Sensors;
pub use super::steer_path::SteerPath;
use crate::error::{EffectLimit, Limit, ParamError, ParamReason};
use crate::scalar::{off, Scalar};
use serde::{Deserialize, Serialize};

/// Relaxation lengths below this (m) are no lag: 1 mm is 50 µs at 20 m/s,
/// far below what a logged run resolves, and a shorter lag would make the
/// lag states stiff for explicit integration (a fit that drives σ toward
/// zero would otherwise chase it through ever stiffer models).
pub const MIN_RELAXATION_LENGTH: f64 = 1e-3;

/// The steady roll per lateral acceleration of [`RollModel::default`], a
/// passenger car's 4°/g, rad per m/s².
pub const PASSENGER_CAR_ROLL_GRADIENT: f64 = 4f64.to_radians() / crate::constants::G;

/// The largest roll gradient a scenario may give, rad per m/s² (28°/g,
/// beyond any car's; [`Limit::RollGradient`]).
pub const MAX_ROLL_GRADIENT: f64 = 0.05;

/// The largest down-force coefficient of one axle a scenario may give, N
/// per (m/s)²: twice the diagnosis's search bound (6), four times a
/// Formula 1 car's whole down-force ([`Limit::AeroLoad`]).
pub const MAX_AERO_LOAD: f64 = 12.0;

/// The steepest road bank, rad (35°): steeper is no road. The same limit
/// as a run's `bank` column is read against ([`crate::constants`]).
pub const MAX_ROAD_BANK: f64 = crate::constants::STEEPEST_BANK;

/// Roll degree of freedom used by roll steer and roll camber: a second-order
/// response of the body roll φ to lateral acceleration,
/// `φ̈ = ω²·(k·ay − φ) − 2ζω·φ̇`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    default,
    bound(
        serialize = "T: Serialize",
        deserialize = "T: Deserialize<'de>, RollModel<T>: Default"
    )
)]
pub struct RollModel<T = f64> {
    /// Steady roll per lateral acceleration k, rad per m/s².
    pub gradient: T,
    /// Undamped natural frequency, Hz.
    pub frequency: T,
    /// Damping ratio ζ.
    pub damping: T,
}

impl RollModel {
    /// Checks the values for physical sense; the error names the key.
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::in_range(
            "gradient",
            self.gradient,
            -f64::MIN_POSITIVE,
            MAX_ROLL_GRADIENT,
            Limit::RollGradient,
        )?;
        ParamError::positive("frequency", self.frequency)?;
        let effect = |why| Limit::Effect(why);
        ParamError::in_range(
            "frequency",
            self.frequency,
            0.0,
            10.0,
            effect(EffectLimit::RollFrequency),
        )?;
        ParamError::positive("damping", self.damping)?;
        ParamError::in_range(
            "damping",
            self.damping,
            0.0,
            5.0,
            effect(EffectLimit::RollDamping),
        )
    }
}

impl<T: Copy> RollModel<T> {
    /// Every number mapped by `f`.
    pub fn map<U>(&self, f: impl Fn(T) -> U) -> RollModel<U> {
        RollModel {
            gradient: f(self.gradient),
            frequency: f(self.frequency),
            damping: f(self.damping),
        }
    }
}

impl Default for RollModel {
    /// A passenger car: 4°/g, 1.5 Hz, ζ = 0.5.
    fn default() -> Self {
        Self {
            gradient: PASSENGER_CAR_ROLL_GRADIENT,
            frequency: 1.5,
            damping: 0.5,
        }
    }
}

/// How much of the longitudinal force `m·ax` the tyres carry through their
/// friction circles, and how it is shared between the axles: shares of the
/// front axle, the rest on the rear.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    default,
    bound(
        serialize = "T: Serialize",
        deserialize = "T: Deserialize<'de>, CombinedSlip<T>: Default"
    )
)]
pub struct CombinedSlip<T = f64> {
    /// Front share of the drive force (ax > 0): 0 for rear-wheel drive.
    pub drive_front_share: T,
    /// Front share of the brake force (ax < 0), the brake balance.
    pub brake_front_share: T,
    /// Share of `m·ax` the tyres carry (1: all of it; 0: none, the pure-slip
    /// forces exactly). Not a share of a whole: above 1 the tyres carry
    /// more than `m·ax` (drag and rolling resistance the throttle works
    /// against, an `ax` logged low).
    pub force_share: T,
}

impl<T: Copy> CombinedSlip<T> {
    /// Every number mapped by `f`.
    pub fn map<U>(&self, f: impl Fn(T) -> U) -> CombinedSlip<U> {
        CombinedSlip {
            drive_front_share: f(self.drive_front_share),
            brake_front_share: f(self.brake_front_share),
            force_share: f(self.force_share),
        }
    }
}

impl Default for CombinedSlip {
    /// Rear-wheel drive, 60 % of the braking on the front axle, all of
    /// `m·ax` carried by the tyres.
    fn default() -> Self {
        Self {
            drive_front_share: 0.0,
            brake_front_share: 0.6,
            force_share: 1.0,
        }
    }
}

/// Effects beyond the papers' model, in a scalar of [`crate::scalar`]
/// (`f64` by default); [`Effects::default`] is the base model. The fields
/// after `combined_slip` have no key in a scenario's `[model.effects]`
/// (they are not read from files, and an unknown key there is refused).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    default,
    bound(
        serialize = "T: Serialize",
        deserialize = "T: Deserialize<'de>, Effects<T>: Default, RollModel<T>: Default, \
                       CombinedSlip<T>: Default"
    )
)]
pub struct Effects<T = f64> {
    /// Aerodynamic down-force per axle (front, rear), N per (m/s)²: each
    /// wheel of the axle carries half of `k·u²` on top of its static load.
    #[serde(deserialize_with = "super::pair::front_rear")]
    pub aero_load: [T; 2],
    /// Road bank angle θ, rad, positive when the road's left edge is higher:
    /// gravity then pulls the car to the right with `m·g·sin θ`, the static
    /// loads scale by `cos θ`, and the accelerometer (`ay`, the tyres' force
    /// over the mass) reads `g·sin θ` more than the path's acceleration.
    pub road_bank: T,
    /// How much of the measured bank profile ([`super::Inputs::bank`]) the
    /// road has on top of `road_bank`: 1 as measured, 0 (the default) none.
    pub bank_profile_scale: T,
    /// Relaxation length σ of both axles, m (below
    /// [`MIN_RELAXATION_LENGTH`]: no lag).
    pub relaxation_length: T,
    /// Steer lost per front axle force, rad/N.
    pub steering_compliance: T,
    /// Roll steer (front, rear), rad of axle steer per rad of roll.
    #[serde(deserialize_with = "super::pair::front_rear")]
    pub roll_steer: [T; 2],
    /// Camber thrust per roll (front, rear): lateral force per wheel load
    /// per rad of roll.
    #[serde(deserialize_with = "super::pair::front_rear")]
    pub roll_camber: [T; 2],
    /// Scale on the slip angle each axle's tyre sees (front, rear): the
    /// cornering stiffness scaled, the peak force kept.
    #[serde(deserialize_with = "super::pair::front_rear")]
    pub cornering_stiffness_scale: [T; 2],
    /// The body's roll response (drives roll steer and roll camber).
    pub roll: RollModel<T>,
    /// Share of the rigid-body longitudinal load transfer `m·ax·h/l` at
    /// [`super::Inputs::ax`] (0: none, 1: as the CG height gives).
    pub longitudinal_load_transfer: T,
    /// Combined slip from [`super::Inputs::ax`] (None: pure slip).
    pub combined_slip: Option<CombinedSlip<T>>,
    /// Scale on the vehicle's yaw moment of inertia (1: the vehicle's).
    #[serde(skip)]
    pub yaw_inertia_scale: T,
    /// Scale on the road's friction ([`super::Inputs::friction`]; 1: the
    /// road's).
    #[serde(skip)]
    pub friction_scale: T,
    /// Front share χ of the lateral load transfer (None: the vehicle's,
    /// [`super::Vehicle::load_transfer_front_share`]).
    #[serde(skip)]
    pub transfer_share: Option<T>,
    /// The measurement system (all zero: ideal).
    #[serde(skip)]
    pub sensors: Sensors<T>,
    /// The steer path between the logged steer and the road wheels (zero:
    /// the wheels follow the logged steer).
    #[serde(skip)]
    pub steer_path: SteerPath<T>,
}

impl Default for Effects {
    fn default() -> Self {
        Self {
            aero_load: [0.0; 2],
            road_bank: 0.0,
            bank_profile_scale: 0.0,
            relaxation_length: 0.0,
            steering_compliance: 0.0,
            roll_steer: [0.0; 2],
            roll_camber: [0.0; 2],
            cornering_stiffness_scale: [1.0; 2],
            roll: RollModel::default(),
            longitudinal_load_transfer: 0.0,
            combined_slip: None,
            yaw_inertia_scale: 1.0,
            friction_scale: 1.0,
            transfer_share: None,
            sensors: Sensors::default(),
            steer_path: SteerPath::default(),
        }
    }
}

impl<T: Copy> Effects<T> {
    /// Every number mapped by `f`: the one place the struct is taken apart
    /// number by number ([`Effects::lift`] into dual numbers, their values
    /// back by [`Effects::re`]).
    pub fn map<U>(&self, f: impl Fn(T) -> U) -> Effects<U> {
        Effects {
            aero_load: self.aero_load.map(&f),
            road_bank: f(self.road_bank),
            bank_profile_scale: f(self.bank_profile_scale),
            relaxation_length: f(self.relaxation_length),
            steering_compliance: f(self.steering_compliance),
            roll_steer: self.roll_steer.map(&f),
            roll_camber: self.roll_camber.map(&f),
            cornering_stiffness_scale: self.cornering_stiffness_scale.map(&f),
            roll: self.roll.map(&f),
            longitudinal_load_transfer: f(self.longitudinal_load_transfer),
            combined_slip: self.combined_slip.map(|c| c.map(&f)),
            yaw_inertia_scale: f(self.yaw_inertia_scale),
            friction_scale: f(self.friction_scale),
            transfer_share: self.transfer_share.map(&f),
            sensors: self.sensors.map(&f),
            steer_path: self.steer_path.map(&f),
        }
    }
}

impl Effects {
    /// The same numbers in scalar `T`, as constants.
    pub fn lift<T: Scalar>(&self) -> Effects<T> {
        self.map(T::from)
    }

    /// Checks the values for physical sense (the keys of a scenario's
    /// `[model.effects]` first, in its order); the error names the key.
    pub fn validate(&self) -> Result<(), ParamError> {
        self.validate_road()?;
        self.validate_axles()?;
        if let Some(c) = &self.combined_slip {
            c.validate()?;
        }
        self.roll.validate().map_err(|e| e.within("roll"))?;
        self.validate_scales_and_sensors()
    }

    /// The road's and the aerodynamics' keys: aero load, bank, bank scale.
    fn validate_road(&self) -> Result<(), ParamError> {
        for (i, k) in self.aero_load.iter().enumerate() {
            let key = format!("aero_load[{i}]");
            ParamError::non_negative(&key, *k)?;
            ParamError::in_range(&key, *k, -f64::MIN_POSITIVE, MAX_AERO_LOAD, Limit::AeroLoad)?;
        }
        let road_bank = self.road_bank;
        ParamError::finite("road_bank", road_bank)?;
        if road_bank.abs() > MAX_ROAD_BANK {
            // Said with its sign: the range is symmetric, the value as written.
            let (lo, hi, why) = (-MAX_ROAD_BANK, MAX_ROAD_BANK, Limit::RoadBank);
            let reason = ParamReason::OutOfRange { lo, hi, why };
            return Err(ParamError::new("road_bank", road_bank, reason));
        }
        ParamError::non_negative("relaxation_length", self.relaxation_length)?;
        effect_limit(
            "bank_profile_scale",
            self.bank_profile_scale,
            -f64::MIN_POSITIVE,
            2.0,
            EffectLimit::BankProfileScale,
        )
    }

    /// The tyres' and the steering's keys: relaxation length, compliance,
    /// roll steer and camber, stiffness scales, longitudinal transfer.
    fn validate_axles(&self) -> Result<(), ParamError> {
        effect_limit(
            "relaxation_length",
            self.relaxation_length,
            -f64::MIN_POSITIVE,
            3.0,
            EffectLimit::RelaxationLength,
        )?;
        let compliance = self.steering_compliance;
        ParamError::finite("steering_compliance", compliance)?;
        // Far above any car's (1e-6 to 3e-5 rad/N), the steer lost to the
        // force exceeds the steer given and the compliance solve has no
        // physical root: a value in rad/kN is refused, not integrated.
        ParamError::in_range(
            "steering_compliance",
            compliance.abs(),
            -1e-12,
            1e-4,
            Limit::SteeringCompliance,
        )?;
        for (i, v) in self.roll_steer.iter().enumerate() {
            let key = format!("roll_steer[{i}]");
            effect_limit(&key, *v, -1.0, 1.0, EffectLimit::RollSteer)?;
        }
        for (i, v) in self.roll_camber.iter().enumerate() {
            let key = format!("roll_camber[{i}]");
            effect_limit(&key, *v, -10.0, 10.0, EffectLimit::RollCamber)?;
        }
        for (i, v) in self.cornering_stiffness_scale.iter().enumerate() {
            let key = format!("cornering_stiffness_scale[{i}]");
            ParamError::positive(&key, *v)?;
            effect_limit(&key, *v, 0.2, 5.0, EffectLimit::CorneringStiffnessScale)?;
        }
        ParamError::in_range(
            "longitudinal_load_transfer",
            self.longitudinal_load_transfer,
            -f64::MIN_POSITIVE,
            3.0,
            Limit::LongitudinalLoadTransfer,
        )
    }

    /// The diagnosis's scales, the load-transfer share, the sensors and
    /// the steer path.
    fn validate_scales_and_sensors(&self) -> Result<(), ParamError> {
        // Not read from files: set by the diagnosis within its bounds.
        ParamError::positive("yaw_inertia_scale", self.yaw_inertia_scale)?;
        ParamError::positive("friction_scale", self.friction_scale)?;
        if let Some(chi) = self.transfer_share {
            if !(0.0..=1.0).contains(&chi) {
                return Err(ParamError::new(
                    "transfer_share",
                    chi,
                    ParamReason::TransferShare,
                ));
            }
        }
        let sensors = &self.sensors;
        ParamError::non_negative("sensors.delay", sensors.delay)?;
        for (key, v) in [
            ("yaw_rate_bias", sensors.yaw_rate_bias),
            ("ay_bias", sensors.ay_bias),
            ("beta_bias", sensors.beta_bias),
            ("accelerometer_x", sensors.accelerometer_x),
            ("roll_gradient", sensors.roll_gradient),
            ("mount_yaw", sensors.mount_yaw),
        ] {
            ParamError::finite(key, v).map_err(|e| e.within("sensors"))?;
        }
        let path = &self.steer_path;
        ParamError::non_negative("delay", path.delay).map_err(|e| e.within("steer_path"))?;
        ParamError::non_negative("lag", path.lag).map_err(|e| e.within("steer_path"))?;
        ParamError::positive("gain", path.gain).map_err(|e| e.within("steer_path"))?;
        ParamError::finite("cubic", path.cubic).map_err(|e| e.within("steer_path"))
    }

    /// True when body roll feeds back into the forces (roll steer or roll
    /// camber).
    pub(crate) fn uses_roll(&self) -> bool {
        self.roll_steer != [0.0; 2] || self.roll_camber != [0.0; 2]
    }

    /// True when the model needs states beyond (β, r): lagged slip angles
    /// or body roll.
    pub(crate) fn extra_states(&self) -> bool {
        self.lagged() || self.uses_roll()
    }

    /// The effects switched on that [`super::VehicleModel::equilibrium_residual`]
    /// does not model, by their keys in `[model.effects]`: those acting
    /// through the steer the wheels see or the slip their tyres see
    /// (steering compliance, roll steer, the cornering-stiffness scale, the
    /// steer path's ratio) or
    /// through body roll (roll camber). The others are in it (aero load,
    /// road bank, the yaw-inertia and friction scales, the load-transfer
    /// share) or leave a steady state as it is: a tyre lag's states sit at
    /// the kinematic slip angles, the longitudinal effects see no
    /// longitudinal acceleration, a steady state has no measured bank
    /// profile, a steer path's delay and lag pass a constant steer
    /// unchanged (its ratio does not: listed), and the
    /// sensors act on what is measured, not on the state. Every field is
    /// named, so that a new effect must be sorted here.
    pub(crate) fn beyond_equilibrium_residual(&self) -> Vec<&'static str> {
        let Effects {
            aero_load: _,
            road_bank: _,
            bank_profile_scale: _,
            relaxation_length: _,
            steering_compliance,
            roll_steer,
            roll_camber,
            cornering_stiffness_scale,
            roll: _,
            longitudinal_load_transfer: _,
            combined_slip: _,
            yaw_inertia_scale: _,
            friction_scale: _,
            transfer_share: _,
            sensors: _,
            steer_path,
        } = self;
        [
            ("steering_compliance", *steering_compliance != 0.0),
            ("roll_steer", *roll_steer != [0.0; 2]),
            ("roll_camber", *roll_camber != [0.0; 2]),
            (
                "cornering_stiffness_scale",
                *cornering_stiffness_scale != [1.0; 2],
            ),
            (
                "steer_path",
                steer_path.gain != 1.0 || steer_path.cubic != 0.0,
            ),
        ]
        .into_iter()
        .filter_map(|(key, on)| on.then_some(key))
        .collect()
    }
}

impl<T: Scalar> Effects<T> {
    /// The values without their derivatives.
    pub fn re(&self) -> Effects {
        self.map(|x| x.re())
    }

    /// The road bank under the car, rad: the constant bank plus the scaled
    /// measured profile `measured` (read only when the scale is not zero
    /// and constant, so a missing profile cannot reach the model).
    pub fn bank(&self, measured: f64) -> T {
        if off(self.bank_profile_scale) {
            self.road_bank
        } else {
            self.road_bank + self.bank_profile_scale * measured
        }
    }

    /// True when the slip angles lag (a relaxation length of at least
    /// [`MIN_RELAXATION_LENGTH`]).
    pub fn lagged(&self) -> bool {
        self.relaxation_length.re() >= MIN_RELAXATION_LENGTH
    }
}

impl CombinedSlip {
    /// The force shares within [0, 1] and the force share within [0, 3];
    /// the error names the key within `combined_slip`.
    fn validate(&self) -> Result<(), ParamError> {
        for (key, v) in [
            ("drive_front_share", self.drive_front_share),
            ("brake_front_share", self.brake_front_share),
        ] {
            if !(0.0..=1.0).contains(&v) {
                return Err(
                    ParamError::new(key, v, ParamReason::ForceShare).within("combined_slip")
                );
            }
        }
        ParamError::in_range(
            "force_share",
            self.force_share,
            -f64::MIN_POSITIVE,
            3.0,
            Limit::LongitudinalForceShare,
        )
        .map_err(|e| e.within("combined_slip"))
    }
}

/// An effect's key `key` at `v` within `[lo, hi]`, refused with the
/// effect's reason `why`.
fn effect_limit(key: &str, v: f64, lo: f64, hi: f64, why: EffectLimit) -> Result<(), ParamError> {
    ParamError::in_range(key, v, lo, hi, Limit::Effect(why))
}
