//! Which candidate effects exist: each is a model extension with one to
//! three physical parameters, off in the base model, defined once as an
//! [`Effect`] impl in [`library`] (its name — as a campaign's
//! `[diagnose] effects` and `diagnosis.json` spell it —, its parameters
//! with units, search bounds and the values that switch it off, its
//! signature, what a run needs for it to show, whether it uses roll, its
//! truth on the proving ground, and how it sets the vehicle model's
//! numbers, [`Effect::apply`]). The library's one list makes
//! [`EffectKind`], `EffectKind::ALL` and the dispatch of every item
//! (`generate.rs`); the values of every effect live in the vehicle model's
//! [`crate::vehicle::Effects`], whose physics the vehicle model holds. The
//! roll dynamics fitted with the roll effects ([`RollDynamics`]) are set
//! the same way.
//!
//! Signs follow ISO 8855 (x forward, y left, z up, positive steer left,
//! positive roll φ puts the right side down, as in a left turn). Units: SI,
//! rad; scales are dimensionless factors on the base model's value.

mod generate;
pub mod library;

pub use crate::vehicle::RollModel;
pub use library::EffectKind;

use crate::scalar::Scalar;
use crate::vehicle::Effects;
use serde::Serialize;

/// One candidate effect, defined once: every item is required (none has a
/// default), so a new effect fails to compile until each is given. Its
/// unit struct and its variant of [`EffectKind`] come from the list in
/// [`library`].
pub trait Effect {
    /// The name in a campaign's `[diagnose] effects` and in
    /// `diagnosis.json` (snake case; unique).
    const NAME: &'static str;
    /// Its parameters, in the order of a fit's vector (one to three). The
    /// bounds are wide physical ranges: the search must be able to find a
    /// value the truth did not use.
    const PARAMETERS: &'static [Parameter];
    /// What the effect does to the measurements that no other effect does:
    /// the experiment that separates it from a look-alike.
    const SIGNATURE: &'static str;
    /// What a run must carry for the effect to show.
    const NEEDS: Needs;
    /// Whether the effect acts through the roll degree of freedom (whose
    /// dynamics the diagnosis then fits with it, [`RollDynamics`]).
    const USES_ROLL: bool;
    /// Its parameters' values on the augmented proving ground
    /// (`crate::proving_ground::truth_values`): realistic, and large enough
    /// to matter in a handling test; one per parameter.
    const TRUTH: &'static [f64];
    /// Sets the effect's numbers for parameters `p` (as many as
    /// [`Effect::PARAMETERS`], in their units) on `effects`, a copy of the
    /// base model's: added where the base may have some already, a scale
    /// where it scales, else replaced. At the off values the model is the
    /// base model's. Written for any scalar: a fit's dual numbers carry
    /// their derivatives through it.
    fn apply<T: Scalar>(p: &[T], effects: &mut Effects<T>);
}

/// What a run must carry for an effect to show in it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Needs {
    /// Nothing beyond steer, speed and a response.
    Nothing,
    /// A longitudinal acceleration (an `ax` channel, or a speed that
    /// changes) somewhere.
    LongitudinalAcceleration,
    /// A `bank` channel.
    BankChannel,
    /// Base tyres with a friction limit: a friction scale moves a linear
    /// tyre's force nowhere.
    FrictionLimit,
}

/// A parameter of an effect.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parameter {
    /// Name in reports.
    pub name: &'static str,
    /// Unit.
    pub unit: &'static str,
    /// Value that switches the effect off.
    pub off: f64,
    /// Search bounds (lower, upper).
    pub bounds: (f64, f64),
    /// What each bound is (lower, upper).
    pub limits: (Bound, Bound),
    /// Whether it only adds a constant to a measured channel after the
    /// dynamics, their start included: the residuals are then affine in it
    /// with a slope no parameter changes, every second derivative with it
    /// is zero, and the fits' second differences skip it
    /// (`crate::diagnose::fit`). The lateral-acceleration offset is; the
    /// yaw-rate and sideslip offsets are not, as each replay starts from
    /// the first measured state less them.
    pub additive: bool,
    /// What it is per radian of body roll, where its effect on the runs
    /// is only its product with the campaign's roll gradient (None: it
    /// acts on its own). The model's roll is `φ̈ = ω²·(k·ay − φ) −
    /// 2ζω·φ̇`, linear in the gradient k, and a roll steer or camber acts
    /// as its value times φ: a coefficient c at gradient k replays as c/2
    /// at 2k (the roll state doubled, the steer or thrust the same). The runs
    /// determine c·k, not c (the report's
    /// [`crate::diagnose::report::PerLateralAcceleration`]).
    pub per_roll: Option<PerRoll>,
}

