//! The right-hand side of the vehicle model: one function,
//! [`VehicleModel::rates`], that every job integrates — the simulation, the
//! equilibrium and stability analysis (through the (β, r) wrappers) and the
//! replays of the sim-to-real diagnosis.
//!
//! States ([`StateVector`]): sideslip β, yaw rate r, the lagged front and
//! rear slip angles, body roll φ and its rate. With every
//! [`super::Effects`] off the last four do not feed back and the model is
//! exactly the 2-DOF model of the module documentation ([`super`]), to the
//! bit: the extra terms are added only when their effect is on.
//! Units: SI, rad; ISO 8855 signs.

use super::loads::solve_load_transfer;
use super::{Inputs, Kinematics, LoadTransferSeed, Outputs, State, VehicleModel, MIN_SPEED};
use crate::tyre::{SlipState, Tyre, TyreModel};

/// The full state: β (rad), r (rad/s), the lagged front and rear slip
/// angles (rad), roll φ (rad) and roll rate (rad/s).
pub type StateVector = [f64; 6];

/// Relative tolerance of the load-transfer loop on g(ay). The loads then
/// belong to an ay within 1e-9·(1 + |ay|) of the returned one; since the axle
/// forces change with ay by about 5 % of m per m/s², the forces are
/// consistent to ~1e-10 relative: two orders below RK4's own truncation error
/// at a 1 ms step (≈ (h·λ)⁴ ≈ 1e-7 with λ ≈ 20 1/s).
pub(crate) const LOAD_TOLERANCE: f64 = 1e-9;

/// What the load-transfer loop carries out of its last evaluation.
#[derive(Clone, Copy)]
struct AxleSolution {
    alpha_front: f64,
    fy_front: f64,
    fy_rear: f64,
    projection: f64,
    fz: [f64; 4],
}

/// An axle's tyre at a slip angle. A tyre whose force is proportional to
/// its load ([`TyreModel::lateral_force_per_load`]) is evaluated here once
/// for both wheels and every load the load-transfer loop tries.
struct AtSlip<'a> {
    tyre: &'a Tyre,
    alpha: f64,
    per_load: Option<f64>,
}

impl<'a> AtSlip<'a> {
    fn new(tyre: &'a Tyre, alpha: f64, inp: &Inputs) -> Self {
        let per_load = tyre.lateral_force_per_load(&SlipState {
            alpha,
            kappa: 0.0,
            fz: 1.0,
            camber: 0.0,
            mu_scale: inp.friction,
            speed: inp.speed,
        });
        Self {
            tyre,
            alpha,
            per_load,
        }
    }

    /// A wheel's lateral force at load `fz`.
    fn wheel(&self, fz: f64, inp: &Inputs) -> f64 {
        match self.per_load {
            Some(k) if fz > 0.0 => k * fz,
            Some(_) => 0.0,
            None => VehicleModel::wheel_force(self.tyre, self.alpha, fz, inp),
        }
    }

    /// A wheel's lateral force with a longitudinal force `fx` taken from its
    /// friction circle: `Fy0·√(1 − (Fx/(μ·Fz))²)`, zero once `fx` uses all
    /// of it.
    fn combined(&self, fz: f64, fx: f64, inp: &Inputs) -> f64 {
        let fy0 = self.wheel(fz, inp);
        if fx == 0.0 || fy0 == 0.0 {
            return fy0;
        }
        let ratio = fx / (self.tyre.friction_coefficient(fz, inp.friction) * fz);
        fy0 * (1.0 - ratio * ratio).max(0.0).sqrt()
    }
}

impl VehicleModel {
    pub(crate) fn wheel_force(tyre: &Tyre, alpha: f64, fz: f64, inp: &Inputs) -> f64 {
        tyre.lateral_force(&SlipState {
            alpha,
            kappa: 0.0,
            fz,
            camber: 0.0,
            mu_scale: inp.friction,
            speed: inp.speed,
        })
    }

