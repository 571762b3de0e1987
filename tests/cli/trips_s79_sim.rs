//! What `simulate`, a scenario and `tyre-eval` did not say or did not
//! read (session 79): a replay that ignored its log's `ax` and `bank`, a
//! tyre fitted to braking data run round a corner without a word, the two
//! names of the integration table both written, a `[metrics]` table set
//! aside silently, a sensor's delay among the car's effects, the wrong
//! kind of file given as a scenario, a linear tyre evaluated where its
//! line means nothing, a refused speed printed as the limit, and the
//! `.tir` Kxκ check `tyre-eval` makes and `simulate` did not.

use super::*;

/// The sedan of `VEHICLE` on the bundled linear tyre, with `rest` after
/// its `[tyres]` table, written to `dir/<name>.toml`.
pub(super) fn sedan(dir: &Path, name: &str, rest: &str) -> PathBuf {
    let tyre = root().join("tyres/linear.toml");
    let path = dir.join(format!("{name}.toml"));
    let text = format!(
        "{VEHICLE}\n[tyres]\nfront = \"{}\"\n\n{rest}",
        tyre.display()
    );
    fs::write(&path, text).unwrap();
    path
}

/// A straight run at 20 m/s over `seconds` s at 100 Hz, with the extra
/// columns `extra` (name, value on every row), written to `dir/run.csv`.
fn straight_run(dir: &Path, seconds: f64, extra: &[(&str, f64)]) {
    let mut text = String::from("t,speed,steer,yaw_rate,ay");
    for (name, _) in extra {
        text += &format!(",{name}");
    }
    text += "\n";
    let n = (seconds * 100.0).round() as usize;
    for i in 0..=n {
        text += &format!("{},20,0,0,0", i as f64 * 0.01);
        for (_, v) in extra {
            text += &format!(",{v}");
        }
        text += "\n";
    }
    fs::write(dir.join("run.csv"), text).unwrap();
}

pub(super) const REPLAY: &str = "[manoeuvre]\nkind = \"replay\"\nrun = \"run.csv\"\n";

/// The history's column `name`.
fn column(history: &Path, name: &str) -> Vec<f64> {
    let text = fs::read_to_string(history).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = header.iter().position(|h| *h == name).unwrap();
    lines
        .map(|l| l.split(',').nth(k).unwrap().parse().unwrap())
        .collect()
}

