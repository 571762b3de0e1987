//! The augmented model of the sim-to-real diagnosis: the base vehicle
//! model ([`crate::vehicle`]) with the candidate effects of
//! [`crate::diagnose::effects`] switched on, and its replay of a run.
//!
//! The physics is the vehicle model's own ([`VehicleModel::rates`], with
//! its [`crate::vehicle::Effects`]), integrated by the simulation's
//! integrator ([`Integrator::replay`]: RK4 on a grid where the run's inputs
//! are sampled once, [`Drive`], so repeated replays only evaluate the
//! model). What this module adds is the mapping of a candidate's values
//! ([`EffectSet`]) onto the model — effects set, vehicle values scaled, road
//! friction scaled — and the sensors ([`crate::diagnose::effects::sensors::Sensors`]) applied
//! to the response. With every effect off it is the base model (tested
//! against [`crate::sim::Integrator::run`]).
//!
//! The steer path ([`SteerPath`]: an actuator's delay and first-order lag
//! between the logged steer and the road wheels) is linear in the input,
//! so it is no state of the model: a replay whose steer path is on runs a
//! copy of the drive whose steer samples are the path's exact output for
//! the logged (piecewise-linear) steer ([`Augmented::steered`]); one whose
//! path is off runs the drive itself. [`Augmented::simulate`] replays the
//! drive it is given: the callers that replay logged runs
//! ([`crate::diagnose::model::replay::Prepared::drive_for`], the proving ground) pass it
//! through [`Augmented::steered`] first. Units: SI, rad.

pub(crate) mod axles;
pub(crate) mod channels;
pub(crate) mod replay;