    /// Axle force of a tyre at a slip angle (`at`) on wheel loads `fz`, plus
    /// camber thrust `thrust` per unit load (roll camber); with a
    /// longitudinal force `fx` per wheel (combined slip), each wheel's force
    /// reduced on its friction circle.
    fn axle_force(at: &AtSlip, fz: [f64; 2], thrust: f64, fx: Option<f64>, inp: &Inputs) -> f64 {
        let y = match fx {
            None => at.wheel(fz[0], inp) + at.wheel(fz[1], inp),
            Some(fx) => at.combined(fz[0], fx, inp) + at.combined(fz[1], fx, inp),
        };
        if thrust == 0.0 {
            y
        } else {
            y + thrust * (fz[0] + fz[1])
        }
    }

    /// Kinematic slip angles (front, rear) of axles steered by `steer`
    /// (front, rear) at sideslip `beta` and yaw rate `r`, speed `u` (already
    /// held at [`MIN_SPEED`]).
    fn kinematic_slip(&self, beta: f64, r: f64, u: f64, steer: [f64; 2]) -> (f64, f64) {
        let (a, b) = (self.vehicle.a, self.vehicle.b);
        match self.options.kinematics {
            Kinematics::Exact => {
                let v = u * beta.tan();
                (
                    steer[0] - ((v + a * r) / u).atan(),
                    steer[1] - ((v - b * r) / u).atan(),
                )
            }
            Kinematics::SmallAngle => (steer[0] - beta - a * r / u, steer[1] - beta + b * r / u),
        }
    }

    /// Front and rear slip angles for a state and inputs (no roll).
    pub(crate) fn slip_angles(&self, x: &State, inp: &Inputs) -> (f64, f64) {
        let u = inp.speed.max(MIN_SPEED);
        self.kinematic_slip(x.beta, x.yaw_rate, u, [inp.steer, 0.0])
    }

    /// cos δ of the force projection (1 in the small-angle form).
    pub(crate) fn steer_projection(&self, steer: f64) -> f64 {
        match self.options.kinematics {
            Kinematics::Exact => steer.cos(),
            Kinematics::SmallAngle => 1.0,
        }
    }

    /// The full state of a (β, r) state, the extra states zero when no
    /// effect needs them, else at their quasi-static values
    /// ([`VehicleModel::quasi_static_state`]).
    pub(crate) fn state_vector(&self, x: &State, inp: &Inputs) -> StateVector {
        if self.options.effects.extra_states() {
            self.quasi_static_state(x, inp)
        } else {
            [x.beta, x.yaw_rate, 0.0, 0.0, 0.0, 0.0]
        }
    }

    /// The magnitude of the fastest eigenvalue of the model linearised about
    /// straight running at `speed` on a road of friction `friction`, 1/s,
    /// estimated from above: the (β, r) pair of the 2-DOF model with each
    /// axle at its cornering stiffness under its static and aero load (the
    /// steepest slope of a saturating tyre; the friction scale taken as at
    /// least 1), the lag states' `u/σ` and the roll mode's. A fixed-step
    /// integrator is stable where its step times this lies inside its
    /// stability region: RK4 at 20 ms is not for stiff racing axles at
    /// 5–15 m/s, whose yaw mode reaches 250–1000 1/s.
    pub(crate) fn fastest_rate(&self, speed: f64, friction: f64) -> f64 {
        let v = &self.vehicle;
        let e = &self.options.effects;
        let u = speed.max(MIN_SPEED);
        let (load_f, load_r) = v.static_axle_loads();
        let (cf, cr) = self.axle_cornering_stiffness_under((
            load_f + e.aero_load[0] * u * u,
            load_r + e.aero_load[1] * u * u,
        ));
        let [scale_f, scale_r] = e.cornering_stiffness_scale;
        let mu = friction.max(1.0);
        let (cf, cr) = (mu * (scale_f * cf).abs(), mu * (scale_r * cr).abs());
        let (m, iz, a, b) = (v.mass, v.yaw_inertia, v.a, v.b);
        let a11 = -(cf + cr) / (m * u);
        let a12 = (b * cr - a * cf) / (m * u * u) - 1.0;
        let a21 = (b * cr - a * cf) / iz;
        let a22 = -(a * a * cf + b * b * cr) / (iz * u);
        let (half_trace, det) = (0.5 * (a11 + a22), a11 * a22 - a12 * a21);
        let disc = half_trace * half_trace - det;
        let bicycle = if disc >= 0.0 {
            half_trace.abs() + disc.sqrt()
        } else {
            det.sqrt()
        };
        let lag = if e.lagged() {
            u / e.relaxation_length
        } else {
            0.0
        };
        let omega = std::f64::consts::TAU * e.roll.frequency;
        let zeta = e.roll.damping;
        let roll = if zeta >= 1.0 {
            omega * (zeta + (zeta * zeta - 1.0).sqrt())
        } else {
            omega
        };
        bicycle.max(lag).max(roll)
    }

