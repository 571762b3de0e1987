//! The proving ground's test programmes: what the driver does in each run.
//!
//! - [`Programme::Handling`]: the handling test of a proving ground (step
//!   steers, a ramp, a sweep at constant speed on a flat road, 100 Hz);
//!   described in [`super`].
//! - [`Programme::Oval`]: a car on a banked oval, driven like a racing car
//!   and logged at 25 Hz: left turns banked 20° (the bank blends to 0° on
//!   the straights over about 1.5 s), braking at about 3 m/s² into every
//!   turn while turning in, throttle out of it, three runs at paces of 0.9
//!   to 1.05 (about 3 min of driving); the second run stops in turn 1 and
//!   stands parked on the banking for 20 s before it drives off.
//! - [`Programme::RoadCourse`]: a road course at 25 Hz: left and right
//!   corners with trail braking (up to about 4.4 m/s² while the steer comes
//!   in), throttle out, a chicane, corners banked up to 3.4° and one
//!   off-camber, three laps at paces of 0.85 to 1.0 (about 100 s).
//! - [`Programme::SlowOval`]: a light racing car (790 kg, the Putnam log's
//!   car, [`truth_vehicle`], with some downforce, [`truth_downforce`])
//!   lapping an oval whose turns are banked 20° at 5–21 m/s, far below
//!   the banking's neutral speed (about 30 m/s on the 250 m turns), so the
//!   tyres hold the car up the slope: the driver steers for the path on the
//!   banked road (the tyres pushing up the slope, the understeering car
//!   needs less steer than on a flat road). Three runs of
//!   200 s at paces 1.0, 0.7 (with a stop in turn 1 and 20 s parked on the
//!   banking) and 0.42, logged at 25 Hz with `ax`, `beta` and `bank` and no
//!   `ay` (the Putnam log's channels), no rig data.
//!
//! The levels are those this near-neutral sedan survives with every effect
//! of the library on: the driver is open-loop and does not catch a slide,
//! and harder braking with the rigid-body load transfer spins it.
//!
//! The two logged programmes record `t, speed, steer, yaw_rate, ay, ax,
//! bank` (no sideslip, as a racing logger): `ax` is the speed's derivative
//! plus noise, `bank` the road's bank from a track survey (no body roll in
//! it) plus noise. The driver is open-loop: each leg of a lap names a target
//! speed at its end and a lateral acceleration, and the steer is the one
//! that would hold that acceleration at the current speed on a flat road
//! (sized on the truth vehicle without effects), so where the truth feels
//! a bank or an effect the car's path differs, as a real car's would: the
//! diagnosis only compares responses to the recorded inputs. On the slow
//! oval the steer is sized on the banked road instead (the path's
//! acceleration u²/R less the bank's g·sin θ), as a driver below the
//! neutral speed steers; without `bank_profile` the truth drives it flat.
//!
//! Units: SI, rad; bank positive with the road's left edge higher
//! (`../shared/FORMATS.md`), so the oval's left turns are banked negative.

use crate::manoeuvre::Manoeuvre;
use crate::vehicle::{Vehicle, VehicleModel};
use serde::Serialize;

/// A test programme of the proving ground.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Programme {
    /// Steps, a ramp and a sweep at constant speed on a flat road, 100 Hz.
    #[default]
    Handling,
    /// A banked oval at 25 Hz with braking, throttle and a standstill.
    Oval,
    /// A road course at 25 Hz with trail braking and cambered corners.
    RoadCourse,
    /// A light racing car slowly lapping a 20° banked oval at 25 Hz, with a
    /// standstill on the banking, sideslip and no lateral acceleration.
    SlowOval,
}