/// What a per-radian-of-roll parameter ([`Parameter::per_roll`]) moves:
/// its product with the roll gradient is that quantity per lateral
/// acceleration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PerRoll {
    /// An axle's steer (roll steer, rad of steer per rad of roll): the
    /// product is rad of steer per m/s² of lateral acceleration, as
    /// engineers quote it in °/g.
    Steer,
    /// An axle's camber thrust (roll camber, lateral force per wheel load
    /// per rad of roll): the product is N/N per m/s².
    CamberThrust,
}

impl PerRoll {
    /// The unit of the product with a roll gradient (rad per m/s²).
    pub fn unit(self) -> &'static str {
        match self {
            PerRoll::Steer => "rad/(m/s²)",
            PerRoll::CamberThrust => "N/N per m/s²",
        }
    }
}

/// What bounds a parameter on one side.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Bound {
    /// The end of a wide search range: a fit that stops there would go
    /// further.
    Search,
    /// A limit of the quantity itself (a length, a delay or a share below
    /// 0, a share above 1): no value lies beyond it.
    Physical,
}

const fn par(name: &'static str, unit: &'static str, off: f64, lo: f64, hi: f64) -> Parameter {
    Parameter {
        name,
        unit,
        off,
        bounds: (lo, hi),
        limits: (Bound::Search, Bound::Search),
        additive: false,
        per_roll: None,
    }
}

impl Parameter {
    /// The same with its lower bound a physical limit.
    const fn floor(self) -> Self {
        Self {
            limits: (Bound::Physical, self.limits.1),
            ..self
        }
    }

    /// The same with both bounds physical limits (a share).
    const fn share(self) -> Self {
        Self {
            limits: (Bound::Physical, Bound::Physical),
            ..self
        }
    }

    /// The same as a value per radian of body roll, which acts only
    /// through its product with the roll gradient ([`Parameter::per_roll`]).
    const fn per_roll(self, what: PerRoll) -> Self {
        Self {
            per_roll: Some(what),
            ..self
        }
    }

    /// The same as an offset added to a measured channel after the
    /// dynamics ([`Parameter::additive`]).
    const fn additive(self) -> Self {
        Self {
            additive: true,
            ..self
        }
    }

    /// The bound `value` lies on (within 1e-9 of the span: the bounded fits
    /// stop exactly on a bound they press against), if any.
    pub fn bound_at(&self, value: f64) -> Option<Bound> {
        on_bound(value, self.bounds).map(|upper| if upper { self.limits.1 } else { self.limits.0 })
    }
}

/// The roll degree of freedom's dynamics, fitted with the roll effects: a
/// campaign's `[roll]` is a guess (no roll channel is needed), and roll
/// steer or camber seen through the wrong roll frequency and damping is
/// mimicked by stiffness changes of the wrong sign. The roll gradient stays
/// the campaign's: it only scales the per-radian roll-steer and roll-camber
/// values ([`Parameter::per_roll`]: the runs determine their product with
/// it, which the report gives). Off values (NaN) are the campaign's.
pub struct RollDynamics;

impl RollDynamics {
    /// Frequency (Hz) and damping ratio, in the order of a fit's vector.
    pub const PARAMETERS: &'static [Parameter] = &[
        par("frequency", "Hz", f64::NAN, 0.5, 4.0),
        par("damping", "-", f64::NAN, 0.05, 1.5),
    ];

    /// Sets the roll model's frequency and damping to `p`.
    pub fn apply<T: Scalar>(p: &[T], effects: &mut Effects<T>) {
        effects.roll.frequency = p[0];
        effects.roll.damping = p[1];
    }
}

/// Whose a fitted parameter after the axle characteristics is: an
/// effect's, whose [`Parameter`] in the registry holds its off value and
/// search bounds, or the roll dynamics' ([`RollDynamics`]), whose off
/// values are the campaign's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Group {
    /// The effect's parameter.
    Effect(EffectKind),
    /// The roll dynamics' parameter.
    Roll,
}

