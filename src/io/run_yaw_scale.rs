//! The scale of a measured run's yaw rate judged where its `ay` holds
//! steady and large ([`super::read_run`]): at a steady state `ay = u·r`
//! (ISO 8855, `β̇ = 0`; the bank's `g·sin θ` out of `ay` where the run has
//! `bank`). The β term of the slope check is left out: at a steady `ay`
//! it is about 0, and a sideslip sensor's noise differenced over half a
//! second (0.002 rad at 27.8 m/s: 0.15 m/s²) swamps a yaw rate read 57
//! times too small (its `u·r` 0.035 m/s² at 2 m/s²).
//!
//! **Why.** The slope check (`run_slope.rs`) and the per-sample ratios
//! (`run_units.rs`) read `ay` where `|u·r|` is 1 m/s² or more, and the steer
//! check ([`yaw_per_neutral`]) where the steer is held at 0.01 rad or more.
//! A yaw rate in rad/s declared in deg/s reads 57.3 times too small: its
//! `u·r` never reaches 1 m/s², and an ISO 7401 step at 100 km/h and
//! 2 m/s² steers 0.008 rad. Such a run passed every check, and the
//! calibration took its steady 2 m/s² turn for a straight (an `ay` offset
//! of 1.98 m/s²).
//!
//! **Rule.** Over the run's half-second means ([`stretches`]) at
//! [`MOVING`] m/s or more whose `|ay|` (less the bank's term) is
//! [`STEADY_AY`] m/s² or more and within [`STEADY_SHARE`] of each
//! neighbour's (a steady turn, not a transient's passing peak), `u·r` is
//! fitted on `ay` through the origin: its slope is the share
//! of `ay` the yaw rate explains, near 1 on a car (0.6–1.6 with a bank or
//! body roll, [`SI_RANGE`]). A share below [`YAW_EXPLAINS`] with R² of
//! [`MIN_R2`] or more (the yaw rate follows `ay`, scaled) over
//! [`MIN_BINS`] means or more, where the steer turns the car as `ay` says
//! (the median of `δ·u²/ay`, a neutral car's wheelbase and more with
//! understeer, is [`SHORTEST_WHEELBASE`] or more) is a scale of the yaw
//! rate: 1/57.3 (within a factor of 1.25, [`IN_DEGREES`]) a yaw rate in
//! rad/s read as deg/s; another, a gyro's gain or range. Refused at the
//! first sample of the first mean judged.
//!
//! Not judged: a yaw rate that holds one value (a dead gyro, refused as
//! such), a run the steer check judges (its steer held at 0.01 rad or
//! more: it names a declared column itself), a yaw rate that does not
//! follow `ay` (R² below [`MIN_R2`]: a banked straight's `ay` without a
//! bank column, whose yaw rate is noise about 0, and whose steer is about
//! straight too), and a steer that does not turn the car as `ay` says (an
//! accelerometer's offset or an unlogged bank on a gentle curve).

use super::run_slope::{fit, stretches, Lateral, Stretch, MIN_BINS, MIN_R2, MOVING, SI_RANGE};
use crate::error::YawScale;
use crate::measured::clean::median;
use crate::measured::MeasuredRun;
use crate::metrics::measured::{yaw_per_neutral, LONGEST_WHEELBASE, SHORTEST_WHEELBASE};
use std::path::Path;

/// The least |mean ay| of a mean judged, m/s²: well above a lateral
/// accelerometer's offset (0.01–0.5 m/s² for automotive MEMS sensors)
/// and its noise over a mean.
pub const STEADY_AY: f64 = 1.0;

/// How far a judged mean's `ay` may lie from each neighbour's, as a share
/// of it: a steady turn's means lie within a few percent of each other,
/// a step's rise or a sine's peak moves by more.
pub const STEADY_SHARE: f64 = 0.2;

/// Below this share of a steady `ay` explained by `u·r`, the yaw rate is
/// off by a scale: a third of [`SI_RANGE`]'s lowest, far below what a
/// bank or body roll takes off.
pub const YAW_EXPLAINS: f64 = SI_RANGE.0 / 3.0;

/// The shares of a yaw rate in rad/s read as deg/s: π/180 within a factor
/// of 1.25 either way.
pub const IN_DEGREES: (f64, f64) = (
    std::f64::consts::PI / 180.0 / 1.25,
    std::f64::consts::PI / 180.0 * 1.25,
);

/// Whether mean `i` of `means` is judged: moving, `|ay|` (less the
/// bank's term) at least [`STEADY_AY`] and within [`STEADY_SHARE`] of
/// each neighbour's, its kinematic term finite.
fn steady_turn(means: &[Stretch], i: usize) -> bool {
    let a = |s: &Stretch| s.ay - s.bank_term;
    let s = &means[i];
    let ay = a(s);
    let near = |k: Option<usize>| {
        k.and_then(|k| means.get(k))
            .is_none_or(|n| (a(n) - ay).abs() <= STEADY_SHARE * ay.abs())
    };
    s.speed >= MOVING
        && ay.abs() >= STEADY_AY
        && s.speed_yaw.is_finite()
        && near(i.checked_sub(1))
        && near(Some(i + 1))
}

