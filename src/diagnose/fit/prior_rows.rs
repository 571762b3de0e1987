//! The rows a prior on the axle characteristics appends to a fit's scaled
//! data residuals ([`PriorRows`]): `(ln x − ln centre)/σ` for each axle's
//! cornering coefficient and for the peak friction, on the axle shares of
//! the vector ([`crate::diagnose::model::axles`]). A held peak friction is
//! a row of width [`HELD_WIDTH`]. What the prior is and when the friction
//! is held: `crate::diagnose::campaign::prior`, `crate::diagnose::base::prior`.
//! Units: dimensionless rows.

use crate::diagnose::campaign::prior::AxlePrior;
use crate::diagnose::model::axles::{coefficient, friction, D_REF};
use nalgebra::DMatrix;

/// Width (standard deviation of `ln D`) of the row that holds the peak
/// friction: a hold, not a preference (a 1 % move of D adds 5,000 to the
/// cost).
pub const HELD_WIDTH: f64 = 1e-4;

/// The prior's rows appended to a fit's data residuals: one per axle
/// coefficient and one for the peak friction (the hold when it is held),
/// on the axle shares at `offset` of the parameter vector.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PriorRows {
    /// Where the shares `[s_f, s_r, t]` are in the vector.
    pub offset: usize,
    /// `ln` of the centres: k front, k rear, D.
    centres: [f64; 3],
    /// Standard deviations of `ln k`, `ln k`, `ln D`.
    sigmas: [f64; 3],
    /// What the rows of the prior (not a hold) are multiplied by: the
    /// tempering of the data ([`PriorRows::tempered`]).
    weight: f64,
}

impl PriorRows {
    /// Rows appended.
    pub const ROWS: usize = 3;

    /// The rows of `prior` on shares at `offset`, the peak friction
    /// `held` at a value (a row of width [`HELD_WIDTH`]) or, for `None`,
    /// fitted against the prior.
    pub fn new(prior: &AxlePrior, held: Option<f64>, offset: usize) -> Self {
        let k = AxlePrior::centre(prior.cornering).ln();
        let s = AxlePrior::sigma_ln(prior.cornering);
        let (d, width) = match held {
            Some(v) => (v, HELD_WIDTH),
            None => (
                AxlePrior::centre(prior.friction),
                AxlePrior::sigma_ln(prior.friction),
            ),
        };
        Self {
            offset,
            centres: [k, k, d.ln()],
            sigmas: [s, s, width],
            weight: 1.0,
        }
    }

    /// The same rows weighed against data whose residuals count as fewer,
    /// noisier samples than their rows ([`Tempering`]): the prior's rows
    /// multiplied by its `prior_weight`. A hold stays a hold, as narrow
    /// as it was.
    ///
    /// [`Tempering`]: crate::diagnose::fit::tempering::Tempering
    pub fn tempered(self, prior_weight: f64) -> Self {
        Self {
            weight: prior_weight.max(1.0),
            ..self
        }
    }

    /// What the prior's rows (not a hold) are multiplied by.
    pub fn weight(&self) -> f64 {
        self.weight
    }

    /// Whether row `i` is a hold (only the peak friction's can be).
    fn holds(&self, i: usize) -> bool {
        self.sigmas[i] == HELD_WIDTH
    }

    /// The multiplier of row `i`.
    fn row_weight(&self, i: usize) -> f64 {
        if self.holds(i) {
            1.0
        } else {
            self.weight
        }
    }

    /// The friction share the axle grid starts from: the held value, or
    /// `free` (a friction that does not saturate) when it is fitted.
    pub fn grid_friction(&self, free: f64) -> f64 {
        if self.holds(2) {
            let d = self.centres[2].exp();
            d / (d + D_REF)
        } else {
            free
        }
    }

    /// `ln k` or `ln D` of share `x` of characteristic `i`, and its
    /// derivative in the share.
    fn log_of(i: usize, x: f64) -> (f64, f64) {
        let v = if i < 2 { coefficient(x) } else { friction(x) };
        // ln(ref·x/(1 − x)): d/dx = 1/x + 1/(1 − x).
        (v.ln(), 1.0 / x + 1.0 / (1.0 - x))
    }

    /// Writes the rows of vector `p` into `out` (`ROWS` long).
    pub fn write(&self, p: &[f64], out: &mut [f64]) {
        for (i, o) in out.iter_mut().enumerate().take(Self::ROWS) {
            let (l, _) = Self::log_of(i, p[self.offset + i]);
            *o = self.row_weight(i) * (l - self.centres[i]) / self.sigmas[i];
        }
    }

    /// The rows' Jacobian in the `n` parameters at `p` (`ROWS × n`).
    pub fn jacobian(&self, p: &[f64], n: usize) -> DMatrix<f64> {
        let mut j = DMatrix::zeros(Self::ROWS, n);
        for i in 0..Self::ROWS {
            let (_, d) = Self::log_of(i, p[self.offset + i]);
            j[(i, self.offset + i)] = self.row_weight(i) * d / self.sigmas[i];
        }
        j
    }
}
