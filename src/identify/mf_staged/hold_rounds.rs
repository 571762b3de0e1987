//! The rounds that hold a stage's parameters the data do not determine
//! (the rule and its words: `holds.rs`; its core, shared with the swarm
//! fits: `identify/spare.rs`): each round tries the flagged parameters'
//! holds side by side, keeps the one the fit can best spare, refits, and
//! records the holds the guard refused (`hold_refusal.rs`), until no free
//! parameter is flagged. Costs are `½Σe²` of the stage's residuals (N² or
//! (N·m)²); σ is % of the channel's RMS.

use super::curvature_clip::{at_clip, AtClip};
use super::hold_guard::{guarded_refit, Fitted, Refit};
use super::hold_refusal::{refused_hold, RefusedHold};
use super::holds::{near_bound, HoldReason, HoldSource};
use super::params::Need;
use super::problem::StageProblem;
use super::uncertainty::{uncertainty, Uncertainty};
use crate::identify::spare::{
    candidates, spare, standard_errors_away, HoldFit, HoldWays, Spared, TieBreak, Tried,
};
use crate::optim::bounded::BoundedLm;

/// A stage's fit in progress: its problem and its free parameters (with
/// the levels each needs) at `p`, within `bounds`, started at `starts`.
pub(super) struct StageFit<'a> {
    pub(super) problem: StageProblem<'a>,
    pub(super) needs: Vec<Need>,
    pub(super) p: Vec<f64>,
    pub(super) bounds: Vec<(f64, f64)>,
    pub(super) starts: Vec<f64>,
}

impl StageFit<'_> {
    /// Parameter `k` held at `value`, out of the free ones.
    pub(super) fn hold_out(&mut self, k: usize, value: f64) {
        self.problem = held_out(&self.problem, &self.p, k, value);
        self.p.remove(k);
        self.needs.remove(k);
        self.starts.remove(k);
        self.bounds.remove(k);
    }
}

