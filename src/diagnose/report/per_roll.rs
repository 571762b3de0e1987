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
use crate::diagnose::report::ParameterValue;
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
/// the runs determine ([`ParameterValue::per_lateral_acceleration`]).
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

impl ParameterValue {
    /// The same with its product with the `held` roll gradient, where it is
    /// a value per radian of roll (any other is returned as it is). The
    /// product's standard error is the gradient times the value's, of
    /// whichever basis ([`ParameterValue::std_error_basis`]).
    pub fn at_roll_gradient(self, held: &HeldRollGradient) -> Self {
        let Some(quantity) = self.effect_parameter.and_then(|q| q.per_roll) else {
            return self;
        };
        let k = held.gradient;
        Self {
            per_lateral_acceleration: Some(PerLateralAcceleration {
                quantity,
                value: self.value * k,
                std_error: self.std_error * k.abs(),
                unit: quantity.unit(),
                roll_gradient: held.clone(),
            }),
            ..self
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::effects::{EffectKind, Group};

    fn held(gradient: f64) -> HeldRollGradient {
        HeldRollGradient {
            gradient,
            file: Some("camp/vehicle.toml".into()),
            line: Some(19),
            runs_logging_roll: 0,
        }
    }

    #[test]
    fn the_product_and_its_error_scale_with_the_gradient_and_only_roll_values_carry_one() {
        let steer = &EffectKind::RollSteer.parameters()[0];
        let v = ParameterValue::of(Group::Effect(EffectKind::RollSteer), steer, -0.251, 0.00305);
        let k = 3f64.to_radians() / crate::constants::G;
        let p = v.clone().at_roll_gradient(&held(k));
        let per = p.per_lateral_acceleration.as_ref().unwrap();
        assert_eq!(per.quantity, PerRoll::Steer);
        assert_eq!(per.unit, "rad/(m/s²)");
        assert!((per.value - -0.251 * k).abs() < 1e-15);
        assert!((per.std_error - 0.00305 * k).abs() < 1e-15);
        // 3°/g times -0.251 rad/rad is -0.753°/g of steer.
        assert!((per.per_g(per.value) - -0.753).abs() < 1e-12);
        assert!((per.roll_gradient.degrees_per_g() - 3.0).abs() < 1e-12);
        // At twice the gradient, half the coefficient: the same product.
        let twice = ParameterValue::of(
            Group::Effect(EffectKind::RollSteer),
            steer,
            -0.1255,
            0.001525,
        )
        .at_roll_gradient(&held(2.0 * k));
        let per2 = twice.per_lateral_acceleration.unwrap();
        assert!((per2.value - per.value).abs() < 1e-15);
        assert!((per2.std_error - per.std_error).abs() < 1e-15);
        // Camber thrust per g is N/N per m/s² times g.
        let camber = &EffectKind::RollCamber.parameters()[1];
        let c = ParameterValue::of(Group::Effect(EffectKind::RollCamber), camber, 2.0, 0.5)
            .at_roll_gradient(&held(k));
        let per = c.per_lateral_acceleration.unwrap();
        assert_eq!(
            (per.quantity, per.unit),
            (PerRoll::CamberThrust, "N/N per m/s²")
        );
        assert!((per.per_g(per.value) - 2.0 * k * crate::constants::G).abs() < 1e-15);
        // Neither a roll dynamics' value nor another effect's has one.
        let frequency = &crate::diagnose::effects::RollDynamics::PARAMETERS[0];
        let f = ParameterValue::of(Group::Roll, frequency, 1.8, 0.01).at_roll_gradient(&held(k));
        assert!(f.per_lateral_acceleration.is_none());
        let bank = &EffectKind::RoadBank.parameters()[0];
        let b = ParameterValue::of(Group::Effect(EffectKind::RoadBank), bank, 0.01, 0.001)
            .at_roll_gradient(&held(k));
        assert!(b.per_lateral_acceleration.is_none());
        // A value without a standard error has a product without one.
        let none = ParameterValue::of(Group::Effect(EffectKind::RollSteer), steer, 0.1, f64::NAN)
            .at_roll_gradient(&held(k));
        assert!(none.per_lateral_acceleration.unwrap().std_error.is_nan());
    }
}
