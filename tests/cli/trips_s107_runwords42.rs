//! What fresh-eyes round 38 tripped on in run files, replay pieces and
//! `metrics`, run as a user runs the tool: a sideslip refusal
//! that named one of two reversed files, a held replay piece said to
//! "stay within 0 rad", `min_speed` refused in forms of its own,
//! `--min-overshoot`'s two refusals with two ranges, rows of "—" without
//! a word of why, and a run with two dead channels refused for one.

use super::*;

/// A synthetic handling campaign (`sensor_delay` on, seed 1) with
/// `extra` appended under its `[diagnose]` table.
fn handling(dir: &Path, extra: &str) -> PathBuf {
    crate::synth_extended(dir, "handling", "sensor_delay", "1", extra)
}

/// `diagnose` on campaign `c` (outputs in `dir/d`), expected to fail: its
/// stderr.
fn refused_diagnosis(dir: &Path, c: &Path) -> String {
    let o = run(&[
        "diagnose",
        c.to_str().unwrap(),
        "--out",
        dir.join("d").to_str().unwrap(),
    ]);
    assert!(!o.status.success(), "diagnosed: {}", stderr(&o));
    stderr(&o)
}

/// Two run files of a campaign with `beta` logged in the other sign
/// convention: main's refusal named the first alone (its `others` held
/// one file); the user negated it, reran, and only then heard of the
/// second. Both are named in one refusal, each with its correlation.
#[test]
fn two_files_whose_sideslip_moves_against_the_model_are_named_in_one_refusal() {
    let dir = tempfile::tempdir().unwrap();
    let c = handling(dir.path(), "effects = [\"sensor_delay\"]\n");
    for f in ["step_100kph_6ms2.csv", "step_120kph_4ms2.csv"] {
        map_column(&c.join("runs").join(f), "beta", |v| -v);
    }
    let e = refused_diagnosis(dir.path(), &c);
    assert!(
        e.contains("`beta` of 2 files moves against the base model's sideslip (correlation over samples): "),
        "{e}"
    );
    for f in ["step_100kph_6ms2.csv (-0.9", "step_120kph_4ms2.csv (-0.9"] {
        assert!(e.contains(f), "{f}\n{e}");
    }
    assert!(
        e.contains("while the other files' move with it (0.9")
            && e.contains("negate the `beta` of each"),
        "{e}"
    );
    // Negating both back, as the refusal asks, passes the check.
    for f in ["step_100kph_6ms2.csv", "step_120kph_4ms2.csv"] {
        map_column(&c.join("runs").join(f), "beta", |v| -v);
    }
    let o = run(&[
        "diagnose",
        c.to_str().unwrap(),
        "--out",
        dir.path().join("d2").to_str().unwrap(),
    ]);
    assert!(
        !stderr(&o).contains("moves against the base model"),
        "{}",
        stderr(&o)
    );
}

/// The bundled sedan with `manoeuvre` as its `[manoeuvre]` table, written
/// to `dir/<name>.toml`.
fn sedan_with(dir: &Path, name: &str, manoeuvre: &str) -> PathBuf {
    let text = bundled_scenario("sedan_step.toml");
    let head = text.split("[manoeuvre]").next().unwrap();
    let path = dir.join(format!("{name}.toml"));
    fs::write(&path, format!("{head}[manoeuvre]\n{manoeuvre}")).unwrap();
    path
}

