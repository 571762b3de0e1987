//! The warning on a measured step whose steady yaw rate is far smaller
//! than a neutral car's for its steer even on the longest wheelbase a car
//! has: a steer likely larger than the road wheels' (a steering-wheel
//! angle, 12–20×) or in degrees. `metrics` has no wheelbase, so it judges
//! the ratio `r·l/(u·δ)` (1 for a neutral car, ISO 8855 signs) with
//! [`LONGEST_WHEELBASE`] and warns; `diagnose`, which knows the car,
//! refuses below [`STEER_IN_DEGREES`] with its own wheelbase. Both say it
//! in the same words ([`times_smaller`], [`STEER_UNIT_QUESTION`]). Units:
//! SI, rad.
//!
//! Round 50: a 100 km/h step logged as a 15:1 steering-wheel angle at a
//! steady ay of 6 m/s² was measured without a word, where `diagnose`
//! refused the same run ("17× smaller, median r·l/(u·δ) = 0.0585"): the
//! warning held only below 4 m/s², to spare a car ploughing at its limit.
//! It now holds at any ay and says where a plough could explain it.
//!
//! Session 115: an understeering car's ratio falls with speed (`1/(1 +
//! K·u²/l)`), and the bundled sedan simulated at 90 m/s (0.085 with 5 m)
//! was warned of as a steer in degrees: the warning's limit falls at speed
//! as the refusal's does, to three quarters of the least a car gives there
//! (`least_gain.rs`), and says so where it did.

use super::least_gain::limit_at_speed;
use super::{LONGEST_WHEELBASE, STEER_IN_DEGREES};
use crate::format::readable;
use crate::metrics::StepMetrics;

/// Below this steady `r·l/(u·δ)` of a step, with [`LONGEST_WHEELBASE`],
/// the step's yaw rate is said as far smaller than a neutral car's for
/// its steer: 0.08 of a neutral car's on a 2.7 m car, an understeer
/// gradient of about 11 times the car's `l/u²` (a linear car at 5°/g and
/// 160 km/h gives 0.24; a 15:1 steering-wheel angle on a 2.7 m car about
/// 0.12 or less; the run's refusal below [`STEER_IN_DEGREES`] is kept for
/// what no wheelbase explains). Lower at speed, where the least a car
/// gives falls below 0.2 (`least_gain.rs`).
pub const SMALL_STEADY_GAIN: f64 = 0.15;

/// The steady lateral acceleration from which a car ploughing on sliding
/// front tyres may turn so little for its steer, m/s²: ISO 7401's
/// 4 m/s², below the limit where a ploughing car's gain falls with its
/// front grip. Below it no car understeers so much.
pub const SMALL_GAIN_AY: f64 = 4.0;

/// The wheelbase of a typical car the ratio is also said for, m.
const TYPICAL_WHEELBASE: f64 = 2.7;

/// The question `metrics` and `diagnose` ask of a yaw rate far smaller
/// than a neutral car's for its steer.
pub(crate) const STEER_UNIT_QUESTION: &str =
    "is `steer` in degrees (57×) or a steering-wheel angle (divide by the steering ratio)?";

/// A ratio `r·l/(u·δ)` below 1 as `diagnose` says a run's (`17× smaller,
/// median r·l/(u·δ) = 0.0585`), `how` naming how it was taken (`median`,
/// `steady`).
pub(crate) fn times_smaller(ratio: f64, how: &str) -> String {
    format!(
        "{}× smaller, {how} r·l/(u·δ) = {}",
        readable(1.0 / ratio, 2),
        readable(ratio, 3)
    )
}

