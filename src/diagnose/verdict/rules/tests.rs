//! Each rule of the verdict on hand-built numbers, at its boundary: a
//! changed threshold or ordering fails one of these.

use super::*;
use crate::diagnose::base::identify::{AxleLimit, NoTyre};
use crate::diagnose::effects::EffectKind;

#[test]
fn a_gap_is_significant_above_1_3_noise_levels() {
    assert!(!significant(1.3, 1.0));
    assert!(!significant(1.2999, 1.0));
    assert!(significant(1.3001, 1.0));
    // Scaled with the noise level.
    assert!(!significant(2.59, 2.0));
    assert!(significant(2.61, 2.0));
}

#[test]
fn acceptance_needs_30_percent_and_a_lower_bic() {
    assert!(!accepted(29.9, -10.0, 0.0), "29.9 % is refused");
    assert!(accepted(30.0, -10.0, 0.0), "30 % is accepted");
    assert!(accepted(30.1, -10.0, 0.0), "30.1 % is accepted");
    // The BIC must be strictly lower than the one it is compared with
    // (the base's, or the set's it extends).
    assert!(!accepted(95.0, 0.0, 0.0));
    assert!(!accepted(95.0, 5.0, 0.0));
    assert!(accepted(95.0, -100.0, -99.9));
}

#[test]
fn the_greedy_search_starts_from_a_best_single_that_removes_10_percent() {
    assert!(!promising(9.9, -1.0));
    assert!(promising(10.0, -1.0));
    assert!(promising(10.1, -1.0));
    // With a BIC no lower than the base's it starts nothing.
    assert!(!promising(80.0, 0.0));
    assert!(!promising(80.0, 1.0));
}

#[test]
fn a_single_pairs_with_the_best_in_sample_where_it_removes_something_and_lowers_the_bic() {
    assert!(pairable(0.1, -1.0));
    assert!(pairable(5.1, -473.0));
    assert!(!pairable(0.0, -1.0));
    assert!(!pairable(-2.0, -1.0));
    assert!(!pairable(5.0, 0.0));
    assert!(!pairable(5.0, 8.0));
    assert_eq!(PAIRED, 4);
}

#[test]
fn a_lookalike_passes_and_leaves_a_gap_within_1_5_g_plus_a_quarter_noise_level() {
    // Best's gap above noise 1, noise level 1: the limit is 1.75.
    assert!(lookalike(30.0, 1.7499, 1.0, 1.0));
    assert!(lookalike(30.0, 1.75, 1.0, 1.0));
    assert!(!lookalike(30.0, 1.7501, 1.0, 1.0));
    // The noise allowance scales with J_n, the factor with G.
    assert!(lookalike(40.0, 3.49, 2.0, 2.0));
    assert!(!lookalike(40.0, 3.51, 2.0, 2.0));
    assert!(lookalike(40.0, 3.24, 2.0, 1.0));
    assert!(!lookalike(40.0, 3.26, 2.0, 1.0));
    // It must pass the acceptance share itself.
    assert!(!lookalike(29.9, 0.5, 1.0, 1.0));
}

#[test]
fn an_alternative_set_replaces_the_first_below_two_thirds_of_its_gap() {
    assert!(!replaces(1.0, 1.5), "1.5 × 1.0 is not below 1.5");
    assert!(replaces(1.0, 1.5001));
    assert!(replaces(0.9, 1.5));
    assert!(!replaces(1.1, 1.5));
}

#[test]
fn cross_validation_disagrees_past_25_points_from_30_percent_in_sample() {
    assert!(disagrees(55.0, 29.9));
    assert!(
        !disagrees(55.0, 30.0),
        "25 points exactly is no disagreement"
    );
    // Below the acceptance share in sample, nothing to disagree about.
    assert!(!disagrees(29.9, 0.0));
    assert!(disagrees(30.0, 4.9));
}

#[test]
fn a_single_is_screened_below_30_percent_less_the_10_point_margin() {
    assert!(screened(19.9));
    assert!(!screened(20.0));
    assert!(!screened(20.1));
    assert!(screened(-5.0));
}

