//! A slow response judged settled by its spread alone: an oversteering car
//! near its critical speed creeps towards a steady state 9 % beyond the
//! last second's mean while spreading by under 2 % in it. "Settled" now
//! asks where the trend heads as well; a study keeps such a converging
//! combination in its maps, flagged, where it left none out before.

use super::trips_s84_sim::oversteering_step;
use super::*;

/// The linear model's steady yaw-rate gain v/(l + K·v²) of the car in
/// [`oversteering_step`] (K = (m/l)·(b − a)/C, equal axles of two
/// 57,296 N/rad wheels).
fn linear_gain(speed: f64) -> f64 {
    let (m, a, b) = (1530.0, 1.59, 1.19);
    let l = a + b;
    let c = 2.0 * 57_295.8;
    let k = m / l * (b - a) / c;
    speed / (l + k * speed * speed)
}

/// The number before `after` in `text`.
fn number_before(text: &str, after: &str) -> f64 {
    let head = &text[..text
        .find(after)
        .unwrap_or_else(|| panic!("{after}: {text}"))];
    let word = head.split_whitespace().last().unwrap();
    word.parse().unwrap_or_else(|_| panic!("{word}: {text}"))
}

#[test]
fn a_slow_approach_within_the_spread_is_said_still_settling_and_where_it_heads() {
    let dir = tempfile::tempdir().unwrap();
    let path = oversteering_step(dir.path(), 35.0, 0.01, 8.0);
    let out = dir.path().join("out");
    let said = succeeds(&[
        "simulate",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let gain = number_before(&said, "1/s");
    // 8 % short of the linear model's steady state, once called settled.
    assert!((gain / linear_gain(35.0) - 1.0).abs() > 0.05, "{gain}");
    assert!(
        said.contains("the yaw rate is still settling: the trend across its steady window heads"),
        "{said}"
    );
    // Where the trend heads is where the linear model settles.
    let heads = number_before(
        &said[said.find("the yaw rate is still settling").unwrap()..],
        "% of its step beyond its steady value",
    );
    let limit = gain * (1.0 + heads / 100.0);
    assert!(
        (limit / linear_gain(35.0) - 1.0).abs() < 0.005,
        "{limit} vs {}",
        linear_gain(35.0)
    );
    let m = read_json(&out.join("metrics.json"));
    assert_eq!(m["settled"], false, "{m}");
    assert_eq!(m["settling"]["yaw_rate"]["verdict"], "drifting", "{m}");
    assert_eq!(m["settling"]["yaw_rate"]["converging"], true, "{m}");
    // Further from the critical speed the same step settles within the
    // window, at the linear model's gain, and nothing is said.
    let path = oversteering_step(dir.path(), 30.0, 0.01, 8.0);
    let said = succeeds(&[
        "simulate",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!said.contains("settl"), "{said}");
    let gain = number_before(&said, "1/s");
    assert!((gain / linear_gain(30.0) - 1.0).abs() < 0.01, "{gain}");
}

#[test]
fn a_study_keeps_a_combination_still_settling_and_says_how_far_it_has_to_go() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let said = succeeds(&[
        "study",
        "scenarios/sedan_study_coarse.toml",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        said.contains("  still settling at the end of the step: 1 of 47 combinations"),
        "{said}"
    );
    let summary = read_json(&out.join("summary.json"));
    assert_eq!(summary["still_settling"], 1, "{summary}");
    assert_eq!(summary["not_settled"], 0, "{summary}");
    let csv = fs::read_to_string(out.join("study.csv")).unwrap();
    let row = csv
        .lines()
        .find(|l| l.starts_with("700,420,"))
        .unwrap_or_else(|| panic!("{csv}"));
    // Kept: a handling response with its metrics, its note saying how far
    // it heads (the step lengthened to 15 s moves the steady sideslip
    // 2.55 % further).
    assert!(row.contains(",handling,\"still settling at the end of the step: a steady value heads 2.5 % of its step further"), "{row}");
    let er: f64 = row.split(',').nth(4).unwrap().parse().unwrap();
    assert!(er > 0.0, "{row}");
    let rbf = read_json(&out.join("rbf.json"));
    assert_eq!(rbf["training_pairs"], 9, "{rbf}");
}

/// A run saved again under another name in the runs folder: held out, the
/// copy was scored on the samples its twin was fitted on, a verdict's
/// held-out evidence counted twice. Refused at `[runs]`, naming both.
#[test]
fn a_byte_for_byte_copy_of_a_run_is_refused_as_the_same_run_twice() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "c", &[]);
    let runs = c.join("runs");
    let mut names: Vec<String> = fs::read_dir(&runs)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".csv"))
        .collect();
    names.sort();
    let original = &names[1];
    fs::copy(runs.join(original), runs.join("zz_copy.csv")).unwrap();
    let o = run(&[
        "diagnose",
        c.to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("zz_copy.csv is a copy of ") && e.contains(original.as_str()),
        "{e}"
    );
    assert!(
        e.contains("counts the same evidence twice; select one of them"),
        "{e}"
    );
    assert!(!dir.path().join("out").exists());
}
