//! Screening the single effects before their cross-validation: a
//! candidate whose fit on all runs removes too little of the in-sample gap
//! above noise to pass on held-out runs is not refitted fold by fold.
//!
//! The rule. Every single effect is fitted on all runs first; its in-sample
//! reduction `R_in = 1 − G_in,after/G_in,before` (the gap above noise of
//! the all-run fits, see [`crate::diagnose::verdict::score`]) costs nothing more. A
//! candidate is screened when `R_in + `[`SCREEN_MARGIN`]` < `[`ACCEPT`]
//! (in percent; [`rules::screened`]). Its held-out reduction `R_out` is then below the
//! acceptance share as long as `R_out ≤ R_in + SCREEN_MARGIN`: the fold
//! refits see fewer runs than the all-run fit, so an effect removes less
//! of the gap on the runs it did not see than on those it was fitted to,
//! and the base model, refitted on the same folds, loses about as much on
//! them. `R_out − R_in` stays within a few points on every campaign of
//! the confusion matrices and on the racing log (the largest measured is
//! in the book's table); the margin is several times that, and the test
//! of the screening checks it on every candidate.
//!
//! Why a screened candidate can never be the verdict (nor change it): the
//! search ([`crate::diagnose::verdict::search`]) reads a single's held-out score in three
//! places. (1) A look-alike, which can start another search and is reported
//! as confounded, must remove [`ACCEPT`] on held-out runs: a screened one
//! cannot. (2) The search starts from the best single, or a simpler one
//! within [`PARSIMONY`] noise levels of it: a screened candidate whose
//! least possible held-out error ([`Baseline::heldout_floor`] of
//! `R_in + SCREEN_MARGIN`) could reach that window is cross-validated
//! after all. (3) Without a verdict, the statement names the best single:
//! likewise. A screened single still joins sets in the greedy additions,
//! from its all-run fit (which is all they use of it). Without a
//! significant gap nothing is searched, and every candidate below the
//! threshold stays screened.
//!
//! The greedy additions are screened alike ([`screened_additions`]): a set
//! is added where it removes [`ACCEPT`] of the held-out gap the current set
//! leaves, so a step whose every set removes less than `ACCEPT −
//! SCREEN_MARGIN` of the in-sample gap the current set leaves adds none
//! (the current set, refitted on the same folds, in the base model's
//! place), and its sets are listed as screened with the set they extend.
//! Where one set could pass, every set the pick among them can read is
//! cross-validated (`search/spare.rs`): the pick reads them as it does
//! without screening.

use crate::diagnose::effects::{joined, set_of, EffectKind};
use crate::diagnose::report::{Ranked, Screened};
use crate::diagnose::verdict::baseline::Baseline;
#[cfg(doc)]
use crate::diagnose::verdict::rules::PARSIMONY;
use crate::diagnose::verdict::rules::{self, ACCEPT, SCREEN_MARGIN};
use crate::diagnose::verdict::score::{Context, Fitted, Scored};
use rayon::prelude::*;

/// A single effect fitted on all runs: cross-validated, or screened (its
/// all-run fit kept, with the linearisation its folds would start from).
enum Slot<'a> {
    Scored(Scored),
    Screened(Fitted<'a>, f64),
}

/// The single effects fitted on all runs and cross-validated unless
/// screened (`screening` on): every single as scored (a screened one
/// without held-out errors), the cross-validated ones ordered by held-out
/// error, the screened ones (indices), and their report rows.
pub(crate) fn singles(
    ctx: &Context,
    effects: &[EffectKind],
    base: &Baseline,
    screening: bool,
    significant: bool,
) -> (Vec<Scored>, Vec<usize>, Vec<usize>, Vec<Screened>) {
    let screens = screening && base.insample_gap();
    let mut slots: Vec<Slot> = effects
        .par_iter()
        .map(|e| {
            // Seeded by the effect's name: its fit does not depend on
            // which other effects the campaign lists.
            let f = ctx.fit_all(vec![*e], &[], e.seed());
            let inside = base.insample_reduction(&f.insample);
            if screens && rules::screened(inside) {
                Slot::Screened(f, inside)
            } else {
                Slot::Scored(ctx.cross_validate(&f))
            }
        })
        .collect();
    if significant {
        recheck(ctx, base, &mut slots);
    }
    let mut screened_rows = Vec::new();
    let mut screened = Vec::new();
    let mut singles = Vec::with_capacity(slots.len());
    for (i, slot) in slots.into_iter().enumerate() {
        match slot {
            Slot::Scored(sc) => singles.push(sc),
            Slot::Screened(f, inside) => {
                screened.push(i);
                let sc = f.unscored();
                screened_rows.push(screened_row(&sc, inside, None, base));
                singles.push(sc);
                if let Some(rec) = ctx.timing {
                    rec.candidate(false);
                }
                // The folds it was spared count as done.
                for _ in 0..ctx.folds.len() {
                    ctx.tick();
                }
            }
        }
    }
    // The cross-validated ones best first ([`rules::best_first`]).
    let scales = ctx.scales;
    let scored: Vec<usize> = (0..singles.len())
        .filter(|i| !screened.contains(i))
        .collect();
    let errors: Vec<f64> = scored
        .iter()
        .map(|&i| singles[i].heldout.combined(&scales))
        .collect();
    let order = rules::best_first(&errors)
        .into_iter()
        .map(|k| scored[k])
        .collect();
    (singles, order, screened, screened_rows)
}

