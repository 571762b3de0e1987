//! A verdict's fitted sensor offsets against the ones the runs'
//! standstills and straights measured ([`crate::measured::calibration`]):
//! the evidence lines under an explained verdict. A fitted offset is judged
//! on the uncertainty the report trusts (its fold refits' scatter where its
//! standard error does not cover it: the grouped jackknife, Efron & Stein
//! 1981); the standstills' `ay`, where the verdict fits the road's bank, is
//! read through that bank, `mean(a_y) − g·sin θ_fitted` (the accelerometer
//! reads `b_ay + g·sin θ` parked, ISO 8855, bank positive with the left
//! edge higher; Groves 2013). Units: the channel's (rad/s, m/s², rad), rad
//! for banks.

use crate::constants::G;
use crate::diagnose::effects::EffectKind;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::outcome::CALIBRATION_AGREES;
use crate::diagnose::report::{
    CalibrationSource, Evidence, GapFinding, NotIdentifiable, OffsetMatch, OutsideLibrary,
    ParameterValue, ThroughBank, Verdict,
};
use crate::diagnose::verdict::score::Calibrated;

/// The sensor offsets among a verdict's `parameters` against the ones the
/// runs' standstills and straights measured. A fitted offset is judged on
/// the uncertainty the report trusts ([`trusted_std_error`]); the
/// standstills' `ay`, where the verdict fits the road's bank, is read
/// through that bank ([`through_fitted_bank`]): the offset was fitted with
/// it, not with the logged one.
pub(crate) fn calibration_evidence(
    parameters: &[ParameterValue],
    calibrated: &Calibrated,
) -> Vec<Evidence> {
    Channel::ALL
        .into_iter()
        .filter_map(|c| {
            let (mut measured, measured_std_error, measured_on, logged_bank) =
                calibrated[c.index()]?;
            let name = format!("{}.{}", EffectKind::SensorBias.name(), c.name());
            let p = parameters
                .iter()
                .find(|p| p.name == name && p.std_error.is_finite())?;
            let standstill_ay = c == Channel::Ay && measured_on == CalibrationSource::Standstills;
            let through_bank =
                through_fitted_bank(parameters, measured, logged_bank).filter(|_| standstill_ay);
            let mut measured_std_error = measured_std_error;
            if let Some(t) = &through_bank {
                measured = t.as_logged + G * (t.logged_bank.unwrap_or(0.0).sin() - t.bank.sin());
                // The reading moves by −g·cos θ per radian of the fitted
                // bank: the bank's own uncertainty is the reading's too.
                measured_std_error = measured_std_error.hypot(G * t.bank.cos() * t.bank_std_error);
            }
            let fitted_fold_std_error = p.fold_std_error.filter(|_| p.understated());
            let combined = trusted_std_error(p).hypot(measured_std_error);
            Some(Evidence::Calibration {
                channel: c,
                fitted: p.value,
                fitted_std_error: p.std_error,
                fitted_fold_std_error,
                measured,
                measured_on,
                measured_std_error,
                through_bank,
                agrees: (p.value - measured).abs() <= CALIBRATION_AGREES * combined,
            })
        })
        .collect()
}

/// Where a verdict names the candidates a campaign narrowed the library
/// to and `sensor_bias` is not among them, the channels whose gap's steady
/// offset (`findings`) matches the offset the runs measured
/// (`calibrated`; [`OffsetMatch::matches`]): the words name `sensor_bias`
/// to add. Round 43's logc3 (truth: logger offsets) printed the
/// standstills' ay offset 0.2028 ± 0.0018 m/s² and the gap's steady
/// offset −0.1917 m/s², and advised trying every effect.
pub(crate) fn offsets_matched(
    verdict: &mut Verdict,
    findings: &[GapFinding],
    calibrated: &Calibrated,
) {
    let (Verdict::OutsideLibrary(OutsideLibrary {
        narrowed: Some(n), ..
    })
    | Verdict::NotIdentifiable(NotIdentifiable {
        narrowed: Some(n), ..
    })) = verdict
    else {
        return;
    };
    if n.tried.contains(&EffectKind::SensorBias) {
        return;
    }
    n.offsets = findings
        .iter()
        .filter_map(|f| match f {
            GapFinding::Channel {
                channel,
                offset: Some(o),
                ..
            } => {
                let (measured, measured_std_error, measured_on, _) = calibrated[channel.index()]?;
                let residual = (o.mean, o.std_error);
                OffsetMatch::matches(residual, (measured, measured_std_error)).then_some(
                    OffsetMatch {
                        channel: *channel,
                        residual: o.mean,
                        residual_std_error: o.std_error,
                        measured,
                        measured_std_error,
                        measured_on,
                    },
                )
            }
            _ => None,
        })
        .collect();
}

