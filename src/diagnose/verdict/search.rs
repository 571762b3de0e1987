//! The verdict's search: which effects, alone or together, explain the gap
//! between the base model and the runs.
//!
//! Every candidate is ranked against the base model ([`Baseline`]): its
//! held-out error `J` after, and its reduction `1 − G_after/G_before` of the
//! held-out gap above noise `G = sqrt(J² − J_n²)` (see [`crate::diagnose::verdict::score`]),
//! with warnings where its in-sample reduction exceeds the held-out one by
//! [`DISAGREEMENT`] points or its axles are no tyre.
//!
//! The best single effect is accepted when it removes at least [`ACCEPT`]
//! of the held-out gap above noise and lowers the BIC; where the best leaves
//! a parameter idle, a simpler single within [`PARSIMONY`] noise levels is
//! taken instead. More effects are added greedily (jointly refitted) while
//! each removes [`ACCEPT`] of what is left (starting from a best single that
//! removes at least [`PROMISING`], so that two effects that each explain
//! only part of the gap are found together; the set must then pass as a
//! whole). While the set found leaves a gap above [`SIGNIFICANT`]·J_n, the
//! search starts again from up to [`ALTERNATIVE_STARTS`] look-alikes of the
//! best single; with no verdict yet, from the pairs of [`super::pairs`].
//! Effects that also pass and leave a gap above noise within
//! [`CONFOUNDED`]·G + [`CONFOUNDED_NOISE`]·J_n of the accepted one's G are
//! reported as confounded with it, with the experiment that would separate
//! them. Each of these rules is a pure function in
//! [`crate::diagnose::verdict::rules`], tested there.
//!
//! A greedy step cross-validates only the sets its pick can read: a set
//! whose least possible held-out error (its in-sample share plus the
//! screening's margin) lies beyond the pick's windows around the step's
//! best is reported with that bound instead ([`spare`]).
//!
//! A candidate's fitted vector is read through its [`Layout`] (the axle
//! characteristics, each effect's parameters, the roll dynamics), and a
//! combination starts from [`Layout::combined`] of its members' fits.
//!
//! Units: SI, rad; J is dimensionless (residuals over channel scales),
//! reductions in percent. The method is the project's own (see
//! [`crate::diagnose::pipeline`] for the overview).

use crate::diagnose::effects::EffectKind;
use crate::diagnose::fit::layout::Layout;
use crate::diagnose::model::channels::{gap_above, reduction};
use crate::diagnose::report::{Confounded, Lookalike, Lookalikes, Ranked, Refused, Screened};
use crate::diagnose::verdict::baseline::Baseline;
use crate::diagnose::verdict::pairs::{paired, Fallback, Simpler};
use crate::diagnose::verdict::restricted::{screen_step, Step};
use crate::diagnose::verdict::rules::{self, Candidate};
#[cfg(doc)]
use crate::diagnose::verdict::rules::{
    ACCEPT, ALTERNATIVE_STARTS, CONFOUNDED, CONFOUNDED_NOISE, DISAGREEMENT, PARSIMONY, PROMISING,
    SIGNIFICANT,
};
use crate::diagnose::verdict::score::{Context, Scored, Started};
use crate::diagnose::verdict::screening::one_screened_row_per_set;
use crate::diagnose::verdict::twins::simpler_twin;
use rayon::prelude::*;
use rows::{one_row_per_set, worse_than_subsets};
use spare::{cross_validated, spared_row, Spared};

mod rows;
mod spare;

