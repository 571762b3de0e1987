//! A parameter and a ranked candidate's warnings in words: held, unseen,
//! on a bound, a standard error the folds say understates, a set worse
//! than one it contains.

use super::*;
use crate::diagnose::effects::{EffectKind, Group};
use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::ParameterValue;
use crate::diagnose::report::Part;
use crate::diagnose::report::RankWarning;

#[test]
fn a_parameter_no_channel_responds_to_reads_as_held_not_as_undetermined() {
    let [_, ay, _] = EffectKind::SensorBias.parameters() else {
        panic!("a sensor bias has three offsets");
    };
    let p = ParameterValue::of(Group::Effect(EffectKind::SensorBias), ay, 0.0, f64::NAN);
    assert_eq!(
        parameter(&p),
        "sensor_bias.ay = 0.0000 m/s² (no standard error: not determined by the runs)"
    );
    assert_eq!(
        parameter(&p.unseen()),
        "sensor_bias.ay = 0.0000 m/s² (held at its off value: no measured channel responds to it)"
    );
}

/// The roll damping's farthest fold 10.5 standard errors of white
/// residuals from the all-run fit, the report's robust one `reported`.
fn far_fold(reported: f64) -> RankWarning {
    RankWarning::FoldsFar {
        parameter: "roll.damping".into(),
        value: 0.4095,
        std_error: 0.02,
        reported_std_error: reported,
        fold_value: 0.2,
        distance: 10.47,
        far: 2,
        folds: 5,
    }
}

#[test]
fn a_fold_far_from_the_full_fit_names_the_parameter_and_how_far() {
    let w = far_fold(0.05);
    assert_eq!(
        rank_warning(&w),
        "2 of 5 fold refits land far from the fit on all runs (roll.damping 0.2000 against 0.4095: 10.5 times its standard error of white residuals, ± 0.0200; 4.2 times the ± 0.0500 given, robust to correlated residuals): its held-out score measures a fit on fewer runs as much as the effect"
    );
    // No robust standard error: only the one the rule reads, no NaN.
    let w = far_fold(f64::NAN);
    assert_eq!(
        rank_warning(&w),
        "2 of 5 fold refits land far from the fit on all runs (roll.damping 0.2000 against 0.4095: 10.5 times its standard error of white residuals, ± 0.0200): its held-out score measures a fit on fewer runs as much as the effect"
    );
}

#[test]
fn a_parameter_held_because_the_runs_do_not_determine_it_says_where_and_why() {
    let [_, lag] = EffectKind::SteerPath.parameters() else {
        panic!("a steer path has a delay and a lag");
    };
    let held =
        ParameterValue::of(Group::Effect(EffectKind::SteerPath), lag, 0.0, f64::NAN).held(69.8);
    assert!(!held.determined && held.held == Some(69.8));
    assert_eq!(
        parameter(&held),
        "steer_path.lag = 0.0000 s (held at its off value: the runs do not determine it, fitted free its standard error 69.8 s exceeds its whole range)"
    );
    // The roll dynamics' off value is the campaign's.
    let frequency = &crate::diagnose::effects::RollDynamics::PARAMETERS[0];
    let roll = ParameterValue::of(Group::Roll, frequency, 3.0, f64::NAN).held(5.26);
    assert_eq!(
        parameter(&roll),
        "roll.frequency = 3.0000 Hz (held at the campaign's value: the runs do not determine it, fitted free its standard error 5.26 Hz exceeds its whole range)"
    );
    // A dimensionless parameter carries no unit, not a stray `-`.
    let scale = &EffectKind::YawInertia.parameters()[0];
    let fitted = ParameterValue::of(
        Group::Effect(EffectKind::YawInertia),
        scale,
        1.3038,
        3.27e-3,
    );
    assert_eq!(parameter(&fitted), "yaw_inertia.scale = 1.3038 ± 0.00327");
    // Not `1.03e0`: a standard error of 0.01 or more in plain digits.
    let frequency = &crate::diagnose::effects::RollDynamics::PARAMETERS[0];
    let roll = ParameterValue::of(Group::Roll, frequency, 3.0, 1.03);
    assert_eq!(parameter(&roll), "roll.frequency = 3.0000 ± 1.03 Hz");
}

