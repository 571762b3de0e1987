//! What a fresh-eyes user tripped on in round 35, in the diagnosis's
//! words: a channel within noise alone (the table's "not significant
//! alone") called "a gap spread over the runs" on the terminal and the
//! page; a verdict carried by a delay on its search bound said to explain
//! part of the gap as if it measured the delay; a lag on its physical
//! limit written `3.959e-5 s` beside another's `0.0000 s`.

use super::*;

/// The line of `said` that starts with `head` (after its indent).
fn line_of<'a>(said: &'a str, head: &str) -> &'a str {
    said.lines()
        .map(str::trim_start)
        .find(|l| l.starts_with(head))
        .unwrap_or_else(|| panic!("no line {head:?}: {}", without_temp_names(said)))
}

/// The book's narrowed synthetic campaign (`synth --effects sensor_delay
/// --seed 1`, candidates sensor_delay and relaxation_length): beta's gap
/// is 1.2 noise floors over the runs, and the table says "not significant
/// alone". Its line under "where the gap lies" read "so a gap spread over
/// the runs, not in one place" on the terminal and the page. Now it says
/// the channel is within noise alone, no gap of its own, and where the
/// combined gap lies: in the channels significant by the table's rule.
#[test]
fn a_channel_the_table_calls_not_significant_alone_is_no_gap_of_its_own() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "c",
        &["--effects", "sensor_delay", "--seed", "1"],
    );
    let vehicle = c.join("vehicle.toml");
    let toml = fs::read_to_string(&vehicle).unwrap();
    fs::write(
        &vehicle,
        format!("{toml}effects = [\"sensor_delay\", \"relaxation_length\"]\n"),
    )
    .unwrap();
    let out = dir.path().join("out");
    let (said, d) = diagnose_to(&c, &out);
    // The table: beta within noise alone, yaw_rate and ay not.
    let table = line_of(&said, "beta  ");
    assert!(table.contains("not significant alone (1.2"), "{table}");
    for ch in ["yaw_rate  ", "ay  "] {
        let row = line_of(&said, ch);
        assert!(row.contains("of the gap above noise removed"), "{row}");
    }
    let line = line_of(&said, "beta: RMS ");
    assert!(
        line.contains(
            ": within noise alone (1.2 noise floors over the runs, below the 3 a channel, run or part needs alone), so no gap of its own; the significant gap lies in yaw_rate and ay"
        ),
        "{line}"
    );
    assert!(!line.contains("a gap spread"), "{line}");
    // The JSON's summary and the page say the same words.
    let summary: Vec<&str> = d["gap"]["summary"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|s| s.as_str())
        .collect();
    assert!(summary.contains(&line), "{summary:?}");
    let page = fs::read_to_string(out.join("report.html")).unwrap();
    assert!(page.contains("so no gap of its own; the significant gap lies in yaw_rate and ay"));
    assert!(!page.contains("a gap spread over the runs"));
    let finding = d["gap"]["findings"]
        .as_array()
        .unwrap()
        .iter()
        .find(|f| f["kind"] == "channel" && f["channel"] == "beta")
        .unwrap();
    assert_eq!(
        finding["combined"]["significant_alone"],
        serde_json::json!(["yaw_rate", "ay"]),
        "{finding}"
    );
}

/// The Putnam log with the candidates narrowed to sensor_delay and
/// relaxation_length: the verdict, sensor_delay "explains most of the
/// gap", rests on a delay on the 0.3 s end of its search range, which only
/// a warning below said. A verdict whose parameter sits on its search
/// bound is no measurement of that effect's physics: its statement (the
/// terminal's verdict line, the JSON's and the page's) says so, and the
/// JSON lists the parameter (`verdict.on_search_bound`). Which effect wins
/// is unchanged.
#[test]
fn a_verdict_whose_delay_sits_on_its_search_bound_says_it_is_no_measurement_of_it() {
    let test = "a_verdict_whose_delay_sits_on_its_search_bound_says_it_is_no_measurement_of_it";
    let Some(log) = shared_data(test, "run_iac_putnam/putnam_run4_2.csv") else {
        return;
    };
    let text = putnam_campaign(&log, "effects = [\"sensor_delay\", \"relaxation_length\"]");
    let dir = scratch(&[("putnam.toml", &text)]);
    let out = dir.path().join("out");
    let (said, d) = diagnose_to(&dir.path().join("putnam.toml"), &out);
    let v = &d["verdict"];
    assert_eq!(v["effects"], serde_json::json!(["sensor_delay"]), "{v}");
    assert_eq!(v["parameters"][0]["bound"], "search", "{v}");
    assert_eq!(
        v["on_search_bound"],
        serde_json::json!(["sensor_delay.delay"]),
        "{v}"
    );
    let statement = v["statement"].as_str().unwrap();
    assert!(
        statement.contains("; sensor_delay.delay = 0.3000 s on its search bound, so the verdict is not a measurement of sensor_delay: the runs would take it beyond the range the library allows, and the cause may be sensor_delay beyond that range, or a different effect that sensor_delay at its limit imitates"),
        "{statement}"
    );
    let line = line_of(&said, "verdict: ");
    assert_eq!(line, format!("verdict: {statement}"));
    let page = fs::read_to_string(out.join("report.html")).unwrap();
    assert!(page.contains("so the verdict is not a measurement of sensor_delay"));
}

/// A synthetic campaign with a sensor delay and a relaxation length
/// (seed 2), its candidates sensor_delay, relaxation_length and
/// steer_path: steer_path+relaxation_length fits its lag to 3.959e-5 s,
/// on its physical limit 0, and the table wrote `steer_path.lag =
/// 3.959e-5 s` where the rows beside it wrote `steer_path.lag = 0.0000 s`
/// for the same finding. A value on its physical limit is now written as
/// the limit, in the notation of the rest (the JSON keeps the fitted
/// value).
#[test]
fn a_lag_on_its_physical_limit_reads_as_the_limit_in_every_row() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "c",
        &["--effects", "sensor_delay,relaxation_length", "--seed", "2"],
    );
    let vehicle = c.join("vehicle.toml");
    let toml = fs::read_to_string(&vehicle).unwrap();
    fs::write(
        &vehicle,
        format!("{toml}effects = [\"sensor_delay\", \"relaxation_length\", \"steer_path\"]\n"),
    )
    .unwrap();
    let out = dir.path().join("out");
    let (said, d) = diagnose_to(&c, &out);
    // The premise: a set fits the lag a hair above its limit.
    let lags: Vec<f64> = d["combinations"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|r| r["parameters"].as_array().unwrap())
        .filter(|p| p["name"] == "steer_path.lag" && p["bound"] == "physical")
        .map(|p| p["value"].as_f64().unwrap())
        .collect();
    assert!(lags.iter().any(|&l| l > 0.0 && l < 1e-4), "{lags:?}");
    let page = fs::read_to_string(out.join("report.html")).unwrap();
    for text in [said.as_str(), page.as_str()] {
        let written: Vec<&str> = text
            .split("steer_path.lag = ")
            .skip(1)
            .filter_map(|s| s.split_once(' '))
            .filter(|(_, rest)| rest.starts_with("s (at its physical limit"))
            .map(|(value, _)| value)
            .collect();
        assert!(!written.is_empty(), "{}", without_temp_names(&said));
        assert!(written.iter().all(|w| *w == "0.0000"), "{written:?}");
    }
    let row = line_of(&said, "steer_path+relaxation_length ");
    assert!(
        row.contains("steer_path.lag = 0.0000 s (at its physical limit: any smaller value would be negative)"),
        "{row}"
    );
}
