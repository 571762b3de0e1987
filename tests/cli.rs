//! The one integration test binary: runs the `handling` CLI on the bundled
//! scenarios and on broken inputs, and checks what a user sees.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_handling"))
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn run(args: &[&str]) -> Output {
    bin().args(args).current_dir(root()).output().expect("runs")
}

/// Says on the terminal that a test skipped itself: written to the process's
/// stderr directly, past the test harness's capture of `eprintln!`.
fn skipped(test: &str, missing: &Path) {
    use std::io::Write;
    let _ = writeln!(
        std::io::stderr().lock(),
        "SKIPPED {test}: {} is absent",
        missing.display()
    );
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Parses a JSON output file.
fn read_json(p: &Path) -> serde_json::Value {
    serde_json::from_str(&fs::read_to_string(p).unwrap()).unwrap()
}

/// Writes `files` into a fresh folder and returns it.
fn scratch(files: &[(&str, &str)]) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in files {
        fs::write(dir.path().join(name), text).unwrap();
    }
    dir
}

const VEHICLE: &str = "[vehicle]\nmass = 1530.0\nyaw_inertia = 2315.0\na = 1.11\nb = 1.67\ntrack_front = 1.55\ntrack_rear = 1.55\ncg_height = 0.55\n";
const GIM: &str = "model = \"gim\"\ncornering_stiffness = 57296.0\ncontact_length = 0.18\n";
const STEP: &str = "[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\n";

fn scenario(vehicle: &str, tyre: &str, manoeuvre: &str) -> tempfile::TempDir {
    let sc = format!("{vehicle}\n[tyres]\nfront = \"tyre.toml\"\n\n{manoeuvre}");
    scratch(&[("scenario.toml", &sc), ("tyre.toml", tyre)])
}

/// Runs `command input --out dir/out`, expects it to fail without leaving
/// outputs, and returns its stderr.
fn fails_cleanly(command: &str, input: &Path, dir: &Path) -> String {
    let o = run(&[
        command,
        input.to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
    ]);
    assert!(!o.status.success(), "expected failure");
    assert!(
        !dir.join("out").exists(),
        "a failed run must not leave outputs"
    );
    stderr(&o)
}

