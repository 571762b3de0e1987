//! The error of a lateral acceleration no steady state of the vehicle
//! model holds at a speed, with the largest one that does (its words here,
//! below the vehicle model that finds it). Units: m/s, m/s².

use thiserror::Error;

/// No steady state holds the asked lateral acceleration at the speed:
/// beyond the vehicle's lateral limit, or the solver did not converge.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("{}", no_steady_words(*speed, *ay, *limit))]
pub struct NoSteadyState {
    /// The speed, m/s (at least the model's smallest speed).
    pub speed: f64,
    /// The lateral acceleration asked, m/s².
    pub ay: f64,
    /// The largest steady lateral acceleration of the same sign at the
    /// speed, m/s² (`None`: none found, not even 0).
    pub limit: Option<f64>,
}

/// The sentence of [`NoSteadyState`]: the limit said where the bisection
/// found one clearly below the asked value (else the solver's failure).
/// The ay is said to six significant digits: on a bank it is the change
/// asked plus g·sin θ, a sum of seventeen (the field keeps them all).
fn no_steady_words(speed: f64, ay: f64, limit: Option<f64>) -> String {
    let head = format!(
        "no steady state at {} m/s with ay = {} m/s²",
        crate::format::exact(speed),
        crate::format::carried(ay, 6)
    );
    match limit {
        Some(l) if l.abs() < 0.99 * ay.abs() => format!(
            "{head}: beyond the vehicle's lateral limit at this speed, {} m/s² with these tyres and this road (the largest steady ay, within 45° of steer and sideslip)",
            crate::format::readable(l, 3)
        ),
        _ => format!("{head}: the solver did not converge"),
    }
}
