//! The closed-loop driver of the winding-track analogues: a path follower
//! with preview who steers the truth car around a [`Track`] while the
//! truth's response is integrated, so the steer is what a driver does to
//! keep the car on its line (corrections included), not a script.
//!
//! **The driver** ([`Driver`]) is a pure-pursuit follower with preview
//! (Coulter, *Implementation of the Pure Pursuit Path Tracking Algorithm*,
//! 1992): from the rear axle it aims at the point of the centre line a
//! preview distance ahead (`max(minimum, preview time · u)`), which asks
//! for the path curvature `κ = 2·sin η / l` (η the angle to that point from
//! the car's heading, l its distance). Knowing the car, the driver asks the
//! road wheels for `atan(L·κ) + K·u²·κ` (L the wheelbase, K the car's
//! understeer gradient) and turns the steering wheel to the angle that gives
//! it through the car's steering ([`Steering`]). A human's reaction delay
//! (0.1–0.3 s; McRuer & Krendel, *Mathematical Models of Human Pilot
//! Behavior*, 1974) delays that command, the neuromuscular system follows
//! it through a first-order lag (about 0.1 s, same source), no faster than
//! a steering-rate limit, and a remnant (the part of a human's steer no
//! model of the task explains; a sum of five sines at 0.07–1.3 Hz with
//! fixed phases, so every noise seed drives the same runs) adds small
//! corrections.
//!
//! **The car** is the truth's augmented model with its effects
//! ([`Augmented::model`], whose effects its right-hand side applies), integrated by classical RK4 at a fixed step
//! together with its position and heading on the ground (`Ẋ = u·cos ψ −
//! v·sin ψ`, `Ẏ = u·sin ψ + v·cos ψ`, `ψ̇ = r`, `v = u·tan β`); the road
//! wheels' steer is held over each step, the speed (prescribed in time)
//! interpolated at the stages. The truth's steer path (an actuator's delay
//! and lag) acts between the steering and the road wheels. Parked (speed
//! 0) the car stands: its states are zero, the driver's hands hold.
//!
//! Units: SI, rad; ISO 8855 (steer, yaw rate and curvature positive left).

use super::winding::Track;
use crate::diagnose::model::Augmented;
use crate::sim::TimeHistory;
use crate::vehicle::{Inputs, LoadTransferSeed, Outputs, StateVector, LOAD_TOLERANCE};

/// The steering between the driver's hands and the road wheels: a
/// variable ratio, `δ = (θ/i)·(1 + p·(θ/θ_ref)²)` (θ the steering-wheel
/// angle, i the on-centre ratio, p the progression), and the fixed ratio
/// `θ/i` a logger converts the steering-wheel angle with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Steering {
    /// On-centre ratio i (steering-wheel angle per road-wheel angle).
    pub ratio: f64,
    /// Progression p (0: a constant ratio).
    pub progression: f64,
    /// Steering-wheel angle θ_ref at which the road wheels gain p, rad.
    pub reference: f64,
}

impl Steering {
    /// A constant ratio of 1: the steer is the road-wheel angle (a steer
    /// actuator's command, as an autonomous car logs it).
    pub(super) const DIRECT: Steering = Steering {
        ratio: 1.0,
        progression: 0.0,
        reference: 1.0,
    };

    /// The road-wheel angle of steering-wheel angle `hand`, rad.
    pub(super) fn wheel(&self, hand: f64) -> f64 {
        hand / self.ratio * (1.0 + self.progression * (hand / self.reference).powi(2))
    }

    /// The steering-wheel angle that gives road-wheel angle `wheel`, rad
    /// (Newton's method on the monotonic law, from the on-centre guess).
    pub(super) fn hand(&self, wheel: f64) -> f64 {
        let mut x = wheel * self.ratio;
        for _ in 0..30 {
            let r = self.wheel(x) - wheel;
            let slope = (1.0 + 3.0 * self.progression * (x / self.reference).powi(2)) / self.ratio;
            x -= r / slope;
            if r.abs() < 1e-14 {
                break;
            }
        }
        x
    }

