//! The candidates a campaign's `[diagnose] effects` narrowed the
//! library to, as the verdicts that would otherwise blame "a model-form
//! error outside the library" carry them: a gap none of the named effects
//! explains says nothing of the effects left out, the true one perhaps
//! among them (a fresh-eyes tester's `effects = ["road_bank"]` on a
//! relaxation-length truth read as "outside the library" while 19 of the
//! library's 20 effects were never tried).

use crate::diagnose::effects::EffectKind;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::CalibrationSource;
use serde::Serialize;

/// The candidates a campaign's `[diagnose] effects` narrowed the library
/// to: a gap none of them explains says nothing of the effects left out,
/// so it is no model-form error outside the library.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Narrowed {
    /// The effects the campaign names, the only ones tried.
    pub tried: Vec<EffectKind>,
    /// The library's effects it leaves out, untried.
    pub untried: Vec<EffectKind>,
    /// Where `sensor_bias` is among the untried: the channels whose gap's
    /// steady offset matches the offset the standstills (or straights)
    /// measured, each pointing at it.
    pub offsets: Vec<OffsetMatch>,
}

/// A channel whose base-model gap has a steady offset
/// ([`crate::diagnose::report::SteadyOffset`]) that matches the sensor
/// offset the runs' standstills or straights measured: a sensor offset
/// `b` reads as a residual (simulated − measured) of `−b`, so they match
/// where `|residual + measured|` is within
/// [`crate::diagnose::report::outcome::CALIBRATION_AGREES`] combined
/// standard errors. Units: the channel's.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct OffsetMatch {
    /// The channel.
    pub channel: Channel,
    /// The gap's steady offset: the runs' mean residual.
    pub residual: f64,
    /// Its standard error (the runs' spread over `√runs`).
    pub residual_std_error: f64,
    /// The offset the calibration measured.
    pub measured: f64,
    /// Its standard error.
    pub measured_std_error: f64,
    /// Where it was measured.
    pub measured_on: CalibrationSource,
}

impl OffsetMatch {
    /// Whether a residual `residual ± residual_std_error` matches a
    /// measured offset `measured ± measured_std_error`: `residual ≈
    /// −measured` within [`crate::diagnose::report::outcome::CALIBRATION_AGREES`]
    /// combined standard errors, and the two apart from zero by more than
    /// that (an offset within its errors of none points at nothing).
    pub fn matches(residual: (f64, f64), measured: (f64, f64)) -> bool {
        let k = crate::diagnose::report::outcome::CALIBRATION_AGREES;
        let combined = residual.1.hypot(measured.1);
        (residual.0 + measured.0).abs() <= k * combined && measured.0.abs() > k * measured.1
    }
}

impl Narrowed {
    /// The narrowing of the library to `named` (None where `named` is the
    /// whole library, or the campaign names none: the default).
    pub fn of(named: Option<&[EffectKind]>) -> Option<Narrowed> {
        let tried = named?.to_vec();
        let untried: Vec<EffectKind> = EffectKind::ALL
            .into_iter()
            .filter(|k| !tried.contains(k))
            .collect();
        (!untried.is_empty()).then_some(Narrowed {
            tried,
            untried,
            offsets: Vec::new(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_whole_library_or_none_named_is_no_narrowing() {
        assert_eq!(Narrowed::of(None), None);
        assert_eq!(Narrowed::of(Some(&EffectKind::ALL)), None);
    }

    #[test]
    fn a_narrowing_names_every_effect_it_leaves_out() {
        let n = Narrowed::of(Some(&[EffectKind::ALL[1]])).unwrap();
        assert_eq!(n.tried, vec![EffectKind::ALL[1]]);
        assert_eq!(n.untried.len(), EffectKind::ALL.len() - 1);
        assert!(!n.untried.contains(&EffectKind::ALL[1]));
    }

    /// Round 43's logc3 (truth: logger offsets 0.008 rad/s and 0.2 m/s²):
    /// the ay gap's steady offset −0.1917 ± 0.0072 m/s² over 8 runs
    /// against the standstills' 0.2028 ± 0.0018, 1.5 combined standard
    /// errors apart; the yaw rate's −0.00726 ± 0.00029 against 0.00799 ±
    /// 0.00011, 2.3.
    #[test]
    fn a_steady_offset_matches_the_standstills_of_the_opposite_sign_within_three_errors() {
        assert!(OffsetMatch::matches((-0.1917, 0.0072), (0.2028, 0.0018)));
        assert!(OffsetMatch::matches(
            (-0.00726, 0.00029),
            (0.00799, 0.00011)
        ));
        // The same sign is a bias of the model, not the sensor's.
        assert!(!OffsetMatch::matches((0.1917, 0.0072), (0.2028, 0.0018)));
        // Beyond three combined errors (0.0074 · 3 = 0.0223).
        assert!(!OffsetMatch::matches((-0.17, 0.0072), (0.2028, 0.0018)));
        assert!(OffsetMatch::matches((-0.181, 0.0072), (0.2028, 0.0018)));
        // A measured offset within its errors of none points at nothing.
        assert!(!OffsetMatch::matches((-0.001, 0.002), (0.001, 0.002)));
    }
}
