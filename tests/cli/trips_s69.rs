//! What a user still tripped on: a car sliding at its grip limit holds
//! its yaw rate and lateral acceleration while its sideslip keeps
//! growing, and `simulate` gave it clean step-steer metrics, `settled`
//! true and no warning.

use super::*;

/// `simulate` of the bundled sedan step on a road of the given friction:
/// the terminal and `metrics.json`.
pub(super) fn sedan_on(friction: Option<f64>) -> (String, serde_json::Value) {
    let road = friction.map_or(String::new(), |mu| format!("\n[road]\nfriction = {mu}\n"));
    let dir = tempfile::tempdir().unwrap();
    let scenario = super::sedan_runs::sedan(dir.path(), &road);
    let out = dir.path().join("out");
    let said = succeeds(&[
        "simulate",
        scenario.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    (said, read_json(&out.join("metrics.json")))
}

#[test]
fn a_car_sliding_at_its_grip_limit_is_not_said_settled() {
    const NOT_SETTLED: &str = "the response has not settled in the steady window";
    let (said, m) = sedan_on(None);
    assert_eq!(m["settled"], true, "{m}");
    assert!(!said.contains(NOT_SETTLED), "{said}");
    // At μ = 0.1 the lateral acceleration sits at μ·g and the sideslip
    // grows by about 0.8° a second through the steady window.
    let (said, m) = sedan_on(Some(0.1));
    assert_eq!(m["settled"], false, "{m}");
    let ay = m["ay_steady"].as_f64().unwrap();
    assert!((ay.abs() - 0.1 * 9.80665).abs() < 0.05, "{m}");
    let warned = said
        .lines()
        .find(|l| l.contains(NOT_SETTLED))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(warned.contains("sideslip"), "{warned}");
}

/// A tyre file with `Model = "gim"` was refused as "missing field
/// `model`", leaving the user to find the capital: the key written is
/// named with the fix.
#[test]
fn a_tyre_key_written_in_capitals_is_named_with_its_fix() {
    let text = fs::read_to_string(root().join("tyres/gim_sedan_front.toml"))
        .unwrap()
        .replace("model = \"gim\"", "Model = \"gim\"");
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n";
    let dir = scratch(&[("tyre.toml", &text), ("points.csv", points)]);
    let o = run(&[
        "tyre-eval",
        dir.path().join("tyre.toml").to_str().unwrap(),
        dir.path().join("points.csv").to_str().unwrap(),
        "--out",
        dir.path().join("out.csv").to_str().unwrap(),
    ]);
    let e = refused(&o, &dir.path().join("out.csv"));
    assert!(
        e.contains("tyre.toml:1:1: missing field `model`: the file writes `Model`, and keys are matched as written, in lower case: rename it `model`"),
        "{e}"
    );
}
