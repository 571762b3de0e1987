//! The numbers behind a verdict's look-alikes: the confounding window of
//! the look-alike rule (`verdict::rules::lookalike`) and where each
//! look-alike lies in it, alone ([`Lookalikes`]) and fitted in a set in
//! the place of its first effect ([`InSet`]). A look-alike can remove a
//! visibly smaller share of the gap than the verdict (50 % against 74 %)
//! and still lie in the window: the words say the window's numbers, not
//! "about as well". Held-out errors and gaps above noise are
//! dimensionless (J over channel scales), reductions in percent.

use crate::diagnose::effects::EffectKind;
use serde::Serialize;

/// The confounding window of a reference candidate: another that passes
/// and leaves a held-out gap above noise `G ≤ bound`, with
/// `bound = gap_factor·gap + noise_factor·noise_level`, is not told apart
/// from it. The factors are written with it so that a reader of
/// `diagnosis.json` can check the bound without the rule's source.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Window {
    /// The reference's held-out gap above noise `G = √(J² − J_n²)`.
    pub gap: f64,
    /// The noise level `J_n`.
    pub noise_level: f64,
    /// The multiple of the reference's gap the window reaches.
    pub gap_factor: f64,
    /// The noise allowance, in noise levels.
    pub noise_factor: f64,
    /// The bound on another's gap above noise.
    pub bound: f64,
}

impl Window {
    /// The window of a reference whose gap above noise is `gap` at noise
    /// level `noise_level`, by the factors `(gap_factor, noise_factor)`.
    pub fn of(gap: f64, noise_level: f64, (gap_factor, noise_factor): (f64, f64)) -> Self {
        Self {
            gap,
            noise_level,
            gap_factor,
            noise_factor,
            bound: gap_factor * gap + noise_factor * noise_level,
        }
    }
}

/// A single effect that passes alone and leaves a gap within the window
/// of the single the verdict's search started from.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Lookalike {
    /// The effect.
    pub effect: EffectKind,
    /// Its held-out reduction of the gap above noise, alone, %.
    pub reduction_percent: f64,
    /// Its held-out gap above noise, alone.
    pub gap: f64,
}

/// The verdict's look-alikes alone and the window they lie in.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Lookalikes {
    /// The single the window is of: the one the verdict's search started
    /// from.
    pub start: EffectKind,
    /// Its held-out reduction alone, %.
    pub start_reduction_percent: f64,
    /// Its window.
    pub window: Window,
    /// The look-alikes the verdict did not take in, best first.
    pub members: Vec<Lookalike>,
}

/// A look-alike of a set's first effect fitted in the set in its place.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InSet {
    /// The set with the look-alike in place of the first effect.
    pub effects: Vec<EffectKind>,
    /// Its held-out reduction of the gap above noise, %.
    pub reduction_percent: f64,
    /// Its held-out gap above noise.
    pub gap: f64,
    /// The window of the verdict's set it is judged against.
    pub window: Window,
    /// Its gap lies within the window (the look-alike rule): still
    /// confounded in the set; false: the set tells them apart.
    pub confounded: bool,
}
