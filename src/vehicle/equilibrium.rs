//! The equilibrium residual of the (β, r) model and its Jacobian in closed
//! form, for the equilibrium solvers and the stability analysis: the wheel
//! loads taken at the lateral acceleration an equilibrium has, so no
//! load-transfer loop is solved. Units: SI, rad; ISO 8855 signs.
//!
//! It is the one right-hand side ([`VehicleModel::rates`]) with the
//! load-transfer loop stopped at that acceleration, written out to
//! differentiate it (the yaw inertia and road friction as the effects scale
//! them, [`super::ModelScalars`]); the effects it leaves out are named by
//! [`super::Effects::beyond_equilibrium_residual`]. Tests in
//! `equilibria/tests.rs` hold its value and Jacobian to the right-hand
//! side's and its differences at random states with every other effect on,
//! and show each effect it leaves out moving the right-hand side away from
//! it.

use super::{Inputs, Kinematics, State, VehicleModel, MIN_SPEED};
use crate::tyre::Tyre;

impl VehicleModel {
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
    pub(crate) fn equilibrium_residual(
        &self,
        x: &State,
        inp: &Inputs,
    ) -> ([f64; 2], [[f64; 2]; 2]) {
        let v = &self.vehicle;
        // The road's friction and the vehicle's yaw inertia as the effects
        // scale them ([`super::ModelScalars`]).
        let sc = self.scalars(inp.friction);
        let inp = &Inputs {
            friction: sc.friction,
            ..*inp
        };
        let u = inp.speed.max(MIN_SPEED);
        let (a, b) = (v.a, v.b);
        let r = x.yaw_rate;
        let (af, ar) = self.slip_angles(x, inp);
        let (daf, dar, sec2, vy) = slip_partials(self.options.kinematics, x.beta, r, u, a, b);
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
        let yaw = (a * p * fyf - b * fyr) / sc.yaw_inertia;
        let dyaw = [
            (a * p * dfyf[0] - b * dfyr[0]) / sc.yaw_inertia,
            (a * p * dfyf[1] - b * dfyr[1]) / sc.yaw_inertia,
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
}

/// The slip angles' partials `[∂/∂β, ∂/∂r]` (front, rear) at sideslip
/// `beta` (rad), yaw rate `r` (rad/s) and speed `u` (m/s) with the axles at
/// `a`, `b` (m) from the centre of mass, with sec²β and the lateral
/// velocity (m/s) the sideslip rate's partials reuse (1 and 0 in small
/// angles). Apart from [`VehicleModel::equilibrium_residual`] so that it reads on a
/// screen; inlined, on fixed arrays, so the Newton loop is what it was.
#[inline]
fn slip_partials(
    kinematics: Kinematics,
    beta: f64,
    r: f64,
    u: f64,
    a: f64,
    b: f64,
) -> ([f64; 2], [f64; 2], f64, f64) {
    match kinematics {
        Kinematics::Exact => {
            let tb = beta.tan();
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
    }
}
