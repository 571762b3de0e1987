//! What `simulate` (and `equilibria`) left or said wrongly (session 82,
//! fresh-eyes round 9): an earlier run's outputs left beside a new run's
//! in one folder, a replay's refusals naming `metrics` flags and the run
//! file's line 1:1 for the scenario's own keys, and a `.tir` whose
//! lateral block `identify` never fitted simulated without a word.

use super::trips_s79_sim::{sedan, REPLAY};
use super::*;

/// A 1° step steer at 80 km/h from t = 1 s to 4 s.
const STEP_STEER: &str = "[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\nstart = 1.0\nrise_time = 0.1\nend = 4.0\n";

/// Runs `simulate path --out out`; its stdout.
fn simulate_into(path: &Path, out: &Path) -> String {
    succeeds(&[
        "simulate",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
}

/// Runs `simulate path --out dir/out`, expecting a refusal; its stderr.
fn refused(path: &Path, dir: &Path) -> String {
    let o = run(&[
        "simulate",
        path.to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    stderr(&o)
}

/// A run at `speed` m/s over 3 s at 100 Hz, weaving with a steer of
/// 0.02 rad at 0.5 Hz, its yaw rate a neutral car's
/// (r = u·δ/l, l = 2.78 m), `steer` written `steer_scale` times its
/// radians (57.2958: in degrees), to `dir/run.csv`.
fn run_file(dir: &Path, speed: f64, steer_scale: f64) {
    let mut text = String::from("t,speed,steer,yaw_rate,ay\n");
    for i in 0..=300 {
        let t = i as f64 * 0.01;
        let steer = 0.02 * (std::f64::consts::PI * t).sin();
        let r = speed * steer / 2.78;
        text += &format!("{t},{speed},{},{r},{}\n", steer * steer_scale, speed * r);
    }
    fs::write(dir.join("run.csv"), text).unwrap();
}

/// A replay into the folder of a step steer left the step's
/// `metrics.json` beside the replay's `gap.json`: two runs in one folder.
/// The earlier run's file is removed, and said; a file of the user's is
/// left, and named.
#[test]
fn a_replay_into_a_step_steers_folder_removes_its_metrics_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let step = sedan(dir.path(), "step", STEP_STEER);
    simulate_into(&step, &out);
    assert!(out.join("metrics.json").is_file());
    fs::write(out.join("notes.txt"), "mine").unwrap();
    run_file(dir.path(), 20.0, 1.0);
    let replay = sedan(dir.path(), "replay", REPLAY);
    let said = simulate_into(&replay, &out);
    assert!(!out.join("metrics.json").exists(), "{said}");
    assert!(out.join("gap.json").is_file());
    assert_eq!(fs::read_to_string(out.join("notes.txt")).unwrap(), "mine");
    assert!(
        said.contains("  removed 1 file of an earlier `simulate` run into this folder, which this run does not write: metrics.json\n"),
        "{said}"
    );
    assert!(
        said.contains("  the folder also holds 1 file that `simulate` does not write, left as they are: notes.txt (give each run a folder of its own, with --out, to keep runs apart)\n"),
        "{said}"
    );
    // The same run again: nothing of an earlier run's to remove.
    let again = simulate_into(&replay, &out);
    assert!(!again.contains("removed"), "{again}");
}

/// `equilibria` into a folder holding another sweep's branch diagram and
/// a fourth phase portrait, and `simulate`'s figure: its own kind of
/// files it does not write are removed, the figure named.
#[test]
fn equilibria_removes_an_earlier_sweeps_figures_and_names_simulates() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    fs::create_dir(&out).unwrap();
    for f in ["branches_speed.png", "phase_portrait_7.png", "response.png"] {
        fs::write(out.join(f), "old").unwrap();
    }
    let sweep = root().join("scenarios/equilibria_steer.toml");
    let said = succeeds(&[
        "equilibria",
        sweep.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!out.join("branches_speed.png").exists());
    assert!(!out.join("phase_portrait_7.png").exists());
    assert!(out.join("branches_steer.png").is_file());
    assert!(out.join("phase_portrait_1.png").is_file());
    assert!(out.join("response.png").is_file());
    assert!(
        said.contains("  removed 2 files of an earlier `equilibria` run into this folder, which this run does not write: branches_speed.png, phase_portrait_7.png\n"),
        "{said}"
    );
    assert!(
        said.contains("  the folder also holds 1 file that `equilibria` does not write, left as they are: response.png"),
        "{said}"
    );
}

/// `degrees = ["bank"]` for a run without `bank` was refused at the run
/// file's line 1:1, which holds no `degrees`: it stands at the entry.
#[test]
fn a_replays_degrees_entry_the_run_lacks_is_refused_at_the_entry() {
    let dir = tempfile::tempdir().unwrap();
    run_file(dir.path(), 20.0, 1.0);
    let rest = format!("{REPLAY}degrees = [\"steer\", \"bank\"]\n");
    let path = sedan(dir.path(), "bank", &rest);
    let e = refused(&path, dir.path());
    assert!(
        e.contains("bank.toml:16:21: `manoeuvre.degrees` names `bank`, a column the run run.csv does not have (its columns: t, speed, steer, yaw_rate, ay); leave it out, or name a column the run has"),
        "{e}"
    );
    assert!(!e.contains("run.csv:1:1"), "{e}");
}

/// A replay's `min_speed` above the run's speed sent the user to
/// `--min-speed`, a `metrics` flag: it names the key, at its line, and
/// the run's top speed.
#[test]
fn a_replays_min_speed_above_the_run_is_refused_at_its_key() {
    let dir = tempfile::tempdir().unwrap();
    run_file(dir.path(), 20.0, 1.0);
    let rest = format!("{REPLAY}min_speed = 30.0\n");
    let path = sedan(dir.path(), "slow", &rest);
    let e = refused(&path, dir.path());
    assert!(
        e.contains("slow.toml:16:13: the run run.csv has no two successive samples at or above the replay's min_speed = 30 m/s (301 of 301 samples below it; its top speed is 20.0 m/s): set `min_speed` under [manoeuvre] below its top speed to replay it"),
        "{e}"
    );
    assert!(!e.contains("--min-speed"), "{e}");
}

/// A `.tir` that `identify` fitted to braking data alone, its lateral
/// block the template's: the step steer it drives rests on lateral
/// forces no data set, and `simulate` said nothing.
#[test]
fn a_tir_whose_lateral_block_identify_did_not_fit_is_warned_of() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let template = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    // Longitudinal rig rows: the template's own fx at three loads.
    let mut points = String::from("fz,kappa,alpha,camber,speed\n");
    for fz in [3000.0, 5000.0, 7000.0] {
        for k in -20..=20 {
            points += &format!("{fz},{},0,0,11\n", f64::from(k) * 0.01);
        }
    }
    fs::write(d.join("points.csv"), points).unwrap();
    let forces = d.join("forces.csv");
    succeeds(&[
        "tyre-eval",
        template.to_str().unwrap(),
        d.join("points.csv").to_str().unwrap(),
        "--out",
        forces.to_str().unwrap(),
    ]);
    let text = fs::read_to_string(&forces).unwrap();
    let mut rig = String::from("fz,kappa,fx,speed\n");
    for line in text.lines().skip(1) {
        let c: Vec<&str> = line.split(',').collect();
        rig += &format!("{},{},{},{}\n", c[0], c[1], c[5], c[4]);
    }
    fs::write(d.join("braking.csv"), rig).unwrap();
    let tir = d.join("braking.tir");
    succeeds(&[
        "identify",
        d.join("braking.csv").to_str().unwrap(),
        "--model",
        "mf61",
        "--template",
        template.to_str().unwrap(),
        "--out",
        tir.to_str().unwrap(),
    ]);
    let sc = format!(
        "{VEHICLE}\n[tyres]\nfront = \"{}\"\n\n{STEP_STEER}",
        tir.display()
    );
    let path = d.join("step.toml");
    fs::write(&path, sc).unwrap();
    let said = simulate_into(&path, &d.join("out"));
    let line = fs::read_to_string(&tir)
        .unwrap()
        .lines()
        .position(|l| l.starts_with("$ no pure lateral data"))
        .unwrap()
        + 1;
    assert!(
        said.contains(&format!("  warning: {}:{line}: the file says its lateral force block was never fitted to data (\"no pure lateral data: the lateral force block is not fitted (no pure lateral rows", tir.display())),
        "{said}"
    );
    assert!(
        said.contains("the 2-DOF model steers on the lateral force alone, so this run's response rests on coefficients no measurement set; fit the tyre to cornering data (`identify` on a file with `alpha` and `fy`)\n"),
        "{said}"
    );
    // Said once, though both axles use the file.
    assert_eq!(said.matches("never fitted to data").count(), 1, "{said}");
}

/// A long run showed nothing on a terminal while it integrated (`study`
/// and `diagnose` show a progress line): a 100 s step steer at the
/// default 1 ms under Dormand–Prince is 100 000 rows, integrated then
/// evaluated again at the dense output, 200 000 units. On a terminal
/// (`script` gives the run one) the line ends at its total; off one, as
/// in a pipe or CI's log, there is none.
#[test]
fn a_long_simulation_shows_its_progress_on_a_terminal() {
    if Command::new("script").arg("--version").output().is_err() {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI is set but `script` is missing: install Debian's `bsdutils` (.ci/run does)"
        );
        eprintln!("SKIPPED a_long_simulation_shows_its_progress_on_a_terminal: no `script` to give the run a terminal");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let long = STEP_STEER.replace("end = 4.0", "end = 100.0");
    let path = sedan(dir.path(), "long", &long);
    let out = dir.path().join("out");
    let command = format!(
        "{} simulate {} --out {}",
        env!("CARGO_BIN_EXE_handling"),
        path.display(),
        out.display()
    );
    let o = Command::new("script")
        .args(["-qec", &command, "/dev/null"])
        .output()
        .unwrap();
    let seen = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{seen}");
    assert!(seen.contains("simulate: 200000/200000 (100 %)"), "{seen}");
    let piped = run(&[
        "simulate",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!stderr(&piped).contains("simulate:"), "{}", stderr(&piped));
}

/// A sweep's unknown unit and an empty list of values were quoted as
/// `= NaN`, a value nobody wrote: the unit is refused at its key with the
/// text written, the empty list at its key without a value.
#[test]
fn a_sweeps_unknown_unit_and_empty_values_are_not_quoted_as_nan() {
    let text = fs::read_to_string(root().join("scenarios/equilibria_steer.toml")).unwrap();
    let tyres = format!("\"{}/", root().join("tyres").display());
    let text = text.replace("\"../tyres/", &tyres);
    let speed = text
        .lines()
        .find(|l| l.starts_with("speed = "))
        .unwrap()
        .to_string();
    let line = text.lines().position(|l| l == speed).unwrap() + 1;
    let dir = tempfile::tempdir().unwrap();
    for (name, given, said) in [
        (
            "kph",
            "speed = { values = [70.0], unit = \"kph\" }",
            format!("kph.toml:{line}:35: `sweep.speed.unit`: unknown unit `kph` (steer: rad or deg; speed: m/s or km/h; friction: none)"),
        ),
        (
            "empty",
            "speed = { values = [], unit = \"km/h\" }",
            format!("empty.toml:{line}:20: `sweep.speed.values`: no values"),
        ),
    ] {
        let path = dir.path().join(format!("{name}.toml"));
        fs::write(&path, text.replace(&speed, given)).unwrap();
        let e = fails_cleanly("equilibria", &path, dir.path());
        assert!(e.contains(&said), "{e}");
        assert!(!without_temp_names(&e).contains("NaN"), "{e}");
    }
}

/// `synth --drive` of a scenario on a slippery road drove it on the
/// truth's own road (friction 1) without a word: said, with the key.
#[test]
fn synth_drive_says_the_scenarios_road_is_not_used() {
    let dir = tempfile::tempdir().unwrap();
    let rest = format!("{STEP_STEER}\n[road]\nfriction = 0.5\n");
    let path = sedan(dir.path(), "icy_step", &rest);
    let said = succeeds(&[
        "synth",
        "--drive",
        path.to_str().unwrap(),
        "--out",
        dir.path().join("campaign").to_str().unwrap(),
    ]);
    assert!(
        said.contains(&format!("note: {}: the scenario's road, friction 0.5 (`[road] friction`), is not used: the truth drives the manoeuvre on the programme's road, as it drives the programme's runs (its grip the truth's own, flat but for a replay's logged bank): only the scenario's manoeuvre is taken", path.display())),
        "{said}"
    );
}
