//! What a new user trips on, run as a user runs the tool: each test is one
//! thing a fresh user met, and the message or refusal the tool now gives.

use super::*;

/// The stderr of `args`, which must fail.
fn fails(args: &[&str]) -> String {
    let o = run(args);
    assert!(!o.status.success(), "expected failure: {args:?}");
    stderr(&o)
}

#[test]
fn a_mistyped_effect_model_or_programme_is_answered_with_the_nearest_name() {
    let e = fails(&[
        "synth",
        "--effects",
        "sensor_dely",
        "--out",
        "/nonexistent/x",
    ]);
    assert!(
        e.contains("unknown effect `sensor_dely` (did you mean `sensor_delay`?): one of none,"),
        "{e}"
    );
    let e = fails(&["synth", "--programme", "ovl", "--out", "/nonexistent/x"]);
    assert!(e.contains("(did you mean `oval`?)"), "{e}");
    // Nothing near: no guess.
    let e = fails(&[
        "synth",
        "--programme",
        "autobahn",
        "--out",
        "/nonexistent/x",
    ]);
    assert!(!e.contains("did you mean"), "{e}");
    let dir = scratch(&[("rig.csv", "fz,alpha,fy\n4000,0.01,800\n")]);
    let o = identify_to(
        &dir.path().join("rig.csv"),
        "pac98",
        &dir.path().join("t.toml"),
    );
    let e = refused(&o, &dir.path().join("t.toml"));
    assert!(e.contains("(did you mean `pac89`?)"), "{e}");
    // A tyre file's model, and a campaign's effects (read by the campaign
    // reader, at their key and line).
    let dir = scenario(VEHICLE, "model = \"unitrie\"\n", STEP);
    let e = simulate_err(dir.path());
    assert!(
        e.contains("tyre.toml:1:9")
            && e.contains("unknown variant `unitrie` (did you mean `unitire`?)"),
        "{e}"
    );
    let campaign = format!("{VEHICLE}\n[diagnose]\neffects = [\"relaxation_lenght\"]\n");
    let dir = scratch(&[("campaign.toml", &campaign)]);
    let e = fails_cleanly("diagnose", &dir.path().join("campaign.toml"), dir.path());
    assert!(e.contains("campaign.toml:"), "{e}");
    assert!(
        e.contains("unknown effect `relaxation_lenght` (did you mean `relaxation_length`?)"),
        "{e}"
    );
}

/// A run at 20 m/s whose steer is `steer(t)`, sampled at 100 Hz for 6 s.
fn run_csv(steer: impl Fn(f64) -> f64) -> String {
    let mut s = String::from("t,speed,steer,yaw_rate,ay\n");
    for k in 0..600 {
        let t = 0.01 * f64::from(k);
        let d = steer(t);
        s += &format!("{t},20,{d},{},{}\n", 4.0 * d, 80.0 * d);
    }
    s
}

#[test]
fn metrics_of_a_run_without_a_step_say_what_the_steer_does() {
    let dir = scratch(&[
        ("still.csv", &run_csv(|_| 0.0)),
        ("tiny.csv", &run_csv(|t| if t > 2.0 { 1e-4 } else { 0.0 })),
    ]);
    let e = fails(&["metrics", dir.path().join("still.csv").to_str().unwrap()]);
    assert!(
        e.contains("the steer stays at 0 rad (0.00°) from the initial window to the steady one; a step steer needs a change of at least 0.00017 rad (0.01°)"),
        "{e}"
    );
    assert!(!e.contains("e0 rad") && !e.contains("e-"), "{e}");
    let e = fails(&["metrics", dir.path().join("tiny.csv").to_str().unwrap()]);
    assert!(
        e.contains(
            "a change of 0.00010 rad (0.006°), less than the 0.00017 rad (0.010°) a step steer needs"
        ),
        "{e}"
    );
}

#[test]
fn simulate_refuses_a_steer_no_road_wheel_makes_and_a_step_of_nothing_at_its_key() {
    for (steer, expected) in [
        (
            "1.7",
            "`manoeuvre.steer` = 1.7: must lie within ±0.785398: no road wheel steers beyond ±45°",
        ),
        (
            "0",
            "`manoeuvre.steer` = 0: a step steer needs a steer step of at least 0.00017 rad (0.01°) from straight running",
        ),
    ] {
        let dir = scenario(
            VEHICLE,
            GIM,
            &format!("[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2\nsteer = {steer}\n"),
        );
        let e = simulate_err(dir.path());
        let file = dir.path().join("scenario.toml");
        assert!(e.contains(&format!("{}:", file.display())), "{e}");
        assert!(e.contains(expected), "{steer}: {e}");
    }
    // A sine of 60° of road-wheel steer likewise.
    let dir = scenario(
        VEHICLE,
        GIM,
        "[manoeuvre]\nkind = \"sine\"\nspeed = 20.0\namplitude = 1.05\nfrequency = 0.5\nend = 4.0\n",
    );
    let e = simulate_err(dir.path());
    assert!(
        e.contains("`manoeuvre.amplitude` = 1.05: must lie within ±0.785398"),
        "{e}"
    );
}

