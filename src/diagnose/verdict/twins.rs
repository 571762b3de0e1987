//! A verdict's set against its twins: the set with a look-alike of its
//! first effect (a single that removes about as much of the gap alone,
//! [`rules::lookalike`]) fitted in that effect's place.
//!
//! Why. The greedy search grows a set from one single; a look-alike of
//! that single is never tried in the grown set's place, so the parsimony
//! rule ([`rules::pick`]) that the greedy step, the pairs fallback and the
//! singles apply to what they fit never read the twin, and the same tie
//! got opposite verdicts: steer_path+yaw_inertia (the lag idle, 3
//! parameters) from the greedy search, sensor_delay+yaw_inertia (2) from
//! the pairs fallback on a campaign that differed only in the sign of the
//! yaw-inertia error. [`simpler_twin`] fits the twins where the set leaves
//! a parameter idle and lets the same rule read them
//! ([`rules::simpler_twin`]); [`in_set`] fits them (or reads them) for the
//! report, confounded where their gap lies in the set's window.
//!
//! Units: J dimensionless, reductions in percent; the method is the
//! project's own.

use crate::diagnose::effects::{set_of, EffectKind};
use crate::diagnose::model::channels::gap_above;
use crate::diagnose::report::{Confounded, InSet, Ranked};
use crate::diagnose::verdict::baseline::Baseline;
use crate::diagnose::verdict::pairs::Simpler;
use crate::diagnose::verdict::rules;
use crate::diagnose::verdict::score::{Context, Scored};
use rayon::prelude::*;

/// The start of the `chosen` set's twin `kinds` (a look-alike in its first
/// effect's place): the look-alike's single fit with each other member's
/// added ([`crate::diagnose::fit::layout::Layout::combined`]).
fn twin_start(
    chosen: &Scored,
    kinds: &[EffectKind],
    singles: &[Scored],
    base: &Baseline,
) -> Option<Vec<f64>> {
    let single = |e: EffectKind| singles.iter().find(|s| s.kinds[0] == e);
    let mut start = single(kinds[0])?.full.params.clone();
    for (k, &e) in chosen.kinds[1..].iter().enumerate() {
        start = base
            .layout(&kinds[..=k])
            .combined(&start, e, &single(e)?.full.params);
    }
    Some(start)
}

/// The twin of `chosen` with `other` in its first effect's place.
fn twin_kinds(chosen: &Scored, other: EffectKind) -> Vec<EffectKind> {
    let mut kinds = vec![other];
    kinds.extend_from_slice(&chosen.kinds[1..]);
    kinds
}

/// Where the search's accepted set `chosen` (of more than one effect)
/// leaves a parameter idle, its twins (of the search's `lookalikes` of
/// the start, indices into `singles`) fitted and cross-validated (their
/// rows join `rows`), and the one the parsimony rule takes over it
/// ([`rules::simpler_twin`]) with the set it passed over. A set that
/// leaves nothing idle is left as it is, and nothing more is fitted.
pub(crate) fn simpler_twin(
    ctx: &Context,
    (singles, lookalikes): (&[Scored], &[usize]),
    base: &Baseline,
    chosen: &Scored,
    rows: &mut Vec<Ranked>,
) -> Option<(Scored, Simpler)> {
    if chosen.kinds.len() < 2 || !base.candidate(chosen).idle {
        return None;
    }
    let confounded = confounded_with(chosen, singles, (lookalikes, None), base);
    let group = confounded.first()?;
    let twins: Vec<Scored> = group.effects[1..]
        .par_iter()
        .filter_map(|&other| {
            let kinds = twin_kinds(chosen, other);
            let start = twin_start(chosen, &kinds, singles, base)?;
            // in_set's salt: the twin fitted here is the one it reads.
            Some(ctx.score(kinds, &[start], other.seed().wrapping_add(2)))
        })
        .collect();
    rows.extend(twins.iter().map(|t| base.rank(t)));
    let ranked: Vec<rules::Candidate> = twins.iter().map(|t| base.candidate(t)).collect();
    let k = rules::simpler_twin(base.candidate(chosen), &ranked, base.jn)?;
    let over = Simpler {
        over: chosen.clone(),
        taken: twins[k].clone(),
    };
    Some((twins[k].clone(), over))
}

