//! An independent truth for the virtual proving ground: a four-wheel vehicle
//! with a roll degree of freedom and Magic-Formula-style tyres, written from
//! the textbook and sharing no code with the diagnosed model
//! ([`crate::diagnose::model`], [`crate::vehicle`]). Tuning the diagnosis against its
//! own augmented model can hide model-form errors; this truth differs from
//! it in structure (four wheels, per-wheel loads and slip, an elastic and
//! geometric load-transfer split, its own tyre).
//!
//! The model (body axes, ISO 8855: x forward, y left, z up; positive steer
//! left; positive roll φ puts the right side down, as in a left turn):
//! - states: lateral velocity v_y, yaw rate r, roll φ and roll rate p, and
//!   the lagged slip angle of each wheel (FL, FR, RL, RR) when the
//!   relaxation length σ > 0; the forward speed u is prescribed by the
//!   manoeuvre (a driver holding speed);
//! - wheels at (a, ±t_f/2) and (−b, ±t_r/2); each wheel's slip angle from
//!   its own velocity, exactly: `α_i = δ_i − atan2(v_y + r·x_i, u − r·y_i)`;
//!   steer on the front wheels (parallel), plus roll steer `ε·φ` per axle
//!   and minus the steering compliance `c·F_y,front axle`;
//! - planar equations: `m·(v̇_y + u·r) = Σ F_y,i·cos δ_i`,
//!   `I_z·ṙ = Σ (x_i·F_y,i·cos δ_i + y_i·F_y,i·sin δ_i)`;
//! - roll about the roll axis (height under the centre of gravity
//!   h' = h − (b·h_f + a·h_r)/L), the quasi-static form of Gillespie,
//!   *Fundamentals of Vehicle Dynamics* (1992), ch. 8, with the lateral
//!   inertia coupling m·h'·φ̈ left out:
//!   `I_x·φ̈ = m·a_y·h' − (K_f + K_r)·φ − (C_f + C_r)·p`, where K are net roll
//!   stiffnesses (springs and anti-roll bars, less the gravity term m·g·h'),
//!   so the steady roll is `φ = m·a_y·h'/(K_f + K_r)`;
//! - wheel loads: static axle load (plus aero down-force) shared between
//!   the two wheels, and the lateral transfer per axle
//!   `ΔF_z = (K·φ + C·p)/t + F_y,axle·h_rc/t` (elastic through the roll
//!   stiffness and damping split, geometric through the roll-centre
//!   height), outer wheel up; a wheel that would go negative lifts (load
//!   0) and its axle partner carries the axle's load, so the loads always
//!   sum to m·g (plus the down-force);
//! - tyres: a Magic Formula (Pacejka, *Tyre and Vehicle Dynamics*, §4.3)
//!   `F_y = D·sin(C·atan(Bα − E·(Bα − atan Bα)))` with load-dependent peak
//!   `D = μ(F_z)·F_z`, `μ = μ₀·(1 − k_μ·(F_z − F_z0)/F_z0)`, and cornering
//!   stiffness `C_α = c₁·F_z0·sin(2·atan(F_z/(c₂·F_z0)))` (the PAC89 load
//!   form), `B = C_α/(C·D)`; camber thrust `C_γ·F_z·γ` added (γ: wheel
//!   lean toward +y relative to the road);
//! - effects of its own: tyre relaxation length (`α̇_i = (v_x,i/σ)·(α_kin −
//!   α_i)`), roll steer, roll camber (wheels lean with the body by a gain),
//!   steering compliance, aero down-force, road friction, cornering
//!   stiffness and yaw inertia differing from the tyre data and vehicle
//!   file, and the sensors: delay, offsets, a body-fixed accelerometer that
//!   rolls with the body (reads `a_y·cos φ + g·sin φ`).
//!
//! Integration: fixed-step RK4 (1 ms); the loads, forces and compliant
//! steer of one evaluation are solved by a relaxed fixed-point iteration.
//! Units: SI, rad.

use crate::manoeuvre::{interpolate, Manoeuvre};
use crate::sim::ode::{self, OdeSystem};
use serde::Serialize;

