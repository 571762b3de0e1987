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
//!   `ay` (the Putnam log's channels), no rig data;
//!   [`Programme::SlowOvalNoBeta`] the same without its `beta` column, and
//!   [`Programme::SlowOvalEstimatedBeta`] with a `beta` as a state
//!   estimator gives it (smooth, with a drifting error; `estimator`),
//!   both with runs of 100 s (the first 100 s of the slow oval's runs).
//! - [`Programme::SedanWinding`] and [`Programme::RacingRearSteer`]: the
//!   analogues of real logs (`analogues`), driven by a closed-loop driver
//!   on winding tracks: a heavy sedan by hand with a logger's offsets, and
//!   the Putnam log's car whose rear axle steers with roll.
//!
//! The levels are those this near-neutral sedan survives with every effect
//! of the library on: the driver is open-loop and does not catch a slide,
//! and harder braking with the rigid-body load transfer spins it.
//!
//! The two logged programmes record `t, speed, steer, yaw_rate, ay, ax,
//! bank` (no sideslip, as a racing logger): `ax` is the speed's derivative
//! plus noise, `bank` the road's bank from a track survey (no body roll in
//! it) plus noise. The laps are in `laps`, the open-loop driver who turns
//! them into logged inputs in `driver`.
//!
//! Units: SI, rad; bank positive with the road's left edge higher, so the
//! oval's left turns are banked negative.

use super::driver::{drive_legs, LoggedInputs};
use super::laps::{
    at_pace, fill_to, leg, oval_lap, road_course_lap, slow_oval_lap, Leg, OVAL_BANK,
};
use crate::manoeuvre::{Manoeuvre, RampSteer, StepSteer, SweepSteer};
use crate::vehicle::{Vehicle, VehicleModel};
use serde::Serialize;

#[cfg(test)]
mod tests;

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
    /// The slow oval without its sideslip column.
    SlowOvalNoBeta,
    /// The slow oval with a sideslip as a state estimator gives it.
    SlowOvalEstimatedBeta,
    /// A 2.3 t sedan driven by hand on a winding track at 0–19 m/s, 100 Hz,
    /// with a logger's offsets, a progressive steering ratio, a held steer
    /// and the sideslip measured ahead of the centre of gravity.
    SedanWinding,
    /// The Putnam log's car path-tracked around a road course, its rear
    /// axle steering with roll, logged as the Putnam log.
    RacingRearSteer,
}

impl Programme {
    /// Every programme.
    pub(crate) const ALL: [Programme; 8] = [
        Programme::Handling,
        Programme::Oval,
        Programme::RoadCourse,
        Programme::SlowOval,
        Programme::SlowOvalNoBeta,
        Programme::SlowOvalEstimatedBeta,
        Programme::SedanWinding,
        Programme::RacingRearSteer,
    ];

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Programme::Handling => "handling",
            Programme::Oval => "oval",
            Programme::RoadCourse => "road-course",
            Programme::SlowOval => "slow-oval",
            Programme::SlowOvalNoBeta => "slow-oval-no-beta",
            Programme::SlowOvalEstimatedBeta => "slow-oval-estimated-beta",
            Programme::SedanWinding => "sedan-winding",
            Programme::RacingRearSteer => "racing-rear-steer",
        }
    }

    /// Whether this is the slow oval or one of its variants (the same car,
    /// laps and truth; another `beta` column).
    pub fn slow_oval(self) -> bool {
        matches!(
            self,
            Programme::SlowOval | Programme::SlowOvalNoBeta | Programme::SlowOvalEstimatedBeta
        )
    }

    /// Whether the runs carry a lateral acceleration (all but the slow
    /// ovals' and the racing analogue's, which carry sideslip instead, as
    /// the Putnam log).
    pub(super) fn logs_ay(self) -> bool {
        !self.slow_oval() && self != Programme::RacingRearSteer
    }

    /// Whether the runs carry sideslip.
    pub(super) fn logs_beta(self) -> bool {
        matches!(
            self,
            Programme::Handling
                | Programme::SlowOval
                | Programme::SlowOvalEstimatedBeta
                | Programme::SedanWinding
                | Programme::RacingRearSteer
        )
    }

    /// Whether the runs carry the road's bank (the racing programmes on
    /// banked tracks; the analogues' tracks are flat and logged without).
    pub fn logs_bank(self) -> bool {
        matches!(self, Programme::Oval | Programme::RoadCourse) || self.slow_oval()
    }

    /// Whether the campaign has tyre rig data (not the slow ovals' nor the
    /// analogues': their base model identifies the axles from the runs, as
    /// for the Putnam log).
    pub(super) fn has_rig(self) -> bool {
        matches!(
            self,
            Programme::Handling | Programme::Oval | Programme::RoadCourse
        )
    }

    /// The length of the pieces the campaign cuts its runs into, s (the
    /// slow ovals' and the racing analogue's `[runs] segment`, as the
    /// Putnam log's campaign).
    pub(super) fn segment(self) -> Option<f64> {
        (self.slow_oval() || self == Programme::RacingRearSteer).then_some(SLOW_OVAL_SEGMENT)
    }

    /// The replay step its campaign states, s: the 25 Hz slow ovals' and
    /// racing analogue's, like a real 25 Hz log's campaign, replay at 20 ms
    /// (half the log's interval); the others take the default.
    pub(super) fn replay_step(self) -> Option<f64> {
        (self.slow_oval() || self == Programme::RacingRearSteer).then_some(0.02)
    }

    /// Whether the runs carry `ax` and `bank` (the logged programmes).
    pub fn logged(self) -> bool {
        self != Programme::Handling
    }
}

