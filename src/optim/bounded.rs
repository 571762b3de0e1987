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
//!
//! Where a Jacobian costs many replays ([`Jacobians::Secant`]), an accepted
//! step updates the last one by Broyden's (1965) rank-one secant formula
//! instead, as in the secant Levenberg–Marquardt of Madsen, Nielsen &
//! Tingleff (2004, §3.4): the update is taken in the parameters scaled by
//! their ranges (the least change in that scaled norm that satisfies the
//! secant condition `J⁺·δ = r(p + δ) − r(p)`), and the Jacobian is
//! differenced afresh after [`SECANT_STEPS`] updates, after a step whose
//! decrease falls short of a quarter of the model's prediction, or after a
//! trial an updated model proposed fails. Convergence is only ever declared
//! on a freshly differenced Jacobian, so the optimum it stops at is the one
//! [`Jacobians::Every`] would accept; there a fresh model that predicts a
//! decrease below half the tolerance's is converged without its trial
//! (a replay), and the Jacobian at the optimum is handed back
//! ([`BoundedLm::minimize_linearised`]) for the caller's linearisation.

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
    /// How each iteration's Jacobian is had.
    pub jacobians: Jacobians,
}

/// How [`BoundedLm`] has the Jacobian of each iteration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Jacobians {
    /// The problem's at every iterate (its exact one, or `n` replays).
    #[default]
    Every,
    /// Broyden's secant update of the last one after an accepted step, the
    /// problem's afresh when that model no longer serves (for residuals
    /// whose Jacobian costs many replays).
    Secant,
}

impl Default for BoundedLm {
    fn default() -> Self {
        Self {
            iterations: 100,
            tolerance: 1.5e-8,
            jacobians: Jacobians::Every,
        }
    }
}

/// Secant updates in a row before the Jacobian is differenced afresh: the
/// update is exact along the steps taken only, and the steps of a
/// Levenberg–Marquardt tail turn little from one to the next.
pub const SECANT_STEPS: usize = 4;

/// A fitted value within this share of its parameter's range from a
/// physical limit stands on it: no data resolve the difference (a steer
/// lag of a few microseconds is no lag, a tyre's friction decay of 1e-17
/// none). `identify` and `diagnose` judge their fits by it.
pub const LIMIT_RESOLUTION: f64 = 1e-4;

/// Share of the decrease its model predicted below which a step taken on
/// an updated Jacobian calls for a fresh one.
const SECANT_RATIO: f64 = 0.25;

