//! The registry of tyre models: the one list of the crate's models (one line
//! each, expanded by `generate.rs` into the [`Tyre`] enum and the
//! [`ModelName`] constants), the models registered at run time
//! ([`register`]), and every list derived from them: the names a tyre
//! file's `model` key accepts ([`model_names`]), the models a swarm fits
//! ([`swarm_models`]), the names of `identify --model` (each entry's
//! [`Identification`]), and the messages that list them.
//!
//! The model files do not import this file; it imports them. Units and
//! signs are those of `tyre/mod.rs`.

use super::erased::{Buffered, Erased, Tagged};
use super::generate::tyre_models;
use super::{
    Gim, Identification, LateralVisitor, Linear, MagicFormula, MagicSimple, MaybeLateralForceOf,
    Model, ModelName, ModelParameters, Pac89, SlipState, TyreModel, UniTire,
};
use crate::error::{Error, NameKind, OptionsError};
use serde::de::{DeserializeSeed, Deserializer, Error as _, MapAccess, Visitor};
use serde::{Deserialize, Serialize, Serializer};
use std::any::TypeId;
use std::borrow::{Borrow, BorrowMut};
use std::fmt;
use std::sync::{PoisonError, RwLock};

// The crate's tyre models, one line each, in the order every list shows
// them. The variant name is the `Tyre` variant and the `ModelName`
// constant; the model's own file gives its name, its construction and its
// identification (`Model`).
tyre_models! {
    /// Gim / brush model with adhesion and sliding regions.
    Gim(Gim),
    /// Simplified Magic Formula `Fy = μ·Fz·sin(C·atan(B·α))` (Li, Jia & Zhao).
    MagicSimple(MagicSimple),
    /// UniTire pure-slip model (Zhang & Li (2017)).
    Unitire(UniTire),
    /// PAC89 Magic Formula in the Adams numbering (Zhang et al. (2021)).
    Pac89(Pac89),
    /// Linear tyre `Fy = C_α·α` (the textbook bicycle model).
    Linear(Linear),
    /// Magic Formula 5.2/6.1/6.2, usually read from a `.tir` file.
    MagicFormula(MagicFormula, boxed),
}

/// A model as the registry holds it, its type erased: its name, how it is
/// identified, its start tyre and its construction from a tyre file's table.
pub trait ModelEntry: Send + Sync {
    /// The model's name ([`Model::NAME`]).
    fn name(&self) -> ModelName;
    /// How `identify` fits it ([`Model::IDENTIFICATION`]).
    fn identification(&self) -> Identification;
    /// The start tyre of a fit to data whose median load is `fz`
    /// ([`Model::start`]).
    fn start(&self, fz: f64) -> Option<Tyre>;
    /// The tyre of a tyre file's table without its `model` key.
    fn read_table(&self, table: toml::Table) -> Result<Tyre, toml::de::Error>;
    /// The Rust type of the model (a second registration of the same type
    /// is no conflict).
    fn model_type(&self) -> TypeId;
}

/// The registry entry of model `M`: the model and how its tyre is held in
/// a [`Tyre`].
pub struct Registration<M> {
    wrap: fn(M) -> Tyre,
}

impl<M: Model> Registration<M> {
    const fn new(wrap: fn(M) -> Tyre) -> Self {
        Self { wrap }
    }
}

impl<M: Model> ModelEntry for Registration<M> {
    fn name(&self) -> ModelName {
        ModelName::new(M::NAME)
    }
    fn identification(&self) -> Identification {
        M::IDENTIFICATION
    }
    fn start(&self, fz: f64) -> Option<Tyre> {
        M::start(fz).map(self.wrap)
    }
    fn read_table(&self, table: toml::Table) -> Result<Tyre, toml::de::Error> {
        toml::Value::Table(table).try_into::<M>().map(self.wrap)
    }
    fn model_type(&self) -> TypeId {
        TypeId::of::<M>()
    }
}

/// The models registered at run time, after the list's.
static REGISTERED: RwLock<Vec<&'static dyn ModelEntry>> = RwLock::new(Vec::new());