/// A replay of a run split by a time gap whose second piece holds the
/// steer at 0.010 rad: main dropped it saying "its steer stays within 0
/// rad", a steer at 0 for one held at 0.010 rad. Said where it is held.
#[test]
fn a_dropped_replay_piece_is_said_where_its_steer_is_held() {
    let dir = tempfile::tempdir().unwrap();
    let step = "kind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.01\nstart = 1.0\nrise_time = 0.1\nend = 12.0\n";
    let sc = sedan_with(dir.path(), "long", step);
    succeeds(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        dir.path().join("long").to_str().unwrap(),
    ]);
    let text = fs::read_to_string(dir.path().join("long/history.csv")).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = |name: &str| head.iter().position(|h| *h == name).unwrap();
    let names = ["t", "speed", "steer", "yaw_rate", "ay", "beta"];
    let mut csv = names.join(",") + "\n";
    for l in lines.step_by(10) {
        let v: Vec<&str> = l.split(',').collect();
        let t: f64 = v[at("t")].parse().unwrap();
        if t > 3.0 + 1e-9 && t < 4.0 - 1e-9 {
            continue;
        }
        csv += &(names.map(|c| v[at(c)]).join(",") + "\n");
    }
    fs::write(dir.path().join("gap_run.csv"), csv).unwrap();
    let replay = sedan_with(
        dir.path(),
        "replay",
        "kind = \"replay\"\nrun = \"gap_run.csv\"\n",
    );
    let out = dir.path().join("out");
    let said = succeeds(&[
        "simulate",
        replay.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        said.contains("gap_run.csv#2 (4.00–12.00 s, 801 samples) dropped: its steer holds at 0.010 rad throughout (it does not move; a step moves it by 0.00017 rad or more) while another piece moves it"),
        "{said}"
    );
    assert!(!said.contains("within 0 rad"), "{said}");
}

/// `[diagnose] min_speed` refused in three forms of its own on main ("must
/// not be negative", "must be a finite number", "is above 100 m/s …") and
/// a fourth above every run's top speed ("min_speed = 50 m/s removed
/// every run"): each now reads as the campaign file's other keys do, the
/// key and value at its line, the range, and what to write.
#[test]
fn every_min_speed_refusal_reads_like_the_campaign_files_other_key_refusals() {
    let dir = tempfile::tempdir().unwrap();
    let base = handling(dir.path(), "");
    let line = fs::read_to_string(base.join("vehicle.toml"))
        .unwrap()
        .lines()
        .count()
        + 1;
    let cases = [
        ("-1", "= -1: must lie in [0, 100]: it is the speed in m/s below which samples are left out as slow", "write a speed in m/s, such as `min_speed = 5` (the default)"),
        ("nan", "= NaN: must lie in [0, 100]: it is the speed in m/s", "write a speed in m/s, such as `min_speed = 5` (the default)"),
        ("200", "= 200: must lie in [0, 100]: it is the speed in m/s", "is it in km/h? 200 km/h is 55.6 m/s: write `min_speed = 55.6`"),
        ("50", "= 50: must lie in [0, ", "write `min_speed = 5` under [diagnose] (m/s), below every run's top speed"),
    ];
    for (k, (value, range, write)) in cases.into_iter().enumerate() {
        let c = dir.path().join(format!("c{k}"));
        fs::rename(&base, &c).unwrap();
        let v = c.join("vehicle.toml");
        let text = fs::read_to_string(&v).unwrap();
        fs::write(&v, format!("{text}min_speed = {value}\n")).unwrap();
        let e = refused_diagnosis(dir.path(), &c);
        let head = format!("vehicle.toml:{line}:13: `diagnose.min_speed` {range}");
        assert!(e.contains(&head), "{head}\n{e}");
        assert!(e.contains(write), "{write}\n{e}");
        fs::write(&v, text).unwrap();
        fs::rename(&c, &base).unwrap();
    }
}

/// A step-steer run of `t,speed,steer,yaw_rate` (20 m/s, 0.02 rad at 1 s),
/// with `extra` columns' header and a value each, in `dir/run.csv`.
fn step_run(dir: &Path, extra: &[(&str, &str)]) -> PathBuf {
    let p = dir.join("run.csv");
    let mut names = vec!["t", "speed", "steer", "yaw_rate"];
    names.extend(extra.iter().map(|(n, _)| *n));
    let mut s = names.join(",") + "\n";
    for k in 0..400 {
        let t = f64::from(k) * 0.01;
        let d = if t < 1.0 { 0.0 } else { 0.02 };
        s += &format!("{t},20,{d},{}", 10.0 * d);
        for (n, _) in extra {
            // ay = u·r; β a tenth of the steer, of a car below its tangent speed.
            let v = if *n == "ay" { 200.0 * d } else { 0.1 * d };
            s += &format!(",{v}");
        }
        s += "\n";
    }
    fs::write(&p, s).unwrap();
    p
}

