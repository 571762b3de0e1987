//! A run whose error-controlled integration stalled before the
//! manoeuvre's end ([`crate::sim::ode::step_budget`]), refused with its
//! cause as far as the scenario tells it ([`StallCause`]): a step above an
//! oversteering car's critical speed as its divergence ([`critical`]); a
//! step whose linearised car asks for a steady lateral acceleration beyond
//! the lift-off of its inner wheels or its tyres' grip (near the critical
//! speed or not) by those numbers, and on linear tyres, which have no grip
//! limit, the step that keeps the turn within the road's μ·g too (the
//! speed that only kept the car on four wheels ran at 1.39 g); a large
//! steer as one. A tester's 1° step 2 m/s under the critical speed was
//! said as "linear tyres at a large steer". Units: SI, rad.

use super::{checks, critical};
use crate::error::{
    AskedTurn, Error, InputError, InputProblem, ScenarioProblem, StallCause, TurnLimit, LARGE_STEER,
};
use crate::io::Scenario;
use crate::manoeuvre::{Manoeuvre, StepSteer};
use crate::sim::{Simulation, TimeHistory};
use crate::vehicle::VehicleModel;
use std::path::Path;

/// The most lateral acceleration searched for a wheel's lift-off, m/s²
/// (100 g): a car whose wheels stay down beyond it transfers no load.
const LIFT_SEARCH: f64 = 100.0 * crate::constants::G;

/// Refuses a run whose integration stalled before the manoeuvre's end:
/// its history would end there.
pub(super) fn refuse_stalled(path: &Path, sc: &Scenario, sim: &Simulation) -> Result<(), Error> {
    let Some(w) = sim.work.filter(|w| w.stalled) else {
        return Ok(());
    };
    let at = sim.history.t.last().copied().unwrap_or(f64::NAN);
    let end = sc.manoeuvre.end_time();
    // A step above the critical speed diverges whatever the integrator:
    // said as such, as the same step run through is (RK4, no load
    // transfer), not as a model that is not smooth.
    let above = match &sc.manoeuvre {
        Manoeuvre::StepSteer(s) => {
            critical::above_critical(&sc.model, sc.integrator.friction, s.speed)
        }
        _ => None,
    };
    let problem = match above {
        Some(a) => a.stalled(at, end),
        None => ScenarioProblem::Stalled {
            at,
            end,
            steps: w.accepted + w.rejected,
            cause: cause(sc, &sim.history),
        },
    };
    Err(InputError::problem(path, InputProblem::Scenario(Box::new(problem))).into())
}

/// Why the run of `sc` stalled, as far as its numbers tell: a step's
/// steady turn beyond the car's limit, else a steer beyond
/// [`LARGE_STEER`] (the step's, or the largest in the rows `h` before the
/// stall), else unknown.
fn cause(sc: &Scenario, h: &TimeHistory) -> StallCause {
    if let Manoeuvre::StepSteer(s) = &sc.manoeuvre {
        if let Some(a) = asked_turn(sc, s) {
            return StallCause::Asked(a);
        }
    }
    let steer = match &sc.manoeuvre {
        Manoeuvre::StepSteer(s) => s.amplitude.abs(),
        _ => h.steer.iter().fold(0.0, |m: f64, d| m.max(d.abs())),
    };
    match steer > LARGE_STEER {
        true => StallCause::LargeSteer(steer),
        false => StallCause::Unknown,
    }
}

/// The step `s`'s steady turn on the linearised car (understeer gradient
/// at the static axle loads on the scenario's road), where it lies beyond
/// the lower of the inner wheels' lift-off and the tyres' grip.
fn asked_turn(sc: &Scenario, s: &StepSteer) -> Option<AskedTurn> {
    let speed = s.speed.abs();
    let lift = TurnLimit::Lift(lift_off_ay(&sc.model, speed));
    let grip = checks::axle_friction(sc)
        .map(|[f, r]| f.min(r))
        .map(|mu| TurnLimit::Grip(mu * crate::constants::G, mu));
    let limit = match grip {
        Some(g) if g.ay() < lift.ay() => g,
        _ => lift,
    };
    // Linear tyres hold any turn short of lift-off: the advice keeps it
    // within the road's μ·g as well, which a car on real tyres holds.
    let mu = sc.integrator.friction;
    let unlimited = super::unlimited::unlimited_tyres(&sc.model).is_some();
    let road = (unlimited && mu * crate::constants::G < limit.ay()).then_some(mu);
    let turn = AskedTurn {
        speed,
        steer: s.amplitude.abs(),
        wheelbase: sc.model.vehicle.wheelbase(),
        gradient: critical::understeer_gradient_at(&sc.model, mu, speed),
        limit,
        road,
    };
    let asked = turn.asked();
    (limit.ay().is_finite() && asked.is_finite() && asked > limit.ay()).then_some(turn)
}

/// The lateral acceleration (m/s², either sign alike) at which the first
/// wheel of `model` at `speed` (m/s, for its aero load) lifts off, by
/// bisection on the model's own wheel loads; infinite where none lifts
/// within [`LIFT_SEARCH`] (no load transfer).
fn lift_off_ay(model: &VehicleModel, speed: f64) -> f64 {
    let lifted = |ay: f64| model.wheel_loads_at(ay, speed).iter().any(|fz| *fz <= 0.0);
    if !lifted(LIFT_SEARCH) {
        return f64::INFINITY;
    }
    let (mut lo, mut hi) = (0.0, LIFT_SEARCH);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        match lifted(mid) {
            true => hi = mid,
            false => lo = mid,
        }
    }
    hi
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::constants::G;

    /// A rigid car whose transfer share is b/l lifts both inner wheels
    /// at once, at its static stability factor g·t/(2h).
    #[test]
    fn the_lift_off_of_a_rigid_car_is_its_static_stability_factor() {
        use crate::tyre::{Linear, Tyre};
        use crate::vehicle::{Vehicle, VehicleModel};
        let tyre = Tyre::Linear(Linear::new(57_296.0));
        let model = VehicleModel::new(Vehicle::compact_sedan(), tyre.clone(), tyre);
        let v = &model.vehicle;
        let sff = G * v.track_front.min(v.track_rear) / (2.0 * v.cg_height);
        let lift = lift_off_ay(&model, 20.0);
        assert!((lift - sff).abs() < 1e-9 * sff, "{lift} against {sff}");
    }
}
