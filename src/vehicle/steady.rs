//! Steady states of the 2-DOF model: the steer angle that holds a target
//! lateral acceleration (GB/T 6323 sets the step amplitude by it).
//!
//! At a steady state β̇ = ṙ = 0, so `ay = u·r` and the unknowns for a target
//! ay are (β, δ). A damped Newton iteration with a central-difference Jacobian
//! solves it from the linear bicycle model's answer. Units: SI, rad.

use super::rates::StateVector;
use super::{Inputs, State, VehicleModel, MIN_SPEED};
pub use crate::error::NoSteadyState;

/// Largest sideslip or steer a steady state may have, rad (45°): beyond it
/// the 2-DOF model's assumptions no longer hold.
const MAX_ANGLE: f64 = std::f64::consts::FRAC_PI_4;

/// A steady state of the model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyState {
    /// Sideslip, rad.
    pub beta: f64,
    /// Yaw rate, rad/s.
    pub yaw_rate: f64,
    /// Front road-wheel steer, rad.
    pub steer: f64,
    /// Lateral acceleration, m/s².
    pub ay: f64,
}

/// Damped Newton iteration for a 2×2 system with a central-difference
/// Jacobian. Returns the root and the final residual norm, or `None` when it
/// stalls before `tol`.
pub(crate) fn newton2(
    f: impl Fn([f64; 2]) -> [f64; 2],
    x0: [f64; 2],
    scale: [f64; 2],
    tol: f64,
    max_iter: usize,
) -> Option<([f64; 2], f64)> {
    let norm = |r: [f64; 2]| r[0].hypot(r[1]);
    let mut x = x0;
    let mut r = f(x);
    for _ in 0..max_iter {
        let n = norm(r);
        if !n.is_finite() {
            return None;
        }
        if n <= tol {
            return Some((x, n));
        }
        let mut jac = [[0.0; 2]; 2];
        for j in 0..2 {
            let h = 1e-7 * scale[j].max(x[j].abs());
            let (mut xp, mut xm) = (x, x);
            xp[j] += h;
            xm[j] -= h;
            let (fp, fm) = (f(xp), f(xm));
            for i in 0..2 {
                jac[i][j] = (fp[i] - fm[i]) / (2.0 * h);
            }
        }
        let det = jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0];
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let dx = [
            (jac[1][1] * r[0] - jac[0][1] * r[1]) / det,
            (-jac[1][0] * r[0] + jac[0][0] * r[1]) / det,
        ];
        // Backtrack until the residual falls: keeps Newton inside the basin
        // near the friction limit, where the Jacobian changes fast.
        // A step that cannot lower the residual even at 1/1024 of its
        // length means Newton is stuck (a fold, a kink): give up early.
        let mut step = 1.0;
        loop {
            let xn = [x[0] - step * dx[0], x[1] - step * dx[1]];
            let rn = f(xn);
            if norm(rn) < n {
                x = xn;
                r = rn;
                break;
            }
            if step < 1e-3 {
                return None;
            }
            step *= 0.5;
        }
    }
    let n = norm(r);
    (n <= tol).then_some((x, n))
}

/// Damped Newton iteration as [`newton2`] for a system that returns its
/// Jacobian with its value (one evaluation per iteration instead of five).
pub(crate) fn newton2_analytic(
    f: impl Fn([f64; 2]) -> ([f64; 2], [[f64; 2]; 2]),
    x0: [f64; 2],
    tol: f64,
    max_iter: usize,
) -> Option<([f64; 2], f64)> {
    let norm = |r: [f64; 2]| r[0].hypot(r[1]);
    let mut x = x0;
    let (mut r, mut jac) = f(x);
    for _ in 0..max_iter {
        let n = norm(r);
        if !n.is_finite() {
            return None;
        }
        if n <= tol {
            return Some((x, n));
        }
        let det = jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0];
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let dx = [
            (jac[1][1] * r[0] - jac[0][1] * r[1]) / det,
            (-jac[1][0] * r[0] + jac[0][0] * r[1]) / det,
        ];
        // The same backtracking as `newton2`.
        let mut step = 1.0;
        loop {
            let xn = [x[0] - step * dx[0], x[1] - step * dx[1]];
            let (rn, jn) = f(xn);
            if norm(rn) < n {
                (x, r, jac) = (xn, rn, jn);
                break;
            }
            if step < 1e-3 {
                return None;
            }
            step *= 0.5;
        }
    }
    let n = norm(r);
    (n <= tol).then_some((x, n))
}

impl VehicleModel {
    /// This model with the tyres' lag off. At a steady state each lagged
    /// slip angle sits at its target (the kinematic slip, the front's less
    /// its compliance's `c·Fyf`), so the steady states are the lagged
    /// model's; without the lag states the balance solves the compliant
    /// front's slip with its force.
    pub(crate) fn without_lag(&self) -> VehicleModel {
        let mut m = self.clone();
        m.options.effects.relaxation_length = 0.0;
        m
    }