/// `metrics --min-overshoot -1` was refused as "a finite share of at
/// least 0 %" and `1e308` as "must lie in [0, 100]": two bounds for one
/// option. Every value refused now states the one range, as a
/// scenario's `[metrics] min_overshoot` does.
#[test]
fn every_least_overshoot_refused_states_one_range() {
    let dir = tempfile::tempdir().unwrap();
    let p = step_run(dir.path(), &[]);
    for v in ["-1", "1e308", "nan", "100.5"] {
        let o = run(&["metrics", p.to_str().unwrap(), "--min-overshoot", v]);
        assert!(!o.status.success(), "{v} taken");
        let e = stderr(&o);
        assert!(e.contains("--min-overshoot: `min_overshoot` = "), "{e}");
        assert!(
            e.contains(": must lie in [0, 100]: the threshold is there to pass over"),
            "{e}"
        );
    }
    let o = run(&["metrics", p.to_str().unwrap(), "--min-overshoot", "lots"]);
    assert!(
        stderr(&o).contains("not a number (the least overshoot is in % of the step, 0 to 100)"),
        "{}",
        stderr(&o)
    );
}

/// `metrics` on a run without `ay` or `beta` printed the steady sideslip
/// and TB rows as "—" without saying why. The warning names the missing
/// column and the rows that need it, once.
#[test]
fn metrics_says_once_which_missing_column_the_empty_rows_need() {
    let dir = tempfile::tempdir().unwrap();
    let p = step_run(dir.path(), &[]);
    let o = run(&["metrics", p.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (out, e) = (String::from_utf8_lossy(&o.stdout), stderr(&o));
    for row in ["steady sideslip", "TB"] {
        let line = out
            .lines()
            .find(|l| l.trim_start().starts_with(row))
            .unwrap();
        assert!(
            line.trim_end().ends_with("—") || line.contains(" — "),
            "{line}"
        );
    }
    let beta = "warning: the run has no `beta` column, which the steady sideslip and TB rows need (TB is the yaw-rate peak time × the steady sideslip): they read — (null in --json)";
    let ay = "warning: the run has no `ay` column, which the ay response time, steady ay, E_ay and Er rows need: they read — (null in --json)";
    assert_eq!(e.matches(beta).count(), 1, "{e}");
    assert_eq!(e.matches(ay).count(), 1, "{e}");
    // With both columns the rows have values and neither warning is said.
    let p = step_run(dir.path(), &[("ay", ""), ("beta", "")]);
    let o = run(&["metrics", p.to_str().unwrap()]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert!(
        !e.contains("has no `beta`") && !e.contains("has no `ay`"),
        "{e}"
    );
}

/// A campaign run whose `ay` and `beta` both log zeros was refused for
/// `ay` alone; removed, the rerun refused it for `beta`. Both in one.
#[test]
fn a_run_with_two_dead_channels_is_refused_for_both_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let c = handling(dir.path(), "");
    let dead = |f: &str| f == "step_100kph_6ms2.csv";
    for column in ["ay", "beta"] {
        super::trips_s81_diag::rewrite(&c, column, &dead, &|_| 0.0);
    }
    let e = refused_diagnosis(dir.path(), &c);
    for column in ["ay", "beta"] {
        let said = format!(
            "step_100kph_6ms2.csv: channel `{column}` holds one value (0) over the whole run"
        );
        assert!(e.contains(&said), "{said}\n{e}");
    }
}

/// `degrees = ["roll", "bank"]` under `[runs]` where no run has either:
/// main refused `roll` alone; left out, the rerun refused `bank`. Both
/// are refused at once, each at its place in the list.
#[test]
fn every_declared_column_no_run_has_is_refused_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let c = handling(dir.path(), "\n[runs]\ndegrees = [\"roll\", \"bank\"]\n");
    let e = refused_diagnosis(dir.path(), &c);
    for column in ["roll", "bank"] {
        let said = format!("`{column}` is declared in degrees, and none of the 8 run files has it");
        assert!(e.contains(&said), "{said}\n{e}");
    }
}
