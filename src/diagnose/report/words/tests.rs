//! The words made from the typed outcome: the sentences readers and tests
//! match, and what a sentence may not say.

use super::*;
use crate::diagnose::base::identify::{Axle, AxleLimit, NoTyre};
use crate::diagnose::effects::{Bound, EffectKind, Group};
use crate::diagnose::report::outcome::{
    Evidence, Explained, NoSignificantGap, OutsideLibrary, VerdictWarning,
};
use crate::diagnose::report::RankWarning;
use crate::diagnose::report::{ParameterValue, Part, Unseen};

pub(super) fn explained(reduction_percent: f64) -> Verdict {
    Verdict::Explained(Explained {
        effects: vec![EffectKind::SensorDelay, EffectKind::RelaxationLength],
        parameters: Vec::new(),
        heldout_error_before: 3.628,
        heldout_error_after: 1.073,
        noise_level: 0.941,
        reduction_percent,
        warnings: Vec::new(),
        evidence: Vec::new(),
        confounded_with: None,
        in_set: Vec::new(),
    })
}

#[test]
fn a_fitted_offset_is_confirmed_or_not_by_the_standstills_in_its_unit() {
    let e = |fitted: f64, agrees: bool| Evidence::Calibration {
        channel: crate::diagnose::model::channels::Channel::Ay,
        fitted,
        fitted_std_error: 0.005,
        fitted_fold_std_error: None,
        measured: -0.6,
        measured_on: crate::diagnose::report::outcome::CalibrationSource::Standstills,
        measured_std_error: 0.001,
        through_bank: None,
        agrees,
    };
    assert_eq!(
        evidence(&e(-0.6, true)),
        "confirmed: the ay offset fitted, -0.6000 ± 0.00500 m/s², agrees with the standstills' -0.6000 ± 0.00100 m/s²"
    );
    assert!(evidence(&e(0.1, false)).starts_with("not confirmed: the ay offset fitted, 0.1000"));
}
#[test]
fn an_explained_verdict_says_how_much_and_whether_part() {
    assert_eq!(
        statement(&explained(85.3)),
        "sensor_delay+relaxation_length explains the gap: held-out error 3.628 → 1.073 (noise level 0.941), 85.3 % of the gap above noise removed"
    );
    assert_eq!(
        statement(&explained(42.0)),
        "sensor_delay+relaxation_length explains part of the gap: held-out error 3.628 → 1.073 (noise level 0.941), 42.0 % of the gap above noise removed; the other 58.0 % is not shown to be a gap: the held-out error left is 1.14 × the noise level, within the 1.3 × a gap must exceed (more or longer runs would tell a further cause from noise)"
    ); // The extent the sentence says, typed for the JSON.
    let extent = |v: &Verdict| match v {
        Verdict::Explained(e) => e.extent(),
        _ => unreachable!(),
    };
    use crate::diagnose::report::outcome::Extent;
    assert_eq!(extent(&explained(85.3)), Extent::All);
    assert_eq!(extent(&explained(42.0)), Extent::Part);
}

#[test]
fn an_explained_verdict_names_a_channel_whose_gap_it_leaves_in_its_sentence_and_warning() {
    use crate::diagnose::model::channels::Channel;
    use crate::diagnose::report::outcome::{ChannelLeft, VerdictWarning};
    let mut v = explained(52.5);
    if let Verdict::Explained(e) = &mut v {
        e.warnings = vec![VerdictWarning::ChannelLeft(ChannelLeft {
            channel: Channel::YawRate,
            before: 0.0247,
            after: 0.0216,
            noise_floor: 0.0020,
            removed_percent: 12.6,
            acceptance_percent: 30.0,
            causes: Vec::new(),
        })];
    }
    assert_eq!(
        statement(&v),
        "sensor_delay+relaxation_length explains the gap but not its yaw_rate part: held-out error 3.628 → 1.073 (noise level 0.941), 52.5 % of the gap above noise removed"
    );
    assert_eq!(
        verdict_warnings(&v),
        ["it leaves the yaw_rate gap: RMS 0.0247 → 0.0216 rad/s on held-out runs (noise floor 0.0020), 13 % of the gap above noise removed, less than the 30 % the verdict needs of the whole; the combined error falls through the other channels, so this channel's gap has another cause (a model-form error the candidates do not hold, or this channel's sensor)"]
    );
}

