//! Exact Jacobians (`[diagnose] derivatives = "exact"`: one replay of the
//! runs in dual numbers) against the default forward differences on
//! proving-ground campaigns: the same verdict, its held-out reduction and
//! every single effect's within half a point, the verdict's parameters
//! within a tenth of their standard errors. And the key is read from a
//! campaign's `[diagnose]` table, a wrong value refused naming it.

use handling::diagnose::effects::EffectKind;
use handling::diagnose::{diagnose, DiagnoseSettings, Diagnosis};
use handling::optim::local::Derivatives;
use handling::proving_ground::{generate, truth_values, Noise, SynthSpec};

/// A campaign with `truth` withheld, diagnosed with `derivatives`.
fn diagnosed(truth: EffectKind, derivatives: Derivatives) -> Diagnosis {
    let s = generate(&SynthSpec {
        effects: vec![(truth, truth_values(truth))],
        seed: 3,
        noise: Noise::default(),
        programme: Default::default(),
    });
    let settings = DiagnoseSettings {
        seed: 3,
        derivatives,
        ..Default::default()
    };
    diagnose(&s.campaign(EffectKind::ALL.to_vec(), settings), None).unwrap()
}

#[test]
fn exact_jacobians_give_the_verdict_of_differences_within_noise() {
    for truth in [EffectKind::SensorDelay, EffectKind::RoadBank] {
        let exact = diagnosed(truth, Derivatives::Exact);
        let diff = diagnosed(truth, Derivatives::Differences);
        // The report says how its Jacobians were taken.
        assert_eq!(exact.derivatives, Derivatives::Exact);
        assert_eq!(diff.derivatives, Derivatives::Differences);
        assert_eq!(exact.verdict.effects(), [truth]);
        assert_eq!(exact.verdict.effects(), diff.verdict.effects(), "{truth:?}");
        for r in &exact.ranking {
            let Some(d) = diff.ranking.iter().find(|d| d.effect == r.effect) else {
                continue;
            };
            let moved = (r.reduction_percent - d.reduction_percent).abs();
            assert!(moved <= 0.5, "{truth:?}: {}: {moved} points", r.effect);
        }
        for (e, d) in exact
            .verdict
            .parameters()
            .iter()
            .zip(diff.verdict.parameters())
        {
            assert_eq!(e.name, d.name);
            let se = e.std_error.max(d.std_error);
            assert!(se.is_finite() && se > 0.0, "{truth:?}: {e:?}");
            assert!(
                (e.value - d.value).abs() <= 0.1 * se,
                "{truth:?}: {e:?} vs {d:?}"
            );
        }
    }
}

#[test]
fn the_derivatives_key_is_read_and_a_wrong_value_named() {
    let s: DiagnoseSettings = toml::from_str("derivatives = \"exact\"").unwrap();
    assert_eq!(s.derivatives, Derivatives::Exact);
    assert_eq!(
        DiagnoseSettings::default().derivatives,
        Derivatives::Differences
    );
    let e = toml::from_str::<DiagnoseSettings>("derivatives = \"dual\"").unwrap_err();
    let text = e.to_string();
    assert!(
        text.contains("dual") && text.contains("exact") && text.contains("differences"),
        "{text}"
    );
}
