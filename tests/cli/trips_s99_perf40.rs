//! A greedy step whose restricted fits screen all but
//! some of its sets polishes only those (`verdict/restricted.rs`): on the
//! racing log, `steer_path+steering_ratio` removes more than 10 % of what
//! the steer path leaves in its restricted fit and is polished, and
//! `steer_path+yaw_inertia`, far below, is screened by its restricted fit
//! alone; the step is screened as before.

use super::*;

/// The racing log's campaign (`campaigns/putnam.toml`) against `effects`
/// only, diagnosed; None where the log is missing.
fn putnam_with(test: &str, effects: &str) -> Option<serde_json::Value> {
    let log = shared_data(test, "run_iac_putnam/putnam_run4_2.csv")?;
    let text = putnam_campaign(&log, &format!("effects = [{effects}]"));
    let dir = scratch(&[("putnam.toml", &text)]);
    let (_, d) = diagnose_to(&dir.path().join("putnam.toml"), &dir.path().join("out"));
    Some(d)
}

#[test]
fn a_greedy_step_polishes_only_the_sets_its_restricted_fits_do_not_screen() {
    let Some(d) = putnam_with(
        "a_greedy_step_polishes_only_the_sets_its_restricted_fits_do_not_screen",
        "\"steer_path\", \"steering_ratio\", \"yaw_inertia\"",
    ) else {
        return;
    };
    assert_eq!(d["verdict"]["effects"][0], "steer_path", "{}", d["verdict"]);
    let share = |name: &str| {
        d["screened"]
            .as_array()
            .unwrap()
            .iter()
            .find(|s| s["effect"] == name)
            .unwrap_or_else(|| panic!("{name} not screened: {}", d["screened"]))
            ["insample_reduction_percent"]
            .as_f64()
            .unwrap()
    };
    // The step from the steer path is screened: neither set removes
    // 30 % − 10 points of what the steer path leaves in its full fit.
    let ratio = share("steer_path+steering_ratio");
    assert!((10.0..20.0).contains(&ratio), "{ratio}");
    assert!(share("steer_path+yaw_inertia") < 10.0);
    // The three singles' and the steering ratio set's optima linearised
    // (residuals and Jacobians), not the yaw inertia set's: before, one
    // set at or above 10 % in its restricted fit had every set of the
    // step polished (36).
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
    assert_eq!(phase("candidate_jacobian"), 29);
    assert_eq!(d["timing"]["candidates_fitted"], 5);
}
