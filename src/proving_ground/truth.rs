//! The model that plays the car on the virtual proving ground ([`Truth`]):
//! the diagnosis's own augmented 2-DOF model on the bundled UniTire tyre
//! (225/55R17 class, [`truth_tyre`]), or the independent four-wheel model
//! of `proving_ground` with roll and a Magic-Formula tyre of its own. Each
//! effect's truth value ([`truth_values`], [`Truth::values`]: for the
//! augmented truth the effect's own
//! ([`crate::diagnose::effects::Effect::TRUTH`]), in the diagnosis's
//! parameters, SI units and rad, scale factors 1 at nominal; the
//! four-wheel truth has its own subset of the effects in its own units, one
//! table, `FOUR_WHEEL`), and the roll the four-wheel truth's campaign file
//! states, which differs from the truth's: the diagnosis is not handed the
//! truth.

use super::programme::Programme;
use crate::diagnose::effects::{EffectKind, Needs, RollModel};
use crate::error::{ParamError, ParamReason};
use crate::proving_ground::four_wheel::FourWheelEffects;
use crate::tyre::Tyre;
use serde::Serialize;

/// The model that plays the car.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Truth {
    /// The diagnosis's own augmented 2-DOF model on the UniTire tyre.
    #[default]
    Augmented,
    /// The independent four-wheel model with roll and its own tyre.
    FourWheel,
}

impl Truth {
    /// Every truth.
    pub(crate) const ALL: [Truth; 2] = [Truth::Augmented, Truth::FourWheel];

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Truth::Augmented => "augmented",
            Truth::FourWheel => "four-wheel",
        }
    }

    /// The truth of a name, if it is one.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|t| t.name() == name)
    }

    /// Whether this truth can drive `programme`: the four-wheel truth holds
    /// its speed on a flat road, so it drives the handling programme only.
    pub(crate) fn drives(self, programme: Programme) -> Result<(), ParamError> {
        if self == Truth::FourWheel && programme.logged() {
            return Err(ParamError::without_value(
                "programme",
                ParamReason::TruthProgramme {
                    programme: programme.name().into(),
                },
            ));
        }
        Ok(())
    }

    /// The effects this truth can switch on in `programme`.
    pub fn effects(self, programme: Programme) -> Vec<EffectKind> {
        EffectKind::ALL
            .into_iter()
            .filter(|k| self.values(programme, *k).is_some())
            .collect()
    }

    /// The truth value of `kind` in this truth's own parameters (None: the
    /// truth has no such effect). For the four-wheel truth: relaxation
    /// length m; steering compliance rad/kN of front axle force; roll steer
    /// (front, rear) rad/rad; roll camber (front, rear) wheel lean per body
    /// roll, rad/rad; aero (front, rear) N/(m/s)²; friction and stiffness
    /// scales; yaw-inertia scale; delay s; offsets as the diagnosis's; a
    /// rolling accelerometer 1. The four-wheel truth holds its speed and
    /// drives the handling programme only.
    pub fn values(self, programme: Programme, kind: EffectKind) -> Option<Vec<f64>> {
        match self {
            // The handling programme (steps and sweeps at constant speed on
            // a flat road, no ax or bank channel) cannot show the
            // longitudinal and bank-profile effects; the logged ones can
            // (the bank profile where they log the bank).
            Truth::Augmented => match kind.needs() {
                // The proving ground's UniTire truth and PAC89 base saturate.
                Needs::Nothing | Needs::FrictionLimit => true,
                Needs::LongitudinalAcceleration => programme.logged(),
                Needs::BankChannel => programme.logs_bank(),
            }
            .then(|| truth_values(kind)),
            Truth::FourWheel if programme.logged() => None,
            Truth::FourWheel => four_wheel(kind).map(|(values, _)| values.to_vec()),
        }
    }
}

