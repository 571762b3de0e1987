//! The rule that holds a swarm fit's undetermined parameters: flagged by
//! the standard error and its effect, held on data that leave a direction
//! free, never on data that fix it, and never over a value the user gives.

use super::*;
use crate::identify::data::identification_conditions;
use crate::identify::{fit_channel_holding, Channel, FitSettings, HeldFor, ParameterReport};
use crate::tyre::{MagicSimple, Pac89};

fn settings(seed: u64) -> FitSettings {
    let mut s = FitSettings::new(seed);
    s.hold_undetermined = true;
    s
}

/// PAC89 rig data in its linear range only (|α| ≤ 1.5°, three loads):
/// the stiffness `BCD` is fixed, the peak `D` and the curvature `E` are
/// not.
fn linear_range_pac89() -> (Tyre, Vec<Condition>) {
    let truth = Tyre::Pac89(Pac89::adams_example());
    let (mut conditions, _) = identification_conditions(&truth, 0.01, 7);
    for c in &mut conditions {
        c.points.retain(|q| q.slip().abs() <= 1.5f64.to_radians());
        c.samples = c.points.len();
    }
    let start = Tyre::Pac89(Pac89 {
        b: None,
        c: None,
        ..Pac89::adams_example()
    });
    (start, conditions)
}

#[test]
fn a_parameter_is_flagged_by_its_standard_error_and_its_effect_or_by_having_none() {
    let spread = Spread {
        covariance: Some(DMatrix::from_diagonal(&nalgebra::dvector![
            4.0,
            4.0,
            0.01,
            f64::NAN
        ])),
        effect: vec![0.05, 0.005, 0.5, f64::NAN],
        pull: vec![0.0; 4],
    };
    // ±2 on 1.5, moving the fit by 5 %: not determined.
    assert!(spread.flagged(0, 1.5));
    // ±2 on 1.5 moving it by 0.5 %: a value the fit does not need.
    assert!(!spread.flagged(1, 1.5));
    // ±0.1 on 1.5: determined, whatever its effect.
    assert!(!spread.flagged(2, 1.5));
    // No standard error (singular along it).
    assert!(spread.flagged(3, 1.5));
    // The rest trade along the held one's direction as the covariance says.
    let mut c = DMatrix::from_diagonal(&nalgebra::dvector![4.0, 1.0]);
    c[(0, 1)] = -2.0;
    c[(1, 0)] = -2.0;
    let traded = Spread {
        covariance: Some(c),
        effect: vec![0.1, 0.1],
        pull: vec![0.0; 2],
    };
    assert_eq!(traded.compensating(0, 2.0), vec![2.0, -1.0]);
}

#[test]
fn linear_range_data_hold_the_peak_and_curvature_terms_not_the_stiffness() {
    let (start, conditions) = linear_range_pac89();
    let free = fit_channel_holding(
        &start,
        Channel::LateralForce,
        &conditions,
        &FitSettings::new(3),
        &[],
    )
    .unwrap();
    let fit = fit_channel_holding(
        &start,
        Channel::LateralForce,
        &conditions,
        &settings(3),
        &[],
    )
    .unwrap();
    let held: Vec<&ParameterReport> = fit
        .parameters
        .iter()
        .filter(|p| matches!(p.held, Some(HeldFor::Undetermined { .. })))
        .collect();
    assert!(!held.is_empty(), "{:#?}", fit.parameters);
    let a = Pac89::adams_example().a;
    for p in &held {
        assert!(!p.free && p.warning.is_none(), "{p:?}");
        // At the start tyre's value.
        let i: usize = p.name[1..].parse().unwrap();
        assert_eq!(p.value, a[i], "{}", p.name);
        let Some(HeldFor::Undetermined {
            fitted,
            std_error,
            effect_percent,
            ..
        }) = p.held
        else {
            unreachable!()
        };
        assert!(
            std_error.is_none_or(|s| s >= fitted.abs() && effect_percent.unwrap() >= 1.0),
            "{p:?}"
        );
    }
    // The cornering stiffness is what these data fix.
    let a3 = fit.parameters.iter().find(|p| p.name == "a3").unwrap();
    assert!(a3.free, "{a3:?}");
    // What is left free is determined, or moves the fit by less than 1 %.
    for p in fit.parameters.iter().filter(|p| p.free) {
        let (se, effect) = (p.std_error.unwrap(), p.effect_percent.unwrap());
        assert!(se < p.value.abs() || effect < 1.0, "{p:?}");
    }
    // Holding what the data do not determine costs them little.
    assert_eq!(fit.free_sigma_percent, Some(free.sigma_percent));
    assert!(
        fit.sigma_percent < 1.1 * free.sigma_percent + 0.01,
        "{} against {}",
        fit.sigma_percent,
        free.sigma_percent
    );
}