#[test]
fn no_gap_names_its_threshold() {
    let v = Verdict::NoSignificantGap(NoSignificantGap {
        heldout_error: 1.05,
        noise_level: 0.95,
        threshold: 1.3,
        resting_on: Vec::new(),
        assumed: Vec::new(),
        far_from_off: None,
    });
    assert_eq!(
        statement(&v),
        "no significant gap: held-out error 1.050 is within 1.3 × the noise level 0.950"
    );
    assert_eq!(v.kind().name(), "no_significant_gap");
    // Resting on an uncertainty stated far above the channel's scatter.
    let excess = crate::diagnose::model::scale::stated_excess(
        crate::diagnose::model::channels::Channel::YawRate,
        crate::diagnose::report::ScaleSource::Stated,
        0.04,
        0.0025,
    );
    let v = Verdict::NoSignificantGap(NoSignificantGap {
        heldout_error: 1.05,
        noise_level: 0.95,
        threshold: 1.3,
        resting_on: excess.into_iter().collect(),
        assumed: Vec::new(),
        far_from_off: None,
    });
    assert_eq!(
        statement(&v),
        "no significant gap: held-out error 1.050 is within 1.3 × the noise level 0.950; this rests on the uncertainty stated under [channels] for yaw_rate, 0.0400 rad/s, 16× the channel's own scatter, 0.0025 rad/s: a gap below it is called insignificant only because of the statement"
    );
}

fn peak() -> NoTyre {
    NoTyre::EarlyPeak {
        axle: Axle::Rear,
        peak_slip: 1.81f64.to_radians(),
        coefficient_over_friction: 44.0,
    }
}

fn outside(reduction_percent: f64, why: Vec<Refusal>) -> Verdict {
    Verdict::OutsideLibrary(OutsideLibrary {
        heldout_error: 2.5,
        noise_level: 1.0,
        refused: Some(Refused {
            effects: vec![EffectKind::SensorBias],
            reduction_percent,
            why,
        }),
        threshold_percent: 30.0,
        tyre_class: None,
        narrowed: None,
        bearing: Vec::new(),
        runs_carrying: None,
    })
}

#[test]
fn a_best_below_acceptance_is_a_model_form_error_outside_the_library() {
    let v = outside(
        12.4,
        vec![Refusal::BelowAcceptance {
            threshold_percent: 30.0,
        }],
    );
    assert_eq!(
        statement(&v),
        "a gap (held-out error 2.500, noise level 1.000) that no candidate effect explains: the best, sensor_bias, removes 12.4 % of it (acceptance needs 30 %) — a model-form error outside the library"
    );
}

#[test]
fn a_best_below_acceptance_that_fails_more_names_the_share_once_then_the_rest() {
    let v = outside(
        12.4,
        vec![
            Refusal::BelowAcceptance {
                threshold_percent: 30.0,
            },
            Refusal::BicNotLower { delta_bic: 4.0 },
        ],
    );
    let s = statement(&v);
    assert_eq!(
        s,
        "a gap (held-out error 2.500, noise level 1.000) that no candidate effect explains: the best, sensor_bias, removes 12.4 % of it, less than the 30 % acceptance needs, and besides its BIC is not lower than the base model's (ΔBIC +4) — a model-form error outside the library"
    );
    assert_eq!(s.matches("acceptance needs").count(), 1, "{s}");
    assert!(!s.contains("but is refused"), "{s}");
}

