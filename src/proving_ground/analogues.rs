//! Synthetic analogues of real logs the diagnosis fails on: campaigns with
//! what those logs have and the other programmes lack (a human or an
//! autonomous driver in the loop on a winding track, the speed varying,
//! standstills, a logger's offsets, held and quantised samples, a
//! sideslip measured away from the centre of gravity). Two programmes
//! drive the closed-loop driver of `closed_loop` on tracks of `winding`.
//!
//! ## `sedan-winding`: a heavy sedan driven by hand, far from the limit
//!
//! **Car.** A large sedan of 2,300 kg (kerb mass of the class, 2.0–2.2 t,
//! with driver and logging equipment): wheelbase 3.05 m, 52 % of the
//! weight on the front axle (a = 1.464 m, b = 1.586 m), tracks 1.63 /
//! 1.64 m (manufacturers' data of current large luxury sedans:
//! wheelbases 3.0–3.2 m, tracks 1.60–1.66 m); yaw inertia 4,800 kg m²,
//! a dynamic index k²/(a·b) of 0.9, and centre-of-gravity height 0.56 m,
//! both typical of the large sedans in NHTSA's measured inertial
//! parameters (Heydinger et al., *Measured Vehicle Inertial Parameters —
//! NHTSA's Data Through November 1998*, SAE 1999-01-1336). Tyres: the
//! bundled UniTire road tyre, whose peak friction is 0.97 at its rated
//! load of 5.7 kN (the sedan's front wheels carry 5.9 kN): a road tyre.
//! No rig data: the diagnosis identifies the axles from the runs.
//!
//! **Steering.** The road wheels follow the steering wheel through a
//! mildly progressive ratio, `δ = (θ/16)·(1 + 0.15·(θ/π)²)`: 16:1 on
//! centre, 13.9:1 at 180° of steering wheel (a variable-ratio rack); the
//! logger records θ/16, the fixed on-centre ratio, so in the tight
//! corners (150–230° of steering wheel) the road wheels turn 8–20 % more
//! than the logged steer says.
//!
//! **Driver and track.** A human driver ([`Driver`]: preview 1.2 s, at
//! least 7 m; reaction 0.2 s; neuromuscular lag 0.12 s; steering-wheel
//! rate at most 400°/s; a remnant of 1.5° RMS at the steering wheel)
//! drives a winding track of about 1 km (`sedan_lap`): right and left
//! corners of radii 12 to 80 m, two hairpins, a chicane, straights of 30
//! to 100 m, each corner at the speed a brisk driver takes it (|ay| of
//! 3.5–4.6 m/s², up to about 0.5 g with the driver's corrections),
//! straights at 12–19 m/s, accelerating at up to 1.8 m/s² and braking at
//! up to 3 m/s². Three runs, 100 Hz: parked 10 s then a lap (120 s);
//! parked 5 s, a lap with a stop of 15 s on its longest straight (135 s);
//! parked 5 s, the lap mirrored, every left a right (115 s). Speeds 0–19
//! m/s; no bank. `synth --duration` lengthens the runs of both analogues
//! in proportion (`plan_lasting`): the parked time and the stop stay, the
//! driver laps the track more often.
//!
//! **Logger** ([`Logger`]): `t, speed, steer, yaw_rate, ay, ax, beta` at
//! 100 Hz. Offsets: the accelerometer's mounting reads −0.6 m/s² at rest
//! (a tilt of 3.5° about the car's x axis), the gyro +0.005 rad/s (a MEMS
//! gyro's bias, 0.3°/s), the sideslip −0.01 rad (a heading misalignment of
//! 0.6°). The sideslip is measured at the inertial unit, 0.5 m ahead of
//! the centre of gravity: `β + 0.5·r/u` (u at least 1 m/s). The steer is
//! the steering-angle sensor's, quantised at 0.1° of steering wheel and
//! sent at 20 Hz, held in the 100 Hz log. Noise (white, Gaussian, seeded):
//! yaw rate 0.002 rad/s (an automotive gyro's rate noise, about
//! 0.015°/s/√Hz over 50 Hz, with road vibration), ay and ax 0.06 m/s² (an
//! accelerometer with engine and road vibration), sideslip 0.002 rad (a
//! GNSS-aided inertial unit's 0.1–0.15° slip accuracy), speed 0.02 m/s
//! while moving (wheel speeds read 0 at rest). The runs' standstills are
//! kept in the files (the diagnosis's cleaning leaves them out).
//!
//! ## `racing-rear-steer`: a racing car whose rear looks stiff
//!
//! The Putnam log's car (790 kg, 1,000 kg m², a = 1.248 m, b = 1.733 m,
//! a little down-force; `truth_vehicle`) on the UniTire, path-tracked by
//! an autonomous driver (preview 0.9 s, at least 10 m; reaction 0.08 s;
//! a steer actuator's lag of 0.08 s and rate limit of 0.6 rad/s of road
//! wheel; a remnant of 0.002 rad) around a road course of about 2.6 km
//! (`road_course`: corners of 18–120 m at 8.5–24 m/s, |ay| up to about
//! 5.5 m/s², straights up to 32 m/s, accelerating at up to 1.9 m/s² and
//! braking at up to 2.7 m/s², the Putnam log's levels). Its rear axle
//! steers with body roll ([`REAR_ROLL_STEER`], [`RACING_ROLL`]): in a
//! turn the rear wheels steer into it, so the rear makes more force at a
//! given body sideslip than its tyres alone would: the rear looks stiff.
//! Three runs of 100 s from 20 m/s, logged at 25 Hz like the Putnam log:
//! `t, speed, steer, yaw_rate, ax, beta` (steer the road wheels', no
//! `ay`, no bank), cut into 20 s pieces, no rig data. The sideslip is
//! measured 0.6 m ahead of the centre of gravity (where an independent
//! replay of the Putnam log puts it). Noise: yaw rate 0.003 rad/s and
//! sideslip 0.001 rad (the Putnam log's high-frequency scatter), ax 0.05
//! m/s², speed 0.02 m/s; no offsets.
//!
//! Units: SI, rad; ISO 8855.

