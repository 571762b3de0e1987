//! The verdict's search: which effects, alone or together, explain the gap
//! between the base model and the runs, and the verdict in words.
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
//! them.
//!
//! A candidate's fitted vector is read through its [`Layout`] (the axle
//! characteristics, each effect's parameters, the roll dynamics), and a
//! combination starts from [`Layout::combined`] of its members' fits.
//!
//! Units: SI, rad; J is dimensionless (residuals over channel scales),
//! reductions in percent. The method is the project's own (see
//! [`crate::diagnose::pipeline`] for the overview).

use crate::diagnose::base::identify::AxleIdentification;
use crate::diagnose::effects::{joined, Bound, EffectKind};
use crate::diagnose::fit::layout::Layout;
use crate::diagnose::model::channels::{gap_above, reduction};
use crate::diagnose::model::channels::{Channel, ChannelErrors};
use crate::diagnose::report::{ChannelError, Confounded, Part, Ranked, Shrinkage, Verdict};
use crate::diagnose::verdict::candidate::parameter_values;
use crate::diagnose::verdict::score::{Context, Scored};
use rayon::prelude::*;

/// Share of the held-out gap above noise an effect must remove to be
/// accepted (and each further effect of what is left).
pub const ACCEPT: f64 = 0.3;
/// An effect whose remaining held-out gap above noise is at most this
/// multiple of the accepted one's (plus [`CONFOUNDED_NOISE`] noise levels)
/// explains the data about as well: it is confounded with it.
pub const CONFOUNDED: f64 = 1.5;
/// The noise allowance of the confounding test, in noise levels.
pub const CONFOUNDED_NOISE: f64 = 0.25;
/// A held-out error below this multiple of the noise level is no gap.
pub const SIGNIFICANT: f64 = 1.3;
/// Share of the gap a best single effect must remove for the greedy search
/// to start from it (a pair whose halves each remove less than [`ACCEPT`]).
pub const PROMISING: f64 = 0.1;
/// In-sample minus held-out reduction (percentage points) past which a
/// candidate's cross-validation disagrees with its fit: a warning.
pub const DISAGREEMENT: f64 = 25.0;
/// Look-alikes of the best single the verdict's search also starts from
/// while the set found leaves a significant gap.
pub const ALTERNATIVE_STARTS: usize = 2;
/// Held-out error, in noise levels, by which a candidate that leaves a
/// parameter idle must beat a simpler one (fewer parameters) to be
/// preferred to it.
pub const PARSIMONY: f64 = 0.1;

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
}

impl Baseline {
    /// Why the axle characteristics fitted with a candidate are no tyre (a
    /// rigid axle, one without force, no grip), if they are not: such a
    /// candidate cannot be a verdict.
    pub(crate) fn degenerate(&self, sc: &Scored) -> Option<String> {
        self.axle
            .then(|| {
                let (p, a) = (&sc.full, self.layout(&sc.kinds).axles());
                AxleIdentification::new(&p.params[a.clone()], &p.std_errors[a], None, 0).degenerate
            })
            .flatten()
    }

