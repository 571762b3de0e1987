//! Effects beyond the papers' model, and the body-roll degree of freedom
//! they act through. Every effect is off by default, and off it changes
//! nothing: the base model stays exactly Li, Jia & Zhao's / Wang &
//! Liang's. They are what the sim-to-real diagnosis searches over
//! (its candidates set them) and what a scenario's `[model.effects]` table
//! may switch on.
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
//!   ones exactly: the effect is nested in the base model.
//!
//! Roll (the [`RollModel`]) is a second-order response of the body to the
//! lateral acceleration, `φ̈ = ω²·(k·ay − φ) − 2ζω·φ̇`.

use serde::{Deserialize, Serialize};

/// Relaxation lengths below this (m) are no lag: 1 mm is 50 µs at 20 m/s,
/// far below what a logged run resolves, and a shorter lag would make the
/// lag states stiff for explicit integration (a fit that drives σ toward
/// zero would otherwise chase it through ever stiffer models).
pub const MIN_RELAXATION_LENGTH: f64 = 1e-3;

/// Roll degree of freedom used by roll steer and roll camber: a second-order
/// response of the body roll φ to lateral acceleration,
/// `φ̈ = ω²·(k·ay − φ) − 2ζω·φ̇`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct RollModel {
    /// Steady roll per lateral acceleration k, rad per m/s².
    pub gradient: f64,
    /// Undamped natural frequency, Hz.
    pub frequency: f64,
    /// Damping ratio ζ.
    pub damping: f64,
}

impl RollModel {
    /// Checks the values for physical sense; the error names the key.
    pub fn validate(&self) -> Result<(), crate::error::ParamError> {
        use crate::error::ParamError;
        ParamError::non_negative("gradient", self.gradient)?;
        ParamError::positive("frequency", self.frequency)?;
        ParamError::positive("damping", self.damping)
    }
}

impl Default for RollModel {
    /// A passenger car: 4°/g, 1.5 Hz, ζ = 0.5.
    fn default() -> Self {
        Self {
            gradient: 4f64.to_radians() / crate::constants::G,
            frequency: 1.5,
            damping: 0.5,
        }
    }
}

/// How much of the longitudinal force `m·ax` the tyres carry through their
/// friction circles, and how it is shared between the axles: shares of the
/// front axle, the rest on the rear.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct CombinedSlip {
    /// Front share of the drive force (ax > 0): 0 for rear-wheel drive.
    pub drive_front_share: f64,
    /// Front share of the brake force (ax < 0), the brake balance.
    pub brake_front_share: f64,
    /// Share of `m·ax` the tyres carry (1: all of it; 0: none, the pure-slip
    /// forces exactly). Not a share of a whole: above 1 the tyres carry
    /// more than `m·ax` (drag and rolling resistance the throttle works
    /// against, an `ax` logged low).
    pub force_share: f64,
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

/// Effects beyond the papers' model; [`Effects::default`] is the base model.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Effects {
    /// Aerodynamic down-force per axle (front, rear), N per (m/s)²: each
    /// wheel of the axle carries half of `k·u²` on top of its static load.
    pub aero_load: [f64; 2],
    /// Road bank angle θ, rad, positive when the road's left edge is higher:
    /// gravity then pulls the car to the right with `m·g·sin θ`, the static
    /// loads scale by `cos θ`, and the accelerometer (`ay`, the tyres' force
    /// over the mass) reads `g·sin θ` more than the path's acceleration.
    pub road_bank: f64,
    /// How much of the measured bank profile ([`super::Inputs::bank`]) the
    /// road has on top of `road_bank`: 1 as measured, 0 (the default) none.
    pub bank_profile_scale: f64,
    /// Relaxation length σ of both axles, m (below
    /// [`MIN_RELAXATION_LENGTH`]: no lag).
    pub relaxation_length: f64,
    /// Steer lost per front axle force, rad/N.
    pub steering_compliance: f64,
    /// Roll steer (front, rear), rad of axle steer per rad of roll.
    pub roll_steer: [f64; 2],
    /// Camber thrust per roll (front, rear): lateral force per wheel load
    /// per rad of roll.
    pub roll_camber: [f64; 2],
    /// Scale on the slip angle each axle's tyre sees (front, rear): the
    /// cornering stiffness scaled, the peak force kept.
    pub cornering_stiffness_scale: [f64; 2],
    /// The body's roll response (drives roll steer and roll camber).
    pub roll: RollModel,
    /// Share of the rigid-body longitudinal load transfer `m·ax·h/l` at
    /// [`super::Inputs::ax`] (0: none, 1: as the CG height gives).
    pub longitudinal_load_transfer: f64,
    /// Combined slip from [`super::Inputs::ax`] (None: pure slip).
    pub combined_slip: Option<CombinedSlip>,
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
        }
    }
}

impl Effects {
    /// Checks the values for physical sense.
    pub fn validate(&self) -> Result<(), crate::error::ParamError> {
        use crate::error::{ParamError, ParamReason};
        ParamError::non_negative("aero_load[0]", self.aero_load[0])?;
        ParamError::non_negative("aero_load[1]", self.aero_load[1])?;
        ParamError::in_range(
            "road_bank",
            self.road_bank.abs(),
            -1.0,
            0.5,
            crate::error::Limit::RoadBank,
        )?;
        ParamError::finite("bank_profile_scale", self.bank_profile_scale)?;
        ParamError::non_negative("relaxation_length", self.relaxation_length)?;
        ParamError::finite("steering_compliance", self.steering_compliance)?;
        // Far above any car's (1e-6 to 3e-5 rad/N), the steer lost to the
        // force exceeds the steer given and the compliance solve has no
        // physical root: a value in rad/kN is refused, not integrated.
        ParamError::in_range(
            "steering_compliance",
            self.steering_compliance.abs(),
            -1e-12,
            1e-4,
            crate::error::Limit::SteeringCompliance,
        )?;
        for (i, v) in self.roll_steer.iter().enumerate() {
            ParamError::finite(&format!("roll_steer[{i}]"), *v)?;
        }
        for (i, v) in self.roll_camber.iter().enumerate() {
            ParamError::finite(&format!("roll_camber[{i}]"), *v)?;
        }
        for (i, v) in self.cornering_stiffness_scale.iter().enumerate() {
            ParamError::positive(&format!("cornering_stiffness_scale[{i}]"), *v)?;
        }
        ParamError::finite(
            "longitudinal_load_transfer",
            self.longitudinal_load_transfer,
        )?;
        if let Some(c) = &self.combined_slip {
            for (key, v) in [
                ("drive_front_share", c.drive_front_share),
                ("brake_front_share", c.brake_front_share),
            ] {
                if !(0.0..=1.0).contains(&v) {
                    return Err(
                        ParamError::new(key, v, ParamReason::ForceShare).within("combined_slip")
                    );
                }
            }
            ParamError::non_negative("force_share", c.force_share)
                .map_err(|e| e.within("combined_slip"))?;
        }
        self.roll.validate().map_err(|e| e.within("roll"))
    }

    /// The road bank under the car, rad: the constant bank plus the scaled
    /// measured profile `measured` (read only when the scale is not zero, so
    /// a missing profile cannot reach the model).
    pub fn bank(&self, measured: f64) -> f64 {
        if self.bank_profile_scale == 0.0 {
            self.road_bank
        } else {
            self.road_bank + self.bank_profile_scale * measured
        }
    }

    /// True when the slip angles lag (a relaxation length of at least
    /// [`MIN_RELAXATION_LENGTH`]).
    pub fn lagged(&self) -> bool {
        self.relaxation_length >= MIN_RELAXATION_LENGTH
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
}