/// The uncertainty of a fitted value the report trusts: its standard
/// error, or the fold refits' scatter where the report says the standard
/// error does not cover it ([`ParameterValue::understated`]).
pub(super) fn trusted_std_error(p: &ParameterValue) -> f64 {
    match p.fold_std_error.filter(|_| p.understated()) {
        Some(j) => j.max(p.std_error),
        None => p.std_error,
    }
}

/// The bank the verdict's `parameters` fit where the standstills stood on
/// the logged bank `logged_bank` (rad; None: no bank column, a flat road
/// as read), and the offset `as_logged` read through the logged one: None
/// where the verdict fits no bank (its model drives the base's flat road
/// and the logged bank is what the calibration had). The fitted bank is
/// `bank_profile.scale·θ + bank_profile.offset + road_bank.bank`
/// ([`crate::vehicle::Effects`]); the standstills' mean logged bank stands
/// for each one's (g·sin is linear within 0.2 % to 0.1 rad).
pub(super) fn through_fitted_bank(
    parameters: &[ParameterValue],
    as_logged: f64,
    logged_bank: Option<f64>,
) -> Option<ThroughBank> {
    let find = |name: &str| parameters.iter().find(|p| p.name == name);
    let (scale, offset, road) = (
        find("bank_profile.scale"),
        find("bank_profile.offset"),
        find("road_bank.bank"),
    );
    if scale.is_none() && offset.is_none() && road.is_none() {
        return None;
    }
    let value = |p: Option<&ParameterValue>| p.map_or(0.0, |p| p.value);
    let theta = logged_bank.unwrap_or(0.0);
    let bank = value(scale) * theta + value(offset) + value(road);
    Some(ThroughBank {
        bank,
        logged_bank,
        as_logged,
        bank_std_error: bank_std_error(scale, offset, road, theta),
    })
}

