//! The 2-DOF lateral/yaw vehicle model (states sideslip β and yaw rate r)
//! with four wheels and lateral load transfer.
//!
//! Equations (Li, Jia & Zhao eq. 1–2, Wang & Liang eq. 1–4), ISO 8855 axes, positive
//! steer δ turns left:
//! `m·(v̇ + u·r) = Fyf·cos δ + Fyr`, `Iz·ṙ = a·Fyf·cos δ − b·Fyr`, `v = u·tan β`,
//! with `Fyf`, `Fyr` the axle forces (sum of the two wheels), both wheels of an
//! axle at the same slip angle (Wang & Liang). Slip angles use the crate's tyre
//! sign (positive α gives positive force):
//! exact `αf = δ − atan((v + a·r)/u)`, `αr = −atan((v − b·r)/u)`;
//! small-angle (Li, Jia & Zhao) `αf = δ − β − a·r/u`, `αr = −β + b·r/u`, with
//! `m·u·(β̇ + r) + m·u̇·β = Fyf + Fyr` (no cos δ).
//!
//! Wheel loads (Wang & Liang eq. 4): static axle loads `m·g·b/l` and `m·g·a/l`
//! split evenly, plus a lateral transfer `ΔFz = χ·m·ay·h/d_f` (front) and
//! `(1 − χ)·m·ay·h/d_r` (rear) from the inner (left, for ay > 0) to the outer
//! wheel, with χ = b/l by default (transfer in proportion to static axle
//! load). A wheel whose load would go negative is off the ground (load 0).
//!
//! The algebraic loop: the loads depend on ay and ay on the forces, which
//! depend on the loads. It is solved at every derivative evaluation (every RK
//! stage) by a secant iteration on `g(ay) = ay − Y(ay)/m` to
//! |g| ≤ 1e-9·(1 + |ay|) — not lagged by a step. The integrator seeds each
//! solve with a quadratic extrapolation of the same RK stage's solutions in
//! the three previous steps, so a solve usually costs one evaluation of the four
//! tyres. `g` is strictly increasing
//! for any tyre whose force does not grow faster with load than `m/(h/d)`
//! allows, so the root is unique.
//!
//! Units: SI, rad. Speeds below `MIN_SPEED` are held at it, because the slip
//! angles of a 2-DOF model are undefined at standstill.

mod params;
pub mod steady;

pub use params::Vehicle;

use crate::tyre::{SlipState, Tyre, TyreModel};
use serde::{Deserialize, Serialize};

/// Standard gravity, m/s².
pub const G: f64 = 9.80665;
/// Lowest forward speed the model evaluates, m/s.
pub const MIN_SPEED: f64 = 0.5;

/// How slip angles and force projections are computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum Kinematics {
    /// atan slip angles, cos δ projection, v = u·tan β (default).
    #[default]
    Exact,
    /// Seed 003's small-angle form.
    SmallAngle,
}

/// Model options; defaults are exact kinematics with load transfer.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelOptions {
    /// Slip-angle kinematics.
    #[serde(default)]
    pub kinematics: Kinematics,
    /// Lateral load transfer on (Wang & Liang) or off (axle tyres, Li, Jia & Zhao).
    #[serde(default = "yes")]
    pub load_transfer: bool,
    /// Effects beyond the papers' model, all off by default.
    #[serde(default)]
    pub effects: Effects,
}

/// Effects beyond the papers' model (candidates of the sim-to-real
/// diagnosis). Every one is off by default, and off it changes nothing: the
/// base model stays exactly Li, Jia & Zhao's / Wang & Liang's.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct Effects {
    /// Aerodynamic down-force per axle (front, rear), N per (m/s)²: each
    /// wheel of the axle carries half of `k·u²` on top of its static load.
    pub aero_load: [f64; 2],
    /// Road bank angle θ, rad, positive when the road's left edge is higher:
    /// gravity then pulls the car to the right with `m·g·sin θ`, the static
    /// loads scale by `cos θ`, and the accelerometer (`ay`, the tyres' force
    /// over the mass) reads `g·sin θ` more than the path's acceleration.
    pub road_bank: f64,
}

