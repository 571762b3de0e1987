//! The sets a greedy step of the verdict's search tries
//! ([`crate::diagnose::verdict::search`]): the current set with each
//! remaining effect added, their starts, and their global stages.

use crate::diagnose::effects::EffectKind;
use crate::diagnose::fit::layout::Layout;
use crate::diagnose::verdict::baseline::Baseline;
use crate::diagnose::verdict::score::{Context, Scored, Started};
use rayon::prelude::*;

/// A set a greedy step tries: its effects, the starts of its global stage
/// and the seed of its swarm.
pub(crate) type SetStarts = (Vec<EffectKind>, [Vec<f64>; 4], u64);

/// The sets of `current` plus each effect of `tries`, with their starts.
/// Each set's seed is that of the effect added (its name's, not its place
/// in the ranking, which screening shortens), one apart from its single
/// fit's.
pub(super) fn extension_starts(
    ctx: &Context,
    singles: &[Scored],
    base: &Baseline,
    current: &Scored,
    tries: &[EffectKind],
) -> Vec<SetStarts> {
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
            (
                kinds,
                [members, extended, own, added],
                e.seed().wrapping_add(1),
            )
        })
        .collect()
}

/// The sets `sets` with their global stage on all runs done
/// ([`Context::started`]).
pub(super) fn extensions<'a>(ctx: &Context<'a>, sets: Vec<SetStarts>) -> Vec<Started<'a>> {
    sets.into_par_iter()
        .map(|(kinds, starts, salt)| ctx.started(kinds, &starts, salt))
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
pub(super) fn alone(layout: &Layout, off: &[f64], added: EffectKind, single: &[f64]) -> Vec<f64> {
    let mut start = layout.combined(off, added, single);
    let one = Layout::new(&[added], layout.axle);
    start[layout.axles()].copy_from_slice(&single[one.axles()]);
    let set = Layout::new(&[layout.kinds.as_slice(), &[added]].concat(), layout.axle);
    if !one.roll().is_empty() {
        start[set.roll()].copy_from_slice(&single[one.roll()]);
    }
    start
}
