//! The least yaw rate a car gives for its steer at a speed, and the steer
//! limits it lowers: the one rule `metrics`, a replay and `diagnose` judge
//! a run's `r·l/(u·δ)` by (ISO 8855 signs; SI, rad, m/s).
//!
//! A car's steady yaw rate over a neutral car's, `q = r·l/(u·δ)` with `l`
//! its wheelbase, is `1/(1 + K·u²/l)` (the linear bicycle model's steady
//! turn, K the understeer gradient in rad per m/s²; Gillespie 1992, ch. 6;
//! Milliken & Milliken 1995, ch. 5); taken with an `l` longer than the
//! car's (`metrics`' 5 m) it is larger. An understeering car's `q` falls
//! with speed: the bundled sedan (about 4°/g, 2.7 m) gives 0.045 at 90 m/s
//! (0.084 with 5 m), which the fixed limits (a refusal below
//! [`super::STEER_IN_DEGREES`], 0.1; a warning below
//! [`super::SMALL_STEADY_GAIN`], 0.15, with 5 m) took for a steer in
//! degrees: `metrics` refused the tool's own simulation, `diagnose` the
//! sedan's runs above about 60 m/s (round 51).
//!
//! The rule: the least `q` a car gives at speed `u`, with the `l` the
//! ratio is taken with, is the most understeering car's,
//! [`MOST_UNDERSTEER`] (6°/g): `least = 1/(1 + K_most·u²/l)`. The fixed
//! limits were set where that least is [`LEAST_SET_AT`] (0.2) or more, as
//! at the handling tests' 80–100 km/h (a 6°/g car on 2.7 m gives 0.25 at
//! 100 km/h): the refusal at half of it, the warning at three quarters.
//! Where the speed brings `least` below 0.2 (above 31.8 m/s on a 2.7 m
//! car, 43.3 m/s with 5 m), the limits fall with it in those shares:
//! `limit = base · min(1, least/0.2)`; below, they are the fixed ones.
//! Scaling the fixed limits by the whole of `least` instead would count
//! the understeer they already allow twice: at 100 km/h a 15:1
//! steering-wheel angle on a 2.7 m car (0.0585, round 50's refusal) would
//! pass a limit of 0.025.
//!
//! What it lets through and what it still catches: a refusal at half the
//! least passes cars up to `2·K_most + l/u²` (12°/g and more); the
//! warning, at three quarters, up to `(4/3)·K_most + l/(3u²)` (8°/g and
//! more). A steer in degrees is still refused on any car whose own `q`
//! is below 28.5× the least (57.3 × ½): the sedan at 90 m/s logged in
//! degrees reads 0.00079 against a limit of 0.0151 with its 2.7 m. Not
//! caught: a neutral car logged in degrees at 90 m/s (1/57.3 = 0.0175):
//! no ratio tells it from a car understeering 6°/g in radians (0.0303).
//!
//! The run's own steady `ay` gives the same rule as an implied understeer
//! gradient: in a steady turn `ay = u·r`, so `(δ − l·r/u)/ay =
//! (l/u²)·(1/q − 1)`, and a limit on `q` at speed `u` is a limit on that
//! gradient. The ratio is kept: it needs no `ay`, which a run may lack and
//! a bank or the body's roll biases (`ay_check.rs`).

use crate::error::LimitAtSpeed;

/// The understeer gradient of the most understeering car the limits allow
/// for, rad per m/s²: 6°/g, a strongly understeering passenger car or SUV
/// in its linear range, beyond the few °/g production cars are set to
/// (Gillespie 1992, ch. 6; Milliken & Milliken 1995, ch. 5; the bundled
/// sedan is about 4°/g).
pub const MOST_UNDERSTEER: f64 = 6.0 * std::f64::consts::PI / 180.0 / crate::constants::G;

/// The least `r·l/(u·δ)` a car gives where the fixed limits were set (the
/// most understeering car at the handling tests' speeds): they are half
/// ([`super::STEER_IN_DEGREES`]) and three quarters
/// ([`super::SMALL_STEADY_GAIN`]) of it.
pub const LEAST_SET_AT: f64 = 0.2;

/// The least steady `r·l/(u·δ)` a car gives at `speed` (m/s) with the
/// ratio taken on `wheelbase` (m, at least the car's): the most
/// understeering car's, `1/(1 + K_most·u²/l)`.
pub fn least_ratio(speed: f64, wheelbase: f64) -> f64 {
    1.0 / (1.0 + MOST_UNDERSTEER * speed * speed / wheelbase)
}

