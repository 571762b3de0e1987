//! A Magic Formula 5.2 / 6.1 / 6.2 named as a campaign's rig model: those
//! are fitted in stages by `identify` and read as `.tir` files, not fitted
//! by the diagnosis's swarm, so the answer says how to make and give one.

use thiserror::Error;

/// A Magic Formula named as `[tyres] model` beside rig data.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("`{model}` is no model the diagnosis fits to rig data (one of {}): the Magic Formula is fitted in stages by `handling identify <rig> --model mf61 --out base.tir` (or mf62), and its .tir given as `[tyres] file = \"base.tir\"` (or `front` and `rear`)", fitted.join(", "))]
pub struct StagedMagicFormula {
    /// The name given.
    pub model: String,
    /// The models the diagnosis fits to rig data.
    pub fitted: Vec<&'static str>,
}
