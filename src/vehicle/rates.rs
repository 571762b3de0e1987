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

use super::loads::{solve_load_transfer, LoadSplit};
use super::scalar::{off, ModelScalars, Scalar};
use super::wheels::{AxleTyres, PlainTyres, FRONT, REAR};
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

/// What the load-transfer loop carries out of its last evaluation.
#[derive(Debug, Clone, Copy)]
pub(crate) struct AxleSolution<T> {
    pub(crate) alpha_front: T,
    pub(crate) fy_front: T,
    pub(crate) fy_rear: T,
    pub(crate) projection: T,
    pub(crate) fz: [T; 4],
}

impl<T: Scalar> AxleSolution<T> {
    /// [`Scalar::eliminate`] of every value.
    fn eliminate(self, k: usize, x: T) -> Self {
        Self {
            alpha_front: self.alpha_front.eliminate(k, x),
            fy_front: self.fy_front.eliminate(k, x),
            fy_rear: self.fy_rear.eliminate(k, x),
            projection: self.projection.eliminate(k, x),
            fz: self.fz.map(|f| f.eliminate(k, x)),
        }
    }
}

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

/// An axle's tyre at a slip angle. A tyre whose force is proportional to
/// its load ([`AxleTyres::per_load`]) is evaluated here once for both
/// wheels and every load the load-transfer loop tries.
#[derive(Debug, Clone, Copy)]
struct AtSlip<T> {
    axle: usize,
    alpha: T,
    per_load: Option<T>,
}

/// What every tyre evaluation of one right-hand side shares: road friction
/// scale and speed.
#[derive(Debug, Clone, Copy)]
struct Road<T> {
    mu: T,
    speed: f64,
}

impl<T: Scalar> AtSlip<T> {
    fn new(tyres: &impl AxleTyres<T>, axle: usize, alpha: T, road: Road<T>) -> Self {
        Self {
            axle,
            alpha,
            per_load: tyres.per_load(axle, alpha, road.mu, road.speed),
        }
    }

    /// A wheel's lateral force at load `fz`.
    fn wheel(&self, tyres: &impl AxleTyres<T>, fz: T, road: Road<T>) -> T {
        match self.per_load {
            Some(k) if fz > 0.0 => k * fz,
            Some(_) => T::from(0.0),
            None => tyres.wheel(self.axle, self.alpha, fz, road.mu, road.speed),
        }
    }

    /// A wheel's lateral force with a longitudinal force `fx` taken from its
    /// friction circle: `Fy0·√(1 − (Fx/(μ·Fz))²)`, zero once `fx` uses all
    /// of it.
    fn combined(&self, tyres: &impl AxleTyres<T>, fz: T, fx: T, road: Road<T>) -> T {
        let fy0 = self.wheel(tyres, fz, road);
        if off(fx) || off(fy0) {
            return fy0;
        }
        let ratio = fx / (tyres.friction_coefficient(self.axle, fz, road.mu) * fz);
        let left = T::from(1.0) - ratio * ratio;
        if left.re() > 0.0 {
            fy0 * left.sqrt()
        } else {
            fy0 * 0.0
        }
    }

    /// Axle force on wheel loads `fz`, plus camber thrust `thrust` per
    /// unit load (roll camber); with a longitudinal force `fx` per wheel
    /// (combined slip), each wheel's force reduced on its friction circle.
    fn axle(
        &self,
        tyres: &impl AxleTyres<T>,
        fz: [T; 2],
        thrust: T,
        fx: Option<T>,
        road: Road<T>,
    ) -> T {
        let y = match fx {
            None => self.wheel(tyres, fz[0], road) + self.wheel(tyres, fz[1], road),
            Some(fx) => {
                self.combined(tyres, fz[0], fx, road) + self.combined(tyres, fz[1], fx, road)
            }
        };
        if off(thrust) {
            y
        } else {
            y + thrust * (fz[0] + fz[1])
        }
    }
}