impl Group {
    /// The group's name, before the parameter's in a report
    /// (`effect.parameter`, `roll.frequency`).
    pub fn name(self) -> &'static str {
        match self {
            Group::Effect(e) => e.name(),
            Group::Roll => "roll",
        }
    }
}

/// Whether `value` lies on the lower (`Some(false)`) or upper (`Some(true)`)
/// of `bounds`, within 1e-9 of their span (the bounded fits stop exactly
/// on a bound they press against), or on neither.
pub(crate) fn on_bound(value: f64, (lo, hi): (f64, f64)) -> Option<bool> {
    let tol = 1e-9 * (hi - lo);
    if value - lo <= tol {
        Some(false)
    } else if hi - value <= tol {
        Some(true)
    } else {
        None
    }
}

/// Whether `a` and `b` name the same effects, in any order (`a+b` is
/// `b+a`: a combination is a set, in whichever order it was built).
pub fn same_effects(a: &[EffectKind], b: &[EffectKind]) -> bool {
    a.len() == b.len() && b.iter().all(|e| a.contains(e))
}

/// The effects of `kinds` as a set: in one order whatever order they were
/// listed in (a key for [`same_effects`]'s comparison).
pub fn set_of(kinds: &[EffectKind]) -> Vec<EffectKind> {
    let mut set = kinds.to_vec();
    set.sort();
    set
}

/// The names of `kinds` joined by `sep` (a candidate's label: `a+b`).
pub fn joined(kinds: &[EffectKind], sep: &str) -> String {
    let names: Vec<&str> = kinds.iter().map(|e| e.name()).collect();
    names.join(sep)
}

