//! The candidates a campaign's `[diagnose] effects` narrowed the
//! library to, as the verdicts that would otherwise blame "a model-form
//! error outside the library" carry them: a gap none of the named effects
//! explains says nothing of the effects left out, the true one perhaps
//! among them (a fresh-eyes tester's `effects = ["road_bank"]` on a
//! relaxation-length truth read as "outside the library" while 19 of the
//! library's 20 effects were never tried).

use crate::diagnose::effects::EffectKind;
use serde::Serialize;

/// The candidates a campaign's `[diagnose] effects` narrowed the library
/// to: a gap none of them explains says nothing of the effects left out,
/// so it is no model-form error outside the library.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Narrowed {
    /// The effects the campaign names, the only ones tried.
    pub tried: Vec<EffectKind>,
    /// The library's effects it leaves out, untried.
    pub untried: Vec<EffectKind>,
}

impl Narrowed {
    /// The narrowing of the library to `named` (None where `named` is the
    /// whole library, or the campaign names none: the default).
    pub fn of(named: Option<&[EffectKind]>) -> Option<Narrowed> {
        let tried = named?.to_vec();
        let untried: Vec<EffectKind> = EffectKind::ALL
            .into_iter()
            .filter(|k| !tried.contains(k))
            .collect();
        (!untried.is_empty()).then_some(Narrowed { tried, untried })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_whole_library_or_none_named_is_no_narrowing() {
        assert_eq!(Narrowed::of(None), None);
        assert_eq!(Narrowed::of(Some(&EffectKind::ALL)), None);
    }

    #[test]
    fn a_narrowing_names_every_effect_it_leaves_out() {
        let n = Narrowed::of(Some(&[EffectKind::ALL[1]])).unwrap();
        assert_eq!(n.tried, vec![EffectKind::ALL[1]]);
        assert_eq!(n.untried.len(), EffectKind::ALL.len() - 1);
        assert!(!n.untried.contains(&EffectKind::ALL[1]));
    }
}
