//! The augmented model: the base 2-DOF model with load transfer
//! ([`crate::vehicle`]) plus every candidate effect of [`super::effects`],
//! and its replay of a run.
//!
//! States: sideslip β, yaw rate r (as the base model), the lagged front and
//! rear slip angles (relaxation length σ: `α̇ = (u/σ)·(α_kin − α)`, the
//! first-order tyre lag of Pacejka, *Tyre and Vehicle Dynamics*, §7.1), and
//! body roll φ with its rate (the second-order roll response of
//! [`super::effects::RollModel`]). With every effect off the lag and roll
//! states do not feed back and the model is the base model (tested against
//! [`crate::sim::Integrator`] to 1e-9).
//!
//! Effects and their equations (ISO 8855, positive steer and positive roll in
//! a left turn; φ > 0 puts the right side down):
//! - roll steer: front steer `δ + ε_f·φ`, rear steer `ε_r·φ`;
//! - steering compliance: the front wheels lose `c·Fyf` of steer (solved
//!   with the front force, or through the lag state when σ > 0);
//! - roll camber: each wheel gains `κ·φ·Fz` of camber thrust, outside the
//!   tyre's slip curve (camber thrust does not saturate with slip the way
//!   slip force does — what separates it from roll steer);
//! - cornering stiffness: the tyre sees `s·α` (stiffness × s, peak kept);
//! - friction, load-transfer share, aero load, bank, yaw inertia: values of
//!   the base model changed (see [`crate::vehicle::Effects`]);
//! - sensor effects: [`super::sensors::Sensors`] applied to the response.
//!
//! Integration: fixed-step RK4 on a grid where the run's inputs are sampled
//! once ([`Drive`]), so repeated replays (the fits) only evaluate the model.
//! Units: SI, rad.

use super::effects::{EffectSet, RollModel};
use crate::manoeuvre::{interpolate, Manoeuvre, Replay};
use crate::sim::TimeHistory;
use crate::tyre::{SlipState, Tyre, TyreModel};
use crate::vehicle::{Kinematics, LoadTransferSeed, VehicleModel, MIN_SPEED};

/// Relaxation lengths below this (m) are no lag: 1 mm is 50 µs at 20 m/s,
/// far below what a logged run resolves, and a shorter lag would make the
/// lag states stiff for the explicit integration (a fit that drives σ toward
/// zero would otherwise chase it through ever stiffer models).
pub const MIN_RELAXATION_LENGTH: f64 = 1e-3;

/// The state vector: β, r, front and rear lagged slip angle, roll, roll rate.
pub type AugmentedState = [f64; 6];

/// A run's inputs sampled at every integration stage: index `2i` is grid
/// time `t0 + i·h`, index `2i + 1` is `t0 + (i + ½)·h`.
#[derive(Debug, Clone, PartialEq)]
pub struct Drive {
    /// Integration step, s.
    pub step: f64,
    /// First time, s.
    pub start: f64,
    /// Number of steps.
    pub steps: usize,
    steer: Vec<f64>,
    speed: Vec<f64>,
    speed_rate: Vec<f64>,
}

impl Drive {
    /// Samples `m` over its duration with step `step`.
    pub fn new(m: &Manoeuvre, step: f64) -> Self {
        let start = m.start_time();
        let steps = ((m.end_time() - start) / step).round().max(1.0) as usize;
        let times: Vec<f64> = (0..=2 * steps)
            .map(|j| start + 0.5 * step * j as f64)
            .collect();
        Self {
            step,
            start,
            steps,
            steer: times.iter().map(|&t| m.steer(t)).collect(),
            speed: times.iter().map(|&t| m.speed(t)).collect(),
            speed_rate: times.iter().map(|&t| m.speed_rate(t)).collect(),
        }
    }

    /// The replay of measured steer and speed.
    pub fn replay(t: &[f64], steer: &[f64], speed: &[f64], step: f64) -> Self {
        Self::new(
            &Manoeuvre::Replay(Replay {
                t: t.to_vec(),
                steer: steer.to_vec(),
                speed: speed.to_vec(),
            }),
            step,
        )
    }

