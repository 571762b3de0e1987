//! The tyre models as a closed set of names (the `model` key of a tyre
//! file), and the start tyre of a fit of each: the one place besides the
//! [`Tyre`] enum that lists the models.

use super::{Gim, Linear, MagicFormula, MagicSimple, ModelParameters, Pac89, Tyre, UniTire};
use serde::{Deserialize, Serialize};

/// The tyre models, a closed set: the `model` key of a tyre file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum ModelName {
    /// [`Gim`].
    Gim,
    /// [`MagicSimple`].
    MagicSimple,
    /// [`UniTire`].
    Unitire,
    /// [`Pac89`].
    Pac89,
    /// [`Linear`].
    Linear,
    /// [`MagicFormula`].
    MagicFormula,
}

impl ModelName {
    /// Every model, in the order of the [`Tyre`] variants.
    pub const ALL: [ModelName; 6] = [
        ModelName::Gim,
        ModelName::MagicSimple,
        ModelName::Unitire,
        ModelName::Pac89,
        ModelName::Linear,
        ModelName::MagicFormula,
    ];

    /// The name as a tyre file writes it.
    pub const fn as_str(self) -> &'static str {
        match self {
            ModelName::Gim => "gim",
            ModelName::MagicSimple => "magic-simple",
            ModelName::Unitire => "unitire",
            ModelName::Pac89 => "pac89",
            ModelName::Linear => "linear",
            ModelName::MagicFormula => "magic-formula",
        }
    }

    /// The start tyre of a fit of this model to data whose median load is
    /// `fz` ([`ModelParameters::start`]); `None` for a model the swarm does
    /// not fit (the Magic Formula, identified in stages).
    pub fn start_tyre(self, fz: f64) -> Option<Tyre> {
        match self {
            ModelName::Gim => Gim::start(fz).map(Tyre::Gim),
            ModelName::MagicSimple => MagicSimple::start(fz).map(Tyre::MagicSimple),
            ModelName::Unitire => UniTire::start(fz).map(Tyre::Unitire),
            ModelName::Pac89 => Pac89::start(fz).map(Tyre::Pac89),
            ModelName::Linear => Linear::start(fz).map(Tyre::Linear),
            ModelName::MagicFormula => {
                MagicFormula::start(fz).map(|m| Tyre::MagicFormula(Box::new(m)))
            }
        }
    }

    /// The models that have a start tyre, in [`ModelName::ALL`]'s order.
    pub fn fitted() -> Vec<ModelName> {
        Self::ALL
            .into_iter()
            .filter(|m| m.start_tyre(1.0).is_some())
            .collect()
    }
}

impl std::fmt::Display for ModelName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

impl std::str::FromStr for ModelName {
    type Err = crate::error::OptionsError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        crate::error::named(
            &Self::ALL,
            ModelName::as_str,
            crate::error::NameKind::TyreModel,
            s,
        )
    }
}

/// Names accepted by the `model` key ([`ModelName::ALL`] as strings).
pub const MODEL_NAMES: [&str; ModelName::ALL.len()] = {
    let mut out = [""; ModelName::ALL.len()];
    let mut i = 0;
    while i < out.len() {
        out[i] = ModelName::ALL[i].as_str();
        i += 1;
    }
    out
};
