//! What the fourth fresh-eyes check found in `simulate` and `metrics`:
//! runs that were not what their input's words suggest and said nothing
//! (a trim, a drift, a slide outside a step, a steer no rack makes, tyres
//! beyond their fitted data, gigabytes of rows, a step at varying speed),
//! and a slow car's turn said as a slide.
//! Each test one finding, run as a user runs it.

use super::*;

/// `simulate <dir>/scenario.toml --out <dir>/out`: status, stdout, stderr.
pub(super) fn simulated(dir: &Path) -> (bool, String, String) {
    let o = run(&[
        "simulate",
        dir.join("scenario.toml").to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
    ]);
    (
        o.status.success(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        stderr(&o),
    )
}

/// The bundled PAC89 tyre, whose curve is shifted (force at zero slip).
fn pac89() -> String {
    fs::read_to_string(root().join("tyres/pac89_adams_example.toml")).unwrap()
}

/// The bundled step on PAC89 tyres started from a trimmed steer and
/// sideslip without a word; a ramp on the same tyres started from zero
/// and drifted without one.
#[test]
fn a_step_says_its_straight_running_trim_and_a_ramp_on_shifted_tyres_warns_of_its_drift() {
    let out = tempfile::tempdir().unwrap();
    let o = run(&[
        "simulate",
        "scenarios/step_gbt6323_pac89.toml",
        "--out",
        out.path().join("o").to_str().unwrap(),
    ]);
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("note: the tyres make lateral force at zero slip (conicity, ply steer): straight running needs a steer of -0.019° and a sideslip of 0.051°; the run starts there, the 0.677° step is added to that steer, and the metrics measure changes from there (the steady sideslip is its change from the 0.0513° the run holds before the step)"),
        "{said}"
    );
    assert!(!said.contains("warning:"), "{said}");
    let ramp =
        "[manoeuvre]\nkind = \"ramp-steer\"\nspeed = 22.2\nrate = 0.01\nstart = 1.0\nend = 3.0\n";
    let dir = scenario(VEHICLE, &pac89(), ramp);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(
        said.contains("warning: the tyres make lateral force at zero slip (conicity, ply steer): straight running at 22.2 m/s needs a steer of -0.0"),
        "{said}"
    );
    assert!(said.contains("so the car drifts from the start"), "{said}");
    // Symmetric Gim tyres hold a straight line at zero steer: nothing.
    let dir = scenario(VEHICLE, GIM, ramp);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(!said.contains("zero slip"), "{said}");
}

/// A 10 Hz sine of 0.1 rad (6.3 rad/s at the wheels) and a sweep that
/// slid the car ran without a word: only step steers were checked.
#[test]
fn a_sine_no_rack_can_steer_and_a_sweep_that_slides_are_said() {
    let sine = "[manoeuvre]\nkind = \"sine\"\nspeed = 22.2\namplitude = 0.1\nfrequency = 10.0\nstart = 1.0\nend = 3.0\n";
    let dir = scenario(VEHICLE, GIM, sine);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(
        said.contains("warning: the sine's peak rate (2π·10 Hz·amplitude) is 6.3 rad/s (360°/s at the road wheels), faster than a steering system turns the wheels"),
        "{said}"
    );
    // 0.2 rad at 0.5 Hz on the sedan at 80 km/h: past its grip.
    let slide = "[manoeuvre]\nkind = \"sweep\"\nspeed = 22.2\namplitude = 0.2\nf_start = 0.2\nf_end = 0.5\nstart = 1.0\nend = 8.0\n";
    let dir = scenario(VEHICLE, GIM, slide);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(said.contains("warning: the sideslip reaches "), "{said}");
    assert!(
        said.contains("the car slides past its grip, where a 2-DOF model"),
        "{said}"
    );
    assert!(!said.contains("peak rate"), "{said}");
    // The same sweep at a tenth of the amplitude: a handling response.
    let dir = scenario(
        VEHICLE,
        GIM,
        &slide.replace("0.2\nf_start", "0.02\nf_start"),
    );
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(!said.contains("warning:"), "{said}");
}

/// A tyre `identify` fitted to 1–4 kN was run at 4.5 kN per front wheel
/// without a word, where `tyre-eval` counts such points.
#[test]
fn simulate_counts_the_rows_beyond_a_tyres_fitted_ranges() {
    let tyre = format!("{GIM}\n[fitted_ranges]\nfz = [1000.0, 4000.0]\nalpha = [-0.1, 0.1]\n");
    let dir = scenario(VEHICLE, &tyre, STEP);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    // Front wheels carry 4.5 kN static (5.2 kN loaded in the turn), the
    // rear 3.0 kN: every row of the front beyond 4 kN, no rear row beyond
    // either range.
    let front = said
        .lines()
        .find(|l| l.contains("take the front tyres outside"))
        .unwrap_or_else(|| panic!("{said}"));
    let rows = front
        .trim_start_matches("  warning: ")
        .split(' ')
        .collect::<Vec<_>>();
    assert_eq!(rows[0], rows[2], "{front}");
    assert!(
        front.contains("(fz 1000 to 4000 N, alpha -0.1000 to 0.1000 rad; their [fitted_ranges]"),
        "{front}"
    );
    assert!(
        front.contains("evaluated by extrapolation: there, wheel loads 40"),
        "{front}"
    );
    assert!(!front.contains("slip angles"), "{front}");
    assert!(!said.contains("rear tyres outside"), "{said}");
    // Within a wider range: nothing.
    let wide = tyre.replace("4000.0", "6000.0");
    let dir = scenario(VEHICLE, &wide, STEP);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(!said.contains("outside the ranges"), "{said}");
}

