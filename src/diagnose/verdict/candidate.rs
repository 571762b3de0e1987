//! A candidate of the diagnosis as a parameter vector ([`Setting`]): its
//! [`Layout`] (the axle characteristics of an identified base first when
//! the base has them, then each effect's parameters, then the roll
//! dynamics when a roll effect is among them), its bounds and off values,
//! and its fitted parameters as report rows ([`parameter_values`]). The
//! start of a combination from its members' fits is
//! [`Layout::combined`]. Units: SI, rad; the roll frequency in Hz.

use crate::diagnose::base::Bases;
use crate::diagnose::effects::{EffectKind, Group};
use crate::diagnose::fit::layout::Layout;
use crate::diagnose::fit::FitOutcome;
use crate::diagnose::model::axles::AXLE_BOUNDS;
use crate::diagnose::report::traded::traded;
use crate::diagnose::report::ParameterValue;

/// A set of effects on the base models, as a parameter vector.
#[derive(Clone)]
pub(crate) struct Setting<'a> {
    pub(crate) base: &'a Bases,
    pub(crate) layout: Layout,
}

impl<'a> Setting<'a> {
    /// The vector of `kinds` on `base` (after its axle characteristics
    /// when it has them).
    pub(crate) fn new(base: &'a Bases, kinds: Vec<EffectKind>) -> Self {
        let axle = base.axle.is_some();
        Self {
            base,
            layout: Layout { kinds, axle },
        }
    }

    /// The effects, in vector order.
    pub(crate) fn kinds(&self) -> &[EffectKind] {
        &self.layout.kinds
    }

    pub(crate) fn bounds(&self) -> Vec<(f64, f64)> {
        let axle = if self.layout.axle {
            &AXLE_BOUNDS[..]
        } else {
            &[]
        };
        axle.iter()
            .copied()
            .chain(self.layout.parameters().map(|(_, q)| q.bounds))
            .collect()
    }

    /// The vector with every effect off: the base's axle characteristics,
    /// each effect's off values (the vehicle's own share where NaN), the
    /// base's roll dynamics.
    pub(crate) fn off(&self) -> Vec<f64> {
        let axle = self.base.axle.as_ref().map_or(&[][..], |a| &a.0[..]);
        let roll = self.base.all.effects().roll;
        let mut p: Vec<f64> = axle
            .iter()
            .copied()
            .chain(self.layout.kinds.iter().flat_map(|e| {
                e.parameters().iter().map(|q| {
                    if q.off.is_nan() {
                        self.base.nominal_share
                    } else {
                        q.off
                    }
                })
            }))
            .collect();
        if self.layout.fits_roll() {
            p.extend([roll.frequency, roll.damping]);
        }
        p
    }
}

/// The effect parameters (and roll dynamics) of a fit of `layout`, as
/// report rows.
///
/// `folds`: the parameters of each fold refit (none where the candidate was
/// not cross-validated), for each parameter's jackknife, and the
/// jackknife the runs' noise alone gives each, in standard errors, with
/// its degrees of freedom ([`crate::diagnose::fit::fold_noise`]).
/// `inexact`: the fit leaves a held-out error above the noise level, so
/// each parameter reports the larger of its asymptotic standard error and
/// its fold spread ([`ParameterValue::with_model_error`]).
pub(crate) fn parameter_values(
    layout: &Layout,
    f: &FitOutcome,
    (folds, noise): (&[Vec<f64>], &[(f64, f64)]),
    inexact: bool,
) -> Vec<ParameterValue> {
    let at = layout.effects().start;
    let reported = f.reported_std_errors();
    let groups: Vec<Group> = layout.parameters().map(|(g, _)| g).collect();
    let mut values: Vec<ParameterValue> = layout
        .parameters()
        .enumerate()
        .map(|(i, (group, q))| {
            let fold_values: Vec<f64> = folds.iter().map(|p| p[at + i]).collect();
            let factor = noise.get(at + i).copied().filter(|x| x.0.is_finite());
            let v = ParameterValue::of(group, q, f.params[at + i], reported[at + i])
                .with_folds(&fold_values, factor);
            if f.is_unseen(at + i) {
                v.unseen()
            } else if let Some(se) = f.held_for(at + i) {
                v.held(se)
            } else {
                v.with_model_error(inexact)
            }
        })
        .collect();
    // A pair of one effect whose sum the runs determine far better than
    // either ([`traded`]): said on the second of the two.
    let Some(c) = &f.robust_covariance else {
        return values;
    };
    for b in 0..values.len() {
        for a in (0..b).filter(|&a| groups[a] == groups[b]) {
            let sums: Vec<f64> = folds.iter().map(|p| p[at + a] + p[at + b]).collect();
            if let Some(t) = traded(&values[a], &values[b], c[(at + a, at + b)], &sums) {
                values[b].traded = Some(t);
                break;
            }
        }
    }
    values
}
