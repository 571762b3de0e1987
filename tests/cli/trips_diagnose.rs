//! What a fresh-eyes check found a user trips on in `diagnose`'s outputs,
//! run as a user runs the tool: each test one finding, and
//! what the terminal, `report.html` and `diagnosis.json` now say.

use super::*;

/// A ranking row of the page (`<tr>` of the ranking table up to `</tr>`).
fn page_row<'a>(page: &'a str, effect: &str) -> &'a str {
    let at = page
        .find("<table id=\"ranking-table\"")
        .expect("ranking table");
    let start = at + page[at..].find(&format!("<tr><td>{effect}</td>")).unwrap();
    &page[start..start + page[start..].find("</tr>").unwrap()]
}

/// On a campaign without a gap the terminal printed the reductions
/// (21.7 %, or a negative share: a "worsening") where the page said "not
/// significant": both now decide by one rule and say it alike.
#[test]
fn a_reduction_within_noise_reads_the_same_on_terminal_and_page() {
    let dir = tempfile::tempdir().unwrap();
    let (stdout, d, page) = narrowed(
        dir.path(),
        "none",
        "\"cornering_stiffness\", \"steering_compliance\"",
    );
    assert_eq!(d["gap"]["significant"], false, "{}", d["gap"]);
    let line = stdout
        .lines()
        .find(|l| l.trim_start().starts_with("cornering_stiffness "))
        .unwrap_or_else(|| panic!("no cornering_stiffness row: {stdout}"));
    assert!(line.contains("not significant"), "{line}");
    assert!(!line.contains(" %"), "a share of noise printed: {line}");
    let row = page_row(&page, "cornering_stiffness");
    assert_eq!(row.matches("not significant").count(), 2, "{row}");
}

/// `shrinkage` wrote −73 % for a part whose gap is noise before and after;
/// `gap.parts` wrote after = before although the verdict changed them
/// (now not written: the same rows as `shrinkage`).
#[test]
fn a_part_within_noise_has_no_percentage_and_the_gap_parts_have_the_verdicts_after() {
    let dir = tempfile::tempdir().unwrap();
    let (_, d, _) = narrowed(dir.path(), "sensor_delay", "\"sensor_delay\"");
    assert_eq!(verdict_of(&d), ["sensor_delay"]);
    let rows = d["shrinkage"].as_array().unwrap();
    let mut within = 0;
    for s in rows {
        let f = |k: &str| s[k].as_f64().unwrap();
        let noise = f("before") <= 3.0 * f("noise_floor") && f("after") <= 3.0 * f("noise_floor");
        if noise {
            within += 1;
            assert!(s["reduction_percent"].is_null(), "{s}");
            assert_eq!(s["change"], "within_noise", "{s}");
        } else {
            assert!(s["reduction_percent"].is_f64(), "{s}");
            assert_ne!(s["change"], "within_noise", "{s}");
        }
    }
    assert!(within > 0, "no part within noise: {rows:?}");
    // The rows are written once (`gap.parts` repeated them, a third of
    // the file twice over), with the verdict's after.
    assert!(d["gap"].get("parts").is_none(), "{}", d["gap"]);
    assert!(rows.iter().any(|p| p["after"] != p["before"]), "{rows:?}");
}

/// A pair was fitted in both orders and listed twice
/// (`steer_path+sensor_delay` and `sensor_delay+steer_path`): a set of
/// effects is one candidate. The verdict is unchanged.
#[test]
fn a_set_of_effects_is_listed_once_whatever_its_order() {
    let dir = tempfile::tempdir().unwrap();
    let (stdout, d, _) = narrowed(
        dir.path(),
        "sensor_delay,yaw_inertia",
        "\"sensor_delay\", \"steer_path\"",
    );
    assert_eq!(verdict_of(&d), ["steer_path"]);
    // Cross-validated, or screened as a set the greedy additions could not
    // add to (`extends`): one row either way.
    let screened_sets = d["screened"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s.get("extends").is_some());
    let sets: Vec<Vec<String>> = d["combinations"]
        .as_array()
        .unwrap()
        .iter()
        .chain(screened_sets)
        .map(|c| {
            let mut s: Vec<String> = c["effects"]
                .as_array()
                .unwrap()
                .iter()
                .map(|e| e.as_str().unwrap().to_string())
                .collect();
            s.sort();
            s
        })
        .collect();
    assert_eq!(sets, [["sensor_delay", "steer_path"]], "{stdout}");
    let pairs = stdout
        .lines()
        .filter(|l| l.contains("sensor_delay+steer_path") || l.contains("steer_path+sensor_delay"))
        .filter(|l| !l.trim_start().starts_with("verdict"))
        .count();
    assert_eq!(pairs, 1, "{stdout}");
}
