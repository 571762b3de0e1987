//! A set's global stage, through the CLI: a set searches only the effect
//! it adds beside the current set (held at its best start), so a pair of
//! one-parameter effects is a grid of 9 cells along the added one (10
//! replays with its start), not a 5 × 5 grid or a swarm over both; and it
//! still recovers the truth of a campaign with both effects on.

use crate::narrowed;

#[test]
fn a_set_searches_only_the_effect_it_adds_and_still_finds_both_truths() {
    let dir = tempfile::tempdir().unwrap();
    let candidates = "\"sensor_delay\", \"relaxation_length\", \"yaw_inertia\"";
    let (_, d, _) = narrowed(dir.path(), "relaxation_length,sensor_delay", candidates);
    let sets = d["combinations"].as_array().unwrap();
    assert!(!sets.is_empty(), "{d}");
    for set in sets {
        let g = &set["global_search"];
        assert_eq!(g["kind"], "grid", "{set}");
        assert_eq!(g["per_parameter"], 9, "{set}");
        assert_eq!(g["points"], 10, "{set}");
    }
    let v = &d["verdict"];
    assert_eq!(
        v["effects"],
        serde_json::json!(["sensor_delay", "relaxation_length"]),
        "{v}"
    );
    // The truth: a 0.05 s delay and a 0.8 m relaxation length (to 2 ms and
    // 4 %: the matrix's row recovers 0.050 s and 0.78 m).
    let value = |name: &str| {
        let p = v["parameters"].as_array().unwrap();
        let p = p.iter().find(|p| p["name"] == name).unwrap();
        p["value"].as_f64().unwrap()
    };
    let delay = value("sensor_delay.delay");
    assert!((delay - 0.05).abs() < 0.002, "{delay}");
    let length = value("relaxation_length.relaxation_length");
    assert!((length - 0.8).abs() < 0.032, "{length}");
}