    /// The steer a logger records of steering-wheel angle `hand`: the
    /// angle over the on-centre ratio, rad.
    pub(super) fn logged(&self, hand: f64) -> f64 {
        hand / self.ratio
    }
}

/// The driver (values in the programme that uses it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Driver {
    /// Preview time: the aim point lies this far ahead at the speed, s.
    pub preview_time: f64,
    /// Shortest preview distance, m.
    pub min_preview: f64,
    /// Reaction delay, s.
    pub reaction: f64,
    /// Neuromuscular lag time constant, s.
    pub neuromuscular: f64,
    /// Largest steering-wheel rate, rad/s.
    pub rate_limit: f64,
    /// RMS of the remnant at the steering wheel, rad.
    pub remnant: f64,
}

/// The remnant at `t`, of RMS 1: five sines (frequency Hz, relative
/// amplitude, phase rad) with more power at the low frequencies, as a
/// human's remnant has.
fn remnant(t: f64) -> f64 {
    const SINES: [(f64, f64, f64); 5] = [
        (0.07, 1.0, 0.3),
        (0.19, 0.8, 2.1),
        (0.37, 0.6, 4.0),
        (0.71, 0.4, 1.2),
        (1.3, 0.25, 5.3),
    ];
    let power: f64 = SINES.iter().map(|s| 0.5 * s.1 * s.1).sum();
    SINES
        .iter()
        .map(|&(f, a, p)| a * (std::f64::consts::TAU * f * t + p).sin())
        .sum::<f64>()
        / power.sqrt()
}

/// A closed-loop run: the truth's response on the integration grid, and
/// the steering-wheel angle the driver held.
#[derive(Debug, Clone)]
pub(super) struct ClosedLoop {
    /// The truth's history (steer: the road wheels'; roll recorded).
    pub history: TimeHistory,
    /// Steering-wheel angle at the history's times, rad.
    pub hand: Vec<f64>,
    /// Largest distance of the rear axle from the centre line, m (the
    /// tests hold the driver to the track with it).
    #[cfg_attr(not(test), allow(dead_code))]
    pub largest_offset: f64,
}

/// The full state with the pose: the model's six, then X, Y, ψ.
type Full = [f64; 9];

/// The truth model's derivatives of the full state with the pose, and its
/// outputs.
fn rates(
    model: &crate::vehicle::VehicleModel,
    x: &Full,
    inp: &Inputs,
    seed: &mut LoadTransferSeed,
) -> (Full, Outputs) {
    let state: StateVector = std::array::from_fn(|i| x[i]);
    let (dx, o) = model.rates(&state, inp, seed, LOAD_TOLERANCE);
    let (u, psi) = (inp.speed, x[8]);
    let v = u * x[0].tan();
    let mut d = [0.0; 9];
    d[..6].copy_from_slice(&dx);
    d[6] = u * psi.cos() - v * psi.sin();
    d[7] = u * psi.sin() + v * psi.cos();
    d[8] = x[1];
    (d, o)
}