/// The lateral force balance the load-transfer loop solves, with
/// everything that does not depend on the loads evaluated once.
#[derive(Debug, Clone, Copy)]
struct Balance<T> {
    split: LoadSplit<T>,
    /// The front tyre at its fixed slip angle (None: a compliant front,
    /// whose slip depends on its force).
    front_at: Option<AtSlip<T>>,
    rear_at: AtSlip<T>,
    alpha_front: T,
    kin_front: T,
    compliance: T,
    steer: T,
    scale_front: T,
    thrust: [T; 2],
    fx: Option<[T; 2]>,
    fixed_projection: T,
    inv_mass: f64,
    road: Road<T>,
    exact_kinematics: bool,
    transfer: bool,
    directions: [usize; 2],
}

impl<T: Scalar> Balance<T> {
    /// The values without their derivatives (the tyres' per-load factors
    /// evaluated again in plain numbers).
    fn re(&self, plain: &PlainTyres) -> Balance<f64> {
        let re2 = |x: [T; 2]| [x[0].re(), x[1].re()];
        let road = Road {
            mu: self.road.mu.re(),
            speed: self.road.speed,
        };
        let at = |a: &AtSlip<T>| AtSlip::new(plain, a.axle, a.alpha.re(), road);
        Balance {
            split: self.split.re(),
            front_at: self.front_at.as_ref().map(at),
            rear_at: at(&self.rear_at),
            alpha_front: self.alpha_front.re(),
            kin_front: self.kin_front.re(),
            compliance: self.compliance.re(),
            steer: self.steer.re(),
            scale_front: self.scale_front.re(),
            thrust: re2(self.thrust),
            fx: self.fx.map(re2),
            fixed_projection: self.fixed_projection.re(),
            inv_mass: self.inv_mass,
            road,
            exact_kinematics: self.exact_kinematics,
            transfer: self.transfer,
            directions: self.directions,
        }
    }

    /// The front axle's force with a compliant steer at slip angle `a`.
    fn front_force(&self, tyres: &impl AxleTyres<T>, a: T, fz: [T; 2]) -> T {
        let at = AtSlip::new(tyres, FRONT, self.scale_front * a, self.road);
        let fx = self.fx.map(|f| f[0]);
        at.axle(tyres, fz, self.thrust[0], fx, self.road)
    }

    /// The plain balance a compliant front's slip is solved in when `T`
    /// carries derivatives (None otherwise).
    fn plain_if_compliant(&self, tyres: &impl AxleTyres<T>) -> Option<Balance<f64>> {
        (!T::PLAIN && self.front_at.is_none()).then(|| self.re(&tyres.plain()))
    }

    /// The front slip angle and axle force on wheel loads `fz`; `re` the
    /// plain balance a compliant front's slip is solved in when `T` carries
    /// derivatives.
    fn front(&self, tyres: &impl AxleTyres<T>, re: Option<&Balance<f64>>, fz: [T; 2]) -> (T, T) {
        if let Some(at) = &self.front_at {
            let fx = self.fx.map(|f| f[0]);
            return (
                self.alpha_front,
                at.axle(tyres, fz, self.thrust[0], fx, self.road),
            );
        }
        let (kin, c) = (self.kin_front, self.compliance);
        let Some(re) = re else {
            return compliant_slip(kin, c, |a: T| self.front_force(tyres, a, fz));
        };
        // The slip solved in plain numbers, then differentiated at its
        // root: `α − α_kin + c·Fyf(α) = 0`.
        let plain = tyres.plain();
        let fz_re = [fz[0].re(), fz[1].re()];
        let (root, _) = compliant_slip(re.kin_front, re.compliance, |a: f64| {
            re.front_force(&plain, a, fz_re)
        });
        let k = self.directions[1];
        let a = T::variable(root, k);
        let f = self.front_force(tyres, a, fz);
        let alpha = T::implicit(a, a - kin + c * f, k);
        (alpha, f.eliminate(k, alpha))
    }

