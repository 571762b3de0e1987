//! `metrics` on measured runs, fresh-eyes round 50 (session 114): one
//! absurd steer cell (`1e308`) is refused at its cell with the limit, not
//! said as a steer that "does not hold its step … at inf %"; a step logged
//! as a steering-wheel angle is warned of at any steady ay in the words
//! and figure `diagnose` refuses it with; a run that starts with sideslip
//! says its steady sideslip is a change, in the words `simulate` uses; a
//! header's name is read with its unit whatever its case and separators
//! (`Yaw Rate [deg/s]`).

use super::*;

/// The speed of the logged step, m/s (100 km/h).
const SPEED: f64 = 27.7778;

/// Its steady lateral acceleration, m/s².
const STEADY_AY: f64 = 6.0;

/// The road-wheel steer step, rad: a car of 2.78 m wheelbase turning at
/// 0.88 of a neutral car's yaw rate (`r·l/(u·δ)`).
const ROAD_WHEEL_STEP: f64 = 0.0246;

/// The steering ratio of a steering-wheel angle logged as the steer.
const STEERING_RATIO: f64 = 15.0;

/// A 100 km/h step steer as a logger writes it: 100 Hz for 9 s, the steer
/// ramped over 0.1 s from 3 s to `step` (rad), the yaw rate, `ay` and
/// `beta` a damped second-order response (1.2 Hz, ζ = 0.7) to a steady
/// ay of `ay` (m/s²), `beta` from `beta0` to `beta0 − 0.01·ay/6` rad, with
/// a fixed pseudo-random noise; `yaw_scale` multiplies the yaw rate (deg/s
/// for 180/π). Header `t,speed,steer,<yaw>,ay,beta`.
fn step_log(step: f64, ay: f64, beta0: f64, (yaw, yaw_scale): (&str, f64)) -> String {
    let r_ss = ay / SPEED;
    let (w, zeta): (f64, f64) = (2.0 * std::f64::consts::PI * 1.2, 0.7);
    let shape = |tau: f64| damped_step(w, zeta, tau);
    let mut noise = lcg_noise(12345);
    let mut s = format!("t,speed,steer,{yaw},ay,beta\n");
    for i in 0..=900 {
        let t = f64::from(i) * 0.01;
        let steer = step * ((t - 3.0) / 0.1).clamp(0.0, 1.0);
        let r = r_ss * shape(t - 3.05) + noise(0.004);
        let a = ay * shape(t - 3.1) + noise(0.06);
        let b = beta0 - 0.01 * ay / 6.0 * shape(t - 3.15) + noise(0.0002);
        s += &format!(
            "{t:.2},{SPEED},{steer:.6},{:.6},{a:.5},{b:.7}\n",
            r * yaw_scale
        );
    }
    s
}

/// The value of the table row `label` of `metrics`' stdout.
fn row(out: &str, label: &str) -> f64 {
    let line = out
        .lines()
        .find(|l| l.trim_start().starts_with(label))
        .unwrap_or_else(|| panic!("no row {label}: {out}"));
    let value = line.trim_start()[label.len()..].split_whitespace().next();
    value.unwrap().parse().unwrap_or_else(|_| panic!("{line}"))
}

