//! Local stability of an equilibrium from the eigenvalues of the 2×2
//! Jacobian ∂(β̇, ṙ)/∂(β, r) (with a tyre lag, of the 4×4 Jacobian of the
//! full state: the `lagged` module, which imports this one): exact from one
//! evaluation of the right-hand side in dual numbers (the model's effects
//! lifted into them, the state seeded) where the tyres have a generic
//! force, else central differences (step 1e-7 scaled).

use super::{residual, Condition};
use crate::report::stability::Class;
use crate::scalar::Scalar;
use crate::vehicle::wheels::ParamTyres;
use crate::vehicle::{LoadSolve, LoadTransferSeed, VehicleModel};
use num_dual::DualSVec64;
use serde::{Deserialize, Serialize};

/// Kind of equilibrium.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Kind {
    /// Real negative eigenvalues.
    StableNode,
    /// Complex eigenvalues with negative real part.
    StableFocus,
    /// Real eigenvalues of opposite sign.
    Saddle,
    /// Real positive eigenvalues.
    UnstableNode,
    /// Complex eigenvalues with positive real part.
    UnstableFocus,
    /// Zero trace with positive determinant, or a zero eigenvalue.
    Degenerate,
}

impl Kind {
    /// Whether small disturbances decay.
    pub(crate) fn is_stable(self) -> bool {
        matches!(self, Kind::StableNode | Kind::StableFocus)
    }
    /// The class it is drawn as (stable node or focus: stable; saddle;
    /// unstable node or focus, or degenerate: unstable).
    pub fn class(self) -> Class {
        match self {
            Kind::StableNode | Kind::StableFocus => Class::Stable,
            Kind::Saddle => Class::Saddle,
            Kind::UnstableNode | Kind::UnstableFocus | Kind::Degenerate => Class::Unstable,
        }
    }

    /// Short name used in CSV files.
    pub fn name(self) -> &'static str {
        match self {
            Kind::StableNode => "stable-node",
            Kind::StableFocus => "stable-focus",
            Kind::Saddle => "saddle",
            Kind::UnstableNode => "unstable-node",
            Kind::UnstableFocus => "unstable-focus",
            Kind::Degenerate => "degenerate",
        }
    }
}

/// Eigenvalues and classification.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Stability {
    /// Kind.
    pub kind: Kind,
    /// Eigenvalues (re, im), the one with the larger real part first (with
    /// a tyre lag: the two of the four with the largest real parts).
    pub eigenvalues: [(f64, f64); 2],
    /// Trace of the Jacobian, 1/s.
    pub trace: f64,
    /// Determinant of the Jacobian, 1/s² (1/s⁴ with a tyre lag; its sign,
    /// the index, is the same either way).
    pub determinant: f64,
}

/// Jacobian of (β̇, ṙ) with respect to (β, r): exact, from one evaluation
/// of the right-hand side in dual numbers ([`crate::scalar`], the
/// load-transfer loop differentiated at its root), where the tyres have a
/// generic force; else by central differences.
pub(crate) fn jacobian(model: &VehicleModel, c: &Condition, x: [f64; 2]) -> [[f64; 2]; 2] {
    exact_jacobian(model, c, x).unwrap_or_else(|| difference_jacobian(model, c, x))
}

/// The exact Jacobian, None when a tyre has no generic force.
pub(crate) fn exact_jacobian(
    model: &VehicleModel,
    c: &Condition,
    x: [f64; 2],
) -> Option<[[f64; 2]; 2]> {
    // β and r in directions 0 and 1; 2 and 3 the implicit solves'.
    type D = DualSVec64<4>;
    let tyres = ParamTyres::<D>::constant(&model.front, &model.rear)?;
    let inp = c.inputs();
    let sc = model.scalars_of(model.options.effects.lift::<D>(), inp.friction, [2, 3]);
    let (beta, r) = (D::variable(x[0], 0), D::variable(x[1], 1));
    let steer = D::from(inp.steer);
    let zero = D::from(0.0);
    let full = if model.options.effects.extra_states() {
        model.quasi_static_of(&sc, beta, r, inp.speed, steer)
    } else {
        [beta, r, zero, zero, zero, zero]
    };
    let mut seed = LoadTransferSeed {
        ay: [c.speed * x[1] + model.bank_acceleration(); 3],
        slope: 1.0,
    };
    let solve = LoadSolve::Solved(&mut seed, 1e-13);
    let dx = model.rates_of(&sc, &tyres, &full, &inp, steer, solve).dx;
    Some([
        [dx[0].part(0), dx[0].part(1)],
        [dx[1].part(0), dx[1].part(1)],
    ])
}

/// Jacobian of (β̇, ṙ) with respect to (β, r) by central differences.
pub(crate) fn difference_jacobian(
    model: &VehicleModel,
    c: &Condition,
    x: [f64; 2],
) -> [[f64; 2]; 2] {
    let mut j = [[0.0; 2]; 2];
    for k in 0..2 {
        let h = 1e-7 * x[k].abs().max(0.01);
        let (mut xp, mut xm) = (x, x);
        xp[k] += h;
        xm[k] -= h;
        let (fp, fm) = (residual(model, c, xp), residual(model, c, xm));
        for i in 0..2 {
            j[i][k] = (fp[i] - fm[i]) / (2.0 * h);
        }
    }
    j
}

/// The scale the relative thresholds of a Jacobian's classification
/// take: its largest |entry|, floored at 1e-300 so that a zero Jacobian
/// divides by no zero (2×2 here, 4×4 in `lagged.rs`).
pub(crate) fn jacobian_scale<const N: usize>(j: &[[f64; N]; N]) -> f64 {
    j.iter()
        .flatten()
        .map(|v| v.abs())
        .fold(0.0, f64::max)
        .max(1e-300)
}

/// Classifies a 2×2 Jacobian.
pub(crate) fn from_jacobian(j: [[f64; 2]; 2]) -> Stability {
    let tr = j[0][0] + j[1][1];
    let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    let disc = 0.25 * tr * tr - det;
    let eigenvalues = if disc >= 0.0 {
        let s = disc.sqrt();
        [(0.5 * tr + s, 0.0), (0.5 * tr - s, 0.0)]
    } else {
        let s = (-disc).sqrt();
        [(0.5 * tr, s), (0.5 * tr, -s)]
    };
    // Relative thresholds: a determinant or trace this close to zero is
    // numerically a bifurcation point.
    let scale = jacobian_scale(&j);
    let kind = if det.abs() <= 1e-10 * scale * scale {
        Kind::Degenerate
    } else if det < 0.0 {
        Kind::Saddle
    } else if tr.abs() <= 1e-10 * scale {
        Kind::Degenerate
    } else if disc >= 0.0 {
        if tr < 0.0 {
            Kind::StableNode
        } else {
            Kind::UnstableNode
        }
    } else if tr < 0.0 {
        Kind::StableFocus
    } else {
        Kind::UnstableFocus
    };
    Stability {
        kind,
        eigenvalues,
        trace: tr,
        determinant: det,
    }
}

/// Stability of the equilibrium at `x` in (β, r) alone, the lag states (if
/// any) held at the kinematic slip angles: the phase plane's, whose index
/// (sign det J) is the full model's (`lagged::classify` takes the
/// lag states into account).
pub(crate) fn classify(model: &VehicleModel, c: &Condition, x: [f64; 2]) -> Stability {
    from_jacobian(jacobian(model, c, x))
}
