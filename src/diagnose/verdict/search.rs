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
//! best single. Effects that also pass and leave a gap above noise within
//! [`CONFOUNDED`]·G + [`CONFOUNDED_NOISE`]·J_n of the accepted one's G are
//! reported as confounded with it, with the experiment that would separate
//! them. Each of these rules is a pure function in
//! [`crate::diagnose::verdict::rules`], tested there.
//!
//! A candidate's fitted vector is read through its [`Layout`] (the axle
//! characteristics, each effect's parameters, the roll dynamics), and a
//! combination starts from [`Layout::combined`] of its members' fits.
//!
//! Units: SI, rad; J is dimensionless (residuals over channel scales),
//! reductions in percent. The method is the project's own (see
//! [`crate::diagnose::pipeline`] for the overview).

use crate::diagnose::base::identify::{AxleIdentification, NoTyre};
use crate::diagnose::base::prior::PriorReport;
use crate::diagnose::effects::{joined, Bound, EffectKind};
use crate::diagnose::fit::layout::Layout;
use crate::diagnose::model::channels::{gap_above, reduction};
use crate::diagnose::model::channels::{Channel, ChannelErrors};
use crate::diagnose::report::{ChannelError, Confounded, RankWarning, Ranked, Refused};
use crate::diagnose::verdict::candidate::parameter_values;
use crate::diagnose::verdict::rules::{self, Candidate};
#[cfg(doc)]
use crate::diagnose::verdict::rules::{
    ACCEPT, ALTERNATIVE_STARTS, CONFOUNDED, CONFOUNDED_NOISE, DISAGREEMENT, PARSIMONY, PROMISING,
    SIGNIFICANT,
};
use crate::diagnose::verdict::score::{Context, Scored};
use rayon::prelude::*;

/// A candidate's held-out RMS error per channel, as report rows.
fn channel_errors(e: &ChannelErrors) -> Vec<ChannelError> {
    Channel::ALL
        .into_iter()
        .filter_map(|c| {
            e.rms(c).map(|rms| ChannelError {
                channel: c,
                unit: c.unit(),
                rms,
            })
        })
        .collect()
}

/// The base model's held-out and in-sample scores that every candidate is
/// ranked against.
pub(crate) struct Baseline {
    /// Held-out error J of the base model, and of the noise alone.
    pub(crate) j0: f64,
    pub(crate) jn: f64,
    /// The same on all runs with the all-run fit.
    j0_in: f64,
    jn_in: f64,
    bic0: f64,
    scales: [f64; 3],
    folds: usize,
    /// Whether axle characteristics lead every parameter vector.
    axle: bool,
    /// The base's held-out errors by channel.
    pub(crate) heldout: ChannelErrors,
    /// The prior the axles are fitted against (axles identified from the
    /// runs).
    prior: Option<PriorReport>,
}

impl Baseline {
    /// Why the axle characteristics fitted with a candidate are no tyre (a
    /// rigid axle, one without force, no grip, an early peak; empty for a
    /// tyre): such a candidate cannot be a verdict.
    pub(crate) fn no_tyre(&self, sc: &Scored) -> Vec<NoTyre> {
        if !self.axle {
            return Vec::new();
        }
        let (p, a) = (&sc.full, self.layout(&sc.kinds).axles());
        let shares = &p.params[a.clone()];
        let mut why = AxleIdentification::new(shares, &p.std_errors[a], None, 0).no_tyre;
        if let Some(prior) = &self.prior {
            why.extend(PriorReport::new(prior.prior, prior.friction_rule, shares).far_outside());
        }
        why
    }

    /// The parameter vector of `kinds` ([`Layout`]).
    pub(crate) fn layout(&self, kinds: &[EffectKind]) -> Layout {
        Layout::new(kinds, self.axle)
    }

    /// Whether the axles fitted with a candidate are no tyre.
    pub(crate) fn degenerate(&self, sc: &Scored) -> bool {
        !self.no_tyre(sc).is_empty()
    }

