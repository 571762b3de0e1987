//! The cross-validation's fold refits: a candidate fitted on all runs is
//! refitted on each fold's training runs (all but the held-out ones)
//! from the all-run optimum ([`refit`]), on the all-run quadratic model of
//! the training residuals while it holds, by Levenberg–Marquardt where it
//! does not. [`training_rows`] picks the training runs' rows out of the
//! all-run residuals. The counts of replays quoted below were measured on
//! the Putnam racing log (`campaigns/putnam.toml`). Units: SI, rad.
//!
//! When a refit stops. The training cost is `C = ½·Σ r²` over the fold's
//! `m` rows of whitened residuals ([`Problem`]), and a parameter's standard
//! error is `s_i = √(s²·(H⁻¹)_ii)` with `H ≈ JᵀJ` and the residual variance
//! `s² = 2C/(m − n)` (the all-run fit's, [`fit`]). A Newton step that
//! predicts a decrease `P = ½·δᵀHδ` is `δ` from the model's minimum, and
//! the largest move of one parameter that `P` allows is
//! `|δ_i| = √(2P·(H⁻¹)_ii)`, that is `|δ_i|/s_i = √(P·(m − n)/C)`
//! standard errors (`√(2P)` where the residuals are at the noise, `s² =
//! 1`). A stop at `P ≤ τ·C/m` ([`settled`]) leaves every parameter within
//! `√τ` of its standard error of the fold's optimum:
//! [`REFIT_SETTLED`](crate::diagnose::fit::REFIT_SETTLED) `τ = 1e-3`, 0.03
//! standard errors. The stop at `P ≤ 1e-6·C` before it left up to
//! `√(1e-6·m)`, 0.18 of them on a 600 s sedan's 31,000 rows (0.06–0.16
//! measured against Levenberg–Marquardt run to convergence): part of the
//! folds' spread, the reported `fold_std_error`, was where the refits
//! stopped, not where the data put them. Levenberg–Marquardt, where it
//! takes over from the model, stops by the same test on its own fresh
//! models (and on an accepted step's decrease below `τ·C/m`).
//!
//! The model is exact to second order in the move from where its Jacobian
//! was taken; a fold that went far ([`REFIT_FAR`] all-run standard errors)
//! is checked at its own point before it stops: the stale model of the
//! 600 s sedan's road friction folds, 13 and 21 standard errors from the
//! all-run fit, saw minima 12 and 40 cost units above the true ones.

pub(crate) use crate::diagnose::fit::fold_check::training_rows;
use crate::diagnose::fit::fold_check::{against_start, start_cost, FoldRefit};
use crate::diagnose::fit::problem::Problem;
use crate::diagnose::fit::{fit, pair_index, settled, FitOutcome, GlobalSearch, Polish};
use crate::diagnose::model::Augmented;
use crate::optim::bounded::ProjectedModel;
use crate::optim::local::Residuals;
use nalgebra::{DMatrix, DVector};

/// The all-run quadratic model of a fold's training residuals.
struct FoldModel {
    jacobian: DMatrix<f64>,
    curvature: DMatrix<f64>,
    p0: Vec<f64>,
    /// The all-run fit's standard errors (NaN where it has none): the unit
    /// of how far the model is from where its Jacobian was taken.
    std_errors: Vec<f64>,
    /// The parameters the all-run fit held (unseen, or undetermined): the
    /// folds keep them, so the model has no columns for them.
    fixed: Vec<usize>,
}

impl FoldModel {
    /// Zeroes the columns of the [`FoldModel::fixed`] parameters. A
    /// relaxation length held at 0 has a zero Jacobian column there (its
    /// lag is below any replay's resolution) but not a zero second
    /// derivative: left in, `Σ r·∇²r` made the Newton model indefinite
    /// along it, no damping of a zero diagonal could cure that, and the
    /// fold stopped at the all-run optimum, its held-out error the
    /// in-sample one (measured on Putnam).
    fn hold(&mut self) {
        let n = self.p0.len();
        let curved = self.curvature.ncols() > 0;
        for &k in &self.fixed {
            self.jacobian.column_mut(k).fill(0.0);
            for b in (0..n).filter(|_| curved) {
                self.curvature.column_mut(pair_index(n, k, b)).fill(0.0);
            }
        }
    }

    /// Takes the problem's Jacobian afresh at `p` (residuals `r`) and builds
    /// the model there; the all-run second derivatives are kept.
    fn relinearise<F: Fn(&[f64]) -> Augmented + Sync>(
        &mut self,
        problem: &Problem<F>,
        p: &[f64],
        r: &[f64],
    ) {
        self.jacobian = problem.jacobian(p, r, &problem.bounds);
        self.p0 = p.to_vec();
        self.hold();
    }