/// Runs `simulate path --out dir/out`; its stdout.
pub(super) fn simulated(path: &Path, dir: &Path) -> String {
    let out = dir.join("out");
    succeeds(&[
        "simulate",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
}

/// A replay with `longitudinal_load_transfer = 1` of a log braking at
/// ax = −4 m/s² left the front loads static: it read the speed's
/// derivative (0 on a constant logged speed), not the log's `ax`. The
/// front-left wheel gains m·|ax|·h/l/2 = 1530·4·0.55/2.78/2 = 605.4 N.
#[test]
fn a_replay_reads_the_logs_ax() {
    let dir = tempfile::tempdir().unwrap();
    straight_run(dir.path(), 3.0, &[("ax", -4.0)]);
    let effects = "[model.effects]\nlongitudinal_load_transfer = 1\n";
    let path = sedan(dir.path(), "braking", &format!("{REPLAY}\n{effects}"));
    simulated(&path, dir.path());
    let fz = column(&dir.path().join("out/history.csv"), "fz_fl");
    let static_fl = 1530.0 * 9.80665 * 1.67 / 2.78 / 2.0;
    let gained = fz[fz.len() / 2] - static_fl;
    let expected = 1530.0 * 4.0 * 0.55 / 2.78 / 2.0;
    assert!(
        (gained / expected - 1.0).abs() < 0.01,
        "{gained} N against {expected} N"
    );
}

/// A replay of a log driven straight on a road banked 0.05 rad ignored
/// the `bank` column. Applied, the settled car's tyres hold it against
/// gravity's pull: the accelerometer's ay reads g·sin(bank) more than the
/// path's acceleration u·r; said as a note.
#[test]
fn a_replay_drives_on_the_logs_bank() {
    let dir = tempfile::tempdir().unwrap();
    straight_run(dir.path(), 12.0, &[("bank", 0.05)]);
    // Without a scale the bank is said and left out (a logger's bank the
    // car may not have felt is `diagnose`'s `bank_profile` to fit).
    let flat = sedan(dir.path(), "flat", REPLAY);
    let said = simulated(&flat, dir.path());
    assert!(
        said.contains("note: the run's `bank` column (road bank 0.05 rad (2.86°)) does not act on the replay: the road is flat"),
        "{said}"
    );
    let history = dir.path().join("out/history.csv");
    let (ay, u, r) = (
        column(&history, "ay"),
        column(&history, "speed"),
        column(&history, "yaw_rate"),
    );
    let k = ay.len() - 1;
    assert!(
        (ay[k] - u[k] * r[k]).abs() < 1e-3,
        "{}",
        ay[k] - u[k] * r[k]
    );
    fs::remove_dir_all(dir.path().join("out")).unwrap();
    let rest = format!("{REPLAY}\n[model.effects]\nbank_profile_scale = 1.0\n");
    let path = sedan(dir.path(), "banked", &rest);
    let said = simulated(&path, dir.path());
    assert!(!said.contains("`bank` column"), "{said}");
    let history = dir.path().join("out/history.csv");
    let (ay, u, r) = (
        column(&history, "ay"),
        column(&history, "speed"),
        column(&history, "yaw_rate"),
    );
    let k = ay.len() - 1;
    let excess = ay[k] - u[k] * r[k];
    let expected = 9.80665 * 0.05f64.sin();
    assert!(
        (excess / expected - 1.0).abs() < 0.01,
        "{excess} m/s² against {expected} m/s²"
    );
}

/// A linear tyre file whose `[fitted_ranges]` give a slip ratio and no
/// slip angle (fitted to a braking sweep) steered round a corner without
/// a word.
#[test]
fn a_tyre_fitted_to_longitudinal_data_only_is_warned_of_in_a_turn() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(
        dir.path().join("braking.toml"),
        "model = \"linear\"\ncornering_stiffness = 57296.0\n\n[fitted_ranges]\nkappa = [-0.2, 0.2]\n",
    )
    .unwrap();
    let path = dir.path().join("turn.toml");
    fs::write(
        &path,
        format!("{VEHICLE}\n[tyres]\nfront = \"braking.toml\"\n\n{STEP}"),
    )
    .unwrap();
    let said = simulated(&path, dir.path());
    assert!(
        said.contains("warning: the front and rear tyres were fitted to longitudinal data only (their `[fitted_ranges]` give a slip ratio of -0.2 to 0.2 and no slip angle): their lateral behaviour, which this steered run rests on, was never fitted to data"),
        "{said}"
    );
}

/// `[simulation]` and `[integrator]` both: refused as "duplicate field
/// `simulation`" at line 1:1, naming neither table as written.
#[test]
fn both_integration_tables_are_refused_at_the_second() {
    let dir = tempfile::tempdir().unwrap();
    let rest = format!("{STEP}\n[integrator]\nstep = 0.01\n\n[simulation]\nstep = 0.002\n");
    let path = sedan(dir.path(), "both", &rest);
    let e = fails_cleanly("simulate", &path, dir.path());
    assert!(
        e.contains("both.toml:21:2: [simulation] and [integrator] (line 18) are one table under two names (the method, step and tolerances of the integration): give one of them"),
        "{e}"
    );
}

/// `[metrics]` in a sine's scenario was set aside without a word.
#[test]
fn metrics_in_a_scenario_that_is_no_step_steer_is_warned_of_with_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let rest = "[manoeuvre]\nkind = \"sine\"\nspeed = 20.0\namplitude = 0.02\nfrequency = 0.5\nend = 5.0\n\n[metrics]\nsteady_window = 1.0\n";
    let path = sedan(dir.path(), "sine", rest);
    let said = simulated(&path, dir.path());
    assert!(
        said.contains("warning: [metrics] (line 20) is ignored: its windows and filter set the step-steer metrics, and a sine has none"),
        "{said}"
    );
}

/// `sensor_delay` in `[model.effects]` was "unknown field", its list of
/// keys offered; a property of the measurement is sent to `diagnose`, and
/// a `diagnose` effect a scenario sets elsewhere to its key.
#[test]
fn a_measurement_effect_in_a_scenario_is_sent_to_diagnose() {
    let dir = tempfile::tempdir().unwrap();
    for (key, said) in [
        ("sensor_delay = 0.05", "`model.effects.sensor_delay` is a property of the measurement (the sensors and the steer they log), not of the car: a scenario simulates the car alone; `sensor_delay` belongs to `handling diagnose`"),
        ("steer_path = 0.1", "`model.effects.steer_path` is a property of the measurement"),
        ("yaw_inertia = 1.2", "`yaw_inertia` is the name of a `diagnose` effect; a scenario sets it as `[vehicle] yaw_inertia` (kg·m²)"),
    ] {
        let name = key.split(' ').next().unwrap();
        let path = sedan(dir.path(), name, &format!("{STEP}\n[model.effects]\n{key}\n"));
        let e = fails_cleanly("simulate", &path, dir.path());
        // At the value, as every key's error is.
        let column = key.find('=').unwrap() + 3;
        assert!(e.contains(&format!("{name}.toml:19:{column}: {said}")), "{e}");
    }
}

