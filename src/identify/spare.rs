//! The core of the rule that holds a parameter the data do not determine,
//! shared by the swarm fit of a channel (`undetermined.rs`) and the staged
//! Magic Formula fit (`mf_staged/holds.rs`), which differ in how they build
//! a problem, refit it and rank a tie, not in the rule: each flagged
//! parameter (the largest relative standard error first, at most
//! [`CANDIDATES`]) is held in turn at the value [`held_value`] gives and
//! the rest refitted, from the optimum or with the rest moved along the
//! trade-off where that starts lower, and the hold that raises the cost
//! least is kept, of those within half a residual variance of it (which
//! the data cannot tell apart) the one the [`TieBreak`] names.
//!
//! The value held is one the data allow. A parameter is flagged when its
//! standard error reaches its value: a large *relative* error, which a
//! free value near zero has with a small standard error too, so the data
//! may still reject a stated value far from it. It is held at its stated
//! value when that lies within [`LEAN_STANDARD_ERRORS`] standard errors
//! of the free fit (about the 95 % interval the data allow); otherwise at
//! the end of that interval nearest the stated value, clamped into its
//! bounds: the closest to the prior the data allow. Without a standard
//! error (the fit is singular along it) the stated value is held.
//!
//! Those standard errors are a linearisation's at the free fit, which a
//! fit stopped in a local minimum or a trade-off far from linear
//! misjudges (noise-free data from a template, the Mx stage stopped near
//! singular with the template's true `QSX9` 25 standard errors off). So
//! a fit may try the stated value first ([`HoldFit::stated_first`], the
//! staged Magic Formula fit's): held there, the rest refitted, it is kept
//! when its refit passes the [`guard`], whatever the standard errors say,
//! and only when refused is the edge of the ±2 tried; the held line says
//! which ([`held_at_tried`]).
//!
//! And a guard: a hold whose refit raises the cost (`½Σe²`) of the fit it
//! is tried on by more than [`guard`] allows, about 2.5 times that fit's
//! residual variance `s²` or a rise of σ by [`SIGMA_RISE`] of itself,
//! whichever is larger, is not kept, whatever its value. Moving one
//! parameter `z` standard errors from its optimum, the rest refitted,
//! raises `Σe²` by `z²·s²` to first order, so `½Σe²` by `½z²s²`: `2s²` is
//! a hold at the edge of the ±2 standard errors, the most the data can
//! ignore, and the guard leaves a quarter of a standard error past it for
//! the refit's own tolerance ([`GUARD_STANDARD_ERRORS`]). A hold that
//! costs more (a trade-off far from linear, where the standard error
//! misjudges the interval; a stated value held without a standard error;
//! a clamp) would keep a value the data reject: the parameter is left
//! free instead, with its warning as a free parameter's, and not tried
//! again in later rounds.

use crate::format::{exact, rounded};
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

/// One hold tried: the parameter (index in the free vector), the value
/// it is held at ([`held_value`]), the problem without it, its refitted
/// values and cost.
pub(crate) struct Tried<P> {
    pub(crate) k: usize,
    pub(crate) value: f64,
    pub(crate) problem: P,
    pub(crate) p: Vec<f64>,
    pub(crate) cost: f64,
}

/// The fit the holds are tried on: its problem at its optimum `p`, the
/// free parameters' standard errors there (`None`: none), their `bounds`,
/// whether a refit's start is clamped into them
/// (the staged fit's bounded LM wants it; the swarm's polish may start, as
/// its optimum may lie, past the box) and the tie rule.
pub(crate) struct HoldFit<'a, P> {
    pub(crate) problem: &'a P,
    pub(crate) p: &'a [f64],
    pub(crate) std_errors: &'a [Option<f64>],
    pub(crate) bounds: &'a [(f64, f64)],
    pub(crate) clamp_starts: bool,
    pub(crate) tie: TieBreak,
    /// Whether the [`guard`] refuses a hold that costs too much. Both
    /// fits guard: the staged Magic Formula fit's stated values (a
    /// template's or the book's) are no prior that may cost the fit what
    /// the data reject either (on MFeval's own MF 6.1 grid its unguarded
    /// holds raised combined Fy's σ fourteenfold).
    pub(crate) guarded: bool,
    /// Whether a stated value more than [`LEAN_STANDARD_ERRORS`] from the
    /// free fit is tried before the edge of its ±2 standard errors, and
    /// held where its refit passes the [`guard`] (module notes). The
    /// staged Magic Formula fit's: its stages stop in local minima whose
    /// linearisation misjudged a template's true value as 25 standard
    /// errors off. The swarm fits keep the edge rule for now (their
    /// written holds, PAC89's aligning `c9` on the Hoosier file, would
    /// move to the stated values).
    pub(crate) stated_first: bool,
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