#[test]
fn a_standard_error_the_fold_jackknife_exceeds_threefold_is_said_to_understate() {
    let [front, _] = EffectKind::RollSteer.parameters() else {
        panic!("roll steer has a front and a rear");
    };
    let v = ParameterValue::of(
        Group::Effect(EffectKind::RollSteer),
        front,
        -0.4112,
        4.65e-3,
    );
    // Five folds at ±0.02 about -0.41: the jackknife √(4/5·Σd²) = 0.0358.
    let folds = [-0.39, -0.43, -0.41, -0.39, -0.43];
    let j = crate::diagnose::report::jackknife(&folds).unwrap();
    assert!((j - (0.8f64 * 4.0 * 0.0004).sqrt()).abs() < 1e-12, "{j}");
    let flagged = v.clone().with_folds(&folds, Some((1.0, 4.0)));
    assert!(flagged.understated());
    assert_eq!(
        parameter(&flagged),
        "roll_steer.front = -0.4112 ± 0.00465 rad/rad (the fold refits scatter ± 0.0358, 8× it: the runs disagree beyond their noise, which the standard error does not cover)"
    );
    // Folds within three standard errors, or too few to judge, say nothing.
    let close = v
        .clone()
        .with_folds(&[-0.405, -0.415, -0.41, -0.405, -0.415], Some((1.0, 4.0)));
    assert!(!close.understated());
    assert_eq!(
        parameter(&close),
        "roll_steer.front = -0.4112 ± 0.00465 rad/rad"
    );
    assert_eq!(
        v.clone()
            .with_folds(&[-0.3, -0.5], Some((1.0, 4.0)))
            .fold_std_error,
        None
    );
    // A parameter on a bound has no standard error to understate.
    let on_bound = ParameterValue::of(
        Group::Effect(EffectKind::RollSteer),
        front,
        front.bounds.0,
        4.65e-3,
    )
    .with_folds(&folds, None);
    assert!(!on_bound.understated());
}

#[test]
fn folds_the_runs_noise_alone_moves_far_are_not_said_to_understate() {
    let [front, _] = EffectKind::RollSteer.parameters() else {
        panic!("roll steer has a front and a rear");
    };
    let v = ParameterValue::of(
        Group::Effect(EffectKind::RollSteer),
        front,
        -0.4112,
        4.65e-3,
    );
    let folds = [-0.39, -0.43, -0.41, -0.39, -0.43];
    // One run carries most of what determines it: leaving it out moves
    // the fold 5 standard errors by noise alone; 8× the standard error is
    // under 2× that.
    let heavy = v.clone().with_folds(&folds, Some((5.0, 4.0)));
    assert!((heavy.fold_noise_std_error.unwrap() - 5.0 * 4.65e-3).abs() < 1e-15);
    assert!(!heavy.understated());
    assert_eq!(
        parameter(&heavy),
        "roll_steer.front = -0.4112 ± 0.00465 rad/rad"
    );
    // Beyond three times that yardstick it is said, against the yardstick.
    let far = v.clone().with_folds(&folds, Some((2.0, 4.0)));
    assert!(far.understated());
    // 3.1× a yardstick of 2.5 standard errors: past 3× where the folds
    // share it (four degrees of freedom), within what chance gives where
    // one fold carries the rest (one degree of freedom: 3.3× at 99.9 %).
    assert!(v.clone().with_folds(&folds, Some((2.5, 4.0))).understated());
    let one = v.clone().with_folds(&folds, Some((2.5, 1.0)));
    assert!(!one.understated());
    assert!(
        (one.fold_limit() - 3.34).abs() < 0.05,
        "{}",
        one.fold_limit()
    );
    assert_eq!(
        parameter(&far),
        "roll_steer.front = -0.4112 ± 0.00465 rad/rad (the fold refits scatter ± 0.0358, 4× the ± 0.00930 the runs' noise alone moves them by, leaving out a run that carries much of what determines it: the runs disagree beyond their noise, which the standard error does not cover)"
    );
}

#[test]
fn a_set_worse_in_sample_than_one_it_contains_says_so() {
    let w = RankWarning::WorseThanSubset {
        subset: "sensor_delay".into(),
        subset_error: 1.234,
        error: 1.5,
    };
    assert_eq!(
        rank_warning(&w),
        "it fits the runs worse than sensor_delay, which it contains (in-sample error 1.500 against 1.234): its fit stopped short of that optimum or holds a parameter sensor_delay fits, so its scores understate the set"
    );
}