impl Programme {
    /// Every programme.
    pub const ALL: [Programme; 4] = [
        Programme::Handling,
        Programme::Oval,
        Programme::RoadCourse,
        Programme::SlowOval,
    ];

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Programme::Handling => "handling",
            Programme::Oval => "oval",
            Programme::RoadCourse => "road-course",
            Programme::SlowOval => "slow-oval",
        }
    }

    /// Whether the runs carry a lateral acceleration (all but the slow
    /// oval's, which carry sideslip instead, as the Putnam log).
    pub fn logs_ay(self) -> bool {
        self != Programme::SlowOval
    }

    /// Whether the runs carry sideslip.
    pub fn logs_beta(self) -> bool {
        matches!(self, Programme::Handling | Programme::SlowOval)
    }

    /// Whether the campaign has tyre rig data (all but the slow oval's: its
    /// base model identifies the axles from the runs, as for the Putnam
    /// log).
    pub fn has_rig(self) -> bool {
        self != Programme::SlowOval
    }

    /// The length of the pieces the campaign cuts its runs into, s (the
    /// slow oval's `[runs] segment`).
    pub fn segment(self) -> Option<f64> {
        (self == Programme::SlowOval).then_some(SLOW_OVAL_SEGMENT)
    }

    /// The replay step its campaign states, s: the slow oval's, like a
    /// real 25 Hz log's campaign, replays at 20 ms (half the log's
    /// interval); the others take the default.
    pub fn replay_step(self) -> Option<f64> {
        (self == Programme::SlowOval).then_some(0.02)
    }

    /// Whether the runs carry `ax` and `bank` (the logged programmes).
    pub fn logged(self) -> bool {
        self != Programme::Handling
    }
}

impl std::str::FromStr for Programme {
    type Err = crate::error::Error;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        crate::error::by_name(&Self::ALL, |p| p.name(), "programme", s)
            .map_err(crate::error::Error::Options)
    }
}

/// The inputs of one logged run as the logger records them (before noise).
#[derive(Debug, Clone, PartialEq)]
pub struct LoggedInputs {
    /// Run name.
    pub name: String,
    /// Sample times, s.
    pub t: Vec<f64>,
    /// Speed, m/s.
    pub speed: Vec<f64>,
    /// Steer, rad.
    pub steer: Vec<f64>,
    /// Longitudinal acceleration (the speed's derivative), m/s².
    pub ax: Vec<f64>,
    /// Road bank, rad.
    pub bank: Vec<f64>,
}

impl LoggedInputs {
    /// The steer and speed as a replay manoeuvre.
    pub fn manoeuvre(&self) -> Manoeuvre {
        Manoeuvre::Replay(crate::manoeuvre::Replay {
            t: self.t.clone(),
            steer: self.steer.clone(),
            speed: self.speed.clone(),
        })
    }
}

/// One leg of a lap: its duration (s), the speed at its end (m/s), the
/// lateral acceleration the driver asks for (m/s², positive left) and the
/// road's bank (rad).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Leg {
    duration: f64,
    speed_end: f64,
    ay: f64,
    bank: f64,
}

const fn leg(duration: f64, speed_end: f64, ay: f64, bank: f64) -> Leg {
    Leg {
        duration,
        speed_end,
        ay,
        bank,
    }
}

/// Logging rate of the logged programmes, Hz.
pub const LOG_RATE: f64 = 25.0;
/// Blend time of the steer and the bank between legs, s.
const STEER_BLEND: f64 = 1.5;
/// Blend time of the longitudinal acceleration between legs, s.
const AX_BLEND: f64 = 0.4;
/// Below this speed the steer is sized as at this speed (a parked or
/// crawling car's steer stays finite), m/s.
const SIZING_SPEED: f64 = 5.0;

/// The oval's bank in the turns, rad (20°, left turns: left edge lower).
const OVAL_BANK: f64 = -0.349_065_850_398_865_9;

/// Duration of each slow-oval run, s.
const SLOW_OVAL_RUN: f64 = 200.0;
/// Piece length of the slow-oval campaign, s.
const SLOW_OVAL_SEGMENT: f64 = 20.0;

/// The car that drives `programme`: the compact sedan, or on the slow oval
/// a light racing car with the Putnam log's mass, yaw inertia and axle
/// distances (its track widths and centre-of-gravity height assumed as in
/// `campaigns/putnam.toml`).
pub fn truth_vehicle(programme: Programme) -> Vehicle {
    match programme {
        Programme::SlowOval => Vehicle {
            mass: 790.0,
            yaw_inertia: 1000.0,
            a: 1.248,
            b: 1.733,
            track_front: 1.6,
            track_rear: 1.55,
            cg_height: 0.3,
            ..Vehicle::compact_sedan()
        },
        _ => Vehicle::compact_sedan(),
    }
}

