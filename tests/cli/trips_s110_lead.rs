//! What round 43's fresh-eyes tester tripped on that the lead fixed
//! (session 110): `metrics` on a run whose yaw rate rises 10 %/s to the
//! record's end said it "spreads by 2.1 % … may be off by up to about
//! 2.1 %", its gain 40 % above the car's: a ramp's spread about its
//! window's mean is a fraction of its rise.

use super::*;

use crate::trips_s108_lead::{logged, sedan_rows};

/// The bundled sedan's logged step with its yaw rate scaled by
/// 1 + 0.1·(t − 1.5) after 1.5 s (round 43's file): the yaw rate is said
/// to drift without slowing, no bound is given for its gain, the gain is
/// marked as read against no steady state, and `--json` says `drifting`;
/// the same run unscaled says none of it.
#[test]
fn a_yaw_rate_ramping_to_the_records_end_is_drifting_and_bounds_no_gain() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let ramp = logged(&rows, dir.path(), "ramp.csv", |mut c| {
        c[4] *= 1.0 + 0.1 * (c[0] - 1.5).max(0.0);
        c
    });
    let clean = logged(&rows, dir.path(), "clean.csv", |c| c);
    let said = |path: &Path| {
        let o = run(&["metrics", path.to_str().unwrap()]);
        assert!(o.status.success(), "{}", stderr(&o));
        (String::from_utf8_lossy(&o.stdout).into_owned(), stderr(&o))
    };
    let (table, warned) = said(&ramp);
    let table = format!("{warned}{table}");
    assert!(
        table.contains("the yaw rate is still drifting")
            && table.contains("it drifts without slowing"),
        "{table}"
    );
    assert!(!table.contains("off by up to"), "{table}");
    let gain = table
        .lines()
        .find(|l| l.trim_start().starts_with("yaw-rate gain"))
        .unwrap();
    assert!(gain.ends_with("(no steady state)"), "{table}");
    let json = succeeds(&["metrics", ramp.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    let yaw = &v["settling"]["yaw_rate"];
    assert_eq!(yaw["verdict"], "drifting", "{yaw}");
    assert_eq!(yaw["converging"], false, "{yaw}");
    assert_eq!(yaw["rising"], true, "{yaw}");
    let (table, warned) = said(&clean);
    let table = format!("{warned}{table}");
    assert!(
        !table.contains("drift") && !table.contains("not settled"),
        "{table}"
    );
}