fn simulate_err(dir: &Path) -> String {
    fails_cleanly("simulate", &dir.join("scenario.toml"), dir)
}

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
    let o = run(&[
        "metrics",
        out.path().join("history.csv").to_str().unwrap(),
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let a: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let b: serde_json::Value = read_json(&out.path().join("metrics.json"));
    for key in ["yaw_rate_response_time", "yaw_rate_overshoot", "er", "tb"] {
        let (x, y) = (a[key].as_f64().unwrap(), b[key].as_f64().unwrap());
        assert!(
            (x - y).abs() <= 1e-9 * y.abs().max(1.0),
            "{key}: {x} vs {y}"
        );
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
        e.contains("manoeuvre.rise_time") && e.contains("0.2 s"),
        "{e}"
    );
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
fn equilibria_sweep_writes_tables_and_figures() {
    let out = tempfile::tempdir().unwrap();
    let o = run(&[
        "equilibria",
        "scenarios/seed003_steer.toml",
        "--out",
        out.path().to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(stdout.contains("agree at 11/11 conditions"), "{stdout}");
    let csv = fs::read_to_string(out.path().join("equilibria.csv")).unwrap();
    assert!(csv.starts_with("steer,friction,speed,beta,yaw_rate,kind,"));
    assert!(csv.lines().count() > 11);
    let bif = fs::read_to_string(out.path().join("bifurcations.csv")).unwrap();
    assert!(
        bif.lines().nth(1).unwrap().starts_with("pitchfork,steer,"),
        "{bif}"
    );
    for png in [
        "branches_steer.png",
        "phase_portrait_0.png",
        "phase_portrait_1.png",
    ] {
        assert!(
            fs::metadata(out.path().join(png)).unwrap().len() > 10_000,
            "{png}"
        );
    }
    let s: serde_json::Value = read_json(&out.path().join("summary.json"));
    assert_eq!(s["seed"], 1);
    assert_eq!(s["agreeing"], 11);
}

#[test]
fn sweep_with_an_unknown_unit_is_refused() {
    let text = fs::read_to_string(root().join("scenarios/seed003_steer.toml")).unwrap();
    let text = text
        .replace("unit = \"km/h\"", "unit = \"mph\"")
        .replace("../tyres/", &format!("{}/tyres/", root().display()));
    let dir = scratch(&[("sweep.toml", &text)]);
    let o = run(&[
        "equilibria",
        dir.path().join("sweep.toml").to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("sweep.toml:") && e.contains("mph") && e.contains("sweep.speed"),
        "{e}"
    );
    assert!(!dir.path().join("out").exists());
}

#[test]
fn seed004_study_writes_map_rbf_and_inverse() {
    let out = tempfile::tempdir().unwrap();
    let o = run(&[
        "study",
        "scenarios/seed004_study.toml",
        "--out",
        out.path().to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        stdout.contains("676 map combinations + 51 RBF pairs"),
        "{stdout}"
    );
    let csv = fs::read_to_string(out.path().join("study.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 676 + 51);
    let rbf: serde_json::Value = read_json(&out.path().join("rbf.json"));
    assert_eq!(rbf["training_pairs"], 46);
    assert_eq!(rbf["validation"].as_array().unwrap().len(), 5);
    let inv: serde_json::Value = read_json(&out.path().join("inverse.json"));
    for t in inv["targets"].as_array().unwrap() {
        let target = t["target"].as_f64().unwrap();
        let er = t["best"]["er_resimulated"].as_f64().unwrap();
        assert!((er - target).abs() <= 1e-5 * target, "{er} vs {target}");
    }
    assert!(fs::metadata(out.path().join("maps.png")).unwrap().len() > 10_000);
}

fn rig_csv(rows: &[(f64, f64, f64)]) -> String {
    let mut s = String::from("fz,alpha,fy\n");
    for (fz, a, fy) in rows {
        s.push_str(&format!("{fz},{a},{fy}\n"));
    }
    s
}

#[test]
fn identify_refuses_bad_rig_data_clearly() {
    // No lateral columns.
    let dir = scratch(&[("rig.csv", "fz,kappa,fx\n4000,0.01,500\n")]);
    let e = stderr(&run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "gim",
    ]));
    assert!(
        e.contains("rig.csv")
            && e.contains("no lateral data")
            && e.contains("no longitudinal force"),
        "{e}"
    );
    // Neither lateral nor longitudinal columns.
    let dir2 = scratch(&[("rig.csv", "fz,speed\n4000,10\n")]);
    let e = stderr(&run(&[
        "identify",
        dir2.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "pac89",
    ]));
    assert!(
        e.contains("no lateral data") && e.contains("no longitudinal data"),
        "{e}"
    );
    // Unknown model.
    let e = stderr(&run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "pac2002",
    ]));
    assert!(e.contains("unknown tyre model `pac2002`"), "{e}");
    // A NaN cell.
    let dir = scratch(&[("rig.csv", "fz,alpha,fy\n4000,0.01,500\n4000,NaN,600\n")]);
    let e = stderr(&run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "gim",
    ]));
    assert!(e.contains("rig.csv:3:2") && e.contains("alpha"), "{e}");
    // A single load for a load-dependent model.
    let rows: Vec<(f64, f64, f64)> = (0..40)
        .map(|i| {
            (
                4000.0,
                0.005 * (i as f64 - 20.0),
                60_000.0 * 0.005 * (i as f64 - 20.0),
            )
        })
        .collect();
    let dir = scratch(&[("rig.csv", &rig_csv(&rows))]);
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "pac89",
        "--bin-deg",
        "0",
        "--out",
        dir.path().join("t.toml").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("at least 3 loads"), "{}", stderr(&o));
    assert!(!dir.path().join("t.toml").exists());
}

#[test]
fn an_identified_tyre_file_loads_and_simulates() {
    let rows: Vec<(f64, f64, f64)> = [2000.0, 4000.0, 6000.0]
        .iter()
        .flat_map(|&fz| {
            (0..41).map(move |i| {
                let a = 0.005 * (i as f64 - 20.0);
                (fz, a, fz * (1.3 * (10.0 * a).atan()).sin())
            })
        })
        .collect();
    let dir = scratch(&[("rig.csv", &rig_csv(&rows))]);
    let tyre = dir.path().join("fitted.toml");
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "magic-simple",
        "--bin-deg",
        "0",
        "--seed",
        "3",
        "--out",
        tyre.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report: serde_json::Value = read_json(&dir.path().join("fitted.report.json"));
    assert_eq!(report["seed"], 3);
    assert!(report["sigma_percent"].as_f64().unwrap() < 1e-6, "{report}");
    for key in ["model", "curves", "parameters", "evaluations", "seconds"] {
        assert!(report.get(key).is_some(), "{key}");
    }
    assert_eq!(report["curves"].as_array().unwrap().len(), 3);
    // The fitted file is a tyre file like any other.
    let sc = format!("{VEHICLE}\n[tyres]\nfront = \"fitted.toml\"\n\n{STEP}");
    fs::write(dir.path().join("scenario.toml"), sc).unwrap();
    let o = run(&[
        "simulate",
        dir.path().join("scenario.toml").to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn real_hoosier_rig_data_fits_within_a_few_percent() {
    let data = root().join("../shared/data/tyre_ttc_hoosier_43075/cornering.csv");
    if !data.exists() {
        skipped("real_hoosier_rig_data_fits_within_a_few_percent", &data);
        return;
    }
    let out = tempfile::tempdir().unwrap();
    let o = run(&[
        "identify",
        data.to_str().unwrap(),
        "--model",
        "pac89",
        "--pressure",
        "83000",
        "--camber",
        "0",
        "--out",
        out.path().join("pac89.toml").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report: serde_json::Value = read_json(&out.path().join("pac89.report.json"));
    let sigma = report["sigma_percent"].as_f64().unwrap();
    assert!(sigma < 3.0, "σ {sigma} %");
    assert_eq!(
        report["curves"].as_array().unwrap().len(),
        5,
        "five loads at one pressure and camber"
    );
}

#[test]
fn identify_fits_longitudinal_only_rig_data() {
    // Fx of the Adams PAC89 example at three loads (kN inside the model):
    // D·sin(C·atan(B·x − E·(B·x − atan(B·x)))), x = 100·κ + Sh.
    let b = [
        1.67272, -9.46, 1490.0, 30.0, 176.0, 0.0886, 0.00402, -0.0615, 0.20, 0.0299, -0.176,
    ];
    let mut s = String::from("fz,kappa,fx\n");
    for fz in [2000.0, 4000.0, 6000.0] {
        let z: f64 = fz / 1000.0;
        let c = b[0];
        let d = b[1] * z * z + b[2] * z;
        let bb = (b[3] * z * z + b[4] * z) * (-b[5] * z).exp() / (c * d);
        let e = b[6] * z * z + b[7] * z + b[8];
        for i in -25..=25 {
            let kappa = 0.01 * i as f64;
            let x = 100.0 * kappa + b[9] * z + b[10];
            let fx = d * (c * (bb * x - e * (bb * x - (bb * x).atan())).atan()).sin();
            s.push_str(&format!("{fz},{kappa},{fx}\n"));
        }
    }
    let dir = scratch(&[("rig.csv", &s)]);
    let out = dir.path().join("fx.toml");
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "pac89",
        "--bin-deg",
        "0",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report: serde_json::Value = read_json(&dir.path().join("fx.report.json"));
    assert_eq!(report["channel"], "longitudinal-force");
    assert!(report["sigma_percent"].as_f64().unwrap() < 0.01, "{report}");
    assert!(fs::read_to_string(&out).unwrap().contains("b = ["));
}

#[test]
fn replaying_a_simulated_run_shows_no_gap_and_a_changed_model_does() {
    let out = tempfile::tempdir().unwrap();
    let o = run(&[
        "simulate",
        "scenarios/seed004_step.toml",
        "--out",
        out.path().to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let hist = out.path().join("history.csv");
    let scenario = |tyre: &str| {
        format!(
            "{VEHICLE}\n[tyres]\nfront = \"{}\"\nrear = \"{}\"\n\n[manoeuvre]\nkind = \"replay\"\nrun = \"{}\"\n",
            root().join(format!("tyres/{tyre}")).display(),
            root().join("tyres/gim_seed004_rear.toml").display(),
            hist.display()
        )
    };
    let gap = |tyre: &str, name: &str| -> serde_json::Value {
        let dir = out.path().join(name);
        fs::create_dir_all(&dir).unwrap();
        fs::write(dir.join("replay.toml"), scenario(tyre)).unwrap();
        let o = run(&[
            "simulate",
            dir.join("replay.toml").to_str().unwrap(),
            "--out",
            dir.join("o").to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        read_json(&dir.join("o/gap.json"))
    };
    let same = gap("gim_seed004_front.toml", "same");
    for ch in same["channels"].as_array().unwrap() {
        assert_eq!(ch["significant"], false, "{ch}");
    }
    // A front tyre twice as stiff: the replay no longer matches.
    let other = gap("gim.toml", "other");
    let yaw = &other["channels"][0];
    assert_eq!(yaw["channel"], "yaw_rate");
    assert_eq!(yaw["significant"], true, "{yaw}");
}

// ---- diagnose / synth (issue 6) ----

/// Writes a synthetic campaign folder with `effects` into `dir/name`.
fn synth(dir: &Path, name: &str, effects: &str, seed: &str) -> PathBuf {
    let out = dir.join(name);
    let o = run(&[
        "synth",
        "--effects",
        effects,
        "--seed",
        seed,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    out
}

#[test]
fn synth_then_diagnose_names_the_withheld_effect_and_shrinks_the_gap() {
    let dir = tempfile::tempdir().unwrap();
    let campaign = synth(dir.path(), "delay", "sensor_delay", "3");
    for f in ["vehicle.toml", "tyre_rig.csv", "runs/sweep_080kph.csv"] {
        assert!(campaign.join(f).is_file(), "{f}");
    }
    // synth never overwrites.
    let again = run(&["synth", "--out", campaign.to_str().unwrap()]);
    assert!(!again.status.success() && stderr(&again).contains("exists"));
    let out = dir.path().join("out");
    let o = run(&[
        "diagnose",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        stdout.contains("verdict: sensor_delay explains the gap"),
        "{stdout}"
    );
    for f in ["diagnosis.json", "gap_map.png", "overlays.png"] {
        assert!(out.join(f).is_file(), "{f}");
    }
    let d = read_json(&out.join("diagnosis.json"));
    assert_eq!(d["verdict"]["effects"], serde_json::json!(["sensor_delay"]));
    assert_eq!(d["seed"], 3);
    let top = &d["ranking"][0];
    assert_eq!(top["effect"], "sensor_delay");
    // The delay is recovered (truth 0.05 s) and most of the gap goes.
    let delay = top["parameters"][0]["value"].as_f64().unwrap();
    assert!((delay - 0.05).abs() < 0.005, "{delay}");
    assert!(top["reduction_percent"].as_f64().unwrap() > 70.0);
    for key in ["heldout_error_before", "heldout_error_after", "bic"] {
        assert!(top[key].is_number(), "{key}");
    }
    assert!(d["gap"]["significant"].as_bool().unwrap());
    assert!(d["confounded"].is_array());
}

fn campaign_err(dir: &Path) -> String {
    fails_cleanly("diagnose", dir, dir)
}

/// A run CSV: a 0.02 rad step at 1 s, first-order yaw response, at `rate` Hz
/// for `seconds`, with `gap` seconds missing after 2 s when given.
fn run_csv(rate: f64, seconds: f64, with_ay: bool, gap: Option<f64>) -> String {
    let mut s = String::from(if with_ay {
        "t,speed,steer,yaw_rate,ay\n"
    } else {
        "t,speed,steer,yaw_rate\n"
    });
    let n = (seconds * rate) as usize;
    for i in 0..=n {
        let mut t = i as f64 / rate;
        if let Some(g) = gap {
            if t > 2.0 {
                t += g;
            }
        }
        let on = t > 1.0;
        let steer = if on { 0.02 } else { 0.0 };
        let r = if on {
            0.2 * (1.0 - (-(t - 1.0) / 0.15).exp())
        } else {
            0.0
        };
        if with_ay {
            s += &format!("{t:.4},20,{steer},{r:.6},{:.5}\n", 20.0 * r);
        } else {
            s += &format!("{t:.4},20,{steer},{r:.6}\n");
        }
    }
    s
}

fn campaign_folder(vehicle: &str, runs: &[(&str, String)]) -> tempfile::TempDir {
    let dir = scratch(&[("vehicle.toml", vehicle)]);
    fs::create_dir(dir.path().join("runs")).unwrap();
    for (name, text) in runs {
        fs::write(dir.path().join("runs").join(name), text).unwrap();
    }
    dir
}

#[test]
fn diagnose_refuses_bad_campaigns_clearly() {
    // A vehicle file missing a key.
    let no_cg = VEHICLE.replace("cg_height = 0.55\n", "");
    let dir = campaign_folder(&no_cg, &[("a.csv", run_csv(100.0, 6.0, true, None))]);
    let e = campaign_err(dir.path());
    assert!(e.contains("vehicle.toml") && e.contains("cg_height"), "{e}");
    // A run too short for the windows.
    let dir = campaign_folder(
        VEHICLE,
        &[
            ("a.csv", run_csv(100.0, 6.0, true, None)),
            ("short.csv", run_csv(100.0, 1.0, true, None)),
        ],
    );
    let e = campaign_err(dir.path());
    assert!(e.contains("short.csv") && e.contains("1.00 s long"), "{e}");
    // One run: nothing to hold out.
    let dir = campaign_folder(VEHICLE, &[("a.csv", run_csv(100.0, 6.0, true, None))]);
    let e = campaign_err(dir.path());
    assert!(e.contains("held-out scoring needs at least two"), "{e}");
    // An unknown effect is named with the list of known ones.
    let v = format!("{VEHICLE}\n[diagnose]\neffects = [\"relaxation\"]\n");
    let dir = campaign_folder(
        &v,
        &[
            ("a.csv", run_csv(100.0, 6.0, true, None)),
            ("b.csv", run_csv(100.0, 6.0, true, None)),
        ],
    );
    let e = campaign_err(dir.path());
    assert!(
        e.contains("unknown effect `relaxation`") && e.contains("relaxation_length"),
        "{e}"
    );
    // A NaN in a run names file, line and column.
    let mut bad = run_csv(100.0, 6.0, true, None);
    bad = bad.replacen(
        "\n0.0500,20,0,0.000000,0.00000\n",
        "\n0.0500,20,0,NaN,0.00000\n",
        1,
    );
    let dir = campaign_folder(
        VEHICLE,
        &[("a.csv", bad), ("b.csv", run_csv(100.0, 6.0, true, None))],
    );
    let e = campaign_err(dir.path());
    assert!(e.contains("a.csv:7:") && e.contains("yaw_rate"), "{e}");
    // A folder without vehicle.toml.
    let empty = tempfile::tempdir().unwrap();
    let e = campaign_err(empty.path());
    assert!(e.contains("vehicle.toml"), "{e}");
}

#[test]
fn diagnose_handles_mixed_rates_gaps_and_missing_channels() {
    // Linear tyres given, one candidate: the point is the input handling.
    let v = format!(
        "{VEHICLE}\n[tyres]\nfile = \"tyre.toml\"\n\n[diagnose]\neffects = [\"sensor_bias\"]\n"
    );
    let dir = campaign_folder(
        &v,
        &[
            ("a_100hz.csv", run_csv(100.0, 6.0, true, None)),
            ("b_40hz_no_ay.csv", run_csv(40.0, 6.0, false, None)),
            ("c_gap.csv", run_csv(100.0, 8.0, true, Some(1.5))),
        ],
    );
    fs::write(
        dir.path().join("tyre.toml"),
        "model = \"linear\"\ncornering_stiffness = 60000.0\n",
    )
    .unwrap();
    let out = dir.path().join("out");
    let o = run(&[
        "diagnose",
        dir.path().to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        stdout.contains("c_gap.csv: time gaps at 2.000–3.510 s"),
        "{stdout}"
    );
    let d = read_json(&out.join("diagnosis.json"));
    // The gap split c into two pieces: four runs replayed.
    assert_eq!(d["runs"].as_array().unwrap().len(), 4);
    // The run without ay is compared on yaw rate only.
    let b = d["gap"]["runs"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["run"].as_str().unwrap().ends_with("b_40hz_no_ay.csv"))
        .unwrap();
    assert_eq!(b["channels"].as_array().unwrap().len(), 1);
    assert_eq!(b["channels"][0]["channel"], "yaw_rate");
}

/// Diagnoses a synthetic campaign with `truth` withheld (library API).
fn diagnose_synthetic(
    truth: &[handling::diagnose::effects::EffectKind],
    seed: u64,
) -> handling::diagnose::Diagnosis {
    use handling::diagnose::synth::{generate, truth_values, Noise, SynthSpec};
    let s = generate(&SynthSpec {
        effects: truth.iter().map(|e| (*e, truth_values(*e))).collect(),
        seed,
        noise: Noise::default(),
    });
    let dir = tempfile::tempdir().unwrap();
    let rig = dir.path().join("rig.csv");
    let [fz, alpha, fy] = s.rig_columns();
    handling::report::write_columns(&rig, &[("fz", &fz), ("alpha", &alpha), ("fy", &fy)]).unwrap();
    let settings = handling::io::campaign::DiagnoseSettings {
        seed,
        ..Default::default()
    };
    let c = s.campaign(
        rig,
        handling::diagnose::effects::EffectKind::ALL.to_vec(),
        settings,
    );
    handling::diagnose::diagnose(&c, None).unwrap()
}

#[test]
fn no_effect_gives_an_empty_verdict_and_a_pair_is_found_together() {
    use handling::diagnose::effects::EffectKind;
    // Only measurement noise and the tyre's model-form error: no gap.
    let d = diagnose_synthetic(&[], 4);
    assert!(d.verdict.effects.is_empty(), "{}", d.verdict.statement);
    assert!(!d.gap.significant);
    assert!(d.verdict.statement.starts_with("no significant gap"));
    // A tyre lag and sensor offsets together: each alone explains less than
    // the acceptance share, the pair nearly all of it.
    let d = diagnose_synthetic(&[EffectKind::RelaxationLength, EffectKind::SensorBias], 4);
    let mut found = d.verdict.effects.clone();
    found.sort();
    assert_eq!(
        found,
        ["relaxation_length", "sensor_bias"],
        "{}",
        d.verdict.statement
    );
    let pair = d
        .combinations
        .iter()
        .find(|r| r.effects == d.verdict.effects)
        .unwrap();
    assert!(pair.reduction_percent > 70.0, "{}", pair.reduction_percent);
    let sigma = pair
        .parameters
        .iter()
        .find(|p| p.name == "relaxation_length.relaxation_length")
        .unwrap();
    assert!((sigma.value - 0.8).abs() < 0.1, "{}", sigma.value);
}

#[test]
fn look_alike_effects_are_reported_as_confounded_and_runs_reproduce() {
    use handling::diagnose::effects::EffectKind;
    // Steering compliance and a softer front axle are the same thing in the
    // linear range: named, and reported as confounded with the test that
    // separates them.
    let d = diagnose_synthetic(&[EffectKind::SteeringCompliance], 5);
    assert_eq!(
        d.verdict.effects,
        ["steering_compliance"],
        "{}",
        d.verdict.statement
    );
    let group = &d.confounded[0];
    assert_eq!(group.effects[0], "steering_compliance");
    assert!(group.effects.contains(&"cornering_stiffness".to_string()));
    assert!(group.separating_test.contains("cornering_stiffness:"));
    let c = d.verdict.parameters[0].value;
    assert!((c - 0.003).abs() < 0.0003, "{c} rad/kN");
    // Reproducible: the same seed gives the same numbers (compared as text:
    // an unidentifiable parameter's standard error is NaN).
    let again = diagnose_synthetic(&[EffectKind::SteeringCompliance], 5);
    assert_eq!(format!("{:?}", again.ranking), format!("{:?}", d.ranking));
    assert_eq!(format!("{:?}", again.verdict), format!("{:?}", d.verdict));
}

#[test]
fn real_racing_log_is_diagnosed_with_axle_characteristics_from_the_runs() {
    let log = root().join("../shared/data/run_iac_putnam/putnam_run4_2.csv");
    if !log.is_file() {
        skipped(
            "real_racing_log_is_diagnosed_with_axle_characteristics_from_the_runs",
            &log,
        );
        return;
    }
    // The bundled campaign, cut to 40 s pieces and two candidates to keep
    // the test short (the README runs the full library).
    let text = fs::read_to_string(root().join("campaigns/putnam.toml"))
        .unwrap()
        .replace(
            "\"../../shared/data/run_iac_putnam/putnam_run4_2.csv\"",
            &format!("{:?}", log.to_str().unwrap()),
        )
        .replace("segment = 20.0", "segment = 40.0")
        .replace(
            "[diagnose]\nseed = 1",
            "[diagnose]\nseed = 1\neffects = [\"sensor_delay\", \"relaxation_length\"]\nmax_effects = 1",
        );
    let dir = scratch(&[("putnam.toml", &text)]);
    let out = dir.path().join("out");
    let o = run(&[
        "diagnose",
        dir.path().join("putnam.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let d = read_json(&out.join("diagnosis.json"));
    assert_eq!(d["runs"].as_array().unwrap().len(), 12);
    assert!(d["base"]["tyres"]
        .as_str()
        .unwrap()
        .starts_with("no tyre data: axle characteristics identified from the runs"));
    // The log has yaw rate and sideslip, no ay.
    let noise: Vec<&str> = d["gap"]["noise"]
        .as_array()
        .unwrap()
        .iter()
        .map(|n| n["channel"].as_str().unwrap())
        .collect();
    assert_eq!(noise, ["yaw_rate", "beta"]);
    // A 2-DOF model of a racing car driven hard does not match to the noise.
    assert!(d["gap"]["significant"].as_bool().unwrap());
    assert_eq!(d["ranking"].as_array().unwrap().len(), 2);
    for f in ["gap_map.png", "overlays.png"] {
        assert!(out.join(f).is_file());
    }
}