/// Share of the tolerance's decrease below which a fresh secant-mode model
/// is not tried ([`Jacobians::Secant`]). A trial it proposes would lower
/// the cost by its prediction times the ratio of the two, which on a fresh
/// Jacobian near an optimum stays within 0.4–1.3 (the diagnosis's fits on
/// the racing log, `campaigns/putnam.toml`): below half the tolerance's
/// decrease the step would be taken as small and the fit stop there, a
/// share of the tolerance away from where it stops now.
const PROMISE_SHARE: f64 = 0.5;

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
        self.minimize_linearised(problem, p0, bounds).0
    }

    /// [`BoundedLm::minimize`], and the Jacobian at the point it returns
    /// where the last one it differenced was taken there (None where it
    /// was not: a step was taken after it, or none was differenced). A
    /// caller that linearises the optimum reads it instead of differencing
    /// the same point again: the same replays, the same numbers.
    pub(crate) fn minimize_linearised(
        &self,
        problem: &dyn Residuals,
        p0: &[f64],
        bounds: &[(f64, f64)],
    ) -> (LocalResult, Option<DMatrix<f64>>) {
        self.minimize_settled(problem, p0, bounds, &|_, _| false)
    }

    /// [`BoundedLm::minimize_linearised`] that also stops, converged and
    /// without its trial, where a fresh Jacobian's model predicts a
    /// decrease `settled(predicted, cost)` accepts (a diagnosis's fold
    /// refit: the stop of its own model's steps).
    pub(crate) fn minimize_settled(
        &self,
        problem: &dyn Residuals,
        p0: &[f64],
        bounds: &[(f64, f64)],
        settled: &dyn Fn(f64, f64) -> bool,
    ) -> (LocalResult, Option<DMatrix<f64>>) {
        let n = p0.len();
        let mut it = Iterate::new(problem, p0, bounds, self.tolerance);
        let mut converged = false;
        let mut lambda = LAMBDA0;
        if n == 0 || !it.cost.is_finite() {
            return (it.result(n == 0), None);
        }
        // The Jacobian of the iterate: differenced (`Some(0)`), or updated
        // `k` times since (`Some(k)`); None: to be differenced.
        let mut j = DMatrix::zeros(0, 0);
        let mut updates: Option<usize> = None;
        let secant = self.jacobians == Jacobians::Secant;
        for _ in 0..self.iterations {
            if updates.is_none() {
                j = problem.jacobian(&it.p, &it.r, bounds);
                it.evaluations += problem.jacobian_evaluations(n);
                updates = Some(0);
            }
            let fresh = updates == Some(0);
            let model = ProjectedModel::new(&j, &it.r, &it.p, bounds);
            // Where a Jacobian costs replays, a fresh model that promises
            // less than the tolerance has converged: its trial could only
            // be a step too small to go on from.
            // A caller's own stop (`settled`) likewise.
            let stops = fresh
                && model.step(lambda).is_some_and(|(_, p)| {
                    (secant && p < PROMISE_SHARE * self.tolerance * it.cost) || settled(p, it.cost)
                });
            if stops {
                converged = true;
                break;
            }
            // Only a fresh model may say the iterate is optimal; an
            // updated one that does asks for a fresh one.
            let Some(step) = (!model.stationary())
                .then(|| it.trial_steps(&model, &mut lambda, fresh))
                .flatten()
            else {
                if fresh {
                    converged = true;
                    break;
                }
                updates = None;
                continue;
            };
            let (small, ratio) = it.take(&step);
            if secant {
                broyden_update(&mut j, &step.delta, &it.change, bounds);
            }
            updates = match updates {
                _ if small && fresh => {
                    converged = true;
                    // The Jacobian is the last point's, not this one's.
                    updates = None;
                    break;
                }
                Some(k) if secant && !small && k < SECANT_STEPS && ratio >= SECANT_RATIO => {
                    Some(k + 1)
                }
                _ => None,
            };
        }
        // Differenced at the iterate and no step taken since: the loop
        // stopped on it (a step taken leaves an update count or None).
        let at_end = (converged && updates == Some(0)).then_some(j);
        (it.result(converged), at_end)
    }
}

/// An accepted trial step: the move, the cost there, the decrease its
/// model predicted.
struct Step {
    delta: Vec<f64>,
    cost: f64,
    predicted: f64,
}

/// The iterate of [`BoundedLm::minimize`]: point, residuals, cost, and the
/// work done.
struct Iterate<'p> {
    problem: &'p dyn Residuals,
    bounds: &'p [(f64, f64)],
    tolerance: f64,
    p: Vec<f64>,
    r: Vec<f64>,
    cost: f64,
    /// The residuals of the last trial (of the accepted step, once taken).
    trial: Vec<f64>,
    /// `r(p + δ) − r(p)` of the last step taken.
    change: Vec<f64>,
    evaluations: usize,
}

impl<'p> Iterate<'p> {
    fn new(
        problem: &'p dyn Residuals,
        p0: &[f64],
        bounds: &'p [(f64, f64)],
        tolerance: f64,
    ) -> Self {
        let mut p = p0.to_vec();
        clamp(&mut p, bounds);
        let m = problem.count();
        let mut r = vec![0.0; m];
        problem.residuals(&p, &mut r);
        problem.keep_last();
        let cost = half_sum_of_squares(&r);
        Self {
            problem,
            bounds,
            tolerance,
            p,
            r,
            cost,
            trial: vec![0.0; m],
            change: vec![0.0; m],
            evaluations: 1,
        }
    }

