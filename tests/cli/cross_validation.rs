//! Held-out scoring that agrees with the fit: a truth that is not our model,
//! with roll stiffness and roll camber differing from the campaign's
//! settings, through `synth` and `diagnose`.

use super::*;

#[test]
fn roll_camber_on_an_independent_truth_is_named_and_its_scores_agree() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "--truth",
        "four-wheel",
        "--effects",
        "roll_camber",
        "--seed",
        "1",
    ];
    let campaign = synth_campaign(dir.path(), "c", &args);
    // The campaign's roll model is not the truth's (3°/g against 6°/g).
    let vehicle = fs::read_to_string(campaign.join("vehicle.toml")).unwrap();
    assert!(vehicle.contains("[roll]"), "{vehicle}");
    let (_, d) = diagnose_campaign(&campaign);
    assert_eq!(verdict_of(&d), vec!["roll_camber"], "{}", d["verdict"]);
    let r = d["ranking"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["effect"] == "roll_camber")
        .unwrap();
    let held = r["reduction_percent"].as_f64().unwrap();
    let inside = r["insample_reduction_percent"].as_f64().unwrap();
    // Every fold refit converged, and the held-out reduction is what the
    // fit on all runs promised, within the disagreement the report warns of.
    assert_eq!(r["folds_converged"], r["folds"], "{r}");
    assert!(
        held >= 30.0 && (inside - held).abs() < 25.0,
        "held out {held} %, in sample {inside} %"
    );
    assert!(r["warning"].is_null(), "{r}");
}