/// The truth car's own aerodynamic down-force (front, rear), N/(m/s)²:
/// none, or on the slow oval 0.3 and 0.4 (310 N at 21 m/s, 4 % of the
/// weight). Part of the truth the campaign file cannot state: the
/// diagnosis's base model does not have it.
pub fn truth_downforce(programme: Programme) -> [f64; 2] {
    match programme {
        Programme::SlowOval => [0.3, 0.4],
        _ => [0.0; 2],
    }
}

/// One lap of the slow oval from 12 m/s at pace 1: 250 m turns banked 20°
/// (path acceleration u²/R), flat straights.
fn slow_oval_lap() -> Vec<Leg> {
    let b = OVAL_BANK;
    vec![
        leg(8.0, 21.0, 0.0, 0.0),
        leg(3.0, 15.0, 0.6, b),
        leg(8.0, 15.0, 0.9, b),
        leg(3.0, 18.0, 0.5, b),
        leg(8.0, 21.0, 0.0, 0.0),
        leg(3.0, 14.0, 0.6, b),
        leg(8.0, 14.0, 0.8, b),
        leg(3.0, 12.0, 0.4, b),
    ]
}

/// `legs` filled to `duration` (s) with a straight at the last leg's
/// speed, or cut there.
fn fill_to(mut legs: Vec<Leg>, speed: f64, duration: f64) -> Vec<Leg> {
    let mut out = Vec::new();
    let mut used = 0.0;
    for l in legs.drain(..) {
        if used + l.duration > duration {
            break;
        }
        used += l.duration;
        out.push(l);
    }
    let end = out.last().map_or(speed, |l| l.speed_end);
    if duration - used > 1e-9 {
        out.push(leg(duration - used, end, 0.0, 0.0));
    }
    out
}

/// One lap of the oval from 30 m/s on the back straight, at pace 1.
fn oval_lap() -> Vec<Leg> {
    let b = OVAL_BANK;
    vec![
        leg(6.0, 36.0, 0.0, 0.0),
        leg(2.5, 28.0, 1.5, b),
        leg(5.0, 28.0, 4.5, b),
        leg(2.5, 32.0, 2.0, b),
        leg(5.0, 36.0, 0.0, 0.0),
        leg(2.5, 28.0, 1.5, b),
        leg(5.0, 28.0, 4.5, b),
        leg(2.5, 30.0, 2.0, b),
    ]
}

/// One lap of the road course from 30 m/s, at pace 1: T1 left (banked),
/// T2 right (off-camber), a chicane, T3 right (banked).
fn road_course_lap() -> Vec<Leg> {
    vec![
        leg(4.0, 36.0, 0.0, 0.0),
        leg(2.5, 25.0, 1.5, -0.04),
        leg(2.0, 25.0, 5.5, -0.04),
        leg(2.5, 30.0, 2.0, 0.0),
        leg(2.0, 32.0, 0.0, 0.0),
        leg(2.5, 22.0, -1.5, -0.03),
        leg(2.5, 22.0, -5.0, -0.03),
        leg(2.5, 27.0, -2.0, 0.0),
        leg(1.5, 27.0, 3.5, 0.0),
        leg(1.5, 27.0, -3.5, 0.0),
        leg(3.0, 34.0, 0.0, 0.0),
        leg(2.5, 25.0, -1.5, 0.06),
        leg(3.0, 25.0, -5.5, 0.06),
        leg(2.5, 30.0, -2.0, 0.0),
    ]
}

/// The legs at `pace`: speeds times the pace and lateral accelerations
/// times its square (the same line driven faster), durations over it.
fn at_pace(legs: &[Leg], pace: f64) -> Vec<Leg> {
    legs.iter()
        .map(|l| {
            leg(
                l.duration / pace,
                l.speed_end * pace,
                l.ay * pace * pace,
                l.bank,
            )
        })
        .collect()
}

