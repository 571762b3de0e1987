//! A moving steer (a sweep, a slalom) beyond any road wheel's angle whose
//! yaw rate says it is in degrees: the held-steer check
//! ([`super::measured::yaw_per_neutral`]) has no held samples to judge
//! such a run by, and `metrics` refused a sweep spanning 117° only as "no
//! step steer", never asking about its units. Judged by the median of
//! `r·l/(u·δ)` where the steer is large (at least half its 99th
//! percentile), against the same limit as a held steer (`measured.rs`'s
//! `STEER_IN_DEGREES`, 0.1, with its longest wheelbase, 5 m, lowered at
//! speed as a held steer's is: `measured/least_gain.rs`):
//! in degrees a car's ratio is 57× smaller (0.003–0.02), where in radians
//! the yaw rate lags the steer by well under a quarter period near its
//! peaks up to a few hertz, and the ratio stays near the car's gain.
//! Units: SI, rad.

use crate::error::InputProblem;
use crate::measured::clean::{midpoint_median, quantile};
use crate::measured::MeasuredRun;
use crate::metrics::measured::least_gain::limit_at_speed;

/// A road-wheel steer no handling test reaches at speed, rad (28.6°; a
/// car's largest mean road-wheel angle is 35–40° at parking speeds).
pub const ROAD_WHEEL_MOST: f64 = 0.5;

/// The refusal of a run at speed (at least `min_speed` and 5 m/s) whose
/// steer's 99th percentile of |δ| passes [`ROAD_WHEEL_MOST`] and whose
/// `r·l/(u·δ)` (`l` = `wheelbase`, m: the longest a car has, so that no
/// car's is refused) has a median within ± the held steer's limit at their
/// median speed over the samples steered by at least half that
/// percentile: the refusal a step in degrees gets.
pub fn steer_in_degrees(
    run: &MeasuredRun,
    min_speed: f64,
    wheelbase: f64,
    base: f64,
) -> Option<InputProblem> {
    let at_speed: Vec<usize> = (0..run.t.len())
        .filter(|&i| run.speed[i] >= min_speed.max(5.0) && run.steer[i].is_finite())
        .collect();
    let mut size: Vec<f64> = at_speed.iter().map(|&i| run.steer[i].abs()).collect();
    size.sort_by(f64::total_cmp);
    let p99 = quantile(&size, 0.99)?;
    if p99 <= ROAD_WHEEL_MOST {
        return None;
    }
    let (mut q, mut speeds): (Vec<f64>, Vec<f64>) = at_speed
        .iter()
        .filter(|&&i| run.steer[i].abs() >= 0.5 * p99)
        .map(|&i| {
            let u = run.speed[i];
            (run.yaw_rate[i] * wheelbase / (u * run.steer[i]), u)
        })
        .filter(|(q, _)| q.is_finite())
        .unzip();
    let samples = q.len();
    let median = midpoint_median(&mut q);
    let speed = midpoint_median(&mut speeds);
    let (limit, at_speed) = limit_at_speed(base, speed, wheelbase);
    (median.abs() < limit).then_some(InputProblem::SteerAboveYaw {
        median,
        samples,
        assumed_wheelbase: Some(wheelbase),
        at_speed,
    })
}
