//! What the runs determine of a value per radian of body roll (roll steer,
//! roll camber: [`crate::diagnose::effects::Parameter::per_roll`]): its
//! product with the roll gradient the diagnosis holds, the campaign's
//! `[roll] gradient` ([`PerLateralAcceleration`]). The model's roll is
//! `φ̈ = ω²·(k·ay − φ) − 2ζω·φ̇`, linear in the gradient k, so a coefficient
//! c at k replays as c/2 at 2k: the runs fix c·k, the steer (rad) or the
//! camber thrust (N/N) per m/s² of lateral acceleration, and c only at the
//! stated k, scaling as 1/k. No run's logged roll measures k: a logged
//! `roll` levels `ay` and is not scored (`crate::io::campaign`), so the
//! product is what a report may claim, and the gradient stays an
//! assumption. The words give the product in °/g too, as the roll-steer
//! term of the understeer gradient is quoted (Gillespie 1992, ch. 6).
//! Units: rad, m/s²; °/g with g = 9.80665 m/s².

use crate::diagnose::effects::PerRoll;
use serde::Serialize;
use std::path::PathBuf;

/// The roll gradient the roll effects are fitted at: the campaign's, held.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HeldRollGradient {
    /// The gradient, rad of roll per m/s² of lateral acceleration.
    pub gradient: f64,
    /// The campaign file that states it (`null`: not stated, the default
    /// passenger car's 4°/g, [`crate::vehicle::PASSENGER_CAR_ROLL_GRADIENT`]).
    pub file: Option<PathBuf>,
    /// The line of `[roll] gradient` in that file (`null`: not stated).
    pub line: Option<usize>,
    /// Runs that log a body roll: it levels their `ay` and measures no
    /// gradient, so the gradient is an assumption with or without them.
    pub runs_logging_roll: usize,
}

impl HeldRollGradient {
    /// The gradient in °/g, as engineers quote it.
    pub fn degrees_per_g(&self) -> f64 {
        self.gradient.to_degrees() * crate::constants::G
    }
}

/// A per-radian-of-roll value's product with the held roll gradient: what
/// the runs determine (`ParameterValue::per_lateral_acceleration`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PerLateralAcceleration {
    /// What it moves: an axle's steer or its camber thrust.
    pub quantity: PerRoll,
    /// The product, value × gradient, in [`Self::unit`].
    pub value: f64,
    /// Its standard error: the gradient × the value's (the gradient held;
    /// `null` where the value has none).
    #[serde(serialize_with = "crate::report::finite_or_null")]
    pub std_error: f64,
    /// `rad/(m/s²)` (steer) or `N/N per m/s²` (camber thrust).
    pub unit: &'static str,
    /// The gradient it was fitted at, and where it is stated.
    pub roll_gradient: HeldRollGradient,
}

impl PerLateralAcceleration {
    /// The product in °/g (steer) or N/N per g (camber thrust): rad per
    /// m/s² times 180/π·g, N/N per m/s² times g.
    pub fn per_g(&self, v: f64) -> f64 {
        let g = crate::constants::G;
        match self.quantity {
            PerRoll::Steer => v.to_degrees() * g,
            PerRoll::CamberThrust => v * g,
        }
    }
}
