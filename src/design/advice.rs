//! What a design recommends, and whether its family holds what the
//! diagnosis advises.
//!
//! A manoeuvre is recommended ([`Worth::Separates`]) only when a driven run
//! is expected to separate the pair beyond its own uncertainty (`expected`
//! above its 1 σ) and by at least as much as the campaign's runs already
//! do: a run whose separation lies within its uncertainty may measure
//! nothing or favour the wrong candidate, and one that separates less than
//! the campaign adds less than the runs that left the pair confounded.
//! When none of the best is recommended, the set says so
//! ([`Recommendation`]) instead of offering them as separating tests.
//! One recommended by that rule whose expected separation is within
//! [`FIRM_SIGMAS`] of its own uncertainty is said to be weak ([`Weak`]):
//! Putnam's sweep expected to measure 277.9 ± 268.9 (1.03 σ) was
//! "recommended", where one run of it lands at or below 0, no separation or
//! the wrong candidate favoured, with a chance of 15 % on a normal spread.
//!
//! The diagnosis's confounded words name, per effect, the test that
//! separates it (its signature, e.g. "steps at two speeds"); [`advised`]
//! reads that test as the family's kinds, or says why the family has none
//! (a straight run both ways, a banked corner), so the design states where
//! the advised manoeuvres rank.
//!
//! Units: separations in noise floors.

use super::family::Kind;
use super::Scored;
use crate::diagnose::effects::EffectKind;
use serde::Serialize;

// The weak rule lives beside the worth, where the diagnosis's advice reads
// it too (it cannot import the design).
pub use crate::diagnose::report::worth::{worth, Weak, Worth, FIRM_SIGMAS};

impl Scored {
    /// Whether it is recommended ([`Worth::Separates`]) but weakly: its
    /// expected separation within [`FIRM_SIGMAS`] of its uncertainty.
    pub fn weak(&self) -> Option<Weak> {
        let (e, u) = self.expected.zip(self.uncertainty)?;
        crate::diagnose::report::worth::weak(self.worth?, e, u)
    }
}

/// What the diagnosis reads of a set's candidates with the campaign's
/// runs: the words of the set's separation D say why D of the campaign's
/// runs did not tell them apart.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DiagnosisReads {
    /// It calls them confounded (the set is one of its confounded sets).
    Confounded,
    /// It finds no significant gap: the runs need neither.
    NoGap,
    /// A set asked for beside a gap: the confounding rule is read per
    /// manoeuvre ([`Worth::AlreadyToldApart`]).
    Other,
}

/// What the design recommends for a set.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Recommendation {
    /// Drive the manoeuvres marked [`Worth::Separates`] (`count` of the
    /// best).
    Drive {
        /// How many.
        count: usize,
    },
    /// The diagnosis already tells the pair apart: none needs driving.
    AlreadyToldApart,
    /// None of the best is worth driving as a separating test.
    NoneWorthDriving {
        /// The largest expected separation among them (NaN: none
        /// completed).
        best_expected: f64,
        /// Its uncertainty.
        best_uncertainty: f64,
        /// Whether the campaign's runs already separate the pair by more
        /// than any of them is expected to.
        campaign_separates_more: bool,
    },
}

/// The recommendation for a set whose completed best are `ranked`, its
/// campaign separating the pair by `campaign`.
pub fn recommendation(ranked: &[Scored], campaign: f64) -> Recommendation {
    let count = ranked
        .iter()
        .filter(|s| s.worth == Some(Worth::Separates))
        .count();
    if count > 0 {
        return Recommendation::Drive { count };
    }
    if ranked
        .iter()
        .any(|s| s.worth == Some(Worth::AlreadyToldApart))
    {
        return Recommendation::AlreadyToldApart;
    }
    let best = ranked
        .iter()
        .filter_map(|s| s.expected.zip(s.uncertainty))
        .max_by(|a, b| a.0.total_cmp(&b.0));
    let (best_expected, best_uncertainty) = best.unwrap_or((f64::NAN, f64::NAN));
    Recommendation::NoneWorthDriving {
        best_expected,
        best_uncertainty,
        campaign_separates_more: campaign > best_expected,
    }
}