/// Standard gravity, m/s² (this module's own constant: it shares nothing
/// with the diagnosed model).
const GRAVITY: f64 = 9.80665;
/// Lowest wheel forward speed used in the slip and lag equations, m/s.
const MIN_WHEEL_SPEED: f64 = 0.5;

/// A Magic-Formula lateral tyre with load sensitivity.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MfTyre {
    /// Nominal load F_z0, N.
    pub nominal_load: f64,
    /// Cornering-stiffness coefficient c₁ (C_α = c₁·F_z0 at its maximum), 1/rad.
    pub stiffness_coefficient: f64,
    /// Load at which the cornering stiffness peaks, over F_z0 (c₂).
    pub stiffness_load: f64,
    /// Friction coefficient μ₀ at F_z0.
    pub friction: f64,
    /// Friction loss per relative load k_μ.
    pub friction_load_sensitivity: f64,
    /// Shape factor C.
    pub shape: f64,
    /// Curvature factor E.
    pub curvature: f64,
    /// Camber thrust per load per rad of lean C_γ, 1/rad.
    pub camber_stiffness: f64,
}

impl Default for MfTyre {
    /// A 225/55R17-class passenger tyre: about 72 kN/rad and μ = 1 at 4 kN.
    fn default() -> Self {
        Self {
            nominal_load: 4000.0,
            stiffness_coefficient: 20.0,
            stiffness_load: 1.6,
            friction: 1.0,
            friction_load_sensitivity: 0.08,
            shape: 1.35,
            curvature: -0.3,
            camber_stiffness: 0.9,
        }
    }
}

impl MfTyre {
    /// Cornering stiffness at load `fz`, N/rad.
    pub fn cornering_stiffness(&self, fz: f64) -> f64 {
        let f0 = self.nominal_load;
        self.stiffness_coefficient * f0 * (2.0 * (fz / (self.stiffness_load * f0)).atan()).sin()
    }

    /// Peak lateral force at load `fz` on a road of friction `mu_scale`
    /// times the tyre's, N.
    pub fn peak(&self, fz: f64, mu_scale: f64) -> f64 {
        let f0 = self.nominal_load;
        mu_scale * self.friction * (1.0 - self.friction_load_sensitivity * (fz - f0) / f0) * fz
    }

    /// Lateral force at slip angle `alpha` (rad), load `fz` (N), lean
    /// `camber` (rad, toward +y), friction scale `mu_scale` and
    /// cornering-stiffness scale `stiffness_scale`, N.
    pub fn lateral_force(
        &self,
        alpha: f64,
        fz: f64,
        camber: f64,
        mu_scale: f64,
        stiffness_scale: f64,
    ) -> f64 {
        if fz <= 0.0 {
            return 0.0;
        }
        let d = self.peak(fz, mu_scale);
        let b = stiffness_scale * self.cornering_stiffness(fz) / (self.shape * d);
        let x = b * alpha;
        let e = self.curvature;
        d * (self.shape * (x - e * (x - x.atan())).atan()).sin()
            + self.camber_stiffness * fz * camber
    }
}

/// The four-wheel vehicle.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FourWheelVehicle {
    /// Mass, kg.
    pub mass: f64,
    /// Yaw moment of inertia, kg·m².
    pub yaw_inertia: f64,
    /// Roll moment of inertia about the roll axis, kg·m².
    pub roll_inertia: f64,
    /// Centre of gravity to front axle, m.
    pub a: f64,
    /// Centre of gravity to rear axle, m.
    pub b: f64,
    /// Front track, m.
    pub track_front: f64,
    /// Rear track, m.
    pub track_rear: f64,
    /// Centre-of-gravity height, m.
    pub cg_height: f64,
    /// Roll-centre heights (front, rear), m.
    pub roll_centre: [f64; 2],
    /// Net roll stiffness (front, rear), N·m/rad.
    pub roll_stiffness: [f64; 2],
    /// Roll damping (front, rear), N·m·s/rad.
    pub roll_damping: [f64; 2],
    /// The tyre of every wheel.
    pub tyre: MfTyre,
}

