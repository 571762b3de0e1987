//! What a fresh-eyes check found a user trips on in `identify`,
//! `metrics`, `tyre-eval` and the output folders, run as a user runs the
//! tool: each test one finding, and what the tool now does.

use super::*;

/// Rig data at 2, 4 and 6 kN, a slip sweep of ±0.2 rad each, with `mz`,
/// the forces multiplied by `scale`.
fn rig(scale: f64) -> String {
    let mut s = String::from("fz,alpha,fy,mz\n");
    for fz in [2000.0, 4000.0, 6000.0] {
        for k in -10..=10 {
            let alpha = 0.02 * f64::from(k);
            let fy = fz * (1.4 * (12.0 * alpha).atan()).sin();
            s += &format!("{fz},{alpha},{:e},{:.4}\n", fy * scale, 0.02 * fy);
        }
    }
    s
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// PAC89's camber terms were `free: false` with no word of their value or
/// why; an MF 6.1 fit wrote FNOMIN and UNLOADED_RADIUS defaults silently.
#[test]
fn identify_states_every_held_value_with_its_reason() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let out = dir.path().join("p.toml");
    let o = identify_to(&dir.path().join("rig.csv"), "pac89", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stdout(&o);
    let report = read_json(&out.with_extension("report.json"));
    let held = report["held"].as_array().unwrap();
    let tyre = fs::read_to_string(&out).unwrap();
    for name in ["a5", "a8", "a11"] {
        let h = held
            .iter()
            .find(|h| h["name"] == name)
            .unwrap_or_else(|| panic!("{name} not under `held`: {held:?}"));
        assert_eq!(h["why"], "camber-levels", "{h}");
        assert_eq!(h["have"], 1, "{h}");
        let value = h["value"].as_f64().unwrap();
        assert!(said.contains(&format!("{name} = ")), "{said}");
        // One line per reason, as the terminal says them (session 111).
        assert!(
            tyre.lines()
                .any(|l| l.starts_with("# held: ") && l.contains(&format!("{name} = "))),
            "{name}: {tyre}"
        );
        assert!(value.is_finite());
    }
    assert!(
        said.contains("camber terms, which need more camber levels than the data's 1 level"),
        "{said}"
    );
    // The staged Magic Formula fit: its constants, set without a template.
    let out = dir.path().join("m.tir");
    let o = identify_to(&dir.path().join("rig.csv"), "mf61", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stdout(&o);
    for line in [
        "held: FNOMIN = 4000: no --template: the median load of the data",
        "held: UNLOADED_RADIUS = 0.3: no --template: a default, as rig forces do not measure the radius",
    ] {
        assert!(said.contains(line), "{line}: {said}");
    }
    let tir = fs::read_to_string(&out).unwrap();
    assert!(
        tir.contains("$ held: UNLOADED_RADIUS = 0.3: no --template"),
        "{tir}"
    );
    let report = read_json(&out.with_extension("report.json"));
    let fnomin = report["held"]
        .as_array()
        .unwrap()
        .iter()
        .find(|h| h["name"] == "FNOMIN")
        .expect("FNOMIN under `held`");
    assert_eq!(fnomin["from"], "median-load", "{fnomin}");
    // The parameters a stage held for want of levels are said too.
    assert!(
        said.contains("held: PDY3 = 0") && said.contains("needs 2 camber levels, the data have 1"),
        "{said}"
    );
}

/// A Magic Formula coefficient that ends on its physical bound (`PKY2` at
/// 20 here, `PEY1` at its `E ≤ 1` on the Hoosier data) was not flagged.
#[test]
fn a_coefficient_ending_on_its_bound_is_flagged() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let out = dir.path().join("m.tir");
    let o = identify_to(&dir.path().join("rig.csv"), "mf61", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stdout(&o);
    let report = read_json(&out.with_extension("report.json"));
    let on_bound: Vec<&serde_json::Value> = report["stages"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|s| s["parameters"].as_array().unwrap())
        .filter(|p| p["on_bound"].is_number())
        .collect();
    assert!(!on_bound.is_empty(), "no parameter on a bound: {said}");
    for p in on_bound {
        let name = p["name"].as_str().unwrap();
        assert!(
            p["warning"]
                .as_str()
                .unwrap()
                .contains("on its physical bound"),
            "{p}"
        );
        assert!(
            said.contains(&format!("warning: {name} = "))
                && said.contains("on its physical bound ("),
            "{name}: {said}"
        );
    }
}

/// `fy` multiplied by 1e300 wrote a tyre file with σ NaN.
#[test]
fn rig_forces_no_tyre_carries_are_refused_at_their_cell() {
    let dir = scratch(&[("rig.csv", &rig(1e300))]);
    for (model, name) in [("pac89", "p.toml"), ("gim", "g.toml"), ("mf61", "m.tir")] {
        let out = dir.path().join(name);
        let e = refused(&identify_to(&dir.path().join("rig.csv"), model, &out), &out);
        assert!(
            e.contains("rig.csv:2:3: column `fy`: -1.99429e303 N is beyond ±1000000 N, which no tyre on a rig carries"),
            "{model}: {e}"
        );
        assert!(!without_temp_names(&e).contains("NaN"), "{e}");
    }
}

/// A run whose speed column is 1e308 printed a 300-digit ratio.
#[test]
fn metrics_refuses_a_speed_no_car_reaches_at_its_cell() {
    let run = |speed: &str| {
        let mut s = String::from("t,speed,steer,yaw_rate\n");
        for i in 0..400 {
            let t = f64::from(i) * 0.01;
            let steer = if t > 1.0 { 0.02 } else { 0.0 };
            s += &format!("{t:.2},{speed},{steer},{}\n", steer * 0.4);
        }
        s
    };
    let dir = scratch(&[("fast.csv", &run("1e308")), ("kmh.csv", &run("200"))]);
    let o = run_in(dir.path(), &["metrics", "fast.csv"]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(
        e.contains("fast.csv:2:2: column `speed`: 1e308 m/s is beyond 150 m/s (540 km/h), which no car's speed reaches"),
        "{e}"
    );
    assert!(e.len() < 400, "{e}");
    let e = stderr(&run_in(dir.path(), &["metrics", "kmh.csv"]));
    assert!(
        e.contains("kmh.csv:2:2: column `speed`: 200 m/s is beyond 150 m/s")
            && e.contains("is the column in km/h (divide it by 3.6)"),
        "{e}"
    );
}

/// `2.049e0` for 2.049, `RMS 0.0 N` for a fit to exact data.
#[test]
fn identify_prints_numbers_without_e0_or_a_zero_rms() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    for (model, name) in [("pac89", "p.toml"), ("mf61", "m.tir")] {
        let out = dir.path().join(name);
        let o = identify_to(&dir.path().join("rig.csv"), model, &out);
        assert!(o.status.success(), "{}", stderr(&o));
        let said = stdout(&o);
        for bad in [
            "e0 ",
            "e0;",
            "e0)",
            "RMS 0.0 ",
            "RMS 0.00 ",
            "RMS error 0.00 ",
        ] {
            assert!(!said.contains(bad), "{model}: `{bad}` in {said}");
        }
    }
}

/// A folder where the lock file should be was called an empty lock, taken
/// over after 10 s and left behind as `.stale-PID`.
#[test]
fn a_folder_in_the_lock_files_place_is_named_and_nothing_is_left() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    fs::create_dir_all(out.join(".handling.lock")).unwrap();
    let o = run(&[
        "simulate",
        "scenarios/step_gbt6323_pac89.toml",
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains(".handling.lock is a folder where this tool's lock file should be"),
        "{e}"
    );
    // A lock left by a process that is gone is taken over without a trace.
    fs::remove_dir(out.join(".handling.lock")).unwrap();
    fs::write(out.join(".handling.lock"), "3999999\n").unwrap();
    let o = run(&[
        "simulate",
        "scenarios/step_gbt6323_pac89.toml",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let left: Vec<String> = fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains("stale") || n.contains("lock"))
        .collect();
    assert!(left.is_empty(), "{left:?}");
}

/// A zero-byte CSV read as "missing column `t`"; `time` and `yawrate`
/// were not answered with the names meant.
#[test]
fn an_empty_csv_is_said_empty_and_a_misspelt_column_gets_the_name_meant() {
    let dir = scratch(&[
        ("zero.csv", ""),
        ("header.csv", "t,speed,steer,yaw_rate\n"),
        (
            "time.csv",
            "time,speed,steer,yaw_rate\n0,20,0,0\n0.01,20,0,0\n",
        ),
        ("yaw.csv", "t,speed,steer,yawrate\n0,20,0,0\n0.01,20,0,0\n"),
    ]);
    let said = |f: &str| stderr(&run_in(dir.path(), &["metrics", f]));
    let e = said("zero.csv");
    assert!(e.contains("zero.csv: the file is empty"), "{e}");
    assert!(!e.contains("missing required column"), "{e}");
    let e = said("header.csv");
    assert!(e.contains("header.csv: no data rows"), "{e}");
    let e = said("time.csv");
    assert!(
        e.contains("missing required column `t`")
            && e.contains("header column 1, `time`: did you mean `t`?"),
        "{e}"
    );
    let e = said("yaw.csv");
    assert!(
        e.contains("missing required column `yaw_rate`")
            && e.contains("yaw.csv:1:4: missing")
            && e.contains("header column 4, `yawrate`: did you mean `yaw_rate`?"),
        "{e}"
    );
}

/// A spreadsheet set to a decimal comma writes `;` between values: the
/// header read as one column, and the error only listed it.
#[test]
fn a_semicolon_separated_csv_is_said_to_need_commas_and_decimal_points() {
    let dir = scratch(&[
        (
            "semi.csv",
            "t;speed;steer;yaw_rate\n0;20;0;0\n0,01;20;0;0\n",
        ),
        ("tab.csv", "t\tspeed\tsteer\tyaw_rate\n0\t20\t0\t0\n"),
    ]);
    for (file, name) in [("semi.csv", "semicolons"), ("tab.csv", "tabs")] {
        let e = stderr(&run_in(dir.path(), &["metrics", file]));
        assert!(
            e.contains(&format!("{file}:1:1: missing required column"))
                && e.contains(&format!("the header is one column separated by {name}"))
                && e.contains("comma-separated with a decimal point"),
            "{e}"
        );
    }
}

/// `--mode 121` for a `.toml` tyre was refused without saying why.
#[test]
fn a_magic_formula_mode_for_a_toml_tyre_is_refused_with_why() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("f.csv");
    let o = run(&[
        "tyre-eval",
        "tyres/pac89_adams_example.toml",
        "docs/examples/tyre_points.csv",
        "--mode",
        "121",
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = refused(&o, &out);
    assert!(
        e.contains(
            "mode 121 is MFeval's useMode, a setting of the Magic Formula (.tir) tyres only"
        ) && e.contains("none of which a pac89 tyre has")
            && e.contains("drop --mode"),
        "{e}"
    );
}

/// Putnam's `roll` is logged in degrees: 2° read as radians is a car at
/// 115° of roll. A replay of it is refused at its cell, with the keys that
/// say so; `metrics`, which levels `ay` by the roll as `diagnose` does,
/// refuses it too, naming `--degrees roll`.
#[test]
fn a_roll_column_in_degrees_is_refused_at_its_cell_with_the_key_that_declares_it() {
    let mut s = String::from("t,speed,steer,yaw_rate,roll\n");
    for i in 0..400 {
        let t = f64::from(i) * 0.01;
        let steer = if t > 1.0 { 0.02 } else { 0.0 };
        s += &format!("{t:.2},20,{steer},{},{}\n", steer * 4.0, 1.5 + steer * 20.0);
    }
    let base = fs::read_to_string(root().join("scenarios/sedan_step.toml")).unwrap();
    let base = base.replace("../tyres", root().join("tyres").to_str().unwrap());
    let head = &base[..base.find("[manoeuvre]").unwrap()];
    let scenario = format!("{head}[manoeuvre]\nkind = \"replay\"\nrun = \"deg.csv\"\n");
    let dir = scratch(&[("deg.csv", &s), ("replay.toml", &scenario)]);
    let o = run_in(dir.path(), &["simulate", "replay.toml", "--out", "o"]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(
        e.contains("deg.csv:2:5: column `roll`: 1.5 rad is beyond ±11°")
            && e.contains("is the column in degrees?")
            && e.contains(
                "`degrees = [\"roll\"]` under [runs] in a campaign or a replay's [manoeuvre]"
            ),
        "{e}"
    );
    let o = run_in(dir.path(), &["metrics", "deg.csv"]);
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("deg.csv:2:5: column `roll`: 1.5 rad is beyond ±11°")
            && e.contains("`--degrees roll` to `metrics`"),
        "{e}"
    );
}