#[test]
fn a_greedy_step_is_screened_by_restricted_fits_only_ten_points_below_the_screen() {
    // The full fits' screen is below 20 %; the restricted fits', 10 % (the
    // racing log's full fits removed at most 1.5 points more than them).
    assert!(screened_restricted(9.9));
    assert!(!screened_restricted(10.0));
    assert!(!screened_restricted(15.0));
    assert!(screened(15.0));
    // Whatever the restricted fits screen, the full fits would too, with
    // the margin to spare.
    for x in [-5.0, 0.0, 5.0, 9.99] {
        assert!(screened_restricted(x) && screened(x + RESTRICTED_MARGIN - 1e-9));
    }
}

#[test]
fn a_screened_single_is_cross_validated_where_the_search_could_read_it() {
    // Best cross-validated 2.0; best whose axles are a tyre 2.5; J_n 1.
    assert!(reaches(2.0, false, 2.0, 2.5, 1.0));
    assert!(!reaches(2.01, false, 2.0, 2.5, 1.0));
    // A usable one within 0.1 J_n of the best usable.
    assert!(reaches(2.59, true, 2.0, 2.5, 1.0));
    assert!(!reaches(2.61, true, 2.0, 2.5, 1.0));
}

#[test]
fn candidates_rank_best_first_and_ties_keep_their_order() {
    assert_eq!(best_first(&[3.0, 1.0, 2.0, 1.0]), [1, 3, 2, 0]);
    assert_eq!(best_first(&[]), Vec::<usize>::new());
}

fn cand(heldout: f64, parameters: usize, idle: bool, degenerate: bool) -> Candidate {
    Candidate {
        heldout,
        parameters,
        idle,
        degenerate,
        pressed: false,
        inert: false,
    }
}

fn pressed(c: Candidate) -> Candidate {
    Candidate { pressed: true, ..c }
}

#[test]
fn a_best_pressed_on_its_search_bound_gives_way_to_a_lookalike_inside_its_ranges() {
    // Gaps above noise (J_n = 1): √(2.6² − 1) = 2.400, √(2.72² − 1) =
    // 2.530; the window 1.5·2.400 + 0.25 = 3.850, J = √(3.85² + 1) = 3.978.
    let ranked = [
        pressed(cand(2.6, 1, false, false)),
        cand(2.72, 2, false, false),
    ];
    assert_eq!(pick(&ranked, 1.0), Some(1));
    assert_eq!(passed_over(&ranked, 1.0), Some(0));
    // Just inside the window, and just outside it: then the pressed best.
    let at = |j: f64| {
        [
            pressed(cand(2.6, 1, false, false)),
            cand(j, 2, false, false),
        ]
    };
    assert_eq!(pick(&at(3.97), 1.0), Some(1));
    assert_eq!(pick(&at(3.99), 1.0), Some(0));
    assert_eq!(passed_over(&at(3.99), 1.0), None);
    // A look-alike pressed too: the best.
    let ranked = [
        pressed(cand(2.6, 1, false, false)),
        pressed(cand(2.7, 2, false, false)),
    ];
    assert_eq!(pick(&ranked, 1.0), Some(0));
    // Not pressed, the best is taken over a look-alike as usual.
    let ranked = [cand(2.6, 1, false, false), cand(2.72, 2, false, false)];
    assert_eq!(pick(&ranked, 1.0), Some(0));
    // The look-alike read first leaves a parameter idle: the simplest
    // within the parsimony window of it, the pressed one left out.
    let ranked = [
        pressed(cand(2.6, 1, false, false)),
        cand(2.7, 3, true, false),
        pressed(cand(2.72, 0, false, false)),
        cand(2.75, 2, false, false),
    ];
    assert_eq!(pick(&ranked, 1.0), Some(3));
    // No tyre: never read, pressed or not.
    let ranked = [
        pressed(cand(2.6, 1, false, false)),
        cand(2.7, 1, false, true),
    ];
    assert_eq!(pick(&ranked, 1.0), Some(0));
}

