//! The axle characteristics of a base identified from the runs
//! ([`crate::diagnose::base::identify`]): per axle a simplified Magic Formula (Li, Jia & Zhao,
//! `Fy = D·μ·Fz·sin(C·atan(B·α))`, C = 1.3) of cornering coefficient
//! `k = B·C·D` (1/rad) and one peak friction `D` shared by the axles,
//! parameterised by their shares `s = k/(k + k_ref)` and `t = D/(D + D_ref)`
//! in (0, 1); in plain numbers ([`axle_tyres`]) and in any scalar of
//! [`crate::scalar`] ([`axle_parameters`], for exact derivatives). Units:
//! SI, rad; k in 1/rad, D dimensionless.

use crate::scalar::Scalar;
use crate::tyre::{MagicSimple, Tyre};

/// Shape factor C of the axle characteristics.
pub const SHAPE: f64 = 1.3;
/// Cornering coefficient at the middle of its share, 1/rad: a car tyre's.
pub(crate) const K_REF: f64 = 20.0;
/// Peak friction at the middle of its share.
pub(crate) const D_REF: f64 = 1.0;

/// The fit's box of the shares (front coefficient, rear coefficient,
/// friction): just inside the physical limits 0 and 1, where the model
/// stays finite.
pub const AXLE_BOUNDS: [(f64, f64); 3] = [(0.02, 0.995), (0.02, 0.995), (0.1, 0.9)];

/// Cornering coefficient k (1/rad) of share `s`.
pub fn coefficient(s: f64) -> f64 {
    K_REF * s / (1.0 - s)
}

/// Peak friction D of share `t`.
pub fn friction(t: f64) -> f64 {
    D_REF * t / (1.0 - t)
}

/// The shares of coefficients `(k_f, k_r)` and friction `d`.
pub fn shares(k_f: f64, k_r: f64, d: f64) -> [f64; 3] {
    [k_f / (k_f + K_REF), k_r / (k_r + K_REF), d / (d + D_REF)]
}

/// The axle tyres of shares `p = [s_f, s_r, t]`.
pub fn axle_tyres(p: &[f64]) -> (Tyre, Tyre) {
    let d = friction(p[2]);
    let tyre = |s: f64| {
        Tyre::MagicSimple(MagicSimple {
            b: coefficient(s) / (SHAPE * d),
            c: SHAPE,
            d,
        })
    };
    (tyre(p[0]), tyre(p[1]))
}

/// The lateral parameters (B, C, D) of the front and rear axle
/// characteristics of shares `p = [s_f, s_r, t]`
/// ([`axle_tyres`]) in scalar `T`.
pub(crate) fn axle_parameters<T: Scalar>(p: &[T]) -> [Vec<T>; 2] {
    let one = T::from(1.0);
    let d = p[2] * D_REF / (one - p[2]);
    let b = |s: T| s * K_REF / (one - s) / (d * SHAPE);
    [
        vec![b(p[0]), T::from(SHAPE), d],
        vec![b(p[1]), T::from(SHAPE), d],
    ]
}