use super::closed_loop::{drive, Driver, Steering};
use super::programme::Programme;
use super::winding::{corner, straight, Piece, Track};
use crate::diagnose::effects::{EffectKind, RollModel};
use crate::diagnose::model::Augmented;
use crate::identify::data::gauss;
use crate::measured::MeasuredRun;
use rand_chacha::ChaCha8Rng;

/// Step of the closed-loop integration, s (divides every logging interval).
const STEP: f64 = 0.002;

/// Rear roll steer of the racing analogue's truth, rad of rear steer per
/// rad of body roll (positive: the rear wheels steer left as the body rolls
/// right in a left turn, into the turn: roll understeer).
pub(super) const REAR_ROLL_STEER: f64 = 0.3;

/// The racing analogue's body roll: 2°/g, 2.5 Hz, ζ = 0.5.
pub(super) const RACING_ROLL: RollModel = RollModel {
    gradient: 2.0 * std::f64::consts::PI / 180.0 / crate::constants::G,
    frequency: 2.5,
    damping: 0.5,
};

/// The roll a racing analogue's campaign states (`campaigns/putnam.toml`'s
/// assumption for this car: about 1°/g, 3 Hz, ζ = 0.5), not the truth's.
pub(super) const RACING_CAMPAIGN_ROLL: RollModel = RollModel {
    gradient: 0.0018,
    frequency: 3.0,
    damping: 0.5,
};

/// What the logger does to the truth's response.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Logger {
    /// Logging rate, Hz.
    rate: f64,
    /// Rate at which the steer sensor sends (held in the log), Hz.
    steer_rate: f64,
    /// Resolution of the steer sensor, rad of steering wheel.
    steer_resolution: f64,
    /// Offsets of yaw rate (rad/s), ay (m/s²) and sideslip (rad).
    offsets: [f64; 3],
    /// Where the sideslip is measured, ahead of the centre of gravity, m.
    sideslip_ahead: f64,
    /// Noise of yaw rate, ay, ax, sideslip and speed (SI units).
    noise: [f64; 5],
    /// Whether `ay` is logged.
    ay: bool,
}

/// One run of an analogue.
struct Run {
    name: &'static str,
    pieces: Vec<Piece>,
    start: f64,
    parked: f64,
    duration: f64,
}

/// Everything an analogue does.
struct Plan {
    driver: Driver,
    steering: Steering,
    logger: Logger,
    /// Drive and brake levels, m/s² (positive).
    pedals: (f64, f64),
    runs: Vec<Run>,
}