    /// Whether `p` lies more than [`REFIT_FAR`] all-run standard errors
    /// (in any parameter) from where the model's Jacobian was taken: its
    /// minimum is then not believed without a fresh Jacobian there.
    fn stale_at(&self, p: &[f64]) -> bool {
        p.iter()
            .zip(&self.p0)
            .zip(&self.std_errors)
            .any(|((p, q), s)| *s > 0.0 && (p - q).abs() > REFIT_FAR * s)
    }

    /// The Newton model of the cost at `p` with residuals `r` (replayed).
    fn at(&self, p: &[f64], r: &[f64], bounds: &[(f64, f64)]) -> ProjectedModel {
        let n = p.len();
        let delta: Vec<f64> = p.iter().zip(&self.p0).map(|(p, q)| p - q).collect();
        // The Jacobian at p: J + ∇²r·δ, row by row.
        let mut j = self.jacobian.clone();
        if delta.iter().any(|&d| d != 0.0) {
            for a in 0..n {
                for (b, &d) in delta.iter().enumerate() {
                    if d != 0.0 {
                        let col = self.curvature.column(pair_index(n, a, b));
                        j.column_mut(a).axpy(d, &col, 1.0);
                    }
                }
            }
        }
        let rv = DVector::from_column_slice(r);
        let g = j.transpose() * &rv;
        let gauss_newton = j.transpose() * &j;
        let scale = gauss_newton.diagonal();
        // Σ r·∇²r: the curvature columns weighted by the residuals.
        let weighted = self.curvature.transpose() * &rv;
        let hessian = DMatrix::from_fn(n, n, |a, b| {
            gauss_newton[(a, b)] + weighted[pair_index(n, a, b)]
        });
        ProjectedModel::newton(hessian, g, scale, p, bounds)
    }
}

/// How far from where its model's Jacobian was taken (the all-run fit, or
/// its last fresh one), in all-run standard errors of any parameter, a
/// fold refit takes a fresh Jacobian before it believes the model's
/// minimum. Runs that agree move the optimum when one of `K` leaves by
/// about `1/√(K − 1)` of a standard error (the jackknife's spread: under 1
/// for `K ≥ 2`); 3 is three times the largest of those, where the
/// runs disagree and the terms the model drops (third order in the move,
/// 27 times those at one standard error) no longer vanish. The 600 s
/// sedan's folds moved 1–21 standard errors; those of its road friction
/// that moved 13 and 21 stopped 12 and 40 cost units above their optima.
pub(super) const REFIT_FAR: f64 = 3.0;

/// Replays of a fold refit on its quadratic model before it falls back to
/// Levenberg–Marquardt. A model step costs one replay, an iteration of
/// Levenberg–Marquardt `n + 1` or more: where one run of a real log
/// leaving moves the optimum far (a 20 s piece of a racing log), the model's
/// steps go on lowering the cost as predicted, a share of 1e-3 to 1e-5 a
/// step, well past a handful of them (measured on the Putnam log).
const REFIT_MODEL_STEPS: usize = 60;

/// Rejected model steps in a row (the damping ten times higher after each)
/// after which the model no longer serves. On the Putnam log, 3 handed 54
/// of its 264 fold refits to Levenberg–Marquardt, at 40–100 replays each,
/// where damping on reaches a step that lowers the cost.
const REFIT_MODEL_REJECTIONS: usize = 8;

/// Accepted model steps in a row whose decrease the model mispredicted
/// (outside half to twice its prediction) after which a fold refit near
/// where its Jacobian was taken hands over to Levenberg–Marquardt: its
/// all-run second derivatives, not its Jacobian, are what no longer hold
/// there, and the fresh Gauss–Newton models of Levenberg–Marquardt stop by
/// the same test ([`settled`]). On the slow oval (`synth --programme
/// slow-oval --effects bank_profile --seed 1`) ten of its 48 fold refits
/// went on for all [`REFIT_MODEL_STEPS`] replays without settling, six of
/// them within 0.14 all-run standard errors of their start, and
/// Levenberg–Marquardt then settled them in 11–33 replays; with this
/// hand-over its fold refits took 599 replays where they took 987, its
/// verdict and held-out errors unchanged (session 108, benchmarks chapter).
const REFIT_MODEL_MISPREDICTIONS: usize = 3;

/// Times a fold refit that has moved differences its Jacobian afresh (`n`
/// replays, the all-run second derivatives kept): when its steps stall, or
/// when a model that mispredicted its last step sees a minimum. On the
/// Putnam log, with these limits, 256 of 264 fold refits converge on their
/// models and 8 are handed over, 2,673 replays in all where the all-run
/// model alone (3 rejections, 20 steps) took 3,597.
const REFIT_RELINEARISATIONS: usize = 4;

