//! Scenarios: simulate, metrics of written histories, refused inputs, outputs never overwritten.

use super::*;

#[test]
fn every_bundled_scenario_runs_and_writes_its_outputs() {
    let out = tempfile::tempdir().unwrap();
    let mut n = 0;
    for entry in fs::read_dir(root().join("scenarios")).unwrap() {
        let p = entry.unwrap().path();
        let text = fs::read_to_string(&p).unwrap();
        // Scenarios only: study files carry a [manoeuvre] table too.
        if p.extension().is_none_or(|e| e != "toml")
            || !text.contains("[manoeuvre]")
            || text.contains("\n[stiffness]")
        {
            continue;
        }
        n += 1;
        let dir = out.path().join(p.file_stem().unwrap());
        let o = run(&[
            "simulate",
            p.to_str().unwrap(),
            "--out",
            dir.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}: {}", p.display(), stderr(&o));
        let hist = fs::read_to_string(dir.join("history.csv")).unwrap();
        assert!(hist.starts_with("t,steer,speed,beta,yaw_rate,ay"));
        assert!(fs::metadata(dir.join("response.png")).unwrap().len() > 10_000);
        if text.contains("step-steer") {
            let m: serde_json::Value = read_json(&dir.join("metrics.json"));
            for key in [
                "yaw_rate_response_time",
                "yaw_rate_peak_time",
                "yaw_rate_overshoot",
                "ay_response_time",
                "yaw_rate_gain",
                "beta_steady",
                "tb",
                "yaw_rate_total_variance",
                "ay_total_variance",
                "er",
            ] {
                assert!(m.get(key).is_some(), "{}: no `{key}`", p.display());
            }
            if text.contains("lateral_acceleration = 2.0") {
                let ay = m["ay_steady"].as_f64().unwrap();
                assert!((ay - 2.0).abs() < 1e-3, "{}: steady ay {ay}", p.display());
            }
        }
    }
    assert!(n >= 5, "only {n} scenarios found");
}

#[test]
fn metrics_of_a_written_history_match_the_simulation() {
    // Under RK4 the rows are the simulation's record: the same numbers.
    let out = tempfile::tempdir().unwrap();
    let sc = scenario_with(
        "sedan_step.toml",
        out.path(),
        "rk4.toml",
        "method = \"rk4\"",
    );
    simulate_to(&sc, out.path());
    let history = out.path().join("history.csv");
    let metrics = |extra: &[&str]| -> serde_json::Value {
        let mut args = vec!["metrics", history.to_str().unwrap(), "--json"];
        args.extend_from_slice(extra);
        let o = run(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        serde_json::from_slice(&o.stdout).unwrap()
    };
    let b: serde_json::Value = read_json(&out.path().join("metrics.json"));
    // Unfiltered, as a simulated record is measured: the same numbers, to
    // the nine significant digits the rows are written with (the
    // overshoot, a difference over a sixth of its terms, to about 1e-8).
    let a = metrics(&["--filter-hz", "0"]);
    for key in ["yaw_rate_response_time", "yaw_rate_overshoot", "er", "tb"] {
        let (x, y) = (a[key].as_f64().unwrap(), b[key].as_f64().unwrap());
        assert!(
            (x - y).abs() <= 1e-8 * y.abs().max(1.0),
            "{key}: {x} vs {y}"
        );
    }
    // Under Dormand–Prince (the default) the metrics come from the dense
    // output; the 1 ms rows give them to the rows' accuracy: crossings
    // interpolated linearly, the peak on a row.
    let dense = out.path().join("dense");
    simulate_to(&root().join("scenarios/sedan_step.toml"), &dense);
    let d: serde_json::Value = read_json(&dense.join("metrics.json"));
    let mut args = vec!["metrics", "--json", "--filter-hz", "0"];
    let h = dense.join("history.csv");
    args.insert(1, h.to_str().unwrap());
    let o = run(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let rows: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    for (key, tol) in [
        ("yaw_rate_response_time", 1e-5),
        ("yaw_rate_peak_time", 5e-4),
        ("yaw_rate_overshoot", 1e-3),
        ("er", 1e-5),
    ] {
        let (x, y) = (rows[key].as_f64().unwrap(), d[key].as_f64().unwrap());
        assert!((x - y).abs() <= tol, "{key}: rows {x} vs dense {y}");
    }
    // The default 10 Hz low-pass for measured runs barely moves them.
    let a = metrics(&[]);
    assert_eq!(a["filter_hz"], 10.0);
    for (key, tol) in [
        ("yaw_rate_response_time", 1e-3),
        ("yaw_rate_peak_time", 2e-3),
        ("yaw_rate_overshoot", 0.05),
        ("er", 1e-3),
    ] {
        let (x, y) = (a[key].as_f64().unwrap(), b[key].as_f64().unwrap());
        assert!((x - y).abs() <= tol, "{key}: {x} vs {y}");
    }
}

#[test]
fn misspelt_key_is_named_with_its_line() {
    let dir = scenario(&VEHICLE.replace("yaw_inertia", "yaw_inertai"), GIM, STEP);
    let e = simulate_err(dir.path());
    assert!(e.contains("scenario.toml:3:"), "{e}");
    // With the key meant, as every other unknown name is answered.
    assert!(
        e.contains("unknown field `yaw_inertai` (did you mean `yaw_inertia`?)"),
        "{e}"
    );
}

#[test]
fn missing_key_is_named() {
    let dir = scenario(&VEHICLE.replace("cg_height = 0.55\n", ""), GIM, STEP);
    let e = simulate_err(dir.path());
    assert!(
        e.contains("scenario.toml") && e.contains("cg_height"),
        "{e}"
    );
}

#[test]
fn negative_mass_is_refused_with_file_line_and_value() {
    let dir = scenario(&VEHICLE.replace("1530.0", "-1530.0"), GIM, STEP);
    let e = simulate_err(dir.path());
    assert!(e.contains("scenario.toml:2:8"), "{e}");
    assert!(
        e.contains("vehicle.mass") && e.contains("-1530") && e.contains("positive"),
        "{e}"
    );
}

#[test]
fn wheelbase_disagreeing_with_a_plus_b_is_refused() {
    let dir = scenario(&format!("{VEHICLE}wheelbase = 2.9\n"), GIM, STEP);
    let e = simulate_err(dir.path());
    assert!(
        e.contains("scenario.toml:9:1") && e.contains("wheelbase") && e.contains("a + b"),
        "{e}"
    );
}

#[test]
fn misspelt_tyre_key_is_named_with_its_line() {
    let dir = scenario(
        VEHICLE,
        &GIM.replace("contact_length", "contact_lenght"),
        STEP,
    );
    let e = simulate_err(dir.path());
    assert!(
        e.contains("tyre.toml:3:1") && e.contains("contact_lenght"),
        "{e}"
    );
}

#[test]
fn unknown_tyre_model_is_named() {
    let dir = scenario(VEHICLE, &GIM.replace("gim", "gym"), STEP);
    let e = simulate_err(dir.path());
    assert!(e.contains("tyre.toml:1:") && e.contains("gym"), "{e}");
}

#[test]
fn non_physical_tyre_value_is_named() {
    let dir = scenario(VEHICLE, &GIM.replace("0.18", "-0.18"), STEP);
    let e = simulate_err(dir.path());
    assert!(
        e.contains("tyre.toml:3:1") && e.contains("contact_length"),
        "{e}"
    );
}

#[test]
fn pac89_file_in_1987_numbering_is_refused() {
    let text = fs::read_to_string(root().join("tyres/pac89_adams_example.toml")).unwrap();
    let dir = scenario(VEHICLE, &text.replace("adams-pac89", "pacejka-1987"), STEP);
    let e = simulate_err(dir.path());
    assert!(
        e.contains("tyre.toml") && e.contains("1987") && e.contains("form"),
        "{e}"
    );
}

#[test]
fn step_beyond_the_rise_time_limit_is_refused() {
    let dir = scenario(VEHICLE, GIM, &format!("{STEP}rise_time = 0.5\n"));
    let e = simulate_err(dir.path());
    assert!(
        e.contains("manoeuvre.rise_time") && e.contains("10–90 %") && e.contains("0.15 s"),
        "{e}"
    );
    // A 0.2 s ramp takes 0.16 s from 10 % to 90 %: beyond ISO 7401.
    let dir = scenario(VEHICLE, GIM, &format!("{STEP}rise_time = 0.2\n"));
    assert!(simulate_err(dir.path()).contains("manoeuvre.rise_time"));
    // 0.18 s takes 0.144 s: accepted.
    let dir = scenario(VEHICLE, GIM, &format!("{STEP}rise_time = 0.18\n"));
    let out = dir.path().join("out");
    let o = run(&[
        "simulate",
        dir.path().join("scenario.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn unreachable_lateral_acceleration_is_refused() {
    let m = STEP.replace("steer = 0.0174533", "lateral_acceleration = 15.0");
    let dir = scenario(VEHICLE, GIM, &m);
    let e = simulate_err(dir.path());
    assert!(
        e.contains("lateral_acceleration") && e.contains("15"),
        "{e}"
    );
}

#[test]
fn csv_with_nan_or_text_is_refused_with_line_and_column() {
    let good = "t,speed,steer,yaw_rate,ay\n0,20,0,0,0\n0.1,20,0.01,0.01,0.1\n";
    for (bad, line, what) in [
        ("0.2,20,NaN,0.02,0.2\n", 4, "steer"),
        ("0.2,20,0.01,abc,0.2\n", 4, "yaw_rate"),
        ("0.05,20,0.01,0.02,0.2\n", 4, "strictly increasing"),
    ] {
        let dir = scratch(&[("run.csv", &format!("{good}{bad}"))]);
        let o = run(&["metrics", dir.path().join("run.csv").to_str().unwrap()]);
        assert!(!o.status.success());
        let e = stderr(&o);
        assert!(
            e.contains(&format!("run.csv:{line}:")) && e.contains(what),
            "{e}"
        );
    }
    let dir = scratch(&[("run.csv", "t,speed,yaw_rate\n0,20,0\n")]);
    let e = stderr(&run(&[
        "metrics",
        dir.path().join("run.csv").to_str().unwrap(),
    ]));
    assert!(e.contains("missing required column `steer`"), "{e}");
    let dir = scratch(&[("run.csv", "t,speed,steer,yaw_rate\n0,20,0\n")]);
    let e = stderr(&run(&[
        "metrics",
        dir.path().join("run.csv").to_str().unwrap(),
    ]));
    assert!(e.contains("run.csv:2:") && e.contains("malformed"), "{e}");
}

#[test]
fn an_input_is_never_overwritten() {
    // A replay whose run file is called like an output, written into the
    // inputs' own folder.
    let dir = scenario(VEHICLE, GIM, STEP);
    let sc = fs::read_to_string(dir.path().join("scenario.toml")).unwrap();
    let sc = sc.replace(
        "kind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\n",
        "kind = \"replay\"\nrun = \"history.csv\"\n",
    );
    fs::write(dir.path().join("scenario.toml"), sc).unwrap();
    fs::write(
        dir.path().join("history.csv"),
        "t,speed,steer,yaw_rate\n0,20,0,0\n1,20,0.01,0.01\n",
    )
    .unwrap();
    let o = run(&[
        "simulate",
        dir.path().join("scenario.toml").to_str().unwrap(),
        "--out",
        dir.path().to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("refusing to overwrite"),
        "{}",
        stderr(&o)
    );
    assert!(fs::read_to_string(dir.path().join("history.csv"))
        .unwrap()
        .starts_with("t,speed,steer,yaw_rate\n0,20"));
}

#[test]
fn checks_after_parsing_name_the_real_column() {
    // `t` is the third column and runs backwards on line 4.
    let dir = scratch(&[(
        "run.csv",
        "speed,steer,t,yaw_rate\n20,0,0.00,0\n20,0,0.01,0\n20,0,0.005,0\n20,0,0.02,0\n",
    )]);
    let o = run(&["metrics", dir.path().join("run.csv").to_str().unwrap()]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(e.contains("run.csv:4:3:") && e.contains("0.005"), "{e}");
    // A negative load in the rig file's second column, line 3.
    let dir = scratch(&[("rig.csv", "alpha,fz,fy\n0.01,3000,500\n0.02,-3000,900\n")]);
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "pac89",
        "--out",
        dir.path().join("t.toml").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(e.contains("rig.csv:3:2:") && e.contains("-3000"), "{e}");
}

#[test]
fn wheel_lift_off_keeps_the_weight_and_is_reported() {
    // A tall, narrow vehicle in a hard step: the inner wheels lift.
    let tall = VEHICLE
        .replace("cg_height = 0.55", "cg_height = 1.2")
        .replace("track_front = 1.55", "track_front = 0.9");
    let step = STEP.replace("steer = 0.0174533", "steer = 0.1");
    let dir = scenario(&tall, GIM, &step);
    let out = dir.path().join("out");
    let o = run(&[
        "simulate",
        dir.path().join("scenario.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("lift-off"), "{text}");
    let csv = fs::read_to_string(out.join("history.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| header.iter().position(|h| *h == n).unwrap();
    let fz = ["fz_fl", "fz_fr", "fz_rl", "fz_rr"].map(col);
    let weight = 1530.0 * 9.80665;
    let mut zero_rows = 0;
    for line in lines {
        let v: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        let total: f64 = fz.iter().map(|&i| v[i]).sum();
        assert!((total - weight).abs() < 1e-6 * weight, "{line}");
        zero_rows += usize::from(v[fz[0]] == 0.0);
    }
    assert!(zero_rows > 0, "the inner front wheel must lift");
}

/// A bundled scenario copied into `dir` with its tyre paths made absolute
/// and `settings` added to its `[simulation]` table.
fn scenario_with(name: &str, dir: &Path, file: &str, settings: &str) -> PathBuf {
    let mut text = bundled_scenario(name);
    if text.contains("\n[simulation]\n") {
        text = text.replace("\n[simulation]\n", &format!("\n[simulation]\n{settings}\n"));
    } else {
        text.push_str(&format!("\n[simulation]\n{settings}\n"));
    }
    let p = dir.join(file);
    fs::write(&p, text).unwrap();
    p
}

/// The scenario with every maximum above the steady state a peak
/// (`min_overshoot = 0`): the convergence checks measure the PAC89 step's
/// 0.05 % overshoot, below the 1 % a peak needs by default.
fn any_peak(scenario: PathBuf) -> PathBuf {
    let text = fs::read_to_string(&scenario).unwrap();
    assert!(!text.contains("[metrics]"), "{}", scenario.display());
    fs::write(&scenario, format!("{text}\n[metrics]\nmin_overshoot = 0\n")).unwrap();
    scenario
}

/// `simulate <scenario> --out <out>`, which must succeed: its stdout (the
/// metrics, notes and warnings).
pub(crate) fn simulate_to(scenario: &Path, out: &Path) -> String {
    let o = run(&[
        "simulate",
        scenario.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// The linear car of [`VEHICLE`] on [`linear_tyre`] driven through
/// `manoeuvre` (the lines of its `[manoeuvre]` table), written to
/// `dir/name.toml` with a row every 0.01 s and simulated into
/// `dir/sim_name`: its history's rows (the first six columns, as
/// [`super::trips_s94_met::history_rows`] reads them).
pub(crate) fn simulated_rows(dir: &Path, name: &str, manoeuvre: &str) -> Vec<Vec<f64>> {
    linear_tyre(dir);
    let scenario = format!(
        "{VEHICLE}\n[tyres]\nfront = \"tyre.toml\"\n\n[manoeuvre]\n{manoeuvre}\n[simulation]\nstep = 0.01\n"
    );
    let path = dir.join(format!("{name}.toml"));
    fs::write(&path, scenario).unwrap();
    let out = dir.join(format!("sim_{name}"));
    simulate_to(&path, &out);
    super::trips_s94_met::history_rows(&out.join("history.csv"))
}

/// The reference tolerance of the convergence checks: a hundred times
/// tighter than the default rtol (1e-9), so the reference's own error is
/// two orders below the difference measured.
const REFERENCE: &str = "rtol = 1e-10\natol = 1e-12";

#[test]
fn default_tolerance_gives_every_step_steer_metric_within_1e_6_of_a_tight_reference() {
    let dir = tempfile::tempdir().unwrap();
    // A tiny overshoot (0.05 %, PAC89 with load transfer: its relative error
    // is the most sensitive) and a large one (17 %, Gim).
    for name in ["step_gbt6323_pac89.toml", "sedan_step.toml"] {
        let default = any_peak(scenario_with(name, dir.path(), "default.toml", ""));
        let tight = any_peak(scenario_with(name, dir.path(), "tight.toml", REFERENCE));
        let (out_d, out_t) = (dir.path().join("d"), dir.path().join("t"));
        let text = simulate_to(&default, &out_d);
        assert!(text.contains("Dormand–Prince 5(4), rtol 1e-9"), "{text}");
        simulate_to(&tight, &out_t);
        let (d, t) = (
            read_json(&out_d.join("metrics.json")),
            read_json(&out_t.join("metrics.json")),
        );
        let mut compared = 0;
        for key in [
            "yaw_rate_response_time",
            "yaw_rate_peak_time",
            "yaw_rate_overshoot",
            "ay_response_time",
            "yaw_rate_gain",
            "ay_steady",
            "beta_steady",
            "tb",
            "yaw_rate_total_variance",
            "ay_total_variance",
            "er",
        ] {
            let (x, y) = (d[key].as_f64().unwrap(), t[key].as_f64().unwrap());
            let rel = (x - y).abs() / y.abs();
            assert!(
                rel <= 1e-6,
                "{name} {key}: {x} vs reference {y} ({rel:.1e})"
            );
            compared += 1;
        }
        assert_eq!(compared, 11);
    }
}

#[test]
fn metrics_events_are_located_between_output_rows() {
    // Rows every 10 ms: the grid would put the yaw-rate peak on a multiple
    // of 10 ms; located on the dense output it agrees with 1 ms rows to the
    // tolerance, as do the response times and total variances.
    let dir = tempfile::tempdir().unwrap();
    let fine = scenario_with("sedan_step.toml", dir.path(), "fine.toml", "step = 0.001");
    let coarse = scenario_with("sedan_step.toml", dir.path(), "coarse.toml", "step = 0.01");
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    simulate_to(&fine, &a);
    simulate_to(&coarse, &b);
    let (a, b) = (
        read_json(&a.join("metrics.json")),
        read_json(&b.join("metrics.json")),
    );
    for key in ["yaw_rate_peak_time", "yaw_rate_response_time", "er", "tb"] {
        let (x, y) = (a[key].as_f64().unwrap(), b[key].as_f64().unwrap());
        assert!((x - y).abs() <= 1e-9 * y.abs(), "{key}: {x} vs {y}");
    }
    let tp = b["yaw_rate_peak_time"].as_f64().unwrap() + b["time_zero"].as_f64().unwrap();
    assert!(((tp / 0.01).round() * 0.01 - tp).abs() > 1e-6, "{tp}");
}

#[test]
fn rk4_stays_available_and_agrees_with_the_default_to_its_own_accuracy() {
    let dir = tempfile::tempdir().unwrap();
    let rk4 = scenario_with(
        "step_gbt6323_pac89.toml",
        dir.path(),
        "rk4.toml",
        "method = \"rk4\"",
    );
    let dopri = any_peak(scenario_with(
        "step_gbt6323_pac89.toml",
        dir.path(),
        "d.toml",
        "",
    ));
    let rk4 = any_peak(rk4);
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    let text = simulate_to(&rk4, &a);
    assert!(text.contains("RK4, 6000 steps of 0.001 s"), "{text}");
    simulate_to(&dopri, &b);
    let (a, b) = (
        read_json(&a.join("metrics.json")),
        read_json(&b.join("metrics.json")),
    );
    // RK4's metrics come from 1 ms rows: crossings interpolated linearly
    // between rows (an error of h²·r̈/(8·ṙ), a few µs here), the peak on a
    // row, the rest to RK4's truncation error and the rows' trapezoid.
    for (key, tol) in [
        ("yaw_rate_response_time", 1e-5),
        ("yaw_rate_peak_time", 1e-3),
        ("ay_response_time", 1e-5),
        ("yaw_rate_gain", 1e-9),
        ("er", 1e-6),
    ] {
        let (x, y) = (a[key].as_f64().unwrap(), b[key].as_f64().unwrap());
        assert!((x - y).abs() <= tol, "{key}: rk4 {x} vs dopri5 {y}");
    }
    // Tolerances belong to the adaptive method; an unknown method is named.
    for (file, extra, says) in [
        ("bad.toml", "method = \"rk4\"\nrtol = 1e-9", "rtol"),
        ("bad2.toml", "method = \"rk45\"", "rk45"),
    ] {
        let bad = scenario_with("step_gbt6323_pac89.toml", dir.path(), file, extra);
        let o = run(&[
            "simulate",
            bad.to_str().unwrap(),
            "--out",
            dir.path().join("c").to_str().unwrap(),
        ]);
        assert!(!o.status.success());
        assert!(stderr(&o).contains(says), "{}", stderr(&o));
    }
}

/// A measured run: 12 s at 100 Hz of a driver's steer (three sines) while the
/// car speeds up from 15 to 25 m/s; the responses only give the initial state.
fn measured_run(dir: &Path) -> PathBuf {
    let mut csv = String::from("t,speed,steer,yaw_rate,beta,ay\n");
    for i in 0..=1200 {
        let t = i as f64 * 0.01;
        let steer = 0.02 * (1.3 * t).sin() + 0.01 * (3.1 * t).sin() + 0.004 * (7.0 * t).sin();
        let speed = 15.0 + 10.0 * t / 12.0;
        csv.push_str(&format!("{t},{speed},{steer},0,0,0\n"));
    }
    let p = dir.join("run.csv");
    fs::write(&p, csv).unwrap();
    p
}

/// Columns of a written history.
fn history_columns(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let mut cols = vec![Vec::new(); header.len()];
    for line in lines {
        for (c, v) in cols.iter_mut().zip(line.split(',')) {
            c.push(v.parse::<f64>().unwrap());
        }
    }
    (header, cols)
}

#[test]
fn replay_with_the_default_tolerance_matches_a_tight_reference() {
    let dir = tempfile::tempdir().unwrap();
    measured_run(dir.path());
    let write = |file: &str, settings: &str| {
        let sc = format!(
            "{VEHICLE}\n[tyres]\nfront = \"{}\"\n\n[manoeuvre]\nkind = \"replay\"\nrun = \"run.csv\"\n\n[simulation]\n{settings}\n",
            root().join("tyres/pac89_adams_example.toml").display()
        );
        let p = dir.path().join(file);
        fs::write(&p, sc).unwrap();
        p
    };
    let (d, t) = (write("d.toml", ""), write("t.toml", REFERENCE));
    simulate_to(&d, &dir.path().join("d"));
    simulate_to(&t, &dir.path().join("t"));
    let (header, a) = history_columns(&dir.path().join("d/history.csv"));
    let (_, b) = history_columns(&dir.path().join("t/history.csv"));
    assert_eq!(a[0].len(), 12001, "rows every 1 ms over 12 s");
    for name in ["beta", "yaw_rate", "ay", "fy_front", "fz_fl"] {
        let k = header.iter().position(|h| h == name).unwrap();
        let scale = b[k].iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let worst = a[k]
            .iter()
            .zip(&b[k])
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
        // The replay swings the car through ±0.3 rad/s of yaw rate; its
        // error relative to the channel's range stays within 1e-6.
        assert!(
            scale > 0.0 && worst <= 1e-6 * scale,
            "{name}: {worst:e} of {scale}"
        );
    }
}

#[test]
fn a_scenario_with_tyre_lag_and_roll_steer_integrates_and_writes_the_roll() {
    // The one right-hand side with its extra states, from a file: a tyre
    // lag keeps the steady state, roll steer (front toe-out in roll) makes
    // the car understeer more by its closed form, and the roll is written.
    let dir = tempfile::tempdir().unwrap();
    let base = scenario_with("step_gbt6323_pac89.toml", dir.path(), "base.toml", "");
    let text = fs::read_to_string(&base).unwrap().replace(
        "\n[model]\n",
        "\n[model]\neffects = { relaxation_length = 0.4, roll_steer = [-0.1, 0.0] }\n",
    );
    let lagged = dir.path().join("lagged.toml");
    fs::write(&lagged, text).unwrap();
    let metrics = |p: &Path, out: &str| -> serde_json::Value {
        simulate_to(p, &dir.path().join(out));
        read_json(&dir.path().join(out).join("metrics.json"))
    };
    let (m0, m1) = (metrics(&base, "b"), metrics(&lagged, "l"));
    let gain = |m: &serde_json::Value| m["yaw_rate_gain"].as_f64().unwrap();
    // Roll steer −0.1 at the front steers it out of the turn by 0.1·φ.
    assert!(gain(&m1) < 0.97 * gain(&m0), "{} {}", gain(&m1), gain(&m0));
    let csv = fs::read_to_string(dir.path().join("l/history.csv")).unwrap();
    let header = csv.lines().next().unwrap();
    // The roll, then the body frame's ay (`ay` is what the rolled
    // accelerometer reads).
    assert!(header.ends_with(",roll,ay_body"), "{header}");
    let last: Vec<f64> = csv
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    // Steady roll: 4°/g of the default roll model times the steady ay.
    let (ay, roll) = (last[15], last[14]);
    let k = 4f64.to_radians() / 9.80665;
    assert!((roll - k * ay).abs() < 1e-4 * k * ay.abs(), "{roll} {ay}");
    let h0 = fs::read_to_string(dir.path().join("b/history.csv")).unwrap();
    assert!(!h0.lines().next().unwrap().contains("roll"));
}
