//! Axles identified from the runs that lie outside the stated tyre class's
//! prior but inside another class's ranges ([`ClassMismatch`]): a verdict
//! that would otherwise blame a model-form error outside the library
//! points at the campaign's `[tyres] class` instead. Typed here, found by
//! `crate::diagnose::verdict::class`, worded by `super::words`. Units:
//! cornering coefficients in 1/rad.

use crate::diagnose::campaign::prior::TyreClass;
use crate::diagnose::effects::EffectKind;
use serde::Serialize;

/// The stated class misses axles another class's ranges hold.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ClassMismatch {
    /// The class whose prior the fits used (`[tyres] class`, road where
    /// the campaign states none).
    pub stated: TyreClass,
    /// Its 95 % range of the cornering coefficient, 1/rad.
    pub stated_cornering: [f64; 2],
    /// The classes whose 95 % ranges hold the axles (both cornering
    /// coefficients, and the peak friction where it was fitted), nearest
    /// first (smallest largest `|z|`).
    pub holding: Vec<TyreClass>,
    /// The nearest one's cornering range, 1/rad.
    pub holding_cornering: [f64; 2],
    /// The effects fitted jointly with the axles (empty: the base alone).
    pub effects: Vec<EffectKind>,
    /// The share of the held-out gap above noise they remove, % (None for
    /// the base alone).
    pub reduction_percent: Option<f64>,
    /// Front and rear cornering coefficients, 1/rad.
    pub cornering: [f64; 2],
}
