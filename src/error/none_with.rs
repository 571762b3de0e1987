//! `synth --effects none,…`: `none` (a truth with no effect on) given
//! together with effects to switch on, which contradict each other; the
//! run went on with the effects, and `none` said nothing.

use std::fmt;

/// `none` named with the effects `with`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NoneWithEffects {
    /// The effects named beside `none`, as named.
    pub with: Vec<&'static str>,
}

impl fmt::Display for NoneWithEffects {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "--effects names `none` (a truth with no effect on) together with {}: give `none` alone, or the effects alone (`--effects {}`)",
            self.with
                .iter()
                .map(|e| format!("`{e}`"))
                .collect::<Vec<_>>()
                .join(", "),
            self.with.join(",")
        )
    }
}