    /// Why a candidate is not the verdict ([`rules::refused`]); `gave_way`
    /// why the search started from another in its place, and `instead`
    /// the set the search ended on.
    pub(crate) fn refused(
        &self,
        sc: &Scored,
        gave_way: Option<rules::GaveWay>,
        instead: Option<Refused>,
    ) -> Refused {
        let r = self.rank(sc);
        rules::refused(
            (r.effects, r.reduction_percent, r.delta_bic),
            self.no_tyre(sc),
            gave_way,
            instead,
        )
    }

    /// What the choice of a candidate reads of it ([`rules::pick`]).
    pub(crate) fn candidate(&self, sc: &Scored) -> Candidate {
        Candidate {
            heldout: sc.heldout.combined(&self.scales),
            parameters: sc.full.free_count(),
            idle: idle(sc, &self.layout(&sc.kinds)),
            degenerate: self.degenerate(sc),
            pressed: pressed(sc, &self.layout(&sc.kinds)),
        }
    }

    /// The channel scales of the combined errors.
    pub(crate) fn scales(&self) -> [f64; 3] {
        self.scales
    }

    /// A fit's BIC less the base model's (negative: better).
    pub(crate) fn delta_bic(&self, sc: &Scored) -> f64 {
        sc.full.bic() - self.bic0
    }

    /// The in-sample reduction (%) of a fit with errors `e` on all runs.
    pub(crate) fn insample_reduction(&self, e: &ChannelErrors) -> f64 {
        reduction(self.j0_in, e.combined(&self.scales), self.jn_in)
    }

    /// Whether the base leaves a gap above noise in sample: without one an
    /// in-sample reduction bounds nothing.
    pub(crate) fn insample_gap(&self) -> bool {
        gap_above(self.j0_in, self.jn_in) > 0.0
    }

    /// The least held-out error a candidate can have whose held-out
    /// reduction is at most `percent`.
    pub(crate) fn heldout_floor(&self, percent: f64) -> f64 {
        let g = (1.0 - percent.min(100.0) / 100.0) * gap_above(self.j0, self.jn);
        (g * g + self.jn * self.jn).sqrt()
    }

    /// The warning of fold refits landing far from the all-run fit
    /// ([`rules::far_folds`], over the effect and roll parameters), said
    /// where the cross-validation disagrees with the fit.
    fn folds_far(&self, sc: &Scored) -> Option<RankWarning> {
        let layout = self.layout(&sc.kinds);
        let at = layout.effects().start;
        let p = &sc.full;
        let (i, fold_value, distance, far) = rules::far_folds(
            &p.params,
            &p.std_errors,
            &sc.fold_params,
            at..p.params.len(),
        )?;
        let (group, q) = layout.parameters().nth(i - at)?;
        Some(RankWarning::FoldsFar {
            parameter: format!("{group}.{}", q.name),
            value: p.params[i],
            std_error: p.std_errors[i],
            fold_value,
            distance,
            far,
            folds: sc.fold_params.len(),
        })
    }

