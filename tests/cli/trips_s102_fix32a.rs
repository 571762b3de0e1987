//! Round 32's `simulate` trips: a step sized by `lateral_acceleration`
//! that missed its target with a tyre lag and steering compliance on (the
//! solver's lag states ignored the compliance) and on a banked road (sized
//! for the accelerometer's reading, measured as the change from the
//! trim), each blamed on an instability; an `aero_load` on linear tyres
//! acting on nothing unsaid; a Daytona bank refused by the scenario while
//! the runs' check accepts it; a working folder's 187 other files listed
//! on one line; a bank column's percentile said to nine digits.

use super::scenarios::simulate_to;
use super::{read_json, run, run_in, scratch, stderr, VEHICLE};
use std::fs;
use std::path::Path;

/// Wang & Liang's Gim tyres (500 / 540 N/deg per wheel), as the tester's.
const GIM_FRONT: &str =
    "model = \"gim\"\ncornering_stiffness = 28647.9\ncontact_length = 0.16\nfriction = 1.0\n";
const GIM_REAR: &str =
    "model = \"gim\"\ncornering_stiffness = 30939.7\ncontact_length = 0.16\nfriction = 1.0\n";

/// A step to a steady lateral acceleration of 4 m/s² at 30 m/s.
const STEP_TO_4: &str = "[manoeuvre]\nkind = \"step-steer\"\nspeed = 30.0\nlateral_acceleration = 4.0\nstart = 1.0\nrise_time = 0.1\nend = 8.0\n";

/// The sedan on Gim tyres with `effects` (lines of `[model.effects]`)
/// written to `dir/name.toml`, stepped by `manoeuvre`.
fn sedan(dir: &Path, name: &str, effects: &str, manoeuvre: &str) -> std::path::PathBuf {
    fs::write(dir.join("front.toml"), GIM_FRONT).unwrap();
    fs::write(dir.join("rear.toml"), GIM_REAR).unwrap();
    let path = dir.join(format!("{name}.toml"));
    let text = format!(
        "name = \"{name}\"\n{VEHICLE}\n[tyres]\nfront = \"front.toml\"\nrear = \"rear.toml\"\n\n[model.effects]\n{effects}\n{manoeuvre}"
    );
    fs::write(&path, text).unwrap();
    path
}

/// Simulates `name` with `effects` to 4 m/s²: stdout and metrics.json.
fn stepped_to_4(dir: &Path, name: &str, effects: &str) -> (String, serde_json::Value) {
    let path = sedan(dir, name, effects, STEP_TO_4);
    let out = dir.join(format!("o_{name}"));
    let said = simulate_to(&path, &out);
    (said, read_json(&out.join("metrics.json")))
}

/// The metrics' steady ay of a run stepped to 4 m/s², asserted within
/// 0.005 of it and unwarned.
fn reaches_4(dir: &Path, name: &str, effects: &str) {
    let (said, m) = stepped_to_4(dir, name, effects);
    let ay = m["ay_steady"].as_f64().unwrap();
    assert!((ay - 4.0).abs() <= 0.005, "{name}: steady ay {ay}\n{said}");
    assert!(!said.contains("the step was sized for"), "{name}: {said}");
}

#[test]
fn a_step_with_tyre_lag_and_steering_compliance_reaches_the_lateral_acceleration_asked() {
    // The tester's pp_03: 3.4675 m/s² reached for 4, with an instability
    // blamed; compliance alone took 2.8229° of steer, the pair 2.3997°.
    let dir = tempfile::tempdir().unwrap();
    let pair = "relaxation_length = 0.4\nsteering_compliance = 2e-6\n";
    let (said, m) = stepped_to_4(dir.path(), "pp_03", pair);
    let ay = m["ay_steady"].as_f64().unwrap();
    assert!((ay - 4.0).abs() <= 0.005, "steady ay {ay}\n{said}");
    assert!(!said.contains("unstable"), "{said}");
    // The lag changes no steady state: the same steer as compliance alone.
    let (_, alone) = stepped_to_4(dir.path(), "sc", "steering_compliance = 2e-6\n");
    let (with, without) = (m["steer_step"].as_f64(), alone["steer_step"].as_f64());
    let gap = (with.unwrap() - without.unwrap()).abs();
    assert!(gap < 1e-7, "{with:?} vs {without:?}");
}