/// What the search for a verdict found.
#[derive(Default)]
pub(crate) struct Search<'a> {
    /// The accepted set, if any.
    pub(crate) chosen: Option<Scored>,
    /// Every combination tried, as report rows.
    pub(crate) combinations: Vec<Ranked>,
    /// Singles (indices) that pass and leave about the best's gap.
    pub(crate) lookalikes: Vec<usize>,
    /// The single the search started from (an index into the singles).
    pub(crate) start: Option<usize>,
    /// The best single where it was pressed on a search bound and the
    /// search started from a look-alike inside its ranges instead.
    pub(crate) passed_over: Option<usize>,
    /// Where no set was accepted, the one the search ended on and why it
    /// was refused.
    pub(crate) ended: Option<Refused>,
    /// Sets the greedy additions screened instead of cross-validating
    /// ([`screened_additions`]), one row per set.
    pub(crate) screened: Vec<Screened>,
    /// Where a set was accepted, each candidate its search passed over for
    /// a simpler one on the way to it (the start, then each added effect).
    pub(crate) simpler: Vec<Simpler>,
    /// Where the greedy search ended with no verdict and a pair of the
    /// best singles in sample ([`paired`]) started the one that reached it.
    pub(crate) fallback: Option<Fallback>,
    /// Where the accepted set gave way to a simpler twin (a look-alike in
    /// its first effect's place, [`simpler_twin`]): the single it had been
    /// grown from.
    pub(crate) grown_from: Option<EffectKind>,
    /// Sets the greedy steps did not cross-validate, their pick being
    /// unable to read them ([`spare`]), until the search ends.
    spared: Vec<Spared<'a>>,
}

/// The singles scored, the cross-validated ones' order, their ranking, the
/// screened ones' rows, and the search (as the pipeline takes them).
pub(crate) type Searched<'a> = (
    Vec<Scored>,
    Vec<usize>,
    Vec<Ranked>,
    Vec<Screened>,
    Search<'a>,
);

/// The verdict's search: the best single (`order` ranks the
/// cross-validated `singles` by held-out error), then greedy additions,
/// each tried jointly with every remaining effect (`all`: those in `order`
/// and the screened ones, whose all-run fits start them).
pub(crate) fn search<'a>(
    ctx: &Context<'a>,
    singles: &[Scored],
    (order, all): (&[usize], &[usize]),
    base: &Baseline,
    limits: (usize, bool),
) -> Search<'a> {
    let mut out = Search::default();
    // A single whose axles are no tyre cannot be the verdict, nor start
    // one; it can still join a set (a steer lag whose axles collapse
    // alone on a banked oval is a tyre's once the bank is in), so the
    // greedy additions try every effect (`all`).
    let ranked: Vec<Candidate> = order.iter().map(|&i| base.candidate(&singles[i])).collect();
    let jn = base.jn;
    // The best, or a simpler one that does as well where the best leaves a
    // parameter idle: a steer path whose lag stays off is a steer delay,
    // one with a sensor delay on runs whose every response comes from the
    // steer, and must not win on the interpolation's rounding.
    let Some(picked) = rules::pick(&ranked, jn) else {
        return out;
    };
    let first = order[picked];
    out.start = Some(first);
    // The best whose axles are a tyre, where the pick passed it over for
    // being pressed on a search bound.
    out.passed_over = rules::passed_over(&ranked, jn).map(|k| order[k]);
    let best = &singles[first];
    let start_simpler = rules::simpler_than(&ranked, jn).map(|k| Simpler {
        over: singles[order[k]].clone(),
        taken: best.clone(),
    });
    let r = base.rank(best);
    // A best single below the acceptance share can still be half of a
    // pair of effects: the greedy search starts from it when it is
    // promising, and the set found must pass as a whole.
    if !rules::promising(r.reduction_percent, r.delta_bic) {
        out.ended = Some(base.refused(best, None, None));
        return out;
    }
    let usable: Vec<usize> = order
        .iter()
        .zip(&ranked)
        .filter(|(_, c)| !c.degenerate)
        .map(|(&i, _)| i)
        .collect();
    out.lookalikes = lookalikes(singles, &usable, first, &r, base);
    let (current, mut simpler) = greedy(ctx, singles, all, base, limits, best, &mut out);
    simpler.splice(0..0, start_simpler);
    let mut found = restarted(
        ctx,
        (singles, all),
        base,
        limits,
        (current, simpler),
        &mut out,
    );
    if let Some(k) = rules::degenerate_lead(&ranked, picked) {
        let lead = &singles[order[k]];
        if let Some(led) = led_by(
            ctx,
            (singles, all),
            base,
            limits,
            (lead, &found.0),
            &mut out,
        ) {
            out.start = Some(order[k]);
            found = led;
        }
    }
    let found = fallen_back(ctx, (singles, all), base, limits, found, &mut out);
    concluded(ctx, (singles, all), base, found, &mut out);
    out
}

