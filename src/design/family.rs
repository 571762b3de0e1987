//! The family of manoeuvres a design searches, within the limits of what
//! the car and its driver did in the campaign ([`Limits`]): steps of
//! several sizes at several speeds, ramps, sine sweeps, a double lane
//! change, a speed change on a straight, a steady turn with a speed change
//! (braking and accelerating), and a constant-radius turn at rising speed.
//! Every manoeuvre is a schedule of steer and speed (linear between
//! breakpoints, [`Manoeuvre::Replay`]) that starts from straight running
//! with a second at steady speed, so a scenario file and the proving
//! ground drive exactly what was designed. Steers are sized for a target
//! lateral acceleration by the steady state of the base model.
//!
//! Units: SI, rad; positive steer turns left (ISO 8855).

use crate::diagnose::model::Augmented;
use crate::manoeuvre::{Manoeuvre, Replay};
use crate::measured::MeasuredRun;
use serde::Serialize;

/// What a designed manoeuvre may ask of the car and driver.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Limits {
    /// Lowest and highest speed, m/s: the 5 and 95 % points of the runs'
    /// speeds above the diagnosis's lowest speed.
    pub speed: (f64, f64),
    /// The lateral acceleration the runs reached, m/s²: the 99 % point of
    /// |ay| (of |u·r| where no run measures ay).
    pub ay_reached: f64,
    /// The share of it a design may ask.
    pub ay_share: f64,
    /// The largest steer rate, rad/s (road wheel): the runs' 99 % point
    /// (rates over 0.1 s), at least [`MIN_STEER_RATE`].
    pub steer_rate: f64,
    /// The largest |du/dt|, m/s²: stated (the runs' 99 % point over
    /// 0.1 s where larger).
    pub ax: f64,
}

/// A steer rate any driver makes, rad/s of road wheel (a 0.15 s step of 3°).
pub const MIN_STEER_RATE: f64 = 0.35;

/// The span a rate of the runs is taken over, s.
const RATE_SPAN: f64 = 0.1;

/// The |ax| a design may use when none is stated, m/s² (moderate braking).
pub const DEFAULT_AX: f64 = 3.0;

/// The largest |ax| a design may be asked, m/s²: beyond what tyres give
/// (μ ≈ 1.5).
pub const MAX_AX: f64 = 15.0;

/// The share of the reached lateral acceleration a design may ask by
/// default.
pub const DEFAULT_AY_SHARE: f64 = 0.8;

fn percentile(mut v: Vec<f64>, q: f64) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    v[((v.len() - 1) as f64 * q).round() as usize]
}

impl Limits {
    /// The limits of runs `runs` (moving above `min_speed`), with the
    /// stated `ay_share` and `ax`.
    pub fn of(runs: &[MeasuredRun], min_speed: f64, ay_share: f64, ax: f64) -> Self {
        let (mut speeds, mut ays, mut rates, mut axs) = (vec![], vec![], vec![], vec![]);
        for r in runs {
            let mut j = 0;
            for i in 0..r.t.len() {
                if r.speed[i] < min_speed {
                    continue;
                }
                speeds.push(r.speed[i]);
                ays.push(match &r.ay {
                    Some(a) => a[i].abs(),
                    None => (r.speed[i] * r.yaw_rate[i]).abs(),
                });
                // Rates over at least RATE_SPAN: a logger's sample-to-sample
                // noise, differentiated, is no rate the driver made.
                j = j.max(i);
                while j < r.t.len() && r.t[j] - r.t[i] < RATE_SPAN {
                    j += 1;
                }
                if j < r.t.len() {
                    let dt = r.t[j] - r.t[i];
                    rates.push(((r.steer[j] - r.steer[i]) / dt).abs());
                    axs.push(((r.speed[j] - r.speed[i]) / dt).abs());
                }
            }
        }
        Self {
            speed: (percentile(speeds.clone(), 0.05), percentile(speeds, 0.95)),
            ay_reached: percentile(ays, 0.99),
            ay_share,
            steer_rate: percentile(rates, 0.99).max(MIN_STEER_RATE),
            ax: ax.max(percentile(axs, 0.99)),
        }
    }

