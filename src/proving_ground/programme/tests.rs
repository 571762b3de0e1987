//! The logged programmes' runs: the speed through every leg's target, `ax`
//! its derivative, the standstills on the banking, the slow oval's speed
//! band and steer; the programmes' names.

use super::*;
use crate::proving_ground::driver::{LoggedInputs, LOG_RATE};
use crate::proving_ground::laps::{road_course_lap, OVAL_BANK};
use crate::proving_ground::truth::truth_tyre;
use crate::tyre::Tyre;
use crate::vehicle::Vehicle;

fn model() -> VehicleModel {
    let tyre: Tyre = truth_tyre();
    VehicleModel::new(Vehicle::compact_sedan(), tyre.clone(), tyre)
}

#[test]
fn the_speed_meets_every_legs_target_and_ax_is_its_derivative() {
    let m = model();
    let runs = logged_runs(Programme::RoadCourse, &m).unwrap();
    assert_eq!(runs.len(), 3);
    // The lap at pace 1.
    let r = &runs[2];
    // Between blends the speed runs through the legs' targets: half
    // way through a leg it is on the line between its two targets.
    let legs = road_course_lap();
    let (mut t0, mut u0) = (0.0, 30.0);
    for l in &legs {
        let k = ((t0 + 0.5 * l.duration) * LOG_RATE).round() as usize;
        let mid = u0 + (l.speed_end - u0) * (r.t[k] - t0) / l.duration;
        assert!(
            (r.speed[k] - mid).abs() < 1e-6,
            "t {}: {} vs {mid}",
            r.t[k],
            r.speed[k]
        );
        (t0, u0) = (t0 + l.duration, l.speed_end);
    }
    // Central differences of the speed against the logged ax: within
    // 0.1 m/s² where ax swings by up to 11 m/s² in a 0.4 s blend (the
    // difference's own error, h²/6 times the third derivative, is up
    // to 0.08 there), 1e-9 where it holds.
    for k in 1..r.t.len() - 1 {
        let du = (r.speed[k + 1] - r.speed[k - 1]) / (r.t[k + 1] - r.t[k - 1]);
        let steady = r.ax[k - 1] == r.ax[k] && r.ax[k] == r.ax[k + 1];
        let tol = if steady { 1e-9 } else { 0.1 };
        assert!(
            (du - r.ax[k]).abs() < tol,
            "t {}: {du} vs {}",
            r.t[k],
            r.ax[k]
        );
    }
    assert!(r.ax.iter().any(|a| *a < -4.0) && r.ax.iter().any(|a| *a > 1.5));
    // Trail braking: a sample that brakes hard while steering.
    assert!(r
        .ax
        .iter()
        .zip(&r.steer)
        .any(|(a, d)| *a < -3.0 && d.abs() > 0.01));
}

#[test]
fn the_oval_parks_on_the_banking_for_twenty_seconds() {
    let runs = logged_runs(Programme::Oval, &model()).unwrap();
    let r = &runs[1];
    let parked: Vec<usize> = (0..r.t.len()).filter(|&k| r.speed[k] == 0.0).collect();
    let seconds = parked.len() as f64 / LOG_RATE;
    assert!((19.0..22.0).contains(&seconds), "{seconds} s parked");
    assert!(parked
        .iter()
        .all(|&k| (r.bank[k] - OVAL_BANK).abs() < 1e-12 && r.ax[k] == 0.0));
    // Banked 20° in the turns, flat on the straights.
    let r = &runs[0];
    let min = r.bank.iter().cloned().fold(0.0, f64::min);
    assert!((min - OVAL_BANK).abs() < 1e-12);
    assert!(r.bank[..(4.0 * LOG_RATE) as usize]
        .iter()
        .all(|b| *b == 0.0));
    // Left turns: positive steer in the banked parts.
    let k = r.bank.iter().position(|b| *b == OVAL_BANK).unwrap() + 50;
    assert!(r.steer[k] > 0.0);
}

#[test]
fn the_slow_oval_laps_at_5_to_21_ms_banked_20_degrees_with_a_standstill() {
    let tyre: Tyre = truth_tyre();
    let mut m = VehicleModel::new(truth_vehicle(Programme::SlowOval), tyre.clone(), tyre);
    m.options.effects.aero_load = truth_downforce(Programme::SlowOval);
    let runs = logged_runs(Programme::SlowOval, &m).unwrap();
    assert_eq!(runs.len(), 3);
    let total: f64 = runs.iter().map(|r| r.t.last().unwrap() - r.t[0]).sum();
    assert!((total - 600.0).abs() < 0.1, "{total} s");
    for r in &runs {
        // Logged at 25 Hz.
        assert!(r
            .t
            .windows(2)
            .all(|w| (w[1] - w[0] - 1.0 / LOG_RATE).abs() < 1e-9));
        let max = r.speed.iter().cloned().fold(0.0, f64::max);
        assert!(max <= 21.0 + 1e-9, "{}: {max}", r.name);
        // Bank 0 on the straights, -20° in the turns.
        let min = r.bank.iter().cloned().fold(0.0, f64::min);
        assert!((min - OVAL_BANK).abs() < 1e-12);
        assert!(r.bank[..(4.0 * LOG_RATE) as usize]
            .iter()
            .all(|b| *b == 0.0));
    }
    // The band is 5 to 21 m/s outside the standstill run.
    let speeds = |r: &LoggedInputs| {
        r.speed
            .iter()
            .fold((f64::INFINITY, 0.0_f64), |(lo, hi), &u| {
                (lo.min(u), hi.max(u))
            })
    };
    let (lo, hi) = speeds(&runs[0]);
    // (The acceleration's blends round the speed's peaks off.)
    assert!(
        (20.9..=21.0).contains(&hi) && lo >= 12.0 - 1e-6,
        "{lo} {hi}"
    );
    let (lo, _) = speeds(&runs[2]);
    assert!((5.0..5.1).contains(&lo), "{lo}");
    // The standstill: 20 s parked on the banking.
    let r = &runs[1];
    let parked: Vec<usize> = (0..r.t.len()).filter(|&k| r.speed[k] == 0.0).collect();
    let seconds = parked.len() as f64 / LOG_RATE;
    assert!((19.0..23.0).contains(&seconds), "{seconds} s parked");
    assert!(parked
        .iter()
        .all(|&k| (r.bank[k] - OVAL_BANK).abs() < 1e-12 && r.ax[k] == 0.0));
    // Far below the neutral speed the tyres hold the car up the slope:
    // in the left turns the understeering car steers left, less than
    // it would for the turn's largest path acceleration on the flat.
    let r = &runs[0];
    let k = r.bank.iter().position(|b| *b == OVAL_BANK).unwrap() + 50;
    let flat = m
        .steady_state_for_lateral_acceleration(r.speed[k], 1.0, 0.9)
        .unwrap()
        .steer;
    assert!(m.understeer_gradient() > 0.0);
    assert!(
        r.steer[k] > 0.0 && r.steer[k] < flat,
        "{} {flat}",
        r.steer[k]
    );
}

#[test]
fn programme_names_parse_and_an_unknown_one_is_named() {
    for p in Programme::ALL {
        assert_eq!(p.name().parse::<Programme>().unwrap(), p);
    }
    let e = "ovals".parse::<Programme>().unwrap_err().to_string();
    assert!(e.contains("`ovals`") && e.contains("road-course"), "{e}");
}
