//! A step steer of an oversteering car above its critical speed: the
//! linearised car's straight running is unstable there (its yaw mode has
//! a positive eigenvalue), so its response to any steer diverges and no
//! steady state exists for the step-steer metrics to measure. On linear
//! tyres the divergence never stops (a tester's sedan at 45 m/s, critical
//! speed 38.3 m/s, reported a yaw-rate gain of 39,126 1/s and a steady
//! sideslip of −1,102° as a slide "past its grip", on tyres without one).
//! Tyres that saturate may catch it in a turn of their own; their run is
//! judged by whether it settled. Units: SI, rad; printed in m/s and deg/g.

use crate::vehicle::VehicleModel;
use std::fmt;

/// An oversteering car stepped above its critical speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct AboveCritical {
    /// The understeer gradient at static loads, rad/(m/s²) (negative).
    gradient: f64,
    /// The critical speed `√(−l/K)`, m/s.
    critical: f64,
    /// The step's speed, m/s.
    speed: f64,
    /// The road's friction the stiffness is taken at.
    friction: f64,
    /// The static axle loads the stiffness is taken at, N (front, rear).
    loads: [f64; 2],
}

impl AboveCritical {
    /// The integration's stall at `at` of `end` (s) of this step, said
    /// as its divergence.
    pub(super) fn stalled(&self, at: f64, end: f64) -> crate::error::ScenarioProblem {
        crate::error::ScenarioProblem::StalledAboveCritical {
            at,
            end,
            gradient: self.gradient,
            critical: self.critical,
            speed: self.speed,
            loads: self.loads,
        }
    }
}

/// The step at `speed` (m/s) of `model` on a road of friction `friction`
/// (the scenario's), where it lies above the car's critical speed there.
pub(super) fn above_critical(
    model: &VehicleModel,
    friction: f64,
    speed: f64,
) -> Option<AboveCritical> {
    let gradient = understeer_gradient_at(model, friction, speed);
    let critical = critical_speed_of(model, gradient)?;
    (speed.abs() > critical).then_some(AboveCritical {
        gradient,
        critical,
        speed: speed.abs(),
        friction,
        loads: {
            let (front, rear) = model.vehicle.static_axle_loads();
            [front, rear]
        },
    })
}

/// The understeer gradient `K = (m/l)·(b/Cf − a/Cr)` of the linearised
/// car at road friction `friction` and speed `speed`, rad/(m/s²), each
/// axle's cornering stiffness at zero slip under its static load a
/// central difference of the tyre's own force on that road (the
/// simplified Magic Formula's slope is `B·C·D·μ` per unit load: on a road
/// of friction 0.5 it is half the slope at 1, which
/// [`VehicleModel::critical_speed`] takes, and the critical speed is
/// √2 lower).
pub(crate) fn understeer_gradient_at(model: &VehicleModel, friction: f64, speed: f64) -> f64 {
    let v = &model.vehicle;
    let (front, rear) = v.static_axle_loads();
    let h = 1e-6;
    let axle = |tyre: &dyn crate::tyre::TyreModel, load: f64| {
        let s = |alpha| crate::tyre::SlipState {
            alpha,
            kappa: 0.0,
            fz: 0.5 * load,
            camber: 0.0,
            mu_scale: model.options.effects.friction_scale * friction,
            speed,
        };
        2.0 * (tyre.lateral_force(&s(h)) - tyre.lateral_force(&s(-h))) / (2.0 * h)
    };
    let (cf, cr) = (axle(&model.front, front), axle(&model.rear, rear));
    v.mass / v.wheelbase() * (v.b / cf - v.a / cr)
}

/// The critical speed √(−l/K) of `model` with understeer gradient
/// `gradient` (rad/(m/s²)), m/s; None for a car that does not oversteer.
pub(crate) fn critical_speed_of(model: &VehicleModel, gradient: f64) -> Option<f64> {
    (gradient < 0.0).then(|| (-model.vehicle.wheelbase() / gradient).sqrt())
}

impl fmt::Display for AboveCritical {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let per_g = (self.gradient * crate::constants::G).to_degrees();
        write!(
            f,
            "the car oversteers (understeer gradient K = {} rad/(m/s²), {} deg/g, from the tyres' cornering stiffness at static load{}) and the step is at {:.1} m/s, above its critical speed √(−l/K) = {:.1} m/s: its straight running is unstable there, the response diverges instead of settling, and there is no steady state for the step-steer metrics to measure, so none are given (no metrics.json); a step below {:.1} m/s measures the handling",
            crate::format::significant(self.gradient, 3),
            crate::format::significant(per_g, 3),
            // A tyre whose slope scales with the road's friction (the
            // simplified Magic Formula's B·C·D·μ) has another K there.
            if self.friction == 1.0 {
                String::new()
            } else {
                format!(" on this road of friction {}", self.friction)
            },
            self.speed,
            self.critical,
            self.critical
        )
    }
}
