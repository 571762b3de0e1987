//! Round 35's `simulate` and input findings: a 1° step 2 m/s under the
//! critical speed that stalled Dormand–Prince was said as "linear tyres at
//! a large steer"; a campaign or scenario without `[vehicle]` was refused
//! at its first key (`name`, 1:1); an `end` of 1e9 s was told only its
//! lower limit; `--degrees speed` was offered `steer`; a semicolon header
//! was offered "did you mean `t`?" before the advice that mends it.

use super::{fails_cleanly, run, scratch, stderr, VEHICLE};

/// A linear tyre of 57 296 N/rad per wheel.
const LINEAR: &str = "model = \"linear\"\ncornering_stiffness = 57296.0\n";

/// [`VEHICLE`] with its mass rearward (a = 1.67 m, b = 1.11 m), on
/// [`LINEAR`] tyres with load transfer, stepped `steer` rad at `speed`.
fn rearward_step(speed: f64, steer: f64) -> String {
    let vehicle = VEHICLE.replace("a = 1.11\nb = 1.67\n", "a = 1.67\nb = 1.11\n");
    format!("name = \"os\"\n{vehicle}[tyres]\nfront = \"lin.toml\"\n[manoeuvre]\nkind = \"step-steer\"\nspeed = {speed:?}\nsteer = {steer:?}\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n")
}

