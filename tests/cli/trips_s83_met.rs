//! What a fresh user tripped on in `metrics` (round 11): our own simulated
//! step read as a stuck sensor once settled, quantised logger channels
//! read as spikes and stuck values, a noisy steer's wheels already turned
//! said as a pulse, a sideslip of the wrong sign accepted, a units row
//! quoted in the tool's column order.

use super::*;

/// The tester's linear-tyre step at 80 km/h, 1 kHz, 8 s.
const LIN_STEP: &str = "name = \"lin_step\"\n[vehicle]\nmass = 1530.0\nyaw_inertia = 2315.0\na = 1.11\nb = 1.67\ntrack_front = 1.55\ntrack_rear = 1.55\ncg_height = 0.55\n[tyres]\nfront = \"front.toml\"\nrear = \"rear.toml\"\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\nstart = 1.0\nrise_time = 0.0\nend = 8.0\n";

/// Simulates [`LIN_STEP`] in a fresh folder; the folder and its history.
fn lin_history() -> (tempfile::TempDir, PathBuf) {
    let dir = scratch(&[
        ("lin_step.toml", LIN_STEP),
        (
            "front.toml",
            "model = \"linear\"\ncornering_stiffness = 57296.0\npneumatic_trail = 0.03\n",
        ),
        (
            "rear.toml",
            "model = \"linear\"\ncornering_stiffness = 80000.0\npneumatic_trail = 0.03\n",
        ),
    ]);
    let o = run_in(dir.path(), &["simulate", "lin_step.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let history = dir.path().join("out/history.csv");
    (dir, history)
}

/// `metrics` of `file` with `args`: success, stdout and stderr.
fn metrics(file: &Path, args: &[&str]) -> (bool, String, String) {
    let mut all = vec!["metrics", file.to_str().unwrap()];
    all.extend_from_slice(args);
    let o = run(&all);
    (
        o.status.success(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        stderr(&o),
    )
}

/// The history's columns `t, steer, speed, beta, yaw_rate, ay`, each row
/// passed through `row` (the six values, as written).
fn six_columns(history: &Path, row: impl Fn(&mut [String])) -> String {
    let text = fs::read_to_string(history).unwrap();
    let mut out = String::from("t,steer,speed,beta,yaw_rate,ay\n");
    for line in text.lines().skip(1) {
        let mut cells: Vec<String> = line.split(',').take(6).map(String::from).collect();
        row(&mut cells);
        out.push_str(&cells.join(","));
        out.push('\n');
    }
    out
}

/// A settled noise-free simulated `ay` (written to 9 digits, constant
/// from 2.92 s) was "stuck at 2.920 s … ay 1.77515 (5081 samples,
/// masked)" and the steady window all fill: our own simulation's metrics
/// must stand without masking.
#[test]
fn a_settled_simulation_is_no_stuck_sensor() {
    let (_dir, history) = lin_history();
    let (ok, out, err) = metrics(&history, &["--filter-hz", "0"]);
    assert!(ok, "{err}");
    let said = format!("{out}{err}");
    assert!(said.contains("0 stuck values"), "{said}");
    assert!(said.contains("0 response samples masked"), "{said}");
    assert!(!said.contains("stuck at"), "{said}");
    assert!(!said.contains("do not use these metrics"), "{said}");
    assert!(
        said.contains("steady ay                    1.7751 m/s²"),
        "{said}"
    );
}

/// A 100 Hz yaw rate logged at 0.001 rad/s: a sample one count from a
/// neighbour ("spike at 2.210 s … yaw_rate 0.063") is the quantisation's,
/// and the noise is at least the step/√12 (0.18 % of the step after the
/// 10 Hz low-pass), not "none measured".
#[test]
fn a_quantised_channel_has_no_one_count_spike_and_its_step_as_noise() {
    let file = root().join("tests/fixtures/metrics/quant.csv");
    let (ok, out, err) = metrics(&file, &[]);
    assert!(ok, "{err}");
    let said = format!("{out}{err}");
    assert!(said.contains("0 spikes"), "{said}");
    assert!(!said.contains("spike at"), "{said}");
    assert!(!said.contains("none measured"), "{said}");
    assert!(said.contains("yaw-rate noise 0.18 % of the step"), "{said}");
}

/// A 1 kHz `ay` logged at 0.01 m/s², dithering by one count: its 26
/// equal samples at the overshoot's plateau are the response, no stuck
/// sensor ("stuck at 1.893 s … ay 1.48 (26 samples, masked)").
#[test]
fn a_quantised_plateau_is_no_stuck_sensor() {
    let file = root().join("tests/fixtures/metrics/quant1k.csv");
    let (ok, out, err) = metrics(&file, &[]);
    assert!(ok, "{err}");
    let said = format!("{out}{err}");
    assert!(said.contains("0 stuck values"), "{said}");
    assert!(!said.contains("stuck at"), "{said}");
}

/// A run whose wheels are turned by 1° from its start, with a steer
/// noise of 0.0002 rad, was refused as "a pulse of 0.00037 rad" (its
/// noise): the reason is that the wheels are already turned.
#[test]
fn a_noisy_steer_already_turned_is_said_so_not_as_a_pulse() {
    let file = root().join("tests/fixtures/metrics/turned.csv");
    let (ok, _, err) = metrics(&file, &[]);
    assert!(!ok);
    assert!(
        err.contains("the wheels are already turned by 0.0174 rad (1.00°) in the initial window"),
        "{err}"
    );
    assert!(!without_temp_names(&err).contains("pulse"), "{err}");
}

/// A sideslip logged with the wrong sign (positive in a left turn at
/// 80 km/h) was accepted; its rate moves against `ay/u − r`.
#[test]
fn a_sideslip_of_the_wrong_sign_is_warned_from_the_lateral_kinematics() {
    let (dir, history) = lin_history();
    let text = six_columns(&history, |c| {
        let b: f64 = c[3].parse().unwrap();
        c[3] = format!("{}", -b);
    });
    let file = dir.path().join("betaneg.csv");
    fs::write(&file, text).unwrap();
    let (ok, out, err) = metrics(&file, &["--filter-hz", "0"]);
    assert!(ok, "{err}");
    let said = format!("{out}{err}");
    assert!(
        said.contains(
            "the sideslip turns against the car: its rate correlates at -1.00 with ay/u − r"
        ),
        "{said}"
    );
    // The right sign says nothing.
    let (ok, out, err) = metrics(&history, &["--filter-hz", "0"]);
    assert!(ok, "{err}");
    assert!(!format!("{out}{err}").contains("turns against the car"));
}

/// A units row `s,rad,m/s,rad,rad/s,m/s2` was quoted in the tool's column
/// order (`s, m/s, rad, rad/s, m/s2, rad`): quoted as the file has it.
#[test]
fn a_units_row_is_quoted_in_the_files_order() {
    let (dir, history) = lin_history();
    let text = six_columns(&history, |_| {}).replacen("\n", "\ns,rad,m/s,rad,rad/s,m/s2\n", 1);
    let file = dir.path().join("units_row.csv");
    fs::write(&file, text).unwrap();
    let (ok, _, err) = metrics(&file, &[]);
    assert!(!ok);
    assert!(
        err.contains("no cell of this row is a number (`s, rad, m/s, rad, rad/s, m/s2`)"),
        "{err}"
    );
}

/// The bundled MF 6.1 file's text.
fn mf61() -> String {
    fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
        .unwrap()
        .replace("\r\n", "\n")
}

/// `FNOMIN = 5000` added under [MODEL] while [VERTICAL] keeps 6752 was
/// read silently as 6752: refused, naming both lines.
#[test]
fn a_tir_key_repeated_in_another_section_is_refused_with_both_lines() {
    let text = mf61().replacen("[MODEL]\n", "[MODEL]\nFNOMIN = 5000\n", 1);
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n";
    let dir = scratch(&[("dup.tir", &text), ("points.csv", points)]);
    let o = run_in(
        dir.path(),
        &["tyre-eval", "dup.tir", "points.csv", "--out", "f.csv"],
    );
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("dup.tir:49:1: `FNOMIN` appears twice (also line 14, in section [MODEL]: a parameter belongs to one section)"),
        "{e}"
    );
    // [UNITS]' MASS = 'kg' beside [INERTIA]'s MASS is no repeat.
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            root()
                .join("tests/fixtures/tir/MagicFormula61_Parameters.tir")
                .to_str()
                .unwrap(),
            "points.csv",
            "--out",
            "f.csv",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
}

/// A camber of 1.2 (1.2° meant) was read as 69° and only clamped to
/// CAMMAX: refused as `identify` refuses a rig's, with the degrees hint.
#[test]
fn a_camber_beyond_45_degrees_is_refused_as_degrees() {
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,1.2,16.7\n";
    let dir = scratch(&[("points.csv", points)]);
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            tir.to_str().unwrap(),
            "points.csv",
            "--out",
            "f.csv",
        ],
    );
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("points.csv:2:4: column `camber`: 1.2 rad (68.8°) is beyond ±45° (0.785 rad), steeper than any car tyre runs; a column whose every camber other than 0 is beyond ±20° (0.349 rad) is refused too: angles are in radians (FORMATS.md); is the column in degrees?"),
        "{e}"
    );
}