impl FourWheelVehicle {
    /// The proving ground's sedan: the mass and geometry of the campaign's
    /// vehicle file, a roll gradient of 6°/g (the campaign's file says
    /// otherwise), 62 % of the roll stiffness at the front, roll centres 80
    /// and 120 mm, roll frequency about 1.8 Hz, roll damping ratio 0.35.
    pub fn sedan() -> Self {
        let (mass, a, b, h) = (1530.0, 1.11, 1.67, 0.55);
        let roll_centre = [0.08, 0.12];
        let arm = h - (b * roll_centre[0] + a * roll_centre[1]) / (a + b);
        let total = mass * arm / (6f64.to_radians() / GRAVITY);
        let roll_inertia = 500.0;
        Self {
            mass,
            yaw_inertia: 2315.0,
            roll_inertia,
            a,
            b,
            track_front: 1.55,
            track_rear: 1.55,
            cg_height: h,
            roll_centre,
            roll_stiffness: [0.62 * total, 0.38 * total],
            roll_damping: [0.0; 2],
            tyre: MfTyre::default(),
        }
        .with_roll_damping_ratio(0.35)
    }

    /// The same car with roll damping ratio `zeta`
    /// (`ζ = (C_f + C_r)/(2·√((K_f + K_r)·I_x))`, the diagnosis's roll
    /// model's ζ for this truth's steady roll), split 55/45 front/rear.
    pub fn with_roll_damping_ratio(self, zeta: f64) -> Self {
        let total = self.roll_stiffness[0] + self.roll_stiffness[1];
        let damping = 2.0 * zeta * (total * self.roll_inertia).sqrt();
        Self {
            roll_damping: [0.55 * damping, 0.45 * damping],
            ..self
        }
    }

    /// Wheelbase, m.
    pub fn wheelbase(&self) -> f64 {
        self.a + self.b
    }

    /// Height of the roll axis's arm: centre of gravity above the roll axis, m.
    pub fn roll_arm(&self) -> f64 {
        self.cg_height
            - (self.b * self.roll_centre[0] + self.a * self.roll_centre[1]) / self.wheelbase()
    }

    /// Static axle loads (front, rear), N.
    pub fn static_axle_loads(&self) -> [f64; 2] {
        let w = self.mass * GRAVITY;
        let l = self.wheelbase();
        [w * self.b / l, w * self.a / l]
    }

    /// Steady roll gradient φ/a_y, rad per m/s².
    pub fn roll_gradient(&self) -> f64 {
        self.mass * self.roll_arm() / (self.roll_stiffness[0] + self.roll_stiffness[1])
    }
}

/// The truth's effects; [`FourWheelEffects::default`] is none.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FourWheelEffects {
    /// Tyre relaxation length σ, m (0: no lag).
    pub relaxation_length: f64,
    /// Roll steer (front, rear), rad of wheel steer per rad of roll.
    pub roll_steer: [f64; 2],
    /// Roll camber (front, rear): wheel lean relative to the road per rad
    /// of body roll, rad/rad (1: the wheel leans with the body).
    pub roll_camber: [f64; 2],
    /// Steer lost per front axle lateral force, rad/N.
    pub steering_compliance: f64,
    /// Aerodynamic down-force per axle, N per (m/s)².
    pub aero_load: [f64; 2],
    /// Road friction over the tyre data's.
    pub friction_scale: f64,
    /// Cornering stiffness on the car over the tyre data's (front, rear).
    pub stiffness_scale: [f64; 2],
    /// Yaw inertia over the vehicle's.
    pub yaw_inertia_scale: f64,
    /// Delay of every measured channel, s.
    pub sensor_delay: f64,
    /// Offsets of yaw rate (rad/s), a_y (m/s²) and sideslip (rad).
    pub sensor_bias: [f64; 3],
    /// The accelerometer is fixed to the body and rolls with it.
    pub accelerometer_rolls: bool,
}