/// A CSV, a `.tir`, a tyre TOML, a JSON report and a binary file given to
/// `simulate` were refused by the TOML parser ("invalid key", "expected a
/// table"), never named as what they are.
#[test]
fn the_wrong_kind_of_file_is_named_as_what_it_is() {
    let dir = tempfile::tempdir().unwrap();
    let tir = fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
        .unwrap();
    let files: [(&str, &[u8], &str); 5] = [
        ("run.csv", b"t,speed,steer,yaw_rate\n0,20,0,0\n", "is a measured run (a CSV with `t`, `speed`, `steer`, `yaw_rate`), not a scenario"),
        ("tyre.tir", tir.as_bytes(), "is a .tir tyre file, not a scenario: give it as `[tyres] front = \"<this file>\"` in a scenario"),
        ("tyre.toml", b"model = \"linear\"\ncornering_stiffness = 57296.0\n", "is a tyre file (`model = \"linear\"`), not a scenario: give it as `[tyres] front = \"<this file>\"` in a scenario"),
        ("diagnosis.json", b"{\"verdict\": 1}\n", "is a JSON file (a report `handling` writes: diagnosis.json, metrics.json, gap.json), not a scenario"),
        // A PNG's first bytes name it (session 81), before its NUL at byte 8.
        ("scenario.toml", b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR", "is a PNG image, not a scenario: no command reads it"),
    ];
    for (name, bytes, said) in files {
        let path = dir.path().join(name);
        fs::write(&path, bytes).unwrap();
        let e = fails_cleanly("simulate", &path, dir.path());
        assert!(e.contains(&format!("{name}: the file {said}")), "{e}");
    }
}

/// `tyre-eval` of the linear tyre at 0.3 rad and at a 20 kN load gave a
/// force growing on with the slip and a stiffness per load no tyre has,
/// without a word.
#[test]
fn tyre_eval_says_where_the_linear_model_means_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let points = dir.path().join("points.csv");
    fs::write(
        &points,
        "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n4000,0,0.3,0,20\n20000,0,0.02,0,20\n",
    )
    .unwrap();
    let out = dir.path().join("forces.csv");
    let o = run(&[
        "tyre-eval",
        root().join("tyres/linear.toml").to_str().unwrap(),
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stderr(&o);
    for line in [
        "1 of 3 points at a slip angle beyond ±0.1 rad (5.7°), outside what the linear tyre means",
        "the first at line 3, |alpha| = 0.3 rad (17.2°)",
        "1 of 3 points at a load where the cornering coefficient Cα/Fz is below 4 /rad, which no road tyre's is",
        "the first at line 4, Cα/Fz = 2.86 /rad",
    ] {
        assert!(said.contains(line), "{line}\n{said}");
    }
}

/// A replayed log whose speeds' 99th percentile is a hair above the
/// 150 m/s limit read "the run's 99th percentile of |speed| is 150 m/s":
/// a value that looks legal beside the limit it broke.
#[test]
fn a_refused_speed_is_printed_apart_from_its_limit() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("t,speed,steer,yaw_rate\n");
    for i in 0..200 {
        text += &format!("{},150.00000012345678,0,0\n", i as f64 * 0.01);
    }
    fs::write(dir.path().join("run.csv"), text).unwrap();
    let path = sedan(dir.path(), "fast", REPLAY);
    let e = fails_cleanly("simulate", &path, dir.path());
    assert!(
        e.contains("150.0000001 m/s is beyond 150 m/s (540 km/h), which no car's speed reaches (the run's 99th percentile of |speed| is 150.0000001 m/s)"),
        "{e}"
    );
}

/// `simulate` on the public `FSAE_Defaults.tir`, whose Kxκ turns negative
/// below its FZMAX, said nothing of it where `tyre-eval` warns.
#[test]
fn simulate_says_a_tirs_longitudinal_stiffness_turns_negative() {
    let Some(tir) = shared_data(
        "simulate_says_a_tirs_longitudinal_stiffness_turns_negative",
        "tir_public/FSAE_Defaults.tir",
    ) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("fsae.toml");
    let vehicle = "[vehicle]\nmass = 280.0\nyaw_inertia = 120.0\na = 0.8\nb = 0.75\ntrack_front = 1.2\ntrack_rear = 1.2\ncg_height = 0.3\n";
    let step = "[manoeuvre]\nkind = \"step-steer\"\nspeed = 15.0\nsteer = 0.02\n";
    fs::write(
        &path,
        format!(
            "{vehicle}\n[tyres]\nfront = \"{}\"\n\n{step}",
            tir.display()
        ),
    )
    .unwrap();
    let said = simulated(&path, dir.path());
    assert!(
        said.contains("FSAE_Defaults.tir:")
            && said.contains(
                "the longitudinal slip stiffness Kxκ = Fz·(PKX1 + PKX2·dfz)·exp(PKX3·dfz)"
            )
            && said.contains("turns negative from Fz = 1625 N"),
        "{said}"
    );
}

/// A tyre lag (six states, no dense (β, r) solution) integrated by
/// Dormand–Prince was reported as "RK4, 6000 steps of 0.001 s".
#[test]
fn a_lagged_model_integrated_by_dopri5_is_not_reported_as_rk4() {
    let dir = tempfile::tempdir().unwrap();
    let rest = format!("{STEP}\n[model.effects]\nrelaxation_length = 0.3\n");
    let path = sedan(dir.path(), "lagged", &rest);
    let said = simulated(&path, dir.path());
    let first = said.lines().next().unwrap();
    assert!(
        first.starts_with("lagged: Dormand–Prince 5(4), rtol 1e-9, atol 1e-11: "),
        "{said}"
    );
    assert!(!without_temp_names(first).contains("RK4"), "{said}");
}

/// `roll_camber = [500, 0]` ran away (gigabytes of memory, no output), a
/// relaxation length of 5e6 m, a stiffness scale of 1e6, a roll steer of
/// 5 and a roll at 500 Hz ran without a word: each refused at its key
/// with its range.
#[test]
fn effect_numbers_beyond_any_car_are_refused_with_their_range() {
    let dir = tempfile::tempdir().unwrap();
    for (name, effects, said) in [
        ("camber", "roll_camber = [500, 0]\n", "camber.toml:19:16: `model.effects.roll_camber[0]` = 500: must lie within ±10: camber thrust beyond ±10 of the wheel load per rad of body roll is no car's"),
        ("lag", "relaxation_length = 5e6\n", "lag.toml:19:21: `model.effects.relaxation_length` = 5000000: must lie in [0, 3]: a relaxation length beyond 3 m is no tyre's"),
        ("scale", "cornering_stiffness_scale = [1e6, 1]\n", "`model.effects.cornering_stiffness_scale[0]` = 1000000: must lie in (0.2, 5]: a scale on an axle's cornering stiffness outside 0.2 to 5 is another tyre"),
        ("steer", "roll_steer = [5, 0]\n", "`model.effects.roll_steer[0]` = 5: must lie within ±1: roll steer beyond ±1 rad"),
        ("roll", "roll_steer = [0.1, 0]\n[model.effects.roll]\nfrequency = 500\n", "`model.effects.roll.frequency` = 500: must lie in (0, 10]: a body's roll natural frequency is 1–3 Hz"),
        // The sign was dropped ("= 0.9: must lie in (-1, 0.5]").
        ("bank", "road_bank = -0.9\n", "bank.toml:19:13: `model.effects.road_bank` = -0.9: must lie within ±0.61: a bank steeper than 0.61 rad (35°; Daytona's banking is 31°, Talladega's 33°) is not a road"),
        ("share", "bank_profile_scale = 5\n", "`model.effects.bank_profile_scale` = 5: must lie in [0, 2]: the share of a logged bank the road has lies in 0 to 2"),
    ] {
        let path = sedan(dir.path(), name, &format!("{STEP}\n[model.effects]\n{effects}"));
        let e = fails_cleanly("simulate", &path, dir.path());
        assert!(e.contains(said), "{said}\n{e}");
    }
}

/// A `bank_profile_scale` for a replayed run without a `bank` column was
/// taken without a word, acting on nothing.
#[test]
fn a_bank_scale_for_a_run_without_bank_is_said_to_act_on_nothing() {
    let dir = tempfile::tempdir().unwrap();
    straight_run(dir.path(), 2.0, &[]);
    let rest = format!("{REPLAY}\n[model.effects]\nbank_profile_scale = 0.5\n");
    let path = sedan(dir.path(), "nobank", &rest);
    let said = simulated(&path, dir.path());
    assert!(
        said.contains("warning: `model.effects.bank_profile_scale` (line 18) acts on nothing: it scales a replayed run's `bank` column, and this run has none"),
        "{said}"
    );
}
