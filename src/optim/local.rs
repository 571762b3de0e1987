//! Local least-squares polish: Levenberg–Marquardt (the `levenberg-marquardt`
//! crate, MINPACK's trust-region form with diagonal scaling) and Zhang & Li's (2017)
//! modified Gauss–Newton `x_{k+1} = x_k − (JᵀJ + λ_k·I)⁻¹·Jᵀ·e` with the
//! geometric schedule `λ_k = λ0·q^(k−1)` (0 < q < 1). Zhang & Li (2017) takes every
//! step; here a step that raises the cost is halved until it does not (up to
//! ten times), so the method cannot diverge. Jacobians are the problem's
//! own ([`Residuals::jacobian`]): forward differences with a relative step
//! of 1e-7 (checked against analytic ones in the tests), stepping into the
//! box at an upper bound when the problem has bounds (`bounded`), unless
//! the problem has exact derivatives.

use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt};
use nalgebra::{storage::Owned, DMatrix, DVector, Dyn};
use serde::{Deserialize, Serialize};

/// How a fit takes the Jacobian of its residuals (the polish's steps and
/// the standard errors).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Derivatives {
    /// Exact, in dual numbers, where the problem has them (the lateral
    /// force of a rig fit, a diagnosis's replays); differences elsewhere.
    #[default]
    Exact,
    /// Forward differences of the residuals everywhere.
    Differences,
}

/// A least-squares problem: residuals of a parameter vector.
pub trait Residuals: Sync {
    /// Number of residuals.
    fn count(&self) -> usize;
    /// Fills `out` (length `count()`) with the residuals at `p`.
    fn residuals(&self, p: &[f64], out: &mut [f64]);

    /// The Jacobian of the residuals at `p`, given the residuals `r0`
    /// there, within `bounds` (a column at an upper bound looks into the
    /// box). By default forward differences ([`inward_jacobian`], `n`
    /// residual evaluations); a problem with exact derivatives overrides
    /// it, and [`Residuals::jacobian_evaluations`] with it.
    fn jacobian(&self, p: &[f64], r0: &[f64], bounds: &[(f64, f64)]) -> DMatrix<f64> {
        inward_jacobian(self, p, r0, bounds)
    }

    /// What one [`Residuals::jacobian`] of `n` parameters costs, in
    /// residual evaluations (`n` for the differences): the fits report
    /// their work in these.
    fn jacobian_evaluations(&self, n: usize) -> usize {
        n
    }

    /// Whether [`Residuals::jacobian`] reads its `r0` (differences do; an
    /// exact Jacobian need not): where it does not, the polish does not
    /// evaluate the residuals again to pass them.
    fn jacobian_reads_residuals(&self) -> bool {
        true
    }

    /// ½·Σ e² at `p` (Zhang & Li's (2017) objective ε).
    fn cost(&self, p: &[f64]) -> f64 {
        let mut r = vec![0.0; self.count()];
        self.residuals(p, &mut r);
        0.5 * r.iter().map(|e| e * e).sum::<f64>()
    }

    /// The residuals at `p` for a caller that only uses them when their
    /// cost ½·Σ e² is below `bound` (a trial step, a search point): true
    /// with `out` filled as [`Residuals::residuals`] fills it, or false
    /// when that cost is certainly at or above `bound` (`out` then partly
    /// filled). A problem whose residuals are costly may stop as soon as it
    /// knows; by default every residual is evaluated (true).
    fn residuals_below(&self, p: &[f64], out: &mut [f64], bound: f64) -> bool {
        let _ = bound;
        self.residuals(p, out);
        true
    }

    /// [`Residuals::cost`] where it is below `bound`, else either it or
    /// infinity ([`Residuals::residuals_below`]): a comparison with
    /// `bound` decides as the exact cost would.
    fn cost_below(&self, p: &[f64], bound: f64) -> f64 {
        let mut r = vec![0.0; self.count()];
        if self.residuals_below(p, &mut r, bound) {
            0.5 * r.iter().map(|e| e * e).sum::<f64>()
        } else {
            f64::INFINITY
        }
    }

