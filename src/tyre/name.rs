//! A tyre model's name: the `model` key of its tyre files, its value of
//! `identify --model` when it has a swarm fit, its name in reports and in
//! Python. The names and their constants (`ModelName::Gim`, …) come from
//! the registry's one list (`registry.rs`), and a name is made only there,
//! so every `ModelName` is a model the registry holds.

use serde::Serialize;

/// The name of a registered tyre model (the `model` key of a tyre file).
/// Built-in models have constants (`ModelName::Pac89`); every model, a
/// registered one included, is listed by [`super::models`] and parsed with
/// `FromStr` (the error lists the known names).
#[derive(Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(transparent)]
pub struct ModelName(&'static str);

impl ModelName {
    /// The name of a model the registry holds (its `Model::NAME`).
    pub(super) const fn new(name: &'static str) -> Self {
        Self(name)
    }

    /// The name as a tyre file writes it.
    pub const fn as_str(self) -> &'static str {
        self.0
    }
}

impl std::fmt::Display for ModelName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.0)
    }
}

impl std::fmt::Debug for ModelName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.0)
    }
}