    /// The parameter vector of `kinds` ([`Layout`]).
    pub(crate) fn layout(&self, kinds: &[EffectKind]) -> Layout {
        Layout::new(kinds, self.axle)
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

    /// A scored candidate as a row of the report, with its warnings.
    pub(crate) fn rank(&self, sc: &Scored) -> Ranked {
        let j = sc.heldout.combined(&self.scales);
        let held = reduction(self.j0, j, self.jn);
        let j_in = sc.insample.combined(&self.scales);
        let inside = reduction(self.j0_in, j_in, self.jn_in);
        let folds = self.folds;
        let mut warnings = Vec::new();
        if inside - held > DISAGREEMENT && inside >= 100.0 * ACCEPT {
            warnings.push(format!(
                "the fit on all runs removes {inside:.0} % of the gap but only {held:.0} % on held-out runs: \
                 the effect does not generalise across runs, or the runs cannot pin its parameters"
            ));
        }
        if let Some(why) = self.degenerate(sc) {
            warnings.push(format!(
                "fitted with it, the axles are no tyre ({why}): it cannot be a verdict"
            ));
        }
        if sc.folds_converged < folds {
            warnings.push(format!(
                "{} of {folds} fold refits did not converge",
                folds - sc.folds_converged
            ));
        }
        Ranked {
            effect: joined(&sc.kinds, "+"),
            effects: sc.kinds.clone(),
            axles: self.axle.then(|| {
                let (p, a) = (&sc.full, self.layout(&sc.kinds).axles());
                AxleIdentification::new(&p.params[a.clone()], &p.std_errors[a], None, 0).parameters
            }),
            parameters: parameter_values(&self.layout(&sc.kinds), &sc.full),
            heldout_error_before: self.j0,
            heldout_error_after: j,
            heldout_channels: channel_errors(&sc.heldout),
            reduction_percent: held,
            insample_error_after: j_in,
            insample_reduction_percent: inside,
            folds_converged: sc.folds_converged,
            folds,
            warning: (!warnings.is_empty()).then(|| warnings.join("; ")),
            bic: sc.full.bic(),
            delta_bic: sc.full.bic() - self.bic0,
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
    let usable: Vec<usize> = order
        .iter()
        .copied()
        .filter(|&i| base.degenerate(&singles[i]).is_none())
        .collect();
    let order = &usable[..];
    let (scales, jn) = (base.scales, base.jn);
    let Some(first) = first_single(singles, order, base) else {
        return out;
    };
    let best = &singles[first];
    let r = base.rank(best);
    // A best single below the acceptance share can still be half of a
    // pair of effects: the greedy search starts from it when it is
    // promising, and the set found must pass as a whole.
    if r.reduction_percent < 100.0 * PROMISING || r.delta_bic >= 0.0 {
        return out;
    }
    out.lookalikes = lookalikes(singles, order, first, &r, base);
    let mut current = greedy(ctx, singles, all, base, max_effects, best, &mut out);
    // The best single can be a look-alike that mimics part of a pair and
    // leads the greedy search away from it (a fast, lightly damped roll
    // steering the axles looks like a yaw inertia and aero load together).
    // While the set found leaves a significant gap, the search starts again
    // from the look-alikes (at most ALTERNATIVE_STARTS), and a set that
    // leaves clearly less of the gap (below 1/CONFOUNDED of it) replaces it.
    for &i in out.lookalikes.clone().iter().take(ALTERNATIVE_STARTS) {
        let jc = current.heldout.combined(&scales);
        if jc <= SIGNIFICANT * jn {
            break;
        }
        let other = greedy(ctx, singles, all, base, max_effects, &singles[i], &mut out);
        let (g, g_other) = (
            gap_above(jc, jn),
            gap_above(other.heldout.combined(&scales), jn),
        );
        if g_other * CONFOUNDED < g {
            current = other;
        }
    }
    let total = reduction(base.j0, current.heldout.combined(&scales), jn);
    if total >= 100.0 * ACCEPT && current.full.bic() < base.bic0 {
        out.chosen = Some(current);
    }
    let mut seen = std::collections::HashSet::new();
    out.combinations.retain(|r| seen.insert(r.effect.clone()));
    out.combinations
        .sort_by(|a, b| a.heldout_error_after.total_cmp(&b.heldout_error_after));
    out
}

/// The single the search starts from (an index into `singles`; `order`
/// ranks them by held-out error): the best, or a simpler one that does as
/// well where the best leaves a parameter idle — a steer path whose lag
/// stays off is a steer delay, one with a sensor delay on runs whose every
/// response comes from the steer, and must not win on the interpolation's
/// rounding. `None` without candidates.
fn first_single(singles: &[Scored], order: &[usize], base: &Baseline) -> Option<usize> {
    let ranked: Vec<&Scored> = order.iter().map(|&i| &singles[i]).collect();
    parsimonious(&ranked, base).map(|k| order[k])
}

/// Of candidates ranked by held-out error, the index of the one to take:
/// the first, or where it leaves a parameter idle ([`idle`]) the one with
/// the fewest parameters within [`PARSIMONY`] noise levels of it.
fn parsimonious(ranked: &[&Scored], base: &Baseline) -> Option<usize> {
    let (scales, jn) = (base.scales, base.jn);
    let top = ranked.first()?;
    if !idle(top, &base.layout(&top.kinds)) {
        return Some(0);
    }
    let j_top = top.heldout.combined(&scales);
    (0..ranked.len())
        .filter(|&k| ranked[k].heldout.combined(&scales) <= j_top + PARSIMONY * jn)
        .min_by_key(|&k| ranked[k].full.params.len())
}

/// Look-alikes of the first single (`first`, ranked as `r`): the other
/// singles in `order` that also pass and leave about as small a gap above
/// noise (within [`CONFOUNDED`]·G + [`CONFOUNDED_NOISE`]·J_n).
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
            o.reduction_percent >= 100.0 * ACCEPT
                && gap_above(o.heldout_error_after, jn)
                    <= CONFOUNDED * g_best + CONFOUNDED_NOISE * jn
        })
        .collect()
}