/// Cross-validates the screened candidates the search could read: those
/// whose least possible held-out error reaches the best cross-validated
/// one's (every candidate, and the non-degenerate ones widened by
/// [`PARSIMONY`] noise levels; [`rules::reaches`]). A candidate so added
/// can only lower the best: one pass suffices.
fn recheck(ctx: &Context, base: &Baseline, slots: &mut [Slot]) {
    let scales = ctx.scales;
    let (mut best, mut best_usable) = (f64::INFINITY, f64::INFINITY);
    for slot in slots.iter() {
        if let Slot::Scored(sc) = slot {
            let j = sc.heldout.combined(&scales);
            best = best.min(j);
            if !base.degenerate(sc) {
                best_usable = best_usable.min(j);
            }
        }
    }
    let reach: Vec<usize> = slots
        .iter()
        .enumerate()
        .filter_map(|(i, slot)| match slot {
            Slot::Screened(f, inside) => {
                let floor = base.heldout_floor(inside + SCREEN_MARGIN);
                let usable = !base.degenerate(&f.unscored());
                rules::reaches(floor, usable, best, best_usable, base.jn).then_some(i)
            }
            Slot::Scored(_) => None,
        })
        .collect();
    let scored: Vec<(usize, Scored)> = reach
        .par_iter()
        .filter_map(|&i| match &slots[i] {
            Slot::Screened(f, _) => Some((i, ctx.cross_validate(f))),
            Slot::Scored(_) => None,
        })
        .collect();
    for (i, sc) in scored {
        slots[i] = Slot::Scored(sc);
    }
}

/// A screened candidate as a row of the report: its in-sample reduction
/// `inside` (%) of the gap the base leaves, or where it `extends` a set,
/// of the gap that set leaves.
pub(crate) fn screened_row(
    sc: &Scored,
    inside: f64,
    extends: Option<&[EffectKind]>,
    base: &Baseline,
) -> Screened {
    Screened {
        effect: joined(&sc.kinds, "+"),
        effects: sc.kinds.clone(),
        extends: extends.map(<[EffectKind]>::to_vec).unwrap_or_default(),
        insample_error_after: sc.insample.combined(&base.scales()),
        insample_reduction_percent: inside,
        threshold_percent: 100.0 * ACCEPT,
        margin_percent: SCREEN_MARGIN,
        delta_bic: base.delta_bic(sc),
        global_search: sc.full.global,
        outranked: None,
    }
}

/// Keeps one screened row per set of effects, none for a set another
/// greedy search cross-validated (`rows`).
pub(crate) fn one_screened_row_per_set(screened: &mut Vec<Screened>, rows: &[Ranked]) {
    let mut seen: std::collections::HashSet<Vec<EffectKind>> =
        rows.iter().map(|r| set_of(&r.effects)).collect();
    screened.retain(|r| seen.insert(set_of(&r.effects)));
}

/// The greedy step's screening: where `screening` is on and every set
/// `fitted` (the current set with one effect added, fitted on all runs)
/// removes less than [`ACCEPT`] less [`rules::SCREEN_MARGIN`] of the
/// in-sample gap above noise the current set leaves
/// ([`Baseline::insample_extra`]), none can remove [`ACCEPT`] of its
/// held-out gap (the single effects' screening argument,
/// [`crate::diagnose::verdict::screening`], with the current set in the
/// base model's place: it is refitted on the same folds), so none can be
/// added: their rows as screened, their folds spared. None: at least one
/// could be added, and every set is cross-validated (the pick among them
/// reads every held-out error, as without screening).
pub(crate) fn screened_additions(
    ctx: &Context,
    base: &Baseline,
    current: &Scored,
    fitted: &[Fitted],
    screening: bool,
) -> Option<Vec<Screened>> {
    if !screening {
        return None;
    }
    let extra: Vec<f64> = fitted
        .iter()
        .map(|f| base.insample_extra(&current.insample, &f.insample))
        .collect::<Option<_>>()?;
    if !extra.iter().all(|&x| rules::screened(x)) {
        return None;
    }
    let rows = fitted
        .iter()
        .zip(extra)
        .map(|(f, x)| {
            if let Some(rec) = ctx.timing {
                rec.candidate(false);
            }
            // The folds it was spared count as done.
            for _ in 0..ctx.folds.len() {
                ctx.tick();
            }
            screened_row(&f.unscored(), x, Some(&current.kinds), base)
        })
        .collect();
    Some(rows)
}