#[test]
fn a_steady_offset_is_one_sign_over_the_runs_a_noise_floor_and_most_of_the_mean_square() {
    use crate::diagnose::report::values::SteadyOffset;
    // The sensor-offset campaign's sideslip: −0.0041 rad in 8 of 8 runs,
    // floor 0.0019, RMS 0.0046.
    let biases = [
        -0.0040, -0.0043, -0.0039, -0.0042, -0.0041, -0.0040, -0.0042, -0.0041,
    ];
    let o = SteadyOffset::of(&biases, 0.0019, 0.0046).unwrap();
    assert_eq!((o.same_sign, o.runs), (8, 8));
    assert!((o.floors - 0.0041 / 0.0019).abs() < 1e-3, "{o:?}");
    // A gain error of runs that mostly turn one way: one sign, above a
    // floor, but a quarter of the mean square.
    assert_eq!(SteadyOffset::of(&biases, 0.0019, 0.0082), None);
    // Below a noise floor, or of mixed signs, or on two runs: none.
    assert_eq!(SteadyOffset::of(&biases, 0.005, 0.0046), None);
    let mixed = [-0.004, 0.004, -0.004, 0.004, -0.004];
    assert_eq!(SteadyOffset::of(&mixed, 0.001, 0.004), None);
    assert_eq!(SteadyOffset::of(&biases[..2], 0.0019, 0.0046), None);
}

#[test]
fn a_channel_within_noise_with_a_steady_offset_says_the_offset() {
    use crate::diagnose::report::values::SteadyOffset;
    let biases = [
        -0.0040, -0.0043, -0.0039, -0.0042, -0.0041, -0.0040, -0.0042, -0.0041,
    ];
    let f = GapFinding::Channel {
        channel: Channel::Beta,
        rms: 0.0046,
        noise_floor: 0.0019,
        significant_runs: 0,
        significant_in: Vec::new(),
        within_in: Vec::new(),
        runs: 8,
        wrong: vec![],
        right: vec![Part::All],
        off_in_right: Vec::new(),
        offset: SteadyOffset::of(&biases, 0.0019, 0.0046),
        combined: None,
    };
    assert_eq!(
        finding(&f),
        "beta: RMS 0.0046 rad (noise floor 0.0019); significant in 0 of 8 runs: within noise in every part, so no place where the base model is wrong; a steady offset: mean residual -0.0041 rad over the runs, of that sign in 8 of 8 runs (2.2 noise floors, 79 % of the mean square), a sensor offset or a bias of the model that the RMS does not single out"
    );
}

/// A channel wrong after the input and right before it, with a steady
/// offset of 4.7 floors: a sensor's zero offset would have made the
/// window before the input wrong too (its RMS at least the offset's), so
/// the offset is said as the model's, not "a sensor offset or a bias of
/// the model" beside "right in: before the input". One of 2.2 floors,
/// within the three floors the window's RMS may reach, stays either.
#[test]
fn an_offset_beyond_the_floors_right_before_the_input_is_the_model_s() {
    use crate::diagnose::report::parts::Window;
    use crate::diagnose::report::values::SteadyOffset;
    let f = |biases: &[f64], rms: f64| GapFinding::Channel {
        channel: Channel::YawRate,
        rms,
        noise_floor: 0.0017,
        significant_runs: 4,
        significant_in: Vec::new(),
        within_in: Vec::new(),
        runs: 4,
        wrong: vec![(Part::Window(Window::Later), 0.014)],
        right: vec![Part::Window(Window::BeforeInput)],
        off_in_right: Vec::new(),
        offset: SteadyOffset::of(biases, 0.0017, rms),
        combined: None,
    };
    let said = finding(&f(&[0.0081, 0.0079, 0.0083, 0.0081], 0.0114));
    assert!(
        said.contains("right in: before the input; a steady offset: mean residual +0.0081 rad/s over the runs, of that sign in 4 of 4 runs (4.8 noise floors, 50 % of the mean square), a bias of the model's response that the RMS does not single out, after the input only (before it the channel is right, where a sensor's zero offset would show too), not a sensor offset"),
        "{said}"
    );
    let small = finding(&f(&[0.0037, 0.0038, 0.0036, 0.0037], 0.0051));
    assert!(
        small.contains("a sensor offset or a bias of the model"),
        "{small}"
    );
}