/// The limit `base` (set where a car's least ratio is [`LEAST_SET_AT`])
/// on a ratio taken at median speed `speed` (m/s) with `wheelbase` (m):
/// `base` where the least a car gives there is 0.2 or more, else
/// `base · least/0.2`, with what lowered it for the words.
pub fn limit_at_speed(base: f64, speed: f64, wheelbase: f64) -> (f64, Option<LimitAtSpeed>) {
    let least = least_ratio(speed, wheelbase);
    // A speed that is not a number (no samples) leaves the fixed limit.
    if least.is_nan() || least >= LEAST_SET_AT {
        return (base, None);
    }
    let limit = base * least / LEAST_SET_AT;
    let said = LimitAtSpeed {
        limit,
        least,
        share: base / LEAST_SET_AT,
        speed,
        gradient: MOST_UNDERSTEER,
    };
    (limit, Some(said))
}

#[cfg(test)]
mod tests {
    use super::super::{SMALL_STEADY_GAIN, STEER_IN_DEGREES};
    use super::*;

    /// The closed form `1/(1 + K·u²/l)` at 6°/g: 0.0303 at 90 m/s on
    /// 2.7 m (K·u²/l = 0.0106784 × 8100 / 2.7 = 32.04), 0.0546 with 5 m.
    #[test]
    fn the_least_ratio_is_the_most_understeering_car_s() {
        assert!(
            (MOST_UNDERSTEER - 0.0106784).abs() < 1e-7,
            "{MOST_UNDERSTEER}"
        );
        assert_eq!(least_ratio(0.0, 2.7), 1.0);
        assert!((least_ratio(90.0, 2.7) - 1.0 / 33.03533).abs() < 1e-8);
        assert!((least_ratio(90.0, 5.0) - 1.0 / 18.29908).abs() < 1e-8);
        // A linear car of K = 6°/g simulated in closed form is that car.
        let (k, l, u) = (MOST_UNDERSTEER, 2.7, 40.0);
        let gain = u / (l + k * u * u);
        assert!((gain * l / u - least_ratio(u, l)).abs() < 1e-12);
    }

    /// At standstill and up to where the least is 0.2 the limits are the
    /// fixed ones, with nothing to say; just past it they fall by the
    /// least's own ratio to 0.2.
    #[test]
    fn the_fixed_limits_hold_until_the_least_falls_below_a_fifth() {
        for l in [1.0, 2.7, 5.0] {
            assert_eq!(limit_at_speed(STEER_IN_DEGREES, 0.0, l), (0.1, None));
            assert_eq!(limit_at_speed(SMALL_STEADY_GAIN, 0.0, l), (0.15, None));
            assert_eq!(limit_at_speed(0.1, f64::NAN, l), (0.1, None));
            // K·u²/l = 4 at the crossover.
            let at = (4.0 * l / MOST_UNDERSTEER).sqrt();
            assert_eq!(limit_at_speed(0.1, at * 0.999, l), (0.1, None));
            let (limit, said) = limit_at_speed(0.1, at * 1.001, l);
            assert!(limit < 0.1 && limit > 0.0998, "{limit}");
            assert!(said.is_some());
        }
        assert!((31.8f64.powi(2) * MOST_UNDERSTEER / 2.7 - 4.0).abs() < 0.01);
        assert!((43.3f64.powi(2) * MOST_UNDERSTEER / 5.0 - 4.0).abs() < 0.01);
    }

    /// At 90 m/s: half of 0.0303 on the sedan's 2.7 m (0.0151, the true
    /// run's 0.045 passes, in degrees 0.00079 is refused), three quarters
    /// of 0.0546 with 5 m for the warning (0.0410, the true run's 0.084
    /// passes), and the words.
    #[test]
    fn at_ninety_metres_a_second_the_limits_are_the_least_car_s_shares() {
        let (limit, said) = limit_at_speed(STEER_IN_DEGREES, 90.0, 2.7);
        assert!((limit - 0.5 / 33.03533).abs() < 1e-8, "{limit}");
        assert!(0.045 > limit && 0.045 / 57.3 < limit);
        let said = said.unwrap();
        assert_eq!(
            said.to_string(),
            "below 0.0151: half of 0.0303, the least a car understeering 6°/g gives at 90.0 m/s"
        );
        let (warn, said) = limit_at_speed(SMALL_STEADY_GAIN, 90.0, 5.0);
        assert!((warn - 0.75 / 18.29908).abs() < 1e-8, "{warn}");
        assert!(0.084 > warn);
        assert!(said
            .unwrap()
            .to_string()
            .starts_with("below 0.0410: three quarters of 0.0546"));
    }
}
