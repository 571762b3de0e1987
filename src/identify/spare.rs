//! The core of the rule that holds a parameter the data do not determine,
//! shared by the swarm fit of a channel (`undetermined.rs`) and the staged
//! Magic Formula fit (`mf_staged/holds.rs`), which differ in how they build
//! a problem, refit it and rank a tie, not in the rule: each flagged
//! parameter (the largest relative standard error first, at most
//! [`CANDIDATES`]) is held in turn at its stated value and the rest
//! refitted, from the optimum or with the rest moved along the trade-off
//! where that starts lower, and the hold that raises the cost least is
//! kept, of those within half a residual variance of it (which the data
//! cannot tell apart) the one the [`TieBreak`] names.
//!
//! And the words of a stated value the data lean against: one more than
//! [`LEAN_STANDARD_ERRORS`] standard errors from the free fit is held where
//! the data would not put it, and the user is told so with the option
//! that chooses another.

use crate::optim::bounded::clamp;
use crate::optim::local::{LocalResult, Residuals};
use rayon::prelude::*;

/// Flagged parameters tried per round, the largest relative standard
/// error first.
pub(crate) const CANDIDATES: usize = 4;

/// Which of the holds the data cannot tell apart is kept.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum TieBreak {
    /// The least determined (the first in the candidates' order): the
    /// swarm models' parameter orders do not rank their terms (PAC89's
    /// `a1`, a load variation, comes before `a2`, the friction).
    LeastDetermined,
    /// The latest in the problem's order: the Magic Formula's stages list
    /// a secondary term after its primary one (`PKY4` after `PKY1`).
    LatestInOrder,
}

/// One hold tried: the parameter (index in the free vector), the problem
/// without it, its refitted values and cost.
pub(crate) struct Tried<P> {
    pub(crate) k: usize,
    pub(crate) problem: P,
    pub(crate) p: Vec<f64>,
    pub(crate) cost: f64,
}

/// The fit the holds are tried on: its problem at its optimum `p`, the
/// free parameters' `bounds`, whether a refit's start is clamped into them
/// (the staged fit's bounded LM wants it; the swarm's polish may start, as
/// its optimum may lie, past the box) and the tie rule.
pub(crate) struct HoldFit<'a, P> {
    pub(crate) problem: &'a P,
    pub(crate) p: &'a [f64],
    pub(crate) bounds: &'a [(f64, f64)],
    pub(crate) clamp_starts: bool,
    pub(crate) tie: TieBreak,
}

/// The ways a fit builds and refits a hold: the problem with free
/// parameter `k` held at `value`, the stated value of `k`, the change of
/// every free parameter that keeps the fit when `k` moves by `dv`, and
/// the refit of a problem from a start within bounds.
pub(crate) struct HoldWays<W, S, C, R> {
    pub(crate) without: W,
    pub(crate) stated: S,
    pub(crate) compensating: C,
    pub(crate) refit: R,
}

/// `flagged` in the order they are tried, the largest `relative` standard
/// error first, cut to [`CANDIDATES`].
pub(crate) fn candidates(mut flagged: Vec<usize>, relative: impl Fn(usize) -> f64) -> Vec<usize> {
    flagged.sort_by(|&a, &b| relative(b).total_cmp(&relative(a)));
    flagged.truncate(CANDIDATES);
    flagged
}

/// The hold among `candidates` the fit can best spare (module notes), and
/// the residual evaluations the refits took.
pub(crate) fn spare<P, W, S, C, R>(
    fit: &HoldFit<P>,
    candidates: &[usize],
    ways: &HoldWays<W, S, C, R>,
) -> (Option<Tried<P>>, usize)
where
    P: Residuals + Send + Sync,
    W: Fn(usize, f64) -> P + Sync,
    S: Fn(usize) -> f64 + Sync,
    C: Fn(usize, f64) -> Vec<f64> + Sync,
    R: Fn(&P, &[f64], &[(f64, f64)]) -> LocalResult + Sync,
{
    // The holds tried are independent refits: run side by side (a
    // UniTire aligning fit tries four per round, each a full polish).
    let tried: Vec<(Option<Tried<P>>, usize)> = candidates
        .par_iter()
        .map(|&k| {
            let value = (ways.stated)(k);
            let sub = (ways.without)(k, value);
            let without = |v: &[f64]| -> Vec<f64> {
                v.iter()
                    .enumerate()
                    .filter(|(i, _)| *i != k)
                    .map(|e| *e.1)
                    .collect()
            };
            let bounds = without_bounds(fit.bounds, k);
            // From the optimum, or with the rest moved as they trade
            // against the held value where that starts lower: a warm start
            // that jumps one parameter of a traded pair alone can stall far
            // from the pair's valley.
            let moved: Vec<f64> = fit
                .p
                .iter()
                .zip((ways.compensating)(k, value - fit.p[k]))
                .map(|(a, d)| a + d)
                .collect();
            let x = [without(&moved), without(fit.p)]
                .into_iter()
                .map(|mut x| {
                    if fit.clamp_starts {
                        clamp(&mut x, &bounds);
                    }
                    x
                })
                .min_by(|a, b| sub.cost(a).total_cmp(&sub.cost(b)))
                .unwrap_or_default();
            let r = (ways.refit)(&sub, &x, &bounds);
            let tried = Tried {
                k,
                problem: sub,
                p: r.params,
                cost: r.cost,
            };
            (r.cost.is_finite().then_some(tried), r.evaluations)
        })
        .collect();
    let evaluations = tried.iter().map(|t| t.1).sum();
    let tried: Vec<Tried<P>> = tried.into_iter().filter_map(|t| t.0).collect();
    (chosen(fit, tried), evaluations)
}