/// A MoTeC export with 3 metadata lines and a blank one above its header
/// was refused as "missing required column t (the header has: Format,
/// MoTeC CSV File)" alone: the line that names it is said, and how to
/// skip the lines above.
#[test]
fn a_header_under_metadata_lines_is_pointed_at() {
    let (dir, history) = lin_history();
    let text = format!(
        "\"Format\",\"MoTeC CSV File\"\n\"Venue\",\"Test track\"\n\"Sample Rate\",\"1000\",\"Hz\"\n\n{}",
        six_columns(&history, |_| {})
    );
    let file = dir.path().join("motec.csv");
    fs::write(&file, text).unwrap();
    let (ok, _, err) = metrics(&file, &[]);
    assert!(!ok);
    assert!(
        err.contains("missing required column `t` (the header has: Format, MoTeC CSV File); line 5 names it: the header is further down, under lines of metadata (a logger's export, as MoTeC's): start each line above it with `#` (a comment line, skipped) or delete them"),
        "{err}"
    );
}

/// `simulate` with a .tir whose FZMIN is above the wheel loads said the
/// forces were "evaluated at the ranges' ends (… the force stays that of
/// the range's end …)", but a load below FZMIN is not raised to it.
#[test]
fn simulate_says_a_load_below_fzmin_is_evaluated_at_the_load_given() {
    let text = mf61().replace(
        "FZMIN                    =    0 ",
        "FZMIN                    =    5000 ",
    );
    let sc = format!(
        "{VEHICLE}\n[tyres]\nfront = \"tyre.tir\"\nrear = \"tyre.tir\"\n\n{STEP}start = 1.0\nrise_time = 0.1\nend = 4.0\n"
    );
    let dir = scratch(&[("tyre.tir", &text), ("scenario.toml", &sc)]);
    let o = run_in(dir.path(), &["simulate", "scenario.toml", "--out", "out"]);
    let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    assert!(o.status.success(), "{said}");
    assert!(
        said.contains("evaluated at the ranges' ends, a load below FZMIN excepted (MFeval's limit checks: the force stays that of the range's end, however far beyond; a load below FZMIN is not raised to it, its force is evaluated at the load given)"),
        "{said}"
    );
}
