//! What round 41's fresh-eyes tester tripped on that the lead fixed
//! (session 109): `metrics` on a run whose yaw rate and ay drift without
//! slowing after the step printed its response times, E_r and Er as plain
//! numbers — 90 % crossings of a level the response passes on its way
//! (2.75 s where the car's is 0.19 s) — and "no overshoot" above it.

use super::*;

use crate::trips_s108_lead::{logged, sedan_rows};

/// The metric table's line that starts with `name`.
fn line<'a>(table: &'a str, name: &str) -> &'a str {
    table
        .lines()
        .find(|l| l.trim_start().starts_with(name))
        .unwrap_or_else(|| panic!("no `{name}` line in {table}"))
}

/// A yaw rate and ay rising linearly after the bundled sedan's step
/// (0.004 rad/s per s, ay u times that): the metrics defined against a
/// steady value are marked as read against none, the overshoot is not
/// given as below a bound, and the table says why; the same run without
/// the drift is marked nowhere.
#[test]
fn metrics_read_against_a_drifting_level_are_marked_as_having_no_steady_state() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let drift = logged(&rows, dir.path(), "drift.csv", |mut c| {
        let ramp = 0.004 * (c[0] - 1.0).max(0.0);
        c[4] += ramp;
        c[5] += 22.22 * ramp;
        c
    });
    let clean = logged(&rows, dir.path(), "clean.csv", |c| c);
    let table = succeeds(&["metrics", drift.to_str().unwrap()]);
    for name in [
        "yaw-rate response time",
        "ay response time",
        "yaw-rate gain",
        "steady ay",
        "E_r (yaw rate)",
        "E_ay",
        "Er ",
    ] {
        assert!(
            line(&table, name).ends_with("(no steady state)"),
            "{name}: {table}"
        );
    }
    assert!(
        line(&table, "yaw-rate overshoot").contains("— %"),
        "{table}"
    );
    assert!(!table.contains("no overshoot:"), "{table}");
    assert!(table.contains("no steady state: the yaw rate and the lateral acceleration drift without slowing through the steady window"), "{table}");
    // Not its steady sideslip: β does not drift.
    assert!(
        !line(&table, "steady sideslip").contains("no steady"),
        "{table}"
    );
    let table = succeeds(&["metrics", clean.to_str().unwrap()]);
    assert!(!table.contains("no steady state"), "{table}");
}
