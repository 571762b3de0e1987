//! The 2-DOF lateral/yaw vehicle model (states sideslip β and yaw rate r)
//! with four wheels and lateral load transfer.
//!
//! Equations (Li, Jia & Zhao eq. 1–2, Wang & Liang eq. 1–4), ISO 8855 axes, positive
//! steer δ turns left:
//! `m·(v̇ + u·r) = Fyf·cos δ + Fyr`, `Iz·ṙ = a·Fyf·cos δ − b·Fyr`, `v = u·tan β`,
//! with `Fyf`, `Fyr` the axle forces (sum of the two wheels), both wheels of an
//! axle at the same slip angle (Wang & Liang). Slip angles use the crate's tyre
//! sign (positive α gives positive force):
//! exact `αf = δ − atan((v + a·r)/u)`, `αr = −atan((v − b·r)/u)`;
//! small-angle (Li, Jia & Zhao) `αf = δ − β − a·r/u`, `αr = −β + b·r/u`, with
//! `m·u·(β̇ + r) + m·u̇·β = Fyf + Fyr` (no cos δ).
//!
//! Wheel loads with lateral load transfer (Wang & Liang eq. 4) and the
//! algebraic loop they close (loads depend on ay, ay on the forces) are in
//! `loads.rs`: the loop is solved at every derivative evaluation, not lagged
//! by a step, each solve seeded from the same RK stage's earlier solutions
//! so that it usually costs one evaluation of the four tyres.
//!
//! Effects beyond the papers ([`Effects`], `effects.rs`: tyre lag, steering
//! compliance, roll steer and camber through a roll degree of freedom,
//! stiffness scale, aero load, road bank, the longitudinal effects, the
//! yaw-inertia and friction scales, the load-transfer share, and the
//! sensors (`sensors.rs`) and steer path (`steer_path.rs`) that act outside
//! the right-hand side) are one struct, generic over the scalar: what a
//! scenario's `[model.effects]` reads, what the model carries and what the
//! diagnosis's candidates set. They extend the state to a [`StateVector`];
//! the one right-hand side ([`VehicleModel::rates`], in `rates.rs`, reading
//! them through [`ModelScalars`]) reduces to the (β, r) model exactly when
//! they are off. The equilibrium residual with its
//! closed-form Jacobian is in `equilibrium.rs` (that right-hand side at the
//! equilibrium's loads, written out to differentiate it; the effects it
//! leaves out named by [`Effects::beyond_equilibrium_residual`]), steady
//! states in [`steady`].
//!
//! Units: SI, rad. Speeds below `MIN_SPEED` are held at it, because the slip
//! angles of a 2-DOF model are undefined at standstill.

mod balance;
mod effects;
mod equilibrium;
mod loads;
mod pair;
mod params;
mod rates;
pub mod scalar;
mod sensors;
pub(crate) mod steady;
mod steer_path;
pub mod wheels;

pub use effects::{
    CombinedSlip, Effects, RollModel, Sensors, SteerPath, MIN_RELAXATION_LENGTH,
    PASSENGER_CAR_ROLL_GRADIENT,
};
pub use loads::{implicit_root, LoadTransferSeed};
pub use params::Vehicle;
pub use rates::StateVector;
pub(crate) use rates::{LoadSolve, SteerCosine, LOAD_TOLERANCE};
pub use scalar::{ModelScalars, Scalar};

use crate::tyre::{Tyre, TyreModel};
use serde::{Deserialize, Serialize};

// Standard gravity where the model's users have found it; its home is
// `crate::constants`, which the measured-data processing uses too.
pub use crate::constants::G;

/// Lowest forward speed the model evaluates, m/s.
pub(crate) const MIN_SPEED: f64 = 0.5;

/// How slip angles and force projections are computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum Kinematics {
    /// atan slip angles, cos δ projection, v = u·tan β (default).
    #[default]
    Exact,
    /// The small-angle form of Li, Jia & Zhao.
    #[serde(alias = "small_angle")]
    SmallAngle,
}

/// Model options; defaults are exact kinematics with load transfer.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelOptions {
    /// Slip-angle kinematics.
    #[serde(default)]
    pub kinematics: Kinematics,
    /// Lateral load transfer on (Wang & Liang) or off (axle tyres, Li, Jia & Zhao).
    #[serde(default = "yes")]
    pub load_transfer: bool,
    /// Effects beyond the papers' model, all off by default.
    #[serde(default)]
    pub effects: Effects,
}

fn yes() -> bool {
    true
}

impl Default for ModelOptions {
    fn default() -> Self {
        Self {
            kinematics: Kinematics::Exact,
            load_transfer: true,
            effects: Effects::default(),
        }
    }
}

/// Inputs at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inputs {
    /// Front road-wheel steer angle δ, rad.
    pub steer: f64,
    /// Forward speed u of the centre of gravity, m/s.
    pub speed: f64,
    /// du/dt, m/s².
    pub speed_rate: f64,
    /// Road friction as a scale on the tyres' own friction.
    pub friction: f64,
    /// Longitudinal acceleration of the centre of gravity, m/s² (positive
    /// forward): measured, or a manoeuvre's du/dt. Only the longitudinal
    /// effects read it ([`Effects::longitudinal_load_transfer`],
    /// [`Effects::combined_slip`]).
    pub ax: f64,
    /// Measured road bank under the car at this instant, rad (positive: the
    /// road's left edge higher); the model adds it, scaled by
    /// [`Effects::bank_profile_scale`], to the constant [`Effects::road_bank`].
    pub bank: f64,
}

