//! What a design is asked: the sets of candidates to separate (else the
//! diagnosis's confounded sets), the limits' stated shares and how many
//! of the best manoeuvres to complete, checked before any work is done.

use super::family;
use crate::diagnose::effects::{joined, same_effects, EffectKind};
use crate::error::{Limit, ParamError, ParamReason};

/// What to design for.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignRequest {
    /// Sets of candidates to separate, each the reference first (None:
    /// the diagnosis's confounded sets).
    pub sets: Option<Vec<Vec<Vec<EffectKind>>>>,
    /// The share of the reached lateral acceleration a design may ask.
    pub ay_share: f64,
    /// The largest |du/dt| a design may ask, m/s².
    pub ax: f64,
    /// How many of the best manoeuvres get their uncertainty and are kept.
    pub top: usize,
    /// Manoeuvres to complete beyond the best `top` (the names of runs
    /// driven afterwards, whose predictions they are compared with).
    pub also: Vec<String>,
}

impl Default for DesignRequest {
    fn default() -> Self {
        Self {
            sets: None,
            ay_share: family::DEFAULT_AY_SHARE,
            ax: family::DEFAULT_AX,
            top: 3,
            also: Vec::new(),
        }
    }
}

impl DesignRequest {
    /// Ok when a design can honour the request: `ax` in (0, 15] m/s²,
    /// `ay_share` in (0, 1], `top` ≥ 1, no candidate named twice in a set.
    /// The keys are the command line's options.
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::in_range("--max-ax", self.ax, 0.0, family::MAX_AX, Limit::MaxAx)?;
        ParamError::in_range("--ay-share", self.ay_share, 0.0, 1.0, Limit::AyShare)?;
        if self.top == 0 {
            return Err(ParamError::new("--top", 0.0, ParamReason::NotPositive));
        }
        for set in self.sets.iter().flatten() {
            for (i, a) in set.iter().enumerate() {
                let same = |b: &Vec<EffectKind>| same_effects(b, a);
                if set[..i].iter().any(same) {
                    return Err(ParamError::without_value(
                        "--effects",
                        ParamReason::GivenTwice {
                            candidate: joined(a, "+"),
                        },
                    ));
                }
            }
        }
        Ok(())
    }
}