/// One lap of the sedan's winding track (about 1 km).
fn sedan_lap() -> Vec<Piece> {
    vec![
        straight(60.0, 15.0),
        corner(40.0, -90.0, 13.0),
        straight(40.0, 16.0),
        corner(25.0, 120.0, 10.0),
        straight(30.0, 12.0),
        corner(12.0, -170.0, 6.5),
        straight(100.0, 19.0),
        corner(60.0, 70.0, 16.0),
        corner(80.0, -40.0, 18.5),
        straight(50.0, 18.0),
        corner(15.0, 160.0, 7.5),
        straight(40.0, 14.0),
        corner(30.0, -45.0, 11.0),
        corner(30.0, 45.0, 11.0),
        straight(80.0, 19.0),
        corner(45.0, 100.0, 14.0),
        straight(40.0, 17.0),
        corner(20.0, -90.0, 8.5),
        straight(60.0, 15.0),
    ]
}

/// The pieces mirrored: every left a right.
fn mirrored(pieces: &[Piece]) -> Vec<Piece> {
    pieces
        .iter()
        .map(|p| match *p {
            Piece::Corner {
                radius,
                angle,
                speed,
            } => Piece::Corner {
                radius,
                angle: -angle,
                speed,
            },
            other => other,
        })
        .collect()
}

/// `count` laps of `lap`, with a stop of `dwell` s after piece `at` of the
/// first when given.
fn laps(lap: &[Piece], stop: Option<(usize, f64)>, count: usize) -> Vec<Piece> {
    let mut out = lap.to_vec();
    if let Some((at, dwell)) = stop {
        out.insert(at + 1, Piece::Stop { dwell });
    }
    for _ in 1..count {
        out.extend_from_slice(lap);
    }
    out
}

/// The plan of an analogue programme with `count` laps a run (None for
/// the other programmes).
fn plan_with(programme: Programme, count: usize) -> Option<Plan> {
    match programme {
        Programme::SedanWinding => Some(sedan_plan(count)),
        Programme::RacingRearSteer => Some(racing_plan(count)),
        _ => None,
    }
}

/// The runs' total duration, s, of an analogue programme as it is driven
/// by default; None for the other programmes, whose runs are fixed
/// manoeuvres or laps and cannot be lengthened.
pub fn analogue_duration(programme: Programme) -> Option<f64> {
    plan_with(programme, 2).map(|p| p.runs.iter().map(|r| r.duration).sum())
}

/// The plan of an analogue programme whose runs last `total` s together
/// (None: its own durations): each run lengthened in proportion to its
/// own duration and rounded to whole seconds (the last takes what is
/// left, so that they add up to `total`), on more laps: two laps cover a
/// run's own duration, so `2·⌈k⌉ + 1` laps cover `k` times it. `total` is at
/// least the programme's own total (`synth` checks).
fn plan_lasting(programme: Programme, total: Option<f64>) -> Option<Plan> {
    let Some(total) = total else {
        return plan_with(programme, 2);
    };
    let k = total / analogue_duration(programme)?;
    // One lap more than the ratio says: a run's parked time and stop stay
    // as they are, so the lengthened run drives more than `k` times its
    // own driving; the extra lap covers that.
    let mut plan = plan_with(programme, 2 * k.ceil() as usize + 1)?;
    let mut left = total;
    let n = plan.runs.len();
    for (i, r) in plan.runs.iter_mut().enumerate() {
        r.duration = if i + 1 == n {
            left
        } else {
            (r.duration * k).round()
        };
        left -= r.duration;
    }
    Some(plan)
}

/// The sedan's stop in its second run: 15 s on the 100 m straight after
/// the right hairpin (after piece 6 of the lap).
const SEDAN_STOP: (usize, f64) = (6, 15.0);

/// The sedan analogue's plan, `count` laps a run.
fn sedan_plan(count: usize) -> Plan {
    let lap = sedan_lap();
    Plan {
        driver: Driver {
            preview_time: 1.2,
            min_preview: 7.0,
            reaction: 0.2,
            neuromuscular: 0.12,
            rate_limit: 400f64.to_radians(),
            remnant: 1.5f64.to_radians(),
        },
        steering: Steering {
            ratio: 16.0,
            progression: 0.15,
            reference: std::f64::consts::PI,
        },
        logger: Logger {
            rate: 100.0,
            steer_rate: 20.0,
            steer_resolution: 0.1f64.to_radians(),
            offsets: [0.005, -0.6, -0.01],
            sideslip_ahead: 0.5,
            noise: [0.002, 0.06, 0.06, 0.002, 0.02],
            ay: true,
        },
        pedals: (1.8, 3.0),
        runs: vec![
            Run {
                name: "winding_lap",
                pieces: laps(&lap, None, count),
                start: 0.0,
                parked: 10.0,
                duration: 120.0,
            },
            Run {
                name: "winding_stop",
                pieces: laps(&lap, Some(SEDAN_STOP), count),
                start: 0.0,
                parked: 5.0,
                duration: 135.0,
            },
            Run {
                name: "winding_mirrored",
                pieces: laps(&mirrored(&lap), None, count),
                start: 0.0,
                parked: 5.0,
                duration: 115.0,
            },
        ],
    }
}