use crate::diagnose::effects::EffectSet;
use crate::manoeuvre::{interpolate, interpolate_of};
use crate::scalar::{off, Scalar};
pub use crate::sim::{Drive, FixedStep};
use crate::sim::{Integrator, TimeHistory};
use crate::vehicle::{CombinedSlip, RollModel, State, StateVector, VehicleModel, LOAD_TOLERANCE};
use std::borrow::Cow;

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
    pub(crate) fn same_dynamics(&self, other: &Augmented) -> bool {
        let mut effects = other.effects;
        effects.sensors = self.effects.sensors;
        self.base == other.base
            && self.friction == other.friction
            && self.roll == other.roll
            && self.effects == effects
    }

    /// The vehicle model with the vehicle-side effects applied, and the road
    /// friction it runs on.
    pub(crate) fn model(&self) -> (VehicleModel, f64) {
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
        if let Some([drive, brake, share]) = e.combined_slip {
            x.combined_slip = Some(CombinedSlip {
                drive_front_share: drive,
                brake_front_share: brake,
                force_share: share,
            });
        }
        x.bank_profile_scale += e.bank_profile[0];
        x.road_bank += e.bank_profile[1];
        x.roll = self.roll;
        (model, self.friction * e.friction_scale.unwrap_or(1.0))
    }

    /// The steer path of its effects.
    pub(crate) fn steer_path(&self) -> SteerPath {
        let [delay, lag] = self.effects.steer_path;
        SteerPath { delay, lag }
    }

    /// The drive the road wheels see when the steer logged as (`t`,
    /// `steer`), which `drive` samples, goes through the steer path:
    /// `drive` itself while the path is off (so the replay is the base
    /// model's bit for bit), else a copy whose steer at every stage time is
    /// the path's output (`SteerPath::apply`).
    pub(crate) fn steered<'d>(&self, drive: &'d Drive, t: &[f64], steer: &[f64]) -> Cow<'d, Drive> {
        let path = self.steer_path();
        if path.is_off() {
            Cow::Borrowed(drive)
        } else {
            let wheel = path.apply(t, steer, &drive.stage_times());
            Cow::Owned(drive.clone().with_steer(wheel))
        }
    }

    /// The state that starts a replay at sideslip `beta` and yaw rate
    /// `yaw_rate`: lag states at their kinematic slip angles, roll at its
    /// steady value for ay = u·r.
    pub(crate) fn initial_state(&self, drive: &Drive, beta: f64, yaw_rate: f64) -> StateVector {
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
    pub(crate) fn simulate(&self, drive: &Drive, x0: StateVector) -> TimeHistory {
        let (model, friction) = self.model();
        Self::replay(&model, friction, drive, x0, LOAD_TOLERANCE)
    }

    /// Replays the drive from the state [`Augmented::initial_state`] gives
    /// for `beta` and `yaw_rate`, building the model once (the fits replay
    /// every run at every evaluation).
    #[cfg(test)]
    pub(crate) fn simulate_from(&self, drive: &Drive, beta: f64, yaw_rate: f64) -> TimeHistory {
        self.simulate_from_to(drive, beta, yaw_rate, LOAD_TOLERANCE)
    }

    /// [`Augmented::simulate_from`] with the load-transfer loop solved to
    /// relative tolerance `tol`.
    pub(crate) fn simulate_from_to(
        &self,
        drive: &Drive,
        beta: f64,
        yaw_rate: f64,
        tol: f64,
    ) -> TimeHistory {
        let (model, friction) = self.model();
        let x0 = Self::quasi_static(&model, friction, drive, beta, yaw_rate);
        Self::replay(&model, friction, drive, x0, tol)
    }

    fn replay(
        model: &VehicleModel,
        friction: f64,
        drive: &Drive,
        x0: StateVector,
        tol: f64,
    ) -> TimeHistory {
        let integrator = Integrator {
            friction,
            ..Integrator::default()
        };
        integrator.replay_to(model, drive, x0, tol)
    }

    /// What the sensors record of a response, interpolated at `times`:
    /// (yaw rate, ay, β).
    pub(crate) fn observe(&self, response: &TimeHistory, times: &[f64]) -> Observed {
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

/// The steer path between the logged steer δ and the road wheels:
/// δ_wheel(t) = lag_τ(δ(t − delay)), with lag_τ a first-order lag of time
/// constant `lag` (dy/dt = (u − y)/τ). The logged steer is the
/// piecewise-linear signal through its samples, held at its first sample
/// before the start (and at its last after the end), and the lag starts
/// settled on that first sample. Its numbers may be dual numbers
/// ([`crate::scalar`]): the output then carries their derivatives.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SteerPath<T = f64> {
    /// Dead time, s (≥ 0).
    pub delay: T,
    /// Time constant of the first-order lag, s (≥ 0; 0: none).
    pub lag: T,
}

impl<T: Scalar> SteerPath<T> {
    /// Whether the road wheels follow the logged steer as it is.
    pub fn is_off(&self) -> bool {
        off(self.delay) && off(self.lag)
    }

    /// The road-wheel steer at times `at` (in any order) of the steer
    /// logged at increasing times `t` (repeated times allowed: a jump). The
    /// delay interpolates the samples at `at − delay`; the lag is the exact
    /// discretisation of the first-order lag driven by the delayed
    /// piecewise-linear input, stepped from one break point or output time
    /// to the next (the delayed input is linear between them), so the
    /// output is exact to round-off at every time asked for, whatever the
    /// spacing. Without a lag, a lag being differentiated at zero adds its
    /// one-sided derivative `−τ·δ̇` (value unchanged).
    pub fn apply(&self, t: &[f64], steer: &[f64], at: &[f64]) -> Vec<T> {
        assert_eq!(t.len(), steer.len(), "one steer per time");
        assert!(!t.is_empty(), "a steer path needs samples");
        let delay = self.delay;
        let logged: Vec<T> = steer.iter().map(|&v| T::from(v)).collect();
        if self.lag.re() <= 0.0 {
            return at
                .iter()
                .map(|&s| {
                    let y = interpolate_of(t, &logged, T::from(s) - delay);
                    if self.lag.is_constant() {
                        y
                    } else {
                        y - self.lag * slope_below(t, steer, s - delay.re())
                    }
                })
                .collect();
        }
        let tau = self.lag;
        let one = T::from(1.0);
        // One exact step of h of the lag from y with the input linear from
        // u0 to u1: y·a + (1 − a)·u0 + (u1 − u0)·(1 − (1 − a)/x), with
        // x = h/τ and a = e^(−x).
        let advance = |y: T, u0: T, u1: T, h: T| -> T {
            let x = h / tau;
            if x.re() <= 0.0 {
                // A step of no length whose ends move with the parameters
                // (an output time on a delayed break point): the lag's
                // first-order change, zero in value.
                return if x.is_constant() { y } else { y + (u0 - y) * x };
            }
            let one_minus_a = -(-x).exp_m1();
            let a = one - one_minus_a;
            // 1 − (1 − a)/x: in dual numbers by its series for a short
            // step, whose quotient of two small numbers would lose the
            // derivative to rounding (the value is the same to rounding).
            let ramp = if T::PLAIN || x.re() > 1e-3 {
                one - one_minus_a / x
            } else {
                x * (one - x * (one - x * 0.25) * (1.0 / 3.0)) * 0.5
            };
            a * y + one_minus_a * u0 + (u1 - u0) * ramp
        };
        let mut order: Vec<usize> = (0..at.len()).collect();
        order.sort_by(|&i, &j| at[i].total_cmp(&at[j]));
        let node = |j: usize| delay + t[j];
        let mut out = vec![T::from(0.0); at.len()];
        // The state: time, input and output there; the next break point.
        let (mut s, mut u, mut y) = (node(0), logged[0], logged[0]);
        let mut j = 1;
        // An output time on a break point whose time moves with the delay
        // still steps (by nothing in value) to carry its derivative.
        let ahead = |q: f64, s: T| q > s.re() || (q == s.re() && !s.is_constant());
        for i in order {
            let q = at[i];
            if ahead(q, s) {
                while j < t.len() && node(j).re() <= q {
                    y = advance(y, u, logged[j], node(j) - s);
                    (s, u) = (node(j), logged[j]);
                    j += 1;
                }
                if ahead(q, s) {
                    let uq = if j < t.len() {
                        let w = (T::from(q) - delay - t[j - 1]) / (t[j] - t[j - 1]);
                        logged[j - 1] + w * (steer[j] - steer[j - 1])
                    } else {
                        u
                    };
                    y = advance(y, u, uq, T::from(q) - s);
                    (s, u) = (T::from(q), uq);
                }
            }
            out[i] = y;
        }
        out
    }
}

/// The slope of the piecewise-linear signal (`t`, `y`) just below time `x`
/// (0 outside it and across a jump).
fn slope_below(t: &[f64], y: &[f64], x: f64) -> f64 {
    let k = t.partition_point(|v| *v < x);
    if k == 0 || k >= t.len() || t[k] <= t[k - 1] {
        0.0
    } else {
        (y[k] - y[k - 1]) / (t[k] - t[k - 1])
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
mod nesting_tests;
#[cfg(test)]
mod tests;