#[test]
fn no_sentence_claims_a_removal_above_acceptance_and_that_nothing_explains_the_gap() {
    // The sedan: sensor_bias removes 53.5 %, its axles are no tyre.
    let v = outside(
        53.5,
        vec![Refusal::AxlesNoTyre {
            no_tyre: vec![peak()],
        }],
    );
    let s = statement(&v);
    assert_eq!(
        s,
        "a gap (held-out error 2.500, noise level 1.000) for which no candidate effect is accepted: the best, sensor_bias, removes 53.5 % of it (acceptance needs 30 %) but is refused: fitted with it, the axles are no tyre (the rear axle peaks at 1.81° of slip (cornering coefficient over peak friction 44 1/rad; no tyre peaks before 2°): the data pull it to saturate early) — no verdict from the library"
    );
    // Every refusal that is not the share alone.
    let simpler = Refused {
        effects: vec![EffectKind::SensorDelay],
        reduction_percent: 25.0,
        why: vec![Refusal::BelowAcceptance {
            threshold_percent: 30.0,
        }],
    };
    for why in [
        Refusal::BicNotLower { delta_bic: 4.0 },
        Refusal::LeavesParameterIdle {
            simpler: Box::new(simpler.clone()),
        },
        Refusal::PressedOnSearchBound {
            inside: Box::new(simpler.clone()),
        },
        Refusal::SearchEndedOn {
            set: Box::new(simpler),
        },
    ] {
        let s = statement(&outside(53.5, vec![why]));
        assert!(!s.contains("no candidate effect explains"), "{s}");
        assert!(s.contains("removes 53.5 % of it"), "{s}");
        assert!(s.contains("is refused: "), "{s}");
    }
}

#[test]
fn the_base_that_is_no_tyre_is_said_with_its_reasons() {
    let v = Verdict::NotIdentifiable(crate::diagnose::report::NotIdentifiable {
        heldout_error: 4.0,
        noise_level: 1.0,
        no_tyre: vec![
            NoTyre::Limit {
                parameter: "rear cornering coefficient",
                limit: AxleLimit::Rigid,
            },
            peak(),
        ],
        threshold_percent: 30.0,
        closest: Vec::new(),
        road_friction: None,
        tyre_class: None,
        narrowed: None,
    });
    assert_eq!(
        statement(&v),
        "the base model is not identifiable from these runs: rear cornering coefficient at its physical limit 4,000 1/rad (a rigid axle that never slips; no tyre is that stiff): the data pull it higher; the rear axle peaks at 1.81° of slip (cornering coefficient over peak friction 44 1/rad; no tyre peaks before 2°): the data pull it to saturate early; no candidate effect fitted with it gives axles that are a tyre and removes 30 % of the gap (held-out error 4.000, noise level 1.000), so there is no model-form verdict; no candidate fitted with it makes the axles a tyre: what bent them is outside the library"
    );
    // The candidates whose jointly fitted axles are a tyre, named with
    // what they remove: where the fingerprint may come from.
    let Verdict::NotIdentifiable(n) = v else {
        unreachable!()
    };
    let v = Verdict::NotIdentifiable(crate::diagnose::report::NotIdentifiable {
        closest: vec![
            crate::diagnose::report::Closest {
                effects: vec![EffectKind::SensorBias, EffectKind::SteerPath],
                reduction_percent: 21.44,
            },
            crate::diagnose::report::Closest {
                effects: vec![EffectKind::RollSteer],
                reduction_percent: 8.0,
            },
        ],
        ..n
    });
    assert!(
        statement(&v).ends_with("so there is no model-form verdict; the candidates that make the axles a tyre, fitted jointly, come closest: sensor_bias+steer_path (removes 21.4 %), roll_steer (removes 8.0 %)"),
        "{}",
        statement(&v)
    );
    // A road friction the campaign states is named with its line.
    let Verdict::NotIdentifiable(n) = v else {
        unreachable!()
    };
    let v = Verdict::NotIdentifiable(crate::diagnose::report::NotIdentifiable {
        road_friction: Some(crate::diagnose::campaign::StatedFriction {
            value: 0.6,
            line: 7,
        }),
        ..n
    });
    assert!(
        statement(&v).ends_with("roll_steer (removes 8.0 %); the campaign states `[road] friction = 0.6` (line 7), a scale on the grip that trades off with the axles' peak friction identified from the runs: a road friction off the truth bends them out of any tyre's range (check it, or leave it out for 1)"),
        "{}",
        statement(&v)
    );
}