/// The tester's over30.toml: K = (m/l)·(b − a)/C_axle = −0.00269
/// rad/(m/s²), v_crit = √(−l/K) = 32.2 m/s; the 1° step at 30 m/s asks
/// for u²·δ/(l + K·u²) = 43.7 m/s², beyond the g·t/(2h) = 13.8 m/s² at
/// which the rigid car's inner wheels lift. The old binary said "a wheel
/// lifting off under load transfer, or forces far beyond any tyre's:
/// linear tyres at a large steer". The speed it suggests runs.
#[test]
fn a_stall_below_the_critical_speed_is_said_as_the_turn_the_step_asks_for() {
    let steer = 0.0174533;
    let dir = scratch(&[
        ("lin.toml", LINEAR),
        ("s.toml", &rearward_step(30.0, steer)),
    ]);
    let err = fails_cleanly("simulate", &dir.path().join("s.toml"), dir.path());
    let (m, l, g, c): (f64, f64, f64, f64) = (1530.0, 2.78, 9.80665, 2.0 * 57_296.0);
    let k = m / l * (1.11 / c - 1.67 / c);
    let critical = (-l / k).sqrt();
    let asked = 900.0 * steer / (l + k * 900.0);
    let lift = g * 1.55 / (2.0 * 0.55);
    assert!((critical - 32.15).abs() < 0.01 && (asked - 43.71).abs() < 0.01);
    for said in [
        "stalled at t = ".to_string(),
        "the step asks for a turn the car does not hold on four wheels".into(),
        format!("near its critical speed √(−l/K) = {critical:.1} m/s"),
        format!(
            "u²·δ/(l + K·u²) = {asked:.1} m/s² ({:.2} g), beyond the {lift:.1} m/s²",
            asked / g
        ),
        "from which the inner wheels lift off".into(),
    ] {
        assert!(err.contains(&said), "{said} not in: {err}");
    }
    assert!(!err.contains("large steer"), "{err}");
    // The highest speed for this step: its run goes through.
    let below = err
        .split("or of 1.00° below ")
        .nth(1)
        .and_then(|r| r.split(" m/s").next())
        .and_then(|v| v.parse::<f64>().ok())
        .unwrap_or_else(|| panic!("no speed in: {err}"));
    assert!((below - 26.5).abs() < 0.1, "{below}");
    let slower = rearward_step(below - 0.1, steer);
    std::fs::write(dir.path().join("slower.toml"), slower).unwrap();
    let o = run(&[
        "simulate",
        dir.path().join("slower.toml").to_str().unwrap(),
        "--out",
        dir.path().join("slower").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// The tester's st05.toml: a 0.5 rad (28.6°) step at 5 m/s asks for a
/// steady 4.6 m/s², well within the car, and stalls in its transient: a
/// large steer, said with its size.
#[test]
fn a_stall_at_a_large_steer_is_said_with_the_steer() {
    let sc = format!("name = \"st\"\n{VEHICLE}[tyres]\nfront = \"lin.toml\"\n[manoeuvre]\nkind = \"step-steer\"\nspeed = 5.0\nsteer = 0.5\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n");
    let dir = scratch(&[("lin.toml", LINEAR), ("s.toml", &sc)]);
    let err = fails_cleanly("simulate", &dir.path().join("s.toml"), dir.path());
    assert!(
        err.contains("at a large steer: 28.6° of road-wheel steer")
            && err.contains("A smaller steer keeps the car in the model's range"),
        "{err}"
    );
    assert!(!err.contains("asks for a turn"), "{err}");
}

/// A campaign and a scenario without `[vehicle]`: the old binary said
/// "nov.toml:1:1: `name`: missing field `vehicle`".
#[test]
fn a_file_without_its_vehicle_table_is_said_to_lack_it_with_its_tables() {
    let campaign = "name = \"nov\"\n\n[tyres]\nrig = \"rig.csv\"\nmodel = \"pac89\"\n\n[runs]\ndir = \"runs\"\n";
    let scenario = format!("name = \"nov\"\n[tyres]\nfront = \"lin.toml\"\n{}", "[manoeuvre]\nkind = \"step-steer\"\nspeed = 20.0\nsteer = 0.01\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n");
    let dir = scratch(&[
        ("camp.toml", campaign),
        ("scen.toml", &scenario),
        ("lin.toml", LINEAR),
    ]);
    let err = fails_cleanly("diagnose", &dir.path().join("camp.toml"), dir.path());
    assert!(
        err.contains("camp.toml: the table `[vehicle]` is missing (the file's tables: [tyres] at line 3, [runs] at line 7)"),
        "{err}"
    );
    let err = fails_cleanly("simulate", &dir.path().join("scen.toml"), dir.path());
    assert!(
        err.contains("scen.toml: the table `[vehicle]` is missing (the file's tables: [tyres] at line 2, [manoeuvre] at line 4)"),
        "{err}"
    );
    assert!(!err.contains("`name`"), "{err}");
}

/// The tester's endhuge.toml (end = 1e9) was told only "(3.1, 1000000]: the
/// run must last at least 2 s after the steer reaches its final value";
/// an end of 5e5 s passed that check and was refused at `step`, asking
/// for a step of 0.25 s that the scenario may not set (at most 0.05 s).
#[test]
fn an_end_beyond_the_longest_run_is_refused_with_its_upper_limit_and_why() {
    for end in ["1e9", "5e5"] {
        let sc = format!("name = \"end\"\n{VEHICLE}[tyres]\nfront = \"lin.toml\"\n[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\nstart = 1.0\nrise_time = 0.1\nend = {end}\n");
        let dir = scratch(&[("lin.toml", LINEAR), ("s.toml", &sc)]);
        let err = fails_cleanly("simulate", &dir.path().join("s.toml"), dir.path());
        assert!(
            err.contains("`manoeuvre.end` = ")
                && err.contains("must lie in (3.1, 100000]")
                && err
                    .contains("and end by 100000 s (27.8 h): a history holds at most 2000001 rows")
                && err.contains("`step` of at most 0.05 s"),
            "{end}: {err}"
        );
    }
}

/// `--degrees speed` (and a replay's `degrees = ["speed"]`) was answered
/// "did you mean `steer`?": the speed is a column, and no angle.
#[test]
fn a_column_that_is_no_angle_is_not_offered_an_angles_name() {
    let csv = "t,steer,speed,yaw_rate\n0,0,20,0\n0.01,0,20,0\n";
    let replay = format!("name = \"rep\"\n{VEHICLE}[tyres]\nfront = \"lin.toml\"\n[manoeuvre]\nkind = \"replay\"\nrun = \"run.csv\"\ndegrees = [\"speed\"]\n");
    let dir = scratch(&[
        ("run.csv", csv),
        ("lin.toml", LINEAR),
        ("rep.toml", &replay),
    ]);
    let run_csv = dir.path().join("run.csv");
    let o = run(&["metrics", run_csv.to_str().unwrap(), "--degrees", "speed"]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("`speed` is no angle: a run's forward speed is in m/s, never in degrees; the angle columns `metrics` reads in degrees are steer, yaw_rate, beta, roll"),
        "{err}"
    );
    assert!(!err.contains("did you mean"), "{err}");
    let err = fails_cleanly("simulate", &dir.path().join("rep.toml"), dir.path());
    assert!(
        err.contains("`manoeuvre.degrees[0]`: unknown variant `speed` (`speed` is no angle: a run's forward speed is in m/s, never in degrees)"),
        "{err}"
    );
    assert!(!err.contains("did you mean"), "{err}");
}

/// The tester's semi.csv: its one column was offered "did you mean `t`?"
/// before the advice that mends every column at once.
#[test]
fn a_semicolon_header_is_told_its_separator_and_nothing_before_it() {
    let csv = "t [s];steer [deg];speed [m/s];yaw_rate [deg/s];ay [m/s2]\n0;0;22,2222;0;0\n0,001;0;22,2222;0;0\n";
    let dir = scratch(&[("semi.csv", csv)]);
    let o = run(&["metrics", dir.path().join("semi.csv").to_str().unwrap()]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("missing required column `t` (the header has: t [s];steer [deg];speed [m/s];yaw_rate [deg/s];ay [m/s2]); the header is one column separated by semicolons"),
        "{err}"
    );
    assert!(!err.contains("did you mean"), "{err}");
}