impl Default for FourWheelEffects {
    fn default() -> Self {
        Self {
            relaxation_length: 0.0,
            roll_steer: [0.0; 2],
            roll_camber: [0.0; 2],
            steering_compliance: 0.0,
            aero_load: [0.0; 2],
            friction_scale: 1.0,
            stiffness_scale: [1.0; 2],
            yaw_inertia_scale: 1.0,
            sensor_delay: 0.0,
            sensor_bias: [0.0; 3],
            accelerometer_rolls: false,
        }
    }
}

/// The response on the integration grid.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct FourWheelResponse {
    /// Time, s.
    pub t: Vec<f64>,
    /// Road-wheel steer input, rad.
    pub steer: Vec<f64>,
    /// Forward speed, m/s.
    pub speed: Vec<f64>,
    /// Sideslip at the centre of gravity atan(v_y/u), rad.
    pub beta: Vec<f64>,
    /// Yaw rate, rad/s.
    pub yaw_rate: Vec<f64>,
    /// Lateral acceleration of the centre of gravity (the tyres' lateral
    /// force over the mass), m/s².
    pub ay: Vec<f64>,
    /// Body roll, rad.
    pub roll: Vec<f64>,
    /// Wheel loads (FL, FR, RL, RR), N.
    pub loads: Vec<[f64; 4]>,
}

/// What the sensors record, at chosen times.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FourWheelObserved {
    /// Yaw rate, rad/s.
    pub yaw_rate: Vec<f64>,
    /// Lateral acceleration as the accelerometer reads it, m/s².
    pub ay: Vec<f64>,
    /// Sideslip, rad.
    pub beta: Vec<f64>,
}

/// The truth: vehicle and effects.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FourWheel {
    /// Vehicle and tyre.
    pub vehicle: FourWheelVehicle,
    /// Effects.
    pub effects: FourWheelEffects,
}

/// State: v_y, r, φ, p, lagged slip angles FL, FR, RL, RR.
type State = [f64; 8];

/// The car driven by a manoeuvre, as an ODE for the crate's integrator;
/// keeps the last evaluation for the recorded row.
struct Driven<'a> {
    car: &'a FourWheel,
    manoeuvre: &'a Manoeuvre,
    last: Option<Evaluation>,
}

impl OdeSystem<8> for Driven<'_> {
    fn derivatives(&mut self, t: f64, x: &State) -> State {
        let m = self.manoeuvre;
        let e = self.car.evaluate(x, m.steer(t), m.speed(t));
        let d = e.derivative;
        self.last = Some(e);
        d
    }
}

/// One evaluation's derived quantities.
#[derive(Debug, Clone, Copy)]
struct Evaluation {
    derivative: State,
    ay: f64,
    loads: [f64; 4],
}

impl FourWheel {
    /// The truth without effects.
    #[cfg(test)]
    pub fn new(vehicle: FourWheelVehicle) -> Self {
        Self {
            vehicle,
            effects: FourWheelEffects::default(),
        }
    }

    fn positions(&self) -> [[f64; 2]; 4] {
        let v = &self.vehicle;
        let (tf, tr) = (0.5 * v.track_front, 0.5 * v.track_rear);
        [[v.a, tf], [v.a, -tf], [-v.b, tr], [-v.b, -tr]]
    }

    /// Wheel loads (FL, FR, RL, RR) for roll φ, roll rate p, axle lateral
    /// forces and speed u: static plus down-force, elastic and geometric
    /// transfer, wheel lift.
    fn loads(&self, phi: f64, p: f64, axle_force: [f64; 2], u: f64) -> [f64; 4] {
        let v = &self.vehicle;
        let e = &self.effects;
        let s = v.static_axle_loads();
        let tracks = [v.track_front, v.track_rear];
        let mut fz = [0.0; 4];
        for k in 0..2 {
            let axle = s[k] + e.aero_load[k] * u * u;
            let transfer = (v.roll_stiffness[k] * phi
                + v.roll_damping[k] * p
                + axle_force[k] * v.roll_centre[k])
                / tracks[k];
            // φ > 0 (left turn) loads the right wheel; a wheel whose share
            // would be negative lifts and the other carries the axle.
            let right = (0.5 * axle + transfer).clamp(0.0, axle);
            fz[2 * k] = axle - right;
            fz[2 * k + 1] = right;
        }
        fz
    }