#[test]
fn axles_restored_by_the_verdicts_effects_are_evidence_with_the_bases_reasons() {
    let e = Evidence::AxlesRestored {
        no_tyre: vec![peak()],
    };
    assert_eq!(
        evidence(&e),
        "axles restored: the base model alone is no tyre (the rear axle peaks at 1.81° of slip (cornering coefficient over peak friction 44 1/rad; no tyre peaks before 2°): the data pull it to saturate early); fitted with the verdict's effects the axles are a tyre, so the effects account for what bent them (the reductions are measured against the base alone)"
    );
}

#[test]
fn ranking_warnings_and_notes_are_worded_as_readers_match_them() {
    let w = [
        RankWarning::Disagreement {
            insample_percent: 64.0,
            heldout_percent: 12.0,
        },
        RankWarning::FoldsNotConverged {
            failed: 2,
            folds: 8,
        },
    ];
    assert_eq!(
        rank_warnings(&w).unwrap(),
        "the fit on all runs removes 64 % of the gap but only 12 % on held-out runs: the effect does not generalise across runs, or the runs cannot pin its parameters; 2 of 8 fold refits did not converge"
    );
    assert_eq!(rank_warnings(&[]), None);
    let n = Note::NotACandidate {
        effect: EffectKind::CombinedSlip,
        lacks: Unseen::LongitudinalAcceleration { threshold: 0.5 },
    };
    assert_eq!(
        note(&n),
        "combined_slip: not a candidate: no run has a longitudinal acceleration above 0.5 m/s² (an ax channel or a changing speed)"
    );
    let stiff = Note::StiffReplay {
        step: 0.01,
        runs: 2,
        of: 8,
    };
    assert!(note(&stiff).starts_with(
        "replay method: the base model is too stiff for RK4 at the 0.01 s step on 2 of 8 runs"
    ));
}

/// A fitted value of no known standard error, on `bound` if any.
pub(super) fn fitted(
    name: &str,
    unit: &'static str,
    v: f64,
    bound: Option<Bound>,
) -> ParameterValue {
    ParameterValue {
        at_bound: bound.is_some(),
        bound,
        determined: false,
        ..ParameterValue::plain(name, unit, v, f64::NAN)
    }
}

#[test]
fn a_lookalike_passed_over_for_its_search_bound_is_named_with_the_value_it_needed() {
    let e = Evidence::LookalikePressed {
        effects: vec![EffectKind::SensorDelay],
        reduction_percent: 54.3,
        pressed: vec![fitted("sensor_delay.delay", "s", 0.3, Some(Bound::Search))],
        pressed_ranges: Vec::new(),
        verdict_inside: Vec::new(),
    };
    assert_eq!(
        evidence(&e),
        "chosen over a look-alike pressed on its search range: sensor_delay, which removes 54.3 %, but only with sensor_delay.delay = 0.3000 s at the end of the range searched; an effect that explains the gap only at the end of its plausible range stands in for something else, where the verdict, within the confounding window of it, explains the gap from inside its ranges"
    );
    let r = Refusal::PressedOnSearchBound {
        inside: Box::new(Refused {
            effects: vec![EffectKind::SteerPath],
            reduction_percent: 25.0,
            why: vec![Refusal::BelowAcceptance {
                threshold_percent: 30.0,
            }],
        }),
    };
    let s = statement(&outside(31.0, vec![r]));
    assert!(
        s.contains("a parameter of it is pressed on its search bound, and the look-alike inside its ranges was taken in its place: steer_path, which removes 25.0 % and is refused"),
        "{s}"
    );
}