#[test]
fn every_pair_of_the_books_effects_reaches_the_lateral_acceleration_asked() {
    // The effects of the book's table that act on a step at constant speed
    // (the ax effects are idle there, warned of; the bank profile needs a
    // replayed run). On the bank the target is the change from the trim.
    let effects = [
        ("aero", "aero_load = [0.3, 0.4]"),
        ("bank", "road_bank = 0.05"),
        ("lag", "relaxation_length = 0.4"),
        ("compliance", "steering_compliance = 2e-6"),
        ("rollsteer", "roll_steer = [0.1, 0.0]"),
        ("rollcamber", "roll_camber = [0.3, 0.2]"),
        ("scale", "cornering_stiffness_scale = [1.1, 0.9]"),
    ];
    let dir = tempfile::tempdir().unwrap();
    for (i, (a, ea)) in effects.iter().enumerate() {
        reaches_4(dir.path(), a, &format!("{ea}\n"));
        for (b, eb) in &effects[i + 1..] {
            reaches_4(dir.path(), &format!("{a}_{b}"), &format!("{ea}\n{eb}\n"));
        }
    }
}

#[test]
fn a_banked_step_reaches_the_change_asked_and_says_what_the_accelerometer_reads() {
    // The tester's ba_roadbank: 3.5099 m/s² measured (4 less the bank's
    // 0.4901), warned of as an instability or a slide.
    let dir = tempfile::tempdir().unwrap();
    let (said, m) = stepped_to_4(dir.path(), "bank", "road_bank = 0.05\n");
    let ay = m["ay_steady"].as_f64().unwrap();
    assert!((ay - 4.0).abs() <= 0.005, "steady ay {ay}\n{said}");
    assert!(!said.contains("the step was sized for"), "{said}");
    let hold = 9.80665 * 0.05f64.sin();
    assert!(
        said.contains(&format!("`lateral_acceleration` = 4 m/s² is such a change too, from the {hold:.3} m/s² the accelerometer reads on the bank at straight running: the step turns the car to {:.3} m/s² as the accelerometer reads it", 4.0 + hold)),
        "{said}"
    );
    // The history's ay is the accelerometer's: the trim's, then 4 more.
    let history = fs::read_to_string(dir.path().join("o_bank/history.csv")).unwrap();
    let ay_of = |line: &str| line.split(',').nth(5).unwrap().parse::<f64>().unwrap();
    let first = ay_of(history.lines().nth(1).unwrap());
    let last = ay_of(history.lines().last().unwrap());
    assert!((first - hold).abs() < 1e-6, "{first}");
    assert!((last - hold - 4.0).abs() < 0.005, "{last}");
}

#[test]
fn aero_load_on_linear_tyres_is_warned_of_as_acting_on_nothing() {
    let lin = "model = \"linear\"\ncornering_stiffness = 57296.0\npneumatic_trail = 0.03\n";
    let manoeuvre = "[manoeuvre]\nkind = \"step-steer\"\nspeed = 25.0\nsteer = 0.01\nstart = 1.0\nrise_time = 0.1\nend = 12.0\n";
    let sc = |tyres: &str| {
        format!("name = \"aero\"\n{VEHICLE}\n[tyres]\n{tyres}\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n[model.effects]\naero_load = [0.5, 0.7]\n{manoeuvre}")
    };
    let dir = scratch(&[
        ("lin.toml", lin),
        ("gim.toml", GIM_FRONT),
        ("aero_l.toml", &sc("front = \"lin.toml\"\n")),
        ("aero_g.toml", &sc("front = \"gim.toml\"\n")),
    ]);
    let said = simulate_to(&dir.path().join("aero_l.toml"), &dir.path().join("o_l"));
    // k·u² at 25 m/s: 0.5·625 = 312.5 N, 0.7·625 = 437.5 N.
    assert!(
        said.contains("warning: `model.effects.aero_load` = [0.5, 0.7] N per (m/s)² acts on nothing: it adds 312.5 N on the front axle and 437.5 N on the rear axle at 25 m/s (k·u²), and the front and rear tyres are linear, whose force C_α·α does not depend on the load"),
        "{said}"
    );
    // On Gim tyres (a friction limit of μ·Fz) the down-force acts.
    let said = simulate_to(&dir.path().join("aero_g.toml"), &dir.path().join("o_g"));
    assert!(!said.contains("acts on nothing"), "{said}");
}

