//! The lateral accelerometer levelled by a logged body roll.
//!
//! **Why.** A body-fixed accelerometer rolled by φ (ISO 8855: positive
//! puts the right side down, outward in a left turn) reads the specific
//! force along its rolled axis, `a_y,read = a_y·cos φ + g·sin φ + b_ay`
//! (the body frame's lateral acceleration `a_y`, the offset `b_ay`; the
//! gravity term of the accelerometer's tilt: Groves 2013, *Principles of
//! GNSS, Inertial, and Multisensor Integrated Navigation Systems*, the
//! specific force resolved in a tilted frame; Gillespie 1992,
//! *Fundamentals of Vehicle Dynamics*, body roll in a turn). Where the run
//! logs its roll (`FORMATS.md`: relative to the road), gravity's part is
//! known and is taken out before any fit or estimate, as a standstill
//! offset is measured rather than fitted:
//! `a_y ← (a_y,read − g·sin φ)/cos φ`, which leaves `a_y + b_ay/cos φ`
//! (the offset changes by `1 − cos φ`, 0.2 % at 3.5°: below any
//! accelerometer's noise). A sedan's 3.5°/g reads 0.06·a_y more: left in,
//! it is fitted as whatever else grows with `a_y` (an accelerometer ahead
//! of the centre of gravity, stiffer axles).
//!
//! **The roll's own offset.** Parked, a car's body does not roll relative
//! to the road, so the logged roll's mean at the standstills the
//! calibration finds ([`super::spans::standstills`]) is the roll sensor's
//! offset (each standstill's mean and its error for autocorrelated
//! samples, pooled as the other channels' are, [`super::stats`]); it is
//! removed from φ before the levelling. Without a standstill none is
//! known and φ is taken as logged, and the note says so.
//!
//! **Not scored.** The logged roll levels `a_y`; it is not itself a
//! channel of the gap (no candidate's roll dynamics are judged against
//! it). Units: rad, m/s².

use super::stats::{mean_estimate, pool};
use super::{spans, CRITERIA};
use crate::constants::G;
use crate::measured::MeasuredRun;
use serde::Serialize;

/// The logged roll's offset at the standstills.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RollOffset {
    /// Pooled mean, rad.
    pub mean: f64,
    /// Its standard error, rad.
    pub std_error: f64,
    /// Standstills measured.
    pub spans: usize,
    /// Their total length, s.
    pub seconds: f64,
}

/// The logged roll's offset at the standstills of `runs` (raw, as read),
/// None where no run with a roll column stands still.
pub fn roll_offset(runs: &[MeasuredRun]) -> Option<RollOffset> {
    let mut means = Vec::new();
    let mut seconds = 0.0;
    for run in runs {
        let Some(roll) = &run.roll else { continue };
        for (lo, hi) in spans::standstills(run, &CRITERIA) {
            let live: Vec<f64> = (lo..hi)
                .filter(|i| run.masked.binary_search(i).is_err())
                .map(|i| roll[i])
                .collect();
            // A roll that holds one value (a quantised sensor at rest) is
            // that value, known to its resolution.
            let m = match mean_estimate(&live) {
                Some(m) => (m.mean, m.std_error),
                None if !live.is_empty() => (live[0], 0.0),
                None => continue,
            };
            means.push(m);
            seconds += run.t[hi - 1] - run.t[lo];
        }
    }
    (!means.is_empty()).then(|| {
        let p = pool(&means);
        RollOffset {
            mean: p.mean,
            std_error: p.std_error,
            spans: means.len(),
            seconds,
        }
    })
}

/// The gravity term `g·sin(φ − φ₀)` a body-fixed accelerometer reads at
/// each sample of `roll` (rad) with the roll sensor's offset `offset`.
pub fn gravity_term(roll: &[f64], offset: f64) -> Vec<f64> {
    roll.iter().map(|&p| G * (p - offset).sin()).collect()
}

