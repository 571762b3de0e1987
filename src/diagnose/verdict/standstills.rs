//! A bank-like look-alike of the verdict (`bank_profile`, `road_bank`)
//! against the runs' standstills: set aside, not confounded, where the
//! standstills contradict the bank it fits and side with the verdict.
//!
//! **Why.** Parked, a body-fixed accelerometer reads its offset plus
//! `g·sin θ` of the road's bank θ (ISO 8855: bank positive with the left
//! edge higher; the specific force resolved in a tilted frame, Groves 2013,
//! *Principles of GNSS, Inertial, and Multisensor Integrated Navigation
//! Systems*); the calibration ([`crate::measured::calibration`]) reads the
//! standstills' `a_y` less `g·sin θ_logged` of a logged bank. A look-alike
//! that fits a bank `θ_fit` where they stood (`scale·θ_logged + offset`,
//! or `road_bank`'s constant) and no offset predicts the standstills read
//! `g·sin θ_fit − g·sin θ_logged`; the verdict predicts its own fitted
//! `sensor_bias.ay` (0 without one), read through its own bank if it fits
//! one ([`super::calibration`]). The standstills are a measurement the fit
//! never saw (the cleaning leaves them out), so where the two predictions
//! differ and the reading agrees with the verdict's, the runs do tell them
//! apart.
//!
//! **Rule** ([`contradicted`]). Set aside where (1) the runs determine the
//! look-alike's bank there (a bank offset held, or traded with its scale
//! beyond its range, is one of many that fit alike: the standstills would
//! pick one, not refute them all), (2) the two predictions differ by more
//! than [`CALIBRATION_AGREES`] combined standard errors, (3) the reading
//! lies more than that many from the look-alike's prediction, and (4)
//! nearer the verdict's, in standard errors. Otherwise the look-alike stays
//! confounded, and the reading is reported beside it.
//!
//! **Limits.** Standstills only: a straight's `a_y` holds what its
//! criteria let through (a crown, a crosswind) and, without a logged bank
//! at each straight, no bank to read it through. A bank constant over the
//! runs and the standstills alike reads as an offset everywhere, and no
//! standstill contradicts it. Units: m/s², rad.

use crate::constants::G;
use crate::diagnose::effects::EffectKind;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::outcome::CALIBRATION_AGREES;
use crate::diagnose::report::{
    CalibrationSource, Confounded, Lookalikes, ParameterValue, SetAside, StandstillBank,
};
use crate::diagnose::verdict::calibration::{through_fitted_bank, trusted_std_error};
use crate::diagnose::verdict::score::Calibrated;

/// A fit's prediction of the standstills' `a_y` (the logged bank's `g·sin`
/// removed, as the calibration reads them): the reading, its standard
/// error, the bank fitted there (None: none), and whether the runs
/// determine that bank.
struct Predicted {
    reading: f64,
    std_error: f64,
    bank: Option<f64>,
    determined: bool,
}

/// What a fit with `parameters` predicts the standstills on the logged
/// bank `logged_bank` read ([`Predicted`]).
fn predicted(parameters: &[ParameterValue], logged_bank: Option<f64>) -> Predicted {
    let finite = |x: f64| if x.is_finite() { x } else { 0.0 };
    let name = format!("{}.{}", EffectKind::SensorBias.name(), Channel::Ay.name());
    let (offset, offset_se) = parameters
        .iter()
        .find(|p| p.name == name)
        .map_or((0.0, 0.0), |p| (p.value, finite(trusted_std_error(p))));
    let theta = logged_bank.unwrap_or(0.0);
    // A scale on a logged bank of 0 there adds nothing, determined or not.
    let counts = |p: &&ParameterValue| {
        p.name == "bank_profile.offset"
            || p.name == "road_bank.bank"
            || (p.name == "bank_profile.scale" && theta != 0.0)
    };
    let determined = parameters
        .iter()
        .filter(counts)
        .all(|p| p.determined && p.held.is_none() && p.std_error.is_finite());
    match through_fitted_bank(parameters, 0.0, logged_bank) {
        Some(t) => Predicted {
            reading: offset + G * (t.bank.sin() - theta.sin()),
            std_error: offset_se.hypot(G * t.bank.cos() * finite(t.bank_std_error)),
            bank: Some(t.bank),
            determined,
        },
        None => Predicted {
            reading: offset,
            std_error: offset_se,
            bank: None,
            determined: true,
        },
    }
}

/// The bank-like look-alike fitted with `lookalike` against the
/// standstills (`calibrated`) beside the verdict fitted with `verdict`;
/// None where the look-alike fits no bank or no standstill measured `a_y`.
pub(crate) fn standstill_bank(
    verdict: &[ParameterValue],
    lookalike: &[ParameterValue],
    calibrated: &Calibrated,
) -> Option<StandstillBank> {
    let (measured, measured_se, on, logged_bank) = calibrated[Channel::Ay.index()]?;
    if on != CalibrationSource::Standstills {
        return None;
    }
    let l = predicted(lookalike, logged_bank);
    let bank = l.bank?;
    let v = predicted(verdict, logged_bank);
    let z = |x: f64, se: f64| (measured - x).abs() / se.hypot(measured_se);
    Some(StandstillBank {
        measured,
        measured_std_error: measured_se,
        bank,
        logged_bank,
        determined: l.determined,
        predicted: l.reading,
        predicted_std_error: l.std_error,
        standard_errors: z(l.reading, l.std_error),
        verdict_predicted: v.reading,
        verdict_predicted_std_error: v.std_error,
        verdict_standard_errors: z(v.reading, v.std_error),
        apart: (l.reading - v.reading).abs() > CALIBRATION_AGREES * l.std_error.hypot(v.std_error),
    })
}

