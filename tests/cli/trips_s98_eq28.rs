//! What round 27 left open in `equilibria`, `study` and `fleet` (session
//! 98): a two-axis sweep drew its branch diagrams at the first speed only,
//! where none of its bifurcations were; a copied runs folder, or a shard
//! file copied under another name, was counted twice (or refused); the
//! study's summary line called "steady" a sideslip its notes call still
//! moving.

use super::*;
use std::fs;

/// Li, Jia & Zhao's steer sweep at four speeds (the tester's `eq_2d.toml`):
/// the simplified Magic Formula on both axles, small-angle, no load
/// transfer.
fn two_axis_sweep(speeds: &str) -> String {
    let tyre = root().join("tyres/magic_simple.toml");
    format!(
        "name = \"eq_2d\"\n[vehicle]\nmass = 1530.0\nyaw_inertia = 2315.0\na = 1.11\nb = 1.67\ntrack_front = 1.55\ntrack_rear = 1.55\ncg_height = 0.55\n[tyres]\nfront = \"{}\"\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n[sweep]\nsteer = {{ from = 0.0, to = 0.2, step = 0.02 }}\nfriction = 0.8\nspeed = {speeds}\n[pso]\nseed = 1\n",
        tyre.display()
    )
}

/// The files of `dir` whose names start with `prefix` and end with `ext`,
/// sorted.
fn named(dir: &Path, prefix: &str, ext: &str) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with(prefix) && n.ends_with(ext))
        .collect();
    names.sort();
    names
}