    /// `Y(ay)/m` and the axles at lateral acceleration `ay`.
    fn eval(
        &self,
        tyres: &impl AxleTyres<T>,
        re: Option<&Balance<f64>>,
        ay: T,
    ) -> (T, AxleSolution<T>) {
        let fz = self.split.at(ay);
        let (alpha_front, fy_front) = self.front(tyres, re, [fz[0], fz[1]]);
        let fx = self.fx.map(|f| f[1]);
        let fy_rear = self
            .rear_at
            .axle(tyres, [fz[2], fz[3]], self.thrust[1], fx, self.road);
        let projection = if off(self.compliance) {
            self.fixed_projection
        } else {
            projection(
                self.exact_kinematics,
                self.steer - self.compliance * fy_front,
            )
        };
        (
            (fy_front * projection + fy_rear) * self.inv_mass,
            AxleSolution {
                alpha_front,
                fy_front,
                fy_rear,
                projection,
                fz,
            },
        )
    }

    /// The load-transfer loop solved from `seed` to `tolerance`: the
    /// tyres' `Y/m`, the axles there and the evaluations made. In dual
    /// numbers the loop runs in plain numbers and one evaluation at its
    /// root, the lateral acceleration seeded in its direction, gives the
    /// root's derivatives ([`Scalar::implicit`]).
    fn solve(
        &self,
        tyres: &impl AxleTyres<T>,
        seed: &mut LoadTransferSeed,
        tolerance: f64,
    ) -> (T, AxleSolution<T>, u32) {
        if T::PLAIN {
            let (_, y, s, n) = solve_load_transfer(self.transfer, seed, tolerance, |ay| {
                let (y, s) = self.eval(tyres, None, T::from(ay));
                (y.re(), s)
            });
            return (T::from(y), s, n);
        }
        let plain = tyres.plain();
        let re = self.re(&plain);
        let (root, _, _, n) = solve_load_transfer(self.transfer, seed, tolerance, |ay| {
            re.eval(&plain, None, ay)
        });
        if !self.transfer {
            let (y, s) = self.eval(tyres, Some(&re), T::from(0.0));
            return (y, s, n);
        }
        let k = self.directions[0];
        let ay = T::variable(root, k);
        let (y, s) = self.eval(tyres, Some(&re), ay);
        let ay = T::implicit(ay, ay - y, k);
        (y.eliminate(k, ay), s.eliminate(k, ay), n)
    }
}