    /// Damped steps of `model` until one lowers the cost (λ falls after it
    /// and rises after each that does not), at most [`TRIALS`], or one
    /// only where the model is not `fresh` (a failed step of an updated
    /// model asks for a fresh Jacobian first). None: none lowered it.
    fn trial_steps(
        &mut self,
        model: &ProjectedModel,
        lambda: &mut f64,
        fresh: bool,
    ) -> Option<Step> {
        let trials = if fresh { TRIALS } else { 1 };
        for _ in 0..trials {
            let Some((step, predicted)) = model.step(*lambda) else {
                *lambda *= 4.0;
                continue;
            };
            let mut q: Vec<f64> = self.p.iter().zip(&step).map(|(p, d)| p + d).collect();
            clamp(&mut q, self.bounds);
            // A trial is only taken below the cost: the problem may stop
            // replaying once it knows it is not.
            let below = self.problem.residuals_below(&q, &mut self.trial, self.cost);
            self.evaluations += 1;
            let c = if below {
                half_sum_of_squares(&self.trial)
            } else {
                f64::INFINITY
            };
            if c.is_finite() && c < self.cost {
                self.problem.keep_last();
                *lambda = (*lambda / 3.0).max(1e-12);
                let delta = q.iter().zip(&self.p).map(|(a, b)| a - b).collect();
                return Some(Step {
                    delta,
                    cost: c,
                    predicted,
                });
            }
            *lambda *= 4.0;
        }
        None
    }

    /// Moves to the step's point (its residuals those of the last trial);
    /// whether the step was below the tolerance (in cost or in every
    /// parameter's share of its range), and its decrease over the model's.
    fn take(&mut self, step: &Step) -> (bool, f64) {
        let decrease = (self.cost - step.cost) / self.cost.max(1e-300);
        let moved = step
            .delta
            .iter()
            .zip(self.bounds)
            .map(|(d, (lo, hi))| d.abs() / (hi - lo).max(1e-300))
            .fold(0.0, f64::max);
        let ratio = (self.cost - step.cost) / step.predicted.max(1e-300);
        for ((c, t), r) in self.change.iter_mut().zip(&self.trial).zip(&self.r) {
            *c = t - r;
        }
        for (p, d) in self.p.iter_mut().zip(&step.delta) {
            *p += d;
        }
        self.cost = step.cost;
        std::mem::swap(&mut self.r, &mut self.trial);
        (decrease < self.tolerance || moved < self.tolerance, ratio)
    }

    fn result(self, converged: bool) -> LocalResult {
        LocalResult {
            params: self.p,
            cost: self.cost,
            evaluations: self.evaluations,
            converged,
        }
    }
}

/// Broyden's (1965) rank-one update of `j` along the step `delta` whose
/// residuals changed by `change`, in the parameters scaled by their ranges
/// (`bounds`; 1 where unbounded): `J⁺ = J + (y − J·δ)·(D⁻²δ)ᵀ/(δᵀD⁻²δ)`,
/// which satisfies `J⁺·δ = y` and changes `J·D` least.
fn broyden_update(j: &mut DMatrix<f64>, delta: &[f64], change: &[f64], bounds: &[(f64, f64)]) {
    let weight: Vec<f64> = delta
        .iter()
        .zip(bounds)
        .map(|(d, (lo, hi))| {
            let range = hi - lo;
            let s = if range.is_finite() && range > 0.0 {
                range
            } else {
                1.0
            };
            d / (s * s)
        })
        .collect();
    let norm: f64 = weight.iter().zip(delta).map(|(w, d)| w * d).sum();
    if norm <= 0.0 || !norm.is_finite() {
        return;
    }
    let d = DVector::from_column_slice(delta);
    let mut miss = DVector::from_column_slice(change) - &*j * d;
    miss /= norm;
    for (k, w) in weight.iter().enumerate() {
        if *w != 0.0 {
            j.column_mut(k).axpy(*w, &miss, 1.0);
        }
    }
}

