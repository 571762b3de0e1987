//! The augmented model of the sim-to-real diagnosis: the base vehicle
//! model ([`crate::vehicle`]) with the candidate effects of
//! [`super::effects`] switched on, and its replay of a run.
//!
//! The physics is the vehicle model's own ([`VehicleModel::rates`], with
//! its [`crate::vehicle::Effects`]), integrated by the simulation's
//! integrator ([`Integrator::replay`]: RK4 on a grid where the run's inputs
//! are sampled once, [`Drive`], so repeated replays only evaluate the
//! model). What this module adds is the mapping of a candidate's values
//! ([`EffectSet`]) onto the model — effects set, vehicle values scaled, road
//! friction scaled — and the sensors ([`super::sensors::Sensors`]) applied
//! to the response. With every effect off it is the base model (tested
//! against [`crate::sim::Integrator::run`]). Units: SI, rad.

use super::effects::EffectSet;
use crate::manoeuvre::interpolate;
pub use crate::sim::{Drive, FixedStep};
use crate::sim::{Integrator, TimeHistory};
use crate::vehicle::{CombinedSlip, RollModel, State, StateVector, VehicleModel};

/// The base model with effects.
#[derive(Debug, Clone, PartialEq)]
pub struct Augmented {
    /// The base model (vehicle, tyres, kinematics, load transfer).
    pub base: VehicleModel,
    /// Road friction scale of the campaign.
    pub friction: f64,
    /// The roll degree of freedom.
    pub roll: RollModel,
    /// The effects (default: none).
    pub effects: EffectSet,
}

impl Augmented {
    /// The base model alone.
    pub fn new(base: VehicleModel, friction: f64) -> Self {
        Self {
            base,
            friction,
            roll: RollModel::default(),
            effects: EffectSet::default(),
        }
    }

    /// Whether `other` integrates the same history as this model from the
    /// same state: the two differ at most in their sensors, which act on the
    /// response only (their offsets move the start state, which the caller
    /// compares).
    pub fn same_dynamics(&self, other: &Augmented) -> bool {
        let mut effects = other.effects;
        effects.sensors = self.effects.sensors;
        self.base == other.base
            && self.friction == other.friction
            && self.roll == other.roll
            && self.effects == effects
    }

    /// The vehicle model with the vehicle-side effects applied, and the road
    /// friction it runs on.
    pub fn model(&self) -> (VehicleModel, f64) {
        let e = &self.effects;
        let mut model = self.base.clone();
        if let Some(chi) = e.load_transfer_front_share {
            model.vehicle.load_transfer_front_share = Some(chi);
        }
        if let Some(s) = e.yaw_inertia_scale {
            model.vehicle.yaw_inertia *= s;
        }
        let x = &mut model.options.effects;
        // Aero load and bank add to what the campaign's base model has.
        x.aero_load = [
            x.aero_load[0] + e.aero_load[0],
            x.aero_load[1] + e.aero_load[1],
        ];
        x.road_bank += e.road_bank;
        x.relaxation_length = e.relaxation_length;
        x.steering_compliance = e.steering_compliance;
        x.roll_steer = e.roll_steer;
        x.roll_camber = e.roll_camber;
        x.cornering_stiffness_scale = e.cornering_stiffness_scale.unwrap_or([1.0; 2]);
        // Like aero and bank, the longitudinal effects and the bank profile
        // add to (or, for combined slip, replace) the base model's own.
        x.longitudinal_load_transfer += e.longitudinal_load_transfer;
        if let Some([drive, brake]) = e.combined_slip {
            x.combined_slip = Some(CombinedSlip {
                drive_front_share: drive,
                brake_front_share: brake,
            });
        }
        x.bank_profile_scale += e.bank_profile[0];
        x.road_bank += e.bank_profile[1];
        x.roll = self.roll;
        (model, self.friction * e.friction_scale.unwrap_or(1.0))
    }

    /// The state that starts a replay at sideslip `beta` and yaw rate
    /// `yaw_rate`: lag states at their kinematic slip angles, roll at its
    /// steady value for ay = u·r.
    pub fn initial_state(&self, drive: &Drive, beta: f64, yaw_rate: f64) -> StateVector {
        let (model, friction) = self.model();
        Self::quasi_static(&model, friction, drive, beta, yaw_rate)
    }

    fn quasi_static(
        model: &VehicleModel,
        friction: f64,
        drive: &Drive,
        beta: f64,
        yaw_rate: f64,
    ) -> StateVector {
        let x = State { beta, yaw_rate };
        model.quasi_static_state(&x, &drive.first_inputs(friction))
    }

    /// Replays the drive from `x0`; the history carries the roll.
    pub fn simulate(&self, drive: &Drive, x0: StateVector) -> TimeHistory {
        let (model, friction) = self.model();
        Self::replay(&model, friction, drive, x0)
    }

    /// Replays the drive from the state [`Augmented::initial_state`] gives
    /// for `beta` and `yaw_rate`, building the model once (the fits replay
    /// every run at every evaluation).
    pub fn simulate_from(&self, drive: &Drive, beta: f64, yaw_rate: f64) -> TimeHistory {
        let (model, friction) = self.model();
        let x0 = Self::quasi_static(&model, friction, drive, beta, yaw_rate);
        Self::replay(&model, friction, drive, x0)
    }

    fn replay(model: &VehicleModel, friction: f64, drive: &Drive, x0: StateVector) -> TimeHistory {
        let integrator = Integrator {
            friction,
            ..Integrator::default()
        };
        integrator.replay(model, drive, x0)
    }

    /// What the sensors record of a response, interpolated at `times`:
    /// (yaw rate, ay, β).
    pub fn observe(&self, response: &TimeHistory, times: &[f64]) -> Observed {
        let seen = self.effects.sensors.measure(response);
        let at = |ys: &[f64]| -> Vec<f64> {
            times.iter().map(|&t| interpolate(&seen.t, ys, t)).collect()
        };
        Observed {
            yaw_rate: at(&seen.yaw_rate),
            ay: at(seen.ay.as_deref().unwrap_or(&[])),
            beta: at(seen.beta.as_deref().unwrap_or(&[])),
            roll: times
                .iter()
                .map(|&t| interpolate(&response.t, &response.roll, t))
                .collect(),
        }
    }
}

/// Simulated measurements at a run's sample times.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Observed {
    /// Yaw rate, rad/s.
    pub yaw_rate: Vec<f64>,
    /// Lateral acceleration as the accelerometer reads it, m/s².
    pub ay: Vec<f64>,
    /// Sideslip, rad.
    pub beta: Vec<f64>,
    /// Body roll (the model's state, without sensor effects), rad.
    pub roll: Vec<f64>,
}

#[cfg(test)]
mod tests;