/// `bounds` without entry `k`.
fn without_bounds(bounds: &[(f64, f64)], k: usize) -> Vec<(f64, f64)> {
    let mut b = bounds.to_vec();
    b.remove(k);
    b
}

/// The hold kept of those `tried` (in the candidates' order): the lowest
/// cost, of costs within half a residual variance of it the one the tie
/// rule names. Without a tie rule the choice between two parameters along
/// one null direction fell to the last digits of where the optimiser
/// stopped.
fn chosen<P: Residuals>(fit: &HoldFit<P>, tried: Vec<Tried<P>>) -> Option<Tried<P>> {
    let lowest = tried.iter().map(|t| t.cost).fold(f64::INFINITY, f64::min);
    // cost = ½·Σe², so half a residual variance Σe²/dof is cost/dof.
    let dof = fit.problem.count().saturating_sub(fit.p.len()).max(1) as f64;
    let tie = fit.problem.cost(fit.p) / dof;
    let mut within = tried.into_iter().filter(|t| t.cost <= lowest + tie);
    match fit.tie {
        TieBreak::LeastDetermined => within.next(),
        TieBreak::LatestInOrder => within.max_by_key(|t| t.k),
    }
}

/// The distance, in standard errors, past which a stated value is said
/// to lie where the data would not put it: the free fit's value ± two
/// standard errors is about the 95 % interval the data allow.
pub(crate) const LEAN_STANDARD_ERRORS: f64 = 2.0;

/// How many standard errors `stated` lies from the free fit's `fitted`
/// (`None` without a finite, positive standard error).
pub(crate) fn standard_errors_away(stated: f64, fitted: f64, se: Option<f64>) -> Option<f64> {
    se.filter(|s| s.is_finite() && *s > 0.0)
        .map(|s| (stated - fitted).abs() / s)
}

/// The clause a held line of parameter `name` ends with when its stated
/// value lies more than [`LEAN_STANDARD_ERRORS`] from the free fit
/// (`away`, [`standard_errors_away`]); empty otherwise.
pub(crate) fn lean_clause(name: &str, away: Option<f64>) -> String {
    match away {
        Some(z) if z > LEAN_STANDARD_ERRORS => format!(
            "; the data lean against that value: it lies {z:.1} standard errors from the free fit, outside the ±{LEAN_STANDARD_ERRORS:.0} the data allow (to hold it at a value of your own, give --hold {name}=VALUE)"
        ),
        _ => String::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// PAC89's aligning c9 on the Hoosier file: held at its start value
    /// −1.3329 where the free fit gave −0.1947 ± 0.317.
    #[test]
    fn a_stated_value_more_than_two_standard_errors_out_is_said_to_be_leaned_against() {
        let away = standard_errors_away(-1.3329, -0.1947, Some(0.317));
        assert!((away.unwrap() - 3.5905).abs() < 1e-3, "{away:?}");
        assert_eq!(
            lean_clause("c9", away),
            "; the data lean against that value: it lies 3.6 standard errors from the free fit, outside the ±2 the data allow (to hold it at a value of your own, give --hold c9=VALUE)"
        );
        // Within two standard errors, or without one, nothing is said.
        assert_eq!(
            lean_clause("a7", standard_errors_away(0.77394, 0.9957, Some(24.4))),
            ""
        );
        assert_eq!(
            lean_clause("x", standard_errors_away(3.0, 1.0, Some(1.0))),
            ""
        );
        assert_eq!(standard_errors_away(3.0, 1.0, None), None);
        assert_eq!(standard_errors_away(3.0, 1.0, Some(0.0)), None);
        assert_eq!(lean_clause("x", None), "");
    }
}
