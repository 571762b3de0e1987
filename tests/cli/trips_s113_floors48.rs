//! `diagnose`'s before → after block names the runs the verdict leaves
//! (session 113, tester round 48, finding 5). A synth campaign with a
//! 50 ms sensor delay, one run's yaw rate logged +0.01 rad/s high (a gyro
//! offset of that run alone): the verdict, the delay, removes 80 % of the
//! yaw rate's gap above noise, and the block said that and no more, while
//! the run stayed 3.4 noise floors off. Now each channel's runs still
//! above three noise floors alone after the verdict are named under its
//! row, on the terminal and the page alike, with their floors before →
//! after, the windows they stay off in and, off before the input, the
//! offset of their sensor that reads so; `diagnosis.json` carries them
//! typed in the all-samples rows of `shrinkage` (`left_in`). The same
//! campaign without the offset, which the verdict explains, names none.

use super::trips_s112_folds47::delay_campaign;
use super::*;

/// The run given a gyro offset of its own.
const OFF_RUN: &str = "step_060kph_2ms2.csv";

/// The offset added to its yaw rate, rad/s.
const GYRO_OFFSET: f64 = 0.01;

/// The all-samples and window rows of `channel` in `d`'s shrinkage.
fn rows<'a>(d: &'a serde_json::Value, channel: &str) -> Vec<&'a serde_json::Value> {
    d["shrinkage"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|r| r["channel"] == channel)
        .collect()
}

/// Run `run`'s part of a shrinkage row: (samples, before, after).
fn part_of(row: &serde_json::Value, run: &str) -> Option<(u64, f64, f64)> {
    let r = row["runs"].as_array()?.iter().find(|r| r["run"] == run)?;
    let f = |k: &str| r[k].as_f64().unwrap();
    Some((r["samples"].as_u64().unwrap(), f("before"), f("after")))
}

