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

/// What a campaign gives its tyres from when its `[tyres] model` has no
/// rig data to be fitted to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GivenTyres {
    /// Tyre files (`file`, or `front` and `rear`): read, not fitted.
    Files,
    /// No tyre data: the axles are identified from the runs.
    Nothing,
}

/// A `[tyres] model` beside no rig data: a model is fitted only to rig
/// data, so the name would be passed over in silence.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("`{model}` names a model to fit to rig data, but the campaign gives none: {}", match given {
    GivenTyres::Files => "its tyres are read from the tyre files given, whose own model is used; leave `model` out, or give `rig = \"tyre_rig.csv\"` instead of the files to fit one",
    GivenTyres::Nothing => "without tyre data the axles are identified from the runs (a linear cornering coefficient and a peak friction per axle, not a tyre model); give `rig = \"tyre_rig.csv\"` to fit the model to, or leave `model` out",
})]
pub struct TyreSourceError {
    /// The model named.
    pub model: String,
    /// Where the tyres come from instead.
    pub given: GivenTyres,
}