    fn evaluate(&self, x: &State, steer: f64, u: f64) -> Evaluation {
        let e = &self.effects;
        let phi = x[2];
        let (wheel_speed, flow) = self.wheel_flow(x, u);
        let base_steer = [
            steer + e.roll_steer[0] * phi,
            steer + e.roll_steer[0] * phi,
            e.roll_steer[1] * phi,
            e.roll_steer[1] * phi,
        ];
        let (fy, delta, fz) = self.compliant_forces(x, &base_steer, &flow, u);
        let (derivative, ay) = self.rates_of(x, &fy, &delta, &wheel_speed, &flow, u);
        Evaluation {
            derivative,
            ay,
            loads: fz,
        }
    }

    /// Each wheel's forward speed (at least `MIN_WHEEL_SPEED`) and the
    /// angle of its flow, `atan2(vy_wheel, vx_wheel)`, at state `x` and
    /// speed `u`.
    fn wheel_flow(&self, x: &State, u: f64) -> ([f64; 4], [f64; 4]) {
        let (vy, r) = (x[0], x[1]);
        let pos = self.positions();
        let mut wheel_speed = [0.0; 4];
        let mut flow = [0.0; 4];
        for i in 0..4 {
            let vx = u - r * pos[i][1];
            let vyw = vy + r * pos[i][0];
            wheel_speed[i] = vx.max(MIN_WHEEL_SPEED);
            flow[i] = vyw.atan2(wheel_speed[i]);
        }
        (wheel_speed, flow)
    }

    /// The wheels' lateral forces, road-wheel steers and loads `(fy, δ,
    /// Fz)`, iterated with the steering compliance (the front axle's force
    /// steers its wheels back) and the load transfer the axle forces make.
    fn compliant_forces(
        &self,
        x: &State,
        base_steer: &[f64; 4],
        flow: &[f64; 4],
        u: f64,
    ) -> ([f64; 4], [f64; 4], [f64; 4]) {
        let v = &self.vehicle;
        let e = &self.effects;
        let tyre = &v.tyre;
        let (phi, p) = (x[2], x[3]);
        let lagged = e.relaxation_length > 0.0;
        let lean = [-e.roll_camber[0] * phi, -e.roll_camber[1] * phi];
        let mu = e.friction_scale;
        // Relaxation of the compliance loop: near-Newton in the linear range
        // (the front axle's slope is about 2·C_α at static load).
        let c = e.steering_compliance;
        let slope =
            2.0 * e.stiffness_scale[0] * tyre.cornering_stiffness(0.5 * v.static_axle_loads()[0]);
        let relax = 1.0 / (1.0 + c * slope);
        let mut axle_force = [0.0; 2];
        let mut front_force = 0.0;
        let mut fy = [0.0; 4];
        let mut delta = *base_steer;
        let mut fz = [0.0; 4];
        for _ in 0..60 {
            fz = self.loads(phi, p, axle_force, u);
            for i in 0..4 {
                delta[i] = if i < 2 {
                    base_steer[i] - c * front_force
                } else {
                    base_steer[i]
                };
                let alpha = if lagged { x[4 + i] } else { delta[i] - flow[i] };
                let k = i / 2;
                fy[i] = tyre.lateral_force(alpha, fz[i], lean[k], mu, e.stiffness_scale[k]);
            }
            let new_axle = [
                fy[0] * delta[0].cos() + fy[1] * delta[1].cos(),
                fy[2] * delta[2].cos() + fy[3] * delta[3].cos(),
            ];
            let new_front = front_force + relax * (new_axle[0] - front_force);
            let change = (new_axle[0] - axle_force[0]).abs()
                + (new_axle[1] - axle_force[1]).abs()
                + (new_front - front_force).abs();
            axle_force = new_axle;
            front_force = if c == 0.0 { new_axle[0] } else { new_front };
            if change < 1e-7 * (1.0 + new_axle[0].abs() + new_axle[1].abs()) {
                break;
            }
        }
        (fy, delta, fz)
    }

