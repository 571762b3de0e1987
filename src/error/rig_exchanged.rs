//! A rig file whose `fz` and `fy` columns are exchanged: the "loads" swing
//! through zero as a lateral force does over a slip-angle sweep, and the
//! "forces" are positive throughout, at the rig's load levels. Each
//! negative load was refused as a bad sample (963 of them on fresh-eyes
//! round 18's file) without the question that mends them all.

use super::number::Num;
use thiserror::Error;

/// The `fz` column shaped as a lateral force swept both ways (both signs,
/// about symmetric, filling its range) beside an `fy` column shaped as
/// loads (positive throughout, at levels).
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("columns `fz` and `fy` look exchanged: `fz` changes sign ({negative} of its {samples} samples negative, from {} to {} N), as a lateral force does over a slip-angle sweep, while `fy` is positive throughout (from {} to {} N), as loads are: swap the two names in the header (loads are positive, FORMATS.md)", Num(fz.0), Num(fz.1), Num(fy.0), Num(fy.1))]
pub struct LoadAndForceExchanged {
    /// Samples whose `fz` is negative.
    pub negative: usize,
    /// Samples with a finite `fz`.
    pub samples: usize,
    /// The `fz` column's smallest and largest, N.
    pub fz: (f64, f64),
    /// The `fy` column's smallest and largest, N.
    pub fy: (f64, f64),
}

/// The least share of the samples of each sign of an `fz` column read as
/// a lateral force swept both ways (with the rest of the shape,
/// `io/rig_exchanged.rs`): a few negative samples among positive ones are
/// bad rows, said each at its cell.
pub const EXCHANGED_SHARE: f64 = 0.1;