#[test]
fn one_absurd_steer_cell_is_refused_at_its_cell_and_a_spike_below_it_repaired() {
    let log = step_log(ROAD_WHEEL_STEP, STEADY_AY, 0.0, ("yaw_rate", 1.0));
    // Line 600 is t = 5.98 s, after the step.
    let dir = scratch(&[
        ("good.csv", &log),
        ("huge.csv", &with_cell(&log, 600, 3, "1e308")),
        ("spike.csv", &with_cell(&log, 600, 3, "10")),
    ]);
    for args in [&[][..], &["--filter-hz", "0"][..]] {
        let (ok, _, e) = metrics_in(dir.path(), "huge.csv", args);
        assert!(!ok, "{e}");
        assert!(
            e.contains("error: huge.csv:600:3: column `steer`: 1e308 rad is beyond ±10000 rad, which no steer sensor logs in any unit a steer is written in"),
            "{e}"
        );
        assert!(e.contains("mend or remove this row"), "{e}");
        assert!(!e.contains("inf") && !e.contains("NaN"), "{e}");
    }
    // A lone spike below the limit is the cleaning's to repair, and the
    // step is measured as the clean log's.
    let (ok, out, e) = metrics_in(dir.path(), "spike.csv", &[]);
    assert!(ok, "{e}");
    assert!(
        e.contains("cleaning: spike at 5.980 s in spike.csv: steer 10 (1 sample, repaired)"),
        "{e}"
    );
    let (ok, good, e) = metrics_in(dir.path(), "good.csv", &[]);
    assert!(ok, "{e}");
    assert_eq!(row(&out, "steer step"), row(&good, "steer step"));
    assert_eq!(row(&out, "yaw-rate gain"), row(&good, "yaw-rate gain"));
}

#[test]
fn a_steering_wheel_angle_is_warned_of_at_any_ay_in_diagnose_s_words() {
    let wheel = ROAD_WHEEL_STEP * STEERING_RATIO;
    let dir = scratch(&[
        (
            "swa.csv",
            &step_log(wheel, STEADY_AY, 0.0, ("yaw_rate", 1.0)),
        ),
        (
            "swa2.csv",
            &step_log(wheel / 3.0, 2.0, 0.0, ("yaw_rate", 1.0)),
        ),
        (
            "road.csv",
            &step_log(ROAD_WHEEL_STEP, STEADY_AY, 0.0, ("yaw_rate", 1.0)),
        ),
    ]);
    for (file, plough) in [
        (
            "swa.csv",
            "only a car ploughing on sliding front tyres turns so little for its steer",
        ),
        (
            "swa2.csv",
            "no car understeers so much at a steady ay under 4 m/s²",
        ),
    ] {
        let (ok, out, e) = metrics_in(dir.path(), file, &[]);
        assert!(ok, "{e}");
        // The figure, from the table's own gain and the log's speed with
        // the longest wheelbase, 5 m: about 0.1 (a 15:1 steer on a car
        // at 0.88 of a neutral 2.78 m car's rate, 5/2.78 × 0.88 / 15).
        let ratio = row(&out, "yaw-rate gain") * 5.0 / SPEED;
        assert!((0.1..0.15).contains(&ratio), "{ratio}");
        let figure = format!(
            "({:.1}× smaller, steady r·l/(u·δ) = {ratio:.3}: the yaw-rate gain",
            1.0 / ratio
        );
        let w = e
            .lines()
            .find(|l| l.starts_with("warning: the yaw rate is far smaller than a neutral car's for the steer even with l = 5 m, longer than any car's wheelbase"))
            .unwrap_or_else(|| panic!("{e}"));
        assert!(w.contains(&figure), "{figure}\n{w}");
        // `diagnose`'s question, and its rule named.
        assert!(
            w.contains("is `steer` in degrees (57×) or a steering-wheel angle (divide by the steering ratio)?"),
            "{w}"
        );
        assert!(w.contains(plough), "{w}");
        assert!(
            w.contains("`diagnose`, which knows the wheelbase, refuses a run below 0.1 with it"),
            "{w}"
        );
    }
    // The road-wheel angle of the same car: no word of it.
    let (ok, _, e) = metrics_in(dir.path(), "road.csv", &[]);
    assert!(ok, "{e}");
    assert!(!e.contains("far smaller than a neutral car's"), "{e}");
}

