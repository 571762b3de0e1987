//! The tyre model a campaign's `[tyres] model` names for its rig data
//! (`pac89` unless named): one the swarm fits, a staged Magic Formula
//! refused with how to get one. Apart from the campaign's tables
//! (`mod.rs`) so that its tyre source reads on a screen.

use crate::error::{
    named, CampaignReason, InputError, NameKind, ParamError, ParamReason, StagedMagicFormula,
};
use crate::io::toml_file::TomlSource;
use crate::tyre::{swarm_models, ModelName};

/// The model `name` (`[tyres] model`) the rig data is fitted to, or the
/// error at the key.
pub(super) fn rig_model(src: &TomlSource, name: &str) -> Result<ModelName, InputError> {
    // A Magic Formula named here is a .tir fitted by `identify`: say how
    // (a fresh user's guess, answered with a list it is not on).
    if ["mf52", "mf61", "mf62"].contains(
        &name
            .to_ascii_lowercase()
            .replace(['.', '_', '-'], "")
            .as_str(),
    ) {
        return Err(src.value_error(&ParamError::without_value(
            "tyres.model",
            ParamReason::Campaign(Box::new(CampaignReason::StagedMagicFormula(
                StagedMagicFormula {
                    model: name.to_string(),
                    fitted: swarm_models().iter().map(|m| m.as_str()).collect(),
                },
            ))),
        )));
    }
    // The rig fit starts a swarm, which the staged Magic Formula does not.
    named(
        &swarm_models(),
        ModelName::as_str,
        NameKind::TyreModel,
        name,
    )
    .map_err(|why| {
        src.value_error(&ParamError::without_value(
            "tyres.model",
            ParamReason::Name(Box::new(why)),
        ))
    })
}