    /// Grid time of step `i`, s.
    pub fn time(&self, i: usize) -> f64 {
        self.start + self.step * i as f64
    }
}

/// The response of the augmented model to a drive, on the integration grid.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Response {
    /// t, steer, speed, β, r and ay (the tyres' force over the mass, the
    /// accelerometer's quantity).
    pub history: TimeHistory,
    /// Body roll φ, rad.
    pub roll: Vec<f64>,
}

/// The base model with effects.
#[derive(Debug, Clone, PartialEq)]
pub struct Augmented {
    /// The base model (vehicle, tyres, kinematics, load transfer).
    pub base: VehicleModel,
    /// Road friction scale of the campaign.
    pub friction: f64,
    /// The roll degree of freedom.
    pub roll: RollModel,
    /// The effects (default: none).
    pub effects: EffectSet,
}

/// The base model with the vehicle-side effects applied: what one replay
/// evaluates.
struct Applied<'a> {
    model: VehicleModel,
    e: &'a EffectSet,
    friction: f64,
    scale: [f64; 2],
    omega: f64,
    zeta: f64,
    roll_gradient: f64,
    bank_acceleration: f64,
}

impl Applied<'_> {
    fn axle(&self, tyre: &Tyre, alpha: f64, fz: [f64; 2], u: f64, camber_thrust: f64) -> f64 {
        let f = |load: f64| {
            tyre.lateral_force(&SlipState {
                alpha,
                kappa: 0.0,
                fz: load,
                camber: 0.0,
                mu_scale: self.friction,
                speed: u,
            })
        };
        f(fz[0]) + f(fz[1]) + camber_thrust * (fz[0] + fz[1])
    }

    /// Derivatives and the tyres' lateral acceleration; `seed` carries the
    /// load-transfer solutions of this RK stage in earlier steps.
    fn rhs(
        &self,
        x: &AugmentedState,
        steer: f64,
        speed: f64,
        speed_rate: f64,
        seed: &mut LoadTransferSeed,
    ) -> (AugmentedState, f64) {
        let m = &self.model;
        let v = &m.vehicle;
        let e = self.e;
        let u = speed.max(MIN_SPEED);
        let (beta, r, phi) = (x[0], x[1], x[4]);
        let (theta_f, theta_r) = match m.options.kinematics {
            Kinematics::Exact => {
                let vy = u * beta.tan();
                (((vy + v.a * r) / u).atan(), ((vy - v.b * r) / u).atan())
            }
            Kinematics::SmallAngle => (beta + v.a * r / u, beta - v.b * r / u),
        };
        let steer_front = steer + e.roll_steer[0] * phi;
        let steer_rear = e.roll_steer[1] * phi;
        let lagged = e.relaxation_length >= MIN_RELAXATION_LENGTH;
        let camber = [e.roll_camber[0] * phi, e.roll_camber[1] * phi];
        let [sf, sr] = self.scale;
        let projection = |d: f64| match m.options.kinematics {
            Kinematics::Exact => d.cos(),
            Kinematics::SmallAngle => 1.0,
        };
        // Front slip angle and force at given loads; with compliance and no
        // lag, αf = δf − c·Fyf(αf) − θf is solved by a secant (Fyf grows
        // with αf, so the root is unique).
        let front = |fz: [f64; 2]| -> (f64, f64) {
            let force = |a: f64| self.axle(&m.front, sf * a, fz, u, camber[0]);
            if lagged {
                return (x[2], force(x[2]));
            }
            let target = steer_front - theta_f;
            let c = e.steering_compliance;
            if c == 0.0 {
                return (target, force(target));
            }
            let g = |a: f64| {
                let f = force(a);
                (a - target + c * f, f)
            };
            let (mut a0, mut a1) = (target, target - c * force(target));
            let (mut g0, _) = g(a0);
            let (mut g1, mut f1) = g(a1);
            for _ in 0..30 {
                if g1.abs() < 1e-13 || g1 == g0 {
                    break;
                }
                let a2 = a1 - g1 * (a1 - a0) / (g1 - g0);
                let (g2, f2) = g(a2);
                (a0, g0, a1, g1, f1) = (a1, g1, a2, g2, f2);
            }
            (a1, f1)
        };
        let alpha_r = if lagged { x[3] } else { steer_rear - theta_r };
        let inv_m = 1.0 / v.mass;
        let eval = |ay: f64| {
            let fz = m.wheel_loads_at(ay, u);
            let (af, fyf) = front([fz[0], fz[1]]);
            let fyr = self.axle(&m.rear, sr * alpha_r, [fz[2], fz[3]], u, camber[1]);
            let cos = projection(af + theta_f);
            ((fyf * cos + fyr) * inv_m, fyf, fyr, cos)
        };
        // Secant on g(ay) = ay − Y(ay)/m, as the base model's loop.
        let (mut ay, mut out) = if m.options.load_transfer {
            let [s0, s1, s2] = seed.ay;
            let mut x1 = 3.0 * s0 - 3.0 * s1 + s2;
            let mut o1 = eval(x1);
            let mut g1 = x1 - o1.0;
            let mut slope = seed.slope;
            let mut n = 0;
            while g1.abs() > 1e-9 * (1.0 + x1.abs()) && n < 60 {
                let x2 = x1 - g1 / slope;
                let o2 = eval(x2);
                let g2 = x2 - o2.0;
                let s = (g2 - g1) / (x2 - x1);
                slope = if s.is_finite() && (0.1..10.0).contains(&s) {
                    s
                } else {
                    1.0
                };
                (x1, o1, g1) = (x2, o2, g2);
                n += 1;
            }
            seed.slope = slope;
            (o1.0, o1)
        } else {
            let o = eval(0.0);
            (o.0, o)
        };
        if !ay.is_finite() {
            ay = 0.0;
            out = (0.0, 0.0, 0.0, 1.0);
        }
        seed.ay = [ay, seed.ay[0], seed.ay[1]];
        let (_, fyf, fyr, cos) = out;
        let iz = v.yaw_inertia;
        let yaw_acceleration = (v.a * fyf * cos - v.b * fyr) / iz;
        let ay_path = ay - self.bank_acceleration;
        let beta_rate = match m.options.kinematics {
            Kinematics::Exact => {
                let vy = u * beta.tan();
                let vy_dot = ay_path - u * r;
                (u * vy_dot - vy * speed_rate) / (u * u + vy * vy)
            }
            Kinematics::SmallAngle => ay_path / u - r - speed_rate * beta / u,
        };
        let mut dx = [beta_rate, yaw_acceleration, 0.0, 0.0, x[5], 0.0];
        if lagged {
            let k = u / e.relaxation_length;
            dx[2] = k * (steer_front - e.steering_compliance * fyf - theta_f - x[2]);
            dx[3] = k * (steer_rear - theta_r - x[3]);
        }
        dx[5] = self.omega * self.omega * (self.roll_gradient * ay - phi)
            - 2.0 * self.zeta * self.omega * x[5];
        (dx, ay)
    }
}