/// `p` moved into `bounds`, each within its own.
pub(crate) fn clamp(p: &mut [f64], bounds: &[(f64, f64)]) {
    for (x, (lo, hi)) in p.iter_mut().zip(bounds) {
        *x = x.clamp(*lo, *hi);
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

    /// Two decays fitted to three and a ripple: a residual that stays
    /// (Gauss–Newton's linear convergence, as on a diagnosis's runs).
    struct TwoDecays(Vec<f64>, Vec<f64>);
    impl Residuals for TwoDecays {
        fn count(&self) -> usize {
            self.0.len()
        }
        fn residuals(&self, p: &[f64], out: &mut [f64]) {
            for (i, (t, y)) in self.0.iter().zip(&self.1).enumerate() {
                out[i] = p[0] * (-p[1] * t).exp() + p[2] * (-p[3] * t).exp() - y;
            }
        }
    }

    fn two_decays() -> TwoDecays {
        let t: Vec<f64> = (0..200).map(|i| i as f64 * 0.05).collect();
        let y = t
            .iter()
            .map(|t| {
                2.0 * (-0.7 * t).exp()
                    + (-3.0 * t).exp()
                    + 0.3 * (-0.2 * t).exp()
                    + 0.02 * (3.0 * t).sin()
            })
            .collect();
        TwoDecays(t, y)
    }

    #[test]
    fn the_secant_form_stops_at_the_same_optimum_in_fewer_evaluations() {
        let problem = two_decays();
        let bounds = [(0.0, 10.0), (0.0, 5.0), (0.0, 10.0), (0.0, 10.0)];
        let start = [1.0, 0.3, 1.0, 2.0];
        let every = BoundedLm::default().minimize(&problem, &start, &bounds);
        let secant = BoundedLm {
            jacobians: Jacobians::Secant,
            ..BoundedLm::default()
        }
        .minimize(&problem, &start, &bounds);
        assert!(every.converged && secant.converged, "{every:?} {secant:?}");
        // The same optimum: a cost within the tolerance, parameters well
        // within their standard errors (these data pin them to ~1e-3).
        assert!(
            (secant.cost - every.cost).abs() <= 1e-7 * every.cost,
            "{} against {}",
            secant.cost,
            every.cost
        );
        for (a, b) in secant.params.iter().zip(&every.params) {
            assert!(
                (a - b).abs() < 1e-4 * b.abs().max(1.0),
                "{secant:?} {every:?}"
            );
        }
        assert!(
            secant.evaluations < every.evaluations,
            "{} against {}",
            secant.evaluations,
            every.evaluations
        );
    }

    #[test]
    fn the_broyden_update_meets_the_secant_condition_and_changes_nothing_across_the_step() {
        let mut j = DMatrix::from_fn(5, 3, |i, k| ((i + 1) * (k + 2)) as f64 * 0.1 - 0.4);
        let before = j.clone();
        let bounds = [(0.0, 2.0), (-1.0, 1.0), (0.0, 100.0)];
        let delta = [0.1, -0.05, 3.0];
        let change = [0.3, -0.2, 0.1, 0.0, 1.0];
        broyden_update(&mut j, &delta, &change, &bounds);
        let d = DVector::from_column_slice(&delta);
        for (a, b) in (&j * &d).iter().zip(change) {
            assert!((a - b).abs() < 1e-12, "J⁺·δ = {a}, y = {b}");
        }
        // A direction orthogonal to the step in the scaled metric
        // (Σ v·δ/range² = 0) sees the old Jacobian.
        let ranges = [2.0, 2.0, 100.0];
        let w: Vec<f64> = delta.iter().zip(ranges).map(|(d, r)| d / (r * r)).collect();
        let v = DVector::from_column_slice(&[w[1], -w[0], 0.0]);
        let (new, old) = (&j * &v, &before * &v);
        for (a, b) in new.iter().zip(old.iter()) {
            assert!((a - b).abs() < 1e-12, "{a} against {b}");
        }
    }

    #[test]
    fn leaves_a_bound_whose_gradient_points_inside() {
        let r = BoundedLm::default().minimize(&decay(), &[1.0, 0.0], &[(0.0, 10.0), (0.0, 10.0)]);
        assert!((r.params[1] - 0.7).abs() < 1e-7, "{:?}", r.params);
    }
}