    /// The largest lateral acceleration a design may ask, m/s².
    pub fn ay_max(&self) -> f64 {
        self.ay_share * self.ay_reached
    }
}

/// The kinds of manoeuvre in the family.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    /// A steer step at constant speed.
    Step,
    /// A steer ramp at constant speed.
    Ramp,
    /// A sine sweep of the steer at constant speed.
    Sweep,
    /// A double lane change at constant speed.
    LaneChange,
    /// A speed change on a straight.
    SpeedChange,
    /// A steady turn whose speed falls (braking in the turn).
    BrakeInTurn,
    /// A steady turn whose speed rises.
    AccelerateInTurn,
    /// A constant-radius turn at rising speed.
    ConstantRadius,
}

/// One manoeuvre of the family.
#[derive(Debug, Clone, PartialEq)]
pub struct Designed {
    /// Its name (the scenario file's stem).
    pub name: String,
    /// Its kind.
    pub kind: Kind,
    /// What the driver does, in words.
    pub description: String,
    /// The schedule.
    pub manoeuvre: Manoeuvre,
}

/// The smallest speed change a manoeuvre is built around, m/s: less is
/// a manoeuvre at constant speed with a little noise in it.
pub const MIN_SPEED_CHANGE: f64 = 1.0;

/// Lead-in at steady speed and straight, s.
pub const LEAD: f64 = 1.0;
/// Sample interval of the sampled schedules (sweeps, lane changes, the
/// constant radius), s.
const SAMPLE: f64 = 0.02;

/// A schedule from its breakpoints.
fn schedule(points: Vec<(f64, f64, f64)>) -> Manoeuvre {
    Manoeuvre::Replay(Replay::of_inputs(
        points.iter().map(|p| p.0).collect(),
        points.iter().map(|p| p.1).collect(),
        points.iter().map(|p| p.2).collect(),
    ))
}

/// The steer that holds lateral acceleration `ay` at `speed` on `model`
/// (None beyond its limit).
fn steer_for(model: &Augmented, speed: f64, ay: f64) -> Option<f64> {
    let m = &model.model;
    let trim = m.straight_running(speed, model.friction).ok()?;
    let s = m
        .steady_state_for_lateral_acceleration(speed, model.friction, ay)
        .ok()?;
    Some(s.steer - trim.steer)
}

/// The family within `limits`, steers sized on `model` (the base model).
pub fn family(model: &Augmented, limits: &Limits) -> Vec<Designed> {
    family_and_left_out(model, limits).0
}

/// The family within `limits`, and the manoeuvres of it the limits leave
/// out (a speed change too short at the stated |ax|, a steer beyond any
/// steady state of the base model, …), each named by its kind and speed.
pub fn family_and_left_out(model: &Augmented, limits: &Limits) -> (Vec<Designed>, Vec<String>) {
    let (lo, hi) = limits.speed;
    let speeds = [lo, 0.5 * (lo + hi), hi];
    let ay = limits.ay_max();
    let mut out = Vec::new();
    let mut left = Vec::new();
    let mut take = |what: &str, at: Option<(f64, f64)>, d: Option<Designed>| match d {
        Some(d) => out.push(d),
        None => left.push(match at {
            Some((u, ay)) => format!("{what} at {:.0} km/h and {ay:.1} m/s²", kmh(u)),
            None => what.to_string(),
        }),
    };
    for &u in &speeds {
        for share in [0.4, 0.7, 1.0] {
            take(
                "a step",
                Some((u, share * ay)),
                step(model, limits, u, share * ay),
            );
        }
        take("a ramp", Some((u, ay)), ramp(model, u, ay));
        take(
            "a sweep",
            Some((u, 0.4 * ay)),
            sweep(model, limits, u, 0.4 * ay),
        );
        take(
            "a lane change",
            Some((u, 0.6 * ay)),
            lane_change(model, limits, u, 0.6 * ay),
        );
    }
    take("the speed change on a straight", None, speed_change(limits));
    for &u in &speeds[1..] {
        for share in [0.5, 0.9] {
            take(
                "braking in a turn",
                Some((u, share * ay)),
                brake_in_turn(model, limits, u, share * ay),
            );
        }
    }
    for &u in &speeds[..2] {
        take(
            "accelerating in a turn",
            Some((u, 0.5 * ay)),
            accelerate_in_turn(model, limits, u, 0.5 * ay),
        );
    }
    take(
        "the constant-radius turn",
        None,
        constant_radius(model, limits),
    );
    (out, left)
}