/// Refits `problem` (the training runs of a fold, whose residual rows are
/// `rows` of the all-run problem's) from the all-run fit `full`. The
/// optimum moves little when one run of several leaves, so the all-run
/// quadratic model of the residuals restricted to those rows
/// ([`Linearisation`](crate::diagnose::fit::Linearisation)) stands in for their
/// derivatives: at `p0 + δ` the Jacobian is `J + ∇²r·δ` and the Hessian of
/// the cost `JᵀJ + Σ r·∇²r` with the replayed residuals `r`, exact to
/// second order in δ. The second-order
/// term matters: the residuals of a real log stay far above the noise (a
/// model-form gap), where Gauss–Newton alone, which drops it, converges
/// slowly. Damped Newton steps projected into the bounds, each costing one
/// replay of the training runs, the damping raised after a step that does
/// not lower the cost and lowered after one that does, until the model
/// predicts the parameters settled ([`settled`]); that test is
/// believed only where the model predicted its last step's decrease to a
/// factor of 2, and within [`REFIT_FAR`] standard errors of where its
/// Jacobian was taken. A refit that has moved takes a fresh Jacobian (at most
/// [`REFIT_RELINEARISATIONS`] times) when [`REFIT_MODEL_REJECTIONS`] steps
/// in a row fail, when a model it does not believe sees a minimum, or when
/// [`REFIT_MODEL_MISPREDICTIONS`] accepted steps in a row were mispredicted
/// beyond [`REFIT_FAR`]; nearer than that, such a run hands over.
/// Where the model has not converged within [`REFIT_MODEL_STEPS`] replays,
/// or cannot go on, Levenberg–Marquardt (fresh Jacobians) goes on from
/// there within its budget. Without a linearisation (`full` not polished)
/// it is Levenberg–Marquardt from `full`. Checked against its start
/// ([`refit_checked`]): one that ends above it is put back there.
pub fn refit<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    full: &FitOutcome,
    rows: &[std::ops::Range<usize>],
) -> FitOutcome {
    refit_checked(problem, full, rows).0
}

/// [`refit`] and its check against its start ([`FoldRefit`]).
pub fn refit_checked<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    full: &FitOutcome,
    rows: &[std::ops::Range<usize>],
) -> (FitOutcome, FoldRefit) {
    let start = start_cost(problem, full, rows);
    against_start(problem, full, start, descend(problem, full, rows))
}

/// [`refit`]'s descent, unchecked: on the fold's model ([`fold_model`],
/// [`on_model`]), then Levenberg–Marquardt from where that got where it
/// did not converge (its replays counted with the model's).
pub(super) fn descend<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    full: &FitOutcome,
    rows: &[std::ops::Range<usize>],
) -> FitOutcome {
    let Some((mut model, mut at)) = fold_model(full, rows) else {
        return fit(problem, &full.params, None, Polish::Refit);
    };
    if on_model(problem, &mut model, &mut at) {
        return converged(problem, full, at);
    }
    let mut f = fit(problem, &at.p, None, Polish::Refit);
    f.evaluations += at.evaluations;
    f
}

/// Where a fold refit's descent on its model stands: the parameters, the
/// training residuals there (replayed, or the linearisation's at the
/// start), their cost, and the replays made so far.
struct Descent {
    p: Vec<f64>,
    r: Vec<f64>,
    cost: f64,
    evaluations: usize,
}

/// The quadratic model of a fold built from the all-run fit `full` (None
/// where `full` was not linearised, or has no parameters) on its rows
/// `rows` of the Jacobian and second derivatives, the parameters it held
/// kept out; and the descent's start there.
fn fold_model(full: &FitOutcome, rows: &[std::ops::Range<usize>]) -> Option<(FoldModel, Descent)> {
    let linear = full.linear.as_ref().filter(|_| !full.params.is_empty())?;
    let n = full.params.len();
    let picked: Vec<usize> = rows.iter().flat_map(|r| r.clone()).collect();
    let mut model = FoldModel {
        jacobian: linear.jacobian.select_rows(picked.iter()),
        curvature: linear.curvature.select_rows(picked.iter()),
        p0: full.params.clone(),
        std_errors: full.std_errors.clone(),
        fixed: (0..n)
            .filter(|&i| full.is_unseen(i) || full.held_for(i).is_some())
            .collect(),
    };
    model.hold();
    let r: Vec<f64> = picked.iter().map(|&i| linear.residuals[i]).collect();
    let start = Descent {
        p: full.params.clone(),
        cost: 0.5 * r.iter().map(|e| e * e).sum::<f64>(),
        r,
        evaluations: 0,
    };
    Some((model, start))
}

