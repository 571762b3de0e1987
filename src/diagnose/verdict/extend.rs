//! The sets a greedy step of the verdict's search tries
//! ([`crate::diagnose::verdict::search`]): the current set with each
//! remaining effect added, their starts, and their global stages.

use crate::diagnose::effects::EffectKind;
use crate::diagnose::verdict::baseline::Baseline;
use crate::diagnose::verdict::score::{Context, Scored, Started};
use crate::diagnose::verdict::search::alone;
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
