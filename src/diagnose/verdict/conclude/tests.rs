//! Unit tests of the verdict's conclusions (`conclude.rs`).

use super::*;
use crate::diagnose::effects::{EffectKind, Group, Parameter, RollDynamics};
use crate::diagnose::model::channels::Channel;

fn offset(name: &str, value: f64, std_error: f64) -> ParameterValue {
    ParameterValue::plain(name, "m/s²", value, std_error)
}

#[test]
fn only_a_parameter_on_its_search_bound_is_warned_of_not_one_on_a_physical_limit() {
    let at = |bound: Option<Bound>| ParameterValue {
        at_bound: bound.is_some(),
        bound,
        ..offset("x", 0.3, 0.01)
    };
    let p = [at(Some(Bound::Search)), at(Some(Bound::Physical)), at(None)];
    assert_eq!(on_search_bound(&p), vec![p[0].clone()]);
}

#[test]
fn a_rest_above_the_significance_threshold_is_warned_of_only_where_the_sentence_does_not_say_it() {
    let with = |j: f64, reduction: f64| {
        let mut r = row(&[EffectKind::SensorDelay], j, true);
        r.reduction_percent = reduction;
        remains(&r, 1.0)
    };
    // J 1.366 against noise 1.000: above 1.3 × the noise level.
    let Some(VerdictWarning::GapRemains {
        heldout_error_after,
        threshold,
        left_percent,
        ..
    }) = with(1.366, 84.0)
    else {
        panic!("no warning at J 1.366");
    };
    assert_eq!((heldout_error_after, threshold), (1.366, SIGNIFICANT));
    assert!((left_percent - 16.0).abs() < 1e-12);
    // At the threshold and below it, the rest is noise.
    assert!(with(1.3, 84.0).is_none() && with(1.1, 90.0).is_none());
    // A verdict that explains part of the gap says the rest in its
    // sentence: no second word.
    assert!(with(2.5, 49.9).is_none());
    assert!(with(2.5, EXPLAINS_MOST).is_some());
}

/// A ranking row of `effects` with held-out error `j` (base 4, noise
/// 1), its axles a tyre or not.
fn row(effects: &[EffectKind], j: f64, tyre: bool) -> Ranked {
    let no_tyre = vec![NoTyre::Limit {
        parameter: "rear cornering coefficient",
        limit: crate::diagnose::report::AxleLimit::Rigid,
    }];
    Ranked {
        effect: crate::diagnose::effects::joined(effects, "+"),
        effects: effects.to_vec(),
        axles: None,
        prior_weight: None,
        parameters: Vec::new(),
        heldout_error_before: 4.0,
        heldout_error_after: j,
        heldout_channels: Vec::new(),
        reduction_percent: 100.0 * (4.0 - j) / 3.0,
        insample_error_after: j,
        insample_reduction_percent: 100.0 * (4.0 - j) / 3.0,
        folds_converged: 8,
        folds: 8,
        warnings: if tyre {
            Vec::new()
        } else {
            vec![RankWarning::AxlesNoTyre { no_tyre }]
        },
        bic: 0.0,
        delta_bic: 0.0,
        global_search: crate::diagnose::fit::GlobalSearch::None,
    }
}

#[test]
fn the_closest_are_the_candidates_whose_axles_are_a_tyre_best_held_out_first_each_set_once() {
    use EffectKind::{RoadBank, SensorBias, SensorDelay, SteerPath, YawInertia};
    let rows = vec![
        // The best on held-out runs, but its axles are no tyre.
        row(&[RoadBank], 2.0, false),
        row(&[SensorDelay], 3.5, true),
        row(&[SensorBias, SteerPath], 3.2, true),
        // The same set in the other order: said once.
        row(&[SteerPath, SensorBias], 3.3, true),
        row(&[YawInertia], 3.9, true),
        row(&[SteerPath], 3.6, true),
    ];
    let c = closest(rows.into_iter());
    let named: Vec<&[EffectKind]> = c.iter().map(|c| c.effects.as_slice()).collect();
    assert_eq!(
        named,
        [&[SensorBias, SteerPath][..], &[SensorDelay], &[SteerPath]]
    );
    assert_eq!(c.len(), CLOSEST);
    assert!((c[0].reduction_percent - 80.0 / 3.0).abs() < 1e-9);
    // None whose axles are a tyre: none named.
    assert!(closest(vec![row(&[RoadBank], 2.0, false)].into_iter()).is_empty());
}

/// Parameter `q` of `group` fitted to `value` ± `std_error`.
fn fitted(group: Group, q: &'static Parameter, value: f64, std_error: f64) -> ParameterValue {
    ParameterValue::of(group, q, value, std_error)
}

