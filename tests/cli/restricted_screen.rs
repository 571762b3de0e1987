//! A greedy step whose sets cannot be added is screened by restricted fits
//! (the added effect alone free beside the current set held), without
//! polishing the sets: on the racing log, with four candidates.

use super::*;

#[test]
fn a_greedy_step_on_the_racing_log_is_screened_without_polishing_its_sets() {
    let Some(log) = shared_data(
        "a_greedy_step_on_the_racing_log_is_screened_without_polishing_its_sets",
        "run_iac_putnam/putnam_run4_2.csv",
    ) else {
        return;
    };
    let text = putnam_campaign(
        &log,
        "effects = [\"steer_path\", \"yaw_inertia\", \"road_friction\"]",
    );
    let dir = scratch(&[("putnam.toml", &text)]);
    let out = dir.path().join("out");
    let o = run(&[
        "diagnose",
        dir.path().join("putnam.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let d = read_json(&out.join("diagnosis.json"));
    assert_eq!(d["verdict"]["effects"][0], "steer_path", "{}", d["verdict"]);
    // The step from the steer path: both sets screened, each removing
    // far below 10 % of what the steer path leaves.
    let sets: Vec<(String, f64)> = d["screened"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["extends"].as_array().is_some_and(|a| !a.is_empty()))
        .map(|s| {
            (
                s["effect"].as_str().unwrap().to_string(),
                s["insample_reduction_percent"].as_f64().unwrap(),
            )
        })
        .collect();
    let names: Vec<&str> = sets.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        ["steer_path+yaw_inertia", "steer_path+road_friction"],
        "{sets:?}"
    );
    for (name, x) in &sets {
        assert!(*x < 10.0, "{name}: {x}");
    }
    // Only the three singles were polished and linearised (20 replays for
    // their optima's residuals and Jacobians), not the two sets, whose
    // polish was spared (before: 34, the sets' 7 each added).
    let phase = |name: &str| {
        d["timing"]["phases"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["phase"] == name)
            .unwrap()["evaluations"]
            .as_u64()
            .unwrap()
    };
    assert_eq!(phase("candidate_jacobian"), 20);
    assert_eq!(d["timing"]["candidates_fitted"], 5);
}
