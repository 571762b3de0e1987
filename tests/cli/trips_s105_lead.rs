//! Round 36's findings the lead fixed: a campaign's vehicle or road its runs
//! contradict, a batch campaign's two names, a text file given for a TOML
//! file, a replay's yaw rate in deg/s.

use super::*;

/// A friction of 0.05 under runs turning at 6 m/s² (12 μ·g), and a centre
/// of gravity 2.5 m high under runs past its rollover limit (g·t/(2h) =
/// 3.04 m/s²): each contradicts the runs and was diagnosed without a word.
#[test]
fn a_friction_and_a_cg_height_the_runs_contradict_are_warned() {
    let dir = tempfile::tempdir().unwrap();
    let c = trips_s90_diag::edited_campaign(
        dir.path(),
        "cg_height = 0.55",
        "cg_height = 2.5\n\n[road]\nfriction = 0.05",
    );
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    fs::write(
        &v,
        text.replace("seed = 1", "seed = 1\neffects = [\"sensor_delay\"]"),
    )
    .unwrap();
    let (said, d) = diagnose_to(&c, &dir.path().join("out"));
    let warned: Vec<&str> = said
        .lines()
        .filter(|l| l.contains("warning:") && l.contains("the runs turn at up to"))
        .collect();
    assert_eq!(warned.len(), 2, "{said}");
    assert!(
        warned[0].contains("the campaign's friction 0.05")
            && warned[0].contains("is `friction` right?"),
        "{said}"
    );
    assert!(
        warned[1].contains("g·t/(2h) = 3.04 m/s²") && warned[1].contains("cg_height 2.5 m"),
        "{said}"
    );
    let kinds: Vec<&str> = d["note_details"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|n| n["kind"] == "runs_beyond_vehicle")
        .map(|n| n["limit"]["kind"].as_str().unwrap())
        .collect();
    assert_eq!(kinds, ["friction", "rollover"], "{said}");
}

/// A text file (notes, a README) given where a TOML file is read was
/// answered with toml's "expected `.`, `=`" at its first word.
#[test]
fn a_text_file_given_for_a_scenario_or_a_tyre_is_named_as_text() {
    let dir = scratch(&[
        ("notes.txt", "hello world\nthis is not toml\n"),
        (
            "readme.toml",
            "# Tyre files\n\nThirteen files, as published.\nUseful as reader input: `QSY7 = 0`, both sides.\n",
        ),
        ("points.csv", "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n"),
    ]);
    let notes = dir.path().join("notes.txt");
    let said = fails_cleanly("simulate", &notes, dir.path());
    assert!(
        said.contains("is a text file that is not TOML")
            && said.contains("its first reads \"hello world\"")
            && said.contains("not a scenario"),
        "{said}"
    );
    let said = fails_cleanly("simulate", &dir.path().join("readme.toml"), dir.path());
    assert!(said.contains("a text file that is not TOML"), "{said}");
    let o = run(&[
        "tyre-eval",
        notes.to_str().unwrap(),
        dir.path().join("points.csv").to_str().unwrap(),
        "--out",
        dir.path().join("out.csv").to_str().unwrap(),
    ]);
    let said = stderr(&o);
    assert!(!o.status.success());
    assert!(
        said.contains("a text file that is not TOML") && said.contains("not a tyre file"),
        "{said}"
    );
    // A TOML file with a slip keeps its reader's error at the slip.
    let slip = dir.path().join("slip.toml");
    fs::write(&slip, format!("name \"x\"\n{VEHICLE}")).unwrap();
    let said = fails_cleanly("simulate", &slip, dir.path());
    assert!(!said.contains("not TOML"), "{said}");
    assert!(said.contains("slip.toml:1:"), "{said}");
}