#[test]
fn a_daytona_bank_is_a_road_and_one_past_35_degrees_is_refused_naming_the_limit() {
    let dir = tempfile::tempdir().unwrap();
    let step = "[manoeuvre]\nkind = \"step-steer\"\nspeed = 30.0\nsteer = 0.01\nstart = 1.0\nrise_time = 0.1\nend = 4.0\n";
    // Daytona's 31° (0.54 rad), refused above 0.5 rad before.
    let daytona = sedan(dir.path(), "daytona", "road_bank = 0.54\n", step);
    simulate_to(&daytona, &dir.path().join("o_daytona"));
    let steep = sedan(dir.path(), "steep", "road_bank = 0.62\n", step);
    let o = run(&[
        "simulate",
        steep.to_str().unwrap(),
        "--out",
        dir.path().join("o_steep").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("`model.effects.road_bank` = 0.62: must lie within ±0.61: a bank steeper than 0.61 rad (35°; Daytona's banking is 31°, Talladega's 33°) is not a road"),
        "{e}"
    );
}

#[test]
fn a_working_folder_as_out_lists_its_first_other_files_and_counts_the_rest() {
    let lin = "model = \"linear\"\ncornering_stiffness = 57296.0\n";
    let sc = format!("name = \"lin_step\"\n{VEHICLE}\n[tyres]\nfront = \"lin.toml\"\n[manoeuvre]\nkind = \"step-steer\"\nspeed = 25.0\nsteer = 0.01\nstart = 1.0\nrise_time = 0.1\nend = 4.0\n");
    let dir = scratch(&[("lin.toml", lin), ("lin_step.toml", &sc)]);
    for i in 0..30 {
        fs::write(dir.path().join(format!("note_{i:02}.txt")), "x").unwrap();
    }
    let o = run_in(dir.path(), &["simulate", "lin_step.toml", "--out", "."]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout).into_owned();
    let line = said
        .lines()
        .find(|l| l.contains("the folder also holds"))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(
        line.contains("the folder also holds 32 files that `simulate` does not write, left as they are: lin.toml, lin_step.toml, note_00.txt, note_01.txt, note_02.txt and 27 more (give each run a folder of its own"),
        "{line}"
    );
    assert!(line.len() < 300, "{} characters: {line}", line.len());
}

#[test]
fn a_bank_column_in_degrees_is_refused_with_its_percentile_to_three_digits() {
    // The tester's oval log with `bank` in degrees: "1 % of the run is
    // beyond 20.2264435 rad".
    let mut csv = String::from("t,speed,steer,yaw_rate,ay,bank\n");
    for i in 0..400 {
        let t = f64::from(i) * 0.01;
        let bank = 20.2264435 + 0.001 * f64::from(i % 3);
        csv.push_str(&format!("{t},30,0,0,0,{bank}\n"));
    }
    let dir = scratch(&[(
        "tyre.toml",
        "model = \"linear\"\ncornering_stiffness = 60000.0\n",
    )]);
    let replay = super::replay_of(dir.path(), &csv);
    let o = run(&[
        "simulate",
        replay.to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("rad is beyond ±57°, and the run's 99th percentile of |bank| is 20.2 rad: angles are in radians"),
        "{e}"
    );
}
