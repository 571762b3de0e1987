//! Screening the single effects before their cross-validation: on
//! confusion-matrix campaigns of the proving ground, the verdict and every
//! cross-validated row are the same with and without it, no screened
//! effect is a verdict or could have passed on held-out runs, and the
//! margin it relies on (held-out reduction at most the in-sample one plus
//! the margin) holds on every candidate.

use handling::diagnose::effects::EffectKind;
use handling::diagnose::{diagnose, DiagnoseSettings, Diagnosis};
use handling::proving_ground::{generate, truth_values, Noise, SynthSpec};

/// A campaign with `truth` withheld, diagnosed with screening on or off.
fn diagnosed(truth: &[EffectKind], seed: u64, screening: bool) -> Diagnosis {
    let s = generate(&SynthSpec {
        effects: truth.iter().map(|e| (*e, truth_values(*e))).collect(),
        seed,
        noise: Noise::default(),
        programme: Default::default(),
    });
    let settings = DiagnoseSettings {
        seed,
        screening,
        ..Default::default()
    };
    diagnose(&s.campaign(EffectKind::ALL.to_vec(), settings), None).unwrap()
}

/// Checks one campaign; returns the number of effects screened.
fn same_with_and_without(truth: &[EffectKind], seed: u64) -> usize {
    let on = diagnosed(truth, seed, true);
    let off = diagnosed(truth, seed, false);
    let what = format!("{truth:?}, seed {seed}");
    assert!(off.screened.is_empty(), "{what}");
    assert_eq!(
        format!("{:?}", on.verdict),
        format!("{:?}", off.verdict),
        "{what}"
    );
    assert_eq!(
        format!("{:?}", on.combinations),
        format!("{:?}", off.combinations),
        "{what}"
    );
    assert_eq!(
        format!("{:?}", on.confounded),
        format!("{:?}", off.confounded),
        "{what}"
    );
    // Every candidate is either ranked (the same row as without
    // screening) or screened.
    assert_eq!(
        on.ranking.len() + on.screened.len(),
        off.ranking.len(),
        "{what}"
    );
    for r in &on.ranking {
        let same = off.ranking.iter().find(|o| o.effect == r.effect).unwrap();
        assert_eq!(format!("{r:?}"), format!("{same:?}"), "{what}");
    }
    for s in &on.screened {
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
    if let Some(s) = on.screened.first() {
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
    on.screened.len()
}

#[test]
fn screening_leaves_the_verdict_of_a_campaign_without_a_gap_as_it_is() {
    // No gap above noise: nothing is searched, every effect below the
    // threshold stays screened.
    let screened = same_with_and_without(&[], 1);
    assert!(screened >= 10, "{screened} screened");
}

#[test]
fn screening_leaves_a_pair_found_together_as_it_is() {
    // A tyre lag and sensor offsets: each alone below the acceptance
    // share, found as a pair by the greedy additions, which start screened
    // singles from their all-run fits.
    let screened =
        same_with_and_without(&[EffectKind::RelaxationLength, EffectKind::SensorBias], 4);
    assert!(screened >= 5, "{screened} screened");
}