/// `run` with its `ay` levelled by its logged roll less `offset` (rad):
/// `(a_y − g·sin φ)/cos φ`. A run without `roll` or `ay` is returned as
/// it is.
pub fn levelled(mut run: MeasuredRun, offset: f64) -> MeasuredRun {
    if let (Some(roll), Some(ay)) = (&run.roll, &mut run.ay) {
        for (a, &p) in ay.iter_mut().zip(roll) {
            let phi = p - offset;
            *a = (*a - G * phi.sin()) / phi.cos();
        }
    }
    run
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A car parked for 10 s, then in a steady left turn, at 100 Hz: the
    /// roll sensor reads 0.004 rad too much throughout.
    fn parked_then_turning(k: f64, ay_bias: f64) -> (MeasuredRun, Vec<f64>) {
        let n = 3000;
        let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.01).collect();
        let moving = |s: f64| s >= 10.0;
        let speed: Vec<f64> = t
            .iter()
            .map(|&s| if moving(s) { 15.0 } else { 0.0 })
            .collect();
        let true_ay: Vec<f64> = t
            .iter()
            .map(|&s| if moving(s) { 4.0 } else { 0.0 })
            .collect();
        let phi: Vec<f64> = true_ay.iter().map(|a| k * a).collect();
        let wobble = |i: usize| 1e-4 * ((i * 7919 % 13) as f64 - 6.0);
        let roll: Vec<f64> = phi
            .iter()
            .enumerate()
            .map(|(i, p)| p + 0.004 + wobble(i))
            .collect();
        let read: Vec<f64> = true_ay
            .iter()
            .zip(&phi)
            .map(|(a, p)| a * p.cos() + G * p.sin() + ay_bias)
            .collect();
        let r: Vec<f64> = true_ay
            .iter()
            .zip(&speed)
            .map(|(a, u)| if *u > 0.0 { a / u } else { 0.0 })
            .collect();
        let run = MeasuredRun::new("r.csv", t, speed, vec![0.0; n], r)
            .with_ay(read)
            .with_roll(roll);
        (run, true_ay)
    }

    #[test]
    fn the_roll_sensors_offset_is_its_mean_parked() {
        let (run, _) = parked_then_turning(0.006, 0.0);
        let o = roll_offset(&[run]).unwrap();
        assert_eq!(o.spans, 1);
        assert!((o.mean - 0.004).abs() < 1e-5, "{o:?}");
        assert!(o.std_error > 0.0 && o.std_error < 1e-4, "{o:?}");
        // Parked 10 s, less the standstill's 1 s trim at each end, and the
        // running median's half window where the car drives off.
        assert!(o.seconds > 7.0 && o.seconds < 10.0, "{o:?}");
    }

    #[test]
    fn a_levelled_accelerometer_reads_the_bodys_lateral_acceleration_plus_its_offset() {
        // 3.5°/g, a −0.6 m/s² mounting offset: in the turn the raw reading
        // is 4.0 + 0.24 − 0.6; levelled, 4.0 − 0.6/cos φ.
        let k = 3.5_f64.to_radians() / G;
        let (run, truth) = parked_then_turning(k, -0.6);
        let off = roll_offset(std::slice::from_ref(&run)).unwrap().mean;
        let raw = run.ay.clone().unwrap();
        let level = levelled(run, off).ay.unwrap();
        let last = raw.len() - 1;
        // As read, the turn's gravity term g·sin φ (0.24 m/s²) is in it.
        let excess = raw[last] - (truth[last] * (k * truth[last]).cos() - 0.6);
        assert!(
            (excess - G * (k * truth[last]).sin()).abs() < 0.01,
            "{excess}"
        );
        assert!(excess > 0.2, "{excess}");
        for (i, (l, a)) in level.iter().zip(&truth).enumerate() {
            let phi = k * a;
            let want = a - 0.6 / phi.cos();
            // The sensor's wobble of 6e-4 rad is g·6e-4 = 0.006 m/s².
            assert!((l - want).abs() < 0.007, "{i}: {l} against {want}");
        }
    }

    #[test]
    fn a_run_without_roll_keeps_its_ay() {
        let (mut run, _) = parked_then_turning(0.006, 0.0);
        run.roll = None;
        let ay = run.ay.clone();
        assert_eq!(levelled(run, 0.1).ay, ay);
        assert_eq!(gravity_term(&[0.1], 0.1), vec![0.0]);
        let thirty = gravity_term(&[std::f64::consts::FRAC_PI_6], 0.0)[0];
        assert!((thirty - 0.5 * G).abs() < 1e-12, "{thirty}");
    }
}