impl Inputs {
    /// Inputs held constant in time (an equilibrium or a steady state): no
    /// speed change, no longitudinal acceleration, no measured bank.
    pub fn steady(steer: f64, speed: f64, friction: f64) -> Self {
        Self {
            steer,
            speed,
            speed_rate: 0.0,
            friction,
            ax: 0.0,
            bank: 0.0,
        }
    }
}

/// The state (β, r).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct State {
    /// Sideslip angle at the centre of gravity, rad.
    pub beta: f64,
    /// Yaw rate, rad/s.
    pub yaw_rate: f64,
}

/// Everything the model computes at one instant besides the derivatives.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Outputs {
    /// dβ/dt, rad/s.
    pub beta_rate: f64,
    /// dr/dt, rad/s².
    pub yaw_acceleration: f64,
    /// Lateral acceleration of the centre of gravity (body y), m/s².
    pub ay: f64,
    /// Front and rear slip angles, rad.
    pub alpha_front: f64,
    /// Rear slip angle, rad.
    pub alpha_rear: f64,
    /// Front axle lateral force (both wheels, wheel frame), N.
    pub fy_front: f64,
    /// Rear axle lateral force, N.
    pub fy_rear: f64,
    /// Wheel loads front-left, front-right, rear-left, rear-right, N.
    pub fz: [f64; 4],
    /// Tyre-set evaluations the load-transfer loop took (0 without transfer).
    pub load_iterations: u32,
}

/// A vehicle with its tyres and options: the right-hand side of the ODE.
#[derive(Debug, Clone, PartialEq)]
pub struct VehicleModel {
    /// Mass and geometry.
    pub vehicle: Vehicle,
    /// Tyre of each front wheel.
    pub front: Tyre,
    /// Tyre of each rear wheel.
    pub rear: Tyre,
    /// Kinematics and load-transfer options.
    pub options: ModelOptions,
}

impl VehicleModel {
    /// A model with default options.
    pub fn new(vehicle: Vehicle, front: Tyre, rear: Tyre) -> Self {
        Self {
            vehicle,
            front,
            rear,
            options: ModelOptions::default(),
        }
    }

    /// Understeer gradient K (rad per m/s² of lateral acceleration) of the
    /// linearised model at zero slip, from the axle cornering stiffnesses at
    /// static load: `K = (m/l)·(b/Cf − a/Cr)` (positive: understeer).
    pub(crate) fn understeer_gradient(&self) -> f64 {
        let v = &self.vehicle;
        let (cf, cr) = self.axle_cornering_stiffness();
        v.mass / v.wheelbase() * (v.b / cf - v.a / cr)
    }

    /// Axle cornering stiffness (front, rear) at static load, N/rad.
    pub(crate) fn axle_cornering_stiffness(&self) -> (f64, f64) {
        self.axle_cornering_stiffness_under(self.vehicle.static_axle_loads())
    }

    /// Axle cornering stiffness (front, rear) under axle loads `(front,
    /// rear)` shared evenly by the two wheels, N/rad.
    pub(crate) fn axle_cornering_stiffness_under(&self, (front, rear): (f64, f64)) -> (f64, f64) {
        (
            2.0 * self.front.cornering_stiffness(0.5 * front),
            2.0 * self.rear.cornering_stiffness(0.5 * rear),
        )
    }

    /// The larger axle's peak friction coefficient at static load on a
    /// road of friction scale `mu_scale` (infinite for a tyre with no
    /// limit): what the tyres can give the car, over its weight.
    pub fn static_peak_friction(&self, mu_scale: f64) -> f64 {
        let (front, rear) = self.vehicle.static_axle_loads();
        let f = self.front.friction_coefficient(0.5 * front, mu_scale);
        let r = self.rear.friction_coefficient(0.5 * rear, mu_scale);
        f.max(r)
    }

    /// The critical speed `√(−l/K)` of an oversteering car (K < 0,
    /// [`Self::understeer_gradient`]), m/s: above it the linearised car's
    /// straight running is unstable, and a step steer's response diverges
    /// instead of settling. None for a car that does not oversteer.
    pub fn critical_speed(&self) -> Option<f64> {
        let k = self.understeer_gradient();
        (k < 0.0).then(|| (-self.vehicle.wheelbase() / k).sqrt())
    }

    /// Textbook steady-state yaw-rate gain r/δ = u/(l + K·u²) of the linear
    /// bicycle model, 1/s.
    pub fn linear_yaw_rate_gain(&self, speed: f64) -> f64 {
        speed / (self.vehicle.wheelbase() + self.understeer_gradient() * speed * speed)
    }
}

/// The racing car of the Putnam campaign (`campaigns/putnam.toml`: mass,
/// yaw inertia, a and b from the source; tracks and CG height as assumed
/// there), whose fitted axles are stiff enough to test the replays'
/// stability on.
#[cfg(test)]
pub(crate) fn racing_car() -> Vehicle {
    Vehicle {
        mass: 790.0,
        yaw_inertia: 1000.0,
        a: 1.248,
        b: 1.7328,
        track_front: 1.6,
        track_rear: 1.55,
        cg_height: 0.3,
        ..Vehicle::compact_sedan()
    }
}

/// The textbook bicycle model the unit tests check against closed forms:
/// Wang & Liang's sedan on linear tyres (55 and 60 kN/rad per wheel),
/// small-angle kinematics, no load transfer.
#[cfg(test)]
pub(crate) fn linear_bicycle() -> VehicleModel {
    use crate::tyre::Linear;
    let mut m = VehicleModel::new(
        Vehicle::compact_sedan(),
        Tyre::Linear(Linear::new(55_000.0)),
        Tyre::Linear(Linear::new(60_000.0)),
    );
    m.options = ModelOptions {
        kinematics: Kinematics::SmallAngle,
        load_transfer: false,
        ..ModelOptions::default()
    };
    m
}

#[cfg(test)]
mod tests;