#[test]
fn a_parameter_on_a_physical_limit_is_not_worded_as_a_search_bound() {
    // No negative down-force: aero's lower bound is a physical limit.
    for q in EffectKind::AeroLoad.parameters() {
        assert_eq!(q.bound_at(0.0), Some(Bound::Physical), "{}", q.name);
        assert_eq!(q.bound_at(q.bounds.1), Some(Bound::Search), "{}", q.name);
    }
    let at = |v, b| {
        parameter(&fitted(
            "aero_load.front",
            "N/(m/s)²",
            v,
            EffectKind::AeroLoad.parameters()[0].bound_at(b),
        ))
    };
    let floor = at(0.0, 0.0);
    assert_eq!(
        floor,
        "aero_load.front = 0.0000 N/(m/s)² (at its physical limit: any smaller value would be negative)"
    );
    assert!(at(6.0, 6.0).contains("at its search bound: the data would take it further"));
    let share = parameter(&fitted(
        "load_transfer_distribution.front_share",
        "-",
        1.0,
        Some(Bound::Physical),
    ));
    assert!(
        share.ends_with("(at its physical limit: a share cannot exceed 1)"),
        "{share}"
    );
}

#[test]
fn a_steering_compliance_is_given_in_the_unit_of_its_scenario_key_too() {
    let mut p = fitted(
        "steering_compliance.steer_per_front_force",
        "rad/kN",
        0.003,
        None,
    );
    (p.std_error, p.asymptotic_std_error) = (2e-4, 2e-4);
    p.determined = true;
    assert_eq!(
        parameter(&p),
        "steering_compliance.steer_per_front_force = 0.003000 ± 0.000200 rad/kN (3e-6 rad/N)"
    );
}

#[test]
fn a_standard_error_beyond_the_whole_range_is_not_determined_and_a_lag_at_0_is_on_its_limit() {
    let [delay, lag] = EffectKind::SteerPath.parameters() else {
        panic!("a steer path has a delay and a lag");
    };
    let steer_path = |q, v, se| ParameterValue::of(Group::Effect(EffectKind::SteerPath), q, v, se);
    // ±6 s on a delay whose range is 0–0.5 s: the runs do not see it.
    let p = steer_path(delay, 0.12, 6.0);
    assert!(!p.determined && !p.at_bound, "{p:?}");
    assert_eq!(
        parameter(&p),
        "steer_path.delay = 0.1200 s (not determined by the runs: its standard error 6.00 s exceeds its whole range)"
    );
    // Up to the whole range it is (a wide one, but a measure).
    assert!(steer_path(delay, 0.12, 0.5).determined);
    assert!(!steer_path(delay, 0.12, 0.5001).determined);
    assert!(!steer_path(delay, 0.12, f64::NAN).determined);
    // A lag of a few microseconds stands on its physical limit 0 (within
    // 1e-4 of its 0.5 s range); 60 µs does not.
    let on = steer_path(lag, 3e-6, 6.0);
    assert_eq!(on.bound, Some(Bound::Physical));
    assert!(on.at_bound);
    assert_eq!(
        parameter(&on),
        "steer_path.lag = 0.0000 s (at its physical limit: any smaller value would be negative)"
    );
    assert_eq!(steer_path(lag, 5e-5, 1e-5).bound, Some(Bound::Physical));
    assert_eq!(steer_path(lag, 6e-5, 1e-5).bound, None);
    // A search bound is where the fit stops, exactly: 1e-4 of the range
    // off a bank's search bound is inside it.
    let bank = &EffectKind::RoadBank.parameters()[0];
    assert_eq!(
        ParameterValue::of(Group::Effect(EffectKind::RoadBank), bank, 0.15, f64::NAN).bound,
        Some(Bound::Search)
    );
    assert_eq!(
        ParameterValue::of(Group::Effect(EffectKind::RoadBank), bank, 0.15 - 1e-5, 1e-3).bound,
        None
    );
}

