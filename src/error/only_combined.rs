//! A rig file whose rows are all combined slip (both slips at once), read
//! for a fit of one slip at a time: every row is set aside
//! (`identify/pure.rs`), and the grouping's "0 samples" alone left the
//! user to find where the file's rows went.

use std::path::PathBuf;

/// Every row of a rig file combined slip, none left for a pure-slip fit.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "{}: no pure-slip rows to fit: all {rows} rows of the file are combined slip (|alpha| > {tol} rad and |kappa| > {tol}), set aside: the {model} model is fitted to pure slip only (its lateral force at kappa = 0, its longitudinal force at alpha = 0); give a cornering sweep at kappa = 0 or a braking/driving sweep at alpha = 0",
    data.display()
)]
pub struct OnlyCombined {
    /// The rig data.
    pub data: PathBuf,
    /// Its rows, every one combined slip.
    pub rows: usize,
    /// The model asked for.
    pub model: &'static str,
    /// The slip above which a row's slip is not pure (rad for α, and κ).
    pub tol: f64,
}
