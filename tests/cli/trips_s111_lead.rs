//! Round 45's findings on `metrics` (session 111), on records made from
//! the bundled sedan's 1° step (`simulate`, 1 kHz rows, every 10th kept):
//! 1. a steer logged in steps of 0.001 rad (its 1° step 17 counts) and a
//!    gyro with 0.0005 rad/s of noise read the gain 2.3 % high while its
//!    stated spread was 0.1 %, and nothing said the steer's grid: a
//!    logger's rounding of a held channel is no noise the copies see;
//! 3. a response time at or below 0 was printed as a value (and its
//!    "sample intervals" counted): it is marked "(before the steer)";
//! 6. the table's marks ("(no steady state)", …) were not in `--json`: both
//!    now come from one function, and the JSON's `marks` are the table's.

use crate::calibration::Noise;
use crate::trips_s111_metrics44::{measured, sedan_rows, written};

/// The table's marked metrics: each row's JSON name and its marks, read
/// from the terminal's lines.
fn table_marks(table: &str) -> Vec<(String, Vec<String>)> {
    let rows = [
        ("yaw-rate response time", "yaw_rate_response_time"),
        ("yaw-rate peak time", "yaw_rate_peak_time"),
        ("yaw-rate overshoot", "yaw_rate_overshoot"),
        ("ay response time", "ay_response_time"),
        ("yaw-rate gain", "yaw_rate_gain"),
        ("steady ay", "ay_steady"),
        ("TB", "tb"),
        ("E_r (yaw rate)", "yaw_rate_total_variance"),
        ("E_ay", "ay_total_variance"),
        ("Er ", "er"),
    ];
    let words = [
        ("(no steady state)", "no_steady_state"),
        ("(moving window)", "moving_window"),
        ("(steer misaligned)", "steer_misaligned"),
        ("(before the steer)", "before_the_steer"),
    ];
    let mut out = Vec::new();
    for (label, key) in rows {
        let line = table
            .lines()
            .find(|l| l.trim_start().starts_with(label))
            .unwrap_or_else(|| panic!("no `{label}` row in\n{table}"));
        let marks: Vec<String> = words
            .iter()
            .filter(|(w, _)| line.contains(w))
            .map(|(_, k)| k.to_string())
            .collect();
        if !marks.is_empty() {
            out.push((key.to_string(), marks));
        }
    }
    out
}

/// The JSON's `marks`, as [`table_marks`] lists them.
fn json_marks(j: &serde_json::Value) -> Vec<(String, Vec<String>)> {
    let mut out: Vec<(String, Vec<String>)> = j["marks"]
        .as_object()
        .expect("marks")
        .iter()
        .map(|(k, v)| {
            let mut m: Vec<String> = v
                .as_array()
                .unwrap()
                .iter()
                .map(|s| s.as_str().unwrap().to_string())
                .collect();
            m.sort();
            (k.clone(), m)
        })
        .collect();
    out.sort();
    out
}

fn sorted(mut v: Vec<(String, Vec<String>)>) -> Vec<(String, Vec<String>)> {
    for (_, m) in v.iter_mut() {
        m.sort();
    }
    v.sort();
    v
}

/// Finding 1: the steer rounded to 0.001 rad and the yaw rate given gyro
/// noise below its own grid-free resolution: the steer's grid is said with
/// its count, and the gain's stated spread holds the rounding (q/√12 of
/// the step, 1.65 %), so that the gain read lies within two spreads of
/// the unrounded record's; the unrounded noisy record states a spread
/// below 0.5 % and no grid.
#[test]
fn a_steer_logged_in_coarse_counts_widens_the_gains_spread_and_is_said() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let q = 0.001;
    let mut n = Noise(7);
    let noisy: Vec<f64> = rows.iter().map(|_| 0.0005 * n.gauss()).collect();
    let clean = written(&rows, dir.path(), "noisy.csv", 10, |i, mut r| {
        r[4] += noisy[i];
        r
    });
    let rounded = written(&rows, dir.path(), "steer_q.csv", 10, |i, mut r| {
        r[1] = (r[1] / q).round() * q;
        r[4] += noisy[i];
        r
    });
    let (jc, wc, _) = measured(&clean, &[]);
    let (jq, wq, _) = measured(&rounded, &[]);
    let truth = jc["yaw_rate_gain"].as_f64().unwrap();
    let clean_spread = jc["yaw_rate_gain_spread"].as_f64().unwrap_or(0.0);
    assert!(clean_spread < 0.005, "{clean_spread}");
    assert!(!wc.contains("steer is written in steps"), "{wc}");
    let gain = jq["yaw_rate_gain"].as_f64().unwrap();
    let spread = jq["yaw_rate_gain_spread"].as_f64().unwrap();
    // The rounding's share: q/√12 over the 1° step.
    let share = q / 12f64.sqrt() / 1f64.to_radians();
    assert!(
        spread >= share && spread < share * 1.2,
        "{spread} vs {share}"
    );
    let off = (gain / truth - 1.0).abs();
    assert!(off > 0.01, "the rounding moves the gain: {off}");
    assert!(
        off < 2.0 * spread,
        "{gain} vs {truth}: {off} > 2 × {spread}"
    );
    assert!(
        wq.contains("steer is written in steps of 0.0573 deg and its step is")
            && wq.contains("17 of them"),
        "{wq}"
    );
}

