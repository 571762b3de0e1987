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
        // Within 1 % of the largest steady ay found: at the limit, where
        // the bisection cannot tell "beyond" from a solver that fails on
        // the flat top of the ay-steer curve (9.9 m/s² against 9.81 with
        // friction 1 read only "did not converge").
        Some(l) if l.abs() < ay.abs() => format!(
            "{head}: at the vehicle's lateral limit at this speed, where the largest steady ay found is {} m/s² with these tyres and this road, within 1 % of the asked: the solver did not converge this close to the limit; ask for less than {} m/s²",
            crate::format::readable(l, 3),
            crate::format::readable(l, 3)
        ),
        _ => format!("{head}: the solver did not converge"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An ay asked within 1 % above the largest steady ay found is said to
    /// be at the limit, with a value that holds; clearly beyond, beyond;
    /// no limit found, the solver's failure.
    #[test]
    fn an_ay_at_the_limit_is_said_at_it_not_as_a_solver_failure() {
        let at = no_steady_words(22.2222, 9.9, Some(9.81));
        assert!(at.ends_with("at the vehicle's lateral limit at this speed, where the largest steady ay found is 9.81 m/s² with these tyres and this road, within 1 % of the asked: the solver did not converge this close to the limit; ask for less than 9.81 m/s²"), "{at}");
        let beyond = no_steady_words(22.2222, 11.0, Some(9.81));
        assert!(
            beyond.contains("beyond the vehicle's lateral limit at this speed, 9.81 m/s²"),
            "{beyond}"
        );
        let none = no_steady_words(22.2222, 9.9, None);
        assert!(none.ends_with("the solver did not converge"), "{none}");
    }
}
