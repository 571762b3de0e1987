//! A set with a roll effect searched the added effect's parameters and the
//! roll dynamics together by a swarm (90–130 replays a set); the roll
//! dynamics are now held at the members' fit and the added effect's one or
//! two parameters gridded, and the verdict still recovers both truths.

use crate::narrowed;

#[test]
fn a_set_with_a_roll_effect_grids_only_the_added_effect_and_finds_both_truths() {
    let dir = tempfile::tempdir().unwrap();
    let candidates = "\"roll_steer\", \"sensor_delay\", \"yaw_inertia\"";
    let (_, d, _) = narrowed(dir.path(), "roll_steer,sensor_delay", candidates);
    let sets = d["combinations"].as_array().unwrap();
    assert!(!sets.is_empty(), "{d}");
    for set in sets {
        assert_eq!(set["effects"][0], "roll_steer", "{set}");
        let g = &set["global_search"];
        assert_eq!(g["kind"], "grid", "{set}");
        assert_eq!(g["points"], 10, "{set}");
    }
    let v = &d["verdict"];
    assert_eq!(
        v["effects"],
        serde_json::json!(["roll_steer", "sensor_delay"]),
        "{v}"
    );
    let value = |name: &str| {
        let p = v["parameters"].as_array().unwrap();
        let p = p.iter().find(|p| p["name"] == name).unwrap();
        p["value"].as_f64().unwrap()
    };
    // The truth: roll steer −0.15 front, 0 rear; a 0.05 s delay.
    let front = value("roll_steer.front");
    assert!((front + 0.15).abs() < 0.005, "{front}");
    let rear = value("roll_steer.rear");
    assert!(rear.abs() < 0.015, "{rear}");
    let delay = value("sensor_delay.delay");
    assert!((delay - 0.05).abs() < 0.002, "{delay}");
}
