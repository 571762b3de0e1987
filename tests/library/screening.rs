//! Screening before cross-validation: on confusion-matrix campaigns of
//! the proving ground, the verdict and every cross-validated row are the
//! same with and without it, no screened effect or set is a verdict or
//! could have passed on held-out runs, and the margin it relies on
//! (held-out reduction at most the in-sample one plus the margin) holds on
//! every candidate: the single effects against the base model, the sets the
//! greedy additions screened against the set they extend.

use super::diagnosed;
use handling::diagnose::effects::{same_effects, EffectKind};
use handling::diagnose::report::Screened;
use handling::diagnose::Diagnosis;

/// Checks one campaign; returns the number of single effects screened and
/// of sets the greedy additions screened.
fn same_with_and_without(truth: &[EffectKind], seed: u64, hidden: &[EffectKind]) -> (usize, usize) {
    let on = diagnosed(truth, seed, true, hidden);
    let off = diagnosed(truth, seed, false, hidden);
    let what = format!("{truth:?}, seed {seed}");
    assert!(off.screened.is_empty(), "{what}");
    assert_eq!(
        format!("{:?}", on.verdict),
        format!("{:?}", off.verdict),
        "{what}"
    );
    // Every set cross-validated with screening is the same row without;
    // the others were screened.
    for r in &on.combinations {
        let same = off.combinations.iter().find(|o| o.effect == r.effect);
        assert_eq!(format!("{r:?}"), format!("{:?}", same.unwrap()), "{what}");
    }
    let sets: Vec<&Screened> = on.screened_sets().collect();
    assert_eq!(
        on.combinations.len() + sets.len(),
        off.combinations.len(),
        "{what}"
    );
    for s in &sets {
        set_screened_rightly(s, &off, &what);
    }
    assert_eq!(
        format!("{:?}", on.confounded),
        format!("{:?}", off.confounded),
        "{what}"
    );
    // Every candidate is either ranked (the same row as without
    // screening) or screened.
    assert_eq!(
        on.ranking.len() + on.screened_singles().count(),
        off.ranking.len(),
        "{what}"
    );
    for r in &on.ranking {
        let same = off.ranking.iter().find(|o| o.effect == r.effect).unwrap();
        assert_eq!(format!("{r:?}"), format!("{same:?}"), "{what}");
    }
    for s in on.screened_singles() {
        assert!(
            !on.verdict.effects().contains(&s.effects[0]),
            "{what}: {} screened and in the verdict",
            s.effect
        );
        assert!(
            s.insample_reduction_percent + s.margin_percent < s.threshold_percent,
            "{what}: {s:?}"
        );
        // Cross-validated after all (without screening), it would not
        // have passed, and its in-sample reduction is the one screened on.
        let r = off.ranking.iter().find(|o| o.effect == s.effect).unwrap();
        assert!(r.reduction_percent < s.threshold_percent, "{what}: {r:?}");
        assert_eq!(r.insample_reduction_percent, s.insample_reduction_percent);
    }
    // The margin holds on every single effect: held-out reduction at most
    // the in-sample one plus the margin.
    if let Some(s) = on.screened_singles().next() {
        for o in &off.ranking {
            assert!(
                o.reduction_percent <= o.insample_reduction_percent + s.margin_percent,
                "{what}: {} held out {:.1} %, in sample {:.1} %",
                o.effect,
                o.reduction_percent,
                o.insample_reduction_percent
            );
        }
    }
    (on.screened_singles().count(), sets.len())
}

/// The share (%) of the held-out gap above noise `jn` left at `before`
/// that `after` removes.
fn reduction(before: f64, after: f64, jn: f64) -> f64 {
    let gap = |j: f64| (j * j - jn * jn).max(0.0).sqrt();
    100.0 * (1.0 - gap(after) / gap(before))
}

/// A set the greedy additions screened (`s`, in the diagnosis with
/// screening) is, in the diagnosis without (`off`), cross-validated to a
/// held-out reduction of what the set it extends leaves below the
/// acceptance share, within the margin of its in-sample one, and not the
/// verdict; one a greedy step spared (its pick unable to read it), to a
/// held-out error at or above the floor it was spared on.
fn set_screened_rightly(s: &Screened, off: &Diagnosis, what: &str) {
    let row = |effects: &[EffectKind]| {
        off.ranking
            .iter()
            .chain(&off.combinations)
            .find(|r| same_effects(&r.effects, effects))
            .unwrap_or_else(|| panic!("{what}: {effects:?} not cross-validated without screening"))
    };
    let (extended, larger) = (row(&s.extends), row(&s.effects));
    assert!(!same_effects(off.verdict.effects(), &s.effects), "{what}");
    let jn = off.gap.noise_level;
    let extra = reduction(extended.heldout_error_after, larger.heldout_error_after, jn);
    // A set its step's pick could not read: cross-validated after all, it
    // lies at or above the floor it was spared on, beyond the step's best.
    if let Some(o) = &s.outranked {
        assert!(
            larger.heldout_error_after >= o.floor,
            "{what}: {} held out {} below its floor {}",
            s.effect,
            larger.heldout_error_after,
            o.floor
        );
        assert!(o.floor > o.heldout_error, "{what}: {s:?}");
        assert!(
            extra <= s.insample_reduction_percent + s.margin_percent,
            "{what}: {} adds {extra:.1} % held out, {:.1} % in sample",
            s.effect,
            s.insample_reduction_percent
        );
        return;
    }
    assert!(
        s.insample_reduction_percent + s.margin_percent < s.threshold_percent,
        "{what}: {s:?}"
    );
    assert!(
        extra < s.threshold_percent,
        "{what}: {} adds {extra:.1} % held out",
        s.effect
    );
    assert!(
        extra <= s.insample_reduction_percent + s.margin_percent,
        "{what}: {} adds {extra:.1} % held out, {:.1} % in sample",
        s.effect,
        s.insample_reduction_percent
    );
}

#[test]
fn screening_leaves_the_verdict_of_a_campaign_without_a_gap_as_it_is() {
    // No gap above noise: nothing is searched, every effect below the
    // threshold stays screened.
    let (screened, sets) = same_with_and_without(&[], 1, &[]);
    assert!(screened >= 10, "{screened} screened");
    assert_eq!(sets, 0, "nothing searched, no set tried");
}

#[test]
fn screening_leaves_a_pair_found_together_as_it_is() {
    // A tyre lag and sensor offsets: each alone below the acceptance
    // share, found as a pair by the greedy additions, which start screened
    // singles from their all-run fits.
    let (screened, _) = same_with_and_without(
        &[EffectKind::RelaxationLength, EffectKind::SensorBias],
        4,
        &[],
    );
    assert!(screened >= 5, "{screened} screened");
}

#[test]
fn screening_leaves_a_greedy_step_that_adds_nothing_as_it_is() {
    // The same campaign without the sensor offsets among the candidates:
    // the tyre lag alone is promising, and no effect left removes enough
    // of what it leaves, so every pair of the greedy step is screened.
    let (_, sets) = same_with_and_without(
        &[EffectKind::RelaxationLength, EffectKind::SensorBias],
        4,
        &[EffectKind::SensorBias],
    );
    assert!(sets >= 10, "{sets} sets screened");
}
