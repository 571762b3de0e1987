//! What a candidate's cross-validation can take without refitting: the
//! base model's own fold refits for the base's score, and the held-out
//! errors of a fold's model. Units: SI, rad; errors as
//! [`ChannelErrors`] (sums of squared unscaled residuals per channel).

use super::{Context, Fitted};
use crate::diagnose::fit::FitOutcome;
use crate::diagnose::model::channels::ChannelErrors;
use crate::diagnose::model::Augmented;

impl Context<'_> {
    /// The base's own fold refits (its axles per fold) where `fitted` is the
    /// base model refitted (no effect) and `full`, its all-run fit, is the
    /// base's to the last bit, in the same box with the same prior's rows:
    /// its folds' refits would repeat the base's replay for replay (the same
    /// start, linearisation and training problem), so their parameters are
    /// taken as they are. (On a 600 s oval log in 20 pieces, the base's
    /// eight fold refits took 575 replays, 5 % of the diagnosis.) The
    /// base's refits do not keep whether they converged, and nothing reads
    /// it of the base's score ([`crate::diagnose::verdict::baseline`]
    /// reads its errors and BIC): they count as converged.
    pub(super) fn base_folds(&self, fitted: &Fitted, full: &FitOutcome) -> Option<&Vec<Vec<f64>>> {
        let (p, folds) = self.bases.axle.as_ref()?;
        let same = fitted.setting.kinds().is_empty()
            && *p == full.params
            && folds.len() == self.folds.len()
            && fitted.prior == self.bases.prior
            && fitted.bounds == crate::diagnose::model::axles::AXLE_BOUNDS;
        same.then_some(folds)
    }

    /// The errors of `model` on fold `k`'s held-out runs.
    pub(super) fn heldout_errors(&self, k: usize, model: &Augmented) -> ChannelErrors {
        let mut e = ChannelErrors::default();
        for &i in &self.folds[k] {
            e.add(&self.runs[i].errors(model));
        }
        e
    }
}