/// Registers model `M`, defined outside the crate: from then on its tyre
/// files are read (`model = "<M::NAME>"`), and `simulate`, `tyre-eval`,
/// `identify` (as its [`Model::IDENTIFICATION`] says) and every list of
/// models know it. Registering the same model again changes nothing; a
/// different model under a name already taken is refused.
pub fn register<M: Model>() -> Result<ModelName, Error> {
    let mut registered = REGISTERED.write().unwrap_or_else(PoisonError::into_inner);
    let taken = BUILT_IN
        .iter()
        .chain(registered.iter())
        .find(|e| e.name().as_str() == M::NAME);
    match taken {
        Some(e) if e.model_type() == TypeId::of::<M>() => Ok(e.name()),
        Some(_) => Err(Error::Options(OptionsError::ModelNameTaken {
            name: M::NAME,
        })),
        None => {
            let entry: &'static Registration<M> = Box::leak(Box::new(Registration::new(|m| {
                Tyre::Registered(Erased::new(m))
            })));
            registered.push(entry);
            Ok(ModelName::new(M::NAME))
        }
    }
}

/// Every model: the list's, then those registered at run time.
pub fn models() -> Vec<&'static dyn ModelEntry> {
    let registered = REGISTERED.read().unwrap_or_else(PoisonError::into_inner);
    BUILT_IN.iter().chain(registered.iter()).copied().collect()
}

/// The names a tyre file's `model` key accepts, in [`models`]' order.
pub fn model_names() -> Vec<ModelName> {
    models().iter().map(|e| e.name()).collect()
}

/// The models `identify` fits by the swarm from their start tyre, in
/// [`models`]' order.
pub fn swarm_models() -> Vec<ModelName> {
    models()
        .iter()
        .filter(|e| e.identification().by_swarm())
        .map(|e| e.name())
        .collect()
}

/// The entry of the model named `name` (`magic-simple`, or as Python
/// spells it, `magic_simple`).
fn entry(name: &str) -> Option<&'static dyn ModelEntry> {
    let name = name.replace('_', "-");
    models().into_iter().find(|e| e.name().as_str() == name)
}

impl ModelName {
    /// The registry's entry of this model.
    pub fn entry(self) -> &'static dyn ModelEntry {
        entry(self.as_str()).expect("a ModelName is made only for a registered model")
    }

    /// The start tyre of a fit of this model to data whose median load is
    /// `fz` ([`Model::start`]); `None` for a model the swarm does not fit
    /// (the Magic Formula, identified in stages).
    pub(crate) fn start_tyre(self, fz: f64) -> Option<Tyre> {
        self.entry().start(fz)
    }

    /// How `identify` fits this model.
    pub fn identification(self) -> Identification {
        self.entry().identification()
    }
}

impl std::str::FromStr for ModelName {
    type Err = OptionsError;
    fn from_str(s: &str) -> Result<Self, OptionsError> {
        crate::error::named(&model_names(), ModelName::as_str, NameKind::TyreModel, s)
    }
}

impl<'de> Deserialize<'de> for ModelName {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let s = String::deserialize(d)?;
        s.parse().map_err(D::Error::custom)
    }
}

/// A tyre file's table: its `model` key picks the model from the registry,
/// which reads the other keys. An unknown model is an error at the `model`
/// value; an error in the model's keys is the model's own (unknown field,
/// wrong type, missing key).
impl<'de> Deserialize<'de> for Tyre {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let (entry, table) = d.deserialize_map(TyreTable)?;
        entry
            .read_table(table)
            .map_err(|e| D::Error::custom(e.message()))
    }
}

/// Reads a tyre's table: the entry its `model` key names and the other keys.
struct TyreTable;

impl<'de> Visitor<'de> for TyreTable {
    type Value = (&'static dyn ModelEntry, toml::Table);

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a tyre table with a `model` key")
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
        let (mut model, mut table) = (None, toml::Table::new());
        while let Some(key) = map.next_key::<String>()? {
            if key == "model" {
                if model.is_some() {
                    return Err(A::Error::duplicate_field("model"));
                }
                model = Some(map.next_value_seed(ModelKey)?);
            } else if let Buffered(Some(v)) = map.next_value()? {
                table.insert(key, v);
            }
        }
        let model = model.ok_or_else(|| A::Error::missing_field("model"))?;
        Ok((model, table))
    }
}

/// The `model` key's value: the registry's entry of that name.
struct ModelKey;

impl<'de> DeserializeSeed<'de> for ModelKey {
    type Value = &'static dyn ModelEntry;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_str(self)
    }
}

impl<'de> Visitor<'de> for ModelKey {
    type Value = &'static dyn ModelEntry;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("the name of a tyre model")
    }

    fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<Self::Value, E> {
        entry(v).ok_or_else(|| {
            let names: Vec<String> = model_names().iter().map(|n| format!("`{n}`")).collect();
            E::custom(format!(
                "unknown variant `{v}`, expected one of {}",
                names.join(", ")
            ))
        })
    }
}
