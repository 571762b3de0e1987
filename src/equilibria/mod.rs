//! Steering equilibria of the 2-DOF model: points (β, r) where β̇ = ṙ = 0 at a
//! fixed steer δ, friction μ and speed u (Li, Jia & Zhao), with any tyre model, with
//! or without load transfer (at equilibrium ay = u·r).
//!
//! Two independent solvers find them:
//! - [`pso`]: Li, Jia & Zhao's particle swarm on the fitness `f1² + f2²` over a box
//!   of (β, r), positions wrapped back into the box, velocities clamped; then
//!   Newton polish to machine precision, repeated with deflation so that every
//!   equilibrium in the box is found, not only the nearest;
//! - [`exact`]: a deterministic reference that parameterises the equilibria
//!   by the rear slip angle and finds all roots of one scalar function by a
//!   sign scan plus Brent's method.
//!
//! [`stability`] classifies each equilibrium from the Jacobian's eigenvalues
//! (with a tyre lag, the full state's: [`lagged`]);
//! [`bifurcation`] locates folds (saddle-node) and Hopf points along a sweep;
//! [`phase`] traces the phase plane (trajectories, separatrices) the
//! figures of the equilibria job draw.
//! Units: rad, rad/s, m/s; ISO signs (positive steer turns left).

pub(crate) mod bifurcation;
pub mod exact;
pub(crate) mod lagged;
pub(crate) mod phase;
pub mod pso;
pub(crate) mod stability;
pub mod sweep;

use crate::vehicle::{Inputs, LoadTransferSeed, State, VehicleModel};
use serde::{Deserialize, Serialize};
pub use stability::{Kind, Stability};

/// The fixed inputs of one steady-state problem.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Condition {
    /// Front road-wheel steer δ, rad.
    pub steer: f64,
    /// Road friction scale μ.
    pub friction: f64,
    /// Forward speed u, m/s.
    pub speed: f64,
}

impl Condition {
    pub(crate) fn inputs(&self) -> Inputs {
        Inputs::steady(self.steer, self.speed, self.friction)
    }
}

/// The region of the (β, r) plane searched and compared.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SearchBox {
    /// |β| limit, rad.
    pub beta_max: f64,
    /// |r| limit, rad/s.
    pub yaw_rate_max: f64,
}

impl SearchBox {
    /// Whether (β, r) lies in the box.
    pub fn contains(&self, x: [f64; 2]) -> bool {
        x[0].abs() <= self.beta_max && x[1].abs() <= self.yaw_rate_max
    }
    /// Bounds as PSO wants them.
    pub fn bounds(&self) -> [(f64, f64); 2] {
        [
            (-self.beta_max, self.beta_max),
            (-self.yaw_rate_max, self.yaw_rate_max),
        ]
    }
    /// Scale used to measure distances in the (β, r) plane.
    pub fn scale(&self) -> [f64; 2] {
        [self.beta_max, self.yaw_rate_max]
    }
}

/// Which solver found an equilibrium.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FoundBy {
    /// Only the PSO search.
    Pso,
    /// Only the exact reference.
    Exact,
    /// Both.
    Both,
}

/// One equilibrium.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Equilibrium {
    /// Sideslip, rad.
    pub beta: f64,
    /// Yaw rate, rad/s.
    pub yaw_rate: f64,
    /// Stability from the Jacobian.
    pub stability: Stability,
    /// max(|β̇|, |ṙ|) at the point.
    pub residual: f64,
    /// Rear slip angle, rad (orders the equilibria along the exact solver's
    /// parameterisation).
    pub alpha_rear: f64,
}

/// The right-hand side (β̇, ṙ) at a state; the load-transfer solve is seeded
/// with ay = u·r (exact at an equilibrium) and solved to 1e-13, so numerical
/// Jacobians are clean.
pub fn residual(model: &VehicleModel, c: &Condition, x: [f64; 2]) -> [f64; 2] {
    residual_to(model, c, x, 1e-13)
}

/// The right-hand side with the load-transfer loop solved to `tolerance`
/// (the PSO fitness needs no more than the simulation's 1e-9).
pub(crate) fn residual_to(
    model: &VehicleModel,
    c: &Condition,
    x: [f64; 2],
    tolerance: f64,
) -> [f64; 2] {
    let ay = c.speed * x[1] + model.bank_acceleration();
    let mut seed = LoadTransferSeed {
        ay: [ay; 3],
        slope: 1.0,
    };
    residual_seeded(model, c, x, tolerance, &mut seed)
}