/// The greedy searches again from the look-alikes of the best single. The
/// best single can be a look-alike that mimics part of a pair and leads
/// the greedy search away from it (a fast, lightly damped roll steering
/// the axles looks like a yaw inertia and aero load together). While the
/// set found (`found`, with the simpler sets passed over on its way)
/// leaves a significant gap, the search starts again from the look-alikes
/// (at most ALTERNATIVE_STARTS), and a set that leaves clearly less of the
/// gap replaces it.
fn restarted<'a>(
    ctx: &Context<'a>,
    (singles, all): (&[Scored], &[usize]),
    base: &Baseline,
    limits: (usize, bool),
    found: (Scored, Vec<Simpler>),
    out: &mut Search<'a>,
) -> (Scored, Vec<Simpler>) {
    let (scales, jn) = (base.scales(), base.jn);
    let (mut current, mut simpler) = found;
    for &i in out
        .lookalikes
        .clone()
        .iter()
        .take(rules::ALTERNATIVE_STARTS)
    {
        let jc = current.heldout.combined(&scales);
        if !rules::significant(jc, jn) {
            break;
        }
        let (other, other_simpler) = greedy(ctx, singles, all, base, limits, &singles[i], out);
        let (g, g_other) = (
            gap_above(jc, jn),
            gap_above(other.heldout.combined(&scales), jn),
        );
        if rules::replaces(g_other, g) {
            (current, simpler) = (other, other_simpler);
        }
    }
    (current, simpler)
}

/// Where the set `found` is no verdict, the greedy search from the best
/// pair of singles in sample ([`paired`]), which replaces it: the truth
/// can be a pair without the best single.
fn fallen_back<'a>(
    ctx: &Context<'a>,
    (singles, all): (&[Scored], &[usize]),
    base: &Baseline,
    limits: (usize, bool),
    found: (Scored, Vec<Simpler>),
    out: &mut Search<'a>,
) -> (Scored, Vec<Simpler>) {
    let scales = base.scales();
    let total = reduction(base.j0, found.0.heldout.combined(&scales), base.jn);
    if rules::accepted(total, found.0.full.bic(), base.bic0()) {
        return found;
    }
    let extend = |s: &Scored, e| extensions(ctx, singles, base, s, &[e]);
    let rows = &mut out.combinations;
    // A set a greedy step spared was tried all the same.
    let spared: Vec<Vec<EffectKind>> = out.spared.iter().map(|s| s.row.effects.clone()).collect();
    let Some((pair, over, from)) = paired(ctx, (singles, all), base, (rows, &spared), extend)
    else {
        return found;
    };
    out.fallback = Some(Fallback {
        ended: found.0.clone(),
        pair: pair.clone(),
        from,
    });
    let (current, mut simpler) = greedy(ctx, singles, all, base, limits, &pair, out);
    simpler.splice(0..0, over);
    (current, simpler)
}