#[test]
fn a_value_given_with_hold_wins_over_the_rule() {
    let (start, conditions) = linear_range_pac89();
    let hold = [("a7".to_string(), 0.5), ("a2".to_string(), 1100.0)];
    let fit = fit_channel_holding(
        &start,
        Channel::LateralForce,
        &conditions,
        &settings(3),
        &hold,
    )
    .unwrap();
    for (name, v) in hold {
        let p = fit.parameters.iter().find(|p| p.name == name).unwrap();
        assert_eq!((p.value, p.held), (v, Some(HeldFor::Given)), "{p:?}");
    }
}

#[test]
fn data_that_fix_every_parameter_hold_none() {
    let truth = Tyre::MagicSimple(MagicSimple {
        d: 0.95,
        ..MagicSimple::new(11.0, 1.35)
    });
    let (conditions, _) = identification_conditions(&truth, 0.01, 5);
    let start = Tyre::MagicSimple(MagicSimple::new(8.0, 1.2));
    let fit = fit_channel_holding(
        &start,
        Channel::LateralForce,
        &conditions,
        &settings(5),
        &[],
    )
    .unwrap();
    assert_eq!(fit.free_sigma_percent, None);
    assert!(
        fit.parameters.iter().all(|p| p.free),
        "{:#?}",
        fit.parameters
    );
}

/// A hold refused within the free fit's ±2 linearised standard errors
/// shows the data fix the parameter beyond that linearisation: its
/// warning is the staged fit's words for it (`Determination::said`), not
/// "not identified", typed in the report, with the refusal after them;
/// one refused beyond the ±2 keeps its warning and gets no type.
#[test]
fn a_hold_refused_within_its_linearisation_is_said_as_the_staged_fit_says_it() {
    let (start, conditions) = linear_range_pac89();
    let free = fit_channel_holding(
        &start,
        Channel::LateralForce,
        &conditions,
        &FitSettings::new(3),
        &[],
    )
    .unwrap();
    let i = free
        .parameters
        .iter()
        .position(|p| {
            let bound = super::super::parameters::on_search_bound(p.value, p.bounds);
            p.free && p.warning.is_some() && p.std_error.is_some() && !bound
        })
        .unwrap_or_else(|| panic!("{:#?}", free.parameters));
    let p = &free.parameters[i];
    let was = p.warning.clone().unwrap();
    assert!(was.starts_with("not identified"), "{was}");
    let tried = |within| Tried {
        i,
        value: p.value + p.std_error.unwrap(),
        within,
    };
    let fixed = refusals_said(free.clone(), &[tried(true)]);
    let q = &fixed.parameters[i];
    let Some(Determination::FixedBeyondLinearisation {
        effect_percent,
        partner,
    }) = &q.determination
    else {
        panic!("{q:?}")
    };
    assert_eq!(Some(*effect_percent), p.effect_percent);
    let w = q.warning.as_deref().unwrap();
    let head = q.determination.as_ref().unwrap().said(p.std_error).unwrap();
    assert!(w.starts_with(&format!("{head}; held at ")), "{w}");
    assert!(
        w.starts_with("fixed by the data more tightly than its standard error says: the linearised standard error "),
        "{w}"
    );
    assert!(!w.contains("not identified"), "{w}");
    if let Some(partner) = partner {
        assert!(
            partner.correlation.abs() >= STRONG_CORRELATION,
            "{partner:?}"
        );
        assert!(
            w.contains(&format!("it trades with {}", partner.name)),
            "{w}"
        );
    }
    let beyond = refusals_said(free.clone(), &[tried(false)]);
    let q = &beyond.parameters[i];
    assert_eq!(q.determination, None);
    let w = q.warning.as_deref().unwrap();
    assert!(w.starts_with(&format!("{was}; held at ")), "{w}");
}