/// Whether a fit leaves one of its effect parameters idle: at its
/// off value (on a physical limit there, or not), within two standard
/// errors of it, or off a bound without a standard error at all (its
/// Jacobian column all but a combination of the others': exact Jacobians
/// show a steer path's lag at a few microseconds to be its delay's twin):
/// that part of the effect is off, or the data cannot tell it from off,
/// and it reduces to a simpler one.
fn idle(sc: &Scored, layout: &Layout) -> bool {
    let params = sc.kinds.iter().flat_map(|e| e.parameters().iter());
    params.zip(layout.effects()).any(|(q, i)| {
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
        if jc <= SIGNIFICANT * jn {
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
        let mut scored: Vec<Scored> = scored
            .into_iter()
            .filter(|sc| base.degenerate(sc).is_none())
            .collect();
        let ranked: Vec<&Scored> = scored.iter().collect();
        let Some(k) = parsimonious(&ranked, base) else {
            break;
        };
        let next = scored.swap_remove(k);
        let extra = reduction(jc, next.heldout.combined(&scales), jn);
        if extra >= 100.0 * ACCEPT && next.full.bic() < current.full.bic() {
            current = next;
        } else {
            break;
        }
    }
    current
}

/// The accepted first effect's look-alikes, less those the verdict took in
/// as well, with the experiments that would separate them.
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
        separating_test: members
            .iter()
            .map(|x| format!("{}: {}", x.kinds[0].name(), x.kinds[0].signature()))
            .collect::<Vec<_>>()
            .join("; "),
    }]
}

/// The verdict in words.
pub(crate) fn verdict_of(
    chosen: Option<&Scored>,
    base: &Baseline,
    significant: bool,
    ranking: &[Ranked],
    degenerate: Option<&str>,
) -> Verdict {
    let (j0, jn) = (base.j0, base.jn);
    // A base that is no tyre gives no model-form verdict: what no
    // candidate explains may be the base's own collapse.
    if let (None, Some(why), true) = (chosen, degenerate, significant) {
        return Verdict {
            effects: Vec::new(),
            parameters: Vec::new(),
            warnings: Vec::new(),
            statement: format!(
                "the base model is not identifiable from these runs: {why}; no candidate effect fitted with it gives axles that are a tyre and removes {:.0} % of the gap (held-out error {j0:.3}, noise level {jn:.3}), so there is no model-form verdict",
                100.0 * ACCEPT
            ),
        };
    }
    match chosen {
        Some(sc) => {
            let r = base.rank(sc);
            // Accepted at 30 %: where most of the gap stays, the verdict
            // says so.
            let statement = if r.reduction_percent >= 50.0 {
                format!(
                    "{} explains the gap: held-out error {:.3} → {:.3} (noise level {:.3}), {:.1} % of the gap above noise removed",
                    r.effect, j0, r.heldout_error_after, jn, r.reduction_percent
                )
            } else {
                format!(
                    "{} explains part of the gap: held-out error {:.3} → {:.3} (noise level {:.3}), {:.1} % of the gap above noise removed; the other {:.1} % no candidate explains",
                    r.effect,
                    j0,
                    r.heldout_error_after,
                    jn,
                    r.reduction_percent,
                    100.0 - r.reduction_percent
                )
            };
            Verdict {
                effects: r.effects.clone(),
                parameters: r.parameters.clone(),
                statement,
                warnings: Vec::new(),
            }
        }
        None => Verdict {
            effects: Vec::new(),
            parameters: Vec::new(),
            warnings: Vec::new(),
            statement: if !significant {
                format!(
                    "no significant gap: held-out error {j0:.3} is within {SIGNIFICANT} × the noise level {jn:.3}"
                )
            } else {
                format!(
                    "a gap (held-out error {j0:.3}, noise level {jn:.3}) that no candidate effect explains: the best, {}, removes {:.1} % of it (acceptance needs {:.0} %) — a model-form error outside the library",
                    ranking.first().map_or("none", |r| r.effect.as_str()),
                    ranking.first().map_or(0.0, |r| r.reduction_percent),
                    100.0 * ACCEPT
                )
            },
        },
    }
}

/// A channel's gap above noise grown by more than this share (%) under the
/// verdict's effects is worth a warning: beyond the scatter of held-out
/// scores, and the combined error that accepted them does not show it.
const WORSENED: f64 = 10.0;

/// Warnings for the channels the verdict's effects leave worse on
/// held-out runs (all samples).
pub(crate) fn worsened(shrinkage: &[Shrinkage]) -> Vec<String> {
    shrinkage
        .iter()
        .filter(|s| s.part == Part::All && s.reduction_percent < -WORSENED && s.after > s.before)
        .map(|s| {
            format!(
                "it leaves the {} gap larger on held-out runs: RMS {:.4} → {:.4} {} (noise floor {:.4}), {:.0} % of the gap above noise added; the combined error falls through the other channels (check this channel's sensor and whether the effect's physics can make it worse)",
                s.channel.name(),
                s.before,
                s.after,
                s.channel.unit(),
                s.noise_floor,
                -s.reduction_percent
            )
        })
        .collect()
}