#[test]
fn a_run_that_starts_with_sideslip_says_its_steady_sideslip_is_the_change() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("example");
    let scenario = root().join("scenarios/step_gbt6323_pac89.toml");
    let o = run(&[
        "simulate",
        scenario.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let phrase = "the steady sideslip is its change from the 0.0513° the run holds before the step";
    let said = String::from_utf8_lossy(&o.stdout).into_owned() + &stderr(&o);
    assert!(said.contains(&format!("({phrase})")), "{said}");
    // The history's own sideslip, first and last, in degrees: the
    // independent reference of the line `metrics` prints.
    let history = fs::read_to_string(out.join("history.csv")).unwrap();
    let k = history
        .lines()
        .next()
        .unwrap()
        .split(',')
        .position(|c| c == "beta")
        .unwrap();
    let beta: Vec<f64> = history
        .lines()
        .skip(1)
        .map(|l| {
            l.split(',')
                .nth(k)
                .unwrap()
                .parse::<f64>()
                .unwrap()
                .to_degrees()
        })
        .collect();
    let (first, last) = (beta[0], beta[beta.len() - 1]);
    assert_eq!(format!("{first:.4}"), "0.0513");
    let (ok, table, e) = metrics_in(dir.path(), "example/history.csv", &["--filter-hz", "0"]);
    assert!(ok, "{e}");
    let line = format!("  sideslip: {phrase}, to {last:.4}° over the steady window");
    assert!(table.contains(&line), "{line}\n{table}");
    // The row is that change, start to end, to the table's rounding.
    let change = row(&table, "steady sideslip");
    assert!(
        (first + change - last).abs() < 2e-4,
        "{first} {change} {last}"
    );

    // A run that starts at zero sideslip has no such line.
    let log = step_log(ROAD_WHEEL_STEP, STEADY_AY, 0.0, ("yaw_rate", 1.0));
    fs::write(dir.path().join("zero.csv"), log).unwrap();
    let (ok, table, e) = metrics_in(dir.path(), "zero.csv", &[]);
    assert!(ok, "{e}");
    assert!(!table.contains("  sideslip:"), "{table}");
    // A logged sideslip offset of 0.3° is said, with the log's own start.
    let log = step_log(
        ROAD_WHEEL_STEP,
        STEADY_AY,
        0.3_f64.to_radians(),
        ("yaw_rate", 1.0),
    );
    fs::write(dir.path().join("offset.csv"), log).unwrap();
    let (ok, table, e) = metrics_in(dir.path(), "offset.csv", &[]);
    assert!(ok, "{e}");
    assert!(
        table.contains("  sideslip: the steady sideslip is its change from the 0.3"),
        "{table}"
    );
}

#[test]
fn a_header_name_with_spaces_and_capitals_gets_its_unit_advice() {
    let deg = 180.0 / std::f64::consts::PI;
    let dir = scratch(&[
        (
            "units.csv",
            &step_log(ROAD_WHEEL_STEP, STEADY_AY, 0.0, ("Yaw Rate [deg/s]", deg)),
        ),
        (
            "renamed.csv",
            &step_log(ROAD_WHEEL_STEP, STEADY_AY, 0.0, ("yaw_rate", deg)),
        ),
        (
            "rad.csv",
            &step_log(ROAD_WHEEL_STEP, STEADY_AY, 0.0, ("yaw_rate", 1.0)),
        ),
    ]);
    let (ok, _, e) = metrics_in(dir.path(), "units.csv", &[]);
    assert!(!ok, "{e}");
    assert!(
        e.contains("error: units.csv:1:4: column `Yaw Rate [deg/s]` is `yaw_rate` in deg/s, and `yaw_rate` is read in rad/s (FORMATS.md): name the column `yaw_rate` and declare it in degrees: `--degrees yaw_rate` to `metrics`"),
        "{e}"
    );
    // Not a renaming alone, which would read the deg/s as rad/s.
    assert!(!e.contains("did you mean"), "{e}");
    // Done as advised, the step reads as the log in rad/s does.
    let (ok, advised, e) = metrics_in(dir.path(), "renamed.csv", &["--degrees", "yaw_rate"]);
    assert!(ok, "{e}");
    let (ok, rad, e) = metrics_in(dir.path(), "rad.csv", &[]);
    assert!(ok, "{e}");
    let gain = row(&rad, "yaw-rate gain");
    assert!(
        (row(&advised, "yaw-rate gain") - gain).abs() <= 1e-4 * gain,
        "{advised}\n{rad}"
    );
}