impl Effects {
    /// Checks the values for physical sense.
    pub fn validate(&self) -> Result<(), crate::error::ParamError> {
        use crate::error::ParamError;
        ParamError::non_negative("aero_load[0]", self.aero_load[0])?;
        ParamError::non_negative("aero_load[1]", self.aero_load[1])?;
        ParamError::in_range(
            "road_bank",
            self.road_bank.abs(),
            -1.0,
            0.5,
            "a bank steeper than 0.5 rad (29°) is not a road",
        )
    }
}

fn yes() -> bool {
    true
}

impl Default for ModelOptions {
    fn default() -> Self {
        Self {
            kinematics: Kinematics::Exact,
            load_transfer: true,
            effects: Effects::default(),
        }
    }
}

/// Inputs at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inputs {
    /// Front road-wheel steer angle δ, rad.
    pub steer: f64,
    /// Forward speed u of the centre of gravity, m/s.
    pub speed: f64,
    /// du/dt, m/s².
    pub speed_rate: f64,
    /// Road friction as a scale on the tyres' own friction.
    pub friction: f64,
}

/// The state (β, r).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct State {
    /// Sideslip angle at the centre of gravity, rad.
    pub beta: f64,
    /// Yaw rate, rad/s.
    pub yaw_rate: f64,
}

/// Relative tolerance of the load-transfer loop on g(ay). The loads then
/// belong to an ay within 1e-9·(1 + |ay|) of the returned one; since the axle
/// forces change with ay by about 5 % of m per m/s², the forces are
/// consistent to ~1e-10 relative: two orders below RK4's own truncation error
/// at a 1 ms step (≈ (h·λ)⁴ ≈ 1e-7 with λ ≈ 20 1/s).
const LOAD_TOLERANCE: f64 = 1e-9;

/// Where the load-transfer solve starts: the last three solutions (the solve
/// starts from their quadratic extrapolation) and the last slope of
/// g(ay) = ay − Y(ay)/m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadTransferSeed {
    /// Last three solutions, newest first, m/s².
    pub ay: [f64; 3],
    /// dg/day estimate.
    pub slope: f64,
}

impl Default for LoadTransferSeed {
    fn default() -> Self {
        Self {
            ay: [0.0; 3],
            slope: 1.0,
        }
    }
}

impl LoadTransferSeed {
    fn predict(&self) -> f64 {
        let [a, b, c] = self.ay;
        3.0 * a - 3.0 * b + c
    }
    fn push(&mut self, ay: f64) {
        self.ay = [ay, self.ay[0], self.ay[1]];
    }
}

/// Static wheel loads (N) and lateral load transfer per unit ay (N per m/s²).
#[derive(Debug, Clone, Copy)]
struct LoadSplit {
    front: f64,
    rear: f64,
    kf: f64,
    kr: f64,
    /// Track ratio t_f / t_r: a transfer moment that the front axle cannot
    /// carry, expressed as rear transfer.
    front_to_rear: f64,
}

impl LoadSplit {
    /// FL, FR, RL, RR at `ay`. The roll moment m·ay·h is shared between the
    /// axles by the transfer share; an axle whose inner wheel has lifted off
    /// carries no more than its whole load on the outer wheel, and the moment
    /// it cannot carry goes to the other axle (the body pivots on the outer
    /// wheels), so the four loads always add up to the axle loads (m·g·cos θ
    /// plus aero) until both inner wheels are off the ground (roll-over).
    #[inline]
    fn at(&self, ay: f64) -> [f64; 4] {
        let (mut df, mut dr) = (self.kf * ay, self.kr * ay);
        if df.abs() > self.front {
            dr += (df - self.front.copysign(df)) * self.front_to_rear;
            df = self.front.copysign(df);
        }
        if dr.abs() > self.rear {
            df += (dr - self.rear.copysign(dr)) / self.front_to_rear;
            df = df.clamp(-self.front, self.front);
            dr = self.rear.copysign(dr);
        }
        [
            self.front - df,
            self.front + df,
            self.rear - dr,
            self.rear + dr,
        ]
    }
}