/// The warning on a step whose steady yaw-rate gain at median speed `u`
/// (m/s) is below [`SMALL_STEADY_GAIN`] of a neutral car's of the longest
/// wheelbase (less at speed: [`limit_at_speed`]), at any steady lateral
/// acceleration: what a plough at its steady ay could explain is said
/// with it.
pub(super) fn small_gain(m: &StepMetrics, u: f64) -> Option<String> {
    let gain = m.yaw_rate_gain;
    let ratio = gain * LONGEST_WHEELBASE / u;
    let (limit, at_speed) = limit_at_speed(SMALL_STEADY_GAIN, u, LONGEST_WHEELBASE);
    if !(ratio > 0.0 && ratio < limit) {
        return None;
    }
    let plough = match m.ay_steady.map(f64::abs) {
        Some(ay) if ay < SMALL_GAIN_AY => format!(
            "no car understeers so much at a steady ay under {SMALL_GAIN_AY} m/s²"
        ),
        Some(ay) => format!(
            "at a steady ay of {} m/s² only a car ploughing on sliding front tyres turns so little for its steer",
            readable(ay, 3)
        ),
        None => "only a car ploughing on sliding front tyres turns so little for its steer, which a run without `ay` cannot rule out".into(),
    };
    Some(format!(
        "the yaw rate is far smaller than a neutral car's for the steer even with l = {LONGEST_WHEELBASE} m, longer than any car's wheelbase ({}: the yaw-rate gain {} 1/s at {} m/s; {} on a {TYPICAL_WHEELBASE} m car{}): {STEER_UNIT_QUESTION} The metrics take it as the road-wheel angle in radians; {plough}, and `diagnose`, which knows the wheelbase, refuses a run below {STEER_IN_DEGREES} with it{}",
        times_smaller(ratio, "steady"),
        readable(gain, 4),
        readable(u, 3),
        times_smaller(ratio * TYPICAL_WHEELBASE / LONGEST_WHEELBASE, "steady"),
        at_speed.map_or(String::new(), |a| format!("; warned of {a}")),
        match at_speed {
            Some(_) => " (at this speed, below half the least a car with that wheelbase gives)",
            None => "",
        },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A step of gain `gain` (1/s) at steady ay `ay`.
    fn step(gain: f64, ay: Option<f64>) -> StepMetrics {
        let mut m = crate::metrics::applicability::tests::moderate();
        m.yaw_rate_gain = gain;
        m.ay_steady = ay;
        m
    }

    /// The ratio is the gain times 5 m over the speed: 0.583 1/s at
    /// 27.78 m/s is 0.105, 9.5× smaller; on a 2.7 m car 0.0567, 18×.
    #[test]
    fn a_steering_wheel_angle_is_warned_of_at_any_ay_with_the_ratio() {
        for ay in [Some(2.0), Some(6.0), None] {
            let w = small_gain(&step(0.583, ay), 27.78).unwrap_or_else(|| panic!("{ay:?}"));
            assert!(
                w.contains("(9.5× smaller, steady r·l/(u·δ) = 0.105: the yaw-rate gain 0.5830 1/s at 27.8 m/s; 18× smaller, steady r·l/(u·δ) = 0.0567 on a 2.7 m car)"),
                "{w}"
            );
            assert!(w.contains(STEER_UNIT_QUESTION), "{w}");
        }
        let w = small_gain(&step(0.583, Some(6.0)), 27.78).unwrap();
        assert!(
            w.contains("at a steady ay of 6.00 m/s² only a car ploughing"),
            "{w}"
        );
        let w = small_gain(&step(0.583, Some(-2.0)), 27.78).unwrap();
        assert!(
            w.contains("no car understeers so much at a steady ay under 4"),
            "{w}"
        );
    }

    /// At the threshold and above (a linear car at 5°/g and 160 km/h
    /// gives 0.24), and for a gain of the other sign (judged elsewhere),
    /// nothing is said. At 40 m/s the least a car gives with 5 m is still
    /// above 0.2 (0.226): the threshold is the fixed one.
    #[test]
    fn a_car_s_gain_is_not_warned_of() {
        let u = 40.0;
        let at = SMALL_STEADY_GAIN * u / LONGEST_WHEELBASE;
        assert!(small_gain(&step(at * 1.001, Some(2.0)), u).is_none());
        let w = small_gain(&step(at * 0.999, Some(2.0)), u).unwrap();
        assert!(!w.contains("warned of below"), "{w}");
        let u = 44.4;
        assert!(small_gain(&step(0.24 * u / LONGEST_WHEELBASE, Some(8.0)), u).is_none());
        assert!(small_gain(&step(-0.1, Some(2.0)), u).is_none());
    }

    /// At 90 m/s the threshold is three quarters of the least a car
    /// gives with 5 m (0.0546): 0.0410. The sedan's 1.529 1/s (0.085) is
    /// not warned of; just below the threshold the warning says it.
    #[test]
    fn at_speed_the_threshold_falls_with_the_least_car_s_gain() {
        let u = 90.0;
        assert!(small_gain(&step(1.529, Some(2.47)), u).is_none());
        let at = 0.75 / 18.29908 * u / LONGEST_WHEELBASE;
        assert!(small_gain(&step(at * 1.001, Some(2.0)), u).is_none());
        let w = small_gain(&step(at * 0.999, Some(2.0)), u).unwrap();
        assert!(
            w.contains("on a 2.7 m car; warned of below 0.0410: three quarters of 0.0546, the least a car understeering 6°/g gives at 90.0 m/s):"),
            "{w}"
        );
        assert!(w.ends_with("refuses a run below 0.1 with it (at this speed, below half the least a car with that wheelbase gives)"), "{w}");
    }
}
