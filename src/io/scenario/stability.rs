//! RK4's stability at the scenario's fixed step: the model's fastest rate
//! ρ ([`VehicleModel::fastest_rate`]: a tyre lag's `u/σ`, the bicycle
//! model's modes, body roll) over the manoeuvre's speeds against RK4's
//! limit `h·ρ ≤` [`RK4_STABILITY_LIMIT`]. Beyond it the run blows up
//! (a 0.05 s step with σ = 0.3 m at 40 m/s: h·ρ = 6.7, angles of 1e162
//! rad); it is refused at the step, or at the method where the step is
//! the default. Dormand–Prince chooses its own steps and is not checked.
//! Units: s, 1/s, m/s.

use super::{rows::integration_table, SimulationSettings};
use crate::error::{InputError, InputProblem, ScenarioProblem, UnstableStep, RK4_STABILITY_LIMIT};
use crate::io::toml_file::TomlSource;
use crate::manoeuvre::Manoeuvre;
use crate::sim::Method;
use crate::vehicle::VehicleModel;

/// Speeds sampled over the run: the fastest rate is a smooth function of
/// speed, and a manoeuvre's speed changes slowly against its length.
const SPEED_SAMPLES: usize = 400;

/// Refuses an RK4 step beyond the stability limit of `model` on a road of
/// `friction` at any speed of `m`.
pub(super) fn check(
    src: &TomlSource,
    s: &SimulationSettings,
    method: Method,
    model: &VehicleModel,
    friction: f64,
    m: &Manoeuvre,
) -> Result<(), InputError> {
    if method != Method::Rk4 {
        return Ok(());
    }
    let (t0, t1) = (m.start_time(), m.end_time());
    let (rate, speed) = (0..=SPEED_SAMPLES)
        .map(|k| {
            let u = m.speed(t0 + (t1 - t0) * k as f64 / SPEED_SAMPLES as f64);
            (model.fastest_rate(u, friction), u)
        })
        .fold((0.0, 0.0), |a, b| if b.0 > a.0 { b } else { a });
    if s.step * rate <= RK4_STABILITY_LIMIT {
        return Ok(());
    }
    let sigma = model.options.effects.relaxation_length;
    let lag = model.options.effects.lagged() && speed.max(1.0) / sigma >= 0.999 * rate;
    let unstable = UnstableStep {
        step: s.step,
        rate,
        speed,
        relaxation_length: lag.then_some(sigma),
    };
    let table = integration_table(src);
    let span = src
        .key_span(&format!("{table}.step"))
        .or_else(|| src.key_span(&format!("{table}.method")));
    let problem = InputProblem::Scenario(Box::new(ScenarioProblem::UnstableStep(unstable)));
    Err(src.located(span, problem))
}