#[test]
fn a_fit_that_enlarges_the_held_out_gap_says_larger_not_only_a_negative_share() {
    let w = RankWarning::Disagreement {
        insample_percent: 39.4,
        heldout_percent: -8.1,
    };
    assert_eq!(
        rank_warning(&w),
        "the fit on all runs removes 39 % of the gap but makes it 8 % larger on held-out runs: the effect does not generalise across runs, or the runs cannot pin its parameters"
    );
}

/// Where the model leaves a gap above noise, the larger of the asymptotic
/// standard error and the fold refits' spread is reported and said; where
/// it fits to the noise, or the spread is smaller, the asymptotic one.
#[test]
fn a_fit_that_leaves_a_gap_reports_its_fold_spread_where_larger() {
    use crate::diagnose::report::StdErrorBasis;
    let [x] = EffectKind::AccelerometerPosition.parameters() else {
        panic!("an accelerometer position has one parameter");
    };
    let v = ParameterValue::of(
        Group::Effect(EffectKind::AccelerometerPosition),
        x,
        0.8282,
        0.00438,
    );
    // Five folds at ±0.004 about 0.828: the jackknife √(4/5·Σd²) = 0.00716,
    // 1.6× the asymptotic error, below the 3× that says it understates.
    let folds = [0.824, 0.832, 0.828, 0.824, 0.832];
    let j = crate::diagnose::report::jackknife(&folds).unwrap();
    let with = v.clone().with_folds(&folds, Some((1.0, 4.0)));
    assert!(!with.understated());
    let inexact = with.clone().with_model_error(true);
    assert_eq!(inexact.std_error_basis, StdErrorBasis::FoldSpread);
    assert_eq!(
        (inexact.std_error, inexact.asymptotic_std_error),
        (j, 0.00438)
    );
    assert_eq!(
        parameter(&inexact),
        "accelerometer_position.x = 0.8282 ± 0.00716 m (the fold refits' spread: its held-out error stays above the noise level, and its asymptotic ± 0.00438 covers the noise alone)"
    );
    // Fitted to the noise: the asymptotic error, as before.
    let exact = with.with_model_error(false);
    assert_eq!(exact.std_error_basis, StdErrorBasis::Asymptotic);
    assert_eq!(
        parameter(&exact),
        "accelerometer_position.x = 0.8282 ± 0.00438 m"
    );
    // A spread below the asymptotic error changes nothing.
    let tight = v
        .with_folds(&[0.827, 0.829, 0.828, 0.827, 0.829], Some((1.0, 4.0)))
        .with_model_error(true);
    assert_eq!(tight.std_error_basis, StdErrorBasis::Asymptotic);
    assert_eq!(tight.std_error, 0.00438);
}

/// Round 47's campaign: one run's yaw rate and ay logged 0.15 s late, the
/// delay's fold refits at 0.0525–0.0535 s but the one leaving that run out
/// (0.0310 s). The runs disagree beyond their noise, and the words name the
/// fold and its run, with the others' range; where the effect removes
/// nothing significant, or the refits agree, they name none.
#[test]
fn the_fold_that_stands_apart_names_its_run() {
    let [delay] = EffectKind::SensorDelay.parameters() else {
        panic!("a sensor delay has one parameter");
    };
    let v = ParameterValue::of(
        Group::Effect(EffectKind::SensorDelay),
        delay,
        0.0529,
        0.00235,
    );
    let folds = [
        0.0530, 0.0525, 0.0535, 0.0310, 0.0528, 0.0533, 0.0531, 0.0527,
    ];
    let runs: Vec<Vec<String>> = (0..8).map(|i| vec![format!("run{i}.csv")]).collect();
    let p = v
        .clone()
        .with_folds(&folds, Some((1.0, 7.0)))
        .with_model_error(true)
        .with_fold_runs(&runs, &[true; 8]);
    assert!(p.understated());
    assert_eq!(p.folds_apart(), vec![3]);
    assert_eq!(p.fold_refits[3].left_out, vec!["run3.csv".to_string()]);
    let said = parameter(&p);
    assert!(
        said.contains("the runs disagree beyond their noise"),
        "{said}"
    );
    assert!(
        said.ends_with("; the fold leaving out run3.csv refits it to 0.0310 s, the other 7 folds to 0.0525–0.0535 s, beyond 3× their spread: that run is the one to check (its own logger, its own set-up), unless the effect misses what that run alone excites"),
        "{said}"
    );
    // One fold carrying most of what determines it (one degree of
    // freedom): the fold apart may be the one that pins the value, and the
    // run whose fold moves most the other way (run2, 0.0535 s above the
    // all-run 0.0529 s where run3's went below) is named beside it.
    let pinned = v
        .clone()
        .with_folds(&folds, Some((1.0, 1.0)))
        .with_model_error(true)
        .with_fold_runs(&runs, &[true; 8]);
    assert_eq!(pinned.folds_apart(), vec![3]);
    let said = parameter(&pinned);
    assert!(
        said.ends_with(": check that run (its own logger, its own set-up) and run2.csv (its fold 0.0535 s): one fold carrying most of what determines it, without that run the others follow the run that pulls them most the other way — unless the effect misses what that run alone excites"),
        "{said}"
    );
    // A refit that stopped short is said so: the refit, not the run, first.
    let mut stopped = [true; 8];
    stopped[3] = false;
    let s = parameter(&p.clone().with_fold_runs(&runs, &stopped));
    assert!(
        s.ends_with(" (the refit leaving out run3.csv did not converge: its value is where it stopped, so check that refit before the run)"),
        "{s}"
    );
    // Nothing significant removed: no run named.
    assert!(!parameter_of(&p, false).contains("to check"));
    // Folds that scatter alike (±0.01 s) disagree, but none stands apart.
    let alike = [0.043, 0.063, 0.053, 0.043, 0.063, 0.053, 0.043, 0.063];
    let q = v
        .with_folds(&alike, Some((1.0, 7.0)))
        .with_model_error(true)
        .with_fold_runs(&runs, &[true; 8]);
    assert!(q.understated());
    assert!(q.folds_apart().is_empty());
    assert!(!parameter(&q).contains("to check"));
}