/// How an effect sets the four-wheel truth's own effects from its values.
type SetFourWheel = fn(&mut FourWheelEffects, &[f64]);

/// The four-wheel truth's effects: its own subset of the library, each
/// with its truth value in the truth's own units ([`Truth::values`]) and
/// how it sets the truth's effects. An effect not listed is not one of
/// this truth's.
const FOUR_WHEEL: &[(EffectKind, &[f64], SetFourWheel)] = &[
    (EffectKind::RelaxationLength, &[0.7], |e, p| {
        e.relaxation_length = p[0]
    }),
    (EffectKind::SteeringCompliance, &[0.003], |e, p| {
        e.steering_compliance = p[0] * 1e-3
    }),
    (EffectKind::RollSteer, &[-0.12, 0.05], |e, p| {
        e.roll_steer = [p[0], p[1]]
    }),
    (EffectKind::RollCamber, &[0.8, 0.6], |e, p| {
        e.roll_camber = [p[0], p[1]]
    }),
    (EffectKind::AeroLoad, &[1.5, 2.0], |e, p| {
        e.aero_load = [p[0], p[1]]
    }),
    (EffectKind::RoadFriction, &[0.75], |e, p| {
        e.friction_scale = p[0]
    }),
    (EffectKind::CorneringStiffness, &[0.8, 1.0], |e, p| {
        e.stiffness_scale = [p[0], p[1]]
    }),
    (EffectKind::YawInertia, &[1.3], |e, p| {
        e.yaw_inertia_scale = p[0]
    }),
    (EffectKind::SensorDelay, &[0.05], |e, p| {
        e.sensor_delay = p[0]
    }),
    (EffectKind::SensorBias, &[0.008, 0.2, 0.004], |e, p| {
        e.sensor_bias = [p[0], p[1], p[2]]
    }),
    (EffectKind::AccelerometerRoll, &[1.0], |e, p| {
        e.accelerometer_rolls = p[0] != 0.0
    }),
];

/// `kind`'s truth values and setter in the four-wheel truth, if it has it.
fn four_wheel(kind: EffectKind) -> Option<(&'static [f64], SetFourWheel)> {
    FOUR_WHEEL
        .iter()
        .find(|(k, _, _)| *k == kind)
        .map(|&(_, values, set)| (values, set))
}

/// The four-wheel truth's effects from (kind, parameters) pairs.
pub(super) fn four_wheel_effects(
    effects: &[(EffectKind, Vec<f64>)],
) -> Result<FourWheelEffects, ParamError> {
    let mut e = FourWheelEffects::default();
    for (k, p) in effects {
        let (need, set) = four_wheel(*k)
            .ok_or_else(|| ParamError::without_value(k.name(), ParamReason::NotATruthEffect))?;
        if p.len() != need.len() {
            return Err(ParamError::new(
                k.name(),
                p.len() as f64,
                ParamReason::ParameterCount { needed: need.len() },
            ));
        }
        set(&mut e, p);
    }
    Ok(e)
}

/// The roll the four-wheel truth's campaign file states: a generic
/// passenger-car guess (3°/g, 1.2 Hz, ζ = 0.6), not the truth's 6°/g,
/// about 1.8 Hz, ζ = 0.35.
pub(super) fn four_wheel_campaign_roll() -> RollModel {
    RollModel {
        gradient: 3f64.to_radians() / crate::vehicle::G,
        frequency: 1.2,
        damping: 0.6,
    }
}

/// The truth value of each effect used by the checks: realistic, and large
/// enough to matter in a handling test (the effect's
/// [`crate::diagnose::effects::Effect::TRUTH`]).
pub fn truth_values(kind: EffectKind) -> Vec<f64> {
    kind.truth().to_vec()
}

/// The bundled UniTire of the truth.
pub(crate) fn truth_tyre() -> Tyre {
    toml::from_str(include_str!("../../tyres/unitire.toml")).expect("the bundled UniTire file")
}