    /// The full state of a (β, r) state with the extra states at their
    /// quasi-static values: roll at its steady value for ay = u·r, the lag
    /// states at the kinematic slip angles that roll gives.
    pub(crate) fn quasi_static_state(&self, x: &State, inp: &Inputs) -> StateVector {
        let e = &self.options.effects;
        let u = inp.speed.max(MIN_SPEED);
        let phi = e.roll.gradient * u * x.yaw_rate;
        let steer = [inp.steer + e.roll_steer[0] * phi, e.roll_steer[1] * phi];
        let (af, ar) = self.kinematic_slip(x.beta, x.yaw_rate, u, steer);
        [x.beta, x.yaw_rate, af, ar, phi, 0.0]
    }

    /// Derivatives of the full state and the outputs, with the load-transfer
    /// loop solved to relative `tolerance` on g(ay), started from (and
    /// updated into) `seed`.
    pub(crate) fn rates(
        &self,
        x: &StateVector,
        inp: &Inputs,
        seed: &mut LoadTransferSeed,
        tolerance: f64,
    ) -> (StateVector, Outputs) {
        let v = &self.vehicle;
        let e = &self.options.effects;
        let u = inp.speed.max(MIN_SPEED);
        let (beta, r, phi) = (x[0], x[1], x[4]);
        let steer = [inp.steer + e.roll_steer[0] * phi, e.roll_steer[1] * phi];
        let (kin_f, kin_r) = self.kinematic_slip(beta, r, u, steer);
        let lagged = e.lagged();
        let compliance = e.steering_compliance;
        let [scale_f, scale_r] = e.cornering_stiffness_scale;
        let thrust = [e.roll_camber[0] * phi, e.roll_camber[1] * phi];
        let alpha_rear = if lagged { x[3] } else { kin_r };
        // Without compliance the wheel's steer, hence the projection, does
        // not depend on the force: one cosine per evaluation.
        let fixed_projection = self.steer_projection(steer[0]);
        let fx = e.combined_slip.and_then(|c| c.wheel_forces(v.mass, inp.ax));
        // The slip angles the load-transfer loop holds fixed (all but a
        // compliant front's), with their tyres evaluated once.
        let alpha_front = if lagged { x[2] } else { kin_f };
        let front_at = (lagged || compliance == 0.0)
            .then(|| AtSlip::new(&self.front, scale_f * alpha_front, inp));
        let rear_at = AtSlip::new(&self.rear, scale_r * alpha_rear, inp);
        let front = |fz: [f64; 2]| -> (f64, f64) {
            let fx = fx.map(|f| f[0]);
            if let Some(at) = &front_at {
                return (alpha_front, Self::axle_force(at, fz, thrust[0], fx, inp));
            }
            compliant_slip(kin_f, compliance, |a: f64| {
                let at = AtSlip::new(&self.front, scale_f * a, inp);
                Self::axle_force(&at, fz, thrust[0], fx, inp)
            })
        };
        let split = self.load_split_at(u, inp.ax, inp.bank);
        let inv_m = 1.0 / v.mass;
        let eval = |ay: f64| {
            let fz = split.at(ay);
            let (alpha_front, fy_front) = front([fz[0], fz[1]]);
            let fy_rear =
                Self::axle_force(&rear_at, [fz[2], fz[3]], thrust[1], fx.map(|f| f[1]), inp);
            let projection = if compliance == 0.0 {
                fixed_projection
            } else {
                self.steer_projection(steer[0] - compliance * fy_front)
            };
            (
                (fy_front * projection + fy_rear) * inv_m,
                AxleSolution {
                    alpha_front,
                    fy_front,
                    fy_rear,
                    projection,
                    fz,
                },
            )
        };
        let transfer = self.options.load_transfer;
        let (mut ay, mut s, evaluations) = solve_load_transfer(transfer, seed, tolerance, eval);
        if !ay.is_finite() {
            // A tyre evaluated far outside its range (a fit's trial
            // parameters) must not poison the load-transfer seed.
            ay = 0.0;
            (s.fy_front, s.fy_rear, s.projection) = (0.0, 0.0, 1.0);
        }
        if transfer {
            seed.push(ay);
        }
        let fyf_x = s.fy_front * s.projection;
        let yaw_acceleration = (v.a * fyf_x - v.b * s.fy_rear) / v.yaw_inertia;
        // The path's lateral acceleration is the tyres' (ay) less the bank's
        // pull g·sin θ (zero without a bank).
        let ay_path = ay - self.bank_acceleration_at(inp.bank);
        let beta_rate = match self.options.kinematics {
            Kinematics::Exact => {
                let vy = u * beta.tan();
                let vy_dot = ay_path - u * r;
                (u * vy_dot - vy * inp.speed_rate) / (u * u + vy * vy)
            }
            Kinematics::SmallAngle => ay_path / u - r - inp.speed_rate * beta / u,
        };
        let mut dx = [beta_rate, yaw_acceleration, 0.0, 0.0, x[5], 0.0];
        if lagged {
            let k = u / e.relaxation_length;
            dx[2] = k * (kin_f - compliance * s.fy_front - x[2]);
            dx[3] = k * (kin_r - x[3]);
        }
        let omega = std::f64::consts::TAU * e.roll.frequency;
        dx[5] = omega * omega * (e.roll.gradient * ay - phi) - 2.0 * e.roll.damping * omega * x[5];
        let outputs = Outputs {
            beta_rate,
            yaw_acceleration,
            ay,
            alpha_front: s.alpha_front,
            alpha_rear,
            fy_front: s.fy_front,
            fy_rear: s.fy_rear,
            fz: s.fz,
            load_iterations: evaluations,
        };
        (dx, outputs)
    }