    /// Told that the point of the last [`Residuals::residuals`] (or
    /// [`Residuals::residuals_below`] that returned true) is one the caller
    /// will come back to (an accepted step, a search's best): a problem
    /// that caches its evaluations may keep it. By default nothing.
    fn keep_last(&self) {}
}

/// Forward-difference Jacobian at `p` given the residuals `r0` there
/// (relative step 1e-7; [`inward_jacobian`] without bounds).
#[cfg(test)]
pub(crate) fn jacobian<R: Residuals + ?Sized>(problem: &R, p: &[f64], r0: &[f64]) -> DMatrix<f64> {
    inward_jacobian(problem, p, r0, &unbounded(p.len()))
}

/// No bounds on `n` parameters.
fn unbounded(n: usize) -> Vec<(f64, f64)> {
    vec![(f64::NEG_INFINITY, f64::INFINITY); n]
}

/// Forward differences (relative step 1e-7) that step into the box at an
/// upper bound.
pub(crate) fn inward_jacobian<R: Residuals + ?Sized>(
    problem: &R,
    p: &[f64],
    r0: &[f64],
    bounds: &[(f64, f64)],
) -> DMatrix<f64> {
    let (m, n) = (r0.len(), p.len());
    let mut j = DMatrix::zeros(m, n);
    let mut x = p.to_vec();
    let mut r = vec![0.0; m];
    for k in 0..n {
        let mut h = 1e-7 * p[k].abs().max(1e-4);
        if p[k] + h > bounds[k].1 {
            h = -h;
        }
        x[k] = p[k] + h;
        problem.residuals(&x, &mut r);
        for i in 0..m {
            j[(i, k)] = (r[i] - r0[i]) / h;
        }
        x[k] = p[k];
    }
    j
}

/// The outcome of a local polish.
#[derive(Debug, Clone, PartialEq)]
pub struct LocalResult {
    /// Final parameters.
    pub params: Vec<f64>,
    /// ½·Σ e² there.
    pub cost: f64,
    /// Residual evaluations (Jacobian columns included).
    pub evaluations: usize,
    /// Whether the method stopped on its convergence test (not on its
    /// iteration limit or a failure).
    pub converged: bool,
}

struct Adapter<'a> {
    problem: &'a dyn Residuals,
    p: DVector<f64>,
}

impl LeastSquaresProblem<f64, Dyn, Dyn> for Adapter<'_> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, x: &DVector<f64>) {
        self.p.copy_from(x);
    }
    fn params(&self) -> DVector<f64> {
        self.p.clone()
    }
    fn residuals(&self) -> Option<DVector<f64>> {
        let mut r = vec![0.0; self.problem.count()];
        self.problem.residuals(self.p.as_slice(), &mut r);
        r.iter()
            .all(|v| v.is_finite())
            .then(|| DVector::from_vec(r))
    }
    fn jacobian(&self) -> Option<DMatrix<f64>> {
        // The crate gives no residuals with its call for the Jacobian.
        let mut r = Vec::new();
        if self.problem.jacobian_reads_residuals() {
            r.resize(self.problem.count(), 0.0);
            self.problem.residuals(self.p.as_slice(), &mut r);
        }
        let p = self.p.as_slice();
        let j = self.problem.jacobian(p, &r, &unbounded(p.len()));
        j.iter().all(|v| v.is_finite()).then_some(j)
    }
}

/// Levenberg–Marquardt from `p0`.
pub(crate) fn levenberg_marquardt(problem: &dyn Residuals, p0: &[f64]) -> LocalResult {
    levenberg_marquardt_within(problem, p0, 200)
}

