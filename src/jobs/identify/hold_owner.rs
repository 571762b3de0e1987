//! A `--hold` name that belongs to another model than the one chosen:
//! said with the model it belongs to and the `--model` that fits it, and
//! an example of the chosen model's own (`--model mf62 --hold a1=-22`
//! had said only "not one of the 177 known", a1 being PAC89's). Every
//! model `identify` fits is asked, in `--model`'s order: the swarm
//! models' fitted parameters (every block), the staged Magic Formula
//! fits' `.tir` coefficients. The example is `holds.rs`'s, as a malformed
//! `--hold` gives it.

use super::choices::IdentifyModel;
use super::holds::CHECK_LOAD;
use crate::error::OptionsError;
use crate::identify::{fitted_names, start_tyre_of};
use crate::tyre::mf::MfCoefficients;

/// Most names of the chosen model listed in the refusal (the Magic
/// Formula's 177 are not: its example stands for them).
const LISTED: usize = 40;

/// The names `--hold` takes for `model`.
fn names_of(model: IdentifyModel) -> Vec<String> {
    match model.swarm_model() {
        Some(m) => start_tyre_of(m, CHECK_LOAD)
            .map(|t| fitted_names(&t))
            .unwrap_or_default(),
        None => MfCoefficients::NAMES
            .iter()
            .map(|n| n.to_string())
            .collect(),
    }
}

/// The refusal of `--hold name` for `chosen` where `name` is none of its
/// own but a parameter of another model `identify` fits; `None` where no
/// model has it (the caller's own refusal then lists the known names).
pub(super) fn of_another_model(name: &str, chosen: IdentifyModel) -> Option<OptionsError> {
    let owner = IdentifyModel::all()
        .into_iter()
        .filter(|m| *m != chosen)
        .find(|m| names_of(*m).iter().any(|n| n == name))?;
    let own = names_of(chosen);
    let known = match own.len() {
        1..=LISTED => format!(" (its parameters are {})", own.join(", ")),
        _ => String::new(),
    };
    Some(OptionsError::HoldOfOtherModel {
        known,
        given: name.to_string(),
        owner: owner.as_str(),
        model: chosen.as_str(),
        example: super::holds::hold_example(chosen),
    })
}