/// The runs of a logged programme, their inputs sized on `model` (the
/// truth vehicle without effects). `None` for the handling programme.
pub fn logged_runs(programme: Programme, model: &VehicleModel) -> Option<Vec<LoggedInputs>> {
    let runs: Vec<(String, f64, Vec<Leg>)> = match programme {
        Programme::Handling => return None,
        Programme::Oval => {
            let laps = |pace: f64, n: usize| -> Vec<Leg> {
                (0..n).flat_map(|_| at_pace(&oval_lap(), pace)).collect()
            };
            // Stop in turn 1 and park on the banking, then drive off
            // straight along it.
            let mut stop = at_pace(&oval_lap(), 0.9);
            stop.extend([
                leg(2.5, 25.0, 1.5, OVAL_BANK),
                leg(6.0, 0.0, 0.0, OVAL_BANK),
                leg(20.0, 0.0, 0.0, OVAL_BANK),
                leg(10.0, 25.0, 0.0, OVAL_BANK),
                leg(4.0, 30.0 * 0.9, 0.0, 0.0),
            ]);
            stop.extend(at_pace(&oval_lap(), 0.9));
            vec![
                ("oval_pace100".into(), 30.0, laps(1.0, 2)),
                ("oval_stop_on_banking".into(), 30.0 * 0.9, stop),
                ("oval_pace105".into(), 30.0 * 1.05, laps(1.05, 1)),
            ]
        }
        Programme::RoadCourse => [0.85, 0.95, 1.0]
            .into_iter()
            .map(|p| {
                (
                    format!("lap_pace{:03.0}", 100.0 * p),
                    30.0 * p,
                    at_pace(&road_course_lap(), p),
                )
            })
            .collect(),
        Programme::SlowOval => {
            let laps = |pace: f64| -> Vec<Leg> {
                (0..8)
                    .flat_map(|_| at_pace(&slow_oval_lap(), pace))
                    .collect()
            };
            // Into turn 1, stop on the banking, stand there 20 s, drive off
            // along it, then lap on.
            let pace = 0.7;
            let mut stop = at_pace(&slow_oval_lap()[..1], pace);
            stop.extend([
                leg(3.0, 6.0, 0.6 * pace * pace, OVAL_BANK),
                leg(4.0, 0.0, 0.0, OVAL_BANK),
                leg(20.0, 0.0, 0.0, OVAL_BANK),
                leg(6.0, 10.0, 0.0, OVAL_BANK),
                leg(4.0, 12.0 * pace, 0.0, 0.0),
            ]);
            stop.extend(laps(pace));
            vec![
                ("slow_oval_pace100".into(), 12.0, laps(1.0)),
                ("slow_oval_stop_on_banking".into(), 12.0 * pace, stop),
                ("slow_oval_pace042".into(), 12.0 * 0.42, laps(0.42)),
            ]
            .into_iter()
            .map(|(name, u0, legs): (String, f64, Vec<Leg>)| {
                (name, u0, fill_to(legs, u0, SLOW_OVAL_RUN))
            })
            .collect()
        }
    };
    let banked = programme == Programme::SlowOval;
    Some(
        runs.into_iter()
            .map(|(name, u0, legs)| drive_legs(name, u0, &legs, model, banked))
            .collect(),
    )
}

/// Raised-cosine blend of a piecewise-constant leg value at `t`: within
/// `width/2` of a leg boundary the value moves smoothly from one leg's to
/// the next's. The blend is symmetric about the boundary, so a blended
/// acceleration integrates to the same speed change as the unblended one.
fn blended(bounds: &[f64], values: &[f64], width: f64, t: f64) -> f64 {
    let k = bounds
        .partition_point(|b| *b <= t)
        .saturating_sub(1)
        .min(values.len() - 1);
    let mut v = values[k];
    for (j, &b) in bounds.iter().enumerate().skip(1).take(values.len() - 1) {
        let s = (t - b) / width + 0.5;
        if (0.0..1.0).contains(&s) {
            let w = 0.5 - 0.5 * (std::f64::consts::PI * s).cos();
            v = values[j - 1] + w * (values[j] - values[j - 1]);
        }
    }
    v
}

