//! Levenberg–Marquardt within bounds, for residuals that come from a
//! simulation (each evaluation a replay of measured runs).
//!
//! The crate's MINPACK solver knows no bounds; clamping parameters inside
//! the residuals leaves it a flat cost beyond the box (its trust region
//! shrinks hundreds of times), a penalty leaves it a kink, and the
//! `sin` transform of MINUIT leaves Gauss–Newton a vanishing Jacobian at
//! the bound. All three spend thousands of replays on a parameter whose
//! optimum lies on its bound. This is the projected form instead (an
//! active-set Levenberg–Marquardt, as in Kanzow, Yamashita & Fukushima
//! 2004, without their line search): at each iterate the parameters on a
//! bound whose gradient points out of the box are held, the damped
//! Gauss–Newton step `(J_FᵀJ_F + λ·diag(J_FᵀJ_F))·δ = −J_Fᵀ·r` is taken in
//! the others and projected back into the box, and λ falls after a step that
//! lowers the cost and rises until one does. The Jacobian is the
//! problem's ([`Residuals::jacobian`]; finite differences step into the box
//! at a bound). Each iteration costs a Jacobian (n residual evaluations by
//! differences) and one per trial step; the residuals at the iterate are
//! reused.

use super::local::{LocalResult, Residuals};
use nalgebra::{DMatrix, DVector};

/// Settings of [`BoundedLm`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundedLm {
    /// Largest number of Jacobians (iterations).
    pub iterations: usize,
    /// Converged when an accepted step lowers the cost by less than this
    /// share, or moves every parameter by less than this share of its
    /// range.
    pub tolerance: f64,
}

impl Default for BoundedLm {
    fn default() -> Self {
        Self {
            iterations: 100,
            tolerance: 1.5e-8,
        }
    }
}

/// Initial damping, relative to the diagonal of JᵀJ.
const LAMBDA0: f64 = 1e-3;
/// Trial steps per iteration before the iterate counts as optimal.
const TRIALS: usize = 12;

impl BoundedLm {
    /// Minimises ½·Σ r² from `p0` within `bounds` (lower, upper per
    /// parameter).
    pub(crate) fn minimize(
        &self,
        problem: &dyn Residuals,
        p0: &[f64],
        bounds: &[(f64, f64)],
    ) -> LocalResult {
        let n = p0.len();
        let clamp = |p: &mut [f64]| {
            for (x, (lo, hi)) in p.iter_mut().zip(bounds) {
                *x = x.clamp(*lo, *hi);
            }
        };
        let mut p = p0.to_vec();
        clamp(&mut p);
        let m = problem.count();
        let mut r = vec![0.0; m];
        problem.residuals(&p, &mut r);
        problem.keep_last();
        let mut cost = half_sum_of_squares(&r);
        let mut evaluations = 1;
        let mut converged = false;
        let mut lambda = LAMBDA0;
        let mut trial = vec![0.0; m];
        if n == 0 || !cost.is_finite() {
            return LocalResult {
                params: p,
                cost,
                evaluations,
                converged: n == 0,
            };
        }
        for _ in 0..self.iterations {
            let j = problem.jacobian(&p, &r, bounds);
            evaluations += problem.jacobian_evaluations(n);
            let model = ProjectedModel::new(&j, &r, &p, bounds);
            if model.stationary() {
                converged = true;
                break;
            }
            let mut accepted = None;
            for _ in 0..TRIALS {
                let Some((step, _)) = model.step(lambda) else {
                    lambda *= 4.0;
                    continue;
                };
                let mut q: Vec<f64> = p.iter().zip(&step).map(|(p, d)| p + d).collect();
                clamp(&mut q);
                // A trial is only taken below the cost: the problem may
                // stop replaying once it knows it is not.
                let below = problem.residuals_below(&q, &mut trial, cost);
                evaluations += 1;
                let c = if below {
                    half_sum_of_squares(&trial)
                } else {
                    f64::INFINITY
                };
                if c.is_finite() && c < cost {
                    problem.keep_last();
                    accepted = Some((q, c));
                    lambda = (lambda / 3.0).max(1e-12);
                    break;
                }
                lambda *= 4.0;
            }
            let Some((q, c)) = accepted else {
                // No damped step lowers the cost: optimal to the precision
                // of the residuals.
                converged = true;
                break;
            };
            let decrease = (cost - c) / cost.max(1e-300);
            let moved = q
                .iter()
                .zip(&p)
                .zip(bounds)
                .map(|((a, b), (lo, hi))| (a - b).abs() / (hi - lo).max(1e-300))
                .fold(0.0, f64::max);
            p = q;
            cost = c;
            std::mem::swap(&mut r, &mut trial);
            if decrease < self.tolerance || moved < self.tolerance {
                converged = true;
                break;
            }
        }
        LocalResult {
            params: p,
            cost,
            evaluations,
            converged,
        }
    }
}

/// The quadratic model of the cost at an iterate `p`,
/// `½|r|² + gᵀδ + ½δᵀAδ`: the parameters left free (not on a bound with the
/// gradient pointing out of the box) and the model over them. From a
/// Jacobian it is Gauss–Newton's (`A = JᵀJ`, `g = Jᵀr`); given a Hessian it
/// is Newton's.
pub struct ProjectedModel {
    free: Vec<usize>,
    n: usize,
    a: DMatrix<f64>,
    g: DVector<f64>,
    /// The damping's diagonal (that of JᵀJ: positive where `A` need not be).
    scale: DVector<f64>,
}