#[test]
fn the_best_is_taken_unless_it_leaves_a_parameter_idle() {
    let ranked = [cand(1.0, 2, false, false), cand(1.01, 1, false, false)];
    assert_eq!(pick(&ranked, 1.0), Some(0));
    // Idle: the fewest parameters within 0.1 noise levels of it.
    let ranked = [
        cand(1.0, 3, true, false),
        cand(1.05, 2, false, false),
        cand(1.0999, 1, false, false),
        cand(1.1001, 0, false, false),
    ];
    assert_eq!(pick(&ranked, 1.0), Some(2));
    // The window scales with J_n.
    assert_eq!(pick(&ranked, 2.0), Some(3));
    // As few parameters: the first of them.
    let ranked = [
        cand(1.0, 2, true, false),
        cand(1.02, 1, false, false),
        cand(1.03, 1, false, false),
    ];
    assert_eq!(pick(&ranked, 1.0), Some(1));
    // None simpler within the window: the idle best itself.
    let ranked = [cand(1.0, 2, true, false), cand(1.2, 1, false, false)];
    assert_eq!(pick(&ranked, 1.0), Some(0));
}

#[test]
fn a_best_passed_over_for_a_simpler_one_is_named_and_only_then() {
    // The delays campaign: a steer path (2 parameters, its lag idle) at
    // J 1.060, a sensor delay (1) at 1.073; J_n 0.941, the window 1.154.
    let ranked = [cand(1.060, 2, true, false), cand(1.073, 1, false, false)];
    assert_eq!(pick(&ranked, 0.941), Some(1));
    assert_eq!(simpler_than(&ranked, 0.941), Some(0));
    // Just outside the window the idle best is taken: nothing passed over.
    let ranked = [cand(1.060, 2, true, false), cand(1.155, 1, false, false)];
    assert_eq!(pick(&ranked, 0.941), Some(0));
    assert_eq!(simpler_than(&ranked, 0.941), None);
    // A best not idle is taken over a simpler one within the window.
    let ranked = [cand(1.060, 2, false, false), cand(1.073, 1, false, false)];
    assert_eq!(simpler_than(&ranked, 0.941), None);
    // Idle, but none simpler within the window: as many parameters.
    let ranked = [cand(1.060, 2, true, false), cand(1.073, 2, false, false)];
    assert_eq!(simpler_than(&ranked, 0.941), None);
    // The best whose axles are a tyre is the one passed over, not a
    // better one whose axles are none.
    let ranked = [
        cand(0.9, 1, false, true),
        cand(1.060, 2, true, false),
        cand(1.073, 1, false, false),
    ];
    assert_eq!(simpler_than(&ranked, 0.941), Some(1));
    assert_eq!(simpler_or_pressed(&ranked), (Some(1), None));
}

#[test]
fn a_best_passed_over_for_its_search_bound_is_not_said_to_be_passed_over_for_parsimony() {
    // Pressed and idle too: the look-alike inside its ranges is taken for
    // the bound (passed_over), not for parsimony.
    let ranked = [
        pressed(cand(2.6, 1, true, false)),
        cand(2.72, 2, false, false),
    ];
    assert_eq!(simpler_or_pressed(&ranked), (None, Some(0)));
    // The look-alike read first leaves a parameter idle and a simpler one
    // within the window is taken: that look-alike is the one passed over
    // for parsimony, the pressed best for its bound.
    let ranked = [
        pressed(cand(2.6, 1, false, false)),
        cand(2.7, 3, true, false),
        cand(2.75, 2, false, false),
    ];
    assert_eq!(pick(&ranked, 1.0), Some(2));
    assert_eq!(simpler_or_pressed(&ranked), (Some(1), Some(0)));
    assert_eq!(simpler_than(&[], 1.0), None);
}

/// What [`simpler_than`] and [`passed_over`] find at J_n = 1.
fn simpler_or_pressed(ranked: &[Candidate]) -> (Option<usize>, Option<usize>) {
    (simpler_than(ranked, 1.0), passed_over(ranked, 1.0))
}