fn kmh(u: f64) -> f64 {
    (u * 3.6).round()
}

fn step(model: &Augmented, limits: &Limits, u: f64, ay: f64) -> Option<Designed> {
    let d = steer_for(model, u, ay)?;
    let rise = (d.abs() / limits.steer_rate).max(0.15);
    Some(Designed {
        name: format!("step_{:03}kph_{:.1}ms2", kmh(u), ay),
        kind: Kind::Step,
        description: format!(
            "a steer step of {:.2}° in {rise:.2} s at {:.0} km/h, held 4 s (sized on the base model for {ay:.1} m/s²)",
            d.to_degrees(),
            kmh(u)
        ),
        manoeuvre: schedule(vec![
            (0.0, 0.0, u),
            (LEAD, 0.0, u),
            (LEAD + rise, d, u),
            (LEAD + 4.0, d, u),
        ]),
    })
}

fn ramp(model: &Augmented, u: f64, ay: f64) -> Option<Designed> {
    let d = steer_for(model, u, ay)?;
    let t = 8.0;
    Some(Designed {
        name: format!("ramp_{:03}kph", kmh(u)),
        kind: Kind::Ramp,
        description: format!(
            "a steer ramp to {:.2}° over {t:.0} s at {:.0} km/h",
            d.to_degrees(),
            kmh(u)
        ),
        manoeuvre: schedule(vec![(0.0, 0.0, u), (LEAD, 0.0, u), (LEAD + t, d, u)]),
    })
}

/// A sampled schedule of steer `f(τ)` at speed `u` for `length` s after the
/// lead-in, then 2 s straight.
fn sampled(u: f64, length: f64, f: impl Fn(f64) -> f64) -> Manoeuvre {
    let n = (length / SAMPLE).round() as usize;
    let mut p = vec![(0.0, 0.0, u)];
    p.extend((0..=n).map(|k| {
        let tau = k as f64 * SAMPLE;
        (LEAD + tau, f(tau), u)
    }));
    p.push((LEAD + length + 2.0, 0.0, u));
    schedule(p)
}

fn sweep(model: &Augmented, limits: &Limits, u: f64, ay: f64) -> Option<Designed> {
    use std::f64::consts::TAU;
    let (f0, t) = (0.2, 12.0);
    // The chirp's steer rate peaks at 2π·f1·d: the top frequency comes down
    // to the driver's rate (to 1.5 Hz at least), then the amplitude.
    let d = steer_for(model, u, ay)?;
    let f1 = (limits.steer_rate / (TAU * d.abs())).clamp(1.5, 3.0);
    let d = d.signum() * d.abs().min(limits.steer_rate / (TAU * f1));
    let k = (f1 - f0) / t;
    Some(Designed {
        name: format!("sweep_{:03}kph", kmh(u)),
        kind: Kind::Sweep,
        description: format!(
            "a steer sweep of ±{:.2}° from {f0} to {f1:.2} Hz over {t:.0} s at {:.0} km/h",
            d.to_degrees(),
            kmh(u)
        ),
        manoeuvre: sampled(u, t, |tau| {
            d * (TAU * (f0 * tau + 0.5 * k * tau * tau)).sin()
        }),
    })
}