#[test]
fn the_farthest_from_off_is_measured_from_the_registrys_off_value_and_not_from_a_roll_dynamics_value(
) {
    use EffectKind::{RollSteer, SensorDelay, YawInertia};
    let scale = &YawInertia.parameters()[0];
    let delay = &SensorDelay.parameters()[0];
    let frequency = &RollDynamics::PARAMETERS[0];
    // The yaw inertia's scale is off at 1: 1.30 ± 0.01 is 30 standard
    // errors from it (130 from 0).
    let mut inertia = row(&[YawInertia], 3.0, true);
    inertia.parameters = vec![fitted(Group::Effect(YawInertia), scale, 1.30, 0.01)];
    // 20 standard errors from off.
    let mut delayed = row(&[SensorDelay], 3.5, true);
    delayed.parameters = vec![fitted(Group::Effect(SensorDelay), delay, 0.02, 0.001)];
    // A roll frequency far from any value, whose off value is the
    // campaign's (NaN in the registry): not counted.
    let mut rolled = row(&[RollSteer], 3.2, true);
    rolled.parameters = vec![fitted(Group::Roll, frequency, 3.0, 0.001)];
    // Farther, but it does not lower the held-out error.
    let mut worse = row(&[SensorDelay], 4.5, true);
    worse.parameters = vec![fitted(Group::Effect(SensorDelay), delay, 0.2, 0.001)];
    let rows = [rolled, delayed.clone(), inertia, worse];
    let f = far_from_off(rows.into_iter(), 4.0, 1.0).expect("one far from off");
    assert_eq!((f.effects, f.off), (vec![YawInertia], 1.0));
    assert!(
        (f.standard_errors - 30.0).abs() < 1e-9,
        "{}",
        f.standard_errors
    );
    // The delay, 20 standard errors from off, is named beside it.
    assert_eq!(f.also.len(), 1);
    assert_eq!(f.also[0].effects, vec![SensorDelay]);
    assert_eq!(f.also[0].heldout_error_after, 3.5);
    // Below FAR_FROM_OFF standard errors: none named.
    delayed.parameters[0].value = 0.0099;
    assert!(far_from_off([delayed].into_iter(), 4.0, 1.0).is_none());
}

/// A candidate that lowers the held-out error by less than a quarter of
/// the noise level (1.014 → 0.966 of 1.000: a sensor delay fitted to pure
/// noise) removes nothing the confounding test tells from the base: not
/// named, however many standard errors its parameter lies from off.
#[test]
fn a_candidate_that_removes_less_than_the_noise_allowance_is_not_named_far_from_off() {
    let delay = &EffectKind::SensorDelay.parameters()[0];
    let mut noise_fit = row(&[EffectKind::SensorDelay], 0.966, true);
    noise_fit.parameters = vec![fitted(
        Group::Effect(EffectKind::SensorDelay),
        delay,
        0.0849,
        0.000213,
    )];
    assert!(far_from_off([noise_fit.clone()].into_iter(), 1.014, 1.0).is_none());
    // The same fit where it removes half a noise level is named; a
    // tenth is the line.
    let f = far_from_off([noise_fit].into_iter(), 1.466, 1.0).expect("named");
    assert!((f.standard_errors - 0.0849 / 0.000213).abs() < 1e-6);
}

/// The banked oval's case: the bank ranks first on held-out runs while
/// the bias's beta offset lies more standard errors from off. The best
/// on held-out runs is named, the other beside it, whatever order the
/// rows come in.
#[test]
fn the_candidate_named_far_from_off_is_the_best_on_held_out_runs_not_the_most_standard_errors() {
    use EffectKind::{RoadBank, SensorBias};
    let bank = &RoadBank.parameters()[0];
    let beta = SensorBias
        .parameters()
        .iter()
        .find(|q| q.name == "beta")
        .expect("a beta offset");
    let mut banked = row(&[RoadBank], 1.0015, true);
    banked.parameters = vec![fitted(Group::Effect(RoadBank), bank, 0.0319, 0.000493)];
    let mut biased = row(&[SensorBias], 1.0025, true);
    biased.parameters = vec![fitted(Group::Effect(SensorBias), beta, -0.00229, 2.96e-5)];
    for rows in [[biased.clone(), banked.clone()], [banked, biased]] {
        let f = far_from_off(rows.into_iter(), 1.23, 1.0).expect("one far from off");
        assert_eq!(f.effects, vec![RoadBank]);
        assert!((f.standard_errors - 0.0319 / 0.000493).abs() < 1e-9);
        assert_eq!(f.also.len(), 1);
        assert_eq!(f.also[0].effects, vec![SensorBias]);
        assert!(f.also[0].standard_errors > f.standard_errors);
    }
}