/// Findings 3 and 6: the ay column moved 0.6 s earlier leads the steer,
/// its response time below 0 is marked "(before the steer)" and gets no
/// sample-interval words; the steer logged 80 ms late marks its times and
/// variances. On both, and on the clean record (no marks), the JSON's
/// `marks` are the table's, row by row.
#[test]
fn the_tables_marks_are_the_jsons_and_a_response_before_the_steer_is_marked() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let len = rows.len();
    let early = written(&rows, dir.path(), "ay_early.csv", 10, |i, mut r| {
        r[5] = rows[(i + 600).min(len - 1)][5];
        r
    });
    let late = written(&rows, dir.path(), "late.csv", 10, |i, mut r| {
        r[1] = rows[i.saturating_sub(80)][1];
        r
    });
    let clean = written(&rows, dir.path(), "clean.csv", 10, |_, r| r);
    let (j, w, table) = measured(&early, &[]);
    assert!(j["ay_response_time"].as_f64().unwrap() <= 0.0, "{j}");
    let ay_row = table
        .lines()
        .find(|l| l.contains("ay response time"))
        .unwrap();
    assert!(ay_row.ends_with("(before the steer)"), "{ay_row}");
    assert!(
        table.contains("  before the steer: a response time marked"),
        "{table}"
    );
    assert!(!w.contains("the ay response time, -"), "{w}");
    assert_eq!(
        j["marks"]["ay_response_time"],
        serde_json::json!(["before_the_steer"])
    );
    for run in [&early, &late, &clean] {
        let (j, _, table) = measured(run, &[]);
        assert_eq!(sorted(table_marks(&table)), json_marks(&j), "{table}");
    }
    let (j, _, _) = measured(&late, &[]);
    assert!(
        j["marks"]["er"].to_string().contains("steer_misaligned"),
        "{j}"
    );
    let (j, _, _) = measured(&clean, &[]);
    assert_eq!(j["marks"], serde_json::json!({}));
}

/// Round 46's finding 1: one pressure cell typed in psi (32) among
/// pressures in Pa (220000) was offered as "32000 Pa (32 kPa)", which a
/// .tir's PRESMIN to PRESMAX also holds: the reading nearest the column's
/// median is offered, 32 psi = 220632 Pa; a cell in kPa (230) still reads
/// as kPa.
#[test]
fn a_pressure_cell_in_psi_among_pascals_is_offered_as_psi() {
    let test = "a_pressure_cell_in_psi_among_pascals_is_offered_as_psi";
    let Some(tir) = super::shared_data(test, "tir_public/car205_60R19.tir") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    for (cell, said) in [
        ("32", "did you mean 220632 Pa (32 psi)"),
        ("230", "did you mean 230000 Pa (230 kPa)"),
    ] {
        let points = dir.path().join("points.csv");
        std::fs::write(
            &points,
            format!(
                "fz,kappa,alpha,camber,speed,pressure\n4000,0,0.05,0,20,220000\n4000,0,0.05,0,20,{cell}\n4000,0,0.05,0,20,220000\n"
            ),
        )
        .unwrap();
        let out = dir.path().join("out.csv");
        let o = super::run(&[
            "tyre-eval",
            tir.to_str().unwrap(),
            points.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(!o.status.success());
        let e = super::stderr(&o);
        assert!(
            e.contains("points.csv:3:6") && e.contains(said),
            "{cell}: {e}"
        );
    }
}