fn lane_change(model: &Augmented, limits: &Limits, u: f64, ay: f64) -> Option<Designed> {
    use std::f64::consts::TAU;
    // Two lane changes of one sine period each (out and back), 0.5 Hz: a
    // lateral offset of about ay/(2π·f)² ≈ 2.5 m at 2.5 m/s². Its steer
    // rate peaks at 2π·f·d: slower (to 0.25 Hz) where the driver's rate
    // asks it, then smaller.
    let d = steer_for(model, u, ay)?;
    let f = (limits.steer_rate / (TAU * d.abs())).clamp(0.25, 0.5);
    let d = d.signum() * d.abs().min(limits.steer_rate / (TAU * f));
    let period = 1.0 / f;
    Some(Designed {
        name: format!("lane_change_{:03}kph", kmh(u)),
        kind: Kind::LaneChange,
        description: format!(
            "a double lane change: two sine periods of ±{:.2}° at {f} Hz, the second mirrored, at {:.0} km/h",
            d.to_degrees(),
            kmh(u)
        ),
        manoeuvre: sampled(u, 2.0 * period + 1.0, |tau| {
            if tau < period {
                d * (TAU * f * tau).sin()
            } else if tau < period + 1.0 {
                0.0
            } else if tau < 2.0 * period + 1.0 {
                -d * (TAU * f * (tau - period - 1.0)).sin()
            } else {
                0.0
            }
        }),
    })
}

fn speed_change(limits: &Limits) -> Option<Designed> {
    let (lo, hi) = limits.speed;
    let t = (hi - lo) / limits.ax;
    (hi - lo >= MIN_SPEED_CHANGE).then(|| Designed {
        name: format!("speed_change_{:03}_{:03}kph", kmh(hi), kmh(lo)),
        kind: Kind::SpeedChange,
        description: format!(
            "braking on a straight from {:.0} to {:.0} km/h at {:.1} m/s², then 3 s steady",
            kmh(hi),
            kmh(lo),
            limits.ax
        ),
        manoeuvre: schedule(vec![
            (0.0, 0.0, hi),
            (LEAD, 0.0, hi),
            (LEAD + t, 0.0, lo),
            (LEAD + t + 3.0, 0.0, lo),
        ]),
    })
}

/// A steady turn entered in 1 s at `u`, held 2 s, then the speed changed
/// at `rate` (m/s², signed) for up to 3 s within the speed range, the
/// steer held, then 2 s at the new speed.
fn turn_with_speed_change(
    model: &Augmented,
    limits: &Limits,
    u: f64,
    ay: f64,
    rate: f64,
) -> Option<(f64, f64, f64, Manoeuvre)> {
    let d = steer_for(model, u, ay)?;
    let (lo, hi) = limits.speed;
    let end = (u + 3.0 * rate).clamp(lo, hi);
    let t = (end - u) / rate;
    if t < 0.5 || (end - u).abs() < MIN_SPEED_CHANGE {
        return None;
    }
    // Into the turn in 1 s, or slower where the driver's rate asks it.
    let entry = (d.abs() / limits.steer_rate).max(1.0);
    let s = LEAD + entry + 2.0;
    Some((
        d,
        end,
        t,
        schedule(vec![
            (0.0, 0.0, u),
            (LEAD, 0.0, u),
            (LEAD + entry, d, u),
            (s, d, u),
            (s + t, d, end),
            (s + t + 2.0, d, end),
        ]),
    ))
}