/// The end of the search on the set `found` (with the simpler sets passed
/// over on its way): accepted (or its simpler twin, [`simpler_twin`]), or
/// refused; then the report rows tidied: one per set, warned where worse
/// in sample than a subset, ordered by held-out error.
fn concluded<'a>(
    ctx: &Context<'a>,
    (singles, all): (&[Scored], &[usize]),
    base: &Baseline,
    (current, simpler): (Scored, Vec<Simpler>),
    out: &mut Search<'a>,
) {
    let scales = base.scales();
    let total = reduction(base.j0, current.heldout.combined(&scales), base.jn);
    if rules::accepted(total, current.full.bic(), base.bic0()) {
        out.simpler = simpler;
        let rows = &mut out.combinations;
        match simpler_twin(ctx, (singles, &out.lookalikes), base, &current, rows) {
            Some((twin, over)) => {
                out.grown_from = Some(current.kinds[0]);
                out.simpler.push(over);
                out.chosen = Some(twin);
            }
            None => out.chosen = Some(current),
        }
    } else {
        out.ended = Some(base.refused(&current, None, None));
        out.fallback = None;
    }
    spare::settled(ctx, base, out);
    let chosen = out.chosen.as_ref().map(|c| c.kinds.as_slice());
    one_row_per_set(&mut out.combinations, chosen);
    let members: Vec<&Scored> = all.iter().map(|&i| &singles[i]).collect();
    let spared: Vec<(Vec<EffectKind>, f64)> = (out.screened.iter())
        .filter(|r| r.outranked.is_some())
        .map(|r| (r.effects.clone(), r.insample_error_after))
        .collect();
    worse_than_subsets(&members, &spared, &scales, &mut out.combinations);
    one_screened_row_per_set(&mut out.screened, &out.combinations);
    out.combinations
        .sort_by(|a, b| a.heldout_error_after.total_cmp(&b.heldout_error_after));
}

/// Look-alikes of the first single (`first`, ranked as `r`): the other
/// singles in `order` that also pass and leave about as small a gap above
/// noise ([`rules::lookalike`]).
fn lookalikes(
    singles: &[Scored],
    order: &[usize],
    first: usize,
    r: &Ranked,
    base: &Baseline,
) -> Vec<usize> {
    let jn = base.jn;
    let g_best = gap_above(r.heldout_error_after, jn);
    order
        .iter()
        .copied()
        .filter(|&i| i != first)
        .filter(|&i| {
            let o = base.rank(&singles[i]);
            rules::lookalike(
                o.reduction_percent,
                gap_above(o.heldout_error_after, jn),
                g_best,
                jn,
            )
        })
        .collect()
}

/// The greedy search from `lead`, a single that does better than the one
/// the set `current` grew from but whose axles alone are no tyre
/// ([`rules::degenerate_lead`]), where `current` leaves a significant gap
/// and `lead` is promising: the set it grows, with the simpler ones passed
/// over on the way, where its axles are a tyre and it leaves clearly less
/// of the gap than `current` ([`rules::replaces`]). The sets it tries are
/// report rows either way.
fn led_by<'a>(
    ctx: &Context<'a>,
    (singles, all): (&[Scored], &[usize]),
    base: &Baseline,
    limits: (usize, bool),
    (lead, current): (&Scored, &Scored),
    out: &mut Search<'a>,
) -> Option<(Scored, Vec<Simpler>)> {
    let (scales, jn) = (base.scales(), base.jn);
    let jc = current.heldout.combined(&scales);
    let r = base.rank(lead);
    if !rules::significant(jc, jn) || !rules::promising(r.reduction_percent, r.delta_bic) {
        return None;
    }
    let (other, simpler) = greedy(ctx, singles, all, base, limits, lead, out);
    let g_other = gap_above(other.heldout.combined(&scales), jn);
    (!base.degenerate(&other) && rules::replaces(g_other, gap_above(jc, jn)))
        .then_some((other, simpler))
}

