//! The second derivatives of a lateral-acceleration offset (session 111).
//! `sensor_bias.ay` is added to ay after the dynamics (`Sensors::seen`;
//! unlike the yaw-rate and sideslip offsets it does not set the replay's
//! start): the residuals are affine in it with a slope nothing else moves,
//! so every second derivative with it is zero, yet each cross-validated
//! candidate with it paid its second differences (`n·(n + 3)/2` replays
//! for `n` parameters: 9 for `sensor_bias` alone, now 5; 9 of the 44 of
//! the 600 s sedan's verdict). The fold refits now take those columns as
//! the zeros they are.

use super::*;

/// The `timing.phases` row of `phase` in a diagnosis: its evaluations.
fn evaluations(d: &serde_json::Value, phase: &str) -> u64 {
    d["timing"]["phases"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["phase"] == phase)
        .unwrap_or_else(|| panic!("no phase {phase}: {}", d["timing"]))["evaluations"]
        .as_u64()
        .unwrap()
}

#[test]
fn a_sensors_offsets_are_found_without_second_differences_of_them() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_extended(
        dir.path(),
        "handling",
        "sensor_bias",
        "1",
        "effects = [\"sensor_bias\", \"steering_compliance\"]\nmax_effects = 1\n",
    );
    let (stdout, d) = diagnose_campaign(&c);
    assert_eq!(
        d["verdict"]["effects"],
        serde_json::json!(["sensor_bias"]),
        "{stdout}"
    );
    assert!(stdout.contains("sensor_bias"), "{stdout}");
    let row = ranked(&d, "sensor_bias");
    // Cross-validated, every fold refit converged.
    let folds = row["folds"].as_u64().unwrap();
    assert!(folds >= 2, "{row}");
    assert_eq!(row["folds_converged"].as_u64(), Some(folds), "{row}");
    // The offsets synth withheld (sensor_bias's truth), recovered within
    // 10 % and three of their reported standard errors.
    let truth = [0.008, 0.2, 0.004];
    let params = row["parameters"].as_array().unwrap();
    assert_eq!(params.len(), 3, "{row}");
    for (p, t) in params.iter().zip(truth) {
        let (v, se) = (
            p["value"].as_f64().unwrap(),
            p["std_error"].as_f64().unwrap(),
        );
        assert!((v - t).abs() <= 0.1 * t + 3.0 * se, "{p}");
        // The folds' spread is the data's, not zero.
        assert!(p["fold_std_error"].as_f64().unwrap() > 0.0, "{p}");
    }
    // No second differences along the ay offset: sensor_bias's
    // cross-validation takes 5 (2·5/2 for the yaw-rate and sideslip
    // offsets), at most 2 more for the steering compliance's
    // (r(p + h), r(p + 2h)); before, sensor_bias's alone took 9.
    let second = evaluations(&d, "candidate_curvature");
    assert!(
        (5..=7).contains(&second),
        "{second} second-derivative replays: {}",
        d["timing"]
    );
}