/// The inputs of a run that starts at `u0` and drives `legs`, sampled at
/// [`LOG_RATE`]; with `banked` the steer holds each leg's path on the
/// banked road, else on a flat one.
fn drive_legs(
    name: String,
    u0: f64,
    legs: &[Leg],
    model: &VehicleModel,
    banked: bool,
) -> LoggedInputs {
    let mut sizing = model.clone();
    // Leg boundaries: bounds[k] is leg k's start; the last entry is the end.
    let mut bounds = vec![0.0];
    let mut speed_start = u0;
    let mut ax_leg = Vec::with_capacity(legs.len());
    for l in legs {
        ax_leg.push((l.speed_end - speed_start) / l.duration);
        speed_start = l.speed_end;
        bounds.push(bounds.last().copied().unwrap_or(0.0) + l.duration);
    }
    let ay_leg: Vec<f64> = legs.iter().map(|l| l.ay).collect();
    let bank_leg: Vec<f64> = legs.iter().map(|l| l.bank).collect();
    let end = bounds[legs.len()];
    // The speed integrates the blended acceleration on a fine grid
    // (trapezoids at 1 ms), sampled at the logging rate.
    let fine = 1e-3;
    let n_fine = (end / fine).round() as usize;
    let per_sample = (1.0 / (LOG_RATE * fine)).round() as usize;
    let starts = &bounds[..legs.len()];
    let ax_at = |t: f64| blended(starts, &ax_leg, AX_BLEND, t);
    let mut out = LoggedInputs {
        name,
        t: Vec::new(),
        speed: Vec::new(),
        steer: Vec::new(),
        ax: Vec::new(),
        bank: Vec::new(),
    };
    let mut u = u0;
    for i in 0..=n_fine {
        let t = i as f64 * fine;
        if i > 0 {
            u += 0.5 * fine * (ax_at(t - fine) + ax_at(t));
        }
        // Parked: the speed is 0, not the round-off of the integration.
        let speed = if u < 1e-6 { 0.0 } else { u };
        if i % per_sample != 0 {
            continue;
        }
        let ay = blended(starts, &ay_leg, STEER_BLEND, t);
        let sized = speed.max(SIZING_SPEED);
        // A crawling car asks for the acceleration of its path at speed.
        let ay = ay * (speed / sized).powi(2);
        out.t.push(t);
        out.speed.push(speed);
        out.ax.push(if speed > 0.0 { ax_at(t) } else { 0.0 });
        let bank = blended(starts, &bank_leg, STEER_BLEND, t);
        out.bank.push(bank);
        // On the banked road the accelerometer reads the path's
        // acceleration plus the bank's g·sin θ.
        let ay = if banked {
            sizing.options.effects.road_bank = model.options.effects.road_bank + bank;
            ay + sizing.bank_acceleration()
        } else {
            ay
        };
        let held = sizing
            .steady_state_for_lateral_acceleration(sized, 1.0, ay)
            .map(|s| s.steer)
            .unwrap_or_else(|e| panic!("the truth vehicle holds {ay} m/s² at {sized} m/s: {e}"));
        // An autonomous car's path tracking corrects its line all the
        // time: on the slow oval the steer carries small corrections
        // (0.2–1 Hz, none while parked), through which a steer actuator's
        // lag shows in the yaw rate as it does on a real log.
        let correction = if banked && speed > 0.0 {
            tracking_correction(t)
        } else {
            0.0
        };
        out.steer.push(held + correction);
    }
    out
}

/// Amplitude of the slow oval's path-tracking steer corrections, rad
/// (0.17° of road-wheel angle at each of three frequencies).
const TRACKING_STEER: f64 = 0.003;

/// The path-tracking steer correction at `t`, rad: three incommensurate
/// sines at 0.23, 0.51 and 0.97 Hz (a controller correcting its line
/// excites the yaw response over that band).
fn tracking_correction(t: f64) -> f64 {
    use std::f64::consts::TAU;
    TRACKING_STEER
        * ((TAU * 0.23 * t).sin() + (TAU * 0.51 * t + 1.0).sin() + (TAU * 0.97 * t + 2.0).sin())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tyre::Tyre;
    use crate::vehicle::Vehicle;

    fn model() -> VehicleModel {
        let tyre: Tyre = super::super::truth_tyre();
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
        let tyre: Tyre = super::super::truth_tyre();
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
}
