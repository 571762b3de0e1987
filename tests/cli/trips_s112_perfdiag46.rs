//! A greedy step cross-validates only the sets its pick can read (session
//! 112). A set whose least possible held-out error (its in-sample share of
//! what the set it extends leaves, plus the screening's 10 points) lies
//! beyond the pick's window around the step's best set is not refitted
//! fold by fold: it is listed with that floor and the best set it missed.
//! The verdict, and every set that is cross-validated, are those of the
//! diagnosis that cross-validates every set (`screening = false`).

use super::*;

/// The sets a diagnosis spared: each `screened` row with `outranked`.
fn spared(d: &serde_json::Value) -> Vec<&serde_json::Value> {
    d["screened"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s.get("outranked").is_some())
        .collect()
}

/// The effects of a row as a sorted list (a set whatever its order).
fn set_of(row: &serde_json::Value) -> Vec<String> {
    let mut e: Vec<String> = row["effects"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_str().unwrap().to_string())
        .collect();
    e.sort();
    e
}

#[test]
fn a_greedy_steps_sets_its_pick_cannot_read_are_spared_and_the_verdict_stands() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["--effects", "relaxation_length,sensor_bias", "--seed", "4"];
    let on = synth_campaign(dir.path(), "on", &args);
    let off = synth_campaign(dir.path(), "off", &args);
    let v = off.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    fs::write(&v, format!("{text}screening = false\n")).unwrap();
    let (stdout, d) = diagnose_campaign(&on);
    let (_, all) = diagnose_campaign(&off);
    // The runs' paths (the fold refits' `left_out`) named as the first
    // campaign's: the two differ only in their folder.
    let all: serde_json::Value = serde_json::from_str(
        &all.to_string()
            .replace(off.to_str().unwrap(), on.to_str().unwrap()),
    )
    .unwrap();
    // The same verdict, to the digit.
    assert_eq!(d["verdict"], all["verdict"], "{stdout}");
    assert_eq!(d["confounded"], all["confounded"], "{stdout}");
    // Every set cross-validated is the row cross-validating every set
    // gives.
    let rows = |x: &serde_json::Value| x["combinations"].as_array().unwrap().clone();
    for r in rows(&d) {
        let same = rows(&all).into_iter().find(|o| o["effect"] == r["effect"]);
        assert_eq!(Some(&r), same.as_ref(), "{stdout}");
    }
    // Some sets were spared, and said so.
    let sets = spared(&d);
    assert!(!sets.is_empty(), "{stdout}");
    assert!(stdout.contains("sets not cross-validated"), "{stdout}");
    let jn = d["gap"]["noise_level"].as_f64().unwrap();
    for s in &sets {
        let o = &s["outranked"];
        let floor = o["floor"].as_f64().unwrap();
        let best = o["heldout_error"].as_f64().unwrap();
        // Beyond the parsimony window of the step's best (0.1 noise
        // levels), which the pick reads.
        assert!(floor > best + 0.1 * jn, "{s}");
        assert!(stdout.contains(s["effect"].as_str().unwrap()), "{stdout}");
        // Cross-validated after all, it lies at or above its floor: the
        // bound held, and it could not have been read.
        let kept = rows(&all)
            .into_iter()
            .find(|r| set_of(r) == set_of(s))
            .unwrap_or_else(|| panic!("{s} not cross-validated without screening"));
        let j = kept["heldout_error_after"].as_f64().unwrap();
        assert!(
            j >= floor,
            "{} held out {j} below its floor {floor}",
            s["effect"]
        );
    }
    // Fewer candidates cross-validated than with every set: as many fewer
    // as were spared (and the screened ones).
    let count = |x: &serde_json::Value| rows(x).len();
    assert!(count(&d) + sets.len() <= count(&all), "{stdout}");
}
