//! A run's steer judged where it is never held (a sweep, a random steer):
//! the yaw-rate check of [`crate::metrics::measured::yaw_per_neutral`]
//! reads only held steer, so a sweep logged in degrees passed `diagnose`
//! unjudged and its 57× unit slip was fitted as a model-form gap.
//!
//! The rule: the neutral steer `r·l/u` (rad) shifted by the lag
//! `τ ∈ [0, MAX_LAG]` that best aligns it with the steer (the largest
//! `Σ r·l/u(t + τ)·δ(t)`: the yaw rate follows the steer by the car's
//! response time), and the median of `r·l/(u·δ)` over the samples at
//! speed steered at 0.3 of the 95th-percentile steer or more, as the held
//! steer's check takes them. A car's aligned sweep gives 0.3–1 (its
//! understeer, and the gain's fall with frequency: round 19's 80 km/h
//! sweep 0.54 in radians); a steer in degrees 57× less (0.0095), a
//! steering-wheel angle 15× less; a steer in radians declared in degrees
//! 57× more. The median is judged by [`steer_problem`] as a held steer's
//! is: below [`crate::metrics::measured::STEER_IN_DEGREES`] (0.1, lowered
//! at the samples' median speed as `measured/least_gain.rs` says) or above
//! [`crate::metrics::measured::YAW_ABOVE_STEER`] (5) the run is refused
//! with its words (`diagnose` and a replay alike). ISO 8855 signs; SI,
//! rad, s.

use crate::error::InputProblem;
use crate::measured::MeasuredRun;
use crate::metrics::measured::{
    neutral_steer, steer_problem, yaw_per_neutral, Wheelbase, YawPerNeutral, TURN,
};

/// The longest lag of the yaw rate behind the steer searched, s: a car's
/// yaw response time is 0.1–0.3 s.
const MAX_LAG: f64 = 0.5;

/// Aligned samples below which a sweep is not judged (the held steer's
/// check asks 50 too).
const MIN_SAMPLES: usize = 50;

/// The ratio a run whose steer is never held gives (the module's rule), as the held steer's check gives its own: `None`
/// where the run holds a steer (that check judges it), barely steers
/// (95th percentile below [`TURN`]) while it barely turns (the neutral
/// steer's likewise) or has too few samples.
pub(super) fn swept_per_neutral(
    run: &MeasuredRun,
    wheelbase: f64,
    min_speed: f64,
) -> Option<YawPerNeutral> {
    if yaw_per_neutral(run, wheelbase, min_speed).is_some() {
        return None;
    }
    let at_speed: Vec<usize> = (0..run.t.len())
        .filter(|&i| run.speed[i] >= min_speed.max(5.0))
        .collect();
    let mut size: Vec<f64> = at_speed.iter().map(|&i| run.steer[i].abs()).collect();
    size.sort_by(f64::total_cmp);
    let p95 = *size.get(((size.len() as f64 - 1.0) * 0.95) as usize)?;
    let q: Vec<f64> = (0..run.t.len())
        .map(|i| neutral_steer(run.yaw_rate[i], wheelbase, run.speed[i].max(1e-9)))
        .collect();
    // A run that turns on a steer below 0.01 rad (a radian steer declared
    // in degrees, 57× too small) is judged too, as the held steer's check
    // judges one: its ratio, far above 1, is the slip. Turning is its
    // neutral steer's 95th percentile from 5 mrad, as there (a 0.02 rad
    // sine at 80 km/h turns by 8 mrad).
    let mut turning: Vec<f64> = at_speed.iter().map(|&i| q[i].abs()).collect();
    turning.sort_by(f64::total_cmp);
    let turns = turning
        .get(((turning.len() as f64 - 1.0) * 0.95) as usize)
        .is_some_and(|&n| n >= 0.5 * TURN);
    if p95 < TURN && !(turns && p95 > 0.0) {
        return None;
    }
    let lag = best_lag(&run.t, &run.steer, &q, &at_speed);
    let (mut ratio, mut with, mut against) = (Vec::new(), 0usize, 0usize);
    let mut speeds = Vec::new();
    for &i in at_speed
        .iter()
        .filter(|&&i| run.steer[i].abs() >= 0.3 * p95)
    {
        let Some(&r) = q.get(i + lag) else { continue };
        let x = r / run.steer[i];
        if x.is_finite() {
            with += usize::from(x > 0.0);
            against += usize::from(x < 0.0);
            ratio.push(x);
            speeds.push(run.speed[i]);
        }
    }
    if ratio.len() < MIN_SAMPLES {
        return None;
    }
    let n = ratio.len() as f64;
    ratio.sort_by(f64::total_cmp);
    speeds.sort_by(f64::total_cmp);
    Some(YawPerNeutral {
        median: ratio[ratio.len() / 2],
        samples: ratio.len(),
        speed: speeds[speeds.len() / 2],
        with_steer: with as f64 / n,
        against: against as f64 / n,
        one_value: None,
        ay_with_steer: None,
    })
}

/// The lag in samples (up to [`MAX_LAG`] at the run's median step) at
/// which the neutral steer `q` best follows the steer `steer` over the
/// samples `at` (the largest sum of products; 0 where none is positive).
fn best_lag(t: &[f64], steer: &[f64], q: &[f64], at: &[usize]) -> usize {
    let mut steps: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    steps.sort_by(f64::total_cmp);
    let dt = steps
        .get(steps.len() / 2)
        .copied()
        .unwrap_or(0.01)
        .max(1e-4);
    let max = (MAX_LAG / dt).round() as usize;
    let score = |k: usize| -> f64 {
        at.iter()
            .filter_map(|&i| q.get(i + k).map(|r| r * steer[i]))
            .sum()
    };
    (0..=max)
        .map(|k| (k, score(k)))
        .filter(|&(_, s)| s > 0.0)
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map_or(0, |(k, _)| k)
}

/// A never-held steer's unit slip: far larger than its yaw rate (in
/// degrees, or a steering-wheel angle: [`InputProblem::SteerAboveYaw`]) or
/// far smaller (a steer in radians declared in degrees, 57× too small:
/// [`InputProblem::YawAboveSteer`]), as the held steer's check words them;
/// else `None` (a sweep's other readings are not judged: its lag-aligned
/// ratio is checked for the unit slip only).
pub(crate) fn swept_unit_slip(
    run: &MeasuredRun,
    wheelbase: f64,
    min_speed: f64,
) -> Option<InputProblem> {
    let y = swept_per_neutral(run, wheelbase, min_speed)?;
    match steer_problem(&y, Wheelbase::Known(wheelbase))? {
        p @ (InputProblem::SteerAboveYaw { .. } | InputProblem::YawAboveSteer { .. }) => Some(p),
        _ => None,
    }
}

/// A never-held steer far larger than its yaw rate (in degrees, or a
/// steering-wheel angle): the held steer's refusal
/// ([`InputProblem::SteerAboveYaw`]) and the median, else `None`.
pub(super) fn swept_in_degrees(
    run: &MeasuredRun,
    wheelbase: f64,
    min_speed: f64,
) -> Option<(InputProblem, f64)> {
    match swept_unit_slip(run, wheelbase, min_speed)? {
        p @ InputProblem::SteerAboveYaw { median, .. } => Some((p, median)),
        _ => None,
    }
}