    /// A scored candidate as a row of the report, with its warnings.
    pub(crate) fn rank(&self, sc: &Scored) -> Ranked {
        let j = sc.heldout.combined(&self.scales);
        let held = reduction(self.j0, j, self.jn);
        let j_in = sc.insample.combined(&self.scales);
        let inside = reduction(self.j0_in, j_in, self.jn_in);
        let folds = self.folds;
        let mut warnings = Vec::new();
        if rules::disagrees(inside, held) {
            warnings.push(RankWarning::Disagreement {
                insample_percent: inside,
                heldout_percent: held,
            });
            // Why it may: folds whose refits found other optima. Only
            // here: a model-form gap makes standard errors optimistic, so
            // folds of a candidate that generalises land a few of them
            // away too (measured: cornering_stiffness at 20 of them).
            warnings.extend(self.folds_far(sc));
        }
        let no_tyre = self.no_tyre(sc);
        if !no_tyre.is_empty() {
            warnings.push(RankWarning::AxlesNoTyre { no_tyre });
        }
        if sc.folds_converged < folds {
            warnings.push(RankWarning::FoldsNotConverged {
                failed: folds - sc.folds_converged,
                folds,
            });
        }
        Ranked {
            effect: joined(&sc.kinds, "+"),
            effects: sc.kinds.clone(),
            axles: self.axle.then(|| {
                let (p, a) = (&sc.full, self.layout(&sc.kinds).axles());
                let shares = &p.params[a.clone()];
                let id = AxleIdentification::new(shares, &p.std_errors[a], None, 0);
                match &self.prior {
                    Some(r) => id.with_prior(PriorReport::new(r.prior, r.friction_rule, shares)),
                    None => id,
                }
                .parameters
            }),
            prior_weight: sc.prior_weight,
            parameters: parameter_values(&self.layout(&sc.kinds), &sc.full),
            heldout_error_before: self.j0,
            heldout_error_after: j,
            heldout_channels: channel_errors(&sc.heldout),
            reduction_percent: held,
            insample_error_after: j_in,
            insample_reduction_percent: inside,
            folds_converged: sc.folds_converged,
            folds,
            warnings,
            bic: sc.full.bic(),
            delta_bic: sc.full.bic() - self.bic0,
            global_search: sc.full.global,
        }
    }
}

/// The base model scored on held-out and fitted runs, with the error the
/// channels' noise floors alone would give.
pub(crate) fn baseline(ctx: &Context, floors: &[f64; 3]) -> Baseline {
    let scales = ctx.scales;
    let noise_level = |e: &ChannelErrors| {
        let n: usize = e.count.iter().sum();
        let s: f64 = (0..3)
            .map(|i| e.count[i] as f64 * (floors[i] / scales[i]).powi(2))
            .sum();
        (s / n.max(1) as f64).sqrt()
    };
    let scored = ctx.score(Vec::new(), &[], 0);
    Baseline {
        j0: scored.heldout.combined(&scales),
        jn: noise_level(&scored.heldout),
        j0_in: scored.insample.combined(&scales),
        jn_in: noise_level(&scored.insample),
        bic0: scored.full.bic(),
        scales,
        folds: ctx.folds.len(),
        axle: ctx.bases.axle.is_some(),
        heldout: scored.heldout,
        prior: ctx.bases.identification.as_ref().and_then(|i| i.prior),
    }
}

/// What the search for a verdict found.
#[derive(Default)]
pub(crate) struct Search {
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
}