fn brake_in_turn(model: &Augmented, limits: &Limits, u: f64, ay: f64) -> Option<Designed> {
    let (d, end, t, m) = turn_with_speed_change(model, limits, u, ay, -limits.ax)?;
    Some(Designed {
        name: format!("brake_in_turn_{:03}kph_{:.1}ms2", kmh(u), ay),
        kind: Kind::BrakeInTurn,
        description: format!(
            "a steady turn at {:.0} km/h ({:.2}° of steer, sized on the base model for {ay:.1} m/s²), then braking to {:.0} km/h in {t:.1} s, the steer held",
            kmh(u),
            d.to_degrees(),
            kmh(end)
        ),
        manoeuvre: m,
    })
}

fn accelerate_in_turn(model: &Augmented, limits: &Limits, u: f64, ay: f64) -> Option<Designed> {
    // Accelerating raises ay with u² at a held steer: half the braking rate.
    let (d, end, t, m) = turn_with_speed_change(model, limits, u, ay, 0.5 * limits.ax)?;
    Some(Designed {
        name: format!("accelerate_in_turn_{:03}kph_{:.1}ms2", kmh(u), ay),
        kind: Kind::AccelerateInTurn,
        description: format!(
            "a steady turn at {:.0} km/h ({:.2}° of steer, sized on the base model for {ay:.1} m/s²), then accelerating to {:.0} km/h in {t:.1} s, the steer held",
            kmh(u),
            d.to_degrees(),
            kmh(end)
        ),
        manoeuvre: m,
    })
}

fn constant_radius(model: &Augmented, limits: &Limits) -> Option<Designed> {
    let (lo, hi) = limits.speed;
    let ay = limits.ay_max();
    // At most 30 s on the circle: where the stated |du/dt| cannot cover
    // the speed range in that time, the circle ends below the top speed.
    let rate = (0.5 * limits.ax).min(1.0);
    let top = hi.min(lo + rate * 30.0);
    if top - lo < MIN_SPEED_CHANGE || ay <= 0.0 {
        return None;
    }
    let radius = top * top / ay;
    let t = (top - lo) / rate;
    let n = (t / 0.5).ceil() as usize;
    let mut p = vec![(0.0, 0.0, lo), (LEAD, 0.0, lo)];
    // Into the circle in 2 s (slower where the driver's rate asks it),
    // then along it at rising speed.
    let d0 = steer_for(model, lo, lo * lo / radius)?;
    let entry = (d0.abs() / limits.steer_rate).max(2.0);
    p.push((LEAD + entry, d0, lo));
    for k in 1..=n {
        let tau = t * k as f64 / n as f64;
        let u = lo + (top - lo) * tau / t;
        p.push((LEAD + entry + tau, steer_for(model, u, u * u / radius)?, u));
    }
    Some(Designed {
        name: format!("constant_radius_{:.0}m", radius),
        kind: Kind::ConstantRadius,
        description: format!(
            "a steer schedule at rising speed, {:.0} to {:.0} km/h in {t:.0} s: the steer the base model needs on a {radius:.0} m circle ({:.1} to {ay:.1} m/s² on it); drive the steer schedule, not the circle (the scenario replays the steer open loop: a car unlike the base model leaves the circle, and the separation was predicted for the steer)",
            kmh(lo),
            kmh(top),
            lo * lo / radius
        ),
        manoeuvre: schedule(p),
    })
}

/// The largest steer rate (rad/s) and |du/dt| (m/s²) of schedule `m`
/// between its breakpoints (linear between them, so these are its peaks).
pub fn peak_rates(m: &Manoeuvre) -> (f64, f64) {
    let Manoeuvre::Replay(r) = m else {
        return (0.0, 0.0);
    };
    let mut peak = (0.0f64, 0.0f64);
    for i in 1..r.t.len() {
        let dt = r.t[i] - r.t[i - 1];
        if dt > 0.0 {
            peak.0 = peak.0.max(((r.steer[i] - r.steer[i - 1]) / dt).abs());
            peak.1 = peak.1.max(((r.speed[i] - r.speed[i - 1]) / dt).abs());
        }
    }
    peak
}
