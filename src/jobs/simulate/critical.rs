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
}

/// The step at `speed` (m/s) of `model`, where it lies above the car's
/// critical speed ([`VehicleModel::critical_speed`]).
pub(super) fn above_critical(model: &VehicleModel, speed: f64) -> Option<AboveCritical> {
    let critical = model.critical_speed()?;
    (speed.abs() > critical).then(|| AboveCritical {
        gradient: model.understeer_gradient(),
        critical,
        speed: speed.abs(),
    })
}

impl fmt::Display for AboveCritical {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let per_g = (self.gradient * crate::constants::G).to_degrees();
        write!(
            f,
            "the car oversteers (understeer gradient K = {} rad/(m/s²), {} deg/g, from the tyres' cornering stiffness at static load) and the step is at {:.1} m/s, above its critical speed √(−l/K) = {:.1} m/s: its straight running is unstable there, the response diverges instead of settling, and there is no steady state for the step-steer metrics to measure, so none are given (no metrics.json); a step below {:.1} m/s measures the handling",
            crate::format::significant(self.gradient, 3),
            crate::format::significant(per_g, 3),
            self.speed,
            self.critical,
            self.critical
        )
    }
}
