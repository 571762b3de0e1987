//! The phase plane of the autonomous (β, r) system at one condition
//! (constant steer, friction and speed): trajectories by RK4, the vector
//! field, and the separatrices of every saddle (its stable manifold
//! integrated backward, its unstable one forward, started along the
//! Jacobian's eigenvectors; Strogatz, *Nonlinear Dynamics and Chaos*, 1994,
//! §6.1–6.4). The figures drawn from them are the equilibria job's.
//!
//! Orbits are traced in arc length (the field divided by its length in
//! box-scaled units: the same curves, at an even pace), so that a curve
//! leaving a saddle, where time-stepping crawls, is drawn all the way: until
//! it leaves the box, comes within [`NODE_RADIUS`] of an equilibrium, or has
//! run [`MAX_LENGTH`] box half-widths (a closed orbit).
//! Units: rad, rad/s, s; ISO signs.

use super::stability::{self, Kind};
use super::{residual, Condition, Equilibrium, SearchBox};
use crate::sim::ode::{self, OdeSystem};
use crate::vehicle::VehicleModel;

/// How near an equilibrium (in box half-widths) an orbit ends on it.
pub const NODE_RADIUS: f64 = 0.015;
/// The longest orbit traced, in box half-widths of arc length.
pub const MAX_LENGTH: f64 = 16.0;

/// The (β, r) system reparameterised by arc length `s` in box-scaled units:
/// dx/ds = ±f/‖f‖ with ‖·‖ taken in units of the box.
struct ArcLength<'a> {
    model: &'a VehicleModel,
    condition: &'a Condition,
    scale: [f64; 2],
    /// +1 along the flow, −1 against it.
    direction: f64,
}

impl OdeSystem<2> for ArcLength<'_> {
    fn derivatives(&mut self, _s: f64, x: &[f64; 2]) -> [f64; 2] {
        let f = residual(self.model, self.condition, *x);
        let n = (f[0] / self.scale[0]).hypot(f[1] / self.scale[1]);
        if !n.is_finite() || n == 0.0 {
            return [0.0, 0.0];
        }
        [self.direction * f[0] / n, self.direction * f[1] / n]
    }
}

/// The orbit of the autonomous (β, r) system through `x0`, along the flow
/// (`direction` +1) or against it (−1), by RK4 in arc length with steps of
/// `step` box half-widths: until it leaves the box, comes within
/// [`NODE_RADIUS`] of one of `ends`, or has run [`MAX_LENGTH`].
pub(crate) fn orbit(
    model: &VehicleModel,
    c: &Condition,
    bx: &SearchBox,
    x0: [f64; 2],
    direction: f64,
    step: f64,
    ends: &[[f64; 2]],
) -> Vec<[f64; 2]> {
    let scale = bx.scale();
    let mut sys = ArcLength {
        model,
        condition: c,
        scale,
        direction,
    };
    let near = |x: &[f64; 2], e: &[f64; 2]| {
        ((x[0] - e[0]) / scale[0]).hypot((x[1] - e[1]) / scale[1]) < NODE_RADIUS
    };
    let steps = (MAX_LENGTH / step).ceil() as usize;
    let mut out = Vec::with_capacity(steps + 1);
    ode::rk4(&mut sys, 0.0, step, steps, x0, |_, i, _, x| {
        let inside = i == 0 || (x[0].is_finite() && bx.contains(*x));
        if inside {
            out.push(*x);
        }
        // Stops on reaching an equilibrium (kept as the last point) or at a
        // standstill of the field.
        let moved = out.len() < 2 || out[out.len() - 2] != *x;
        inside && moved && !(i > 0 && ends.iter().any(|e| near(x, e)))
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
/// eigenvector and traced by [`orbit`] until it leaves the box or reaches
/// another equilibrium: per saddle, the stable branches then the unstable
/// ones, the −1 side first.
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
        let others: Vec<[f64; 2]> = eqs
            .iter()
            .map(|o| [o.beta, o.yaw_rate])
            .filter(|o| *o != x)
            .collect();
        let j = stability::jacobian(model, c, x);
        // The plane's own eigenvalues: with a tyre lag the equilibrium's
        // are the full state's, whose leading two need not be these.
        let ev = stability::from_jacobian(j).eigenvalues;
        let mut branches = Vec::with_capacity(4);
        for (lambda, dir, manifold) in [
            (ev[1].0, -1.0, Manifold::Stable),
            (ev[0].0, 1.0, Manifold::Unstable),
        ] {
            let v = eigenvector(j, lambda, scale);
            for side in [-1.0, 1.0] {
                // `v` is a physical direction of unit length in box units.
                let x0 = [x[0] + side * 1e-4 * v[0], x[1] + side * 1e-4 * v[1]];
                branches.push(Separatrix {
                    manifold,
                    side,
                    points: orbit(model, c, bx, x0, dir, 0.004, &others),
                });
            }
        }
        out.push(branches);
    }
    out
}

/// Length of an arrowhead along the flow, in box half-widths.
pub const ARROW_LENGTH: f64 = 0.08;

/// An arrowhead on an orbit: its tip and two barbs, (β, r) in rad, rad/s;
/// the tip lies on the orbit, the barbs behind it, so that it points the
/// way the orbit runs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arrowhead {
    /// The tip, on the orbit.
    pub tip: [f64; 2],
    /// The two barbs, [`ARROW_LENGTH`] behind the tip and half as far to
    /// either side.
    pub barbs: [[f64; 2]; 2],
}