#[test]
fn a_roll_steer_is_said_at_its_stated_gradient_with_the_product_the_runs_determine() {
    use crate::diagnose::report::HeldRollGradient;
    let [front, rear] = EffectKind::RollSteer.parameters() else {
        panic!("roll steer has a front and a rear");
    };
    let steer = |q, v, se| ParameterValue::of(Group::Effect(EffectKind::RollSteer), q, v, se);
    // Round 51's campaign: 3°/g stated on line 19.
    let stated = HeldRollGradient {
        gradient: 3f64.to_radians() / crate::constants::G,
        file: Some("out/fw2/vehicle.toml".into()),
        line: Some(19),
        runs_logging_roll: 0,
    };
    // -0.2510 × 0.0053392 = -0.0013401 rad per m/s², ± 0.00305 × 0.0053392
    // = 1.63e-5; per g, -0.2510 × 3 = -0.753°/g ± 0.00305 × 3 = 0.00915.
    let p = steer(front, -0.2510, 0.00305).at_roll_gradient(&stated);
    assert_eq!(
        parameter(&p),
        "roll_steer.front = -0.2510 ± 0.00305 rad/rad at the stated roll gradient of 3.00°/g (`[roll] gradient` = 0.005339221605729774, out/fw2/vehicle.toml:19), which the diagnosis holds (no run logs roll to measure it): the value scales inversely with that gradient, and the runs determine only its product with it, -0.001340 ± 1.63e-5 rad of front steer per m/s² of ay (-0.753 ± 0.00915°/g)"
    );
    // Not stated: the default 4°/g, and runs that log roll measure no
    // gradient; a value on its search bound has a product without an error.
    let default = HeldRollGradient {
        gradient: crate::vehicle::PASSENGER_CAR_ROLL_GRADIENT,
        file: None,
        line: None,
        runs_logging_roll: 3,
    };
    let bound = steer(rear, 0.5, 0.01).at_roll_gradient(&default);
    assert_eq!(bound.bound, Some(crate::diagnose::effects::Bound::Search));
    // 0.5 × 4°/g = 2°/g of rear steer; 0.5 × 0.0071191 = 0.0035595 rad/(m/s²).
    assert_eq!(
        parameter(&bound),
        "roll_steer.rear = 0.5000 rad/rad (at its search bound: the data would take it further) at the default roll gradient of 4.00°/g (the campaign states no `[roll] gradient`), which the diagnosis holds (the roll logged in 3 runs levels their ay and measures no gradient): the value scales inversely with that gradient, and the runs determine only its product with it, 0.003559 rad of rear steer per m/s² of ay (2.00°/g)"
    );
    // Roll camber: N/N of camber thrust per m/s² and per g (2.0 × 3°/g in
    // rad per m/s² = 0.010678; × g = 0.10472).
    let [_, camber] = EffectKind::RollCamber.parameters() else {
        panic!("roll camber has a front and a rear");
    };
    let c = ParameterValue::of(Group::Effect(EffectKind::RollCamber), camber, 2.0, 0.5)
        .at_roll_gradient(&stated);
    let said = parameter(&c);
    assert!(
        said.ends_with("its product with it, 0.0107 ± 0.00267 N/N of rear camber thrust per m/s² of ay (0.105 ± 0.0262 N/N per g)"),
        "{said}"
    );
    // Any other parameter is said as before.
    let bank = &EffectKind::RoadBank.parameters()[0];
    let b = ParameterValue::of(Group::Effect(EffectKind::RoadBank), bank, 0.01, 0.001);
    assert_eq!(
        parameter(&b.clone().at_roll_gradient(&stated)),
        parameter(&b)
    );
}