/// Levenberg–Marquardt from `p0` with at most `patience`·(n + 1) residual
/// evaluations (not converged when it runs out).
pub(crate) fn levenberg_marquardt_within(
    problem: &dyn Residuals,
    p0: &[f64],
    patience: usize,
) -> LocalResult {
    let (adapter, report) = LevenbergMarquardt::new()
        .with_patience(patience)
        .minimize(Adapter {
            problem,
            p: DVector::from_column_slice(p0),
        });
    let params: Vec<f64> = adapter.p.iter().copied().collect();
    // The crate counts residual evaluations; each Jacobian costs n more.
    LocalResult {
        cost: problem.cost(&params),
        evaluations: report.number_of_evaluations * (1 + problem.jacobian_evaluations(p0.len())),
        // "No improvement possible" is convergence to machine precision
        // (a parameter pinned at a bound of a clamped problem ends so).
        converged: report.termination.was_successful()
            || matches!(
                report.termination,
                levenberg_marquardt::TerminationReason::NoImprovementPossible(_)
            ),
        params,
    }
}

/// Zhang & Li's (2017) modified Gauss–Newton settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GaussNewton {
    /// λ0 > 0, relative to the mean diagonal of JᵀJ.
    pub lambda0: f64,
    /// 0 < q < 1.
    pub q: f64,
    /// Iterations.
    pub iterations: usize,
}

impl Default for GaussNewton {
    fn default() -> Self {
        Self {
            lambda0: 1e-2,
            q: 0.5,
            iterations: 100,
        }
    }
}