/// The arrowhead at the middle of an orbit traced along the flow
/// ([`orbit`] with `direction` +1: the direction of increasing time), or
/// `None` for an orbit too short to carry one (a start next to a node).
pub(crate) fn arrowhead(points: &[[f64; 2]], bx: &SearchBox) -> Option<Arrowhead> {
    if points.len() < 8 {
        return None;
    }
    let s = bx.scale();
    let i = points.len() / 2;
    let (a, b) = (points[i - 1], points[i]);
    let d = [(b[0] - a[0]) / s[0], (b[1] - a[1]) / s[1]];
    let n = d[0].hypot(d[1]);
    if n.is_nan() || n <= 0.0 {
        return None;
    }
    let (u, v) = ([d[0] / n, d[1] / n], [-d[1] / n, d[0] / n]);
    let barb = |side: f64| [0, 1].map(|k| b[k] + s[k] * ARROW_LENGTH * (-u[k] + 0.5 * side * v[k]));
    Some(Arrowhead {
        tip: b,
        barbs: [barb(1.0), barb(-1.0)],
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::equilibria::exact;
    use crate::equilibria::tests::equilibria_model;

    /// How far inside the box a point lies: 0 on its edge, 1 at its centre.
    fn depth(bx: &SearchBox, x: [f64; 2]) -> f64 {
        1.0 - (x[0].abs() / bx.beta_max).max(x[1].abs() / bx.yaw_rate_max)
    }

    /// Every trajectory of the portrait's grid of starts carries its
    /// arrowhead pointing the way the field flows there: from the barbs'
    /// midpoint to the tip along +f (increasing time), never against it.
    #[test]
    fn a_trajectorys_arrowhead_points_along_the_flow() {
        let m = equilibria_model(false);
        let c = Condition {
            steer: 0.05,
            friction: 0.8,
            speed: 70.0 / 3.6,
        };
        let bx = SearchBox {
            beta_max: 0.6,
            yaw_rate_max: 2.0 * 0.968,
        };
        let ends: Vec<[f64; 2]> = exact::solve(&m, &c)
            .iter()
            .map(|e| [e.beta, e.yaw_rate])
            .collect();
        let s = bx.scale();
        let mut drawn = 0;
        for i in 0..7 {
            for k in 0..7 {
                let o = orbit(&m, &c, &bx, grid_point(&bx, 7, i, k), 1.0, 0.01, &ends);
                let Some(a) = arrowhead(&o, &bx) else {
                    continue;
                };
                drawn += 1;
                assert!(o.contains(&a.tip));
                let back = [0, 1].map(|j| 0.5 * (a.barbs[0][j] + a.barbs[1][j]));
                let along = [0, 1].map(|j| (a.tip[j] - back[j]) / s[j]);
                let f = residual(&m, &c, a.tip);
                let fs = [f[0] / s[0], f[1] / s[1]];
                let cos = (along[0] * fs[0] + along[1] * fs[1])
                    / (along[0].hypot(along[1]) * fs[0].hypot(fs[1]));
                assert!(cos > 0.99, "arrow {a:?} against the field {f:?}: cos {cos}");
                let len = along[0].hypot(along[1]);
                assert!((len - ARROW_LENGTH).abs() < 1e-9, "{len}");
            }
        }
        assert!(drawn >= 40, "{drawn} of 49 trajectories carry an arrowhead");
    }

    #[test]
    fn a_saddles_manifolds_run_to_the_edge_of_the_box_or_to_a_node() {
        // Li, Jia & Zhao's vehicle straight ahead at 70 km/h: a stable node
        // at the origin between two spin saddles.
        let m = equilibria_model(false);
        let c = Condition {
            steer: 0.0,
            friction: 0.8,
            speed: 70.0 / 3.6,
        };
        let bx = SearchBox {
            beta_max: 0.6,
            yaw_rate_max: 0.968,
        };
        let eqs = exact::solve(&m, &c);
        let node = eqs
            .iter()
            .find(|e| e.stability.kind.is_stable())
            .map(|e| [e.beta, e.yaw_rate])
            .expect("the straight-running node");
        let seps = separatrices(&m, &c, &bx, &eqs);
        assert_eq!(seps.len(), 2, "two saddles");
        for branches in &seps {
            for b in branches {
                let end = *b.points.last().unwrap();
                let at_node = ((end[0] - node[0]) / bx.beta_max)
                    .hypot((end[1] - node[1]) / bx.yaw_rate_max)
                    < NODE_RADIUS;
                match b.manifold {
                    // The separatrix comes in from outside the box.
                    Manifold::Stable => assert!(depth(&bx, end) < 0.01, "{b:?}"),
                    // The unstable manifold leaves for the node or the edge.
                    Manifold::Unstable => assert!(at_node || depth(&bx, end) < 0.01, "{end:?}"),
                }
            }
            // One side of the unstable manifold falls into the node.
            assert!(branches.iter().any(|b| {
                let end = *b.points.last().unwrap();
                b.manifold == Manifold::Unstable
                    && ((end[0] - node[0]) / bx.beta_max)
                        .hypot((end[1] - node[1]) / bx.yaw_rate_max)
                        < NODE_RADIUS
            }));
        }
        // A separatrix is an orbit of the field, from its first step (started
        // along the eigenvector, not askew): the field at its points is
        // tangent to the curve.
        let b = &seps[0][0];
        for w in b.points.windows(2).step_by(25) {
            let f = residual(&m, &c, w[0]);
            let d = [w[1][0] - w[0][0], w[1][1] - w[0][1]];
            let s = bx.scale();
            let cross = (f[0] / s[0]) * (d[1] / s[1]) - (f[1] / s[1]) * (d[0] / s[0]);
            let norm = (f[0] / s[0]).hypot(f[1] / s[1]) * (d[0] / s[0]).hypot(d[1] / s[1]);
            assert!(cross.abs() < 0.01 * norm, "{w:?}");
        }
    }
}