/// The verdict's search: the best single (`order` ranks the
/// cross-validated `singles` by held-out error), then greedy additions,
/// each tried jointly with every remaining effect (`all`: those in `order`
/// and the screened ones, whose all-run fits start them).
pub(crate) fn search(
    ctx: &Context,
    singles: &[Scored],
    (order, all): (&[usize], &[usize]),
    base: &Baseline,
    max_effects: usize,
) -> Search {
    let mut out = Search::default();
    // A single whose axles are no tyre cannot be the verdict, nor start
    // one; it can still join a set (a steer lag whose axles collapse
    // alone on a banked oval is a tyre's once the bank is in), so the
    // greedy additions try every effect (`all`).
    let ranked: Vec<Candidate> = order.iter().map(|&i| base.candidate(&singles[i])).collect();
    let usable: Vec<usize> = order
        .iter()
        .zip(&ranked)
        .filter(|(_, c)| !c.degenerate)
        .map(|(&i, _)| i)
        .collect();
    let (scales, jn) = (base.scales, base.jn);
    // The best, or a simpler one that does as well where the best leaves a
    // parameter idle: a steer path whose lag stays off is a steer delay,
    // one with a sensor delay on runs whose every response comes from the
    // steer, and must not win on the interpolation's rounding.
    let Some(first) = rules::pick(&ranked, jn).map(|k| order[k]) else {
        return out;
    };
    out.start = Some(first);
    // The best whose axles are a tyre, where the pick passed it over for
    // being pressed on a search bound.
    out.passed_over = rules::passed_over(&ranked, jn).map(|k| order[k]);
    let best = &singles[first];
    let r = base.rank(best);
    // A best single below the acceptance share can still be half of a
    // pair of effects: the greedy search starts from it when it is
    // promising, and the set found must pass as a whole.
    if !rules::promising(r.reduction_percent, r.delta_bic) {
        out.ended = Some(base.refused(best, None, None));
        return out;
    }
    out.lookalikes = lookalikes(singles, &usable, first, &r, base);
    let mut current = greedy(ctx, singles, all, base, max_effects, best, &mut out);
    // The best single can be a look-alike that mimics part of a pair and
    // leads the greedy search away from it (a fast, lightly damped roll
    // steering the axles looks like a yaw inertia and aero load together).
    // While the set found leaves a significant gap, the search starts again
    // from the look-alikes (at most ALTERNATIVE_STARTS), and a set that
    // leaves clearly less of the gap replaces it.
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
        let other = greedy(ctx, singles, all, base, max_effects, &singles[i], &mut out);
        let (g, g_other) = (
            gap_above(jc, jn),
            gap_above(other.heldout.combined(&scales), jn),
        );
        if rules::replaces(g_other, g) {
            current = other;
        }
    }
    let total = reduction(base.j0, current.heldout.combined(&scales), jn);
    if rules::accepted(total, current.full.bic(), base.bic0) {
        out.chosen = Some(current);
    } else {
        out.ended = Some(base.refused(&current, None, None));
    }
    let chosen = out.chosen.as_ref().map(|c| c.kinds.as_slice());
    one_row_per_set(&mut out.combinations, chosen);
    out.combinations
        .sort_by(|a, b| a.heldout_error_after.total_cmp(&b.heldout_error_after));
    out
}