/// A value per radian of roll and its product with the roll gradient.
mod per_roll {
    use crate::diagnose::effects::{EffectKind, Group, PerRoll};
    use crate::diagnose::report::{HeldRollGradient, ParameterValue};

    fn held(gradient: f64) -> HeldRollGradient {
        HeldRollGradient {
            gradient,
            file: Some("camp/vehicle.toml".into()),
            line: Some(19),
            runs_logging_roll: 0,
        }
    }

    #[test]
    fn the_product_and_its_error_scale_with_the_gradient_and_only_roll_values_carry_one() {
        let steer = &EffectKind::RollSteer.parameters()[0];
        let v = ParameterValue::of(Group::Effect(EffectKind::RollSteer), steer, -0.251, 0.00305);
        let k = 3f64.to_radians() / crate::constants::G;
        let p = v.clone().at_roll_gradient(&held(k));
        let per = p.per_lateral_acceleration.as_ref().unwrap();
        assert_eq!(per.quantity, PerRoll::Steer);
        assert_eq!(per.unit, "rad/(m/s²)");
        assert!((per.value - -0.251 * k).abs() < 1e-15);
        assert!((per.std_error - 0.00305 * k).abs() < 1e-15);
        // 3°/g times -0.251 rad/rad is -0.753°/g of steer.
        assert!((per.per_g(per.value) - -0.753).abs() < 1e-12);
        assert!((per.roll_gradient.degrees_per_g() - 3.0).abs() < 1e-12);
        // At twice the gradient, half the coefficient: the same product.
        let twice = ParameterValue::of(
            Group::Effect(EffectKind::RollSteer),
            steer,
            -0.1255,
            0.001525,
        )
        .at_roll_gradient(&held(2.0 * k));
        let per2 = twice.per_lateral_acceleration.unwrap();
        assert!((per2.value - per.value).abs() < 1e-15);
        assert!((per2.std_error - per.std_error).abs() < 1e-15);
        // Camber thrust per g is N/N per m/s² times g.
        let camber = &EffectKind::RollCamber.parameters()[1];
        let c = ParameterValue::of(Group::Effect(EffectKind::RollCamber), camber, 2.0, 0.5)
            .at_roll_gradient(&held(k));
        let per = c.per_lateral_acceleration.unwrap();
        assert_eq!(
            (per.quantity, per.unit),
            (PerRoll::CamberThrust, "N/N per m/s²")
        );
        assert!((per.per_g(per.value) - 2.0 * k * crate::constants::G).abs() < 1e-15);
        // Neither a roll dynamics' value nor another effect's has one.
        let frequency = &crate::diagnose::effects::RollDynamics::PARAMETERS[0];
        let f = ParameterValue::of(Group::Roll, frequency, 1.8, 0.01).at_roll_gradient(&held(k));
        assert!(f.per_lateral_acceleration.is_none());
        let bank = &EffectKind::RoadBank.parameters()[0];
        let b = ParameterValue::of(Group::Effect(EffectKind::RoadBank), bank, 0.01, 0.001)
            .at_roll_gradient(&held(k));
        assert!(b.per_lateral_acceleration.is_none());
        // A value without a standard error has a product without one.
        let none = ParameterValue::of(Group::Effect(EffectKind::RollSteer), steer, 0.1, f64::NAN)
            .at_roll_gradient(&held(k));
        assert!(none.per_lateral_acceleration.unwrap().std_error.is_nan());
    }
}