/// The refusal of a yaw rate that explains a small share of a steady `ay`
/// (the rule above), with the row it names; None where the run passes or
/// is not judged.
pub(super) fn yaw_scale_slip(path: &Path, c: &Lateral) -> Option<(usize, YawScale)> {
    let means = stretches(c);
    let judged: Vec<&Stretch> = (0..means.len())
        .filter(|&i| steady_turn(means, i))
        .map(|i| &means[i])
        .collect();
    // A yaw rate that holds one value (a dead gyro) is refused as dead by
    // the run's checks, not as scaled.
    if judged.len() < MIN_BINS || crate::measured::one_value(c.yaw_rate).is_some() {
        return None;
    }
    let ay = |s: &Stretch| s.ay - s.bank_term;
    let (share, r2) = fit(judged.iter().map(|s| (ay(s), s.speed_yaw)));
    if !(share > 0.0 && share < YAW_EXPLAINS && r2 >= MIN_R2) {
        return None;
    }
    let mut turn: Vec<f64> = judged
        .iter()
        .map(|s| s.steer * s.speed * s.speed / ay(s))
        .collect();
    // NaN (a steer of NaN) turns nothing either.
    let wheelbase = median(&mut turn);
    let turns = wheelbase >= SHORTEST_WHEELBASE;
    if !turns || steer_judges(path, c) {
        return None;
    }
    let first = judged[0];
    let slip = YawScale {
        value: c.yaw_rate[first.first],
        ay: first.ay,
        share,
        r2,
        bins: judged.len(),
        steady_ay: STEADY_AY,
        wheelbase,
        in_degrees: (IN_DEGREES.0..=IN_DEGREES.1).contains(&share),
        with_bank: c.bank.is_some(),
    };
    Some((first.first, slip))
}

/// Whether the steer check ([`yaw_per_neutral`], with the longest
/// wheelbase, which judges the most runs) judges the run: then it says a
/// yaw rate too small for its steer itself, naming a declared column.
fn steer_judges(path: &Path, c: &Lateral) -> bool {
    let run = MeasuredRun::new(
        path,
        c.t.to_vec(),
        c.speed.to_vec(),
        c.steer.to_vec(),
        c.yaw_rate.to_vec(),
    );
    yaw_per_neutral(&run, LONGEST_WHEELBASE, MOVING).is_some()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 9 s step at 100 km/h to a steady 2 m/s² (steer 0.0079 rad, a
    /// 2.78 m car), 100 Hz, its yaw rate scaled by `scale`, its steer
    /// `steer` from 3 s.
    /// Time, speed, steer, yaw rate and `ay`.
    type Channels = [Vec<f64>; 5];

    fn step(scale: f64, steer: f64) -> Channels {
        let u = 27.78;
        let t: Vec<f64> = (0..900).map(|i| i as f64 * 0.01).collect();
        let ay: Vec<f64> = t
            .iter()
            .enumerate()
            .map(|(i, &s)| {
                let wobble = 0.03 * ((i * 7919 % 13) as f64 - 6.0) / 6.0;
                2.0 * (1.0 - (-(s - 3.0).max(0.0) / 0.15).exp()) + wobble
            })
            .collect();
        let r: Vec<f64> = ay.iter().map(|a| scale * a / u).collect();
        let d: Vec<f64> = t
            .iter()
            .map(|&s| if s >= 3.0 { steer } else { 0.0 })
            .collect();
        [t, vec![u; 900], d, r, ay]
    }

    fn judge(scale: f64, steer: f64) -> Option<YawScale> {
        let [t, speed, d, r, ay] = step(scale, steer);
        let c = Lateral {
            t: &t,
            speed: &speed,
            steer: &d,
            yaw_rate: &r,
            ay: &ay,
            beta: None,
            bank: None,
            means: Default::default(),
        };
        yaw_scale_slip(Path::new("s.csv"), &c).map(|(_, s)| s)
    }

    #[test]
    fn a_yaw_rate_read_57_times_too_small_is_refused_as_degrees() {
        // In rad/s: the share is 1, passed.
        assert!(judge(1.0, 0.0079).is_none());
        // Declared in degrees: π/180 of it, named so, to 1 %.
        let s = judge(std::f64::consts::PI / 180.0, 0.0079).unwrap();
        assert!(s.in_degrees, "{s:?}");
        assert!(
            (s.share * 180.0 / std::f64::consts::PI - 1.0).abs() < 0.01,
            "{s:?}"
        );
        assert!((s.wheelbase - 3.05).abs() < 0.1, "{s:?}");
        assert!(s.bins >= MIN_BINS, "{s:?}");
        let e = s.to_string();
        assert!(
            e.contains("57.3× is a yaw rate in rad/s read as deg/s"),
            "{e}"
        );
        // A tenth: a scale, not a unit.
        let s = judge(0.1, 0.0079).unwrap();
        assert!(!s.in_degrees, "{s:?}");
        assert!(s.to_string().contains("reads 10.0× too small"), "{s}");
        // A third: within what no unit explains but above the rule's share.
        assert!(judge(0.35, 0.0079).is_none());
    }

    #[test]
    fn a_steer_that_does_not_turn_the_car_or_that_the_steer_check_judges_is_not_judged() {
        // Straight ahead by the steer: `ay` is a bank's or an offset's.
        assert!(judge(std::f64::consts::PI / 180.0, 0.0).is_none());
        // A steer held at 0.05 rad: the steer check names the yaw rate.
        assert!(judge(std::f64::consts::PI / 180.0, 0.05).is_none());
    }
}