#[test]
fn candidates_whose_axles_are_no_tyre_are_never_picked() {
    let ranked = [
        cand(0.5, 1, false, true),
        cand(1.0, 2, false, false),
        cand(1.1, 1, false, false),
    ];
    assert_eq!(pick(&ranked, 1.0), Some(1));
    // Nor taken as the simpler one of an idle best.
    let ranked = [
        cand(1.0, 3, true, false),
        cand(1.01, 1, false, true),
        cand(1.02, 2, false, false),
    ];
    assert_eq!(pick(&ranked, 1.0), Some(2));
    // The window is measured from the best usable one.
    let ranked = [
        cand(0.5, 1, false, true),
        cand(1.0, 3, true, false),
        cand(1.09, 2, false, false),
    ];
    assert_eq!(pick(&ranked, 1.0), Some(2));
    assert_eq!(pick(&[cand(1.0, 1, false, true)], 1.0), None);
    assert_eq!(pick(&[], 1.0), None);
}

#[test]
fn the_verdict_case_follows_acceptance_then_the_gap_then_the_base() {
    use VerdictKind::*;
    assert_eq!(case(true, true, false), Explained);
    assert_eq!(case(true, true, true), Explained);
    assert_eq!(case(false, false, false), NoSignificantGap);
    assert_eq!(case(false, false, true), NoSignificantGap);
    assert_eq!(case(false, true, true), NotIdentifiable);
    assert_eq!(case(false, true, false), OutsideLibrary);
}

fn rigid() -> Vec<NoTyre> {
    vec![NoTyre::Limit {
        parameter: "rear cornering coefficient",
        limit: AxleLimit::Rigid,
    }]
}

#[test]
fn a_refused_candidate_names_every_rule_it_fails() {
    let bias = vec![EffectKind::SensorBias];
    // The sedan's sensor bias: 53.5 % held out, a lower BIC, axles no
    // tyre — refused for the axles only, never for the share.
    let r = refused((bias.clone(), 53.5, -500.0), rigid(), None, None);
    assert_eq!(r.why, [Refusal::AxlesNoTyre { no_tyre: rigid() }]);
    assert_eq!((r.effects, r.reduction_percent), (bias.clone(), 53.5));
    // At the acceptance boundary.
    let below = refused((bias.clone(), 29.9, -5.0), Vec::new(), None, None);
    assert_eq!(
        below.why,
        [Refusal::BelowAcceptance {
            threshold_percent: 30.0
        }]
    );
    assert!(refused((bias.clone(), 30.0, 0.0), Vec::new(), None, None)
        .why
        .iter()
        .all(|w| !matches!(w, Refusal::BelowAcceptance { .. })));
    // Every rule it fails, in order: axles, share, BIC.
    let all = refused((bias.clone(), 12.0, 3.0), rigid(), None, None);
    assert_eq!(
        all.why,
        [
            Refusal::AxlesNoTyre { no_tyre: rigid() },
            Refusal::BelowAcceptance {
                threshold_percent: 30.0
            },
            Refusal::BicNotLower { delta_bic: 3.0 },
        ]
    );
}

#[test]
fn a_candidate_that_passes_is_refused_through_where_the_search_went_instead() {
    let simpler = refused(
        (vec![EffectKind::SensorDelay], 28.0, -9.0),
        Vec::new(),
        None,
        None,
    );
    // It gave way to a simpler one (it leaves a parameter idle).
    let idle = refused(
        (vec![EffectKind::SteerPath], 31.0, -10.0),
        Vec::new(),
        Some(GaveWay::Idle),
        Some(simpler.clone()),
    );
    assert_eq!(
        idle.why,
        [Refusal::LeavesParameterIdle {
            simpler: Box::new(simpler.clone())
        }]
    );
    // It started the search, which ended on a set that failed.
    let ended = refused(
        (vec![EffectKind::SteerPath], 31.0, -10.0),
        Vec::new(),
        None,
        Some(simpler.clone()),
    );
    assert!(matches!(&ended.why[..], [Refusal::SearchEndedOn { .. }]));
    // It gave way to a look-alike inside its ranges (it is pressed on a
    // search bound).
    let pressed = refused(
        (vec![EffectKind::SensorDelay], 54.3, -30.0),
        Vec::new(),
        Some(GaveWay::Pressed),
        Some(simpler.clone()),
    );
    assert_eq!(
        pressed.why,
        [Refusal::PressedOnSearchBound {
            inside: Box::new(simpler.clone())
        }]
    );
    // Where it fails a rule itself, that is the reason, not the others.
    let own = refused(
        (vec![EffectKind::SteerPath], 20.0, -10.0),
        Vec::new(),
        Some(GaveWay::Idle),
        Some(simpler),
    );
    assert_eq!(own.why.len(), 1);
    assert!(matches!(own.why[0], Refusal::BelowAcceptance { .. }));
}

