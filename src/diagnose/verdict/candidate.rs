//! A candidate of the diagnosis as a parameter vector ([`Setting`]): the
//! axle characteristics of an identified base first (when the base has
//! them), then each effect's parameters, then the roll dynamics when a
//! roll effect is among them ([`crate::diagnose::fit::layout`]); its
//! bounds and off values, the start of a combination from its members'
//! fits ([`combined_start`]), and its fitted parameters as report rows
//! ([`parameter_values`]). Units: SI, rad; the roll frequency in Hz.

use crate::diagnose::base::Bases;
use crate::diagnose::effects::{EffectKind, EffectSet, Parameter, ROLL_DYNAMICS};
use crate::diagnose::fit::layout::{fits_roll, Layout};
use crate::diagnose::fit::FitOutcome;
use crate::diagnose::model::axles::AXLE_BOUNDS;
use crate::diagnose::model::Augmented;
use crate::diagnose::report::ParameterValue;

/// A set of effects with their fitted values, and the model builder.
#[derive(Clone)]
pub(crate) struct Setting<'a> {
    pub(crate) base: &'a Bases,
    pub(crate) kinds: Vec<EffectKind>,
    pub(crate) fixed: EffectSet,
}

/// The start of a combination: the axle characteristics and effect values
/// of the current set, the added effect's values from its single fit, and
/// the roll dynamics from whichever of the two fitted them (the current
/// set first).
pub(crate) fn combined_start(
    current: (&[EffectKind], &[f64]),
    added: (EffectKind, &[f64]),
    axle_count: usize,
) -> Vec<f64> {
    let (kinds, p) = current;
    let effect_len: usize = kinds.iter().map(|e| e.parameters().len()).sum();
    let end = axle_count + effect_len;
    let n = added.0.parameters().len();
    let mut start = p[..end].to_vec();
    start.extend(&added.1[axle_count..axle_count + n]);
    if fits_roll(kinds) {
        start.extend(&p[end..end + 2]);
    } else if added.0.uses_roll() {
        start.extend(&added.1[axle_count + n..axle_count + n + 2]);
    }
    start
}

impl Setting<'_> {
    pub(crate) fn axle(&self) -> bool {
        self.base.axle.is_some()
    }
    /// What this setting's parameters set on `base` ([`with_effects`]).
    pub(crate) fn layout(&self, base: &Augmented) -> Layout {
        Layout {
            base: base.clone(),
            kinds: self.kinds.clone(),
            axle: self.axle(),
        }
    }
    /// The effect parameters in vector order, the roll dynamics last.
    pub(crate) fn parameters(&self) -> impl Iterator<Item = &'static Parameter> + '_ {
        let roll = if fits_roll(&self.kinds) {
            &ROLL_DYNAMICS[..]
        } else {
            &[]
        };
        self.kinds
            .iter()
            .flat_map(|e| e.parameters().iter())
            .chain(roll.iter())
    }
    pub(crate) fn bounds(&self) -> Vec<(f64, f64)> {
        let axle = if self.axle() { &AXLE_BOUNDS[..] } else { &[] };
        axle.iter()
            .copied()
            .chain(self.parameters().map(|q| q.bounds))
            .collect()
    }
    pub(crate) fn off(&self) -> Vec<f64> {
        let axle = self.base.axle.as_ref().map_or(&[][..], |a| &a.0[..]);
        let roll = self.base.all.roll;
        let mut p: Vec<f64> = axle
            .iter()
            .copied()
            .chain(self.kinds.iter().flat_map(|e| {
                e.parameters().iter().map(|q| {
                    if q.off.is_nan() {
                        self.base.nominal_share
                    } else {
                        q.off
                    }
                })
            }))
            .collect();
        if fits_roll(&self.kinds) {
            p.extend([roll.frequency, roll.damping]);
        }
        p
    }
}

/// The effect parameters of a fit whose first `skip` parameters are the
/// axle characteristics.
pub(crate) fn parameter_values(
    kinds: &[EffectKind],
    f: &FitOutcome,
    skip: usize,
) -> Vec<ParameterValue> {
    let named = kinds
        .iter()
        .flat_map(|e| e.parameters().iter().map(move |q| (e.name(), q)));
    let roll = fits_roll(kinds).then_some(ROLL_DYNAMICS.iter().map(|q| ("roll", q)));
    named
        .chain(roll.into_iter().flatten())
        .enumerate()
        .map(|(i, (group, q))| {
            ParameterValue::of(group, q, f.params[skip + i], f.std_errors[skip + i])
        })
        .collect()
}
