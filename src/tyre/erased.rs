//! A tyre of a model registered at run time ([`super::register`]), held as a
//! trait object, and the serde pieces every tyre shares: the `model` tag
//! written in front of a model's own fields, and a tyre file's table
//! buffered until its `model` key has said which model reads it.
//!
//! Units and signs are those of `tyre/mod.rs`; nothing here computes a force.

use super::{Model, ModelParameters};
use serde::de::{Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::Serialize;
use std::any::Any;
use std::fmt;

/// What a tyre of any [`Model`] offers once its type is erased: the model's
/// own knowledge ([`ModelParameters`]) and what a value needs (clone,
/// compare, print, write).
pub trait ErasedModel: ModelParameters + Send + Sync {
    /// The model's name ([`Model::NAME`]).
    fn name(&self) -> &'static str;
    /// A boxed copy.
    fn clone_box(&self) -> Box<dyn ErasedModel>;
    /// The tyre as `Any`, to compare or downcast it.
    fn as_any(&self) -> &dyn Any;
    /// Equal when `other` is the same model with equal parameters.
    fn equals(&self, other: &dyn ErasedModel) -> bool;
    /// `Debug` of the model's parameters.
    fn debug(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result;
    /// The model's fields as a table (what its tyre file holds besides
    /// `model`).
    fn to_table(&self) -> Result<toml::Value, toml::ser::Error>;
}

impl<M: Model> ErasedModel for M {
    fn name(&self) -> &'static str {
        M::NAME
    }
    fn clone_box(&self) -> Box<dyn ErasedModel> {
        Box::new(self.clone())
    }
    fn as_any(&self) -> &dyn Any {
        self
    }
    fn equals(&self, other: &dyn ErasedModel) -> bool {
        other.as_any().downcast_ref::<M>() == Some(self)
    }
    fn debug(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self, f)
    }
    fn to_table(&self) -> Result<toml::Value, toml::ser::Error> {
        toml::Value::try_from(self)
    }
}

/// A tyre of a registered model.
pub struct Erased(Box<dyn ErasedModel>);

impl Erased {
    /// The tyre `m`.
    pub fn new<M: Model>(m: M) -> Self {
        Self(Box::new(m))
    }
    /// The model's name.
    pub fn name(&self) -> &'static str {
        self.0.name()
    }
    /// The model's own knowledge.
    pub(crate) fn as_model(&self) -> &dyn ModelParameters {
        &*self.0
    }
    /// The same, to change its parameters.
    pub(crate) fn as_model_mut(&mut self) -> &mut dyn ModelParameters {
        &mut *self.0
    }
    /// The tyre as model `M`, if it is one.
    pub fn downcast_ref<M: Model>(&self) -> Option<&M> {
        self.0.as_any().downcast_ref()
    }
}

impl Clone for Erased {
    fn clone(&self) -> Self {
        Self(self.0.clone_box())
    }
}

impl PartialEq for Erased {
    fn eq(&self, other: &Self) -> bool {
        self.0.equals(&*other.0)
    }
}

impl fmt::Debug for Erased {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.debug(f)
    }
}

impl Serialize for Erased {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let fields = self.0.to_table().map_err(serde::ser::Error::custom)?;
        Tagged {
            model: self.name(),
            fields: &fields,
        }
        .serialize(s)
    }
}

/// A model's fields with its `model` key in front: a tyre file's table.
#[derive(Serialize)]
pub(super) struct Tagged<'a, T: Serialize + ?Sized> {
    /// The model's name.
    pub model: &'static str,
    /// The model's own fields.
    #[serde(flatten)]
    pub fields: &'a T,
}

/// A value of a tyre's table kept until the `model` key is read: TOML's
/// values (so NaN and ±∞ survive), with a JSON `null` (an unset optional
/// field in Python's JSON) read as an absent key.
pub(super) struct Buffered(pub Option<toml::Value>);

impl<'de> Deserialize<'de> for Buffered {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(BufferVisitor)
    }
}

struct BufferVisitor;

impl<'de> Visitor<'de> for BufferVisitor {
    type Value = Buffered;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a value of a tyre table")
    }
    fn visit_bool<E>(self, v: bool) -> Result<Buffered, E> {
        Ok(Buffered(Some(toml::Value::Boolean(v))))
    }
    fn visit_i64<E>(self, v: i64) -> Result<Buffered, E> {
        Ok(Buffered(Some(toml::Value::Integer(v))))
    }
    fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<Buffered, E> {
        i64::try_from(v)
            .map(|i| Buffered(Some(toml::Value::Integer(i))))
            .map_err(|_| E::custom(format!("{v} is out of the range of an integer")))
    }
    fn visit_f64<E>(self, v: f64) -> Result<Buffered, E> {
        Ok(Buffered(Some(toml::Value::Float(v))))
    }
    fn visit_str<E>(self, v: &str) -> Result<Buffered, E> {
        Ok(Buffered(Some(toml::Value::String(v.to_string()))))
    }
    fn visit_none<E>(self) -> Result<Buffered, E> {
        Ok(Buffered(None))
    }
    fn visit_unit<E>(self) -> Result<Buffered, E> {
        Ok(Buffered(None))
    }
    fn visit_some<D: Deserializer<'de>>(self, d: D) -> Result<Buffered, D::Error> {
        Buffered::deserialize(d)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Buffered, A::Error> {
        let mut out = Vec::new();
        while let Some(Buffered(v)) = seq.next_element()? {
            out.push(v.ok_or_else(|| serde::de::Error::custom("null in an array"))?);
        }
        Ok(Buffered(Some(toml::Value::Array(out))))
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Buffered, A::Error> {
        let mut out = toml::Table::new();
        while let Some((k, Buffered(v))) = map.next_entry::<String, Buffered>()? {
            if let Some(v) = v {
                out.insert(k, v);
            }
        }
        Ok(Buffered(Some(toml::Value::Table(out))))
    }
}