/// One lap of the racing analogue's road course (about 2.6 km).
fn road_course() -> Vec<Piece> {
    vec![
        straight(250.0, 32.0),
        corner(40.0, -100.0, 13.5),
        straight(120.0, 25.0),
        corner(70.0, 80.0, 18.0),
        straight(80.0, 24.0),
        corner(120.0, -60.0, 24.0),
        straight(60.0, 24.0),
        corner(18.0, 150.0, 8.5),
        straight(180.0, 30.0),
        corner(50.0, 90.0, 15.0),
        corner(35.0, -70.0, 12.5),
        straight(100.0, 28.0),
        corner(90.0, -110.0, 20.0),
        straight(150.0, 30.0),
    ]
}

/// The racing analogue's plan, `count` laps a run after its first
/// partial one.
fn racing_plan(count: usize) -> Plan {
    let lap = road_course();
    // Each run starts at another point of the lap, rolling at 20 m/s.
    let from = |k: usize| -> Vec<Piece> {
        let mut p: Vec<Piece> = lap[k..].to_vec();
        for _ in 0..count {
            p.extend_from_slice(&lap);
        }
        p
    };
    let run = |name, k| Run {
        name,
        pieces: from(k),
        start: 20.0,
        parked: 0.0,
        duration: 100.0,
    };
    Plan {
        driver: Driver {
            preview_time: 0.9,
            min_preview: 10.0,
            reaction: 0.08,
            neuromuscular: 0.08,
            rate_limit: 0.6,
            remnant: 0.002,
        },
        steering: Steering::DIRECT,
        logger: Logger {
            rate: 25.0,
            steer_rate: 25.0,
            steer_resolution: 0.0,
            offsets: [0.0; 3],
            sideslip_ahead: 0.6,
            noise: [0.003, 0.0, 0.05, 0.001, 0.02],
            ay: false,
        },
        pedals: (1.9, 2.7),
        runs: vec![
            run("road_course_a", 0),
            run("road_course_b", 4),
            run("road_course_c", 8),
        ],
    }
}

/// The runs of an analogue programme driven by `truth` (None for the
/// others), with the logger's noise drawn from `rng` run by run, channel
/// by channel.
pub(super) fn analogue_runs(
    programme: Programme,
    truth: &Augmented,
    rng: &mut ChaCha8Rng,
    duration: Option<f64>,
) -> Option<Vec<MeasuredRun>> {
    let plan = plan_lasting(programme, duration)?;
    Some(
        plan.runs
            .iter()
            .map(|r| logged(&plan, r, truth, rng))
            .collect(),
    )
}

