//! The guard on a hold of the staged fit (`holds.rs`): a hold whose best
//! refit raises the stage's cost (`½Σe²` of its residuals, in the
//! channel's unit squared) past `spare::guard` is refused, and the
//! coefficient stays free with its warning. The guard is about 2.5
//! residual variances or σ rising by 5 % of itself, whichever is larger
//! (`spare.rs`, which the swarm fits share).

use super::params::Need;
use super::problem::StageProblem;
use crate::identify::spare::guard;
use crate::optim::local::{LocalResult, Residuals};

/// The stage's own fit of a problem from its start values: the problem,
/// each free parameter's levels needed, starts and bounds.
pub(super) type Refit<'r> =
    dyn Fn(&StageProblem, &[Need], &[f64], &[(f64, f64)]) -> LocalResult + Sync + 'r;

/// A stage's fit as the guard reads it: its problem at its point `p`, and
/// each free parameter's levels needed and start value.
pub(super) struct Fitted<'f, 'a> {
    pub(super) problem: &'f StageProblem<'a>,
    pub(super) p: &'f [f64],
    pub(super) needs: &'f [Need],
    pub(super) starts: &'f [f64],
}

/// The refit of a hold, `sub` (the stage's problem of `fit` with one
/// parameter held, within `bounds`), from `warm`, its refit from the
/// optimum: where that raises the cost past the guard (`spare::guard`,
/// about 2.5 residual variances or σ rising by 5 % of itself), the
/// stage's own fit of `sub` from its start values too, and the better.
///
/// The guard refuses a hold whose best refit costs past it: a flagged
/// coefficient is one whose standard error reaches its value, a linear
/// judgement, and where the trade-off is far from linear the hold costs
/// what the standard error did not foresee (`RVY1` on MFeval's own MF 6.1
/// grid, one standard error off, raised combined Fy's σ from 0.064 % to
/// 0.820 %); the coefficient stays free, with its warning. Judged on the
/// warm refit alone, a hold the fresh fit makes cheap was refused too
/// (the Hoosier file's `PKY4` at 60 iterations: σ 1.683 → 1.749 %, 3.9 %
/// fresh, past 5 % warm), so the fresh fit is tried before refusing.
pub(super) fn guarded_refit(
    fit: Fitted,
    sub: &StageProblem,
    warm: LocalResult,
    bounds: &[(f64, f64)],
    refit: &Refit,
) -> LocalResult {
    let base = fit.problem.cost(fit.p);
    if warm.cost - base <= guard(base, fit.problem.count(), fit.p.len()) {
        return warm;
    }
    // The held one: the first of the stage's names `sub` lacks.
    let names = &fit.problem.names;
    let k = (0..names.len())
        .find(|&i| sub.names.get(i) != Some(&names[i]))
        .unwrap_or(names.len() - 1);
    let without = |v: &[Need]| [&v[..k], &v[k + 1..]].concat();
    let starts = [&fit.starts[..k], &fit.starts[k + 1..]].concat();
    let fresh = refit(sub, &without(fit.needs), &starts, bounds);
    let evaluations = warm.evaluations + fresh.evaluations;
    let best = if fresh.cost.is_finite() && fresh.cost < warm.cost {
        fresh
    } else {
        warm
    };
    LocalResult {
        evaluations,
        ..best
    }
}
