//! The scalars the crate's models are written in: a plain `f64` for every
//! job, or a forward-mode dual number of the `num-dual` crate
//! (`DualSVec64<N>`, fixed size, no allocation; `Dual64`) whose derivative
//! part carries the derivatives of every quantity with respect to the
//! parameters a fit varies. In `f64` the arithmetic is the models' own,
//! operation for operation; in duals the value part is the same and the
//! derivative part is exact to rounding (forward-mode automatic
//! differentiation; Griewank & Walther, *Evaluating Derivatives*, 2nd ed.,
//! 2008, ch. 3).
//!
//! Directions of a dual may be reserved for implicit solves (the vehicle's
//! load-transfer loop, a compliant axle's slip angle): a solve runs in
//! plain numbers, then one evaluation in duals at its root, with the
//! solved variable seeded in its own direction, gives both the partial
//! derivatives and the slope, and [`Scalar::implicit`] /
//! [`Scalar::eliminate`] turn them into the root's total derivatives (the
//! implicit-function theorem), not a derivative of the iterations.

use nalgebra::{Const, U1};
use num_dual::{Derivative, Dual64, DualNum, DualSVec64};

/// A scalar the model can be evaluated in.
pub trait Scalar: DualNum<f64> + Copy + Send + Sync {
    /// Whether the scalar is a plain number (no derivative part at all):
    /// the model then takes its plain path, bit for bit.
    const PLAIN: bool;

    /// Whether this value carries no derivative (a constant).
    fn is_constant(&self) -> bool;

    /// The derivative with respect to direction `k` (0 for a plain number).
    fn part(&self, k: usize) -> f64;

    /// A variable of value `re` seeded in direction `k` (a plain number:
    /// `re`).
    fn variable(re: f64, k: usize) -> Self;

    /// This value with its dependence on direction `k` replaced by the
    /// dependence of `x` on the other directions (`x`'s own part in `k`
    /// ignored): the chain rule once `k`'s variable is known to be `x`.
    fn eliminate(self, k: usize, x: Self) -> Self;

    /// The root of `g(v) = 0` in variable `v` (seeded in direction `k`,
    /// value `v.re()`), given `g` evaluated at `v`: value `v.re()`,
    /// derivatives `−(∂g/∂θ)/(∂g/∂v)` (the implicit-function theorem).
    fn implicit(v: Self, g: Self, k: usize) -> Self {
        if Self::PLAIN {
            return v;
        }
        let slope = g.part(k);
        let partial = g.eliminate(k, Self::from(0.0)) - g.re();
        Self::from(v.re()) - partial / slope
    }
}

impl Scalar for f64 {
    const PLAIN: bool = true;
    fn is_constant(&self) -> bool {
        true
    }
    fn part(&self, _k: usize) -> f64 {
        0.0
    }
    fn variable(re: f64, _k: usize) -> Self {
        re
    }
    fn eliminate(self, _k: usize, _x: Self) -> Self {
        self
    }
}

impl Scalar for Dual64 {
    const PLAIN: bool = false;
    fn is_constant(&self) -> bool {
        self.eps == 0.0
    }
    fn part(&self, k: usize) -> f64 {
        if k == 0 {
            self.eps
        } else {
            0.0
        }
    }
    fn variable(re: f64, k: usize) -> Self {
        Dual64::new(re, if k == 0 { 1.0 } else { 0.0 })
    }
    fn eliminate(self, k: usize, x: Self) -> Self {
        if k == 0 {
            Dual64::new(self.re, self.eps * x.eps)
        } else {
            self
        }
    }
}

impl<const N: usize> Scalar for DualSVec64<N> {
    const PLAIN: bool = false;
    fn is_constant(&self) -> bool {
        self.eps == Derivative::none()
    }
    fn part(&self, k: usize) -> f64 {
        if self.is_constant() || k >= N {
            0.0
        } else {
            self.eps.unwrap_generic(Const::<N>, U1)[k]
        }
    }
    fn variable(re: f64, k: usize) -> Self {
        DualSVec64::new(re, Derivative::derivative_generic(Const::<N>, U1, k))
    }
    fn eliminate(self, k: usize, x: Self) -> Self {
        let dk = self.part(k);
        if dk == 0.0 {
            return self;
        }
        let mut eps = self.eps.unwrap_generic(Const::<N>, U1);
        eps[k] = 0.0;
        if !x.is_constant() {
            let mut xe = x.eps.unwrap_generic(Const::<N>, U1);
            xe[k] = 0.0;
            eps += xe * dk;
        }
        DualSVec64::new(self.re, Derivative::some(eps))
    }
}

/// Whether `x` is exactly zero and constant: an effect that is off and
/// not being differentiated, whose terms a model may skip.
pub fn off<T: Scalar>(x: T) -> bool {
    x.re() == 0.0 && x.is_constant()
}
