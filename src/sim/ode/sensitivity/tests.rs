//! RK4's dual-number sensitivities against central differences of the
//! plain RK4 ([`super::super::rk4`]) on a 2-DOF bicycle with saturating
//! tyres (the simplified Magic Formula through
//! [`crate::tyre::LateralForceOf`]), with respect to both axles' tyre
//! parameters and the initial state.

use super::*;
use crate::sim::ode::{rk4, OdeSystem};
use crate::tyre::{LateralForceOf, MagicSimple, Parameterised, SlipOf, SlipState, TyreModel};
use nalgebra::{Const, U1};
use num_dual::DualSVec64;

/// Variables: front B, C, D, rear B, C, D, then β0 and r0.
const VARS: usize = 8;
type D = DualSVec64<VARS>;

/// A passenger car at 20 m/s on magic-simple axles, steered by a 2° sine
/// at 0.8 Hz; `p` the axles' tyre parameters.
struct Bicycle<T> {
    p: [T; 6],
    tyre: MagicSimple,
}

const MASS: f64 = 1500.0;
const YAW_INERTIA: f64 = 2500.0;
const A: f64 = 1.2;
const B: f64 = 1.5;
const SPEED: f64 = 20.0;

fn steer(t: f64) -> f64 {
    2f64.to_radians() * (std::f64::consts::TAU * 0.8 * t).sin()
}

/// One axle's force: two wheels at half its static load, μ scale 1.
fn axle<T: DualNum<f64> + Copy>(tyre: &MagicSimple, p: &[T], alpha: T, load: f64) -> T {
    let s = SlipOf {
        alpha,
        fz: T::from(0.5 * load),
        mu_scale: T::from(1.0),
        speed: SPEED,
    };
    tyre.lateral_force_of(p, &s) * 2.0
}

impl<T: DualNum<f64> + Copy> DualSystem<T, 2> for Bicycle<T> {
    fn derivatives(&mut self, t: f64, x: &[T; 2]) -> [T; 2] {
        let g = crate::constants::G;
        let (load_f, load_r) = (MASS * g * B / (A + B), MASS * g * A / (A + B));
        let (beta, r) = (x[0], x[1]);
        let alpha_f = -beta - r * (A / SPEED) + steer(t);
        let alpha_r = -beta + r * (B / SPEED);
        let fy_f = axle(&self.tyre, &self.p[..3], alpha_f, load_f);
        let fy_r = axle(&self.tyre, &self.p[3..], alpha_r, load_r);
        [
            (fy_f + fy_r) / (MASS * SPEED) - r,
            (fy_f * A - fy_r * B) / YAW_INERTIA,
        ]
    }
}

/// The same bicycle in plain numbers through [`TyreModel::lateral_force`],
/// integrated by the crate's RK4.
struct Plain {
    front: MagicSimple,
    rear: MagicSimple,
}

impl OdeSystem<2> for Plain {
    fn derivatives(&mut self, t: f64, x: &[f64; 2]) -> [f64; 2] {
        let g = crate::constants::G;
        let (load_f, load_r) = (MASS * g * B / (A + B), MASS * g * A / (A + B));
        let (beta, r) = (x[0], x[1]);
        let alpha_f = -beta - r * (A / SPEED) + steer(t);
        let alpha_r = -beta + r * (B / SPEED);
        let wheel = |m: &MagicSimple, a: f64, fz: f64| {
            2.0 * m.lateral_force(&SlipState::lateral(a, 0.5 * fz))
        };
        let (fy_f, fy_r) = (
            wheel(&self.front, alpha_f, load_f),
            wheel(&self.rear, alpha_r, load_r),
        );
        [
            (fy_f + fy_r) / (MASS * SPEED) - r,
            (fy_f * A - fy_r * B) / YAW_INERTIA,
        ]
    }
}

const STEP: f64 = 2e-3;
const STEPS: usize = 2000;

/// The plain replay's states at every grid point.
fn plain_replay(v: &[f64; VARS]) -> Vec<[f64; 2]> {
    let mut front = MagicSimple::new(0.0, 0.0);
    front.set_parameters(&v[..3]);
    let mut rear = front.clone();
    rear.set_parameters(&v[3..6]);
    let mut out = Vec::with_capacity(STEPS + 1);
    rk4(
        &mut Plain { front, rear },
        0.0,
        STEP,
        STEPS,
        [v[6], v[7]],
        |_, _, _, x| {
            out.push(*x);
            true
        },
    );
    out
}

/// The dual replay's states (with their derivatives) at every grid point.
fn dual_replay(v: &[f64; VARS]) -> Vec<[D; 2]> {
    let d: [D; VARS] = std::array::from_fn(|k| D::from(v[k]).derivative(k));
    let mut sys = Bicycle {
        p: std::array::from_fn(|k| d[k]),
        tyre: MagicSimple::new(0.0, 0.0),
    };
    let mut out = Vec::with_capacity(STEPS + 1);
    rk4_dual(&mut sys, 0.0, STEP, STEPS, [d[6], d[7]], |_, _, _, x| {
        out.push(*x);
        true
    });
    out
}

/// The point of the checks: a front tyre stiffer than the rear one (an
/// understeering car), driven near its peak by the steer, from a state
/// off equilibrium.
const POINT: [f64; VARS] = [11.0, 1.4, 0.95, 12.5, 1.35, 1.05, 0.01, -0.05];

#[test]
fn rk4_dual_derivatives_are_those_of_the_discrete_replay() {
    let dual = dual_replay(&POINT);
    let plain = plain_replay(&POINT);
    let mut worst: f64 = 0.0;
    for k in 0..VARS {
        // Fourth-order central differences of the plain replay, with a
        // step of 1e-4 of the variable (1e-4 rad for the initial state).
        let h = 1e-4 * POINT[k].abs().max(1.0);
        let shifted = |m: f64| {
            let mut v = POINT;
            v[k] += m * h;
            plain_replay(&v)
        };
        let (p1, m1, p2, m2) = (shifted(1.0), shifted(-1.0), shifted(2.0), shifted(-2.0));
        for state in 0..2 {
            let column: Vec<f64> = dual
                .iter()
                .map(|x| x[state].eps.unwrap_generic(Const::<VARS>, U1)[k])
                .collect();
            let largest = column.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            assert!(largest > 0.0, "variable {k} moves state {state}");
            for (i, d) in column.iter().enumerate() {
                let central = (8.0 * (p1[i][state] - m1[i][state]) - (p2[i][state] - m2[i][state]))
                    / (12.0 * h);
                // Relative to the derivative, or to a thousandth of its
                // largest where the trajectory crosses zero.
                let e = (d - central).abs() / d.abs().max(1e-3 * largest);
                assert!(
                    e < 1e-6,
                    "variable {k}, state {state}, step {i}: {d} vs {central}"
                );
                worst = worst.max(e);
            }
        }
    }
    // The values are the plain replay's to rounding.
    for (d, p) in dual.iter().zip(&plain) {
        for s in 0..2 {
            assert!(
                (d[s].re - p[s]).abs() <= 1e-12 * (1.0 + p[s].abs()),
                "{} {}",
                d[s].re,
                p[s]
            );
        }
    }
    eprintln!("rk4 sensitivities: largest relative error {worst:.1e}");
}
