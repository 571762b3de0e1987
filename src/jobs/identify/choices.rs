//! The choices of `identify`: the model (from the tyre registry: each
//! model with a swarm fit under its own name, each version of a staged fit
//! under its name), the local polish after the swarm, and where the staged
//! Magic Formula fit starts. Each parses from its command-line name and
//! lists its names, so the command line and Python take them as text.

use crate::error::{named, Error, NameKind, OptionsError};
use crate::identify::LocalMethod;
use crate::tyre::{models, Identification, MagicFormula, ModelName, StagedFit};
use serde::Serialize;

/// A model `identify` fits, from the registry ([`crate::tyre::models`]): a
/// model with a swarm fit under its own name, or one version of a model's
/// staged fit (the Magic Formula's `mf61`, `mf62`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum IdentifyModel {
    /// The swarm fit of this model.
    Swarm(ModelName),
    /// One version of this model's staged fit, as its registry entry
    /// gives it.
    Staged(ModelName, StagedFit),
}

#[allow(non_upper_case_globals)]
impl IdentifyModel {
    /// Magic Formula 6.1, Wei et al.'s (2010) staged fit.
    pub const Mf61: IdentifyModel =
        IdentifyModel::Staged(ModelName::MagicFormula, MagicFormula::FIT_MF61);
    /// Magic Formula 6.2 (`FITTYP = 62`), the same stages.
    pub const Mf62: IdentifyModel =
        IdentifyModel::Staged(ModelName::MagicFormula, MagicFormula::FIT_MF62);

    /// Every model `identify` fits, in the registry's order (a staged
    /// model's versions in its order): the values of `--model`.
    pub fn all() -> Vec<IdentifyModel> {
        models()
            .iter()
            .flat_map(|e| match e.identification() {
                Identification::Swarm | Identification::SwarmAndTwoStage => {
                    vec![IdentifyModel::Swarm(e.name())]
                }
                Identification::Staged(fits) => fits
                    .iter()
                    .map(|fit| IdentifyModel::Staged(e.name(), *fit))
                    .collect(),
                Identification::NotFitted => Vec::new(),
            })
            .collect()
    }

    /// The names of [`IdentifyModel::all`].
    pub fn names() -> Vec<&'static str> {
        Self::all().into_iter().map(Self::as_str).collect()
    }

    /// The name on the command line and in file names.
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Swarm(m) => m.as_str(),
            Self::Staged(_, fit) => fit.name,
        }
    }

    /// The tyre model of a swarm fit (`None`: a staged fit).
    pub(crate) fn swarm_model(self) -> Option<ModelName> {
        match self {
            Self::Swarm(m) => Some(m),
            Self::Staged(..) => None,
        }
    }
}

impl std::fmt::Display for IdentifyModel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

impl std::str::FromStr for IdentifyModel {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self, Error> {
        // `mf52` is a version the readers take, not a misspelt `mf62`:
        // said as such, with the models that are fitted.
        let bare: String = s
            .to_ascii_lowercase()
            .chars()
            .filter(|c| c.is_ascii_alphanumeric())
            .collect();
        if ["mf52", "mf5", "magicformula52"].contains(&bare.as_str()) {
            return Err(Error::Options(OptionsError::VersionNotFitted {
                given: s.to_string(),
                version: "5.2",
                known: Self::names(),
            }));
        }
        named(&Self::all(), IdentifyModel::as_str, NameKind::TyreModel, s).map_err(Error::Options)
    }
}

impl Serialize for IdentifyModel {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}

/// The local polish after the swarm.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Polish {
    /// Levenberg–Marquardt.
    #[default]
    Lm,
    /// Zhang & Li's (2017) modified Gauss–Newton.
    Gn,
    /// None: the swarm's best as it is.
    None,
}

impl Polish {
    /// Every polish, in the order the messages list them.
    pub const ALL: [Polish; 3] = [Polish::Lm, Polish::Gn, Polish::None];

    /// The name on the command line.
    pub fn as_str(self) -> &'static str {
        match self {
            Polish::Lm => "lm",
            Polish::Gn => "gn",
            Polish::None => "none",
        }
    }

    /// The method in words, as the terminal names it.
    pub fn method(self) -> &'static str {
        match self {
            Polish::Lm => "Levenberg–Marquardt",
            Polish::Gn => "Gauss–Newton",
            Polish::None => "no",
        }
    }
}

impl std::str::FromStr for Polish {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self, Error> {
        Polish::ALL
            .into_iter()
            .find(|p| p.as_str() == s)
            .ok_or_else(|| {
                OptionsError::UnknownLocalMethod {
                    given: s.to_string(),
                }
                .into()
            })
    }
}

impl From<Polish> for LocalMethod {
    fn from(p: Polish) -> Self {
        match p {
            Polish::Lm => LocalMethod::LevenbergMarquardt,
            Polish::Gn => LocalMethod::GaussNewton,
            Polish::None => LocalMethod::None,
        }
    }
}

/// Where the staged Magic Formula fit starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum StartArg {
    /// Estimates from the data, then a Levenberg–Marquardt projected onto the bounds.
    #[default]
    Data,
    /// Wei et al. (2010): every parameter 1, μ = 0.1, β = 5.
    Paper,
    /// The template's values, then a Levenberg–Marquardt projected onto the bounds.
    Template,
}

impl StartArg {
    /// Every start, in the order the messages list them.
    pub const ALL: [StartArg; 3] = [StartArg::Data, StartArg::Paper, StartArg::Template];

    /// The name on the command line.
    pub fn as_str(self) -> &'static str {
        match self {
            StartArg::Data => "data",
            StartArg::Paper => "paper",
            StartArg::Template => "template",
        }
    }
}

impl std::str::FromStr for StartArg {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self, Error> {
        named(&StartArg::ALL, StartArg::as_str, NameKind::Start, s).map_err(Error::Options)
    }
}