/// The accepted first effect's look-alikes, less those the verdict took in
/// as well (the report words the experiment that separates them); where the
/// set took a twin's place ([`simpler_twin`]), the single it was grown
/// from (`grown_from`) comes second, before the look-alikes.
pub(crate) fn confounded_with(
    chosen: &Scored,
    singles: &[Scored],
    (lookalikes, grown_from): (&[usize], Option<EffectKind>),
    base: &Baseline,
) -> Vec<Confounded> {
    let single = |e: EffectKind| singles.iter().find(|x| x.kinds[0] == e);
    let first = single(chosen.kinds[0]).expect("the verdict starts from a scored single");
    // A set that took a twin's place for parsimony ([`simpler_twin`]) is
    // confounded with the single it was grown from first of all.
    let grown = grown_from.and_then(single);
    let members: Vec<&Scored> = std::iter::once(first)
        .chain(grown)
        .chain(lookalikes.iter().map(|&i| &singles[i]))
        .filter(|x| x.kinds[0] == chosen.kinds[0] || !chosen.kinds.contains(&x.kinds[0]))
        .fold(Vec::new(), |mut v, x| {
            if !v.iter().any(|m: &&Scored| m.kinds[0] == x.kinds[0]) {
                v.push(x);
            }
            v
        });
    if members.len() < 2 {
        return Vec::new();
    }
    vec![Confounded {
        effects: members.iter().map(|x| x.kinds[0]).collect(),
        reduction_percent: members
            .iter()
            .map(|x| base.rank(x).reduction_percent)
            .collect(),
        separating_runs: None,
    }]
}

/// Each look-alike of the `chosen` set's first effect (`confounded`, as
/// [`confounded_with`] gives them) fitted and cross-validated in the set
/// in its place, where the set has more than one effect: the singles'
/// likeness says nothing of the set's, which no search fitted (the search
/// starts again from a look-alike only while a significant gap is left).
/// Started from the look-alike's single fit with each other member's
/// added ([`crate::diagnose::fit::layout::Layout::combined`]); a set the
/// search already cross-validated (`tried`) is read, not fitted again.
/// Returns each as [`InSet`] and its report row where it is new.
pub(crate) fn in_set(
    ctx: &Context,
    chosen: &Scored,
    singles: &[Scored],
    confounded: &[Confounded],
    base: &Baseline,
    tried: &[Ranked],
) -> Vec<(InSet, Option<Ranked>)> {
    let (Some(c), true) = (confounded.first(), chosen.kinds.len() > 1) else {
        return Vec::new();
    };
    let g_chosen = gap_above(chosen.heldout.combined(&base.scales()), base.jn);
    c.effects[1..]
        .par_iter()
        .filter_map(|&other| {
            let kinds = twin_kinds(chosen, other);
            let known = tried.iter().find(|r| set_of(&r.effects) == set_of(&kinds));
            let (r, new) = match known {
                Some(r) => (r.clone(), false),
                None => {
                    let start = twin_start(chosen, &kinds, singles, base)?;
                    let salt = other.seed().wrapping_add(2);
                    (base.rank(&ctx.score(kinds.clone(), &[start], salt)), true)
                }
            };
            let gap = gap_above(r.heldout_error_after, base.jn);
            let row = InSet {
                effects: kinds,
                reduction_percent: r.reduction_percent,
                gap,
                window: rules::window(g_chosen, base.jn),
                confounded: rules::lookalike(r.reduction_percent, gap, g_chosen, base.jn),
            };
            Some((row, new.then_some(r)))
        })
        .collect()
}
