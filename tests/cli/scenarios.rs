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
    let out = tempfile::tempdir().unwrap();
    let o = run(&[
        "simulate",
        "scenarios/seed004_step.toml",
        "--out",
        out.path().to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let history = out.path().join("history.csv");
    let metrics = |extra: &[&str]| -> serde_json::Value {
        let mut args = vec!["metrics", history.to_str().unwrap(), "--json"];
        args.extend_from_slice(extra);
        let o = run(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        serde_json::from_slice(&o.stdout).unwrap()
    };
    let b: serde_json::Value = read_json(&out.path().join("metrics.json"));
    // Unfiltered, as a simulated record is measured: the same numbers.
    let a = metrics(&["--filter-hz", "0"]);
    for key in ["yaw_rate_response_time", "yaw_rate_overshoot", "er", "tb"] {
        let (x, y) = (a[key].as_f64().unwrap(), b[key].as_f64().unwrap());
        assert!(
            (x - y).abs() <= 1e-9 * y.abs().max(1.0),
            "{key}: {x} vs {y}"
        );
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
    assert!(e.contains("yaw_inertai"), "{e}");
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
    assert!(e.contains("scenario.toml:2:1"), "{e}");
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