/// The module's rule on a reading: the bank determined, the predictions
/// apart, the look-alike's beyond [`CALIBRATION_AGREES`] combined standard
/// errors and the verdict's nearer.
pub(crate) fn contradicted(b: &StandstillBank) -> bool {
    b.determined
        && b.apart
        && b.standard_errors > CALIBRATION_AGREES
        && b.verdict_standard_errors < b.standard_errors
}

/// Reads each look-alike alone of `l` that fits a bank (fitted alone with
/// the parameters `alone` gives) against the standstills beside the
/// verdict's `verdict`, sets aside those they contradict, and drops those
/// from the report's `confounded` groups (a group left with one effect
/// goes).
pub(crate) fn set_aside(
    l: &mut Lookalikes,
    confounded: &mut Vec<Confounded>,
    verdict: &[ParameterValue],
    alone: impl Fn(EffectKind) -> Option<Vec<ParameterValue>>,
    calibrated: &Calibrated,
) {
    for m in &mut l.members {
        m.standstills = alone(m.effect).and_then(|p| standstill_bank(verdict, &p, calibrated));
        m.set_aside = m
            .standstills
            .filter(contradicted)
            .map(|_| SetAside::StandstillsContradictBank);
    }
    let aside: Vec<EffectKind> = l
        .members
        .iter()
        .filter(|m| !m.confounded())
        .map(|m| m.effect)
        .collect();
    Confounded::without(confounded, &aside);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn value(name: &str, value: f64, std_error: f64) -> ParameterValue {
        ParameterValue::plain(name, "", value, std_error)
    }

    fn judged(v: &[ParameterValue], l: &[ParameterValue], c: &Calibrated) -> Option<bool> {
        standstill_bank(v, l, c).map(|b| contradicted(&b))
    }

    /// An accelerometer offset of −0.2 m/s², the standstills on a flat
    /// spot (logged 0) reading −0.201 ± 0.002 m/s². The verdict fits −0.2
    /// (agrees); a bank profile fitting a bank of 0 there predicts 0, 100
    /// standard errors off.
    #[test]
    fn a_determined_bank_the_standstills_contradict_is_set_aside() {
        let on = CalibrationSource::Standstills;
        let calibrated: Calibrated = [None, Some((-0.201, 0.002, on, Some(0.0))), None];
        let verdict = [value("sensor_bias.ay", -0.2, 0.005)];
        let profile = [
            value("bank_profile.scale", 0.2564, 0.008),
            value("bank_profile.offset", 0.0, 0.0004),
        ];
        let b = standstill_bank(&verdict, &profile, &calibrated).unwrap();
        assert_eq!((b.bank, b.predicted, b.measured), (0.0, 0.0, -0.201));
        // 0.201 / √((g·0.0004)² + 0.002²) = 45.65.
        assert!((b.standard_errors - 45.65).abs() < 0.01, "{b:?}");
        assert!(b.verdict_standard_errors < 1.0 && b.apart && contradicted(&b));
        // Its offset held (the runs do not determine it): any bank there
        // fits the runs alike, and the standstills contradict none.
        let mut held = profile.clone();
        held[1].held = Some(0.1);
        assert_eq!(judged(&verdict, &held, &calibrated), Some(false));
        // A constant bank of asin(−0.201/g) reads as the offset does.
        let road = [value("road_bank.bank", (-0.201 / G).asin(), 0.0008)];
        assert_eq!(judged(&verdict, &road, &calibrated), Some(false));
        // One that predicts about what the verdict does is not apart.
        let near = [value("road_bank.bank", (-0.215 / G).asin(), 0.0008)];
        let b = standstill_bank(&verdict, &near, &calibrated).unwrap();
        assert!(!b.apart && !contradicted(&b), "{b:?}");
        // Not a bank, or measured on straights: nothing to read.
        let other = [value("steer_path.delay", 0.05, 0.001)];
        assert_eq!(judged(&verdict, &other, &calibrated), None);
        let straights: Calibrated = [
            None,
            Some((-0.201, 0.002, CalibrationSource::Straights, None)),
            None,
        ];
        assert_eq!(judged(&verdict, &profile, &straights), None);
    }

    /// On a logged bank of −0.08 rad the standstills read −0.6: a bank
    /// fitted at 0.5 × the logged one predicts g·(sin(−0.04) − sin(−0.08))
    /// = +0.392 m/s²; a verdict that reads further off than it tells
    /// nothing apart.
    #[test]
    fn the_prediction_is_read_through_the_logged_bank() {
        let on = CalibrationSource::Standstills;
        let calibrated: Calibrated = [None, Some((-0.6, 0.002, on, Some(-0.08))), None];
        let verdict = [value("sensor_bias.ay", -0.6, 0.005)];
        let profile = [value("bank_profile.scale", 0.5, 0.001)];
        let b = standstill_bank(&verdict, &profile, &calibrated).unwrap();
        let want = G * ((-0.04_f64).sin() - (-0.08_f64).sin());
        assert!((b.predicted - want).abs() < 1e-12 && (want - 0.392).abs() < 1e-3);
        assert!(contradicted(&b) && b.logged_bank == Some(-0.08));
        let worse = [value("sensor_bias.ay", 2.5, 0.005)];
        assert_eq!(judged(&worse, &profile, &calibrated), Some(false));
    }
}