impl std::str::FromStr for Programme {
    type Err = crate::error::Error;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        crate::error::named(
            &Self::ALL,
            |p| p.name(),
            crate::error::NameKind::Programme,
            s,
        )
        .map_err(crate::error::Error::Options)
    }
}
/// Duration of each slow-oval run, s.
const SLOW_OVAL_RUN: f64 = 200.0;
/// Duration of each run of the slow oval's variants, s: half the slow
/// oval's (every run keeps a lap or more, the stop on the banking
/// included), so that their diagnosis costs half as much.
const SLOW_OVAL_VARIANT_RUN: f64 = 100.0;
/// Piece length of the slow-oval campaign, s.
const SLOW_OVAL_SEGMENT: f64 = 20.0;

/// The 2.3 t sedan of `sedan-winding` (the analogue of a heavy sedan's
/// log).
fn large_sedan() -> Vehicle {
    Vehicle {
        mass: 2300.0,
        yaw_inertia: 4800.0,
        a: 1.464,
        b: 1.586,
        track_front: 1.63,
        track_rear: 1.64,
        cg_height: 0.56,
        ..Vehicle::compact_sedan()
    }
}

/// The car that drives `programme`: the compact sedan, on the slow ovals
/// and the racing analogue a light racing car with the Putnam log's mass,
/// yaw inertia and axle distances (its track widths and centre-of-gravity
/// height assumed as in `campaigns/putnam.toml`), on the winding track the
/// sedan analogue's large sedan.
pub(super) fn truth_vehicle(programme: Programme) -> Vehicle {
    match programme {
        Programme::SedanWinding => large_sedan(),
        p if p.slow_oval() || p == Programme::RacingRearSteer => Vehicle {
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
/// none, or on the slow ovals and the racing analogue 0.3 and 0.4 (310 N
/// at 21 m/s, 4 % of the weight). Part of the truth the campaign file
/// cannot state: the diagnosis's base model does not have it.
pub(super) fn truth_downforce(programme: Programme) -> [f64; 2] {
    if programme.slow_oval() || programme == Programme::RacingRearSteer {
        [0.3, 0.4]
    } else {
        [0.0; 2]
    }
}
/// The test programme: (name, manoeuvre) with the steer sized on the truth
/// vehicle without effects.
pub(super) fn handling_programme(model: &VehicleModel) -> Vec<(String, Manoeuvre)> {
    let steer_for = |u: f64, ay: f64| {
        model
            .steady_state_for_lateral_acceleration(u, 1.0, ay)
            .map(|s| s.steer)
            .expect("the truth vehicle holds these levels")
    };
    let pre = 3.0;
    let step = |name: &str, kph: f64, ay: f64| {
        let u = kph / 3.6;
        (
            name.to_string(),
            Manoeuvre::StepSteer(StepSteer {
                speed: u,
                amplitude: steer_for(u, ay),
                trim: 0.0,
                start: pre + 1.0,
                rise_time: 0.15,
                end: pre + 6.0,
            }),
        )
    };
    let u80 = 80.0 / 3.6;
    vec![
        step("step_040kph_3ms2", 40.0, 3.0),
        step("step_060kph_2ms2", 60.0, 2.0),
        step("step_100kph_2ms2", 100.0, 2.0),
        step("step_100kph_6ms2", 100.0, 6.0),
        step("step_120kph_4ms2", 120.0, 4.0),
        step("step_080kph_right_4ms2", 80.0, -4.0),
        (
            "ramp_080kph".into(),
            Manoeuvre::RampSteer(RampSteer {
                speed: u80,
                rate: 1.4 * steer_for(u80, 7.0) / 8.0,
                start: pre + 1.0,
                end: pre + 9.0,
            }),
        ),
        (
            "sweep_080kph".into(),
            Manoeuvre::Sweep(SweepSteer {
                speed: u80,
                amplitude: steer_for(u80, 3.0),
                f_start: 0.1,
                f_end: 3.0,
                start: pre + 1.0,
                end: pre + 21.0,
            }),
        ),
    ]
}

/// The runs of a logged programme, their inputs sized on `model` (the
/// truth vehicle without effects). `None` for the handling programme.
pub(super) fn logged_runs(programme: Programme, model: &VehicleModel) -> Option<Vec<LoggedInputs>> {
    let runs: Vec<(String, f64, Vec<Leg>)> = match programme {
        Programme::Handling | Programme::SedanWinding | Programme::RacingRearSteer => return None,
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
        Programme::SlowOval | Programme::SlowOvalNoBeta | Programme::SlowOvalEstimatedBeta => {
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
                let run = if programme == Programme::SlowOval {
                    SLOW_OVAL_RUN
                } else {
                    SLOW_OVAL_VARIANT_RUN
                };
                (name, u0, fill_to(legs, u0, run))
            })
            .collect()
        }
    };
    let banked = programme.slow_oval();
    Some(
        runs.into_iter()
            .map(|(name, u0, legs)| drive_legs(name, u0, &legs, model, banked))
            .collect(),
    )
}