/// What one round of holds came to: the hold kept, if any, the
/// candidates refused by the [`guard`] (their refits raised the cost past
/// it), each refusal with its value and cost (for its report), and the
/// residual evaluations the refits took.
pub(crate) struct Spared<P> {
    pub(crate) kept: Option<Tried<P>>,
    pub(crate) refused: Vec<usize>,
    pub(crate) refusals: Vec<Refusal>,
    pub(crate) evaluations: usize,
}

/// A hold the [`guard`] refused: the parameter (index in the free
/// vector), the value it was tried at and its best refit's cost (`½Σe²`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Refusal {
    pub(crate) k: usize,
    pub(crate) value: f64,
    pub(crate) cost: f64,
}

/// The hold among `candidates` the fit can best spare (module notes).
pub(crate) fn spare<P, W, S, C, R>(
    fit: &HoldFit<P>,
    candidates: &[usize],
    ways: &HoldWays<W, S, C, R>,
) -> Spared<P>
where
    P: Residuals + Send + Sync,
    W: Fn(usize, f64) -> P + Sync,
    S: Fn(usize) -> f64 + Sync,
    C: Fn(usize, f64) -> Vec<f64> + Sync,
    R: Fn(&P, &[f64], &[(f64, f64)]) -> LocalResult + Sync,
{
    let base = fit.problem.cost(fit.p);
    let most = match fit.guarded {
        true => guard(base, fit.problem.count(), fit.p.len()),
        false => f64::INFINITY,
    };
    // The holds tried are independent refits: run side by side (a
    // UniTire aligning fit tries four per round, each a full polish).
    let tried: Vec<(Option<Tried<P>>, usize)> = candidates
        .par_iter()
        .map(|&k| {
            let stated = (ways.stated)(k);
            let edge = held_value(stated, fit.p[k], fit.std_errors[k], fit.bounds[k]);
            if !fit.stated_first || edge == stated {
                return tried_at(fit, ways, k, edge);
            }
            // The stated value first, judged by its refit's cost: the
            // standard errors are a linearisation's, which a trade-off
            // far from linear, or a fit stopped in a local minimum,
            // misjudges (module notes).
            let (at_stated, n) = tried_at(fit, ways, k, stated);
            match at_stated {
                Some(t) if t.cost - base <= most => (Some(t), n),
                _ => {
                    let (at_edge, m) = tried_at(fit, ways, k, edge);
                    (at_edge, n + m)
                }
            }
        })
        .collect();
    let evaluations = tried.iter().map(|t| t.1).sum();
    // A refit that failed (no finite cost) is refused as one past the
    // guard: the hold left no fit to keep.
    let (kept, refused): (Vec<_>, Vec<_>) = tried
        .into_iter()
        .partition(|t| t.0.as_ref().is_some_and(|t| t.cost - base <= most));
    let refusals = refusals_of(&refused);
    Spared {
        kept: chosen(fit, kept.into_iter().filter_map(|t| t.0).collect()),
        refused: refusals.iter().map(|r| r.k).collect(),
        refusals,
        evaluations,
    }
}

/// Free parameter `k` of `fit` held at `value` and the rest refitted,
/// from the optimum or with the rest moved as they trade against the
/// held value where that starts lower (a warm start that jumps one
/// parameter of a traded pair alone can stall far from the pair's
/// valley); `None` where the refit gave no finite cost. With the
/// residual evaluations it took.
fn tried_at<P, W, S, C, R>(
    fit: &HoldFit<P>,
    ways: &HoldWays<W, S, C, R>,
    k: usize,
    value: f64,
) -> (Option<Tried<P>>, usize)
where
    P: Residuals,
    W: Fn(usize, f64) -> P,
    C: Fn(usize, f64) -> Vec<f64>,
    R: Fn(&P, &[f64], &[(f64, f64)]) -> LocalResult,
{
    let sub = (ways.without)(k, value);
    let without = |v: &[f64]| -> Vec<f64> {
        v.iter()
            .enumerate()
            .filter(|(i, _)| *i != k)
            .map(|e| *e.1)
            .collect()
    };
    let bounds = without_bounds(fit.bounds, k);
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
        value,
        problem: sub,
        p: r.params,
        cost: r.cost,
    };
    (r.cost.is_finite().then_some(tried), r.evaluations)
}