/// The right-hand side with the load-transfer solve started from `seed`
/// (and its solution left there): a point next to one just evaluated (a
/// finite-difference neighbour) then costs one or two tyre-set evaluations.
pub(crate) fn residual_seeded(
    model: &VehicleModel,
    c: &Condition,
    x: [f64; 2],
    tolerance: f64,
    seed: &mut LoadTransferSeed,
) -> [f64; 2] {
    let o = model.evaluate_to(
        &State {
            beta: x[0],
            yaw_rate: x[1],
        },
        &c.inputs(),
        seed,
        tolerance,
    );
    [o.beta_rate, o.yaw_acceleration]
}

/// The right-hand side with the wheel loads taken at the lateral
/// acceleration an equilibrium at `x` would have, ay = u·r (+ g·sin θ),
/// instead of solving the load-transfer loop: one evaluation of the four
/// tyres instead of several. Its roots are exactly the equilibria: at a
/// root β̇ = 0 makes the tyres' Y/m equal u·r (+ g·sin θ), so the loads
/// taken are the loop's solution and ṙ is the model's; and at an
/// equilibrium the loop's solution is ay = u·r. Away from the roots it
/// differs from [`residual`], which is why only the swarm's fitness uses
/// it: polish, indices and the winding certificate use the model itself.
pub(crate) fn residual_at_equilibrium_loads(
    model: &VehicleModel,
    c: &Condition,
    x: [f64; 2],
) -> [f64; 2] {
    let ay = c.speed.max(crate::vehicle::MIN_SPEED) * x[1] + model.bank_acceleration();
    let mut seed = LoadTransferSeed {
        ay: [ay; 3],
        slope: 1.0,
    };
    // An infinite tolerance stops the loop after its first evaluation, at
    // the seed's ay.
    residual_seeded(model, c, x, f64::INFINITY, &mut seed)
}

/// Newton polish of a point toward an equilibrium; `None` when it does not
/// converge to max(|β̇|, |ṙ|) ≤ 1e-12.
pub fn polish(model: &VehicleModel, c: &Condition, x0: [f64; 2]) -> Option<[f64; 2]> {
    let f = |x: [f64; 2]| residual(model, c, x);
    let (x, _) = crate::vehicle::steady::newton2(f, x0, [0.01, 0.01], 1e-13, 40)?;
    let r = f(x);
    (r[0].abs().max(r[1].abs()) <= 1e-12 && x[0].abs() < std::f64::consts::FRAC_PI_2).then_some(x)
}

/// Newton polish as [`polish`], iterated first on
/// [`residual_at_equilibrium_loads`] with its closed-form Jacobian
/// ([`VehicleModel::equilibrium_residual`]: the same roots at a fraction of
/// the cost) and then confirmed on the model, which at a root of the former
/// usually takes one evaluation. `None` when either does not converge.
pub(crate) fn polish_fast(model: &VehicleModel, c: &Condition, x0: [f64; 2]) -> Option<[f64; 2]> {
    let inputs = c.inputs();
    let f = |x: [f64; 2]| {
        model.equilibrium_residual(
            &State {
                beta: x[0],
                yaw_rate: x[1],
            },
            &inputs,
        )
    };
    crate::vehicle::steady::newton2_analytic(f, x0, 1e-13, 40)
        .and_then(|(x, _)| polish(model, c, x))
}

/// An equilibrium record at a point already known to be one.
pub(crate) fn describe(model: &VehicleModel, c: &Condition, x: [f64; 2]) -> Equilibrium {
    let r = residual(model, c, x);
    let (_, alpha_rear) = model.slip_angles(
        &State {
            beta: x[0],
            yaw_rate: x[1],
        },
        &c.inputs(),
    );
    Equilibrium {
        beta: x[0],
        yaw_rate: x[1],
        stability: lagged::classify(model, c, x),
        residual: r[0].abs().max(r[1].abs()),
        alpha_rear,
    }
}

/// Scaled distance between two (β, r) points.
pub(crate) fn distance(a: [f64; 2], b: [f64; 2], scale: [f64; 2]) -> f64 {
    ((a[0] - b[0]) / scale[0]).hypot((a[1] - b[1]) / scale[1])
}

#[cfg(test)]
mod tests;