/// cos δ of the force projection (1 in the small-angle form).
fn projection<T: Scalar>(exact: bool, steer: T) -> T {
    if exact {
        steer.cos()
    } else {
        T::from(1.0)
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
        let (a, b) = (self.vehicle.a, self.vehicle.b);
        match self.options.kinematics {
            Kinematics::Exact => {
                let v = beta.tan() * u;
                (
                    steer[0] - ((v + r * a) / u).atan(),
                    steer[1] - ((v - r * b) / u).atan(),
                )
            }
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
        let u = speed.max(MIN_SPEED);
        let phi = sc.roll[0] * u * r;
        let steer = [steer + sc.roll_steer[0] * phi, sc.roll_steer[1] * phi];
        let (af, ar) = self.kinematic_slip(beta, r, u, steer);
        [beta, r, af, ar, phi, T::from(0.0)]
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
        let tyres = PlainTyres {
            tyres: [&self.front, &self.rear],
        };
        let solve = LoadSolve::Solved(seed, tolerance);
        let o = self.rates_of(&sc, &tyres, x, inp, inp.steer, solve);
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
        let v = &self.vehicle;
        let u = inp.speed.max(MIN_SPEED);
        let (beta, r, phi) = (x[0], x[1], x[4]);
        let steer = [steer + sc.roll_steer[0] * phi, sc.roll_steer[1] * phi];
        let (kin_f, kin_r) = self.kinematic_slip(beta, r, u, steer);
        let lagged = sc.lagged();
        let alpha_rear = if lagged { x[3] } else { kin_r };
        let balance = self.balance(sc, tyres, inp, (steer[0], phi), [x[2], kin_f, alpha_rear]);
        let (mut ay, mut s, evaluations, seed) = match solve {
            LoadSolve::Solved(seed, tolerance) => {
                let (ay, s, n) = balance.solve(tyres, seed, tolerance);
                (ay, s, n, Some(seed))
            }
            LoadSolve::At(ay) => {
                let (y, s) = balance.eval(tyres, balance.plain_if_compliant(tyres).as_ref(), ay);
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
                let vy = beta.tan() * u;
                let vy_dot = ay_path - r * u;
                (vy_dot * u - vy * inp.speed_rate) / (vy * vy + u * u)
            }
            Kinematics::SmallAngle => ay_path / u - r - beta * inp.speed_rate / u,
        };
        let zero = T::from(0.0);
        let mut dx = [beta_rate, yaw_acceleration, zero, zero, x[5], zero];
        if lagged {
            let k = T::from(u) / sc.relaxation_length;
            dx[2] = k * (kin_f - sc.steering_compliance * s.fy_front - x[2]);
            dx[3] = k * (kin_r - x[3]);
        }
        let [gradient, frequency, damping] = sc.roll;
        let omega = frequency * std::f64::consts::TAU;
        dx[5] = omega * omega * (gradient * ay - phi) - damping * 2.0 * omega * x[5];
        RatesOf {
            dx,
            ay,
            axles: s,
            alpha_rear,
            evaluations,
        }
    }

    /// The force balance of one right-hand side at road-wheel steer `steer`
    /// and roll `phi`, with the front's lag state, its kinematic slip
    /// angle and the rear slip angle.
    fn balance<T: Scalar>(
        &self,
        sc: &ModelScalars<T>,
        tyres: &impl AxleTyres<T>,
        inp: &Inputs,
        (steer, phi): (T, T),
        [lag_front, kin_front, alpha_rear]: [T; 3],
    ) -> Balance<T> {
        let lagged = sc.lagged();
        let compliance = sc.steering_compliance;
        let [scale_front, scale_rear] = sc.stiffness_scale;
        let road = Road {
            mu: sc.friction,
            speed: inp.speed,
        };
        let u = inp.speed.max(MIN_SPEED);
        // The slip angles the load-transfer loop holds fixed (all but a
        // compliant front's), with their tyres evaluated once.
        let alpha_front = if lagged { lag_front } else { kin_front };
        let front_at = (lagged || off(compliance))
            .then(|| AtSlip::new(tyres, FRONT, scale_front * alpha_front, road));
        let exact_kinematics = self.options.kinematics == Kinematics::Exact;
        Balance {
            split: self.load_split_of(sc, u, inp.ax, inp.bank),
            front_at,
            rear_at: AtSlip::new(tyres, REAR, scale_rear * alpha_rear, road),
            alpha_front,
            kin_front,
            compliance,
            steer,
            scale_front,
            thrust: sc.roll_camber.map(|k| k * phi),
            fx: sc.wheel_forces(self.vehicle.mass, inp.ax),
            // Without compliance the wheel's steer, hence the projection,
            // does not depend on the force: one cosine per evaluation.
            fixed_projection: projection(exact_kinematics, steer),
            inv_mass: 1.0 / self.vehicle.mass,
            road,
            exact_kinematics,
            transfer: self.options.load_transfer,
            directions: sc.directions,
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

/// The front slip angle and force with steering compliance `c`:
/// `α = α_kin − c·Fyf(α)`, solved by a secant (Fyf grows with α, so the
/// root is unique).
fn compliant_slip<T: Scalar>(kin: T, c: T, force: impl Fn(T) -> T) -> (T, T) {
    let g = |a: T| {
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