/// Everything the model computes at one instant besides the derivatives.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Outputs {
    /// dβ/dt, rad/s.
    pub beta_rate: f64,
    /// dr/dt, rad/s².
    pub yaw_acceleration: f64,
    /// Lateral acceleration of the centre of gravity (body y), m/s².
    pub ay: f64,
    /// Front and rear slip angles, rad.
    pub alpha_front: f64,
    /// Rear slip angle, rad.
    pub alpha_rear: f64,
    /// Front axle lateral force (both wheels, wheel frame), N.
    pub fy_front: f64,
    /// Rear axle lateral force, N.
    pub fy_rear: f64,
    /// Wheel loads front-left, front-right, rear-left, rear-right, N.
    pub fz: [f64; 4],
    /// Tyre-set evaluations the load-transfer loop took (0 without transfer).
    pub load_iterations: u32,
}

/// A vehicle with its tyres and options: the right-hand side of the ODE.
#[derive(Debug, Clone, PartialEq)]
pub struct VehicleModel {
    /// Mass and geometry.
    pub vehicle: Vehicle,
    /// Tyre of each front wheel.
    pub front: Tyre,
    /// Tyre of each rear wheel.
    pub rear: Tyre,
    /// Kinematics and load-transfer options.
    pub options: ModelOptions,
}

impl VehicleModel {
    /// A model with default options.
    pub fn new(vehicle: Vehicle, front: Tyre, rear: Tyre) -> Self {
        Self {
            vehicle,
            front,
            rear,
            options: ModelOptions::default(),
        }
    }

    /// Front and rear slip angles for a state and inputs.
    pub fn slip_angles(&self, x: &State, inp: &Inputs) -> (f64, f64) {
        let u = inp.speed.max(MIN_SPEED);
        let (a, b) = (self.vehicle.a, self.vehicle.b);
        match self.options.kinematics {
            Kinematics::Exact => {
                let v = u * x.beta.tan();
                (
                    inp.steer - ((v + a * x.yaw_rate) / u).atan(),
                    -((v - b * x.yaw_rate) / u).atan(),
                )
            }
            Kinematics::SmallAngle => (
                inp.steer - x.beta - a * x.yaw_rate / u,
                -x.beta + b * x.yaw_rate / u,
            ),
        }
    }

    fn wheel_force(tyre: &Tyre, alpha: f64, fz: f64, inp: &Inputs) -> f64 {
        tyre.lateral_force(&SlipState {
            alpha,
            kappa: 0.0,
            fz,
            camber: 0.0,
            mu_scale: inp.friction,
            speed: inp.speed,
        })
    }

    /// Static wheel loads and the load transferred per m/s² of lateral
    /// acceleration on each axle: computed once per derivative evaluation,
    /// not once per load-transfer iteration.
    fn load_split(&self, speed: f64) -> LoadSplit {
        let v = &self.vehicle;
        let e = &self.options.effects;
        let (mut sf, mut sr) = v.static_axle_loads();
        if e.road_bank != 0.0 {
            let c = e.road_bank.cos();
            sf *= c;
            sr *= c;
        }
        if e.aero_load != [0.0; 2] {
            sf += e.aero_load[0] * speed * speed;
            sr += e.aero_load[1] * speed * speed;
        }
        let (kf, kr) = if self.options.load_transfer {
            let chi = v.front_transfer_share();
            let k = v.mass * v.cg_height;
            (chi * k / v.track_front, (1.0 - chi) * k / v.track_rear)
        } else {
            (0.0, 0.0)
        };
        LoadSplit {
            front: 0.5 * sf,
            rear: 0.5 * sr,
            kf,
            kr,
            front_to_rear: v.track_front / v.track_rear,
        }
    }

    /// Wheel loads (FL, FR, RL, RR) at lateral acceleration `ay` (the
    /// tyres' force over the mass) and standstill.
    pub fn wheel_loads(&self, ay: f64) -> [f64; 4] {
        self.load_split(0.0).at(ay)
    }

    /// Wheel loads at lateral acceleration `ay` and speed `speed` (aero).
    pub fn wheel_loads_at(&self, ay: f64, speed: f64) -> [f64; 4] {
        self.load_split(speed).at(ay)
    }

    /// g·sin θ of the road bank, m/s².
    pub fn bank_acceleration(&self) -> f64 {
        let bank = self.options.effects.road_bank;
        // No sine in the hot loop of the base model.
        if bank == 0.0 {
            0.0
        } else {
            G * bank.sin()
        }
    }