/// Round 27, finding 8: steer × 4 speeds reported 13 pitchforks, and
/// `branches_steer.png` drew speed 30 km/h only ("the first of 4"), which
/// has none. Now one diagram per speed along steer and one per steer along
/// speed, named by the value; every bifurcation along steer is joined to
/// its branches in the diagram of its own speed; the terminal says which
/// file shows what.
#[test]
fn a_two_axis_sweep_draws_a_branch_diagram_per_value_of_the_other_axis() {
    let sweep = two_axis_sweep("{ from = 30.0, to = 120.0, step = 30.0, unit = \"km/h\" }");
    let dir = scratch(&[("eq_2d.toml", &sweep)]);
    let o = run_in(dir.path(), &["equilibria", "eq_2d.toml", "--out", "o"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    let out = dir.path().join("o");
    let speeds = [30, 60, 90, 120];
    let along_steer: Vec<String> = speeds
        .iter()
        .map(|u| format!("branches_steer_speed_{u}kmh.png"))
        .collect();
    let mut sorted = along_steer.clone();
    sorted.sort();
    assert_eq!(named(&out, "branches_steer", ".png"), sorted);
    assert_eq!(named(&out, "branches_speed", ".png").len(), 11);
    assert!(!out.join("branches_steer.png").exists());
    assert!(
        said.contains("  branch diagrams along steer, one per speed (4 figures): branches_steer_speed_30kmh.png … branches_steer_speed_120kmh.png, each with its .csv\n")
            && said.contains("  branch diagrams along speed, one per steer (11 figures): branches_speed_steer_0deg.png … branches_speed_steer_11.4592deg.png")
            && said.contains("  stability_map.png: steer × speed, every swept value, bifurcations along them marked; coloured by the equilibria in the box at each point (points): 1 stable + 1 saddle ("),
        "{said}"
    );
    // Every bifurcation along steer is drawn in its speed's diagram: a
    // branch end joined to it, at its steer (SI in the .csv).
    let bif = fs::read_to_string(out.join("bifurcations.csv")).unwrap();
    let along: Vec<Vec<&str>> = bif
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|r| r[1] == "steer")
        .collect();
    let speeds_with: std::collections::BTreeSet<i64> = along
        .iter()
        .map(|r| (r[4].parse::<f64>().unwrap() * 3.6).round() as i64)
        .collect();
    assert!(
        speeds_with.len() >= 2,
        "bifurcations at {speeds_with:?}: {bif}"
    );
    assert!(!speeds_with.contains(&30), "{bif}");
    for r in &along {
        let u = (r[4].parse::<f64>().unwrap() * 3.6).round() as i64;
        let csv = fs::read_to_string(out.join(format!("branches_steer_speed_{u}kmh.csv"))).unwrap();
        let steer: f64 = r[2].parse().unwrap();
        let joined = csv.lines().skip(1).any(|l| {
            let c: Vec<&str> = l.split(',').collect();
            c[7] == r[0] && (c[4].parse::<f64>().unwrap() - steer).abs() < 1e-12
        });
        assert!(
            joined,
            "{} at steer {steer} not in speed {u}'s diagram:\n{csv}",
            r[0]
        );
    }
}

/// Round 27: a fleet counted campaign files naming one runs folder once,
/// but a copied runs folder (the same bytes under another name) twice,
/// "in the verdict of 2 of 2 diagnosed campaigns". Now counted once, and
/// said with the pair.
#[test]
fn a_copied_runs_folder_is_counted_once_and_named() {
    let dir = tempfile::tempdir().unwrap();
    let batch = dir.path().join("batch");
    fs::create_dir(&batch).unwrap();
    // A campaign with a gap, so that its verdict recurs in the fleet's
    // table (a campaign without one has no best candidate to count).
    synth_campaign(&batch, "c", &["--effects", "sensor_delay", "--seed", "1"]);
    synth_campaign(&batch, "e", &["--effects", "sensor_delay", "--seed", "1"]);
    let out = dir.path().join("out");
    let o = run(&[
        "diagnose",
        "--batch",
        batch.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let s = String::from_utf8_lossy(&o.stdout);
    let c = batch.join("c/runs").canonicalize().unwrap();
    let e = batch.join("e/runs").canonicalize().unwrap();
    assert!(
        s.contains(&format!(
            "  note: 1 campaign reads run files identical, byte for byte, to another's in another folder (a copy): counted once below: e = c ({} = {})\n",
            e.display(),
            c.display()
        )),
        "{s}"
    );
    let recurring: Vec<&str> = s
        .lines()
        .filter(|l| l.contains("diagnosed campaigns"))
        .collect();
    assert!(!recurring.is_empty(), "{s}");
    assert!(
        recurring
            .iter()
            .all(|l| l.contains(" of 1 diagnosed campaigns")),
        "{s}"
    );
    // Both rows stay in the table: nothing dropped.
    let csv = fs::read_to_string(out.join("fleet.csv")).unwrap();
    assert_eq!(csv.lines().count(), 3, "{csv}");
}

/// A shard file copied under another name (`merge o/*.json` with a copy
/// beside the shards) was refused as "given twice"; bytes for bytes the
/// same, it is read once and said; the merge writes the unsharded run's
/// files.
#[test]
fn a_shard_file_given_twice_under_two_names_is_read_once() {
    let sweep = two_axis_sweep("{ values = [60.0, 90.0], unit = \"km/h\" }");
    let dir = scratch(&[("eq_2d.toml", &sweep)]);
    for k in ["1/2", "2/2"] {
        let o = run_in(
            dir.path(),
            &["equilibria", "eq_2d.toml", "--shard", k, "--out", "sh"],
        );
        assert!(o.status.success(), "{}", stderr(&o));
    }
    fs::copy(
        dir.path().join("sh/shard-1-of-2.json"),
        dir.path().join("sh/copy.json"),
    )
    .unwrap();
    let o = run_in(
        dir.path(),
        &[
            "merge",
            "sh/shard-1-of-2.json",
            "sh/copy.json",
            "sh/shard-2-of-2.json",
            "--out",
            "merged",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("  note: 1 shard file identical, byte for byte, to another given before: counted once: sh/copy.json = sh/shard-1-of-2.json\n"),
        "{said}"
    );
    let o = run_in(dir.path(), &["equilibria", "eq_2d.toml", "--out", "whole"]);
    assert!(o.status.success(), "{}", stderr(&o));
    for f in ["equilibria.csv", "bifurcations.csv", "summary.json"] {
        let merged = fs::read(dir.path().join("merged").join(f)).unwrap();
        let whole = fs::read(dir.path().join("whole").join(f)).unwrap();
        assert!(merged == whole, "{f} differs");
    }
}

/// The coarse study's six sliding cars are still moving at the end of the
/// run (their notes: "still moving (no steady value)"), yet the summary
/// line said "6 slide (steady sideslip beyond 10°, …)". The line, the
/// notes and `summary.json` now say the same: counted from study.csv's
/// rows, the JSON's `sliding_still_moving` and the line agree.
#[test]
fn the_study_line_does_not_call_a_sideslip_still_moving_steady() {
    let out = tempfile::tempdir().unwrap();
    let o = run(&[
        "study",
        "scenarios/sedan_study_coarse.toml",
        "--out",
        out.path().to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    let csv = fs::read_to_string(out.path().join("study.csv")).unwrap();
    let sliding: Vec<&str> = csv.lines().filter(|l| l.contains(",sliding,")).collect();
    let moving = sliding
        .iter()
        .filter(|l| l.contains("at the end of the run, still moving (no steady value)"))
        .count();
    assert_eq!((sliding.len(), moving), (6, 6), "{csv}");
    let s = read_json(&out.path().join("summary.json"));
    assert_eq!(s["sliding"], 6);
    assert_eq!(s["sliding_still_moving"], moving);
    assert!(
        said.contains("6 slide (sideslip beyond 10°, up to -58.2° at the end of the run, still moving (no steady value))")
            && !said.contains("steady sideslip"),
        "{said}"
    );
}
