//! Performance: the replays a diagnosis spends on the 8-run
//! campaign of the `diagnose` bench (`handling synth --effects
//! sensor_delay --seed 1`, diagnosed against the whole library). A polish
//! whose last Jacobian was differenced at its optimum hands it to the
//! optimum's linearisation instead of differencing the same point again,
//! and a fresh model that promises less than the tolerance stops the
//! polish without its trial step: fewer replays, the same verdict.

use super::*;

/// Before: `diagnosis.json`'s `timing` counted 587 replays of the run set
/// (198 in the candidates' polish). Now 599 (160 in the polish) since
/// session 105's fold refits stop within about 0.03 standard errors of
/// their optimum (`τ = 1e-3`: 18 fold replays fewer, steer_path 86.044 →
/// 86.050 %); 617 with session 104's stop at 0.01 of them (where they
/// stopped up to 0.18 off before: 32 more fold replays); 585 with session 97's `steering_ratio` in the
/// library; 548 (154, as before
/// session 94; 564 and 166 with session 94's four-wheel PAC89 evaluation,
/// until session 95's Newton load-transfer step, each moving a flat
/// valley's polish by forces within a few ulp or the loop's tolerance; 540
/// before session 92, when a fold refit not started from a linearisation
/// began to replay its start once, to check that it ends below it,
/// `diagnose/fit/fold_check.rs`), and the
/// verdict, its delay and every ranked effect's held-out reduction are
/// those of before to 0.01 point (sensor_delay 85.29 %, steer_path
/// 86.05 %, relaxation_length 31.17 %) until the settled fold refits
/// moved them to 85.27, 86.04 and 31.90 % (relaxation_length's folds had
/// stopped short, 0.7 point of held-out reduction).
#[test]
fn the_eight_run_campaign_is_diagnosed_in_fewer_replays_with_the_same_verdict() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "c8",
        &["--effects", "sensor_delay", "--seed", "1"],
    );
    let (stdout, d) = diagnose_campaign(&c);
    let evaluations = |name: &str| {
        let phases = d["timing"]["phases"].as_array().unwrap();
        let p = phases.iter().find(|p| p["phase"] == name).unwrap();
        p["evaluations"].as_u64().unwrap()
    };
    let all: u64 = [
        "candidate_search",
        "candidate_polish",
        "candidate_jacobian",
        "candidate_curvature",
        "candidate_folds",
    ]
    .iter()
    .map(|p| evaluations(p))
    .sum();
    assert_eq!(
        (all, evaluations("candidate_polish")),
        (599, 160),
        "{}",
        d["timing"]
    );
    assert_eq!(verdict_of(&d), ["sensor_delay"], "{stdout}");
    let delay = d["verdict"]["parameters"][0]["value"].as_f64().unwrap();
    assert!((delay - 0.049604).abs() < 1e-6, "{delay}");
    for (effect, before) in [
        ("sensor_delay", 85.272),
        ("steer_path", 86.044),
        ("relaxation_length", 31.899),
    ] {
        let r = ranked(&d, effect)["reduction_percent"].as_f64().unwrap();
        assert!(
            (r - before).abs() < 0.01,
            "{effect}: {r} % against {before} %"
        );
    }
}