#[test]
fn a_fold_is_far_beyond_three_standard_errors_of_the_all_run_fit() {
    let full = [1.0, 0.4, 9.0];
    let se = [0.1, 0.02, f64::NAN];
    let near = vec![1.29, 0.41, 50.0];
    assert_eq!(
        far_folds(&full, &se, std::slice::from_ref(&near), 0..3),
        None
    );
    // 3.1 standard errors on the first, 10 on the second: the second is
    // named, with the one fold that lands far.
    let off = vec![1.31, 0.2, 9.0];
    let (i, v, d, n) = far_folds(&full, &se, &[near.clone(), off.clone()], 0..3).unwrap();
    assert_eq!((i, v, n), (1, 0.2, 1));
    assert!((d - 10.0).abs() < 1e-9, "{d}");
    // Parameters outside the range read (the axles) are not looked at.
    assert_eq!(
        far_folds(&full, &se, &[near.clone(), off.clone()], 2..3),
        None
    );
    // Two folds beyond on different parameters count as two.
    let other = vec![1.5, 0.4, 9.0];
    assert_eq!(
        far_folds(&full, &se, &[off, near, other], 0..3).map(|f| f.3),
        Some(2)
    );
}

/// Campaign yi of round 19 (sensor delay 0.05 s, yaw inertia 1.5× low):
/// the greedy search grew steer_path+yaw_inertia (held-out 1.063, 3
/// parameters, the lag idle), its twin sensor_delay+yaw_inertia reads
/// 1.080 with 2: within 0.1 noise levels (0.941), the rule takes the
/// twin, as the pairs fallback took it in campaign yi2.
#[test]
fn the_verdicts_set_gives_way_to_a_simpler_twin_within_the_parsimony_window() {
    let set = cand(1.063, 3, true, false);
    let twin = cand(1.080, 2, false, false);
    assert_eq!(simpler_twin(set, &[twin], 0.941), Some(0));
    // The same numbers ranked as the pairs fallback ranks them: the same.
    assert_eq!(pick(&[set, twin], 0.941), Some(1));
    // Just past the window (1.063 + 0.0941 = 1.1571): the set stays.
    assert_eq!(
        simpler_twin(set, &[cand(1.158, 2, false, false)], 0.941),
        None
    );
    assert_eq!(
        simpler_twin(set, &[cand(1.157, 2, false, false)], 0.941),
        Some(0)
    );
    // A set that leaves nothing idle stays, even beside a better twin:
    // the twin is a look-alike, not the rule's to take.
    let busy = cand(1.063, 3, false, false);
    assert_eq!(
        simpler_twin(busy, &[cand(1.0, 2, false, false)], 0.941),
        None
    );
    // A twin with as many parameters is no simpler.
    assert_eq!(
        simpler_twin(set, &[cand(1.080, 3, false, false)], 0.941),
        None
    );
    // A twin whose axles are no tyre is never taken.
    assert_eq!(
        simpler_twin(set, &[cand(1.080, 2, false, true)], 0.941),
        None
    );
    // Of several, the one with the fewest parameters (an index into the
    // twins, whatever their order).
    let twins = [cand(1.10, 2, false, false), cand(1.09, 1, false, false)];
    assert_eq!(simpler_twin(set, &twins, 0.941), Some(1));
    // An idle twin better than the set: the set is not passed over by the
    // rule (the twin is), so nothing changes.
    let idle_better = cand(1.0, 3, true, false);
    assert_eq!(simpler_twin(busy, &[idle_better], 0.941), None);
}

