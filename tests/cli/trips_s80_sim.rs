//! What `simulate`, a scenario and `synth` said wrongly or not at all
//! (session 80, fresh-eyes round 7): a banked road's trim blamed on the
//! tyres' conicity, a `bank_profile_scale` under a step steer, a replay's
//! `ax` in g or reversed, the `[integrator]` table's key named as
//! `simulation`, a replay too long for a history cited at a `step` the
//! file does not write, `synth --drive` dropping a replay's bank and
//! `--effects none,…`, and effects that act on nothing.

use super::trips_s79_sim::{sedan, simulated, REPLAY};
use super::*;

/// A 1° step steer at 80 km/h from t = 1 s to 6 s.
const STEP_STEER: &str = "[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n";

/// A step steer on a road banked 0.05 rad on linear tyres (no force at
/// zero slip) said that "the tyres make lateral force at zero slip
/// (conicity, ply steer)": the trim is the bank's, g·sin(0.05) =
/// 9.80665 × 0.04998 = 0.490 m/s² across the car.
#[test]
fn a_banked_roads_trim_is_the_banks_not_the_tyres() {
    let dir = tempfile::tempdir().unwrap();
    let rest = format!("{STEP_STEER}\n[model.effects]\nroad_bank = 0.05\n");
    let path = sedan(dir.path(), "banked", &rest);
    let said = simulated(&path, dir.path());
    assert!(
        said.contains("note: the road is banked 0.05 rad (2.86°, `road_bank`): gravity pulls the car toward its lower edge with g·sin(bank) = 0.490 m/s², which the tyres hold: straight running needs a steer of"),
        "{said}"
    );
    assert!(!said.contains("conicity"), "{said}");
}

/// The bundled PAC89 step on a banked road: both causes named, the
/// tyres' share as on the flat road (-0.019°, the bundled example's).
#[test]
fn a_banked_road_under_tyres_with_conicity_names_both() {
    let dir = tempfile::tempdir().unwrap();
    let text = bundled_scenario("step_gbt6323_pac89.toml");
    let path = dir.path().join("banked.toml");
    fs::write(
        &path,
        format!("{text}\n[model.effects]\nroad_bank = -0.03\n"),
    )
    .unwrap();
    let said = simulated(&path, dir.path());
    assert!(
        said.contains("the road is banked -0.03 rad (-1.72°, `road_bank`): gravity pulls the car toward its lower edge with g·sin(bank) = 0.294 m/s², which the tyres hold, and the tyres make lateral force at zero slip (conicity, ply steer), which alone need -0.019° of steer on a flat road"),
        "{said}"
    );
}

/// `bank_profile_scale` under a step steer acted on nothing, silently.
#[test]
fn a_bank_profile_scale_under_a_step_steer_is_said_to_act_on_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let rest = format!("{STEP_STEER}\n[model.effects]\nbank_profile_scale = 1.0\n");
    let path = sedan(dir.path(), "step", &rest);
    let said = simulated(&path, dir.path());
    assert!(
        said.contains("warning: `model.effects.bank_profile_scale` (line 22) acts on nothing: it scales a replayed run's `bank` column, and a step-steer replays no run (a constant bank is `road_bank`)"),
        "{said}"
    );
}

/// `[integrator] method = "rk4"` with `rtol`: the key was named
/// `simulation.rtol`, without a line.
#[test]
fn a_tolerance_with_rk4_is_refused_at_its_key_as_written() {
    let dir = tempfile::tempdir().unwrap();
    let rest = format!("{STEP_STEER}\n[integrator]\nmethod = \"rk4\"\nrtol = 1e-6\n");
    let path = sedan(dir.path(), "scenario", &rest);
    let err = simulate_err(dir.path());
    let file = path.display();
    assert!(
        err.contains(&format!(
            "{file}:23:8: `integrator.rtol` = 1e-6: tolerances apply to method = \"dopri5\" or \"dop853\""
        )),
        "{err}"
    );
}

/// A 2400 s log at 25 Hz (60001 samples) replayed at the default row
/// interval: refused at `simulation.step`, a key the file does not
/// write. Now at `run`, with the limit and what to do.
#[test]
fn a_long_replay_is_refused_at_its_run_with_what_to_do() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("t,speed,steer,yaw_rate,ay\n");
    for i in 0..=60_000 {
        let t = i as f64 * 0.04;
        let d = 0.01 * (0.5 * t).sin();
        text += &format!(
            "{t:.2},20,{d:.6},{:.6},{:.6}\n",
            d * 20.0 / 2.78,
            d * 400.0 / 2.78
        );
    }
    fs::write(dir.path().join("run.csv"), text).unwrap();
    let path = sedan(dir.path(), "scenario", REPLAY);
    let err = simulate_err(dir.path());
    let file = path.display();
    assert!(
        err.contains(&format!("{file}:15:7: the replayed run lasts 2400 s (60001 samples): its history, a row every 0.001 s (the default row interval; this scenario sets none), makes 2400001 rows (about 360 MB of history.csv), 400000 more than the 2000001 a history holds (a first row and 2000000 steps after it); cut the run into pieces of at most 2000 s")),
        "{err}"
    );
    assert!(
        err.contains("`step = 0.0012` (s) or more under [simulation]"),
        "{err}"
    );
    assert!(!err.contains("simulation.step"), "{err}");
}