/// Why the family has no manoeuvre of an advised test.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Missing {
    /// A straight run in both directions of travel: the family's
    /// manoeuvres are driven one way, and an offset shows only against
    /// the same run the other way.
    StraightBothWays,
    /// The same banked corner at two speeds: the family is driven on a
    /// flat road (a designed run's bank is not known before it is driven).
    BankedCorner,
}

/// The kinds of manoeuvre of the family that make the test the
/// diagnosis advises to separate `effect` by (its signature), or why the
/// family has none.
pub fn advised(effect: EffectKind) -> Result<&'static [Kind], Missing> {
    use EffectKind as E;
    use Kind::*;
    const STEADY_TURNS: &[Kind] = &[BrakeInTurn, AccelerateInTurn, ConstantRadius];
    // Every effect named: a new one fails to compile until its test is
    // said here (a name string's typo fell to "no test" silently).
    Ok(match effect {
        // Runs at two speeds; steps at two speeds (one level, or two
        // levels at one speed).
        E::RelaxationLength => &[Step, Sweep, LaneChange],
        E::LoadTransferDistribution | E::AeroLoad | E::CorneringStiffness => &[Step],
        // Steady turns compared with u·r.
        E::AccelerometerRoll => STEADY_TURNS,
        // The limit, where the force it follows saturates, and a step,
        // where the roll it does not follow lags.
        E::SteeringCompliance => &[Ramp, Step],
        E::RollSteer | E::RollCamber | E::RoadFriction => &[Ramp],
        E::YawInertia => &[Sweep],
        E::SensorDelay => &[Sweep, Step],
        E::AccelerometerPosition => &[Sweep, BrakeInTurn, AccelerateInTurn, ConstantRadius],
        E::LongitudinalLoadTransfer => &[BrakeInTurn, AccelerateInTurn],
        E::CombinedSlip => &[BrakeInTurn],
        E::SteerPath => &[Step, SpeedChange],
        // Steps at two speeds (one factor at both) and two levels.
        E::SteeringRatio => &[Step],
        // Braking and throttle on a straight read as a lateral acceleration.
        E::MountYaw => &[SpeedChange],
        E::RoadBank | E::SensorBias => return Err(Missing::StraightBothWays),
        E::BankProfile => return Err(Missing::BankedCorner),
    })
}

/// The family's best manoeuvre of an advised test.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AdvisedBest {
    /// Its name.
    pub name: String,
    /// Its place in the whole ranking, 1 the best.
    pub rank: usize,
    /// Its D.
    pub separation: f64,
}

/// What the diagnosis advises to separate one member's effect, and where
/// the family's manoeuvres of that test rank.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Advised {
    /// The effect.
    pub effect: String,
    /// The family's kinds that make the test (empty when missing).
    pub kinds: Vec<Kind>,
    /// Why the family has none of it.
    pub missing: Option<Missing>,
    /// The best of those kinds within the limits (None: every one left
    /// out, or missing).
    pub best: Option<AdvisedBest>,
}