/// One run driven by `truth` and logged.
fn logged(plan: &Plan, run: &Run, truth: &Augmented, rng: &mut ChaCha8Rng) -> MeasuredRun {
    let track = Track::new(&run.pieces);
    let (u0, parked) = (run.start, run.parked);
    let (drive_level, brake_level) = plan.pedals;
    let (speed, ax) = track.drive(u0, parked, run.duration, STEP, drive_level, brake_level);
    let cl = drive(
        truth,
        &track,
        &plan.driver,
        &plan.steering,
        &speed,
        &ax,
        STEP,
    );
    let lg = &plan.logger;
    let every = (1.0 / (lg.rate * STEP)).round() as usize;
    let idx: Vec<usize> = (0..speed.len()).step_by(every).collect();
    let t: Vec<f64> = idx.iter().map(|&k| k as f64 * STEP).collect();
    let seen = truth.observe(&cl.history, &t);
    let [n_r, n_ay, n_ax, n_beta, n_u] = lg.noise;
    let [b_r, b_ay, b_beta] = lg.offsets;
    let mut noise = |s: f64| s * gauss(rng);
    let yaw_rate: Vec<f64> = seen.yaw_rate.iter().map(|r| r + b_r + noise(n_r)).collect();
    let ay: Vec<f64> = seen.ay.iter().map(|a| a + b_ay + noise(n_ay)).collect();
    let ax_log: Vec<f64> = idx.iter().map(|&k| ax[k] + noise(n_ax)).collect();
    let beta: Vec<f64> = idx
        .iter()
        .zip(&seen.beta)
        .zip(&seen.yaw_rate)
        .map(|((&k, b), r)| b + lg.sideslip_ahead * r / speed[k].max(1.0) + b_beta + noise(n_beta))
        .collect();
    let speed_log: Vec<f64> = idx
        .iter()
        .map(|&k| {
            let e = noise(n_u);
            if speed[k] > 0.0 {
                (speed[k] + e).max(0.0)
            } else {
                0.0
            }
        })
        .collect();
    // The steer sensor's last message: sent every 1/steer_rate s,
    // quantised at its resolution, converted at the fixed ratio.
    let hold = (1.0 / (lg.steer_rate * STEP)).round() as usize;
    let steer: Vec<f64> = idx
        .iter()
        .map(|&k| {
            let hand = cl.hand[k - k % hold];
            let q = if lg.steer_resolution > 0.0 {
                (hand / lg.steer_resolution).round() * lg.steer_resolution
            } else {
                hand
            };
            plan.steering.logged(q)
        })
        .collect();
    MeasuredRun::new(format!("{}.csv", run.name), t, speed_log, steer, yaw_rate)
        .with_ay(lg.ay.then_some(ay))
        .with_beta(beta)
        .with_ax(ax_log)
}

/// Puts into `truth` what an analogue's car has built in (the racing
/// analogue's rear roll steer and body roll), unless the effects asked for
/// set it (`roll_steer` switched on replaces the built-in one).
pub(super) fn build_in(programme: Programme, truth: &mut Augmented, asked: &[EffectKind]) {
    if programme == Programme::RacingRearSteer {
        truth.effects_mut().roll = RACING_ROLL;
        if !asked.contains(&EffectKind::RollSteer) {
            truth.effects_mut().roll_steer = [0.0, REAR_ROLL_STEER];
        }
    }
}

/// The roll an augmented truth's campaign file states for `programme`:
/// the racing analogue's is `campaigns/putnam.toml`'s assumption.
pub(super) fn campaign_roll(programme: Programme) -> RollModel {
    if programme == Programme::RacingRearSteer {
        RACING_CAMPAIGN_ROLL
    } else {
        RollModel::default()
    }
}

/// What an analogue's truth and logger do that the campaign file cannot
/// state, as `name = value` lines for its header (withheld from the
/// diagnosis, which reads none of them); empty for the other programmes.
pub(super) fn truth_lines(programme: Programme) -> Vec<String> {
    let Some(plan) = plan_with(programme, 2) else {
        return Vec::new();
    };
    let (s, l, d) = (plan.steering, plan.logger, plan.driver);
    let mut out = vec![
        format!("steering_ratio = {}", s.ratio),
        format!("steering_progression = {}", s.progression),
        format!("steering_progression_reference = {}", s.reference),
        format!("steer_sensor_rate = {}", l.steer_rate),
        format!("steer_sensor_resolution = {}", l.steer_resolution),
        format!("yaw_rate_offset = {}", l.offsets[0]),
        format!("ay_offset = {}", l.offsets[1]),
        format!("beta_offset = {}", l.offsets[2]),
        format!("beta_measured_ahead = {}", l.sideslip_ahead),
        format!(
            "noise = {{ yaw_rate = {}, ay = {}, ax = {}, beta = {}, speed = {} }}",
            l.noise[0], l.noise[1], l.noise[2], l.noise[3], l.noise[4]
        ),
        format!(
            "driver = {{ preview_time = {}, min_preview = {}, reaction = {}, neuromuscular = {}, rate_limit = {}, remnant = {} }}",
            d.preview_time, d.min_preview, d.reaction, d.neuromuscular, d.rate_limit, d.remnant
        ),
    ];
    if programme == Programme::RacingRearSteer {
        out.push(format!("rear_roll_steer = {REAR_ROLL_STEER}"));
        out.push(format!(
            "roll = {{ gradient = {}, frequency = {}, damping = {} }}",
            RACING_ROLL.gradient, RACING_ROLL.frequency, RACING_ROLL.damping
        ));
    }
    out
}

#[cfg(test)]
mod tests;