impl GaussNewton {
    /// Runs from `p0`.
    pub(crate) fn minimize(&self, problem: &dyn Residuals, p0: &[f64]) -> LocalResult {
        let n = p0.len();
        let mut p = p0.to_vec();
        let mut r = vec![0.0; problem.count()];
        problem.residuals(&p, &mut r);
        let mut cost = 0.5 * r.iter().map(|e| e * e).sum::<f64>();
        let mut evaluations = 1;
        let mut converged = false;
        for k in 0..self.iterations {
            let j = problem.jacobian(&p, &r, &unbounded(n));
            evaluations += problem.jacobian_evaluations(n);
            let jtj = j.transpose() * &j;
            let g = j.transpose() * DVector::from_column_slice(&r);
            let scale = jtj.diagonal().mean().max(1e-300);
            let lambda = self.lambda0 * self.q.powi(k as i32) * scale;
            let a = &jtj + DMatrix::identity(n, n) * lambda;
            let Some(step) = a.lu().solve(&g) else { break };
            let mut t = 1.0;
            let mut improved = false;
            for _ in 0..10 {
                let trial: Vec<f64> = p.iter().zip(step.iter()).map(|(x, s)| x - t * s).collect();
                let mut rt = vec![0.0; r.len()];
                problem.residuals(&trial, &mut rt);
                evaluations += 1;
                let ct = 0.5 * rt.iter().map(|e| e * e).sum::<f64>();
                if ct.is_finite() && ct < cost {
                    let rel = (cost - ct) / cost.max(1e-300);
                    p = trial;
                    r = rt;
                    cost = ct;
                    improved = rel > 1e-15;
                    break;
                }
                t *= 0.5;
            }
            if !improved {
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

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// Rosenbrock as least squares: e = (10·(y − x²), 1 − x).
    pub(crate) struct Rosen;
    impl Residuals for Rosen {
        fn count(&self) -> usize {
            2
        }
        fn residuals(&self, p: &[f64], out: &mut [f64]) {
            out[0] = 10.0 * (p[1] - p[0] * p[0]);
            out[1] = 1.0 - p[0];
        }
    }

    /// Exponential decay fitted to exact data: known optimum (2, 0.7).
    pub(crate) struct Decay(pub(crate) Vec<f64>, pub(crate) Vec<f64>);
    impl Residuals for Decay {
        fn count(&self) -> usize {
            self.0.len()
        }
        fn residuals(&self, p: &[f64], out: &mut [f64]) {
            for (i, (t, y)) in self.0.iter().zip(&self.1).enumerate() {
                out[i] = p[0] * (-p[1] * t).exp() - y;
            }
        }
    }

    pub(crate) fn decay() -> Decay {
        let t: Vec<f64> = (0..30).map(|i| i as f64 * 0.2).collect();
        let y = t.iter().map(|t| 2.0 * (-0.7 * t).exp()).collect();
        Decay(t, y)
    }

    #[test]
    fn both_solve_rosenbrock() {
        let lm = levenberg_marquardt(&Rosen, &[-1.2, 1.0]);
        assert!(
            (lm.params[0] - 1.0).abs() < 1e-8 && (lm.params[1] - 1.0).abs() < 1e-8,
            "{lm:?}"
        );
        let gn = GaussNewton {
            iterations: 500,
            ..Default::default()
        }
        .minimize(&Rosen, &[-1.2, 1.0]);
        assert!(
            (gn.params[0] - 1.0).abs() < 1e-6 && (gn.params[1] - 1.0).abs() < 1e-6,
            "{gn:?}"
        );
    }

    #[test]
    fn both_recover_an_exponential() {
        for r in [
            levenberg_marquardt(&decay(), &[1.0, 0.2]),
            GaussNewton::default().minimize(&decay(), &[1.0, 0.2]),
        ] {
            assert!(
                (r.params[0] - 2.0).abs() < 1e-8 && (r.params[1] - 0.7).abs() < 1e-8,
                "{r:?}"
            );
            assert!(r.cost < 1e-16);
        }
    }

    /// The decay with its exact Jacobian, counting the residual
    /// evaluations the methods ask for.
    pub(crate) struct ExactDecay(pub(crate) Decay, pub(crate) std::sync::atomic::AtomicUsize);
    impl Residuals for ExactDecay {
        fn count(&self) -> usize {
            self.0.count()
        }
        fn residuals(&self, p: &[f64], out: &mut [f64]) {
            self.1.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            self.0.residuals(p, out);
        }
        fn jacobian(&self, p: &[f64], _r0: &[f64], _bounds: &[(f64, f64)]) -> DMatrix<f64> {
            let t = &self.0 .0;
            DMatrix::from_fn(t.len(), 2, |i, k| {
                let e = (-p[1] * t[i]).exp();
                if k == 0 {
                    e
                } else {
                    -p[0] * t[i] * e
                }
            })
        }
        fn jacobian_evaluations(&self, _n: usize) -> usize {
            0
        }
    }

    #[test]
    fn the_methods_use_a_problems_own_jacobian() {
        use std::sync::atomic::{AtomicUsize, Ordering};
        let exact = || ExactDecay(decay(), AtomicUsize::new(0));
        let asked = |e: &ExactDecay| e.1.load(Ordering::Relaxed);
        let e = exact();
        let gn = GaussNewton::default().minimize(&e, &[1.0, 0.2]);
        assert!(
            (gn.params[0] - 2.0).abs() < 1e-8 && (gn.params[1] - 0.7).abs() < 1e-8,
            "{gn:?}"
        );
        // No column was differenced: every residual evaluation made is one
        // the method reports.
        assert_eq!(asked(&e), gn.evaluations);
        // The crate's LM asks for the residuals again with each Jacobian
        // (the adapter has no other way to the base point): at most one
        // more per evaluation it counts, never a column's worth.
        let l = exact();
        let lm = levenberg_marquardt(&l, &[1.0, 0.2]);
        assert!(
            (lm.params[0] - 2.0).abs() < 1e-8 && (lm.params[1] - 0.7).abs() < 1e-8,
            "{lm:?}"
        );
        assert!(asked(&l) <= 2 * lm.evaluations + 1, "{} {lm:?}", asked(&l));
    }

    #[test]
    fn numeric_jacobian_matches_the_analytic_one() {
        let d = decay();
        let p = [1.7, 0.55];
        let mut r = vec![0.0; d.count()];
        d.residuals(&p, &mut r);
        let j = jacobian(&d, &p, &r);
        for (i, t) in d.0.iter().enumerate() {
            let e = (-p[1] * t).exp();
            assert!((j[(i, 0)] - e).abs() < 1e-6);
            assert!((j[(i, 1)] + p[0] * t * e).abs() < 1e-6 * (1.0 + p[0] * t));
        }
    }
}