/// What the diagnosis advises for each effect of `effects` (each once),
/// against the family's whole ranking `ranked` (best first).
pub fn advice_of(effects: &[EffectKind], ranked: &[&Scored]) -> Vec<Advised> {
    let mut seen: Vec<EffectKind> = Vec::new();
    let mut out = Vec::new();
    for &e in effects {
        if seen.contains(&e) {
            continue;
        }
        seen.push(e);
        let (kinds, missing) = match advised(e) {
            Ok(k) => (k.to_vec(), None),
            Err(m) => (Vec::new(), Some(m)),
        };
        let best = ranked
            .iter()
            .enumerate()
            .find(|(_, s)| kinds.contains(&s.kind))
            .map(|(k, s)| AdvisedBest {
                name: s.name.clone(),
                rank: k + 1,
                separation: s.separation,
            });
        out.push(Advised {
            effect: e.name().to_string(),
            kinds,
            missing,
            best,
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A set none of whose best is worth driving says so, and whether the
    /// campaign already separates the pair by more than the best would.
    #[test]
    fn a_set_with_nothing_worth_driving_says_whether_the_campaign_separates_more() {
        let scored = |expected: f64, uncertainty: f64, campaign: f64| Scored {
            name: "m".into(),
            kind: Kind::Sweep,
            description: String::new(),
            duration: 12.0,
            separation: expected,
            pairs: Vec::new(),
            uncertainty: Some(uncertainty),
            parameter_uncertainty: None,
            noise_uncertainty: None,
            expected: Some(expected),
            repetitions: None,
            worth: Some(worth(expected, uncertainty, campaign)),
            peak_ay: 1.0,
            manoeuvre: crate::manoeuvre::Manoeuvre::Replay(crate::manoeuvre::Replay::of_inputs(
                vec![0.0, 1.0],
                vec![0.0; 2],
                vec![20.0; 2],
            )),
        };
        let none = recommendation(&[scored(3.1, 9.5, 7.5), scored(2.0, 8.0, 7.5)], 7.5);
        assert_eq!(
            none,
            Recommendation::NoneWorthDriving {
                best_expected: 3.1,
                best_uncertainty: 9.5,
                campaign_separates_more: true
            }
        );
        let wide = recommendation(&[scored(11.8, 15.7, 6.1)], 6.1);
        assert!(
            matches!(
                wide,
                Recommendation::NoneWorthDriving {
                    campaign_separates_more: false,
                    ..
                }
            ),
            "{wide:?}"
        );
        let drive = recommendation(&[scored(27.0, 1.9, 8.2), scored(5.0, 1.0, 8.2)], 8.2);
        assert_eq!(drive, Recommendation::Drive { count: 1 });
        // Putnam's sweep, 277.9 ± 268.9 against a campaign of 247.9: the
        // rule recommends it, but at 1.03 σ one run lands at or below 0
        // with Φ(−1.03) = 15 %; 27 ± 1.9 is firm; 4.0 ± 2.0 is at the
        // bound (2 σ, Φ(−2) = 2.3 %), firm; one not recommended is no
        // weak recommendation.
        let putnam = scored(277.9, 268.9, 247.9).weak().unwrap();
        assert!((putnam.sigmas - 277.9 / 268.9).abs() < 1e-12);
        assert!((putnam.wrong - 0.1507).abs() < 5e-4, "{}", putnam.wrong);
        assert_eq!(scored(27.0, 1.9, 8.2).weak(), None);
        assert_eq!(scored(4.0, 2.0, 1.0).weak(), None);
        assert!(scored(3.9, 2.0, 1.0).weak().is_some());
        assert_eq!(scored(3.1, 9.5, 0.5).weak(), None);
    }

    /// Every effect of the library has its advised test in the family, or
    /// a stated reason why not; the test words of its signature name it.
    #[test]
    fn every_effects_advised_test_is_in_the_family_or_said_missing() {
        for e in EffectKind::ALL {
            match advised(e) {
                Ok(kinds) => assert!(!kinds.is_empty(), "{}", e.name()),
                Err(Missing::StraightBothWays) => {
                    assert!(e.signature().contains("both"), "{}", e.name())
                }
                Err(Missing::BankedCorner) => {
                    assert!(e.signature().contains("corner"), "{}", e.name())
                }
            }
            let words = e.signature().rsplit(':').next().unwrap_or("");
            for (word, kind) in [
                ("sweep", Kind::Sweep),
                ("ramp", Kind::Ramp),
                ("steady turns", Kind::BrakeInTurn),
                ("braking in a turn", Kind::BrakeInTurn),
                ("steps", Kind::Step),
                ("a steer step", Kind::Step),
            ] {
                if words.contains(word) {
                    assert!(
                        advised(e).is_ok_and(|k| k.contains(&kind)),
                        "{}: {words}",
                        e.name()
                    );
                }
            }
        }
    }
}