    /// State derivatives and outputs of a (β, r) state, solving the
    /// load-transfer loop from scratch.
    pub fn evaluate(&self, x: &State, inp: &Inputs) -> Outputs {
        self.evaluate_seeded(x, inp, &mut LoadTransferSeed::default())
    }

    /// State derivatives and outputs, with the load-transfer solve started
    /// from (and updated into) `seed`: the integrator passes the previous
    /// stage's solution. The answer is the same to the loop's tolerance.
    pub(crate) fn evaluate_seeded(
        &self,
        x: &State,
        inp: &Inputs,
        seed: &mut LoadTransferSeed,
    ) -> Outputs {
        self.evaluate_to(x, inp, seed, LOAD_TOLERANCE)
    }

    /// As [`VehicleModel::evaluate_seeded`] with the load-transfer loop solved
    /// to relative `tolerance` on g(ay): equilibrium and stability analysis
    /// differentiate the right-hand side numerically and want it smooth to
    /// near rounding (1e-13), not to the simulation's 1e-9. The extra states
    /// sit at their quasi-static values ([`VehicleModel::state_vector`]).
    pub(crate) fn evaluate_to(
        &self,
        x: &State,
        inp: &Inputs,
        seed: &mut LoadTransferSeed,
        tolerance: f64,
    ) -> Outputs {
        self.rates(&self.state_vector(x, inp), inp, seed, tolerance)
            .1
    }
}

/// The front slip angle and force with steering compliance `c`:
/// `α = α_kin − c·Fyf(α)`, solved by a secant (Fyf grows with α, so the
/// root is unique).
fn compliant_slip(kin: f64, c: f64, force: impl Fn(f64) -> f64) -> (f64, f64) {
    let g = |a: f64| {
        let f = force(a);
        (a - kin + c * f, f)
    };
    // g(kin) = c·Fyf(kin): the first iterate's force is also the first
    // residual's.
    let f0 = force(kin);
    let (mut a0, mut a1, mut g0) = (kin, kin - c * f0, c * f0);
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
}
