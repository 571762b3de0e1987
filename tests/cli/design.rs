//! `handling design` run as a user runs it: a campaign that confounds a
//! sensor delay with a steer delay, diagnosed, designed for, the best
//! manoeuvre simulated from its scenario file and driven on the proving
//! ground, and the run measured against the prediction.

use super::*;

/// A synthetic campaign with a sensor delay, diagnosed against the two
/// delays only (they come out confounded): its folder and diagnosis folder.
fn confounded(dir: &Path, seed: &str) -> (PathBuf, PathBuf) {
    let camp = synth_campaign(dir, "camp", &["--effects", "sensor_delay", "--seed", seed]);
    let mut toml = fs::read_to_string(camp.join("vehicle.toml")).unwrap();
    toml.push_str("effects = [\"sensor_delay\", \"steer_path\"]\n");
    fs::write(camp.join("vehicle.toml"), toml).unwrap();
    let out = dir.join("diagnosis");
    let (_, d) = diagnose_to(&camp, &out);
    assert_eq!(
        d["confounded"][0]["effects"],
        serde_json::json!(["sensor_delay", "steer_path"])
    );
    (camp, out)
}

#[test]
fn a_confounded_delay_gets_a_manoeuvre_whose_speed_changes_written_as_a_scenario_that_runs() {
    let dir = tempfile::tempdir().unwrap();
    let (camp, diag) = confounded(dir.path(), "1");
    let o = run(&["design", diag.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("sensor_delay / steer_path: the two fitted models' replays of the campaign's runs differ by D = "),
        "{text}"
    );
    let design = diag.join("design");
    let j = read_json(&design.join("design.json"));
    let set = &j["sets"][0];
    assert_eq!(
        set["members"],
        serde_json::json!(["sensor_delay", "steer_path"])
    );
    let best = &set["ranked"][0];
    // At constant speed a delay of the steer and a delay of the sensors
    // are the same response: only a speed change tells them apart.
    let kind = best["kind"].as_str().unwrap();
    assert!(
        ["brake_in_turn", "accelerate_in_turn", "constant_radius"].contains(&kind),
        "{best}"
    );
    let (d, u) = (
        best["separation"].as_f64().unwrap(),
        best["uncertainty"].as_f64().unwrap(),
    );
    // The uncertainty is the noise's (1 at least) widened by the scatter
    // the campaign's own runs measure their separations with.
    let inflation = set["calibration"]["inflation"].as_f64().unwrap();
    assert!(
        d > 1.5 * set["campaign_separation"].as_f64().unwrap()
            && u >= inflation
            && inflation >= 1.0,
        "{best} {}",
        set["calibration"]
    );
    assert!(set["calibration"]["runs"].as_u64().unwrap() >= 2, "{set}");
    assert!(
        best["peak_ay"].as_f64().unwrap()
            <= 1.1
                * j["limits"]["ay_share"].as_f64().unwrap()
                * j["limits"]["ay_reached"].as_f64().unwrap()
    );
    // Its scenario file runs in `simulate` as written.
    let name = best["name"].as_str().unwrap();
    let scenario = design.join("scenarios").join(format!("{name}.toml"));
    // Its schedule with the digits it carries (`20.899999998637263` and
    // `1.1400000000000001` were written).
    let written = fs::read_to_string(&scenario).unwrap();
    for key in ["t = [", "steer = [", "speed = ["] {
        let line = written.lines().find(|l| l.starts_with(key)).unwrap();
        for v in line[key.len()..line.len() - 1].split(", ") {
            let digits = v.chars().filter(char::is_ascii_digit).count();
            assert!(digits <= 12 && v.parse::<f64>().is_ok(), "{v} in {line}");
        }
    }
    let sim = dir.path().join("sim");
    let o = run(&[
        "simulate",
        scenario.to_str().unwrap(),
        "--out",
        sim.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(sim.join("history.csv").exists());
    assert!(design.join("separation.png").exists());
    // Driven on the proving ground (the same truth and seed) as a further
    // run, and measured with the candidates as diagnosed before it.
    let driven = dir.path().join("driven");
    let o = run(&[
        "synth",
        "--effects",
        "sensor_delay",
        "--seed",
        "1",
        "--drive",
        scenario.to_str().unwrap(),
        "--out",
        driven.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout)
        .contains("9 handling runs, 1 of them driven from scenario files"));
    let before = fs::read(camp.join("runs/step_040kph_3ms2.csv")).unwrap();
    assert_eq!(
        fs::read(driven.join("runs/step_040kph_3ms2.csv")).unwrap(),
        before,
        "a driven run moved the programme's noise"
    );
    let run_csv = driven.join("runs").join(format!("{name}.csv"));
    let out = dir.path().join("measured");
    let o = run(&[
        "design",
        diag.to_str().unwrap(),
        "--measured",
        run_csv.to_str().unwrap(),
        "--measured",
        camp.join("runs/step_040kph_3ms2.csv").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let j = read_json(&out.join("design.json"));
    let m = &j["measured"][0];
    assert!(m["separation"].as_f64().unwrap().is_finite(), "{m}");
    // The driven run is compared with what the design predicted for it,
    // and was driven as designed (its steer is the schedule's).
    let p = &m["predicted"];
    assert_eq!(p["manoeuvre"], name, "{m}");
    assert!(p["steer_difference"].as_f64().unwrap() < 1e-9, "{m}");
    let dev = p["deviation"].as_f64().unwrap();
    let (measured_d, expected, sigma) = (
        m["separation"].as_f64().unwrap(),
        p["expected"].as_f64().unwrap(),
        p["uncertainty"].as_f64().unwrap(),
    );
    assert!((dev - (measured_d - expected) / sigma).abs() < 1e-9, "{m}");
    // What the run measured lies within the stated uncertainty of what
    // was predicted for it (the noise floors alone put it 15 σ off).
    assert!(dev.abs() < 2.0, "{m}");
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("separates them by"), "{text}");
    assert!(
        text.contains(&format!("  predicted for {name}: ")),
        "{text}"
    );
    // A run that is no designed manoeuvre is measured, with no prediction.
    assert!(
        j["measured"][1]["predicted"].is_null(),
        "{}",
        j["measured"][1]
    );
    assert!(
        text.contains(
            "no prediction to compare: the family has no manoeuvre of this run's file name"
        ),
        "{text}"
    );
    // The same folder reused for a design of one manoeuvre: the other
    // scenario files of the first are removed, and said to be.
    let o = run(&[
        "design",
        diag.to_str().unwrap(),
        "--top",
        "1",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("removed 2 scenario files of an earlier design"),
        "{text}"
    );
    let left: Vec<_> = fs::read_dir(out.join("scenarios"))
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.path().extension().is_some_and(|x| x == "toml"))
        .collect();
    assert_eq!(left.len(), 1, "{left:?}");
    // The driven campaign holds every run diagnosed; one short of a run
    // is another campaign's, refused.
    let o = run(&[
        "design",
        diag.to_str().unwrap(),
        "--campaign",
        driven.to_str().unwrap(),
        "--out",
        dir.path().join("d2").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    fs::remove_file(driven.join("runs/step_040kph_3ms2.csv")).unwrap();
    let o = run(&[
        "design",
        diag.to_str().unwrap(),
        "--campaign",
        driven.to_str().unwrap(),
        "--out",
        dir.path().join("d3").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("has no run `step_040kph_3ms2.csv`, which")
            && stderr(&o).contains("(1 of its 8 runs missing)"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn a_design_asks_for_candidates_the_diagnosis_fitted() {
    let dir = tempfile::tempdir().unwrap();
    let (_, diag) = confounded(dir.path(), "2");
    let o = run(&[
        "design",
        diag.to_str().unwrap(),
        "--effects",
        "sensor_delay,yaw_inertia",
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("the diagnosis did not fit `yaw_inertia`; it fitted: "),
        "{e}"
    );
    let o = run(&[
        "design",
        diag.to_str().unwrap(),
        "--effects",
        "sensor_dely,steer_path",
    ]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("sensor_delay"), "{}", stderr(&o));
    // Options no design can honour are refused by name and value, never a
    // panic (`--max-ax 0` indexed an empty schedule).
    for (opt, value, says) in [
        ("--max-ax", "0", "`--max-ax` = 0: must lie in (0, 15]"),
        ("--max-ax", "nan", "`--max-ax` = NaN: must be a finite number"),
        (
            "--ay-share",
            "1.2",
            "`--ay-share` = 1.2: must lie in (0, 1]: a design asks at most the lateral acceleration the runs reached",
        ),
        ("--ay-share", "0", "`--ay-share` = 0: must lie in (0, 1]"),
        ("--top", "0", "`--top` = 0: must be positive"),
        (
            "--effects",
            "sensor_delay,sensor_delay",
            "`--effects`: `sensor_delay` is given more than once",
        ),
        (
            "--effects",
            "sensor_delay+steer_path,steer_path+sensor_delay",
            "`--effects`: `steer_path+sensor_delay` is given more than once",
        ),
    ] {
        let o = run(&["design", diag.to_str().unwrap(), opt, value]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{opt} {value}: {e}");
        assert!(
            e.contains(says) && !e.contains("panicked"),
            "{opt} {value}: {e}"
        );
    }
    // A candidate the diagnosis screened out is said to be so, with its
    // in-sample share, not called "not fitted".
    let camp = synth_campaign(
        dir.path(),
        "wide",
        &["--effects", "sensor_delay", "--seed", "2"],
    );
    let mut toml = fs::read_to_string(camp.join("vehicle.toml")).unwrap();
    toml.push_str("effects = [\"sensor_delay\", \"steer_path\", \"roll_steer\"]\n");
    fs::write(camp.join("vehicle.toml"), toml).unwrap();
    // Diagnosed from the campaign's own folder, so the diagnosis names it
    // by a relative path.
    let o = bin()
        .args(["diagnose", "wide", "--out", "wide_diagnosis"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let wide = dir.path().join("wide_diagnosis");
    let d = read_json(&wide.join("diagnosis.json"));
    assert_eq!(
        d["screened"][0]["effect"], "roll_steer",
        "{}",
        d["screened"]
    );
    let o = run(&[
        "design",
        wide.to_str().unwrap(),
        "--campaign",
        camp.to_str().unwrap(),
        "--effects",
        "sensor_delay,roll_steer",
    ]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(
        e.contains(
            "the diagnosis screened `roll_steer` out before cross-validating it (it removes "
        ) && e.contains("so it has no held-out fit to design with; it cross-validated: "),
        "{e}"
    );
    // From another folder its relative campaign is found where it was
    // when diagnosed (the diagnosis keeps its absolute path too).
    assert!(
        d["source_absolute"].as_str().unwrap().ends_with("/wide"),
        "{d}"
    );
    let o = run(&[
        "design",
        wide.to_str().unwrap(),
        "--out",
        dir.path().join("w0").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    // Moved since, it is not found: said, with both paths and the option
    // that gives it; given, the design runs.
    let moved = dir.path().join("wide_moved");
    fs::rename(&camp, &moved).unwrap();
    let o = run(&[
        "design",
        wide.to_str().unwrap(),
        "--out",
        dir.path().join("w").to_str().unwrap(),
    ]);
    let e = stderr(&o);
    assert!(
        e.contains("wide: the campaign ")
            && e.contains("is not found from here (a relative path is read from where `diagnose` ran), nor at ")
            && e.contains("/wide, where it was then: give it with --campaign"),
        "{e}"
    );
    let camp = moved;
    let o = run(&[
        "design",
        wide.to_str().unwrap(),
        "--campaign",
        camp.to_str().unwrap(),
        "--out",
        dir.path().join("w").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    // A scenario driven under a run's name the campaign has, or given twice,
    // is refused with the name and where it comes from (it was once called
    // an input of the run, and a repeat silently overwrote the first).
    let text = fs::read_to_string(root().join("scenarios/step_gbt6323_gim.toml"))
        .unwrap()
        .replace("../tyres/", &format!("{}/tyres/", root().display()));
    let clash = dir.path().join("step_040kph_3ms2.toml");
    fs::write(&clash, &text).unwrap();
    let again = dir.path().join("again.toml");
    fs::write(&again, &text).unwrap();
    for (drives, says) in [
        (
            vec![&clash],
            "the campaign already has a run named `step_040kph_3ms2` (one of the programme's own)",
        ),
        (
            vec![&again, &again],
            "the campaign already has a run named `again` (driven from an earlier --drive file)",
        ),
    ] {
        let mut args = vec!["synth", "--effects", "sensor_delay", "--seed", "2"];
        for d in &drives {
            args.extend(["--drive", d.to_str().unwrap()]);
        }
        let out = dir.path().join("never");
        args.extend(["--out", out.to_str().unwrap()]);
        let o = run(&args);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{e}");
        assert!(e.contains(says) && e.contains("rename the file"), "{e}");
        assert!(!out.exists());
    }
    // A schedule with a time out of order is refused at its element.
    let bad = dir.path().join("bad.toml");
    let text = fs::read_to_string(root().join("scenarios/step_gbt6323_gim.toml")).unwrap();
    let head = text
        .split("[manoeuvre]")
        .next()
        .unwrap()
        .replace("../tyres/", &format!("{}/tyres/", root().display()));
    fs::write(&bad, format!("{head}[manoeuvre]\nkind = \"schedule\"\nt = [0, 1, 1]\nsteer = [0, 0.01, 0.01]\nspeed = [20, 20, 20]\n")).unwrap();
    let o = run(&[
        "simulate",
        bad.to_str().unwrap(),
        "--out",
        dir.path().join("x").to_str().unwrap(),
    ]);
    let e = stderr(&o);
    assert!(
        e.contains("`manoeuvre.t[2]` = 1: not after the time before it, 1 s"),
        "{e}"
    );
}

#[test]
fn a_run_of_any_designed_manoeuvre_is_compared_named_apart_from_the_programme_and_said_partial() {
    let dir = tempfile::tempdir().unwrap();
    let (camp, diag) = confounded(dir.path(), "2");
    let all = dir.path().join("all");
    let o = run(&[
        "design",
        diag.to_str().unwrap(),
        "--top",
        "40",
        "--out",
        all.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let j = read_json(&all.join("design.json"));
    let names: Vec<&str> = j["sets"][0]["ranked"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap())
        .collect();
    // The family's sweep at 80 km/h would share the programme's run's
    // name: it is renamed.
    for r in fs::read_dir(camp.join("runs")).unwrap() {
        let stem = r
            .unwrap()
            .path()
            .file_stem()
            .unwrap()
            .to_string_lossy()
            .into_owned();
        assert!(!names.contains(&stem.as_str()), "{stem} in {names:?}");
    }
    assert!(names.contains(&"sweep_080kph_designed"), "{names:?}");
    // The fifth best, driven and measured under a design of the best
    // three, is still compared with its prediction.
    let fifth = names[4];
    let driven = dir.path().join("driven");
    let scenario = all.join("scenarios").join(format!("{fifth}.toml"));
    let o = run(&[
        "synth",
        "--effects",
        "sensor_delay",
        "--seed",
        "2",
        "--drive",
        scenario.to_str().unwrap(),
        "--out",
        driven.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let csv = driven.join("runs").join(format!("{fifth}.csv"));
    let out = dir.path().join("m");
    let o = run(&[
        "design",
        diag.to_str().unwrap(),
        "--measured",
        csv.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let j = read_json(&out.join("design.json"));
    assert_eq!(j["sets"][0]["ranked"].as_array().unwrap().len(), 3);
    let p = &j["measured"][0]["predicted"];
    assert_eq!(p["manoeuvre"], fifth, "{}", j["measured"][0]);
    assert!(p["coverage"].as_f64().unwrap() > 0.99, "{p}");
    assert!(!String::from_utf8_lossy(&o.stdout).contains("warning"));
    // The same run cut to its first half, without its sideslip column:
    // both said.
    let text = fs::read_to_string(&csv).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let header: Vec<&str> = lines[0].split(',').collect();
    let beta = header.iter().position(|h| *h == "beta").unwrap();
    let cut: Vec<String> = lines[..lines.len() / 2]
        .iter()
        .map(|l| {
            let mut f: Vec<&str> = l.split(',').collect();
            f.remove(beta);
            f.join(",")
        })
        .collect();
    let part_dir = dir.path().join("part");
    fs::create_dir_all(&part_dir).unwrap();
    let part = part_dir.join(format!("{fifth}.csv"));
    fs::write(&part, cut.join("\n") + "\n").unwrap();
    let o = run(&[
        "design",
        diag.to_str().unwrap(),
        "--measured",
        part.to_str().unwrap(),
        "--out",
        dir.path().join("m2").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("warning: the run covers 4") || text.contains("warning: the run covers 5"),
        "{text}"
    );
    assert!(
        text.contains("warning: the run does not log beta"),
        "{text}"
    );
}