/// Damped model steps of `problem` from `at` (see [`refit`]); true where
/// the model converged there, false where it stopped (`at` is then the
/// last accepted point, its replays kept).
fn on_model<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    model: &mut FoldModel,
    at: &mut Descent,
) -> bool {
    let n = at.p.len();
    let mut trial = vec![0.0; at.r.len()];
    let (mut lambda, mut relinearised) = (0.0, 0);
    // Damping raised without a replay when the model is not positive
    // definite: a bounded number of tries in all.
    let mut rejected = 0;
    // Whether the model predicted the last accepted step's decrease (to a
    // factor of 2), or was just differenced here: only then, and near
    // where its Jacobian was taken, is its convergence test believed. A
    // model far from where it was built can see a minimum that is not
    // there.
    let mut trusted = true;
    // A minimum seen by a model that is not believed.
    let mut doubted = false;
    // Accepted steps in a row the model mispredicted.
    let mut mispredicted = 0;
    for _ in 0..4 * REFIT_MODEL_STEPS {
        let can_relinearise = relinearised < REFIT_RELINEARISATIONS
            && at.p != model.p0
            && at.evaluations + n < REFIT_MODEL_STEPS;
        // Stalled or doubted after moving, or mispredicting far from where
        // the Jacobian was taken: the Jacobian no longer holds here.
        let astray = mispredicted == REFIT_MODEL_MISPREDICTIONS && model.stale_at(&at.p);
        if (rejected == REFIT_MODEL_REJECTIONS || doubted || astray) && can_relinearise {
            model.relinearise(problem, &at.p, &at.r);
            at.evaluations += problem.jacobian_evaluations(n);
            relinearised += 1;
            (rejected, lambda, trusted, doubted, mispredicted) = (0, 0.0, true, false, 0);
        }
        if doubted
            || at.evaluations >= REFIT_MODEL_STEPS
            || rejected == REFIT_MODEL_REJECTIONS
            || mispredicted == REFIT_MODEL_MISPREDICTIONS
        {
            return false;
        }
        let Some((d, predicted)) = model.at(&at.p, &at.r, &problem.bounds).step(lambda) else {
            lambda = (lambda * 10.0).max(1e-3);
            continue;
        };
        if settled(predicted, at.cost, at.r.len()) {
            if trusted && !model.stale_at(&at.p) {
                return true;
            }
            doubted = true;
            continue;
        }
        match trial_step(problem, at, &d, &mut trial) {
            Some((q, c)) => {
                trusted = (0.5..=2.0).contains(&((at.cost - c) / predicted));
                mispredicted = if trusted { 0 } else { mispredicted + 1 };
                (at.p, at.cost) = (q, c);
                std::mem::swap(&mut at.r, &mut trial);
                lambda *= 0.1;
                rejected = 0;
            }
            None => {
                lambda = (lambda * 10.0).max(1e-3);
                rejected += 1;
            }
        }
    }
    false
}

/// Replays the step `d` from `at` into `trial`: its cost where it lowers
/// `at`'s (its replays kept: Levenberg–Marquardt, if it takes over from
/// there, starts without integrating them again) with the point, else None.
fn trial_step<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    at: &mut Descent,
    d: &[f64],
    trial: &mut [f64],
) -> Option<(Vec<f64>, f64)> {
    let q: Vec<f64> = problem.clamp(&at.p.iter().zip(d).map(|(p, d)| p + d).collect::<Vec<_>>());
    // Only a step below the cost is taken: the replays may stop once they
    // show it is not.
    let below = problem.residuals_below(&q, trial, at.cost);
    at.evaluations += 1;
    let c = if below {
        0.5 * trial.iter().map(|e| e * e).sum::<f64>()
    } else {
        f64::INFINITY
    };
    (c.is_finite() && c < at.cost).then(|| {
        problem.keep_last();
        (q, c)
    })
}

/// The refit that converged on its model at `at`: no standard errors (the
/// folds report parameters and held-out errors only).
fn converged<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    full: &FitOutcome,
    at: Descent,
) -> FitOutcome {
    let n = at.p.len();
    FitOutcome {
        std_errors: vec![f64::NAN; n],
        cost: at.cost - problem.prior_cost(&at.p),
        params: at.p,
        residuals: problem.data_count(),
        evaluations: at.evaluations,
        converged: true,
        global: GlobalSearch::None,
        unseen: Vec::new(),
        held: full.held.clone(),
        linear: None,
        robust_std_errors: Vec::new(),
        robust_covariance: None,
    }
}

#[cfg(test)]
#[path = "refit_tests.rs"]
pub(super) mod tests;
