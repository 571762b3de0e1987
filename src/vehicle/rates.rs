//! The right-hand side of the vehicle model: one function,
//! [`VehicleModel::rates`], that every job integrates — the simulation, the
//! equilibrium and stability analysis (through the (β, r) wrappers) and the
//! replays of the sim-to-real diagnosis.
//!
//! States ([`StateVector`]): sideslip β, yaw rate r, the lagged front and
//! rear slip angles, body roll φ and its rate. With every
//! [`super::Effects`] off the last four do not feed back and the model is
//! exactly the 2-DOF model of the module documentation ([`super`]), to the
//! bit: the extra terms are added only when their effect is on. Every
//! number an effect sets is read through [`ModelScalars`] (the effects and
//! the vehicle's yaw inertia and road friction they scale), in `f64` or in
//! a fit's dual numbers alike. Units: SI, rad; ISO 8855 signs.

use super::balance::{projection, AxleSolution};
use super::scalar::{off, ModelScalars, Scalar};
use super::wheels::{AxleTyres, PlainTyres, FRONT};
use super::{Inputs, Kinematics, LoadTransferSeed, Outputs, State, VehicleModel, MIN_SPEED};
use crate::tyre::Tyre;

/// The full state: β (rad), r (rad/s), the lagged front and rear slip
/// angles (rad), roll φ (rad) and roll rate (rad/s).
pub type StateVector = [f64; 6];

/// Relative tolerance of the load-transfer loop on g(ay). The loads then
/// belong to an ay within 1e-9·(1 + |ay|) of the returned one; since the axle
/// forces change with ay by about 5 % of m per m/s², the forces are
/// consistent to ~1e-10 relative: two orders below RK4's own truncation error
/// at a 1 ms step (≈ (h·λ)⁴ ≈ 1e-7 with λ ≈ 20 1/s).
pub(crate) const LOAD_TOLERANCE: f64 = 1e-9;

/// How an evaluation of the right-hand side finds its lateral acceleration
/// (hence its wheel loads).
pub(crate) enum LoadSolve<'s, T> {
    /// The load-transfer loop solved from (and into) a seed to a relative
    /// tolerance on g(ay).
    Solved(&'s mut LoadTransferSeed, f64),
    /// At the lateral acceleration given, not solved (a Jacobian probe's
    /// wheel loads, frozen at its step's solution).
    At(T),
}

/// One evaluation of the right-hand side in scalar `T`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RatesOf<T> {
    /// Derivatives of the full state.
    pub(crate) dx: [T; 6],
    /// Lateral acceleration of the tyres' force, m/s².
    pub(crate) ay: T,
    /// Axle slip angles, forces and wheel loads.
    pub(crate) axles: AxleSolution<T>,
    /// Rear slip angle, rad.
    pub(crate) alpha_rear: T,
    /// Tyre-set evaluations of the load-transfer loop.
    pub(crate) evaluations: u32,
}

/// The cosine of the last front road-wheel steer a run's right-hand side
/// projected its front force by: a step steer holds one steer over most of
/// its stages, and `cos` was 3 % of a PAC89 right-hand side (profiled,
/// session 113). The C library's cosine of the same number, so the same
/// bits.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SteerCosine {
    steer: u64,
    cos: f64,
}

impl Default for SteerCosine {
    fn default() -> Self {
        Self {
            steer: 0f64.to_bits(),
            cos: 1.0,
        }
    }
}

impl SteerCosine {
    /// `cos steer`, computed only when `steer` is not the last one's.
    #[inline]
    pub(crate) fn of(&mut self, steer: f64) -> f64 {
        if steer.to_bits() != self.steer {
            (self.steer, self.cos) = (steer.to_bits(), steer.cos());
        }
        self.cos
    }
}

impl VehicleModel {
    /// A wheel's lateral force of `tyre` at slip angle `alpha` and load
    /// `fz` on the road of `inp`.
    pub(crate) fn wheel_force(tyre: &Tyre, alpha: f64, fz: f64, inp: &Inputs) -> f64 {
        let plain = PlainTyres {
            tyres: [tyre, tyre],
        };
        plain.wheel(FRONT, alpha, fz, inp.friction, inp.speed)
    }