/// Greedy additions from `start`: the effect that best closes what is left,
/// tried jointly with every remaining effect, while each removes
/// [`ACCEPT`] of what is left and lowers the BIC. Every set tried goes into
/// `out.combinations`. Returns the set it ends on and the sets each
/// accepted step passed over for a simpler one.
fn greedy<'a>(
    ctx: &Context<'a>,
    singles: &[Scored],
    order: &[usize],
    base: &Baseline,
    (max_effects, screening): (usize, bool),
    start: &Scored,
    out: &mut Search<'a>,
) -> (Scored, Vec<Simpler>) {
    let (scales, jn) = (base.scales(), base.jn);
    let mut current = start.clone();
    let mut simpler = Vec::new();
    while current.kinds.len() < max_effects {
        let jc = current.heldout.combined(&scales);
        if !rules::significant(jc, jn) {
            break;
        }
        // Every remaining effect: the second effect of a pair is
        // often not among the best singles (those mimic the first).
        let tries: Vec<EffectKind> = order
            .iter()
            .map(|&i| singles[i].kinds[0])
            .filter(|e| !current.kinds.contains(e))
            .collect();
        let started = extensions(ctx, singles, base, &current, &tries);
        // The restricted fits first: the sets they screen are not polished
        // unless a set of the step could be added (`restricted`).
        let fitted = match screen_step(ctx, base, &current, started, screening) {
            Step::Screened(rows) => {
                out.screened.extend(rows);
                break;
            }
            Step::Polished(fitted) => fitted,
        };
        // Only the sets the step's pick can read ([`spare`]).
        let (mut scored, spared) = cross_validated(ctx, base, &current, fitted, screening);
        scored.sort_by(|a, b| {
            a.heldout
                .combined(&scales)
                .total_cmp(&b.heldout.combined(&scales))
        });
        out.combinations
            .extend(scored.iter().map(|sc| base.rank(sc)));
        let bar = spare::best_read(scored.iter(), base);
        let at = out.combinations.len();
        out.spared
            .extend(spared.into_iter().map(|(fitted, x, floor)| {
                let row = spared_row(&fitted, (x, floor), &current.kinds, bar, base);
                Spared { at, fitted, row }
            }));
        // The best set whose axles are a tyre, or a simpler one that does
        // as well where it leaves a parameter idle.
        let ranked: Vec<Candidate> = scored.iter().map(|sc| base.candidate(sc)).collect();
        let Some(k) = rules::pick(&ranked, jn) else {
            break;
        };
        let over = rules::simpler_than(&ranked, jn).map(|t| scored[t].clone());
        let next = scored.swap_remove(k);
        let extra = reduction(jc, next.heldout.combined(&scales), jn);
        if !rules::accepted(extra, next.full.bic(), current.full.bic()) {
            break;
        }
        simpler.extend(over.map(|over| Simpler {
            over,
            taken: next.clone(),
        }));
        current = next;
    }
    (current, simpler)
}

/// The sets of `current` plus each effect of `tries`, their global stage on
/// all runs done ([`Context::started`]). Each set's seed is that of the effect added (its name's, not its place
/// in the ranking, which screening shortens), one apart from its single
/// fit's.
fn extensions<'a>(
    ctx: &Context<'a>,
    singles: &[Scored],
    base: &Baseline,
    current: &Scored,
    tries: &[EffectKind],
) -> Vec<Started<'a>> {
    tries
        .par_iter()
        .map(|e| {
            let mut kinds = current.kinds.clone();
            kinds.push(*e);
            let single = singles.iter().find(|s| s.kinds[0] == *e).expect("scored");
            let layout = base.layout(&current.kinds);
            let members = layout.combined(&current.full.params, *e, &single.full.params);
            let extended = layout.combined(&current.full.params, *e, &ctx.off(&[*e]));
            // Each member's own optimum: the axles the added effect
            // fitted alone want can differ from the current set's.
            let mut own = members.clone();
            let axles = layout.axles();
            own[axles.clone()].copy_from_slice(&single.full.params[axles]);
            let added = alone(&layout, &ctx.off(&current.kinds), *e, &single.full.params);
            let starts = [members, extended, own, added];
            ctx.started(kinds, &starts, e.seed().wrapping_add(1))
        })
        .collect()
}

/// The start of the set of `layout` (the current set's) with `added`
/// appended at the added effect's own single fit `single`, the current
/// set's effects off (`off`, its off vector): the set contains that
/// single, and a fit started only from the current set's basin can stop
/// short of its optimum. Where the current set was taken for parsimony
/// over a twin of the added effect (a sensor delay over a steer path
/// whose lag is idle), the set's fit otherwise ends between the two
/// delays, each undetermined yet well inside its range, and fits the runs
/// worse than the single it contains. Axle characteristics and roll
/// dynamics the added effect fits are its own.
fn alone(layout: &Layout, off: &[f64], added: EffectKind, single: &[f64]) -> Vec<f64> {
    let mut start = layout.combined(off, added, single);
    let one = Layout::new(&[added], layout.axle);
    start[layout.axles()].copy_from_slice(&single[one.axles()]);
    let set = Layout::new(&[layout.kinds.as_slice(), &[added]].concat(), layout.axle);
    if !one.roll().is_empty() {
        start[set.roll()].copy_from_slice(&single[one.roll()]);
    }
    start
}

