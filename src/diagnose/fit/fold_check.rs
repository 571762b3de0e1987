//! The check of a cross-validation fold's refit against where it started.
//! A fold refit ([`refit`](crate::diagnose::fit::refit::refit)) starts
//! from the all-run fit; it is a descent, so it must end with a training cost (`½·Σ e²` of the fold's scaled training
//! residuals and the prior's rows, dimensionless) no higher than the cost
//! of the all-run parameters on the same training runs. One that ends
//! higher has failed as a fit (a refit that wandered to a worse local
//! minimum, or a start cost that was not the fold's own) and says nothing
//! about the effect:
//! [`refit_checked`](crate::diagnose::fit::refit::refit_checked) puts it back at its start and
//! records it ([`FoldRefit`]), with how far each parameter moved in the
//! all-run fit's standard errors. (An outside check's blind four-wheel
//! campaign with roll camber lost 19 % held out after 44 % in sample.)

use crate::diagnose::fit::fold_noise::run_rows;
use crate::diagnose::fit::problem::Problem;
use crate::diagnose::fit::FitOutcome;
use crate::diagnose::model::replay::Prepared;
use crate::diagnose::model::Augmented;
use crate::optim::local::Residuals;
use serde::Serialize;
use std::ops::Range;

/// One fold refit measured against its start.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FoldRefit {
    /// The fold's training cost (data and prior rows) at the all-run fit's
    /// parameters: where the refit started.
    pub start_cost: f64,
    /// The same at the refit's end (its start when it was put back).
    pub cost: f64,
    /// Each parameter's move from the all-run fit, in the all-run fit's
    /// standard errors (NaN where it has none: held, unseen, on a bound).
    pub moved_std_errors: Vec<f64>,
    /// The refit ended above its start and was put back there.
    pub put_back: bool,
}

/// How far past its start's cost (a share of it) a refit's end may lie
/// before it counts as worse: rounding only, the descent accepts no step
/// that raises the cost.
const WORSE: f64 = 1e-12;

/// The residual rows of a fold's training runs (all but `held_out`) in the
/// all-run problem, whose rows follow the runs' order, then its `prior`
/// rows (the axle characteristics' prior, [`Problem::with_prior`]), which
/// every fold shares.
pub(crate) fn training_rows(
    runs: &[Prepared],
    held_out: &[usize],
    prior: usize,
) -> Vec<Range<usize>> {
    let mut rows = run_rows(runs, |i| !held_out.contains(&i));
    if prior > 0 {
        let all: usize = runs.iter().map(Prepared::count).sum();
        rows.push(all..all + prior);
    }
    rows
}

/// The training cost (data and prior rows) of the fold's `problem`, whose
/// rows are `rows` of the all-run problem's, at the all-run fit `full`:
/// the linearisation's rows (the refit's own start), or a replay where
/// `full` was not linearised.
pub(crate) fn start_cost<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    full: &FitOutcome,
    rows: &[Range<usize>],
) -> f64 {
    match &full.linear {
        Some(l) if !full.params.is_empty() => {
            0.5 * rows
                .iter()
                .flat_map(|r| r.clone())
                .map(|i| l.residuals[i].powi(2))
                .sum::<f64>()
        }
        _ => problem.cost(&full.params),
    }
}

/// `out`, the refit of `problem` from `full` whose training cost there is
/// `start_cost`, put back at `full`'s parameters if it ended above it.
pub(crate) fn against_start<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    full: &FitOutcome,
    start_cost: f64,
    mut out: FitOutcome,
) -> (FitOutcome, FoldRefit) {
    // The refit reports its data cost; the descent lowers data and prior.
    let end = out.cost + problem.prior_cost(&out.params);
    // A cost that is not a number is no descent either.
    let put_back = end.is_nan() || end > start_cost * (1.0 + WORSE);
    if put_back {
        out.params = full.params.clone();
        out.cost = start_cost - problem.prior_cost(&full.params);
    }
    let moved_std_errors = out
        .params
        .iter()
        .zip(&full.params)
        .zip(&full.std_errors)
        .map(|((p, q), s)| {
            if s.is_finite() && *s > 0.0 {
                (p - q).abs() / s
            } else {
                f64::NAN
            }
        })
        .collect();
    let record = FoldRefit {
        start_cost,
        cost: if put_back { start_cost } else { end },
        moved_std_errors,
        put_back,
    };
    (out, record)
}
