//! The phase plane of the autonomous (β, r) system at one condition
//! (constant steer, friction and speed): trajectories by RK4, the vector
//! field, and the separatrices of every saddle (its stable manifold
//! integrated backward, its unstable one forward, started along the
//! Jacobian's eigenvectors; Strogatz, *Nonlinear Dynamics and Chaos*, 1994,
//! §6.1–6.4). The figures drawn from them are the equilibria job's.
//! Units: rad, rad/s, s; ISO signs.

use super::stability::{self, Kind};
use super::{residual, Condition, Equilibrium, SearchBox};
use crate::sim::ode::{self, OdeSystem};
use crate::vehicle::VehicleModel;

/// The (β, r) system at one condition, autonomous (constant steer and
/// speed), as an ODE for the crate's integrator.
struct Autonomous<'a> {
    model: &'a VehicleModel,
    condition: &'a Condition,
}

impl OdeSystem<2> for Autonomous<'_> {
    fn derivatives(&mut self, _t: f64, x: &[f64; 2]) -> [f64; 2] {
        residual(self.model, self.condition, *x)
    }
}

/// RK4 trajectory of the autonomous (β, r) system from `x0`, `dt` signed
/// (negative integrates backward), stopping outside the box.
pub(crate) fn trajectory(
    model: &VehicleModel,
    c: &Condition,
    bx: &SearchBox,
    x0: [f64; 2],
    dt: f64,
    steps: usize,
) -> Vec<[f64; 2]> {
    let mut sys = Autonomous {
        model,
        condition: c,
    };
    let mut out = Vec::with_capacity(steps + 1);
    ode::rk4(&mut sys, 0.0, dt, steps, x0, |_, i, _, x| {
        let inside = i == 0 || (x[0].is_finite() && bx.contains(*x));
        if inside {
            out.push(*x);
        }
        inside
    });
    out
}

/// Eigenvector of a 2×2 matrix for a real eigenvalue λ, unit length in
/// box-scaled units.
fn eigenvector(j: [[f64; 2]; 2], lambda: f64, scale: [f64; 2]) -> [f64; 2] {
    let v = if (j[0][1]).abs() > 1e-14 {
        [j[0][1], lambda - j[0][0]]
    } else if (j[1][0]).abs() > 1e-14 {
        [lambda - j[1][1], j[1][0]]
    } else if (j[0][0] - lambda).abs() < (j[1][1] - lambda).abs() {
        [1.0, 0.0]
    } else {
        [0.0, 1.0]
    };
    let n = (v[0] / scale[0]).hypot(v[1] / scale[1]);
    [v[0] / n, v[1] / n]
}

/// The centre of cell (`i`, `k`) of an `n` × `n` grid over the box.
pub(crate) fn grid_point(bx: &SearchBox, n: usize, i: usize, k: usize) -> [f64; 2] {
    [
        -bx.beta_max + 2.0 * bx.beta_max * (i as f64 + 0.5) / n as f64,
        -bx.yaw_rate_max + 2.0 * bx.yaw_rate_max * (k as f64 + 0.5) / n as f64,
    ]
}

/// The vector field on an `n` × `n` grid over the box as arrows (start,
/// end) of length `0.7/n` in box-scaled units; points where the field is
/// zero or not finite are left out.
pub(crate) fn vector_field(
    model: &VehicleModel,
    c: &Condition,
    bx: &SearchBox,
    n: usize,
) -> Vec<[[f64; 2]; 2]> {
    let scale = bx.scale();
    let mut arrows = Vec::new();
    for i in 0..n {
        for k in 0..n {
            let x = grid_point(bx, n, i, k);
            let f = residual(model, c, x);
            let d = [f[0] / scale[0], f[1] / scale[1]];
            let len = d[0].hypot(d[1]);
            if !len.is_finite() || len == 0.0 {
                continue;
            }
            let s = 0.7 / n as f64;
            arrows.push([
                x,
                [
                    x[0] + s * d[0] / len * scale[0],
                    x[1] + s * d[1] / len * scale[1],
                ],
            ]);
        }
    }
    arrows
}

/// Which invariant manifold of a saddle a separatrix traces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Manifold {
    /// Trajectories that reach the saddle (integrated backward from it).
    Stable,
    /// Trajectories that leave it (integrated forward).
    Unstable,
}

/// One branch of a saddle's manifold.
#[derive(Debug, Clone, PartialEq)]
pub struct Separatrix {
    /// The manifold it belongs to.
    pub manifold: Manifold,
    /// The branch's side of the saddle along the eigenvector (−1 or +1).
    pub side: f64,
    /// Points of the branch, (β, r) in rad, rad/s, until it leaves the box.
    pub points: Vec<[f64; 2]>,
}

/// The stable (integrated backward) and unstable (forward) manifolds of
/// every saddle among `eqs`, each branch started 1e-4 of the box along its
/// eigenvector: per saddle, the stable branches then the unstable ones,
/// the −1 side first.
pub(crate) fn separatrices(
    model: &VehicleModel,
    c: &Condition,
    bx: &SearchBox,
    eqs: &[Equilibrium],
) -> Vec<Vec<Separatrix>> {
    let scale = bx.scale();
    let mut out = Vec::new();
    for e in eqs.iter().filter(|e| e.stability.kind == Kind::Saddle) {
        let x = [e.beta, e.yaw_rate];
        let j = stability::jacobian(model, c, x);
        let mut branches = Vec::with_capacity(4);
        for (lambda, dir, manifold) in [
            (e.stability.eigenvalues[1].0, -1.0, Manifold::Stable),
            (e.stability.eigenvalues[0].0, 1.0, Manifold::Unstable),
        ] {
            let v = eigenvector(j, lambda, scale);
            for side in [-1.0, 1.0] {
                let x0 = [
                    x[0] + side * 1e-4 * v[0] * scale[0],
                    x[1] + side * 1e-4 * v[1] * scale[1],
                ];
                branches.push(Separatrix {
                    manifold,
                    side,
                    points: trajectory(model, c, bx, x0, dir * 0.005, 2000),
                });
            }
        }
        out.push(branches);
    }
    out
}
