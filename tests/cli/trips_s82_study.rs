//! Fresh-eyes round 9 on `study`: a spinning car mapped as a good one, a
//! stiffness in the other unit run without a word, `NaN` in `study.csv`,
//! and `metrics.json` keys that came and went.

use super::*;

/// The coarse study (bundled), run into a scratch folder: its stdout and
/// the folder.
fn coarse_study(text: &str) -> (Output, tempfile::TempDir) {
    let dir = scratch(&[("study.toml", text)]);
    let o = run_in(dir.path(), &["study", "study.toml", "--out", "out"]);
    (o, dir)
}

/// The bundled coarse study's front 500 / rear 220 N/deg is an oversteering
/// car past its critical speed: it slides to −38.8° of steady sideslip,
/// its yaw rate never peaks above a "steady" value, and `study.csv` gave it
/// 0 % overshoot — the best-looking cell of the map for the worst car.
#[test]
fn a_study_flags_counts_and_says_the_combinations_that_slide() {
    let (o, dir) = coarse_study(&bundled_scenario("sedan_study_coarse.toml"));
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("  6 of 47 combinations are no handling response: 6 slide (sideslip beyond 10°, up to -58.2° at the end of the run, still moving (no steady value)); their metrics are left out of the maps, the network and the inverse"),
        "{said}"
    );
    let out = dir.path().join("out");
    let summary = read_json(&out.join("summary.json"));
    assert_eq!(summary["sliding"], 6, "{summary}");
    assert_eq!(summary["not_settled"], 0, "{summary}");
    assert_eq!(summary["without_steady_state"], 0, "{summary}");
    let csv = fs::read_to_string(out.join("study.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    assert_eq!(header[header.len() - 2..], ["response", "note"]);
    let row = csv
        .lines()
        .find(|l| l.starts_with("500,220,"))
        .expect("the 500/220 row");
    assert!(
        row.ends_with(",,,,,,,,,,sliding,\"sideslip -38.8 deg at the end of the run, still moving (no steady value), beyond 10 deg: the car slides past its grip; no handling response, metrics left empty\""),
        "{row}"
    );
    // The good cars are still measured: the book's 500/520 pair.
    let good = csv.lines().find(|l| l.starts_with("500,520,")).unwrap();
    assert!(good.ends_with(",handling,"), "{good}");
    // The inverse is the book's, untouched by the sliders.
    assert!(
        said.contains(
            "Er = 0.13: a curve of 7 map points; closest to (500, 540) N/deg: (503.8, 529.9)"
        ),
        "{said}"
    );
}

/// `study.csv` wrote `NaN` for a peak time and a TB the response does not
/// have; a CSV cell without a value is empty, and `note` says why.
#[test]
fn study_csv_never_writes_nan_and_says_why_a_cell_is_empty() {
    let (o, dir) = coarse_study(&bundled_scenario("sedan_study_coarse.toml"));
    assert!(o.status.success(), "{}", stderr(&o));
    let csv = fs::read_to_string(dir.path().join("out/study.csv")).unwrap();
    assert!(!without_temp_names(&csv).contains("NaN"), "{csv}");
    // 500/320 N/deg: a handling response whose yaw rate does not overshoot.
    let row = csv.lines().find(|l| l.starts_with("500,320,")).unwrap();
    let cells: Vec<&str> = row.split(',').collect();
    assert_eq!(cells[8], "", "peak time of {row}");
    // Below the peak threshold (its own column), not a measured 0.
    assert_eq!(cells[9], "", "overshoot of {row}");
    assert!(
        row.ends_with(",1,handling,\"still settling at the end of the step: a steady value heads 1.8 % of its step further; metrics kept, a longer step settles them; yaw_rate_peak_time, yaw_rate_overshoot, tb empty: no yaw-rate maximum stands more than 1 % above the steady value (the peak threshold, yaw_rate_peak_threshold): an overshoot below it, not a measured 0\""),
        "{row}"
    );
}

/// The book gives stiffness in N/deg (200–700 per tyre); N/rad values
/// under it (20,000–70,000) made tyres 57 times too stiff, and N/deg
/// values under `unit = "N/rad"` 57 times too soft, without a word.
#[test]
fn a_study_refuses_a_stiffness_in_the_other_unit_at_its_key() {
    let coarse = bundled_scenario("sedan_study_coarse.toml");
    let big = coarse.replacen(
        "front = { from = 200.0, to = 700.0, step = 100.0 }",
        "front = { from = 20000.0, to = 70000.0, step = 10000.0 }",
        1,
    );
    let (o, dir) = coarse_study(&big);
    assert!(!o.status.success());
    let line = big
        .lines()
        .position(|l| l.starts_with("front = { from = 20000.0"))
        .unwrap()
        + 1;
    assert!(
        stderr(&o).contains(&format!("study.toml:{line}:9: `stiffness.front` = 20000 N/deg per tyre is 1145916 N/rad, 254 times the front tyre's static load (4507 N) per rad, stiffer than any tyre")),
        "{}",
        stderr(&o)
    );
    assert!(
        stderr(&o).contains(
            "is the value in N/rad? write `unit = \"N/rad\"`, or give it in N/deg as 349.1 N/deg"
        ),
        "{}",
        stderr(&o)
    );
    assert!(!dir.path().join("out").exists());
    let soft = coarse.replace("unit = \"N/deg\"", "unit = \"N/rad\"");
    let (o, _dir) = coarse_study(&soft);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("`stiffness.front` = 200 N/rad per tyre, 0.0444 times the front tyre's static load (4507 N) per rad, softer than any tyre"),
        "{}",
        stderr(&o)
    );
    assert!(
        stderr(&o).contains(
            "is the value in N/deg? write `unit = \"N/deg\"`, or give it in N/rad as 11459 N/rad"
        ),
        "{}",
        stderr(&o)
    );
    // The reference alone in the other unit: refused at its key too.
    let reference = coarse.replace(
        "reference = { front = 500.0, rear = 540.0 }",
        "reference = { front = 500.0, rear = 30940.0 }",
    );
    let (o, _dir) = coarse_study(&reference);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("`inverse.reference.rear` = 30940 N/deg per tyre"),
        "{}",
        stderr(&o)
    );
}

/// `metrics.json` left out `warnings`, `notes` and `lift_offs` when they
/// were empty: a reader could not tell "none" from "not computed".
#[test]
fn metrics_json_keeps_its_keys_when_they_are_empty() {
    let dir = scratch(&[("s.toml", &bundled_scenario("sedan_step.toml"))]);
    let o = run_in(dir.path(), &["simulate", "s.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let m = read_json(&dir.path().join("out/metrics.json"));
    for key in ["warnings", "notes", "lift_offs"] {
        assert_eq!(m[key], serde_json::json!([]), "{key}: {m}");
    }
}

/// `validation = [3, 11]` of 11 pairs was refused as "only 11 pairs": the
/// index counts from 0, and the message blamed the number of pairs.
#[test]
fn an_rbf_validation_index_beyond_the_pairs_is_said_as_counted_from_zero() {
    let text = bundled_scenario("sedan_study_coarse.toml")
        .replace("validation = [3, 8]", "validation = [3, 11]");
    let (o, _dir) = coarse_study(&text);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("`rbf.validation` = 11: no such pair: an index counts from 0 in the order `[rbf] front` × `rear_offsets` makes the pairs (each offset in turn, rear ≤ `rear_max`), and they are 11: an index lies in 0–10"),
        "{}",
        stderr(&o)
    );
}
