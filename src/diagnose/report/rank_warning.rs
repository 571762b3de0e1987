//! The warnings on a ranked candidate, typed: a fit that does not
//! generalise, axles that are no tyre, a set that fits worse than one it
//! contains, fold refits far from the all-run fit or not converged. The
//! sentences are made from them at the edge ([`super::words`]). Errors J
//! dimensionless, reductions in percent, parameters in their own units.

use crate::diagnose::base::identify::NoTyre;
use crate::diagnose::effects::EffectKind;
use serde::Serialize;

/// A warning on a ranked candidate.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum RankWarning {
    /// Its fit on all runs removes far more of the gap than it does on
    /// held-out runs.
    Disagreement {
        /// In-sample reduction, %.
        insample_percent: f64,
        /// Held-out reduction, %.
        heldout_percent: f64,
    },
    /// Fitted with it, the axles are no tyre: it cannot be a verdict.
    AxlesNoTyre {
        /// Why.
        no_tyre: Vec<NoTyre>,
    },
    /// The set fits the runs worse in sample than a set it contains (whose
    /// optimum it contains with its other effects off): its fit stopped
    /// short, or held a parameter the smaller set fits.
    WorseThanSubset {
        /// The contained set that fits better (`a+b`).
        subset: String,
        /// Its in-sample error.
        subset_error: f64,
        /// This set's in-sample error.
        error: f64,
    },
    /// Fold refits that landed beyond
    /// [`crate::diagnose::verdict::rules::FOLD_FAR`] standard errors of
    /// the all-run fit: the held-out score measures those refits on fewer
    /// runs as much as the effect.
    FoldsFar {
        /// The parameter whose fold landed farthest (`effect.parameter`).
        parameter: String,
        /// Its all-run value.
        value: f64,
        /// Its standard error on all runs as the rule reads it: the
        /// Jacobian's, of white residuals.
        std_error: f64,
        /// Its standard error as the report gives it (robust to residuals
        /// correlated over time), which can be several times larger.
        reported_std_error: f64,
        /// The farthest fold's value.
        fold_value: f64,
        /// How far, in standard errors.
        distance: f64,
        /// Folds that landed beyond (of `folds`).
        far: usize,
        /// Folds refitted.
        folds: usize,
    },
    /// Effects of the set whose every parameter sits at its off value
    /// within its standard error
    /// ([`crate::diagnose::verdict::rules::contributes_nothing`]): they
    /// contribute nothing, cannot be named, and the set reduces to the
    /// others (whatever it gains over them comes from its axles refitted,
    /// not from those effects).
    ContributesNothing {
        /// The effects that contribute nothing.
        effects: Vec<EffectKind>,
        /// The set it reduces to (empty: the base model).
        reduces_to: Vec<EffectKind>,
    },
    /// Fold refits that did not converge.
    FoldsNotConverged {
        /// Folds that did not.
        failed: usize,
        /// Folds refitted.
        folds: usize,
    },
}
