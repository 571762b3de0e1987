//! Stability of an equilibrium of the model with a tyre lag: the state is
//! (β, r, αf, αr), the lagged slip angles following their kinematic values
//! through `α̇ = (u/σ)·(α_kin − α)`. The equilibrium is the (β, r) model's
//! (the lag states sit at the kinematic slip angles), its stability is not:
//! at low speed the lag's rate u/σ is slow against the axles' and the
//! delayed forces can turn a stable node into an unstable focus (Pacejka,
//! *Tyre and Vehicle Dynamics*, §7.1). The eigenvalues are those of the 4×4
//! Jacobian of the full right-hand side, exact in dual numbers where the
//! tyres have a generic force, else by central differences.
//!
//! det J₄ = (u/σ)²·det J₂ (the Schur complement of the lag block), so an
//! equilibrium's index, and with it the saddles and the winding
//! certificate, are the (β, r) model's. Body roll does not enter: the sweep
//! refuses roll steer and roll camber, without which roll does not feed
//! back into (β, r) and its mode (always damped) is decoupled.

use super::stability::{jacobian_scale, Kind, Stability};
use super::Condition;
use crate::scalar::Scalar;
use crate::vehicle::wheels::ParamTyres;
use crate::vehicle::{LoadSolve, LoadTransferSeed, State, VehicleModel};
use nalgebra::Matrix4;
use num_dual::DualSVec64;

/// The states: β, r, lagged front and rear slip angle.
const N: usize = 4;

/// The full state at the equilibrium (β, r) = `x`: the lag states at the
/// kinematic slip angles, roll at its steady value.
fn full_state(model: &VehicleModel, c: &Condition, x: [f64; 2]) -> [f64; 6] {
    let s = State {
        beta: x[0],
        yaw_rate: x[1],
    };
    model.quasi_static_state(&s, &c.inputs())
}

/// Jacobian of (β̇, ṙ, α̇f, α̇r) with respect to (β, r, αf, αr) at the
/// equilibrium `x`: exact where the tyres have a generic force, else by
/// central differences.
pub(crate) fn jacobian(model: &VehicleModel, c: &Condition, x: [f64; 2]) -> [[f64; N]; N] {
    exact_jacobian(model, c, x).unwrap_or_else(|| difference_jacobian(model, c, x))
}

/// The exact 4×4 Jacobian, None when a tyre has no generic force.
pub(crate) fn exact_jacobian(
    model: &VehicleModel,
    c: &Condition,
    x: [f64; 2],
) -> Option<[[f64; N]; N]> {
    // The four states in directions 0–3; 4 and 5 the implicit solves'.
    type D = DualSVec64<6>;
    let tyres = ParamTyres::<D>::constant(&model.front, &model.rear)?;
    let inp = c.inputs();
    let sc = model.scalars_of(model.options.effects.lift::<D>(), inp.friction, [4, 5]);
    let q = full_state(model, c, x);
    let full = [
        D::variable(q[0], 0),
        D::variable(q[1], 1),
        D::variable(q[2], 2),
        D::variable(q[3], 3),
        D::from(q[4]),
        D::from(q[5]),
    ];
    let mut seed = LoadTransferSeed {
        ay: [c.speed * x[1] + model.bank_acceleration(); 3],
        slope: 1.0,
    };
    let solve = LoadSolve::Solved(&mut seed, 1e-13);
    let dx = model
        .rates_of(&sc, &tyres, &full, &inp, D::from(inp.steer), solve)
        .dx;
    Some(std::array::from_fn(|i| {
        std::array::from_fn(|k| dx[i].part(k))
    }))
}

/// The 4×4 Jacobian by central differences (step 1e-7 scaled).
pub(crate) fn difference_jacobian(
    model: &VehicleModel,
    c: &Condition,
    x: [f64; 2],
) -> [[f64; N]; N] {
    let q = full_state(model, c, x);
    let inp = c.inputs();
    let rates = |q: [f64; 6]| {
        let mut seed = LoadTransferSeed {
            ay: [c.speed * x[1] + model.bank_acceleration(); 3],
            slope: 1.0,
        };
        model.rates(&q, &inp, &mut seed, 1e-13).0
    };
    let mut j = [[0.0; N]; N];
    for k in 0..N {
        let h = 1e-7 * q[k].abs().max(0.01);
        let (mut qp, mut qm) = (q, q);
        qp[k] += h;
        qm[k] -= h;
        let (fp, fm) = (rates(qp), rates(qm));
        for (i, row) in j.iter_mut().enumerate() {
            row[k] = (fp[i] - fm[i]) / (2.0 * h);
        }
    }
    j
}

/// Classifies a 4×4 Jacobian by the number of eigenvalues in the right
/// half-plane, which generalises the 2×2 kinds: none, stable; an odd
/// number (det J < 0, index −1), a saddle; an even number, unstable. Node
/// or focus by the leading eigenvalue (the largest real part), the one
/// that dominates the response: real, a node; complex, a focus. The
/// eigenvalues reported are the two leading ones; trace and determinant
/// are the 4×4 Jacobian's.
pub(crate) fn from_jacobian(j: [[f64; N]; N]) -> Stability {
    let m = Matrix4::from_fn(|i, k| j[i][k]);
    let mut ev: Vec<(f64, f64)> = m
        .complex_eigenvalues()
        .iter()
        .map(|z| (z.re, z.im))
        .collect();
    ev.sort_by(|a, b| b.0.total_cmp(&a.0).then(b.1.total_cmp(&a.1)));
    let scale = jacobian_scale(&j);
    let lead = ev[0];
    let focus = lead.1 != 0.0;
    let unstable = ev.iter().filter(|(re, _)| *re > 0.0).count();
    // Relative thresholds, as for the 2×2 Jacobian: a zero eigenvalue, or
    // a leading pair on the imaginary axis, is numerically a bifurcation.
    let smallest = ev
        .iter()
        .map(|(re, im)| re.hypot(*im))
        .fold(f64::INFINITY, f64::min);
    let kind = if smallest <= 1e-10 * scale || (focus && lead.0.abs() <= 1e-10 * scale) {
        Kind::Degenerate
    } else if unstable == 0 {
        if focus {
            Kind::StableFocus
        } else {
            Kind::StableNode
        }
    } else if unstable % 2 == 1 {
        Kind::Saddle
    } else if focus {
        Kind::UnstableFocus
    } else {
        Kind::UnstableNode
    };
    Stability {
        kind,
        eigenvalues: [ev[0], ev[1]],
        trace: (0..N).map(|i| j[i][i]).sum(),
        determinant: m.determinant(),
    }
}

/// Stability of the equilibrium at `x` in the model's full state: the
/// (β, r) Jacobian's ([`super::stability::classify`]), or with a tyre lag
/// the 4×4 Jacobian's of (β, r) and the lagged slip angles: the same
/// equilibrium, not the same stability.
pub(crate) fn classify(model: &VehicleModel, c: &Condition, x: [f64; 2]) -> Stability {
    if model.options.effects.lagged() {
        from_jacobian(jacobian(model, c, x))
    } else {
        super::stability::classify(model, c, x)
    }
}