/// The refusals of the holds `refused` that left a fit (a refit without
/// a finite cost left none to report).
fn refusals_of<P>(refused: &[(Option<Tried<P>>, usize)]) -> Vec<Refusal> {
    refused
        .iter()
        .filter_map(|t| t.0.as_ref())
        .map(|t| Refusal {
            k: t.k,
            value: t.value,
            cost: t.cost,
        })
        .collect()
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

/// The reach of the [`guard`], in standard errors: a hold is kept when
/// its refit costs no more than holding one parameter this far from its
/// optimum does to first order. A quarter past the ±2 of
/// [`LEAN_STANDARD_ERRORS`]: a hold at that edge costs `½·2²·s² = 2s²` to
/// first order, so a guard of exactly `2s²` would keep or refuse it by the
/// last digits of where its refit stopped; `½·2.25²·s² ≈ 2.5s²` keeps it,
/// and on few residuals still refuses the holds the data reject (on the
/// many of a rig file, [`SIGMA_RISE`] decides).
pub(crate) const GUARD_STANDARD_ERRORS: f64 = 2.25;

/// The rise of σ, relative, that a hold may always cost: the residuals
/// of a tyre model on rig data are its form's error more than the rig's
/// noise, correlated along each sweep, so the statistical guard, which
/// takes them for independent noise, calls on tens of thousands of points
/// a rise of σ by a thousandth significant. A hold that raises σ by under
/// 5 % of itself (0.08 points of a 1.7 % fit) stays within what the model
/// form leaves: on the Hoosier file PAC89's aligning c9 held at its ±2
/// edge (σ 16.28 % → 16.30 %) is kept, UniTire's aligning c9 held at its
/// start value (9.67 % → 25.1 %) is not.
pub(crate) const SIGMA_RISE: f64 = 0.05;

/// The most a hold may raise the cost (`½Σe²`) of a fit of `cost` on
/// `count` residuals and `free` parameters and be kept (module notes):
/// `½·z²·s²` at `z` = [`GUARD_STANDARD_ERRORS`], with the residual
/// variance `s² = Σe²/dof = 2·cost/dof` the standard errors are scaled by,
/// or the cost of σ rising by [`SIGMA_RISE`] of itself, whichever is
/// larger.
pub(crate) fn guard(cost: f64, count: usize, free: usize) -> f64 {
    let dof = count.saturating_sub(free).max(1) as f64;
    let s2 = 2.0 * cost / dof;
    let statistical = 0.5 * GUARD_STANDARD_ERRORS * GUARD_STANDARD_ERRORS * s2;
    statistical.max(cost * ((1.0 + SIGMA_RISE).powi(2) - 1.0))
}

/// The distance, in standard errors, past which a stated value is said
/// to lie where the data would not put it: the free fit's value ± two
/// standard errors is about the 95 % interval the data allow.
pub(crate) const LEAN_STANDARD_ERRORS: f64 = 2.0;

/// The value a flagged parameter is held at (module notes): `stated` when
/// it lies within [`LEAN_STANDARD_ERRORS`] standard errors `se` of the
/// free fit's `fitted` or there is no standard error; else the end of
/// `fitted ± 2·se` nearest `stated`, clamped into `bounds`, rounded
/// towards `fitted` to a hundredth of the standard error's decade (−0.828
/// for −0.8296 with a standard error of 0.317): a value that reads as
/// written in the file's header and on a `--hold` option, still inside
/// the interval.
pub(crate) fn held_value(stated: f64, fitted: f64, se: Option<f64>, bounds: (f64, f64)) -> f64 {
    match (standard_errors_away(stated, fitted, se), se) {
        (Some(z), Some(se)) if z > LEAN_STANDARD_ERRORS => {
            let reach = LEAN_STANDARD_ERRORS * se;
            let edge = fitted + reach.copysign(stated - fitted);
            let step = 10f64.powf(se.log10().floor() - 2.0);
            let towards = if edge > fitted { f64::floor } else { f64::ceil };
            let rounded = towards(edge / step) * step;
            // The rounding's last bit, read back through `{}`.
            let rounded: f64 = format!("{rounded:.12e}").parse().unwrap_or(rounded);
            rounded.clamp(bounds.0.min(bounds.1), bounds.1.max(bounds.0))
        }
        _ => stated,
    }
}

/// How many standard errors `stated` lies from the free fit's `fitted`
/// (`None` without a finite, positive standard error).
pub(crate) fn standard_errors_away(stated: f64, fitted: f64, se: Option<f64>) -> Option<f64> {
    se.filter(|s| s.is_finite() && *s > 0.0)
        .map(|s| (stated - fitted).abs() / s)
}

/// `z` standard errors to one decimal, or to as many more as keep its
/// side of [`LEAN_STANDARD_ERRORS`]: 2.04 beyond the limit is not said as
/// "2.0", the limit itself (up to six decimals; then the limit's side is
/// said by the sentence around it).
pub(crate) fn z_text(z: f64) -> String {
    let side = |v: f64| v.partial_cmp(&LEAN_STANDARD_ERRORS);
    // On the same side of the ±2 as `z`, and not 0 unless it is (a value
    // 0.003 standard errors away is not "0.0" away).
    let keeps = |t: &String| {
        let v = t.parse::<f64>().ok();
        v.and_then(side) == side(z) && (z == 0.0 || v != Some(0.0))
    };
    (1..=6)
        .map(|d| format!("{z:.d$}"))
        .find(keeps)
        .unwrap_or_else(|| format!("{z:.6}"))
}

/// Where a held value stands, as its line says it: `held` against the
/// `stated` value (named by `what`, "the model's start value") and how
/// many standard errors the stated value lay from the free fit (`away`,
/// [`standard_errors_away`]), by the free fit's linearisation: a fit
/// stopped in a local minimum, or a trade-off far from linear, misjudges
/// it, so the words claim no more (one line said a template's true value
/// lay "where the data would not put it", 25 standard errors from a
/// local minimum). For a fit whose holds try the stated value first
/// ([`HoldFit::stated_first`]), [`held_at_tried`].
pub(crate) fn held_at(what: &str, stated: f64, held: f64, away: Option<f64>) -> String {
    held_words(what, stated, held, away, false)
}

/// [`held_at`] for a fit whose holds try the stated value first
/// ([`HoldFit::stated_first`]): a value held off the stated one was
/// held there first and refused by the [`guard`], said so; a stated value
/// held past the ±2 passed it, said so.
pub(crate) fn held_at_tried(what: &str, stated: f64, held: f64, away: Option<f64>) -> String {
    held_words(what, stated, held, away, true)
}

/// The words of [`held_at`] and [`held_at_tried`] (`tried`).
fn held_words(what: &str, stated: f64, held: f64, away: Option<f64>, tried: bool) -> String {
    // The stated value as the user would give it back with `--hold`.
    let stated_text = exact(stated);
    let edge = format!(
        "held at {}, the end of the free fit's ±{LEAN_STANDARD_ERRORS:.0} standard errors nearest {what} {stated_text}",
        rounded(held, 5)
    );
    match away {
        // Moved off the stated value: to the nearest the data allow.
        Some(z) if held != stated && tried => format!(
            "{edge} (which lies {} standard errors from the free fit: held there first, with the rest refitted, it raised the cost past what a hold may, so the data reject it)",
            z_text(z)
        ),
        Some(z) if held != stated => format!(
            "{edge} (which lies {} standard errors from the free fit, by its linearisation)",
            z_text(z)
        ),
        Some(z) if z > LEAN_STANDARD_ERRORS => format!(
            "held at {what} {stated_text}, which lies {} standard errors from the free fit, outside the ±{LEAN_STANDARD_ERRORS:.0} of its linearisation, and held there, with the rest refitted, it costs no more than the data allow (within the guard)",
            z_text(z)
        ),
        Some(z) => format!(
            "held at {what} {stated_text}, {} standard errors from the free fit (within the ±{LEAN_STANDARD_ERRORS:.0} standard errors the data allow)",
            z_text(z)
        ),
        None => format!("held at {what} {stated_text}"),
    }
}

/// The clause a held line of parameter `name` ends with when the value
/// held is not its stated one, or is one the data lean against (more than
/// [`LEAN_STANDARD_ERRORS`] from the free fit, `away`): the option that
/// holds it where the user says; empty otherwise.
pub(crate) fn lean_clause(name: &str, stated: f64, held: f64, away: Option<f64>) -> String {
    if held != stated || away.is_some_and(|z| z > LEAN_STANDARD_ERRORS) {
        format!("; to hold it at a value of your own, give --hold {name}=VALUE")
    } else {
        String::new()
    }
}

#[cfg(test)]
#[path = "spare_tests.rs"]
mod tests;