impl ProjectedModel {
    /// The Gauss–Newton model of Jacobian `j` and residuals `r` at `p`
    /// within `bounds`.
    pub fn new(j: &DMatrix<f64>, r: &[f64], p: &[f64], bounds: &[(f64, f64)]) -> Self {
        let g = j.transpose() * DVector::from_column_slice(r);
        let a = j.transpose() * j;
        let scale = a.diagonal();
        Self::newton(a, g, scale, p, bounds)
    }

    /// The model of Hessian `a` and gradient `g` at `p` within `bounds`,
    /// damped along `scale` (positive: the diagonal of JᵀJ).
    pub fn newton(
        a: DMatrix<f64>,
        g: DVector<f64>,
        scale: DVector<f64>,
        p: &[f64],
        bounds: &[(f64, f64)],
    ) -> Self {
        let n = p.len();
        let free: Vec<usize> = (0..n)
            .filter(|&i| {
                let (lo, hi) = bounds[i];
                !((p[i] <= lo && g[i] > 0.0) || (p[i] >= hi && g[i] < 0.0))
            })
            .collect();
        let a = a.select_rows(free.iter()).select_columns(free.iter());
        let g = DVector::from_iterator(free.len(), free.iter().map(|&i| g[i]));
        let scale = DVector::from_iterator(free.len(), free.iter().map(|&i| scale[i]));
        Self {
            free,
            n,
            a,
            g,
            scale,
        }
    }

    /// No free parameter can lower the cost to first order.
    pub(crate) fn stationary(&self) -> bool {
        self.free.is_empty() || self.g.iter().all(|&v| v == 0.0)
    }

    /// The step `(A_F + λ·diag(scale_F))·δ = −g_F` (zero for the held
    /// parameters; the scale floored at 1e-12 of its largest entry, which
    /// is also added, so that λ = 0 solves a singular Gauss–Newton system),
    /// and the decrease of the cost the model predicts for it. None when
    /// the damped system is not positive definite (a Newton model far from
    /// its minimum: more damping).
    pub fn step(&self, lambda: f64) -> Option<(Vec<f64>, f64)> {
        let largest = self.scale.max().max(1e-300);
        let mut damped = self.a.clone();
        for k in 0..self.free.len() {
            damped[(k, k)] += lambda * self.scale[k].max(1e-12 * largest) + 1e-12 * largest;
        }
        let d = damped.cholesky()?.solve(&self.g);
        let mut out = vec![0.0; self.n];
        for (k, &i) in self.free.iter().enumerate() {
            out[i] = -d[k];
        }
        let predicted = self.g.dot(&d) - 0.5 * d.dot(&(&self.a * &d));
        Some((out, predicted))
    }
}

fn half_sum_of_squares(r: &[f64]) -> f64 {
    0.5 * r.iter().map(|e| e * e).sum::<f64>()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::optim::local::tests::{decay, ExactDecay, Rosen};

    #[test]
    fn uses_the_problems_own_jacobian() {
        use std::sync::atomic::{AtomicUsize, Ordering};
        let exact = ExactDecay(decay(), AtomicUsize::new(0));
        let bounds = [(0.0, 5.0), (0.0, 0.65)];
        let r = BoundedLm::default().minimize(&exact, &[1.0, 0.2], &bounds);
        // The box holds the rate below its optimum: it ends on the bound.
        assert_eq!(r.params[1], 0.65, "{r:?}");
        // No column was differenced: every residual evaluation made is one
        // the method reports.
        assert_eq!(exact.1.load(Ordering::Relaxed), r.evaluations);
    }

    #[test]
    fn finds_an_interior_optimum() {
        let lm = BoundedLm::default();
        let r = lm.minimize(&Rosen, &[-1.2, 1.0], &[(-5.0, 5.0), (-5.0, 5.0)]);
        assert!(r.converged);
        assert!((r.params[0] - 1.0).abs() < 1e-6, "{:?}", r.params);
        assert!((r.params[1] - 1.0).abs() < 1e-6, "{:?}", r.params);
        // y = 2·exp(−0.7·t).
        let r = lm.minimize(&decay(), &[1.0, 0.2], &[(0.0, 10.0), (0.0, 10.0)]);
        assert!((r.params[0] - 2.0).abs() < 1e-7 && (r.params[1] - 0.7).abs() < 1e-7);
    }

    #[test]
    fn stops_on_a_bound_at_the_conditional_optimum_in_few_evaluations() {
        // b's optimum (0.7) lies beyond its upper bound 0.5: the answer is
        // b = 0.5 and the least-squares a for it, a = Σ y·e^(−bt) / Σ e^(−2bt).
        let d = decay();
        let bounds = [(0.0, 10.0), (0.0, 0.5)];
        let (num, den) = d.0.iter().zip(&d.1).fold((0.0, 0.0), |(n, m), (t, y)| {
            (n + y * (-0.5 * t).exp(), m + (-t).exp())
        });
        let r = BoundedLm::default().minimize(&d, &[1.0, 0.2], &bounds);
        assert!(r.converged);
        assert_eq!(r.params[1], 0.5);
        assert!((r.params[0] - num / den).abs() < 1e-6, "{:?}", r.params);
        assert!(r.evaluations < 60, "{} evaluations", r.evaluations);
        // Started on the bound, with the gradient pointing out: held there.
        let r = BoundedLm::default().minimize(&d, &[1.0, 0.5], &bounds);
        assert_eq!(r.params[1], 0.5);
        assert!((r.params[0] - num / den).abs() < 1e-6);
    }

    #[test]
    fn leaves_a_bound_whose_gradient_points_inside() {
        let r = BoundedLm::default().minimize(&decay(), &[1.0, 0.0], &[(0.0, 10.0), (0.0, 10.0)]);
        assert!((r.params[1] - 0.7).abs() < 1e-7, "{:?}", r.params);
    }
}