#[test]
fn tyre_eval_refuses_a_point_no_tyre_is_evaluated_at_by_row_and_never_writes_a_non_finite_value() {
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    for (row, column, expected) in [
        (
            "4000,1e308,0.01,0,16.7",
            2,
            "column `kappa`: 1e308 is above 10, the largest a tyre is evaluated at",
        ),
        (
            "4000,0.01,0.01,0,1e308",
            5,
            "column `speed`: 1e308 m/s is above 300 m/s, the largest a tyre is evaluated at",
        ),
        (
            "4000,0.01,2.0,0,16.7",
            3,
            "column `alpha`: 2 rad is beyond ±90°: angles are in radians (FORMATS.md); is the column in degrees?",
        ),
    ] {
        let points = format!("fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n{row}\n");
        let dir = scratch(&[("points.csv", &points)]);
        let out = dir.path().join("forces.csv");
        let o = run(&[
            "tyre-eval",
            tir.to_str().unwrap(),
            dir.path().join("points.csv").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let e = refused(&o, &out);
        assert!(
            e.contains(&format!("points.csv:3:{column}: {expected}")),
            "{e}"
        );
        assert!(!e.contains("at the limits"), "{e}");
    }
    // Physical points outside the file's ranges: evaluated at the ranges'
    // ends, said so, and every value written finite.
    let points = "fz,kappa,alpha,camber,speed\n4000,0.01,0.05,0,16.7\n30000,5,1.2,0,100\n";
    let dir = scratch(&[("points.csv", points)]);
    let out = dir.path().join("forces.csv");
    let o = run(&[
        "tyre-eval",
        tir.to_str().unwrap(),
        dir.path().join("points.csv").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("1 of them outside the file's ranges of load, slip, camber or pressure, evaluated at the ranges' ends"),
        "{said}"
    );
    let text = fs::read_to_string(&out).unwrap();
    for cell in text.lines().skip(1).flat_map(|l| l.split(',')) {
        let v: f64 = cell.parse().unwrap();
        assert!(v.is_finite() && v.abs() < 1e6, "{cell} in\n{text}");
    }
}

#[test]
fn a_toml_file_that_is_not_utf8_is_refused_at_its_line_and_column() {
    let dir = scenario(VEHICLE, GIM, STEP);
    let file = dir.path().join("scenario.toml");
    let mut bytes = b"# Lat\xe9ral step\n".to_vec();
    bytes.extend(fs::read(&file).unwrap());
    fs::write(&file, bytes).unwrap();
    let e = simulate_err(dir.path());
    assert!(
        e.contains(&format!("{}:1:6: byte 0xE9 is not UTF-8", file.display())),
        "{e}"
    );
}

#[test]
fn a_tyre_array_one_short_and_a_wrong_type_are_refused_at_their_key_and_line() {
    let pac = fs::read_to_string(root().join("tyres/pac89_adams_example.toml")).unwrap();
    let short = pac.replace(", 6.26206]", "]");
    assert_ne!(short, pac);
    let line = short.lines().position(|l| l.starts_with("a = ")).unwrap() + 1;
    let dir = scenario(VEHICLE, &short, STEP);
    let e = simulate_err(dir.path());
    assert!(e.contains(&format!("tyre.toml:{line}:")), "{e}");
    assert!(e.contains("`a`"), "{e}");
    for (manoeuvre, key) in [
        (
            "kind = \"step-steer\"\nspeed = \"fast\"\nsteer = 0.0174533\n",
            "speed",
        ),
        (
            "kind = \"step-steer\"\nspeed = 22.2\nsteer = 0.0174533\nend = [6.0]\n",
            "end",
        ),
    ] {
        let dir = scenario(VEHICLE, GIM, &format!("[manoeuvre]\n{manoeuvre}"));
        let text = fs::read_to_string(dir.path().join("scenario.toml")).unwrap();
        let line = text
            .lines()
            .position(|l| l.starts_with(&format!("{key} =")))
            .unwrap()
            + 1;
        let e = simulate_err(dir.path());
        assert!(
            e.contains(&format!("scenario.toml:{line}:"))
                && e.contains(&format!("manoeuvre.{key}")),
            "{key}: {e}"
        );
    }
}

/// Sets the modification time of `file` to `seconds` ago.
fn age_by(file: &Path, seconds: u64) {
    let then = std::time::SystemTime::now() - std::time::Duration::from_secs(seconds);
    fs::File::options()
        .write(true)
        .open(file)
        .unwrap()
        .set_modified(then)
        .unwrap();
}

#[test]
fn a_lock_that_names_no_process_is_refused_while_fresh_and_taken_over_once_old() {
    for text in ["", "not a pid\n"] {
        let dir = scenario(VEHICLE, GIM, STEP);
        let out = dir.path().join("out");
        fs::create_dir(&out).unwrap();
        let lock = out.join(".handling.lock");
        fs::write(&lock, text).unwrap();
        let args = [
            "simulate",
            dir.path().join("scenario.toml").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]
        .map(String::from);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let e = fails(&args);
        assert!(
            e.contains("the lock names none, and is taken over once it is 10 s old"),
            "{text:?}: {e}"
        );
        age_by(&lock, 60);
        let o = run(&args);
        assert!(o.status.success(), "{text:?}: {}", stderr(&o));
        let note = stderr(&o);
        assert!(note.contains("taking the folder over"), "{note}");
        assert!(out.join("history.csv").is_file());
        assert!(!lock.exists(), "the lock is released after the run");
    }
}

#[test]
fn rig_data_without_a_test_condition_say_where_their_samples_went() {
    // Two samples: too few to make a load level, so no condition.
    let dir = scratch(&[("rig.csv", "fz,alpha,fy\n4000,0.01,800\n4000,0.02,1500\n")]);
    let out = dir.path().join("t.toml");
    let o = identify_to(&dir.path().join("rig.csv"), "pac89", &out);
    let e = refused(&o, &out);
    assert!(
        e.contains(
            "rig.csv: no test condition found in the data (2 samples: 0 used in conditions, \
             2 samples in groups too few to be a level (fewer than 3 samples at one load, camber or pressure), \
             0 between levels (transitions), 0 at levels not selected; fz levels: 0"
        ),
        "{e}"
    );
}

/// A campaign measured on the diagnosis's own model with no effect: its
/// gap is noise. The terminal, the page and `diagnosis.json` say so in the
/// same sentences, and none of them gives the noise a place (no "wrong
/// in", no list of parts it is "right in").
#[test]
fn a_gap_at_noise_level_is_given_no_place_on_the_terminal_the_page_or_the_json() {
    let dir = tempfile::tempdir().unwrap();
    let campaign = synth_campaign(dir.path(), "none", &[]);
    let (stdout, d) = diagnose_campaign(&campaign);
    assert!(stdout.contains("verdict: no significant gap"), "{stdout}");
    assert!(stdout.contains("\nthe gap, within noise:\n"), "{stdout}");
    assert!(!stdout.contains("where the gap lies"), "{stdout}");
    let page = fs::read_to_string(campaign.with_extension("out").join("report.html")).unwrap();
    assert!(page.contains(">The gap, within noise</h2>"), "{page}");
    // The candidates' ΔBIC and standard errors, on thousands of correlated
    // samples, are said not to be evidence where the gap is noise.
    let caveat = "the ΔBIC and ± below count every sample as independent";
    assert!(
        stdout.contains(&format!("  (the gap is within noise: {caveat}")),
        "{stdout}"
    );
    assert!(
        page.contains(&format!("The gap is within noise: {caveat}")),
        "{page}"
    );
    let summary = d["gap"]["summary"].as_array().unwrap();
    assert_eq!(summary.len(), 4, "{summary:?}");
    for s in summary {
        let s = s.as_str().unwrap();
        assert!(
            stdout.contains(&format!("  {s}\n")),
            "{s} not on the terminal"
        );
        assert!(page.contains(s), "{s} not on the page");
        assert!(!s.contains("wrong in") && !s.contains("right in"), "{s}");
    }
    for channel in ["yaw_rate", "ay", "beta"] {
        assert!(
            summary.iter().any(|s| {
                let s = s.as_str().unwrap();
                s.starts_with(&format!("{channel}: RMS "))
                    && s.ends_with(
                        "within noise in every part, so no place where the base model is wrong",
                    )
            }),
            "{channel}: {summary:?}"
        );
    }
}

/// A count of one takes the singular: a one-point `tyre-eval`, a
/// one-row rig file refused by `identify`.
#[test]
fn one_sample_is_one_sample_not_1_samples() {
    let dir = scratch(&[
        ("p.csv", "fz,kappa,alpha,camber,speed\n4000,0,0.01,0,20\n"),
        ("rig.csv", "fz,alpha,fy\n4000,0.01,800\n"),
    ]);
    let out = dir.path().join("e.csv");
    let o = run(&[
        "tyre-eval",
        "tests/fixtures/tir/MagicFormula61_Parameters.tir",
        dir.path().join("p.csv").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(said.starts_with("1 point of "), "{said}");
    let o = identify_to(
        &dir.path().join("rig.csv"),
        "pac89",
        &dir.path().join("t.toml"),
    );
    let e = refused(&o, &dir.path().join("t.toml"));
    assert!(e.contains("(1 sample: 0 used in conditions"), "{e}");
    assert!(!e.contains("1 samples"), "{e}");
}

/// `--hold` on a swarm fit: PAC89's `a1` held at the value given (in
/// the written file, the report and the terminal, the two-stage fit not
/// run), and a name that is none of the model's parameters refused with
/// the nearest one and the model.
#[test]
fn a_swarm_fit_holds_a_parameter_at_the_value_given() {
    let dir = tempfile::tempdir().unwrap();
    let campaign = synth_campaign(dir.path(), "c", &[]);
    let rig = campaign.join("tyre_rig.csv");
    let out = dir.path().join("held.toml");
    let o = run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "pac89",
        "--hold",
        "a1=-22.1",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("  held: a1 = -22.1: given with --hold"),
        "{said}"
    );
    assert!(
        said.contains("two-stage (Zhang et al. 2021): not run"),
        "{said}"
    );
    let tyre: toml::Value = toml::from_str(&fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(tyre["a"][1].as_float(), Some(-22.1));
    let report = read_json(&out.with_extension("report.json"));
    let a1 = report["parameters"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["name"] == "a1")
        .unwrap();
    assert_eq!(
        (a1["value"].as_f64(), &a1["free"]),
        (Some(-22.1), &serde_json::json!(false))
    );
    assert!(report["two_stage"].is_null());
    // The fit still fits the rest: σ near the unheld fit's 0.74 %.
    assert!(report["sigma_percent"].as_f64().unwrap() < 1.0, "{report}");
    let bad = dir.path().join("bad.toml");
    let e = refused(
        &run(&[
            "identify",
            rig.to_str().unwrap(),
            "--model",
            "gim",
            "--hold",
            "frction=1",
            "--out",
            bad.to_str().unwrap(),
        ]),
        &bad,
    );
    assert!(
        e.contains("--hold `frction`: not a parameter of the gim model (did you mean `friction`?): its parameters are cornering_stiffness,"),
        "{e}"
    );
    assert_eq!(e.matches("contact_length").count(), 1, "{e}");
    // A value the model refuses is refused at its name, not fitted
    // around; one beyond ±1e6 (which stalled the staged fit) too.
    for (model, hold, said) in [
        ("gim", "friction=-5", "`friction` = -5"),
        (
            "mf61",
            "PKY1=1e308",
            "`PKY1` = 1e308: must lie within ±1000000",
        ),
    ] {
        let e = refused(
            &run(&[
                "identify",
                rig.to_str().unwrap(),
                "--model",
                model,
                "--hold",
                hold,
                "--out",
                bad.to_str().unwrap(),
            ]),
            &bad,
        );
        assert!(e.contains(said), "{e}");
    }
}

/// A step steer at an absurd speed is refused at `speed`, its own key and
/// line: 1e308 m/s was refused as a non-finite `steer`, and 1e5 m/s ran
/// (a negative yaw-rate gain, with no more than "not settled").
#[test]
fn an_absurd_step_steer_speed_is_refused_at_its_own_key() {
    for speed in ["1e308", "1e5"] {
        let step = STEP.replace("speed = 22.2222", &format!("speed = {speed}"));
        let dir = scenario(VEHICLE, GIM, &step);
        let e = simulate_err(dir.path());
        assert!(
            e.contains("scenario.toml:15:9: `manoeuvre.speed` = "),
            "{e}"
        );
        assert!(
            e.contains("must lie in (0.5, 150]: the model evaluates no speed below 0.5 m/s"),
            "{e}"
        );
        assert!(!e.contains("steer`"), "{e}");
    }
    // 150 m/s itself runs.
    let dir = scenario(
        VEHICLE,
        GIM,
        &STEP.replace("speed = 22.2222", "speed = 150.0"),
    );
    let o = run(&[
        "simulate",
        dir.path().join("scenario.toml").to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
}