/// A relaxation length of 0.5 mm (below the 1 mm where the lag is
/// switched off) and a longitudinal load transfer under a step steer at a
/// constant 22.22 m/s did nothing, silently.
#[test]
fn effects_that_act_on_nothing_are_said_with_their_numbers() {
    let dir = tempfile::tempdir().unwrap();
    let effects = "[model.effects]\nrelaxation_length = 0.0005\nlongitudinal_load_transfer = 1\n";
    let path = sedan(dir.path(), "idle", &format!("{STEP_STEER}\n{effects}"));
    let said = simulated(&path, dir.path());
    assert!(
        said.contains("warning: `model.effects.relaxation_length` = 0.0005 m acts on nothing: below 0.001 m (1 mm"),
        "{said}"
    );
    assert!(
        said.contains("warning: `model.effects.longitudinal_load_transfer` = 1 acts on nothing: it acts with the longitudinal acceleration ax, and this run holds its speed at 22.22 m/s throughout (ax = 0, and no `ax` is logged)"),
        "{said}"
    );
    // A lag of 1 mm or more acts: not said.
    let path = sedan(
        dir.path(),
        "lag",
        &format!("{STEP_STEER}\n[model.effects]\nrelaxation_length = 0.3\n"),
    );
    fs::remove_dir_all(dir.path().join("out")).unwrap();
    let said = simulated(&path, dir.path());
    assert!(!said.contains("acts on nothing"), "{said}");
}

/// A straight run of 10 s at 25 Hz braking from 30 m/s at 1 m/s² on a
/// road banked −0.2 rad, its accelerometer reading ax = −1.3 m/s² (a
/// downhill grade's share on top), written to `dir/run.csv`.
fn banked_braking(dir: &Path) {
    let mut text = String::from("t,speed,steer,yaw_rate,ay,ax,bank\n");
    for i in 0..=250 {
        let t = i as f64 * 0.04;
        text += &format!("{t},{},0,0,0,-1.3,-0.2\n", 30.0 - t);
    }
    fs::write(dir.join("run.csv"), text).unwrap();
}

/// The mean of the column `name` of the CSV file `path`.
fn mean_of(path: &Path, name: &str) -> f64 {
    let text = fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = header.iter().position(|h| *h == name).unwrap();
    let v: Vec<f64> = lines
        .map(|l| l.split(',').nth(k).unwrap().parse().unwrap())
        .collect();
    v.iter().sum::<f64>() / v.len() as f64
}

/// `synth --drive` of a replay logged the run's bank as 0 and its ax as
/// the speed's derivative: now the replay's own (−0.2 rad, −1.3 m/s²,
/// within the logger's noise), and where the programme logs neither
/// (handling), said to be dropped.
#[test]
fn synth_drive_keeps_a_replays_bank_and_ax_or_says_they_are_dropped() {
    let dir = tempfile::tempdir().unwrap();
    banked_braking(dir.path());
    let replay = sedan(dir.path(), "replay", REPLAY);
    let drive = |programme: &str, out: &str| {
        succeeds(&[
            "synth",
            "--programme",
            programme,
            "--seed",
            "2",
            "--out",
            dir.path().join(out).to_str().unwrap(),
            "--drive",
            replay.to_str().unwrap(),
        ])
    };
    let said = drive("oval", "oval");
    assert!(!said.contains("dropped"), "{said}");
    let run = dir.path().join("oval/runs/replay.csv");
    let (bank, ax) = (mean_of(&run, "bank"), mean_of(&run, "ax"));
    assert!((bank + 0.2).abs() < 0.005, "bank {bank}");
    assert!((ax + 1.3).abs() < 0.05, "ax {ax}");
    let said = drive("handling", "handling");
    assert!(
        said.contains("replay.toml: the replayed run's `bank` column (up to 0.200 rad, 11.46°) is dropped: the handling programme logs no bank, and its truth does not drive on it"),
        "{said}"
    );
    assert!(
        said.contains("replay.toml: the replayed run's `ax` column is dropped: the handling programme logs no ax"),
        "{said}"
    );
}

/// `synth --effects none,sensor_delay` ran with the delay on.
#[test]
fn synth_refuses_none_with_effects() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("c");
    let o = run(&[
        "synth",
        "--effects",
        "none,sensor_delay",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(!out.exists());
    assert!(
        stderr(&o).contains("--effects names `none` (a truth with no effect on) together with `sensor_delay`: give `none` alone, or the effects alone (`--effects sensor_delay`)"),
        "{}",
        stderr(&o)
    );
}