/// Drives `truth` around `track` with `driver` through `steering` at the
/// prescribed speed (`speed` and its derivative `ax`, sampled every `h` s
/// from t = 0), integrating by RK4 at `h`.
pub(super) fn drive(
    truth: &Augmented,
    track: &Track,
    driver: &Driver,
    steering: &Steering,
    speed: &[f64],
    ax: &[f64],
    h: f64,
) -> ClosedLoop {
    let (model, friction) = (&truth.model, truth.friction);
    let path = truth.effects().steer_path;
    let car = Pursued {
        understeer: model.understeer_gradient(),
        wheelbase: model.vehicle.wheelbase(),
        b: model.vehicle.b,
    };
    let n = speed.len();
    let mut history = TimeHistory::default();
    let mut hand_log = Vec::with_capacity(n);
    let mut hands = Hands::new(driver, h);
    let mut wheels = SteerLine::new(path.delay, h);
    let mut x: Full = [0.0; 9];
    let mut seeds = [LoadTransferSeed::default(); 4];
    let (mut nearest, mut largest_offset) = (0usize, 0.0f64);
    for k in 0..n {
        let t = k as f64 * h;
        let u = speed[k];
        let parked = u == 0.0 && speed.get(k + 1).is_none_or(|&v| v == 0.0);
        // The driver: aim from the rear axle at the preview point.
        let rear = (x[6] - car.b * x[8].cos(), x[7] - car.b * x[8].sin());
        nearest = track.nearest(nearest, rear.0, rear.1);
        let offset = (track.x[nearest] - rear.0).hypot(track.y[nearest] - rear.1);
        largest_offset = largest_offset.max(offset);
        if !parked {
            let wanted = car.wanted_steer(track, driver, &x, rear, nearest, u);
            hands.follow(steering.hand(wanted) + driver.remnant * remnant(t));
        }
        // The road wheels through the truth's steer path (delay, lag).
        let steer = wheels.advance(steering.wheel(hands.hand), path.lag);
        let inputs = |s: f64| {
            let j = ((s / h).floor() as usize).min(n - 1);
            let w = (s / h - j as f64).clamp(0.0, 1.0);
            let at = |v: &[f64]| v[j] + w * (v[(j + 1).min(n - 1)] - v[j]);
            Inputs {
                steer,
                speed: at(speed),
                speed_rate: at(ax),
                friction,
                ax: at(ax),
                bank: 0.0,
            }
        };
        if parked {
            x[..6].fill(0.0);
            record(&mut history, t, &x, &inputs(t), &Outputs::default());
        } else {
            let (k1, o) = rates(model, &x, &inputs(t), &mut seeds[0]);
            record(&mut history, t, &x, &inputs(t), &o);
            x = rk4_rest(model, &x, &k1, &inputs, t, h, &mut seeds);
        }
        hand_log.push(hands.hand);
    }
    ClosedLoop {
        history,
        hand: hand_log,
        largest_offset,
    }
}

/// What the driver knows of the car: its understeer gradient, wheelbase
/// and the rear axle's distance behind the centre of gravity.
struct Pursued {
    understeer: f64,
    wheelbase: f64,
    b: f64,
}

impl Pursued {
    /// The road-wheel steer the driver asks for at speed `u` (pure pursuit,
    /// Coulter 1992): the path curvature `κ = 2·sin η / l` to the preview
    /// point ahead of `nearest`, seen from the rear axle `rear` of state
    /// `x`, as `atan(L·κ) + K·u²·κ`.
    fn wanted_steer(
        &self,
        track: &Track,
        driver: &Driver,
        x: &Full,
        rear: (f64, f64),
        nearest: usize,
        u: f64,
    ) -> f64 {
        let (rx, ry) = rear;
        let aim = track.ahead(nearest, driver.min_preview.max(driver.preview_time * u));
        let (gx, gy) = (track.x[aim] - rx, track.y[aim] - ry);
        let (c, s) = (x[8].cos(), x[8].sin());
        let (ahead, left) = (c * gx + s * gy, -s * gx + c * gy);
        let l = ahead.hypot(left).max(1e-3);
        let kappa = 2.0 * left.atan2(ahead).sin() / l;
        (self.wheelbase * kappa).atan() + self.understeer * u * u * kappa
    }
}

/// The driver's hands: the commands in the reaction delay line, and the
/// steering-wheel angle the neuromuscular lag follows them with, no faster
/// than the rate limit.
struct Hands {
    commands: std::collections::VecDeque<f64>,
    hand: f64,
    neuromuscular: f64,
    rate_limit: f64,
    h: f64,
}

impl Hands {
    fn new(driver: &Driver, h: f64) -> Self {
        let reaction = (driver.reaction / h).round() as usize;
        Hands {
            commands: std::collections::VecDeque::from(vec![0.0; reaction + 1]),
            hand: 0.0,
            neuromuscular: driver.neuromuscular,
            rate_limit: driver.rate_limit,
            h,
        }
    }

    /// One step: `command` enters the delay line, the hand moves toward
    /// the one leaving it.
    fn follow(&mut self, command: f64) {
        self.commands.push_back(command);
        self.commands.pop_front();
        let rate = ((self.commands[0] - self.hand) / self.neuromuscular)
            .clamp(-self.rate_limit, self.rate_limit);
        self.hand += self.h * rate;
    }
}

