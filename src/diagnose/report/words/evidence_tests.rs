//! The words of what a verdict was chosen over for parsimony, on the
//! numbers of `synth --effects sensor_delay --seed 1` narrowed to the two
//! delays: the rule, the look-alike and its reduction, the window.

use super::evidence;
use super::tests::fitted;
use crate::diagnose::effects::{Bound, EffectKind};
use crate::diagnose::report::{Evidence, ParameterValue, Parsimony, Searched};

/// The steer path's lag on its physical limit, as the ranking gives it.
fn lag_on_limit() -> ParameterValue {
    fitted("steer_path.lag", "s", 0.0, Some(Bound::Physical))
}

fn chosen() -> Parsimony {
    Parsimony {
        effects: vec![EffectKind::SteerPath],
        reduction_percent: 86.1,
        heldout_error: 1.060,
        free_parameters: 2,
        idle: vec![lag_on_limit()],
        taken: vec![EffectKind::SensorDelay],
        taken_reduction_percent: 85.3,
        taken_heldout_error: 1.073,
        taken_free_parameters: 1,
        noise_level: 0.941,
        window_noise_levels: 0.1,
    }
}

#[test]
fn a_verdict_chosen_for_parsimony_names_the_lookalike_its_reduction_and_the_rule() {
    assert_eq!(
        evidence(&Evidence::ChosenForParsimony(chosen())),
        "chosen for parsimony over a look-alike that removes more: steer_path removes 86.1 % (held-out error 1.060) with 2 parameters, but leaves steer_path.lag = 0.0000 s (at its physical limit: any smaller value would be negative) idle (off, or not told from off); sensor_delay removes 85.3 % with 1 parameter, within 0.1 noise levels of it (held-out error 1.073 ≤ 1.060 + 0.1 × 0.941 = 1.154), and within that window the candidate with the fewest parameters is taken, an idle one counted (a candidate that matches only with a parameter idle is the simpler one's look-alike with a parameter more): a tie the runs do not break, settled by the rule, not evidence against the other"
    );
}

#[test]
fn a_set_taken_for_parsimony_is_named_with_its_counts_and_a_parameter_left_unnamed_is_said() {
    let set = Parsimony {
        effects: vec![EffectKind::SteerPath, EffectKind::RelaxationLength],
        taken: vec![EffectKind::SensorDelay, EffectKind::RelaxationLength],
        free_parameters: 3,
        taken_free_parameters: 2,
        idle: Vec::new(),
        ..chosen()
    };
    let s = evidence(&Evidence::ChosenForParsimony(set));
    assert!(
        s.contains(": steer_path+relaxation_length removes 86.1 % (held-out error 1.060) with 3 parameters, but leaves a parameter idle"),
        "{s}"
    );
    assert!(
        s.contains("; sensor_delay+relaxation_length removes 85.3 % with 2 parameters, within"),
        "{s}"
    );
}

/// A verdict reached by the pairs fallback (`synth --effects sensor_delay
/// --seed 1`, its yaw inertia 1.5× the car's): the start it stopped on,
/// the pair and the singles it came from, the start passed over.
#[test]
fn a_verdict_of_the_pairs_fallback_says_where_the_greedy_search_stopped() {
    use crate::diagnose::report::PairsFallback;
    use EffectKind::{RelaxationLength as R, SensorDelay as D, YawInertia as I};
    let mut f = PairsFallback {
        start: R,
        start_reduction_percent: 28.6,
        ended: vec![R],
        ended_reduction_percent: 28.6,
        threshold_percent: 30.0,
        paired_from: vec![R, D, I],
        pair: vec![D, I],
        pair_reduction_percent: 83.8,
        passed_over: Some(R),
    };
    let s = evidence(&Evidence::PairsFallback(f.clone()));
    assert!(s.starts_with("reached by the pairs fallback, not the greedy search: the greedy search from the best single on held-out runs, relaxation_length (28.6 %), stopped with no verdict (relaxation_length removes 28.6 % alone, and no effect added to it removed 30 % of what it leaves; a verdict must remove 30 % and lower the BIC); the pair sensor_delay+yaw_inertia (83.8 %) came from the pairs of the best singles in sample (relaxation_length, sensor_delay, yaw_inertia), passing over relaxation_length, the best single on held-out runs"), "{s}");
    // Ended on a set refused as a whole; the pair keeps the start.
    f.ended = vec![R, I];
    f.ended_reduction_percent = 27.0;
    f.pair = vec![R, D];
    f.passed_over = None;
    let s = evidence(&Evidence::PairsFallback(f));
    assert!(
        s.contains(
            "(it ended on relaxation_length+yaw_inertia, which removes 27.0 %, refused; a verdict"
        ),
        "{s}"
    );
    assert!(!s.contains("passing over"), "{s}");
}

/// A ratio (unit `-`) on its search bound in the look-alike line is said
/// without a unit (fresh-eyes round 18 read
/// "road_friction.friction_scale = 1.5000 -").
#[test]
fn a_ratio_pressed_on_its_bound_is_said_without_a_unit() {
    let ratio = Evidence::LookalikePressed {
        effects: vec![EffectKind::RoadFriction],
        reduction_percent: 40.0,
        pressed: vec![fitted(
            "road_friction.friction_scale",
            "-",
            1.5,
            Some(Bound::Search),
        )],
        pressed_ranges: Vec::new(),
        verdict_inside: Vec::new(),
    };
    assert!(evidence(&ratio).contains("only with road_friction.friction_scale = 1.5000 at the end"));
}

/// Putnam (fresh-eyes round 27B): a sensor delay pressed on its 0.3 s
/// end was passed over for a steer path whose delay and lag add up to
/// 0.298 s. The line gives both ranges and the sum, so the verdict's own
/// numbers do not contradict why the look-alike was refused.
#[test]
fn a_lookalike_pressed_on_a_size_the_verdict_reaches_inside_its_ranges_says_both_ranges() {
    let searched = |name: &str, v: f64, high: f64| Searched {
        name: name.to_string(),
        unit: "s",
        value: v,
        range: (0.0, high),
    };
    let e = Evidence::LookalikePressed {
        effects: vec![EffectKind::SensorDelay],
        reduction_percent: 52.6,
        pressed: vec![fitted("sensor_delay.delay", "s", 0.3, Some(Bound::Search))],
        pressed_ranges: vec![searched("sensor_delay.delay", 0.3, 0.3)],
        verdict_inside: vec![
            searched("steer_path.delay", 0.1702, 0.5),
            searched("steer_path.lag", 0.128, 0.5),
        ],
    };
    let s = evidence(&e);
    assert!(
        s.contains(
            "sensor_delay.delay = 0.3000 s at the end of the range searched (0.0000–0.3000 s);"
        ),
        "{s}"
    );
    assert!(
        s.ends_with("explains the gap from inside its ranges: steer_path.delay = 0.1702 s (range 0.0000–0.5000 s), steer_path.lag = 0.1280 s (range 0.0000–0.5000 s); their sum, 0.2982 s, is near the end of the look-alike's range (0.3000 s) but inside what the verdict's reach together (1.0000 s): the ranges say what each effect plausibly is, and the size that presses the look-alike is plausible for the verdict's"),
        "{s}"
    );
}