/// The standard error of the fitted bank `scale·θ + offset + bank`, rad:
/// each parameter's trusted standard error ([`trusted_std_error`]; one the
/// runs do not pin counts 0: nothing to add), the scale's times `θ`, with
/// the correlation the report gives a traded scale and offset (otherwise
/// taken as independent: the report carries no other covariance).
fn bank_std_error(
    scale: Option<&ParameterValue>,
    offset: Option<&ParameterValue>,
    road: Option<&ParameterValue>,
    theta: f64,
) -> f64 {
    let se = |p: Option<&ParameterValue>| p.map_or(0.0, trusted_std_error);
    let finite = |x: f64| if x.is_finite() { x } else { 0.0 };
    let (s, o, r) = (
        finite(theta * se(scale)),
        finite(se(offset)),
        finite(se(road)),
    );
    let rho = offset
        .and_then(|p| p.traded.as_ref())
        .filter(|t| t.with == "bank_profile.scale")
        .map_or(0.0, |t| t.correlation);
    (s * s + o * o + r * r + 2.0 * rho * s * o).max(0.0).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn offset(name: &str, value: f64, std_error: f64) -> ParameterValue {
        ParameterValue::plain(name, "m/s²", value, std_error)
    }

    #[test]
    fn a_fitted_offset_agrees_with_the_standstills_within_three_combined_standard_errors() {
        let on = CalibrationSource::Standstills;
        let calibrated: Calibrated = [
            None,
            Some((-0.600, 0.001, on, None)),
            Some((0.0, 0.001, on, None)),
        ];
        // 3·√(0.004² + 0.001²) = 0.0124 m/s².
        let params = [
            offset("sensor_bias.ay", -0.612, 0.004),
            offset("sensor_bias.yaw_rate", 0.01, 0.001),
            offset("sensor_bias.beta", 0.02, f64::NAN),
        ];
        let e = calibration_evidence(&params, &calibrated);
        // No yaw-rate calibration, no beta standard error: ay alone.
        assert_eq!(e.len(), 1);
        let Evidence::Calibration {
            agrees, channel, ..
        } = &e[0]
        else {
            panic!("{e:?}")
        };
        assert!(*agrees && *channel == Channel::Ay);
        let e = calibration_evidence(&[offset("sensor_bias.ay", -0.613, 0.004)], &calibrated);
        let Evidence::Calibration { agrees, .. } = &e[0] else {
            panic!("{e:?}")
        };
        assert!(!agrees);
        // Another effect's parameter is no offset.
        assert!(
            calibration_evidence(&[offset("road_bank.bank", -0.6, 0.001)], &calibrated).is_empty()
        );
    }

    /// Round 25B's banked road: the standstills read −0.5994 m/s² through
    /// the logged bank (−0.08 rad), the verdict fits the bank at 0.9999 ×
    /// logged + 0.003605 rad and ay −0.6308 ± 0.00921; the yaw offset
    /// 0.0004227 ± 0.000112 rad/s with folds scattering ± 0.000391.
    #[test]
    fn a_fitted_offset_is_judged_through_the_fitted_bank_and_on_the_fold_scatter_it_needs() {
        let on = CalibrationSource::Standstills;
        let calibrated: Calibrated = [
            Some((0.00002, 3.66e-5, on, None)),
            Some((-0.5994, 0.000614, on, Some(-0.08))),
            None,
        ];
        let folds = |p: ParameterValue, j: f64| ParameterValue {
            fold_std_error: Some(j),
            fold_noise_std_error: Some(0.000115),
            fold_noise_dof: None,
            ..p
        };
        let mut params = vec![
            offset("bank_profile.scale", 0.9999, 0.00145),
            offset("bank_profile.offset", 0.003605, 0.00106),
            folds(
                offset("sensor_bias.yaw_rate", 0.0004227, 0.000112),
                0.000391,
            ),
            offset("sensor_bias.ay", -0.6308, 0.00921),
        ];
        let e = calibration_evidence(&params, &calibrated);
        let [Evidence::Calibration {
            agrees: yaw_agrees,
            fitted_fold_std_error,
            through_bank: None,
            ..
        }, Evidence::Calibration {
            agrees,
            measured,
            through_bank: Some(t),
            ..
        }] = &e[..]
        else {
            panic!("{e:?}")
        };
        assert!(*yaw_agrees && *fitted_fold_std_error == Some(0.000391));
        // −0.5994 + g·(sin(−0.08) − sin(0.9999·(−0.08) + 0.003605)).
        let bank = 0.9999 * -0.08 + 0.003605;
        let expected = -0.5994 + G * ((-0.08_f64).sin() - f64::sin(bank));
        assert!((measured - expected).abs() < 1e-12 && (expected + 0.6347).abs() < 5e-4);
        assert!(*agrees && (t.bank - bank).abs() < 1e-15 && t.as_logged == -0.5994);
        // Without the fold scatter the yaw offset is 3.7 combined standard
        // errors off; with a bank fitted 0.01 rad further the ay offset
        // disagrees by 0.098 m/s².
        params[2] = offset("sensor_bias.yaw_rate", 0.0004227, 0.000112);
        params[1] = offset("bank_profile.offset", 0.013605, 0.00106);
        let e = calibration_evidence(&params, &calibrated);
        assert!(
            e.iter()
                .all(|e| matches!(e, Evidence::Calibration { agrees: false, .. })),
            "{e:?}"
        );
        // No bank fitted: the standstills as the calibration read them.
        let e = calibration_evidence(&params[2..], &calibrated);
        let Evidence::Calibration {
            measured,
            through_bank: None,
            ..
        } = &e[1]
        else {
            panic!("{e:?}")
        };
        assert_eq!(*measured, -0.5994);
    }

    /// The reading through the fitted bank carries that bank's uncertainty
    /// (g·cos θ·σ_bank): a bank fitted ± 0.005 rad makes the standstills'
    /// −0.5994 ± 0.0006 m/s² uncertain by ± 0.049, and a fitted −0.66 ±
    /// 0.005 agrees with it; judged on the standstills' scatter alone it
    /// was 12 combined standard errors off.
    #[test]
    fn the_standstills_read_through_a_fitted_bank_carry_that_banks_uncertainty() {
        let on = CalibrationSource::Standstills;
        let calibrated: Calibrated = [None, Some((-0.5994, 0.0006, on, Some(-0.08))), None];
        let mut params = vec![
            offset("bank_profile.scale", 1.0, 0.01),
            offset("bank_profile.offset", 0.0, 0.005),
            offset("sensor_bias.ay", -0.66, 0.005),
        ];
        let e = calibration_evidence(&params, &calibrated);
        let [Evidence::Calibration {
            agrees,
            measured_std_error,
            through_bank: Some(t),
            ..
        }] = &e[..]
        else {
            panic!("{e:?}")
        };
        let sigma_bank = (0.0008_f64.powi(2) + 0.005_f64.powi(2)).sqrt();
        assert!((t.bank_std_error - sigma_bank).abs() < 1e-15, "{t:?}");
        let expected = 0.0006_f64.hypot(G * 0.08_f64.cos() * sigma_bank);
        assert!((measured_std_error - expected).abs() < 1e-12 && *agrees);
        // A scale and offset traded against each other (correlation −0.9):
        // at θ = −0.08 their errors add in the bank, 2·ρ·(θ·σ_s)·σ_o > 0.
        params[1].traded = Some(crate::diagnose::report::Traded {
            with: "bank_profile.scale".into(),
            correlation: -0.9,
            sum: 1.0,
            sum_std_error: 0.01,
            sum_fold_std_error: None,
            split_undetermined: false,
        });
        let e = calibration_evidence(&params, &calibrated);
        let Evidence::Calibration {
            through_bank: Some(t),
            ..
        } = &e[0]
        else {
            panic!("{e:?}")
        };
        let (s, o): (f64, f64) = (-0.08 * 0.01, 0.005);
        let with_rho = (s * s + o * o + 2.0 * -0.9 * s * o).sqrt();
        assert!((t.bank_std_error - with_rho).abs() < 1e-15 && with_rho > sigma_bank);
    }
}