    /// Kinematic slip angles (front, rear) of axles steered by `steer`
    /// (front, rear) at sideslip `beta` and yaw rate `r`, speed `u` (already
    /// held at [`MIN_SPEED`]).
    fn kinematic_slip<T: Scalar>(&self, beta: T, r: T, u: f64, steer: [T; 2]) -> (T, T) {
        let vy = self.lateral_velocity(beta, u);
        self.kinematic_slip_at(beta, vy, r, u, steer)
    }

    /// The lateral velocity `tan β · u` (m/s) the exact kinematics reads,
    /// in its slip angles and its sideslip rate alike: the right-hand side
    /// takes one tangent for both. Zero, unread, in the small-angle form.
    fn lateral_velocity<T: Scalar>(&self, beta: T, u: f64) -> T {
        match self.options.kinematics {
            Kinematics::Exact => beta.tan() * u,
            Kinematics::SmallAngle => T::from(0.0),
        }
    }

    /// [`VehicleModel::kinematic_slip`] with the lateral velocity `v`
    /// ([`VehicleModel::lateral_velocity`] of `beta`) already taken.
    fn kinematic_slip_at<T: Scalar>(&self, beta: T, v: T, r: T, u: f64, steer: [T; 2]) -> (T, T) {
        let (a, b) = (self.vehicle.a, self.vehicle.b);
        match self.options.kinematics {
            Kinematics::Exact => (
                steer[0] - ((v + r * a) / u).atan(),
                steer[1] - ((v - r * b) / u).atan(),
            ),
            Kinematics::SmallAngle => (steer[0] - beta - r * a / u, steer[1] - beta + r * b / u),
        }
    }

    /// Front and rear slip angles for a state and inputs (no roll).
    pub(crate) fn slip_angles(&self, x: &State, inp: &Inputs) -> (f64, f64) {
        let u = inp.speed.max(MIN_SPEED);
        self.kinematic_slip(x.beta, x.yaw_rate, u, [inp.steer, 0.0])
    }