/// Keeps one row per set of effects: the greedy searches from the best
/// single and from its look-alikes try a pair in both orders
/// (`steer_path+sensor_delay`, `sensor_delay+steer_path`), and a set is one
/// candidate whatever the order it was built in. The row kept is the
/// chosen set's own (its order, the numbers the verdict states) where it
/// is one of them, else the first tried.
fn one_row_per_set(rows: &mut Vec<Ranked>, chosen: Option<&[EffectKind]>) {
    // Stable: the chosen set's row moves ahead of its other orders only.
    rows.sort_by_key(|r| Some(r.effects.as_slice()) != chosen);
    let mut seen = std::collections::HashSet::new();
    rows.retain(|r| {
        let mut set = r.effects.clone();
        set.sort();
        seen.insert(set)
    });
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

/// Whether a fit leaves one of its effect parameters idle: at its
/// off value (on a physical limit there, or not), within two standard
/// errors of it, or off a bound without a standard error at all (its
/// Jacobian column all but a combination of the others': exact Jacobians
/// show a steer path's lag at a few microseconds to be its delay's twin):
/// that part of the effect is off, or the data cannot tell it from off,
/// and it reduces to a simpler one. A parameter no measured channel
/// responds to ([`crate::diagnose::fit::FitOutcome::unseen`]) is held, not
/// idle.
fn idle(sc: &Scored, layout: &Layout) -> bool {
    let params = sc.kinds.iter().flat_map(|e| e.parameters().iter());
    params.zip(layout.effects()).any(|(q, i)| {
        // Held because no measured channel responds to it: not a part of
        // the effect the runs could test, so not one they found off.
        if sc.full.is_unseen(i) {
            return false;
        }
        let (value, se) = (sc.full.params[i], sc.full.std_errors[i]);
        // Off, or no further from off than the data can tell; a value on
        // a search bound (no standard error) is pressed there, not idle.
        let off = !q.off.is_nan() && (value - q.off).abs() <= 1e-9 * (q.bounds.1 - q.bounds.0);
        match q.bound_at(value) {
            Some(Bound::Search) => false,
            Some(Bound::Physical) => off,
            None => off || (!q.off.is_nan() && (se.is_nan() || (value - q.off).abs() < 2.0 * se)),
        }
    })
}

/// Whether one of a fit's effect parameters (not the roll dynamics, whose
/// damping a roll effect presses on its bound where the runs barely roll)
/// lies on the end of its search range ([`Bound::Search`]).
fn pressed(sc: &Scored, layout: &Layout) -> bool {
    let params = sc.kinds.iter().flat_map(|e| e.parameters().iter());
    params
        .zip(layout.effects())
        .any(|(q, i)| q.bound_at(sc.full.params[i]) == Some(Bound::Search))
}

/// Greedy additions from `start`: the effect that best closes what is left,
/// tried jointly with every remaining effect, while each removes
/// [`ACCEPT`] of what is left and lowers the BIC. Every set tried goes into
/// `out.combinations`.
fn greedy(
    ctx: &Context,
    singles: &[Scored],
    order: &[usize],
    base: &Baseline,
    max_effects: usize,
    start: &Scored,
    out: &mut Search,
) -> Scored {
    let (scales, jn) = (base.scales, base.jn);
    let mut current = start.clone();
    // Greedy: add the effect that best closes what is left.
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
        let cur = &current;
        // Each set's seed is that of the effect added (its name's, not its
        // place in the ranking, which screening shortens), one apart from
        // its single fit's.
        let mut scored: Vec<Scored> = tries
            .par_iter()
            .map(|e| {
                let mut kinds = cur.kinds.clone();
                kinds.push(*e);
                let single = singles.iter().find(|s| s.kinds[0] == *e).expect("scored");
                let layout = base.layout(&cur.kinds);
                let members = layout.combined(&cur.full.params, *e, &single.full.params);
                let extended = layout.combined(&cur.full.params, *e, &ctx.off(&[*e]));
                // Each member's own optimum: the axles the added effect
                // fitted alone want can differ from the current set's.
                let mut own = members.clone();
                let axles = layout.axles();
                own[axles.clone()].copy_from_slice(&single.full.params[axles]);
                ctx.score(kinds, &[members, extended, own], e.seed().wrapping_add(1))
            })
            .collect();
        scored.sort_by(|a, b| {
            a.heldout
                .combined(&scales)
                .total_cmp(&b.heldout.combined(&scales))
        });
        out.combinations
            .extend(scored.iter().map(|sc| base.rank(sc)));
        // The best set whose axles are a tyre, or a simpler one that does
        // as well where it leaves a parameter idle.
        let ranked: Vec<Candidate> = scored.iter().map(|sc| base.candidate(sc)).collect();
        let Some(k) = rules::pick(&ranked, jn) else {
            break;
        };
        let next = scored.swap_remove(k);
        let extra = reduction(jc, next.heldout.combined(&scales), jn);
        if rules::accepted(extra, next.full.bic(), current.full.bic()) {
            current = next;
        } else {
            break;
        }
    }
    current
}

/// The accepted first effect's look-alikes, less those the verdict took in
/// as well (the report words the experiment that separates them).
pub(crate) fn confounded_with(
    chosen: &Scored,
    singles: &[Scored],
    lookalikes: &[usize],
    base: &Baseline,
) -> Vec<Confounded> {
    let first = singles
        .iter()
        .find(|x| x.kinds[0] == chosen.kinds[0])
        .expect("the verdict starts from a scored single");
    let members: Vec<&Scored> = std::iter::once(first)
        .chain(
            lookalikes
                .iter()
                .map(|&i| &singles[i])
                .filter(|x| !chosen.kinds.contains(&x.kinds[0])),
        )
        .collect();
    if members.len() < 2 {
        return Vec::new();
    }
    vec![Confounded {
        effects: members.iter().map(|x| x.kinds[0]).collect(),
        reduction_percent: members
            .iter()
            .map(|x| base.rank(x).reduction_percent)
            .collect(),
    }]
}
