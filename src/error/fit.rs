//! Fit errors: a tyre fit that cannot be made (too few points, loads or
//! test conditions; a model with nothing to fit; rig data with no channel
//! the job can use) or whose result does not survive its own check; and the
//! diagnosis's failures on the rig data of its base model.

use super::Error;
use std::path::PathBuf;
use thiserror::Error as ThisError;

/// The rounded loads of a message, N.
fn rounded(loads: &[f64]) -> Vec<f64> {
    loads.iter().map(|l| l.round()).collect()
}

/// `channel: ` when a channel is named.
fn prefix(channel: &Option<&'static str>) -> String {
    channel.map_or(String::new(), |c| format!("{c}: "))
}

/// Why a fit cannot be made, or failed.
#[derive(Debug, ThisError)]
#[non_exhaustive]
pub enum FitError {
    /// No more points than free parameters.
    #[error("{points} points with a measured {quantity} cannot fit {parameters} parameters")]
    TooFewPoints {
        /// Points with the quantity measured.
        points: usize,
        /// The measured quantity (`lateral force`, …).
        quantity: &'static str,
        /// Free parameters.
        parameters: usize,
    },
    /// A model without parameters for the quantity.
    #[error("the {model} model has no {quantity} to fit")]
    NothingToFit {
        /// The tyre model.
        model: &'static str,
        /// The quantity.
        quantity: &'static str,
    },
    /// Fewer distinct loads than the model's load dependence needs.
    #[error(
        "the {model} model's load dependence needs at least {needed} loads; the data has {} ({:?} N)",
        loads.len(),
        rounded(loads)
    )]
    TooFewLoads {
        /// The tyre model.
        model: &'static str,
        /// Loads it needs.
        needed: usize,
        /// The distinct loads of the data, N.
        loads: Vec<f64>,
    },
    /// Too few test conditions for a method.
    #[error("{method} needs at least {needed} test conditions; the data have {have}")]
    TooFewConditions {
        /// The method.
        method: &'static str,
        /// Conditions it needs.
        needed: usize,
        /// Conditions in the data.
        have: usize,
    },
    /// No stage of a staged identification had the rows it needs; each
    /// stage's reason. Transitional: the staged fit (`identify::mf_staged`)
    /// still gives its reasons as text.
    #[error("no stage could be fitted ({})", .0.join("; "))]
    NoStageFitted(Vec<String>),
    /// A written tyre file that does not reproduce the fitted forces.
    #[error("the written .tir does not reproduce the fitted forces (relative difference {difference:.2e})")]
    RoundTrip {
        /// Relative difference of the forces.
        difference: f64,
    },
    /// Rig data without lateral data, for a model without a longitudinal
    /// force.
    #[error("{}: no lateral data (columns `alpha` and `fy`), and the {model} model has no longitudinal force", data.display())]
    NoLateralData {
        /// The rig data.
        data: PathBuf,
        /// The tyre model.
        model: &'static str,
    },
    /// Rig data with neither lateral nor longitudinal data.
    #[error("{}: no lateral data and no longitudinal data", data.display())]
    NoData {
        /// The rig data.
        data: PathBuf,
    },
    /// Rig data in which the grouping found no test condition.
    #[error("{}: no test condition found in the data ({})", data.display(), grouping.join("; "))]
    NoCondition {
        /// The rig data.
        data: PathBuf,
        /// The grouping report's lines.
        grouping: Vec<String>,
    },
    /// A fit to rig data that failed: the data and, where several channels
    /// are fitted, the channel.
    #[error("{}: {}{source}", data.display(), prefix(channel))]
    InData {
        /// The rig data.
        data: PathBuf,
        /// The channel fitted (`aligning moment`, …).
        channel: Option<&'static str>,
        /// Why the fit failed.
        source: Box<Error>,
    },
}

impl FitError {
    /// A failure of a fit to `data`, of `channel` where named.
    pub(crate) fn in_data(data: &std::path::Path, channel: Option<&'static str>, e: Error) -> Self {
        FitError::InData {
            data: data.to_path_buf(),
            channel,
            source: Box::new(e),
        }
    }
}

/// Why the diagnosis of a campaign could not be made.
#[derive(Debug, ThisError)]
#[non_exhaustive]
pub enum DiagnosisError {
    /// Rig data of the base model with no lateral test condition.
    #[error("{}: no lateral test condition in the rig data", rig.display())]
    NoRigCondition {
        /// The rig data.
        rig: PathBuf,
    },
    /// The base model's fit to its rig data failed.
    #[error("{}: {source}", rig.display())]
    RigFit {
        /// The rig data.
        rig: PathBuf,
        /// Why the fit failed.
        source: Box<Error>,
    },
}