#[test]
fn a_channel_within_noise_is_said_so_on_the_terminal_as_on_the_page() {
    let s = crate::diagnose::report::Shrinkage {
        channel: crate::diagnose::model::channels::Channel::Beta,
        part: crate::diagnose::report::Part::All,
        samples: 10,
        before: 0.0021,
        after: 0.0022,
        noise_floor: 0.0020,
        reduction_percent: -43.0,
        mean_level: None,
        runs: Vec::new(),
    };
    assert_eq!(
        channel_change(&s),
        "beta      0.0021 → 0.0022 (noise floor 0.0020): not significant alone (1.0 → 1.1 noise floors; a channel alone needs 3)"
    );
    // The page's cells are these texts: 0.00325 was 3.250e-3 there and
    // 0.0032 here; a floor of 2.1e-4 rad reads as two digits, not 0.0002.
    assert_eq!(rms(0.0032), "0.0032");
    assert_eq!(rms(0.00021), "0.00021");
    assert_eq!(rms(0.2174), "0.2174");
    let small = crate::diagnose::report::Shrinkage {
        noise_floor: 0.00021,
        ..s
    };
    assert!(channel_change(&small).contains("(noise floor 0.00021)"));
}

fn channel_finding(rms: f64, significant_runs: usize, wrong: Vec<(Part, f64)>) -> GapFinding {
    GapFinding::Channel {
        channel: crate::diagnose::model::channels::Channel::Beta,
        rms,
        noise_floor: 0.002,
        significant_runs,
        significant_in: Vec::new(),
        within_in: Vec::new(),
        runs: 8,
        wrong,
        right: vec![Part::Window(crate::diagnose::report::parts::Window::Later)],
        off_in_right: Vec::new(),
        offset: None,
        combined: None,
    }
}

#[test]
fn a_gap_within_noise_is_given_no_place() {
    let overall = |significant| GapFinding::Overall {
        significant,
        heldout_error: 1.05,
        noise_level: 0.95,
    };
    assert_eq!(gap_heading(&[overall(false)]), "the gap, within noise");
    assert_eq!(gap_heading(&[overall(true)]), "where the gap lies");
    // Within three noise floors overall and in every part: no list.
    let quiet = finding(&channel_finding(0.0021, 0, vec![]));
    assert_eq!(
        quiet,
        "beta: RMS 0.0021 rad (noise floor 0.0020); significant in 0 of 8 runs: within noise in every part, so no place where the base model is wrong"
    );
    // One part above three floors of a channel within noise: named, not
    // as where the model is wrong.
    let one = finding(&channel_finding(
        0.0021,
        0,
        vec![(
            Part::Window(crate::diagnose::report::parts::Window::Later),
            0.0071,
        )],
    ));
    assert!(
        one.ends_with(": within noise over the runs and in every run; one part, later (0.007 rad), reads above 3 noise floors: too little of the runs to say the base model is wrong there"),
        "{one}"
    );
    assert!(!one.contains("wrong in"), "{one}");
    assert!(!one.contains("no place"), "{one}");
    // A gap above noise: where it is wrong and right.
    let loud = finding(&channel_finding(
        0.0090,
        3,
        vec![(
            Part::Window(crate::diagnose::report::parts::Window::Later),
            0.0120,
        )],
    ));
    assert!(
        loud.ends_with("; wrong in: later (0.012 rad); right in: later"),
        "{loud}"
    );
}

#[test]
fn a_verdict_parameter_on_its_search_bound_is_called_a_bound_not_a_measurement() {
    let one = VerdictWarning::OnSearchBound {
        parameters: vec![fitted("sensor_delay.delay", "s", 0.3, Some(Bound::Search))],
    };
    assert_eq!(
        verdict_warning(&one),
        "sensor_delay.delay = 0.3000 s on its search bound: the data would take it further, so its value is a bound on the effect's size, not a measurement of it"
    );
    let two = VerdictWarning::OnSearchBound {
        parameters: vec![
            fitted("aero_load.front", "N/(m/s)²", 6.0, Some(Bound::Search)),
            fitted("aero_load.rear", "N/(m/s)²", 6.0, Some(Bound::Search)),
        ],
    };
    let w = verdict_warning(&two);
    assert!(w.contains("on their search bound"), "{w}");
    assert!(w.contains("their values are a bound"), "{w}");
}
