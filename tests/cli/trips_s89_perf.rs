//! A candidate whose global stage searches three parameters (a sensor's
//! three offsets) was started by a particle swarm of 40 to 100 replays of
//! the runs; it is now started from a 3 × 3 × 3 grid of cell centres (27
//! replays and the start's, each stopped once its runs show it above the
//! best so far) and polished as before: the same verdict, the offsets
//! recovered as well.

use crate::narrowed;

/// Before: `sensor_bias`'s `global_search` in `diagnosis.json` read
/// `{"kind": "swarm", "evaluations": …}`. Now it reads a grid of three
/// cells per parameter and 28 points, and the verdict still names the
/// sensor offsets that were put in, at their values.
#[test]
fn three_sensor_offsets_are_started_from_a_grid_and_still_recovered() {
    let dir = tempfile::tempdir().unwrap();
    let candidates = "\"sensor_bias\", \"sensor_delay\", \"yaw_inertia\"";
    let (stdout, d, _) = narrowed(dir.path(), "sensor_bias", candidates);
    let bias = crate::fitted_row(&d, "sensor_bias");
    assert_eq!(
        bias["global_search"],
        serde_json::json!({"kind": "grid", "per_parameter": 3, "points": 28}),
        "{bias}"
    );
    let v = &d["verdict"];
    assert_eq!(v["effects"], serde_json::json!(["sensor_bias"]), "{stdout}");
    let value = |name: &str| {
        let p = v["parameters"].as_array().unwrap();
        let p = p.iter().find(|p| p["name"] == name).expect(name);
        p["value"].as_f64().unwrap()
    };
    // The truth: yaw rate 0.008 rad/s, ay 0.2 m/s², sideslip 0.004 rad.
    let yaw = value("sensor_bias.yaw_rate");
    assert!((yaw - 0.008).abs() < 0.001, "{yaw}");
    let ay = value("sensor_bias.ay");
    assert!((ay - 0.2).abs() < 0.02, "{ay}");
    let beta = value("sensor_bias.beta");
    assert!((beta - 0.004).abs() < 0.0008, "{beta}");
    assert!(stdout.contains("verdict: sensor_bias explains"), "{stdout}");
}