    /// Axle forces (front, rear) at slip angles and wheel loads.
    fn axle_forces(&self, af: f64, ar: f64, fz: &[f64; 4], inp: &Inputs) -> (f64, f64) {
        (
            Self::wheel_force(&self.front, af, fz[0], inp)
                + Self::wheel_force(&self.front, af, fz[1], inp),
            Self::wheel_force(&self.rear, ar, fz[2], inp)
                + Self::wheel_force(&self.rear, ar, fz[3], inp),
        )
    }

    /// cos δ of the force projection (1 in the small-angle form).
    fn steer_projection(&self, steer: f64) -> f64 {
        match self.options.kinematics {
            Kinematics::Exact => steer.cos(),
            Kinematics::SmallAngle => 1.0,
        }
    }

    /// Solves the load-transfer loop from `seed`; returns (ay, fyf, fyr,
    /// loads, evaluations) and leaves the solution and slope in `seed`.
    fn solve_lateral(
        &self,
        af: f64,
        ar: f64,
        inp: &Inputs,
        cos_steer: f64,
        seed: &mut LoadTransferSeed,
        tolerance: f64,
    ) -> (f64, f64, f64, [f64; 4], u32) {
        let inv_m = 1.0 / self.vehicle.mass;
        let split = self.load_split(inp.speed.max(MIN_SPEED));
        let eval = |ay: f64| {
            let fz = split.at(ay);
            let (f, r) = self.axle_forces(af, ar, &fz, inp);
            ((f * cos_steer + r) * inv_m, f, r, fz)
        };
        if !self.options.load_transfer {
            let (y, f, r, fz) = eval(0.0);
            return (y, f, r, fz, 0);
        }
        // Quasi-Newton (secant) on g(ay) = ay − Y(ay)/m from the seed's
        // prediction, with the seed's slope as the first derivative estimate.
        // The integrator keeps one seed per RK stage, so the prediction is a
        // quadratic extrapolation in time and a solve usually ends after one
        // evaluation of the four tyres.
        let mut x1 = seed.predict();
        let (mut y1, mut f1, mut r1, mut fz1) = eval(x1);
        let mut g1 = x1 - y1;
        let mut slope = seed.slope;
        let mut evals = 1;
        while g1.abs() > tolerance * (1.0 + x1.abs()) && evals < 60 {
            let x2 = x1 - g1 / slope;
            let (y2, f2, r2, fz2) = eval(x2);
            let g2 = x2 - y2;
            let s = (g2 - g1) / (x2 - x1);
            // g' = 1 − Y'/m stays near 1; a wild secant (wheel lift-off kinks
            // Y) falls back to the fixed-point slope 1.
            slope = if s.is_finite() && (0.1..10.0).contains(&s) {
                s
            } else {
                1.0
            };
            (x1, y1, f1, r1, fz1, g1) = (x2, y2, f2, r2, fz2, g2);
            evals += 1;
        }
        seed.push(y1);
        seed.slope = slope;
        (y1, f1, r1, fz1, evals)
    }

    /// State derivatives and outputs, solving the load-transfer loop from
    /// scratch.
    pub fn evaluate(&self, x: &State, inp: &Inputs) -> Outputs {
        self.evaluate_seeded(x, inp, &mut LoadTransferSeed::default())
    }

    /// State derivatives and outputs, with the load-transfer solve started
    /// from (and updated into) `seed`: the integrator passes the previous
    /// stage's solution. The answer is the same to the loop's tolerance.
    pub fn evaluate_seeded(&self, x: &State, inp: &Inputs, seed: &mut LoadTransferSeed) -> Outputs {
        self.evaluate_to(x, inp, seed, LOAD_TOLERANCE)
    }