/// A replay's run logging its yaw rate in deg/s was refused at the run's
/// row with advice for `metrics` and a campaign first; now at the
/// scenario's `run`, with the scenario's own key.
#[test]
fn a_replay_s_yaw_rate_in_degrees_is_declared_by_the_scenario_s_key() {
    let dir = tempfile::tempdir().unwrap();
    let rows: String = (0..400)
        .map(|i| {
            let t = i as f64 * 0.01;
            let steer = if t < 1.0 { 0.0 } else { 0.02 };
            let r_deg = if t < 1.0 { 0.0 } else { 10.0 };
            format!("{t:.2},20,{steer},{r_deg}\n")
        })
        .collect();
    fs::write(dir.path().join("tyre.toml"), LINEAR_1000_PER_DEG).unwrap();
    let sc = replay_of(dir.path(), &format!("t,speed,steer,yaw_rate\n{rows}"));
    let said = fails_cleanly("simulate", &sc, dir.path());
    assert!(said.contains("replay.toml:"), "{said}");
    assert!(said.contains("the run run.csv, at line "), "{said}");
    assert!(
        said.contains("declare it so: `degrees = [\"yaw_rate\"]` under [manoeuvre]"),
        "{said}"
    );
    assert!(!said.contains("--degrees"), "{said}");
}

/// `a.toml` holding `name = "small"`: the terminal and its report said
/// "small", `fleet.csv` and the folder "a"; now the table says both.
#[test]
fn a_batch_campaign_named_otherwise_than_its_file_is_listed_by_both_names() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "c",
        &["--effects", "sensor_delay", "--seed", "1"],
    );
    let batch = dir.path().join("batch");
    fs::create_dir(&batch).unwrap();
    let text = fs::read_to_string(c.join("vehicle.toml")).unwrap();
    let runs = c.join("runs");
    let campaign = format!(
        "name = \"small\"\n{}\n[runs]\nfiles = [\"{}\", \"{}\"]\n",
        text.replace(
            "rig = \"tyre_rig.csv\"",
            &format!("rig = \"{}\"", c.join("tyre_rig.csv").display())
        )
        .replace("seed = 1", "seed = 1\neffects = [\"sensor_delay\"]"),
        runs.join("step_060kph_2ms2.csv").display(),
        runs.join("step_100kph_6ms2.csv").display(),
    );
    fs::write(batch.join("a.toml"), campaign).unwrap();
    let out = dir.path().join("out");
    let said = succeeds(&[
        "diagnose",
        batch.to_str().unwrap(),
        "--batch",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(said.contains("a (name \"small\")"), "{said}");
    let csv = fs::read_to_string(out.join("fleet.csv")).unwrap();
    let mut lines = csv.lines();
    assert!(lines.next().unwrap().ends_with(",kind,name"), "{csv}");
    let row = lines.next().unwrap();
    assert!(row.starts_with("a,") && row.ends_with(",small"), "{csv}");
    assert!(out.join("a").join("report.html").is_file());
}

/// A steady ay asked 1 % above the largest the car holds (9.9 m/s² on the
/// bundled Gim sedan at 22.2 m/s, friction 1, whose limit is 9.81) read
/// only "the solver did not converge", where 11 m/s² was said beyond the
/// limit: now at the limit, with a value to ask for.
#[test]
fn a_steady_ay_just_past_the_limit_is_said_at_the_limit() {
    let tyres = root().join("tyres");
    let scenario = format!(
        "name = \"g\"\n{VEHICLE}[tyres]\nfront = \"{}\"\nrear = \"{}\"\n{SMALL_ANGLE}[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nlateral_acceleration = 9.9\nstart = 1.0\nrise_time = 0.1\nend = 8.0\n",
        tyres.join("gim_sedan_front.toml").display(),
        tyres.join("gim_sedan_rear.toml").display()
    );
    let dir = scratch(&[("g.toml", &scenario)]);
    let said = fails_cleanly("simulate", &dir.path().join("g.toml"), dir.path());
    assert!(
        said.contains("at the vehicle's lateral limit at this speed, where the largest steady ay found is 9.81 m/s²")
            && said.contains("ask for less than 9.81 m/s²"),
        "{said}"
    );
}