    /// The state's derivatives and the lateral acceleration from the
    /// wheels' forces `fy` at steers `delta`: side force and yaw moment,
    /// roll, and (with relaxation) the lagged slip angles.
    fn rates_of(
        &self,
        x: &State,
        fy: &[f64; 4],
        delta: &[f64; 4],
        wheel_speed: &[f64; 4],
        flow: &[f64; 4],
        u: f64,
    ) -> ([f64; 8], f64) {
        let v = &self.vehicle;
        let e = &self.effects;
        let (r, phi, p) = (x[1], x[2], x[3]);
        let pos = self.positions();
        let (mut side, mut yaw) = (0.0, 0.0);
        for i in 0..4 {
            let (s, co) = delta[i].sin_cos();
            side += fy[i] * co;
            yaw += pos[i][0] * fy[i] * co + pos[i][1] * fy[i] * s;
        }
        let ay = side / v.mass;
        let mut d = [0.0; 8];
        d[0] = ay - u * r;
        d[1] = yaw / (v.yaw_inertia * e.yaw_inertia_scale);
        d[2] = p;
        d[3] = (v.mass * ay * v.roll_arm()
            - (v.roll_stiffness[0] + v.roll_stiffness[1]) * phi
            - (v.roll_damping[0] + v.roll_damping[1]) * p)
            / v.roll_inertia;
        if e.relaxation_length > 0.0 {
            for i in 0..4 {
                let kinematic = delta[i] - flow[i];
                d[4 + i] = wheel_speed[i] / e.relaxation_length * (kinematic - x[4 + i]);
            }
        }
        (d, ay)
    }

    /// Integrates `m` from straight running (all states zero; the
    /// manoeuvre must start with zero steer) with RK4 of step `step`.
    pub fn simulate(&self, m: &Manoeuvre, step: f64) -> FourWheelResponse {
        let t0 = m.start_time();
        let n = ((m.end_time() - t0) / step).round().max(1.0) as usize;
        let col = || Vec::with_capacity(n + 1);
        let mut out = FourWheelResponse {
            t: col(),
            steer: col(),
            speed: col(),
            beta: col(),
            yaw_rate: col(),
            ay: col(),
            roll: col(),
            loads: Vec::with_capacity(n + 1),
        };
        // The speed is prescribed: v_y carries the speed change's share of
        // the sideslip through the exact kinematics of each wheel.
        let mut sys = Driven {
            car: self,
            manoeuvre: m,
            last: None,
        };
        ode::rk4(&mut sys, t0, step, n, [0.0; 8], |sys, _, t, x| {
            let k1 = sys.last.as_ref().expect("the first stage was evaluated");
            let u = m.speed(t);
            out.t.push(t);
            out.steer.push(m.steer(t));
            out.speed.push(u);
            out.beta.push((x[0] / u.max(MIN_WHEEL_SPEED)).atan());
            out.yaw_rate.push(x[1]);
            out.ay.push(k1.ay);
            out.roll.push(x[2]);
            out.loads.push(k1.loads);
            true
        });
        out
    }

    /// What the sensors read of `response` at `times`: delay, offsets and a
    /// rolling accelerometer as the effects say.
    pub fn observe(&self, response: &FourWheelResponse, times: &[f64]) -> FourWheelObserved {
        let e = &self.effects;
        let h = response;
        let at = |ys: &[f64], t: f64| interpolate(&h.t, ys, t - e.sensor_delay);
        let mut seen = FourWheelObserved::default();
        for &t in times {
            seen.yaw_rate.push(at(&h.yaw_rate, t) + e.sensor_bias[0]);
            let ay = at(&h.ay, t);
            let ay_read = if e.accelerometer_rolls {
                let phi = at(&h.roll, t);
                ay * phi.cos() + GRAVITY * phi.sin()
            } else {
                ay
            };
            seen.ay.push(ay_read + e.sensor_bias[1]);
            seen.beta.push(at(&h.beta, t) + e.sensor_bias[2]);
        }
        seen
    }
}

#[cfg(test)]
mod tests;