impl EffectKind {
    /// The effect of a name, if it is one.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|e| e.name() == name)
    }

    /// The salt of this effect's random searches: the FNV-1a hash of its
    /// name, so that an effect's fits are the same whatever its place in
    /// the library or in a campaign's list (adding an effect changes no
    /// other effect's result).
    pub fn seed(self) -> u64 {
        self.name().bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_effects_seed_is_its_names_fnv1a_hash_and_no_two_share_one() {
        // FNV-1a of "a" and of "foobar" (the published test vectors of
        // Fowler, Noll and Vo), computed the way `seed` hashes a name.
        let fnv = |s: &str| {
            s.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
                (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
            })
        };
        assert_eq!(fnv("a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv("foobar"), 0x8594_4171_f739_67e8);
        for k in EffectKind::ALL {
            assert_eq!(k.seed(), fnv(k.name()), "{}", k.name());
        }
        let mut seeds: Vec<u64> = EffectKind::ALL.iter().map(|k| k.seed()).collect();
        seeds.sort_unstable();
        seeds.dedup();
        assert_eq!(seeds.len(), EffectKind::ALL.len());
    }

    #[test]
    fn the_per_roll_parameters_are_the_roll_effects_and_act_through_their_product_with_the_gradient(
    ) {
        // Every parameter of an effect that acts through roll is per radian
        // of roll, and no other is (the roll dynamics' are the mode's).
        for k in EffectKind::ALL {
            for q in k.parameters() {
                assert_eq!(
                    q.per_roll.is_some(),
                    k.uses_roll(),
                    "{}.{}",
                    k.name(),
                    q.name
                );
            }
        }
        assert!(RollDynamics::PARAMETERS
            .iter()
            .all(|q| q.per_roll.is_none()));
        let steer = EffectKind::RollSteer.parameters();
        assert!(steer.iter().all(|q| q.per_roll == Some(PerRoll::Steer)));
        let camber = EffectKind::RollCamber.parameters();
        assert!(camber
            .iter()
            .all(|q| q.per_roll == Some(PerRoll::CamberThrust)));
        // A roll steer and camber c at the roll gradient k replay as c/2 at
        // 2k: the runs see c·k alone (a sine through the roll mode, whose
        // lag the product keeps).
        use crate::diagnose::model::{Augmented, Drive};
        use crate::manoeuvre::{Manoeuvre, SineSteer};
        let sine = Manoeuvre::Sine(SineSteer {
            speed: 22.0,
            amplitude: 0.04,
            frequency: 0.7,
            start: 0.2,
            end: 4.0,
        });
        let drive = Drive::new(&sine, 2e-3);
        let run = |c: f64, k: f64| {
            let mut a = Augmented::new(crate::vehicle::linear_bicycle(), 1.0);
            a.effects_mut().roll.gradient = k;
            EffectKind::RollSteer.apply(&[-0.2 * c, 0.1 * c], a.effects_mut());
            EffectKind::RollCamber.apply(&[-2.0 * c, 1.0 * c], a.effects_mut());
            a.simulate(&drive, [0.0; 6])
        };
        let (one, half) = (run(1.0, 0.005), run(0.5, 0.01));
        let plain = run(0.0, 0.005);
        let mut moved: f64 = 0.0;
        for i in 0..one.yaw_rate.len() {
            let r = one.yaw_rate[i];
            assert!(
                (half.yaw_rate[i] - r).abs() <= 1e-12 * (1.0 + r.abs()),
                "{i}"
            );
            moved = moved.max((r - plain.yaw_rate[i]).abs());
        }
        // And the coefficients move the yaw rate (the comparison is no
        // comparison of two base models).
        assert!(moved > 1e-3, "{moved}");
    }

    #[test]
    fn a_bound_is_named_for_what_it_is() {
        let relaxation = EffectKind::RelaxationLength.parameters()[0];
        assert_eq!(relaxation.bound_at(0.0), Some(Bound::Physical));
        assert_eq!(relaxation.bound_at(3.0), Some(Bound::Search));
        assert_eq!(relaxation.bound_at(0.5), None);
        // Within 1e-9 of the span, not beyond.
        assert_eq!(relaxation.bound_at(3.0 * 0.9e-9), Some(Bound::Physical));
        assert_eq!(relaxation.bound_at(3.0 * 1.1e-9), None);
        let bank = EffectKind::RoadBank.parameters()[0];
        assert_eq!(bank.bound_at(-0.15), Some(Bound::Search));
        // Combined slip's drive split and brake balance (not its share of
        // m·ax, which may exceed 1).
        for share in EffectKind::CombinedSlip.parameters()[..2]
            .iter()
            .chain(EffectKind::LoadTransferDistribution.parameters())
        {
            assert_eq!(share.bound_at(0.0), Some(Bound::Physical));
            assert_eq!(share.bound_at(1.0), Some(Bound::Physical));
        }
        // A physical limit is where the quantity ends: below zero for a
        // length, a delay or a share, above one for a share of a whole.
        for k in EffectKind::ALL {
            for q in k.parameters() {
                let (lo, hi) = q.bounds;
                if q.limits.0 == Bound::Physical {
                    assert_eq!(lo, 0.0, "{}.{}", k.name(), q.name);
                }
                if q.limits.1 == Bound::Physical {
                    assert_eq!((lo, hi), (0.0, 1.0), "{}.{}", k.name(), q.name);
                }
            }
        }
    }

    #[test]
    fn names_round_trip_and_off_values_are_the_base_model() {
        for k in EffectKind::ALL {
            assert_eq!(EffectKind::from_name(k.name()), Some(k));
            let json = serde_json::to_string(&k).unwrap();
            assert_eq!(json, format!("\"{}\"", k.name()));
            assert_eq!(serde_json::from_str::<EffectKind>(&json).unwrap(), k);
            let p = k.parameters();
            assert!((1..=3).contains(&p.len()), "{}", k.name());
            for (q, truth) in p.iter().zip(k.truth()) {
                assert!(q.bounds.0 < q.bounds.1);
                assert!(q.off.is_nan() || (q.bounds.0..=q.bounds.1).contains(&q.off));
                assert!((q.bounds.0..=q.bounds.1).contains(truth), "{}", k.name());
            }
            // Setting the off values on the base model's effects leaves
            // them as they were (the share's off value is the vehicle's own,
            // and combined slip's is pure slip in another form: both tested
            // in the model, as every effect's replay at its off values).
            if k != EffectKind::LoadTransferDistribution && k != EffectKind::CombinedSlip {
                let mut e = Effects::default();
                let off: Vec<f64> = p.iter().map(|q| q.off).collect();
                k.apply(&off, &mut e);
                assert_eq!(e, Effects::default(), "{}", k.name());
            }
        }
        assert_eq!(EffectKind::from_name("relaxation"), None);
        let unknown = serde_json::from_str::<EffectKind>("\"relaxation\"").unwrap_err();
        assert!(
            unknown
                .to_string()
                .contains("unknown variant `relaxation`, expected one of `relaxation_length`"),
            "{unknown}"
        );
    }
}
