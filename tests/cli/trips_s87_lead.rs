//! What a fresh user tripped on (round 14), fixed by the lead: a yaw rate
//! logged at a logger's resolution whose flat top hid its overshoot, and a
//! long log's segment named as a file in the other sign convention.

use super::sedan_runs::{run_text, sedan_history};
use super::*;

/// `text` (a run file's, `t,speed,steer,yaw_rate,…`) with the yaw rate
/// rounded to `step` rad/s: a logger's resolution.
fn quantise_yaw_rate(text: &str, step: f64) -> String {
    let mut out = String::new();
    for (k, line) in text.lines().enumerate() {
        let mut cells: Vec<String> = line.split(',').map(String::from).collect();
        if k > 0 {
            let r: f64 = cells[3].parse().unwrap();
            cells[3] = format!("{:.4}", (r / step).round() * step);
        }
        out += &(cells.join(",") + "\n");
    }
    out
}

/// `metrics --filter-hz 0 --json` on `file`.
fn unfiltered(file: &Path) -> serde_json::Value {
    let o = run(&[
        "metrics",
        file.to_str().unwrap(),
        "--filter-hz",
        "0",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    serde_json::from_slice(&o.stdout).unwrap()
}

/// The sedan's 1° step at 50 Hz with its yaw rate rounded to 0.001 rad/s
/// holds its maximum over four equal samples: read unfiltered, it said "no
/// overshoot" (`yaw_rate_overshoot` null, TB lost) where the same samples
/// unrounded overshoot by 16.9 %. The flat top is one peak at its middle:
/// overshoot and peak time as the unrounded log's, within the rounding.
#[test]
fn a_quantised_yaw_rate_keeps_its_overshoot_and_peak_time() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let exact = run_text(&history, 20, None);
    let (a, b) = (dir.path().join("exact.csv"), dir.path().join("rounded.csv"));
    fs::write(&a, &exact).unwrap();
    fs::write(&b, quantise_yaw_rate(&exact, 0.001)).unwrap();
    let e = unfiltered(&a);
    let q = unfiltered(&b);
    let f = |d: &serde_json::Value, k: &str| {
        d[k].as_f64()
            .unwrap_or_else(|| panic!("{k} is {} in {d}", d[k]))
    };
    // The rounding moves the top by at most half a step of a 0.065 rad/s
    // steady yaw rate: under 1 point of overshoot.
    assert!(
        (f(&q, "yaw_rate_overshoot") - f(&e, "yaw_rate_overshoot")).abs() < 1.0,
        "{} against {}",
        q["yaw_rate_overshoot"],
        e["yaw_rate_overshoot"]
    );
    assert!(f(&e, "yaw_rate_overshoot") > 10.0, "{e}");
    // The peak time within one 0.02 s sample of the unrounded log's.
    assert!(
        (f(&q, "yaw_rate_peak_time") - f(&e, "yaw_rate_peak_time")).abs() <= 0.02 + 1e-9,
        "{} against {}",
        q["yaw_rate_peak_time"],
        e["yaw_rate_peak_time"]
    );
    assert!(q["tb"].as_f64().is_some(), "{q}");
}
