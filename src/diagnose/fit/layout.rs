//! What a fit's parameter vector sets on the augmented model
//! ([`Layout`]): the axle characteristics of an identified base
//! ([`crate::diagnose::base::identify`]) first when they are fitted, then each candidate
//! effect's parameters ([`crate::diagnose::effects::EffectSet::set`]), then the roll
//! dynamics when a roll effect is among them. The plain model of a vector
//! is [`with_effects`]; its derivatives are [`crate::diagnose::fit::tangent`]'s. Units:
//! SI, rad.

use crate::diagnose::effects::{EffectKind, EffectSet};
use crate::diagnose::model::axles::axle_tyres;
use crate::diagnose::model::Augmented;

/// What a fit's parameter vector sets on a model: the axle
/// characteristics first when they are fitted (`axle`), then each
/// effect's parameters in `kinds` order, then the roll dynamics when a
/// roll effect is among them (as [`with_effects`] builds the plain model,
/// which the problem's own `build` gives).
#[derive(Debug, Clone)]
pub struct Layout {
    /// The model the parameters are set on (its tyres say whether the
    /// replay has a generic form).
    pub base: Augmented,
    /// The effects fitted, in vector order.
    pub kinds: Vec<EffectKind>,
    /// Whether the axle characteristics lead the vector.
    pub axle: bool,
}

/// Whether a candidate carries the roll-dynamics parameters.
pub(crate) fn fits_roll(kinds: &[EffectKind]) -> bool {
    kinds.iter().any(|e| e.uses_roll())
}

/// The model of a candidate's parameter vector: the axle characteristics
/// first when they are fitted (`axle`), then each effect's parameters, then
/// the roll dynamics when a roll effect is among them (`crate::diagnose::base::ROLL_DYNAMICS`).
pub(crate) fn with_effects(
    base: &Augmented,
    fixed: &EffectSet,
    kinds: &[EffectKind],
    axle: bool,
    p: &[f64],
) -> Augmented {
    let mut m = base.clone();
    m.effects = *fixed;
    let mut k = 0;
    if axle {
        (m.base.front, m.base.rear) = axle_tyres(&p[..3]);
        k = 3;
    }
    for e in kinds {
        let n = e.parameters().len();
        m.effects.set(*e, &p[k..k + n]);
        k += n;
    }
    if fits_roll(kinds) {
        m.roll.frequency = p[k];
        m.roll.damping = p[k + 1];
    }
    m
}