    /// cos δ of the force projection (1 in the small-angle form).
    pub(crate) fn steer_projection(&self, steer: f64) -> f64 {
        projection(self.options.kinematics == Kinematics::Exact, steer)
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
        let sc = self.scalars(friction);
        let e = &sc.effects;
        let u = speed.max(MIN_SPEED);
        let (load_f, load_r) = v.static_axle_loads();
        let (cf, cr) = self.axle_cornering_stiffness_under((
            load_f + e.aero_load[0] * u * u,
            load_r + e.aero_load[1] * u * u,
        ));
        let [scale_f, scale_r] = e.cornering_stiffness_scale;
        let mu = sc.friction.max(1.0);
        let (cf, cr) = (mu * (scale_f * cf).abs(), mu * (scale_r * cr).abs());
        let (m, iz, a, b) = (v.mass, sc.yaw_inertia, v.a, v.b);
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
    /// quasi-static values: roll at its steady value for the tyres' ay at
    /// that state's equilibrium, u·r + g·sin θ (on a road banked by θ the
    /// tyres hold the bank's pull too, and the roll follows their force:
    /// a roll taken from u·r alone left a banked straight-running trim
    /// rolling, and steering through roll steer, before its step), the lag
    /// states at the kinematic slip angles that roll gives.
    pub(crate) fn quasi_static_state(&self, x: &State, inp: &Inputs) -> StateVector {
        let sc = self.scalars(inp.friction);
        self.quasi_static_of(&sc, x.beta, x.yaw_rate, inp.speed, inp.steer)
    }

    /// [`VehicleModel::quasi_static_state`] in a scalar: sideslip `beta`,
    /// yaw rate `r`, speed `speed`, steer `steer`.
    pub(crate) fn quasi_static_of<T: Scalar>(
        &self,
        sc: &ModelScalars<T>,
        beta: T,
        r: T,
        speed: f64,
        steer: T,
    ) -> [T; 6] {
        let e = &sc.effects;
        let u = speed.max(MIN_SPEED);
        let ay = r * u + self.bank_acceleration_of(sc, 0.0);
        let phi = e.roll.gradient * ay;
        let steer = [steer + e.roll_steer[0] * phi, e.roll_steer[1] * phi];
        let (af, ar) = self.kinematic_slip(beta, r, u, steer);
        let af = af - e.steering_compliance * self.steady_front_force(sc, ay, steer[0]);
        [beta, r, af, ar, phi, T::from(0.0)]
    }

    /// The front axle's lateral force (N) that holds the tyres' lateral
    /// acceleration `ay` with no yaw acceleration at road-wheel steer
    /// `steer`: Fyf·cos(δ − c·Fyf)·a = Fyr·b and Fyf·cos(δ − c·Fyf) + Fyr =
    /// m·ay, so Fyf·cos(δ − c·Fyf) = m·ay·b/L. A compliant front's lag
    /// state settles at the kinematic slip less c·Fyf, not at the kinematic
    /// slip: started there, a banked trim with compliance and a lag drifted
    /// before its step. Zero without compliance (the lag state is then the
    /// kinematic slip, to the bit).
    fn steady_front_force<T: Scalar>(&self, sc: &ModelScalars<T>, ay: T, steer: T) -> T {
        let c = sc.effects.steering_compliance;
        if off(c) {
            return T::from(0.0);
        }
        let v = &self.vehicle;
        let held = ay * (v.mass * v.b / (v.a + v.b));
        let exact = self.options.kinematics == Kinematics::Exact;
        // The projection's dependence on Fyf is c·Fyf·sin δ, a small
        // fraction of it: the fixed point converges to round-off in a few
        // steps.
        let mut fyf = held;
        for _ in 0..8 {
            fyf = held / projection(exact, steer - c * fyf);
        }
        fyf
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
        let sc = self.scalars(inp.friction);
        let mut cosine = SteerCosine::default();
        self.rates_in(&sc, x, inp, (seed, &mut cosine), tolerance)
    }

    /// [`VehicleModel::rates`] with the model's numbers `sc` already built
    /// ([`VehicleModel::scalars`] of `inp.friction`): an integrator, whose
    /// road does not change, builds them once per run, not once per stage;
    /// and with the cosine of its last steer kept in `cosine`.
    pub(crate) fn rates_in(
        &self,
        sc: &ModelScalars<f64>,
        x: &StateVector,
        inp: &Inputs,
        (seed, cosine): (&mut LoadTransferSeed, &mut SteerCosine),
        tolerance: f64,
    ) -> (StateVector, Outputs) {
        let tyres = PlainTyres {
            tyres: [&self.front, &self.rear],
        };
        let solve = LoadSolve::Solved(seed, tolerance);
        let o = self.rates_with(sc, &tyres, x, inp, (inp.steer, Some(cosine)), solve);
        let outputs = Outputs {
            beta_rate: o.dx[0],
            yaw_acceleration: o.dx[1],
            ay: o.ay,
            alpha_front: o.axles.alpha_front,
            alpha_rear: o.alpha_rear,
            fy_front: o.axles.fy_front,
            fy_rear: o.axles.fy_rear,
            fz: o.axles.fz,
            load_iterations: o.evaluations,
        };
        (o.dx, outputs)
    }

    /// The right-hand side in scalar `T`: the model's numbers `sc`, its
    /// tyres `tyres`, state `x`, inputs `inp` with the road-wheel steer
    /// `steer` (in `T`: a steer path's parameters move it), the lateral
    /// acceleration found by `solve`. In plain numbers this is
    /// [`VehicleModel::rates`]; in dual numbers the same values with their
    /// derivatives.
    pub(crate) fn rates_of<T: Scalar>(
        &self,
        sc: &ModelScalars<T>,
        tyres: &impl AxleTyres<T>,
        x: &[T; 6],
        inp: &Inputs,
        steer: T,
        solve: LoadSolve<'_, T>,
    ) -> RatesOf<T> {
        self.rates_with(sc, tyres, x, inp, (steer, None), solve)
    }

    /// [`VehicleModel::rates_of`] with the cosine of the front steer taken
    /// from `cosine` where one is kept (plain numbers only).
    fn rates_with<T: Scalar>(
        &self,
        sc: &ModelScalars<T>,
        tyres: &impl AxleTyres<T>,
        x: &[T; 6],
        inp: &Inputs,
        (steer, cosine): (T, Option<&mut SteerCosine>),
        solve: LoadSolve<'_, T>,
    ) -> RatesOf<T> {
        let v = &self.vehicle;
        let e = &sc.effects;
        let u = inp.speed.max(MIN_SPEED);
        let (beta, r, phi) = (x[0], x[1], x[4]);
        let steer = [steer + e.roll_steer[0] * phi, e.roll_steer[1] * phi];
        let vy = self.lateral_velocity(beta, u);
        let (kin_f, kin_r) = self.kinematic_slip_at(beta, vy, r, u, steer);
        let lagged = e.lagged();
        let alpha_rear = if lagged { x[3] } else { kin_r };
        let exact = self.options.kinematics == Kinematics::Exact;
        let cos_steer = match cosine {
            Some(c) if T::PLAIN && exact => T::from(c.of(steer[0].re())),
            _ => projection(exact, steer[0]),
        };
        let at = (steer[0], cos_steer, phi);
        let balance = self.balance(sc, tyres, inp, at, [x[2], kin_f, alpha_rear]);
        let (mut ay, mut s, evaluations, seed) = match solve {
            LoadSolve::Solved(seed, tolerance) => {
                let (ay, s, n) = balance.solve(tyres, seed, tolerance);
                (ay, s, n, Some(seed))
            }
            LoadSolve::At(ay) => {
                let (y, s) = balance.eval(tyres, balance.plain_if_compliant().as_ref(), ay);
                (y, s, 1, None)
            }
        };
        if !ay.re().is_finite() {
            // A tyre evaluated far outside its range (a fit's trial
            // parameters) must not poison the load-transfer seed.
            ay = T::from(0.0);
            (s.fy_front, s.fy_rear, s.projection) = (T::from(0.0), T::from(0.0), T::from(1.0));
        }
        if let (true, Some(seed)) = (balance.transfer, seed) {
            seed.push(ay.re());
        }
        let fyf_x = s.fy_front * s.projection;
        let yaw_acceleration = (fyf_x * v.a - s.fy_rear * v.b) / sc.yaw_inertia;
        // The path's lateral acceleration is the tyres' (ay) less the bank's
        // pull g·sin θ (zero without a bank).
        let ay_path = ay - self.bank_acceleration_of(sc, inp.bank);
        let beta_rate = match self.options.kinematics {
            Kinematics::Exact => {
                let vy_dot = ay_path - r * u;
                (vy_dot * u - vy * inp.speed_rate) / (vy * vy + u * u)
            }
            Kinematics::SmallAngle => ay_path / u - r - beta * inp.speed_rate / u,
        };
        let zero = T::from(0.0);
        let mut dx = [beta_rate, yaw_acceleration, zero, zero, x[5], zero];
        if lagged {
            let k = T::from(u) / e.relaxation_length;
            dx[2] = k * (kin_f - e.steering_compliance * s.fy_front - x[2]);
            dx[3] = k * (kin_r - x[3]);
        }
        let roll = &e.roll;
        let omega = roll.frequency * std::f64::consts::TAU;
        dx[5] = omega * omega * (roll.gradient * ay - phi) - roll.damping * 2.0 * omega * x[5];
        RatesOf {
            dx,
            ay,
            axles: s,
            alpha_rear,
            evaluations,
        }
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
