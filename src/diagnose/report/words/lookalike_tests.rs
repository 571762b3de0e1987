//! A verdict's look-alikes in words: the shares, the gaps and the
//! confounding window said, never "about as well", and the single a set
//! was grown from named as such.

use super::tests::explained;
use super::*;
use crate::diagnose::effects::EffectKind;

/// The window of a reference whose gap above noise is 0.502 at the
/// helper's noise level 0.941: 1.5 × 0.502 + 0.25 × 0.941 = 0.988.
fn window() -> crate::diagnose::report::Window {
    crate::diagnose::report::Window::of(0.502, 0.941, (1.5, 0.25))
}

#[test]
fn a_look_alike_that_removes_a_smaller_share_is_said_with_the_window_it_lies_in() {
    use crate::diagnose::report::{Lookalike, Lookalikes};
    let mut v = explained(74.0);
    if let Verdict::Explained(e) = &mut v {
        e.effects = vec![EffectKind::SensorDelay];
        e.confounded_with = Some(Lookalikes {
            start: EffectKind::SensorDelay,
            start_reduction_percent: 74.0,
            window: window(),
            members: vec![Lookalike {
                effect: EffectKind::SteerPath,
                reduction_percent: 52.0,
                gap: 0.9,
                standstills: None,
                set_aside: None,
            }],
        });
    }
    let s = statement(&v);
    assert_eq!(
        s,
        "sensor_delay explains the gap: held-out error 3.628 → 1.073 (noise level 0.941), 74.0 % of the gap above noise removed; but steer_path removes 52.0 % (gap above noise 0.900) alone, against sensor_delay's 74.0 % (0.502): within the confounding window of sensor_delay's gap, 1.5 × 0.502 + 0.25 × 0.941 = 0.988, so the runs do not tell it from sensor_delay (confounded)"
    );
    assert!(!s.contains("about as well"), "{s}");
}

#[test]
fn a_sets_look_alike_fitted_in_its_place_is_confounded_or_told_apart_by_the_set() {
    use crate::diagnose::report::{InSet, Lookalike, Lookalikes};
    use EffectKind::{RelaxationLength as R, SteerPath as S, YawInertia as Y};
    let mut v = explained(85.3);
    let member = |effect, reduction_percent, gap| Lookalike {
        effect,
        reduction_percent,
        gap,
        standstills: None,
        set_aside: None,
    };
    if let Verdict::Explained(e) = &mut v {
        e.confounded_with = Some(Lookalikes {
            start: EffectKind::SensorDelay,
            start_reduction_percent: 64.0,
            window: window(),
            members: vec![member(S, 57.0, 0.8), member(Y, 55.0, 0.85)],
        });
        e.in_set = vec![
            InSet {
                effects: vec![S, R],
                reduction_percent: 86.1,
                gap: 0.45,
                window: window(),
                confounded: true,
            },
            InSet {
                effects: vec![Y, R],
                reduction_percent: 40.2,
                gap: 2.1,
                window: window(),
                confounded: false,
            },
        ];
    }
    assert_eq!(
        statement(&v),
        "sensor_delay+relaxation_length explains the gap: held-out error 3.628 → 1.073 (noise level 0.941), 85.3 % of the gap above noise removed; but steer_path in place of sensor_delay (the single the set was grown from): steer_path+relaxation_length removes 86.1 % (gap above noise 0.450), against sensor_delay+relaxation_length's 85.3 % (0.502): within the set's confounding window, 1.5 × 0.502 + 0.25 × 0.941 = 0.988, so the runs do not tell the two apart (confounded); yaw_inertia alone lies in the confounding window of sensor_delay alone, but in its place in the set yaw_inertia+relaxation_length removes 40.2 % (gap above noise 2.100), against sensor_delay+relaxation_length's 85.3 % (0.502): outside the set's confounding window, 1.5 × 0.502 + 0.25 × 0.941 = 0.988, so the set tells them apart"
    );
    // Told apart alone: the start is named as the start there.
    if let Verdict::Explained(e) = &mut v {
        e.in_set.remove(0);
    }
    assert!(statement(&v).contains(
        "; yaw_inertia alone lies in the confounding window of sensor_delay alone (the single the set was grown from), but"
    ));
}

#[test]
fn a_look_alike_the_standstills_set_aside_is_said_with_why_and_not_as_confounded() {
    use crate::diagnose::report::{Lookalike, Lookalikes, SetAside, StandstillBank};
    let mut v = explained(90.0);
    let reading = StandstillBank {
        measured: -0.201,
        measured_std_error: 0.002,
        bank: 0.0,
        logged_bank: Some(0.0),
        determined: true,
        predicted: 0.0,
        predicted_std_error: 0.0039,
        standard_errors: 45.65,
        verdict_predicted: -0.2,
        verdict_predicted_std_error: 0.005,
        verdict_standard_errors: 0.2,
        apart: true,
    };
    let member = |effect, set_aside| Lookalike {
        effect,
        reduction_percent: 80.4,
        gap: 0.633,
        standstills: Some(reading),
        set_aside,
    };
    if let Verdict::Explained(e) = &mut v {
        e.effects = vec![EffectKind::SensorBias];
        e.confounded_with = Some(Lookalikes {
            start: EffectKind::SensorBias,
            start_reduction_percent: 90.0,
            window: window(),
            members: vec![member(
                EffectKind::BankProfile,
                Some(SetAside::StandstillsContradictBank),
            )],
        });
    }
    let s = statement(&v);
    assert!(!s.contains("confounded)"), "{s}");
    assert!(
        s.contains("; bank_profile removes 80.4 % (gap above noise 0.633) alone, against sensor_bias's 90.0 % (0.502): within the confounding window of sensor_bias's gap, 1.5 × 0.502 + 0.25 × 0.941 = 0.988, but the standstills contradict its bank: parked, they read -0.201 ± 0.002 m/s²; its bank there, 0.0000 rad, the logged bank 0.0000 rad, would read 0.000 ± 0.0039 m/s² (45.6 standard errors off), the verdict's fit -0.200 ± 0.005 m/s² (0.2): set aside, not confounded"),
        "{s}"
    );
    // Not set aside: confounded, the reading said beside it.
    if let Verdict::Explained(e) = &mut v {
        let l = e.confounded_with.as_mut().unwrap();
        l.members = vec![member(EffectKind::RoadBank, None)];
        l.members[0].standstills.as_mut().unwrap().determined = false;
    }
    let s = statement(&v);
    assert!(
        s.contains("so the runs do not tell it from sensor_bias (confounded); the standstills do not tell road_bank apart: parked, they read -0.201 ± 0.002 m/s²; its bank there, 0.0000 rad as fitted, the logged bank 0.0000 rad, is one of many the runs fit alike (its parameters not all determined), so no reading refutes it; the verdict's fit -0.200 ± 0.005 m/s² (0.2)"),
        "{s}"
    );
    // Determined, but predicting about what the verdict does.
    if let Verdict::Explained(e) = &mut v {
        let b = e.confounded_with.as_mut().unwrap().members[0]
            .standstills
            .as_mut()
            .unwrap();
        (b.determined, b.apart) = (true, false);
    }
    assert!(statement(&v).ends_with("(0.2): the two predict alike"));
}