/// `step = 1e-6` over a 6,000 s run began writing 6.8 GB of history.
#[test]
fn a_run_of_millions_of_rows_is_refused_at_its_step_with_the_least_step_that_fits() {
    let long =
        format!("{STEP}start = 1.0\nrise_time = 0.1\nend = 3000.0\n\n[simulation]\nstep = 0.001\n");
    let dir = scenario(VEHICLE, GIM, &long);
    let (ok, _, err) = simulated(dir.path());
    assert!(!ok);
    assert!(!dir.path().join("out").exists(), "nothing written");
    assert!(err.contains("scenario.toml:22:"), "{err}");
    assert!(
        err.contains("the run lasts 3000 s: a row every 0.001 s ([simulation] step) makes 3000001 rows (about 450 MB of history.csv), 1000000 more than the 2000001 a history holds (a first row and 2000000 steps after it); set `step` under [simulation] to at least 0.0015 s, or shorten the run (the manoeuvre's `end`)"),
        "{err}"
    );
    // At that step it runs.
    let dir = scenario(VEHICLE, GIM, &long.replace("0.001\n", "0.0015\n"));
    let (ok, _, err) = simulated(dir.path());
    assert!(ok, "{err}");
}

/// `metrics` measured a step while the speed rose by a quarter, and said
/// nothing: the standards hold the speed constant.
#[test]
fn metrics_says_when_the_speed_changes_over_the_measured_step() {
    // A schedule: steady at 20 m/s, a 1.5° step at 2 s, the speed then
    // rising to 26 m/s; its history is the measured run.
    let schedule = |end_speed: f64| {
        format!(
            "[manoeuvre]\nkind = \"schedule\"\nt = [0.0, 2.0, 2.1, 8.0]\nsteer = [0.0, 0.0, 0.026, 0.026]\nspeed = [20.0, 20.0, 20.0, {end_speed}]\n"
        )
    };
    for (end_speed, said) in [(26.0, true), (20.5, false)] {
        let dir = scenario(VEHICLE, GIM, &schedule(end_speed));
        let (ok, _, err) = simulated(dir.path());
        assert!(ok, "{err}");
        let history = dir.path().join("out/history.csv");
        let o = run(&["metrics", history.to_str().unwrap(), "--json"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let report: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        let warned = report["warnings"].as_array().unwrap().iter().any(|w| {
            w.as_str()
                .unwrap()
                .starts_with("the speed rises over the measured piece, between 20.")
        });
        assert_eq!(warned, said, "{end_speed}: {report}");
    }
}

/// A 40° road-wheel step at 80 km/h ran with a full metric table: the
/// front axle at 40° of slip ploughed on while the body's sideslip stayed
/// below 1°; a car lifted on both left wheels printed its metrics too.
#[test]
fn an_axle_past_its_peak_and_a_car_on_two_wheels_are_said() {
    let pac89 = fs::read_to_string(root().join("scenarios/step_gbt6323_pac89.toml"))
        .unwrap()
        .replace("lateral_acceleration = 2.0", "steer = 0.7")
        .replace("../tyres/", &format!("{}/tyres/", root().display()));
    let dir = scratch(&[("scenario.toml", &pac89)]);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(
        said.contains("warning: the front axle's slip angle reaches 39.9°"),
        "{said}"
    );
    // Past its own tyres' peak (PAC89's at 8.7° at that row's loads), not
    // the 15° of any tyre's: a slide.
    assert!(said.contains(", past its tyres' peak at 8.7° ("), "{said}");
    assert!(said.contains("the front axle slides"), "{said}");
    // The bundled step (0.7°): no axle near 15°.
    let dir = scratch(&[(
        "scenario.toml",
        &pac89.replace("steer = 0.7", "lateral_acceleration = 2.0"),
    )]);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(!said.contains("warning:"), "{said}");
    // A tall car stepped to 6.2 m/s², past its rollover threshold of
    // 5.07 m/s² (a steady `lateral_acceleration` there is refused): both
    // inner wheels lift.
    let tall = VEHICLE.replace("cg_height = 0.55", "cg_height = 1.5");
    let step = "[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.08\n";
    let dir = scenario(&tall, GIM, step);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(
        said.contains("wheels are off the ground at t = ")
            && said.contains("the car is on two wheels"),
        "{said}"
    );
}

/// `metrics` measured a 6.8 s ramp as a step: response times of 0.1 ms,
/// "settled", and only a warning that the times "include the ramp".
#[test]
fn metrics_refuses_a_ramp_as_a_step() {
    let ramp =
        "[manoeuvre]\nkind = \"ramp-steer\"\nspeed = 22.2\nrate = 0.004\nstart = 1.0\nend = 10.0\n";
    let dir = scenario(VEHICLE, GIM, ramp);
    let (ok, _, err) = simulated(dir.path());
    assert!(ok, "{err}");
    let history = dir.path().join("out/history.csv");
    let o = run(&["metrics", history.to_str().unwrap()]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("the steer rises from 10 % to 90 % of its change in 6.80 s, from 1.85 s: a ramp steer, not a step"),
        "{err}"
    );
}

/// `--bin-deg 1e300` printed a 300-digit bin and wrote a tyre fitted to one
/// point per condition; `--camber -0.0279` was taken for an option.
#[test]
fn identify_refuses_a_bin_wider_than_the_curves_rise_and_takes_negative_values() {
    let dir = scratch(&[("rig.csv", &super::trips_identify::rig(1.0))]);
    let rig = dir.path().join("rig.csv");
    let out = dir.path().join("t.toml");
    let o = run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "gim",
        "--bin-deg",
        "1e300",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(err.contains("bin_deg"), "{err}");
    assert!(err.contains("a slip-angle bin wider than 2°"), "{err}");
    assert!(!out.exists());
    let o = run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "gim",
        "--camber",
        "-0.0279",
        "--out",
        out.to_str().unwrap(),
    ]);
    let err = stderr(&o);
    assert!(!err.contains("unexpected argument"), "{err}");
}