    /// As [`VehicleModel::evaluate_seeded`] with the load-transfer loop solved
    /// to relative `tolerance` on g(ay): equilibrium and stability analysis
    /// differentiate the right-hand side numerically and want it smooth to
    /// near rounding (1e-13), not to the simulation's 1e-9.
    pub fn evaluate_to(
        &self,
        x: &State,
        inp: &Inputs,
        seed: &mut LoadTransferSeed,
        tolerance: f64,
    ) -> Outputs {
        let (af, ar) = self.slip_angles(x, inp);
        let cos_steer = self.steer_projection(inp.steer);
        let (ay, fyf, fyr, fz, it) = self.solve_lateral(af, ar, inp, cos_steer, seed, tolerance);
        let v = &self.vehicle;
        let fyf_x = fyf * cos_steer;
        let yaw_acceleration = (v.a * fyf_x - v.b * fyr) / v.yaw_inertia;
        let u = inp.speed.max(MIN_SPEED);
        // The path's lateral acceleration is the tyres' (ay) less the bank's
        // pull g·sin θ (zero without a bank).
        let ay_path = ay - self.bank_acceleration();
        let beta_rate = match self.options.kinematics {
            Kinematics::Exact => {
                let vy = u * x.beta.tan();
                let vy_dot = ay_path - u * x.yaw_rate;
                (u * vy_dot - vy * inp.speed_rate) / (u * u + vy * vy)
            }
            Kinematics::SmallAngle => ay_path / u - x.yaw_rate - inp.speed_rate * x.beta / u,
        };
        Outputs {
            beta_rate,
            yaw_acceleration,
            ay,
            alpha_front: af,
            alpha_rear: ar,
            fy_front: fyf,
            fy_rear: fyr,
            fz,
            load_iterations: it,
        }
    }

    /// Lateral force of a wheel and its partials in slip angle and load:
    /// closed form for PAC89, forward differences otherwise.
    /// The load partial only when `load_varies` (without load transfer it
    /// multiplies zero).
    fn wheel_force_partials(
        tyre: &Tyre,
        alpha: f64,
        fz: f64,
        inp: &Inputs,
        load_varies: bool,
    ) -> (f64, f64, f64) {
        if let Tyre::Pac89(p) = tyre {
            return p.lateral_force_partials(alpha, fz, inp.friction);
        }
        let f = Self::wheel_force(tyre, alpha, fz, inp);
        let (ha, hz) = (1e-7, 1e-6 * fz.abs().max(1.0));
        let f_z = if load_varies {
            (Self::wheel_force(tyre, alpha, fz + hz, inp) - f) / hz
        } else {
            0.0
        };
        (
            f,
            (Self::wheel_force(tyre, alpha + ha, fz, inp) - f) / ha,
            f_z,
        )
    }

