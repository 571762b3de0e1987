//! The words of what a verdict was chosen over for parsimony, on the
//! numbers of `synth --effects sensor_delay --seed 1` narrowed to the two
//! delays: the rule, the look-alike and its reduction, the window.

use super::evidence;
use super::tests::fitted;
use crate::diagnose::effects::{Bound, EffectKind};
use crate::diagnose::report::{Evidence, ParameterValue, Parsimony};

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