/// A PAC89 fit of lateral data said its longitudinal block kept "the
/// defaults' values" and wrote a tyre with no longitudinal force; its
/// `tyre-eval` then said the PAC89 model "does not read kappa".
#[test]
fn a_lateral_pac89_fit_says_its_file_has_no_longitudinal_force() {
    let dir = scratch(&[("rig.csv", &super::trips_identify::rig(1.0))]);
    let out = dir.path().join("p.toml");
    let o = super::trips_identify::identify_with(dir.path(), "pac89", &["--seed", "1"], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("no longitudinal data: the file's longitudinal force coefficients are not fitted (no kappa/fx columns in the data): the written file's longitudinal force is 0 at any slip ratio"),
        "{said}"
    );
    let points = dir.path().join("points.csv");
    fs::write(&points, "fz,kappa,alpha,camber,speed\n3000,0.1,0,0,10\n").unwrap();
    let o = run(&[
        "tyre-eval",
        out.to_str().unwrap(),
        points.to_str().unwrap(),
        "--out",
        dir.path().join("e.csv").to_str().unwrap(),
    ]);
    let err = stderr(&o);
    assert!(!err.contains("the pac89 model does not read"), "{err}");
    assert!(
        err.contains("this pac89 tyre does not respond to `kappa`"),
        "{err}"
    );
}

/// A 28.6° step at 2 m/s was said to be "sliding, past its grip": its 18°
/// sideslip is the geometry of a slow turn about a point near the rear
/// axle's line (β ≈ b·δ/l = 17.2°), the tyres at 8 % of their grip (a
/// steady ay of 0.78 m/s²); a ramp to the same steer at 2 m/s was said to
/// slide likewise. A slide at speed is still a slide (the sweep above).
#[test]
fn a_large_steer_at_a_crawl_is_said_as_a_kinematic_turn_not_a_slide() {
    let step = "[manoeuvre]\nkind = \"step-steer\"\nspeed = 2.0\nsteer = 0.5\n";
    let dir = scenario(VEHICLE, GIM, step);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(
        said.contains("warning: the steady sideslip is 17.8°, beyond 10°, but no slide: the tyres use no more than 8 % of their grip, and at 2.00 m/s the 28.6° steer (a car's lock is about 35–40° at the road wheels) turns the car about a point near the line of its rear axle, where the sideslip is the turn's geometry (β ≈ b·δ/l), not the tyres sliding: the response is kinematic, limited by the steer, not by grip"),
        "{said}"
    );
    assert!(!said.contains("past its grip"), "{said}");
    // Measured, the same step: the run's grip is unknown, so its crawl is
    // judged against the least a paved road gives, and said so.
    let history = dir.path().join("out/history.csv");
    let o = run(&["metrics", history.to_str().unwrap(), "--min-speed", "1"]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert!(
        e.contains("the steady sideslip is 17.8°, beyond 10°, but no slide: the tyres use no more than 26 % of the grip of any paved road, wet or dry (0.3 g; the run does not measure its tyres'), and at 2.00 m/s the 28.6° steer"),
        "{e}"
    );
    assert!(!e.contains("past its grip"), "{e}");
    let ramp =
        "[manoeuvre]\nkind = \"ramp-steer\"\nspeed = 2.0\nrate = 0.2\nstart = 1.0\nend = 3.5\n";
    let dir = scenario(VEHICLE, GIM, ramp);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(
        said.contains("warning: the sideslip reaches 1")
            && said.contains("but no slide: the tyres use no more than ")
            && said.contains("at 2.00 m/s the 28.6° steer"),
        "{said}"
    );
    assert!(!said.contains("slides past its grip"), "{said}");
}