    /// (β̇, ṙ) and their Jacobian in (β, r) with the wheel loads taken at the
    /// lateral acceleration an equilibrium at `x` has, ay = u·r + g·sin θ,
    /// instead of solving the load-transfer loop (at constant speed: the
    /// equilibrium problem). It vanishes exactly at the model's equilibria
    /// (there the loop's solution is that ay) and costs one evaluation of
    /// the four tyres with their partials (closed form for PAC89), where a
    /// differenced Jacobian costs three.
    pub fn equilibrium_residual(&self, x: &State, inp: &Inputs) -> ([f64; 2], [[f64; 2]; 2]) {
        let v = &self.vehicle;
        let u = inp.speed.max(MIN_SPEED);
        let (a, b) = (v.a, v.b);
        let r = x.yaw_rate;
        let (af, ar) = self.slip_angles(x, inp);
        // Slip-angle partials [∂/∂β, ∂/∂r].
        let (daf, dar, sec2, vy) = match self.options.kinematics {
            Kinematics::Exact => {
                let tb = x.beta.tan();
                let vy = u * tb;
                let sec2 = 1.0 + tb * tb;
                let (pf, pr) = ((vy + a * r) / u, (vy - b * r) / u);
                let (wf, wr) = (1.0 / (1.0 + pf * pf), 1.0 / (1.0 + pr * pr));
                (
                    [-wf * sec2, -wf * a / u],
                    [-wr * sec2, wr * b / u],
                    sec2,
                    vy,
                )
            }
            Kinematics::SmallAngle => ([-1.0, -a / u], [-1.0, b / u], 1.0, 0.0),
        };
        let split = self.load_split(u);
        let ay_eq = u * r + self.bank_acceleration();
        let fz = split.at(ay_eq);
        // Loads are piecewise linear in ay (lift-off clamps): a central
        // difference is exact off the kinks.
        let eps = 1e-6 * (1.0 + ay_eq.abs());
        let (lp, lm) = (split.at(ay_eq + eps), split.at(ay_eq - eps));
        let dfz_dr: [f64; 4] = std::array::from_fn(|i| u * (lp[i] - lm[i]) / (2.0 * eps));
        let axle = |tyre: &Tyre, alpha: f64, d_alpha: [f64; 2], w: [usize; 2]| {
            let mut force = 0.0;
            let mut grad = [0.0; 2];
            for i in w {
                let (f, f_a, f_z) =
                    Self::wheel_force_partials(tyre, alpha, fz[i], inp, dfz_dr[i] != 0.0);
                force += f;
                grad[0] += f_a * d_alpha[0];
                grad[1] += f_a * d_alpha[1] + f_z * dfz_dr[i];
            }
            (force, grad)
        };
        let (fyf, dfyf) = axle(&self.front, af, daf, [0, 1]);
        let (fyr, dfyr) = axle(&self.rear, ar, dar, [2, 3]);
        let p = self.steer_projection(inp.steer);
        let ay = (p * fyf + fyr) / v.mass;
        let day = [
            (p * dfyf[0] + dfyr[0]) / v.mass,
            (p * dfyf[1] + dfyr[1]) / v.mass,
        ];
        let yaw = (a * p * fyf - b * fyr) / v.yaw_inertia;
        let dyaw = [
            (a * p * dfyf[0] - b * dfyr[0]) / v.yaw_inertia,
            (a * p * dfyf[1] - b * dfyr[1]) / v.yaw_inertia,
        ];
        let ay_path = ay - self.bank_acceleration();
        let (beta_rate, dbeta) = match self.options.kinematics {
            Kinematics::Exact => {
                let den = u * u + vy * vy;
                let num = u * (ay_path - u * r);
                (
                    num / den,
                    [
                        u * day[0] / den - num * 2.0 * vy * u * sec2 / (den * den),
                        u * (day[1] - u) / den,
                    ],
                )
            }
            Kinematics::SmallAngle => (ay_path / u - r, [day[0] / u, day[1] / u - 1.0]),
        };
        ([beta_rate, yaw], [dbeta, dyaw])
    }

    /// Understeer gradient K (rad per m/s² of lateral acceleration) of the
    /// linearised model at zero slip, from the axle cornering stiffnesses at
    /// static load: `K = (m/l)·(b/Cf − a/Cr)` (positive: understeer).
    pub fn understeer_gradient(&self) -> f64 {
        let v = &self.vehicle;
        let (cf, cr) = self.axle_cornering_stiffness();
        v.mass / v.wheelbase() * (v.b / cf - v.a / cr)
    }

    /// Axle cornering stiffness (front, rear) at static load, N/rad.
    pub fn axle_cornering_stiffness(&self) -> (f64, f64) {
        let (sf, sr) = self.vehicle.static_axle_loads();
        (
            2.0 * self.front.cornering_stiffness(0.5 * sf),
            2.0 * self.rear.cornering_stiffness(0.5 * sr),
        )
    }

    /// Textbook steady-state yaw-rate gain r/δ = u/(l + K·u²) of the linear
    /// bicycle model, 1/s.
    pub fn linear_yaw_rate_gain(&self, speed: f64) -> f64 {
        speed / (self.vehicle.wheelbase() + self.understeer_gradient() * speed * speed)
    }
}

/// The textbook bicycle model the unit tests check against closed forms:
/// Wang & Liang's sedan on linear tyres (55 and 60 kN/rad per wheel),
/// small-angle kinematics, no load transfer.
#[cfg(test)]
pub(crate) fn linear_bicycle() -> VehicleModel {
    use crate::tyre::Linear;
    let mut m = VehicleModel::new(
        Vehicle::seed004_sedan(),
        Tyre::Linear(Linear::new(55_000.0)),
        Tyre::Linear(Linear::new(60_000.0)),
    );
    m.options = ModelOptions {
        kinematics: Kinematics::SmallAngle,
        load_transfer: false,
        ..ModelOptions::default()
    };
    m
}

#[cfg(test)]
mod tests;