/// The runs of `channel` the table itself shows above three noise floors
/// after the verdict (ten samples or more), each with the windows it is
/// above them in: recomputed from the JSON's rows, apart from `left_in`.
fn left_by_table(d: &serde_json::Value, channel: &str) -> Vec<(String, Vec<String>)> {
    let rows = rows(d, channel);
    let all = rows.iter().find(|r| r["part"] == "all").unwrap();
    let floor = all["noise_floor"].as_f64().unwrap();
    let windows = [
        "before the input",
        "first 0.5 s of the input",
        "0.5–2 s after the input",
        "later",
    ];
    all["runs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["run"].as_str().unwrap())
        .filter(|run| part_of(all, run).is_some_and(|(n, _, a)| n >= 10 && a > 3.0 * floor))
        .map(|run| {
            let off: Vec<String> = windows
                .iter()
                .filter(|w| {
                    rows.iter()
                        .find(|r| r["part"] == **w)
                        .and_then(|r| part_of(r, run))
                        .is_some_and(|(n, _, a)| n >= 10 && a > 3.0 * floor)
                })
                .map(|w| w.to_string())
                .collect();
            (run.to_string(), off)
        })
        .collect()
}

/// `left_in` of `channel`'s all-samples row: each run and its parts.
fn left_in(d: &serde_json::Value, channel: &str) -> Vec<(String, Vec<String>)> {
    let all = rows(d, channel)
        .into_iter()
        .find(|r| r["part"] == "all")
        .unwrap();
    let left = all["left_in"].as_array().unwrap_or_else(|| panic!("{all}"));
    left.iter()
        .map(|r| {
            let parts = r["parts"].as_array().unwrap();
            (
                r["run"].as_str().unwrap().to_string(),
                parts.iter().map(|p| p.as_str().unwrap().into()).collect(),
            )
        })
        .collect()
}

#[test]
fn the_run_a_verdict_leaves_off_is_named_in_the_before_after_block() {
    let dir = tempfile::tempdir().unwrap();
    let clean = delay_campaign(dir.path(), "clean");
    let edited = delay_campaign(dir.path(), "edited");
    map_column(&edited.join("runs").join(OFF_RUN), "yaw_rate", |v| {
        v + GYRO_OFFSET
    });
    let both = diagnosed_together(&[clean.clone(), edited.clone()]);
    for (i, (stdout, d)) in both.iter().enumerate() {
        assert!(
            d["verdict"]["statement"]
                .as_str()
                .unwrap()
                .starts_with("sensor_delay explains the gap"),
            "{}",
            d["verdict"]
        );
        // `left_in` is the table's own reading, for every channel.
        for ch in ["yaw_rate", "ay", "beta"] {
            assert_eq!(left_in(d, ch), left_by_table(d, ch), "campaign {i}, {ch}");
        }
        let page = fs::read_to_string([&clean, &edited][i].join("out/report.html")).unwrap();
        let said =
            stdout.contains("still significant alone") || page.contains("still significant alone");
        assert_eq!(said, i == 1, "campaign {i}:\n{stdout}");
    }
    // The campaign the verdict explains names no run.
    let (_, clean_d) = &both[0];
    for ch in ["yaw_rate", "ay", "beta"] {
        assert!(left_in(clean_d, ch).is_empty(), "{ch}");
    }
    // The edited one names its run in the yaw rate alone.
    let (stdout, d) = &both[1];
    let left = left_in(d, "yaw_rate");
    assert_eq!(left.len(), 1, "{left:?}");
    let run = &left[0].0;
    assert!(run.ends_with(OFF_RUN), "{run}");
    assert!(
        left[0].1.contains(&"before the input".to_string()),
        "{left:?}"
    );
    assert!(left_in(d, "ay").is_empty() && left_in(d, "beta").is_empty());
    check_words(stdout, d, run, &edited);
}

/// The words of the run left, on the terminal under the yaw rate's row and
/// on the page, from `diagnosis.json`'s numbers; its steady offset is the
/// one added, within a noise floor.
fn check_words(stdout: &str, d: &serde_json::Value, run: &str, edited: &Path) {
    let all = rows(d, "yaw_rate")
        .into_iter()
        .find(|r| r["part"] == "all")
        .unwrap();
    let floor = all["noise_floor"].as_f64().unwrap();
    let r = &all["left_in"][0];
    let f = |k: &str| r[k].as_f64().unwrap();
    let (_, before, after) = part_of(all, run).unwrap();
    assert!((f("floors_before") - before / floor).abs() < 1e-12, "{r}");
    assert!((f("floors_after") - after / floor).abs() < 1e-12, "{r}");
    assert!(f("floors_after") > 3.0, "{r}");
    // The residual is simulated − measured: the gyro's +0.01 reads −0.01
    // through the run, within a noise floor (the noise's mean over 151
    // samples is a twelfth of one; the replay, started from the measured
    // state, follows a little of the offset at first).
    let o = &r["steady_offset"];
    let mean = o["mean_residual"].as_f64().unwrap();
    assert!((mean + GYRO_OFFSET).abs() < floor, "{o} against {floor}");
    assert!((o["floors"].as_f64().unwrap() - mean.abs() / floor).abs() < 1e-12);
    assert!(o["share"].as_f64().unwrap() >= 0.5, "{o}");
    let parts: Vec<&str> = r["parts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p.as_str().unwrap())
        .collect();
    let head = "yaw_rate: 1 of 8 runs still significant alone (above 3 noise floors over the run's held-out samples, the ones the verdict is scored on; where the gap lies reads a run over all its samples, so its figure there can differ), which the share removed does not show:";
    // Its held-out samples, the all-samples row's part of the run.
    let samples = r["samples"].as_u64().unwrap();
    assert_eq!(Some(samples), part_of(all, run).map(|p| p.0), "{r}");
    let line = format!(
        "{run}: {:.1} → {:.1} noise floors over its {samples} held-out samples; above them in: {}; off before the input too, where the response has not begun, and steady over the run: mean residual {mean:.4} rad/s ({:.1} noise floors, {:.0} % of its mean square), which reads as a zero offset of that run's yaw_rate sensor of {:+.4} rad/s (a sensor's offset reads as a residual of the opposite sign), the run's own, which the verdict's effects, fitted to every run, do not take up",
        f("floors_before"),
        f("floors_after"),
        parts.join(", "),
        o["floors"].as_f64().unwrap(),
        100.0 * o["share"].as_f64().unwrap(),
        -mean,
    );
    // Under the yaw rate's row, before the ay row.
    let lines: Vec<&str> = stdout.lines().collect();
    let at = lines
        .iter()
        .position(|l| l.starts_with("  yaw_rate  ") && l.contains("of the gap above noise removed"))
        .unwrap_or_else(|| panic!("{stdout}"));
    assert_eq!(lines[at + 1], format!("    {head}"), "{stdout}");
    assert_eq!(lines[at + 2], format!("      {line}"), "{stdout}");
    assert!(lines[at + 3].starts_with("  ay        "), "{stdout}");
    let page = fs::read_to_string(edited.join("out/report.html")).unwrap();
    assert!(
        page.contains(&format!("<p>{}</p>", escaped(head))),
        "{head}"
    );
    assert!(
        page.contains(&format!("<li>{}</li>", escaped(&line))),
        "{line}"
    );
}