/// The truth's steer path between the steering and the road wheels: a
/// delay line of `delay` s and a first-order lag.
struct SteerLine {
    wheels: std::collections::VecDeque<f64>,
    lagged: f64,
    h: f64,
}

impl SteerLine {
    fn new(delay: f64, h: f64) -> Self {
        let late = (delay / h).round() as usize;
        SteerLine {
            wheels: std::collections::VecDeque::from(vec![0.0; late + 1]),
            lagged: 0.0,
            h,
        }
    }

    /// One step with the steering asking for `wheel`: the road wheels'
    /// steer after the delay and the lag of time constant `lag` s (none at
    /// 0).
    fn advance(&mut self, wheel: f64, lag: f64) -> f64 {
        self.wheels.push_back(wheel);
        self.wheels.pop_front();
        if lag > 0.0 {
            self.lagged += (self.wheels[0] - self.lagged) * (1.0 - (-self.h / lag).exp());
        } else {
            self.lagged = self.wheels[0];
        }
        self.lagged
    }
}

/// The classical RK4 step from `x` at `t` over `h`, its first stage `k1`
/// given (its outputs are the step's record): stages 2–4 with the inputs
/// at `t + h/2` and `t + h`, each stage its own load-transfer seed.
fn rk4_rest(
    model: &crate::vehicle::VehicleModel,
    x: &Full,
    k1: &Full,
    inputs: &impl Fn(f64) -> Inputs,
    t: f64,
    h: f64,
    seeds: &mut [LoadTransferSeed; 4],
) -> Full {
    let shift = |d: &Full, f: f64| -> Full { std::array::from_fn(|i| x[i] + f * d[i]) };
    let (k2, _) = rates(
        model,
        &shift(k1, 0.5 * h),
        &inputs(t + 0.5 * h),
        &mut seeds[1],
    );
    let (k3, _) = rates(
        model,
        &shift(&k2, 0.5 * h),
        &inputs(t + 0.5 * h),
        &mut seeds[2],
    );
    let (k4, _) = rates(model, &shift(&k3, h), &inputs(t + h), &mut seeds[3]);
    std::array::from_fn(|i| x[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
}

/// Appends the row of time `t` to `h`.
fn record(h: &mut TimeHistory, t: f64, x: &Full, inp: &Inputs, o: &Outputs) {
    h.t.push(t);
    h.steer.push(inp.steer);
    h.speed.push(inp.speed);
    h.beta.push(x[0]);
    h.yaw_rate.push(x[1]);
    h.ay.push(o.ay);
    h.alpha_front.push(o.alpha_front);
    h.alpha_rear.push(o.alpha_rear);
    h.fy_front.push(o.fy_front);
    h.fy_rear.push(o.fy_rear);
    for (c, f) in h.fz.iter_mut().zip(o.fz) {
        c.push(f);
    }
    h.roll.push(x[4]);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_steering_law_inverts_and_is_progressive() {
        let s = Steering {
            ratio: 16.0,
            progression: 0.15,
            reference: std::f64::consts::PI,
        };
        for hand in [-4.0, -1.0, 0.0, 0.3, 2.0, 6.0] {
            assert!((s.hand(s.wheel(hand)) - hand).abs() < 1e-12, "{hand}");
        }
        // On centre the ratio is 16; at 180° of wheel the road wheels get
        // 15 % more than the fixed ratio says.
        assert!((s.wheel(1e-4) * 16.0 / 1e-4 - 1.0).abs() < 1e-6);
        let pi = std::f64::consts::PI;
        assert!((s.wheel(pi) / s.logged(pi) - 1.15).abs() < 1e-12);
        assert_eq!(Steering::DIRECT.wheel(0.2), 0.2);
    }

    #[test]
    fn the_remnant_has_unit_rms() {
        let n = 200_000;
        let ms: f64 = (0..n)
            .map(|i| remnant(i as f64 * 0.01).powi(2))
            .sum::<f64>()
            / n as f64;
        assert!((ms.sqrt() - 1.0).abs() < 0.05, "{}", ms.sqrt());
    }
}
