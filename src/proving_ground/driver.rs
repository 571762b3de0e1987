//! The open-loop driver of the logged programmes: each leg of a lap names
//! a target speed at its end and a lateral acceleration, and the steer is
//! the one that would hold that acceleration at the current speed on a
//! flat road (sized on the truth vehicle without effects), so where the
//! truth feels a bank or an effect the car's path differs, as a real car's
//! would: the diagnosis only compares responses to the recorded inputs. On
//! the slow oval the steer is sized on the banked road instead (the path's
//! acceleration u²/R less the bank's g·sin θ), as a driver below the
//! neutral speed steers, and carries small path-tracking corrections;
//! without `bank_profile` the truth drives it flat. Leg values blend into
//! each other by raised cosines; the speed integrates the blended
//! acceleration. The inputs are logged at [`LOG_RATE`]. Units: SI, rad.

use super::laps::Leg;
use crate::manoeuvre::Manoeuvre;
use crate::vehicle::VehicleModel;

/// The inputs of one logged run as the logger records them (before noise).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct LoggedInputs {
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
    pub(super) fn manoeuvre(&self) -> Manoeuvre {
        Manoeuvre::Replay(crate::manoeuvre::Replay::of_inputs(
            self.t.clone(),
            self.steer.clone(),
            self.speed.clone(),
        ))
    }
}
/// Logging rate of the logged programmes, Hz.
pub(super) const LOG_RATE: f64 = 25.0;
/// Blend time of the steer and the bank between legs, s.
const STEER_BLEND: f64 = 1.5;
/// Blend time of the longitudinal acceleration between legs, s.
const AX_BLEND: f64 = 0.4;
/// Below this speed the steer is sized as at this speed (a parked or
/// crawling car's steer stays finite), m/s.
const SIZING_SPEED: f64 = 5.0;
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
pub(super) fn drive_legs(
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