#[test]
fn a_searched_range_is_the_registrys_and_a_roll_dynamics_value_has_none() {
    let delay = &EffectKind::SensorDelay.parameters()[0];
    let frequency = &RollDynamics::PARAMETERS[0];
    let values = [
        fitted(Group::Effect(EffectKind::SensorDelay), delay, 0.3, 0.01),
        fitted(Group::Roll, frequency, 4.0, 0.1),
    ];
    let s = searched(values.iter());
    assert_eq!(s.len(), 1);
    assert_eq!(
        (s[0].name.as_str(), s[0].value, s[0].range),
        ("sensor_delay.delay", 0.3, (0.0, 0.3))
    );
}

fn shrink(channel: Channel, part: Part, before: f64, after: f64, floor: f64) -> Shrinkage {
    Shrinkage {
        channel,
        part,
        samples: 1000,
        before,
        after,
        noise_floor: floor,
        reduction_percent: crate::diagnose::model::channels::reduction(before, after, floor),
        mean_level: None,
        runs: Vec::new(),
    }
}

#[test]
fn a_channel_whose_gap_the_effects_leave_is_warned_of_and_not_one_within_noise_or_explained() {
    use Channel::{Ay, Beta, YawRate};
    // The sedan analogue: ay and beta fall by 61 % and 84 %, the yaw
    // rate 10× its noise floor before and after.
    let rows = [
        shrink(YawRate, Part::All, 0.0247, 0.0216, 0.0020),
        shrink(Ay, Part::All, 0.446, 0.184, 0.059),
        shrink(Beta, Part::All, 0.0147, 0.0032, 0.0022),
        // Another part's rows are not the channel's verdict.
        shrink(Ay, Part::Ay { lo: 4.0, hi: 6.0 }, 0.5, 0.5, 0.059),
    ];
    let w = left(&rows);
    assert_eq!(w.len(), 1, "{w:?}");
    let VerdictWarning::ChannelLeft(c) = &w[0] else {
        panic!("{w:?}")
    };
    assert_eq!(c.channel, YawRate);
    assert!(
        (c.removed_percent - 12.64).abs() < 0.01,
        "{}",
        c.removed_percent
    );
    assert_eq!(c.acceptance_percent, 30.0);
    // Just at the acceptance: explained; just below: left.
    let floor = 0.002;
    let at = |removed: f64| {
        let before: f64 = 0.02;
        let gap = (before * before - floor * floor).sqrt() * (1.0 - removed);
        shrink(
            YawRate,
            Part::All,
            before,
            (gap * gap + floor * floor).sqrt(),
            floor,
        )
    };
    assert!(left(&[at(0.301)]).is_empty());
    assert_eq!(left(&[at(0.299)]).len(), 1);
    // Within noise after: nothing left; a worsening is its own warning.
    assert!(left(&[shrink(Beta, Part::All, 0.0147, 0.0021, 0.0022)]).is_empty());
    let grown = shrink(Beta, Part::All, 0.0147, 0.0200, 0.0022);
    assert!(left(std::slice::from_ref(&grown)).is_empty());
    assert_eq!(worsened(&[grown]).len(), 1);
}

/// A sensor delay of 0.2991 ± 0.0165 s against its 0.3 s search bound (the
/// Putnam log with the road prior) stopped short of the bound by less
/// than its standard error, and was not said to press on it: now it is;
/// one further off than its standard error and 1 % of the range is not,
/// and the physical floor (0 s) is never one.
#[test]
fn a_verdict_parameter_within_its_standard_error_of_a_search_bound_is_warned_of() {
    let q = &EffectKind::SensorDelay.parameters()[0];
    let group = Group::Effect(EffectKind::SensorDelay);
    let near = ParameterValue::of(group, q, 0.2991, 0.0165);
    assert!(!near.at_bound, "the rules' test is unchanged");
    let n = near.near_search_bound().unwrap();
    assert_eq!((n.bound, n.by_std_error), (0.3, true));
    // Within 1 % of the 0.3 s range (0.003 s) with a smaller error.
    let n = ParameterValue::of(group, q, 0.2975, 0.001).near_search_bound();
    assert_eq!(n.map(|n| (n.bound, n.by_std_error)), Some((0.3, false)));
    let off = ParameterValue::of(group, q, 0.28, 0.0165);
    let floor = ParameterValue::of(group, q, 0.0001, 0.0165);
    assert_eq!(
        (off.near_search_bound(), floor.near_search_bound()),
        (None, None)
    );
    let p = [near.clone(), off, floor];
    assert_eq!(at_or_near_search_bound(&p), vec![near]);
    assert!(on_search_bound(&p).is_empty());
    // The roll mode's, named `roll.*`, by the roll dynamics' bounds.
    let damping = &RollDynamics::PARAMETERS[1];
    let roll = ParameterValue::of(Group::Roll, damping, 1.49, 0.02);
    assert_eq!(roll.near_search_bound().map(|n| n.bound), Some(1.5));
}