/// What the holds of a stage came to: each parameter held, with its
/// value and reason, and each whose hold the guard refused, with what was
/// tried and what it cost (`hold_refusal.rs`).
#[derive(Default)]
pub(super) struct HoldOutcome {
    pub(super) held: Vec<(&'static str, f64, HoldReason)>,
    pub(super) refused: Vec<(&'static str, RefusedHold)>,
}

/// Holds the parameters of `fit` the data do not determine at their
/// `stated` values, one at a time (module notes). The hold is chosen by
/// refitting the rest from the optimum (Levenberg–Marquardt within the
/// bounds); the one chosen is then refitted by the stage's own fit from
/// its start values (`refit`) too, and the better of the two kept: a
/// warm start that jumped one coefficient can stall where a fresh one
/// does not. Returns each held parameter with its value and reason, and
/// each refused; adds the residual evaluations to `evaluations`.
pub(super) fn hold_undetermined(
    fit: &mut StageFit,
    stated: &dyn Fn(&str) -> (f64, HoldSource),
    refit: &Refit,
    iterations: usize,
    evaluations: &mut usize,
) -> HoldOutcome {
    let mut out = HoldOutcome::default();
    let lm = BoundedLm {
        iterations,
        tolerance: 1e-12,
        ..BoundedLm::default()
    };
    while fit.p.len() > 1 {
        let u = uncertainty(&fit.problem, &fit.p);
        // A curvature coefficient the data do not move because its factor
        // sits at the clip E ≤ 1 over every row it shapes is held where the
        // fit left it, as `--start paper` holds it (`curvature_clip.rs`),
        // not at a stated value for want of data.
        if let Some((k, clip)) = clipped(fit, &u) {
            let (name, fitted) = (fit.problem.names[k], fit.p[k]);
            fit.hold_out(k, fitted);
            let why = HoldReason::AtCurvatureClip { fitted, clip };
            out.held.push((name, fitted, why));
            continue;
        }
        let Spared {
            kept,
            refusals,
            evaluations: n,
            ..
        } = round(fit, &u, stated, (refit, &lm), &out.refused);
        *evaluations += n;
        // Refused: left free, with their warning and what the hold
        // cost, and not tried again (`spare.rs`).
        for r in &refusals {
            let name = fit.problem.names[r.k];
            let se = off_bound_error(&u, r.k, fit.p[r.k], fit.bounds[r.k]);
            let why = refused_hold((&fit.problem, &fit.p), r, stated(name), se, fit.needs[r.k]);
            out.refused.push((name, why));
        }
        let Some(tried) = kept else {
            if refusals.is_empty() {
                break;
            }
            continue;
        };
        let (name, value) = (fit.problem.names[tried.k], tried.value);
        let mut why = not_identifiable(fit, &u, tried.k, stated(name), value);
        let free = fit.problem.sigma_percent(&fit.p);
        keep(fit, tried, refit, evaluations);
        if let HoldReason::NotIdentifiable {
            sigma_held_free, ..
        } = &mut why
        {
            *sigma_held_free = Some([fit.problem.sigma_percent(&fit.p), free]);
        }
        out.held.push((name, value, why));
    }
    number_holds(&mut out.held);
    out
}

/// Each hold for want of data in `held` numbered in the order it was
/// made, of how many: a held line's σ is its round's, and the stage's
/// σ at the end of its own fit is the last one's σ held.
fn number_holds(held: &mut [(&'static str, f64, HoldReason)]) {
    let counted = |why: &HoldReason| matches!(why, HoldReason::NotIdentifiable { .. });
    let n = held.iter().filter(|h| counted(&h.2)).count();
    let mut i = 0;
    for (.., why) in held.iter_mut() {
        if let HoldReason::NotIdentifiable { hold_order, .. } = why {
            i += 1;
            *hold_order = Some([i, n]);
        }
    }
}

/// The first free parameter of `fit` without a standard error (at its
/// uncertainty `u`) that its curvature factor's clip holds, with where.
fn clipped(fit: &StageFit, u: &Uncertainty) -> Option<(usize, AtClip)> {
    (0..fit.p.len())
        .filter(|&k| u.std_error[k].is_none())
        .find_map(|k| at_clip(&fit.problem, &fit.p, k).map(|c| (k, c)))
}

/// One round of holds on `fit` at its uncertainty `u`: the flagged
/// parameters not `refused` before tried side by side at their `stated`
/// values, each refitted from the optimum by `lm` and, past the guard,
/// by the stage's own `refit` (`hold_guard.rs`).
fn round<'a>(
    fit: &StageFit<'a>,
    u: &Uncertainty,
    stated: &dyn Fn(&str) -> (f64, HoldSource),
    (refit, lm): (&Refit, &BoundedLm),
    refused: &[(&'static str, RefusedHold)],
) -> Spared<StageProblem<'a>> {
    let relative = |k: usize| {
        u.std_error[k].map_or(f64::INFINITY, |s| s / fit.p[k].abs().max(f64::MIN_POSITIVE))
    };
    let flagged: Vec<usize> = (0..fit.p.len())
        .filter(|&k| u.flagged(k, fit.p[k]) && !refused.iter().any(|r| r.0 == fit.problem.names[k]))
        .collect();
    // The stated values up front: the holds are tried side by side.
    let values: Vec<f64> = fit.problem.names.iter().map(|n| stated(n).0).collect();
    let (problem, p) = (&fit.problem, &fit.p);
    let ways = HoldWays {
        without: |k: usize, value: f64| held_out(problem, p, k, value),
        stated: |k: usize| values[k],
        compensating: |k: usize, dv: f64| u.compensating(k, dv),
        refit: |sub: &StageProblem, x: &[f64], b: &[(f64, f64)]| {
            guarded_refit(fit.at(), sub, lm.minimize(sub, x, b), b, refit)
        },
    };
    // A standard error taken at a bound means nothing: a parameter
    // stopped there is held at its stated value, as its line says, not
    // at the end of ±2 of them (QBZ1 was said held at the template's
    // 11.692 and written as 2.98, twice a meaningless error off 0).
    let std_errors: Vec<Option<f64>> = (0..p.len())
        .map(|k| off_bound_error(u, k, p[k], fit.bounds[k]))
        .collect();
    let holding = HoldFit {
        problem,
        p,
        std_errors: &std_errors,
        bounds: &fit.bounds,
        clamp_starts: true,
        tie: TieBreak::LatestInOrder,
        guarded: true,
        stated_first: true,
    };
    spare(&holding, &candidates(flagged, relative), &ways)
}

impl<'a> StageFit<'a> {
    /// The fit as the guard reads it: problem, point, needs and starts.
    fn at(&self) -> Fitted<'_, 'a> {
        Fitted {
            problem: &self.problem,
            p: &self.p,
            needs: &self.needs,
            starts: &self.starts,
        }
    }
}

/// The stage's `problem` at `p` with its `k`-th parameter held at
/// `value`: the tyre with it set, and the rest free.
pub(super) fn held_out<'a>(
    problem: &StageProblem<'a>,
    p: &[f64],
    k: usize,
    value: f64,
) -> StageProblem<'a> {
    let mut base = problem.tyre(p);
    base.coefficients.set(problem.names[k], value);
    let mut names = problem.names.clone();
    names.remove(k);
    StageProblem::new(
        base,
        problem.stage,
        names,
        problem.rows.clone(),
        problem.derivatives,
    )
}

/// The standard error of the `k`-th parameter (at `v`, within `bounds`),
/// none where it stopped at a bound: a standard error taken there means
/// nothing.
fn off_bound_error(u: &Uncertainty, k: usize, v: f64, bounds: (f64, f64)) -> Option<f64> {
    u.std_error[k].filter(|_| near_bound(v, bounds).is_none())
}

/// Why the `k`-th parameter of `fit` is held at `held_at`: not
/// identifiable, with its fitted value, standard error and effect, its
/// stated value and source (`stated`), and the bound it stopped at.
fn not_identifiable(
    fit: &StageFit,
    u: &Uncertainty,
    k: usize,
    (value, source): (f64, HoldSource),
    held_at: f64,
) -> HoldReason {
    // At a bound the standard error and its effect are taken as if the
    // box were not there: not reported (null in the report too).
    let at_bound = near_bound(fit.p[k], fit.bounds[k]);
    let std_error = u.std_error[k].filter(|_| at_bound.is_none());
    HoldReason::NotIdentifiable {
        fitted: fit.p[k],
        std_error,
        effect_percent: match at_bound {
            None => 100.0 * u.effect[k],
            Some(_) => f64::NAN,
        },
        source,
        stated: value,
        held_at,
        standard_errors_away: standard_errors_away(value, fit.p[k], std_error),
        at_bound,
        sigma_held_free: None,
        hold_order: None,
    }
}

/// `fit` with the hold `tried` kept: its problem, and of its refit from
/// the optimum and the stage's own fit of it from its start values
/// (`refit`) the better (a warm start that jumped one coefficient can
/// stall where a fresh one does not). Adds the residual evaluations to
/// `evaluations`.
fn keep<'a>(
    fit: &mut StageFit<'a>,
    tried: Tried<StageProblem<'a>>,
    refit: &Refit,
    evaluations: &mut usize,
) {
    let Tried {
        k,
        problem,
        p: mut refitted,
        cost,
        ..
    } = tried;
    fit.needs.remove(k);
    fit.starts.remove(k);
    fit.bounds.remove(k);
    let fresh = refit(&problem, &fit.needs, &fit.starts, &fit.bounds);
    *evaluations += fresh.evaluations;
    if fresh.cost.is_finite() && fresh.cost < cost {
        refitted = fresh.params;
    }
    fit.problem = problem;
    fit.p = refitted;
}