    /// The full state of a steady (β, r) state at inputs `inp`: the
    /// quasi-static state ([`VehicleModel::state_vector`]) with a lagged,
    /// compliant front's slip at its steady value `α = α_kin − c·Fyf(α)`
    /// rather than `α_kin` (a trim on a bank, whose front carries force,
    /// would otherwise start its lag state off its target and move). The
    /// slip is solved with the tyres' own force at the state, not the
    /// steady-turn force [`VehicleModel::quasi_static_state`] assumes: the
    /// two agree at a steady state (to 1e-13, `trim_tests`), and away from
    /// one (a log replayed from mid-transient) only this one is the tyres'.
    pub(crate) fn steady_state_vector(&self, x: &State, inp: &Inputs) -> StateVector {
        let mut full = self.state_vector(x, inp);
        let e = &self.options.effects;
        if e.lagged() && e.steering_compliance != 0.0 {
            full[2] = self.without_lag().evaluate(x, inp).alpha_front;
        }
        full
    }

    /// The steady state at speed `u` with lateral acceleration `ay`: the
    /// steer angle that holds it and the sideslip (`None` beyond the
    /// friction limit, past 45° of either, or where Newton stalls).
    fn steady_state_holding(&self, u: f64, friction: f64, ay: f64) -> Option<SteadyState> {
        // `ay` is what the accelerometer reads (the tyres' force over the
        // mass); on a banked road the path needs g·sin θ less.
        let r = (ay - self.bank_acceleration()) / u;
        let v = &self.vehicle;
        let l = v.wheelbase();
        let (_, cr) = self.axle_cornering_stiffness();
        let steer0 = r * (l + self.understeer_gradient() * u * u) / u;
        let beta0 = (v.b - v.mass * v.a * u * u / (l * cr)) * r / u;
        let f = |x: [f64; 2]| {
            let o = self.evaluate(
                &State {
                    beta: x[0],
                    yaw_rate: r,
                },
                &Inputs::steady(x[1], u, friction),
            );
            // (ay_tyres − ay)/u rather than β̇: β̇ carries a cos²β factor
            // that would let Newton 'converge' by running off to β = ±90°.
            [(o.ay - ay) / u, o.yaw_acceleration]
        };
        let held = newton2(f, [beta0, steer0], [0.01, 0.01], 1e-12, 100)
            .map(|(x, _)| x)
            .filter(|x| x[0].abs() <= MAX_ANGLE && x[1].abs() <= MAX_ANGLE);
        held.map(|x| SteadyState {
            beta: x[0],
            yaw_rate: r,
            steer: x[1],
            ay,
        })
    }

    /// Straight running at `speed` on a road of `friction`: the steer and
    /// sideslip that hold the yaw rate at zero. On a flat road the tyres
    /// then make no net force (unless they make force at zero slip); on a
    /// road banked by θ they hold the car against gravity's pull down the
    /// bank, so the accelerometer reads `ay = g·sin θ`, not zero.
    pub(crate) fn straight_running(
        &self,
        speed: f64,
        friction: f64,
    ) -> Result<SteadyState, NoSteadyState> {
        self.steady_state_for_lateral_acceleration(speed, friction, self.bank_acceleration())
    }

    /// The steady state of the model that holds lateral acceleration `ay`
    /// at `speed` on a road of `friction`, or, where none does, the
    /// largest that one does (by bisection between 0 and `ay`).
    pub(crate) fn steady_state_for_lateral_acceleration(
        &self,
        speed: f64,
        friction: f64,
        ay: f64,
    ) -> Result<SteadyState, NoSteadyState> {
        let e = &self.options.effects;
        if e.lagged() && e.steering_compliance != 0.0 {
            // The quasi-static lag states sit at the kinematic slip angles,
            // which with compliance is not the front's steady slip
            // (α_kin − c·Fyf): solved there, the step ignored the
            // compliance (3.47 m/s² reached for 4 asked). The lag-free
            // model has the same steady states and solves that slip.
            return self
                .without_lag()
                .steady_state_for_lateral_acceleration(speed, friction, ay);
        }
        let u = speed.max(MIN_SPEED);
        if let Some(s) = self.steady_state_holding(u, friction, ay) {
            return Ok(s);
        }
        let holds = |a: f64| self.steady_state_holding(u, friction, a).is_some();
        let limit = holds(0.0).then(|| {
            let (mut lo, mut hi) = (0.0, ay);
            for _ in 0..40 {
                let mid = 0.5 * (lo + hi);
                if holds(mid) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            lo
        });
        Err(NoSteadyState {
            speed: u,
            ay,
            limit,
        })
    }
}