#[test]
fn a_better_single_refused_for_its_axles_leads_a_search_of_its_own() {
    // Held out best first: the refused one ahead of the pick starts too.
    let ranked = [
        cand(4.5, 5, false, true),
        cand(5.9, 3, false, false),
        cand(6.0, 3, false, true),
    ];
    assert_eq!(pick(&ranked, 0.9), Some(1));
    assert_eq!(degenerate_lead(&ranked, 1), Some(0));
    // One behind the pick does not: the pick already does better.
    let behind = [cand(4.5, 5, false, false), cand(5.9, 3, false, true)];
    assert_eq!(degenerate_lead(&behind, 0), None);
    // The first refused of several ahead.
    let two = [
        cand(4.0, 5, false, false),
        cand(4.2, 5, false, true),
        cand(4.4, 5, false, true),
        cand(5.0, 3, false, false),
    ];
    assert_eq!(degenerate_lead(&two, 3), Some(1));
}

fn reading(value: f64, off: f64, std_error: f64) -> OffReading {
    OffReading {
        value,
        off,
        std_error,
        range: 0.3,
    }
}

/// Round 43's truck-prior campaign: sensor_delay.delay = 0.0000 s on its
/// physical limit (its off value, no standard error) beside
/// sensor_bias's three offsets, each many standard errors from off.
#[test]
fn an_effect_whose_every_parameter_sits_off_contributes_nothing() {
    let delay = [reading(0.0, 0.0, f64::NAN)];
    let bias = vec![
        reading(0.009027, 0.0, 0.000925),
        reading(0.2336, 0.0, 0.0261),
        reading(0.005235, 0.0, 0.000776),
    ];
    assert!(contributes_nothing(&delay));
    assert!(!contributes_nothing(&bias));
    assert_eq!(inert_effects(&[bias.clone(), delay.to_vec()]), [1]);
    // Within one standard error of off, not beyond it.
    assert!(contributes_nothing(&[reading(0.0009, 0.0, 0.001)]));
    assert!(!contributes_nothing(&[reading(0.0011, 0.0, 0.001)]));
    // Off the bound without a standard error: not read as off.
    assert!(!contributes_nothing(&[reading(0.0011, 0.0, f64::NAN)]));
    // Two parameters each within a standard error of off, neither
    // exactly (a steer path's delay and lag that trade): not read as off.
    assert!(!contributes_nothing(&[
        reading(0.0496, 0.0, 0.0621),
        reading(6.4e-5, 0.0, 0.0622)
    ]));
    assert!(contributes_nothing(&[
        reading(0.0496, 0.0, 0.0621),
        reading(0.0, 0.0, f64::NAN)
    ]));
    // One parameter off and one on: the effect contributes.
    assert!(!contributes_nothing(&[
        reading(0.0, 0.0, f64::NAN),
        reading(0.05, 0.0, 0.01)
    ]));
    // A parameter without an off value is never off; no parameter, none.
    assert!(!contributes_nothing(&[reading(0.0, f64::NAN, 1.0)]));
    assert!(!contributes_nothing(&[]));
    // An off value other than zero (a scale's 1).
    assert!(contributes_nothing(&[reading(1.02, 1.0, 0.03)]));
}

#[test]
fn a_set_with_an_inert_effect_is_never_taken_and_the_next_is() {
    let inert = |c: Candidate| Candidate { inert: true, ..c };
    // The pair (2.789) with its delay at off, then the bias alone (4.717).
    let ranked = [
        inert(cand(2.789, 7, true, false)),
        cand(4.717, 6, false, false),
    ];
    assert_eq!(pick(&ranked, 0.92), Some(1));
    // Nothing else: nothing taken.
    assert_eq!(pick(&ranked[..1], 0.92), None);
    // Without the flag the pair is taken: the flag alone moves it.
    let plain = [cand(2.789, 7, false, false), cand(4.717, 6, false, false)];
    assert_eq!(pick(&plain, 0.92), Some(0));
}