/// The look-alikes alone the verdict is confounded with (the first group
/// of `confounded`, less its first member, the verdict's own first
/// effect), each with its reduction and gap above noise, and the window of
/// the single the search started from (`start`, an index into `singles`)
/// they lie in ([`rules::lookalike`]). None without a look-alike.
pub(crate) fn lookalikes_alone(
    singles: &[Scored],
    confounded: &[Confounded],
    start: Option<usize>,
    base: &Baseline,
) -> Option<Lookalikes> {
    let (c, start) = (confounded.first()?, &singles[start?]);
    let alone = |e: EffectKind| {
        singles
            .iter()
            .find(|s| s.kinds[0] == e)
            .map(|s| base.rank(s))
    };
    let members: Vec<Lookalike> = c.effects[1..]
        .iter()
        .filter_map(|&effect| {
            let r = alone(effect)?;
            Some(Lookalike {
                effect,
                reduction_percent: r.reduction_percent,
                gap: gap_above(r.heldout_error_after, base.jn),
                // Read against the standstills by the conclusion.
                standstills: None,
                set_aside: None,
            })
        })
        .collect();
    let r = base.rank(start);
    let gap = gap_above(r.heldout_error_after, base.jn);
    (!members.is_empty()).then(|| Lookalikes {
        start: start.kinds[0],
        start_reduction_percent: r.reduction_percent,
        window: rules::window(gap, base.jn),
        members,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use EffectKind::{SensorDelay as D, SteerPath as S};

    #[test]
    fn a_set_starts_too_from_the_added_effect_alone_the_current_set_off() {
        // A sensor delay taken for parsimony over a steer path (lag idle):
        // the pair starts at the steer path's own fit, the delay off.
        let one = Layout::new(&[D], false);
        assert_eq!(alone(&one, &[0.0], S, &[0.0762, 0.0]), [0.0, 0.0762, 0.0]);
        // Axles fitted: the added effect's own.
        let one = Layout::new(&[D], true);
        let off = [1.0, 2.0, 3.0, 0.0];
        let single = [4.0, 5.0, 6.0, 0.07, 0.01];
        assert_eq!(
            alone(&one, &off, S, &single),
            [4.0, 5.0, 6.0, 0.0, 0.07, 0.01]
        );
    }

    #[test]
    fn the_roll_dynamics_of_a_set_started_alone_are_the_added_effects_where_it_fits_them() {
        use EffectKind::{RollCamber, RollSteer};
        let vector = |kinds: &[EffectKind], from: f64| {
            let l = Layout::new(kinds, false);
            let n = l.roll().end;
            (l, (0..n).map(|i| from + i as f64).collect::<Vec<f64>>())
        };
        // The added effect fits roll, the current set does not.
        let (current, off) = vector(&[D], 0.0);
        let (_, single) = vector(&[RollSteer], 10.0);
        let mut want = off.clone();
        want.extend(&single);
        assert_eq!(alone(&current, &off, RollSteer, &single), want);
        // The current set fits roll, the added effect does not: its own.
        let (current, off) = vector(&[RollSteer], 0.0);
        let start = alone(&current, &off, D, &[0.05]);
        let set = Layout::new(&[RollSteer, D], false);
        assert_eq!(start[set.roll()], off[current.roll()]);
        assert_eq!(start[set.effect(1)], [0.05]);
        // Both: the added effect's.
        let (camber, single) = vector(&[RollCamber], 20.0);
        let start = alone(&current, &off, RollCamber, &single);
        let set = Layout::new(&[RollSteer, RollCamber], false);
        assert_eq!(start[set.roll()], single[camber.roll()]);
        assert_eq!(start[set.effect(1)], single[camber.effect(0)]);
        assert_eq!(start[set.effect(0)], off[current.effect(0)]);
    }
}