impl Augmented {
    /// The base model alone.
    pub fn new(base: VehicleModel, friction: f64) -> Self {
        Self {
            base,
            friction,
            roll: RollModel::default(),
            effects: EffectSet::default(),
        }
    }

    fn applied(&self) -> Applied<'_> {
        let e = &self.effects;
        let mut model = self.base.clone();
        if let Some(chi) = e.load_transfer_front_share {
            model.vehicle.load_transfer_front_share = Some(chi);
        }
        if let Some(s) = e.yaw_inertia_scale {
            model.vehicle.yaw_inertia *= s;
        }
        model.options.effects.aero_load = [
            model.options.effects.aero_load[0] + e.aero_load[0],
            model.options.effects.aero_load[1] + e.aero_load[1],
        ];
        model.options.effects.road_bank += e.road_bank;
        let bank_acceleration = model.bank_acceleration();
        Applied {
            bank_acceleration,
            model,
            e,
            friction: self.friction * e.friction_scale.unwrap_or(1.0),
            scale: e.cornering_stiffness_scale.unwrap_or([1.0; 2]),
            omega: std::f64::consts::TAU * self.roll.frequency,
            zeta: self.roll.damping,
            roll_gradient: self.roll.gradient,
        }
    }

    /// The state that starts a replay at sideslip `beta` and yaw rate
    /// `yaw_rate`: lag states at their kinematic slip angles, roll at its
    /// steady value for ay = u·r.
    pub fn initial_state(&self, drive: &Drive, beta: f64, yaw_rate: f64) -> AugmentedState {
        let u = drive.speed[0].max(MIN_SPEED);
        let v = &self.base.vehicle;
        let phi = self.roll.gradient * u * yaw_rate;
        let af = drive.steer[0] + self.effects.roll_steer[0] * phi - (beta + v.a * yaw_rate / u);
        let ar = self.effects.roll_steer[1] * phi - (beta - v.b * yaw_rate / u);
        [beta, yaw_rate, af, ar, phi, 0.0]
    }

    /// Integrates the drive from `x0` (RK4 on the drive's grid).
    pub fn simulate(&self, drive: &Drive, x0: AugmentedState) -> Response {
        let p = self.applied();
        let n = drive.steps;
        let h = drive.step;
        let col = || Vec::with_capacity(n + 1);
        let mut out = Response {
            history: TimeHistory {
                t: col(),
                steer: col(),
                speed: col(),
                beta: col(),
                yaw_rate: col(),
                ay: col(),
                ..TimeHistory::default()
            },
            roll: col(),
        };
        let mut x = x0;
        let mut seeds = [LoadTransferSeed::default(); 4];
        let add = |x: &AugmentedState, k: &AugmentedState, s: f64| {
            let mut y = *x;
            for (yi, ki) in y.iter_mut().zip(k) {
                *yi += s * ki;
            }
            y
        };
        let at = |j: usize| (drive.steer[j], drive.speed[j], drive.speed_rate[j]);
        for i in 0..=n {
            let (d0, u0, du0) = at(2 * i);
            let (k1, ay) = p.rhs(&x, d0, u0, du0, &mut seeds[0]);
            let hist = &mut out.history;
            hist.t.push(drive.time(i));
            hist.steer.push(d0);
            hist.speed.push(u0);
            hist.beta.push(x[0]);
            hist.yaw_rate.push(x[1]);
            hist.ay.push(ay);
            out.roll.push(x[4]);
            if i == n {
                break;
            }
            let (d1, u1, du1) = at(2 * i + 1);
            let (d2, u2, du2) = at(2 * i + 2);
            let (k2, _) = p.rhs(&add(&x, &k1, 0.5 * h), d1, u1, du1, &mut seeds[1]);
            let (k3, _) = p.rhs(&add(&x, &k2, 0.5 * h), d1, u1, du1, &mut seeds[2]);
            let (k4, _) = p.rhs(&add(&x, &k3, h), d2, u2, du2, &mut seeds[3]);
            for j in 0..6 {
                x[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
            }
        }
        out
    }

    /// What the sensors record of a response, interpolated at `times`:
    /// (yaw rate, ay, β).
    pub fn observe(&self, response: &Response, times: &[f64]) -> Observed {
        let seen = self.effects.sensors.measure(&response.history);
        let at = |ys: &[f64]| -> Vec<f64> {
            times.iter().map(|&t| interpolate(&seen.t, ys, t)).collect()
        };
        Observed {
            yaw_rate: at(&seen.yaw_rate),
            ay: at(seen.ay.as_deref().unwrap_or(&[])),
            beta: at(seen.beta.as_deref().unwrap_or(&[])),
            roll: times
                .iter()
                .map(|&t| interpolate(&response.history.t, &response.roll, t))
                .collect(),
        }
    }
}

/// Simulated measurements at a run's sample times.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Observed {
    /// Yaw rate, rad/s.
    pub yaw_rate: Vec<f64>,
    /// Lateral acceleration as the accelerometer reads it, m/s².
    pub ay: Vec<f64>,
    /// Sideslip, rad.
    pub beta: Vec<f64>,
    /// Body roll (the model's state, without sensor effects), rad.
    pub roll: Vec<f64>,
}

#[cfg(test)]
mod tests;
