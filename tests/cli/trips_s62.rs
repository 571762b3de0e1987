//! What a fresh-eyes user still tripped on, run as a user runs
//! the tool: `tyre-eval`'s count of the points at rest and its silence on
//! a slip there, a point named by its index where every other warning
//! names its line, a pressure said as given but not as evaluated, a
//! rolling resistance moment of −1.5e-17 N·m written at 1e-9 m/s;
//! `metrics` calling a smooth simulated channel held and its own filter's
//! ringing an overshoot, and taking `--degrees roll`, a column it does not
//! read, without a word; a `rise_time` at the bound the book states
//! refused; and `identify`'s word on a skipped Mx stage. Each test one
//! finding.

use super::*;
use crate::trips_run_units::metrics;
use crate::tyre_eval::mf61;

/// `tyre-eval` of `tyre` at the points `csv`, written to `dir`: whether it
/// succeeded, its stderr and the CSV it wrote.
fn tyre_eval(dir: &Path, tyre: &Path, csv: &str) -> (bool, String, String) {
    let (o, written) = crate::tyre_eval::eval(dir, tyre, csv, &[]);
    (o.status.success(), stderr(&o), written)
}

/// The cells of column `name` of a written CSV, as written.
fn cells(csv: &str, name: &str) -> Vec<String> {
    let mut lines = csv.lines();
    let at = lines
        .next()
        .unwrap()
        .split(',')
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("no {name}: {csv}"));
    lines
        .map(|l| l.split(',').nth(at).unwrap().to_string())
        .collect()
}

/// Four points at speed 0 were said as "1 of 4 points at zero speed" (the
/// one with a slip angle, whose `mz` lacks its trail), and the one at
/// κ = 0.05, evaluated to fx = 4010 N, a force no standing tyre has, got
/// no word: every point at rest is counted, and those with a slip are said
/// apart, with what was evaluated there.
#[test]
fn a_zero_speed_warning_counts_every_row_at_rest_and_says_a_slip_there_apart() {
    let dir = tempfile::tempdir().unwrap();
    let tir = mf61(dir.path(), &[]);
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0,0,20\n4000,0.05,0,0,0\n4000,0,0.05,0,0\n4000,0,0,0,0\n4000,0,0,0,0\n";
    let (ok, e, written) = tyre_eval(dir.path(), &tir, points);
    assert!(ok, "{e}");
    assert!(
        e.contains("warning: 4 of 5 points at zero speed (below 0.0001 m/s), 2 of them at a slip ratio or slip angle ≠ 0 (the first at line 3: kappa = 0.05, alpha = 0 rad, evaluated to fx = 4010 N, fy = 90.97 N): a slip at zero speed is not a physical state"),
        "{e}"
    );
    assert!(
        e.contains("what was evaluated is the model's steady-state force of a wheel rolling at that slip, its vertical shifts and `my` faded to 0 (linearly below VXLOW = 1 m/s), not a standing tyre's"),
        "{e}"
    );
    // The aligning moment's word counts against the same points at rest.
    assert!(
        e.contains("warning: 1 of the 4 points at zero speed (below 0.0001 m/s) has a slip angle ≠ 0: mz there is the residual torque alone"),
        "{e}"
    );
    assert!(!e.contains("1 of 5 points at zero speed"), "{e}");
    let fx: Vec<f64> = cells(&written, "fx")
        .iter()
        .map(|c| c.parse().unwrap())
        .collect();
    assert!((fx[1] - 4010.0).abs() < 1.0, "{fx:?}");
    // At rest without a slip, a standing tyre: nothing of the kind to say.
    let (ok, e, _) = tyre_eval(
        dir.path(),
        &tir,
        "fz,kappa,alpha,camber,speed\n4000,0,0,0,0\n4000,0,0,0,20\n",
    );
    assert!(ok && !e.contains("not a physical state"), "{e}");
}

/// A negative cornering stiffness's warning said "the first, point 22"
/// where every other warning names the line of the points file; a
/// pressure of 2 MPa beyond PRESMAX was quoted as given, not as the
/// PRESMAX it was evaluated at: both said now.
#[test]
fn tyre_eval_names_every_point_by_its_line_and_a_clamped_pressure_as_given_and_evaluated() {
    let dir = tempfile::tempdir().unwrap();
    // PPY1 = −3: the cornering stiffness is negative above a third of
    // NOMPRES over it.
    let tir = mf61(dir.path(), &[("PPY1", "-3.0")]);
    let points = "fz,kappa,alpha,camber,speed,pressure\n4000,0,0.05,0,20,260000\n4000,0,0.05,0,20,380000\n4000,0,0.05,0,20,2000000\n";
    let (ok, e, _) = tyre_eval(dir.path(), &tir, points);
    assert!(ok, "{e}");
    assert!(
        e.contains("a negative cornering stiffness at their own load, camber, pressure and speed (the first at line 3: fz = 4000 N, camber = 0 rad, pressure = 380000 Pa)"),
        "{e}"
    );
    assert!(!e.contains("point 2") && !e.contains("point 3"), "{e}");
    assert!(
        e.contains("warning: 1 of 3 points above PRESMAX = 400000 Pa (the file's range 200000 to 400000): evaluated at that end; the first at line 4, pressure = 2000000 Pa given, evaluated at 400000 Pa"),
        "{e}"
    );
}

/// `tyre-eval` wrote `my = -1.5e-17` at 1e-9 m/s: the low-speed fade's
/// last digits, not a moment. Written as 0; a moment the model resolves
/// (at 1 mm/s and above) as before, and nothing written is non-finite.
#[test]
fn a_rolling_resistance_moment_of_round_off_at_a_crawl_is_written_as_zero() {
    let dir = tempfile::tempdir().unwrap();
    let tir = mf61(dir.path(), &[]);
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0,0,1e-9\n4000,0.01,0.02,0,1e-9\n4000,0,0,0,0\n4000,0,0,0,0.001\n4000,0,0,0,20\n";
    let (ok, e, written) = tyre_eval(dir.path(), &tir, points);
    assert!(ok, "{e}");
    let my = cells(&written, "my");
    assert_eq!(&my[..3], ["0", "0", "0"], "{written}");
    let value = |c: &String| c.parse::<f64>().unwrap();
    assert!(value(&my[3]) < 0.0 && value(&my[3]) > -1e-3, "{written}");
    assert!(value(&my[4]) < -10.0, "{written}");
    for line in written.lines().skip(1) {
        for c in line.split(',') {
            assert!(c.parse::<f64>().unwrap().is_finite(), "{line}");
        }
    }
}

/// A step at 1 m/s logged at 1 kHz (`simulate`'s history): `metrics` said
/// "held: beta … updates every 2 samples (431.8 Hz)" of a smooth channel
/// whose last written digit repeats now and then, and a yaw-rate peak of
/// 1.15 % at 0.089 s that its own 10 Hz low-pass made, where `simulate`
/// measured no overshoot. Neither now.
#[test]
fn metrics_on_a_crawl_calls_no_smooth_channel_held_and_no_filter_ringing_a_peak() {
    let text = bundled_scenario("step_gbt6323_pac89.toml");
    let crawl = text
        .replace("speed = 22.2222 ", "speed = 1.0 ")
        .replace("lateral_acceleration = 2.0 ", "steer = 0.0174533 ");
    assert!(
        crawl.contains("speed = 1.0 ")
            && crawl.contains("steer = 0.0174533 ")
            && crawl.contains("step = 0.001 "),
        "{crawl}"
    );
    let dir = scratch(&[("scenario.toml", &crawl)]);
    let (ok, said, e) = crate::trips_simulate::simulated(dir.path());
    assert!(ok, "{e}");
    assert!(
        said.contains("yaw-rate overshoot              < 1 %"),
        "{said}"
    );
    let history = dir.path().join("out/history.csv");
    let (ok, table, e) = metrics(&history, &["--min-speed", "0.5"]);
    assert!(ok, "{e}");
    assert!(!e.contains("updates every") && !e.contains("held:"), "{e}");
    assert!(
        table.contains("yaw-rate peak time                — s"),
        "{table}"
    );
    assert!(
        table.contains("the low-pass alone lifts the steer step by: a maximum within that is the filter ringing, not the car"),
        "{table}"
    );
    let o = run(&[
        "metrics",
        history.to_str().unwrap(),
        "--min-speed",
        "0.5",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let m: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(m["yaw_rate_peak_time"].is_null(), "{m}");
    assert!(m["cleaning"]["held"].as_array().unwrap().is_empty(), "{m}");
    let ringing = m["yaw_rate_filter_ringing"].as_f64().unwrap();
    assert!(ringing > 1.0 && ringing < 2.0, "{m}");
    assert!(
        m["yaw_rate_peak_threshold"].as_f64().unwrap() >= ringing,
        "{m}"
    );
    // Unfiltered, there is no ringing to allow for.
    let (ok, table, e) = metrics(&history, &["--min-speed", "0.5", "--filter-hz", "0"]);
    assert!(ok, "{e}");
    assert!(
        table.contains(
            "(the larger of min_overshoot and what the noise and the steady scatter allow)"
        ),
        "{table}"
    );
}

/// A 100 Hz step at 20 m/s with a `roll` column.
fn run_with_roll() -> String {
    let mut s = String::from("t,speed,steer,yaw_rate,ay,roll\n");
    for i in 0..=600 {
        let t = f64::from(i) / 100.0;
        let r = if t > 1.0 {
            0.2 * (1.0 - (-(t - 1.0) / 0.15).exp())
        } else {
            0.0
        };
        let steer = if t > 1.0 { 0.02 } else { 0.0 };
        s += &format!("{t:.2},20,{steer},{r:.6},{:.6},1.5\n", 20.0 * r);
    }
    s
}

/// `metrics --degrees roll` was taken without a word, though `metrics`
/// read no roll: the declaration converted nothing. A column `metrics`
/// does not read (`bank`) is refused, as a column the file lacks is, with
/// the angle columns `metrics` reads (`roll` among them since it levels
/// `ay` by it).
#[test]
fn metrics_refuses_a_degrees_column_it_does_not_read_with_the_columns_it_reads() {
    let dir = scratch(&[("run.csv", &run_with_roll())]);
    let p = dir.path().join("run.csv");
    let (ok, _, e) = metrics(&p, &["--degrees", "bank"]);
    assert!(!ok);
    assert!(
        e.contains("invalid value 'bank' for '--degrees <DEGREES>': not an angle column `metrics` reads: one of steer, yaw_rate, beta, roll"),
        "{e}"
    );
    // A misspelt one is offered only the columns metrics reads.
    let (ok, _, e) = metrics(&p, &["--degrees", "steeer"]);
    assert!(!ok);
    assert!(
        e.contains("(did you mean `steer`?): one of steer, yaw_rate, beta, roll"),
        "{e}"
    );
    // The roll it reads, 1.5 throughout: beyond ±57° read as radians,
    // refused naming `--degrees roll`, which reads it.
    let (ok, _, e) = metrics(&p, &[]);
    assert!(!ok && e.contains("`--degrees roll` to `metrics`"), "{e}");
    let (ok, _, e) = metrics(&p, &["--degrees", "roll"]);
    assert!(ok, "{e}");
}

/// `rise_time = 0.1875` was refused ("must lie in [0, 0.1875]") though
/// the book says "at most 0.1875 s": `0.15 / 0.8` is 0.18749999999999997
/// in floating point. The bound is inclusive at the number the book states.
#[test]
fn a_rise_time_at_the_books_bound_runs_and_one_just_above_is_refused() {
    let book = fs::read_to_string(root().join("docs/src/simulate.md")).unwrap();
    assert!(
        book.contains("`rise_time` (at most 0.1875 s"),
        "the book changed"
    );
    let text = bundled_scenario("sedan_step.toml");
    assert!(text.contains("rise_time = 0.1\n"), "{text}");
    let with = |rise: &str| text.replace("rise_time = 0.1\n", &format!("rise_time = {rise}\n"));
    let dir = scratch(&[("scenario.toml", &with("0.1875"))]);
    let (ok, _, e) = crate::trips_simulate::simulated(dir.path());
    assert!(ok, "{e}");
    // Its 10–90 % rise is ISO 7401's 0.15 s, not said to exceed it.
    let (ok, _, e) = metrics(&dir.path().join("out/history.csv"), &[]);
    assert!(ok && !e.contains("ISO 7401 asks for at most"), "{e}");
    let dir = scratch(&[("scenario.toml", &with("0.18751"))]);
    let e = simulate_err(dir.path());
    assert!(
        e.contains("`manoeuvre.rise_time` = 0.18751: must lie in [0, 0.1875]"),
        "{e}"
    );
}

/// A lateral rig file with cornering data at three loads, each row as
/// `row` writes it from (load, slip angle, lateral force).
pub(crate) fn rig(columns: &str, row: fn(f64, f64, f64) -> String) -> String {
    let mut s = format!("{columns}\n");
    for fz in [2000.0, 4000.0, 6000.0] {
        for k in -10..=10 {
            let alpha = 0.02 * f64::from(k);
            let fy = fz * (1.4 * (12.0 * alpha).atan()).sin();
            s += &row(fz, alpha, fy);
            s += "\n";
        }
    }
    s
}

/// `identify` said "Mx skipped: no rows with a measured `mx` (column
/// `mx`, in a file with `kappa` and `fx`)" of a file that has an `mx`
/// column: it now says what is missing and what to give, and a file so
/// given fits the stage.
#[test]
fn identify_says_what_a_skipped_mx_stage_lacks_and_what_to_give() {
    let lateral = rig("fz,alpha,fy,mz,mx", |fz, a, fy| {
        format!("{fz},{a},{fy:.3},{:.4},{:.4}", 0.02 * fy, -0.01 * fy)
    });
    let with_kappa = rig("fz,kappa,alpha,fx,fy,mz,mx", |fz, a, fy| {
        format!("{fz},0,{a},0,{fy:.3},{:.4},{:.4}", 0.02 * fy, -0.01 * fy)
    });
    let dir = scratch(&[("lateral.csv", &lateral), ("kappa.csv", &with_kappa)]);
    let o = identify_to(
        &dir.path().join("lateral.csv"),
        "mf61",
        &dir.path().join("a.tir"),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("  Mx           skipped: no rows with a measured `mx`: `mx` is fitted only from a rig file with `mx`, `kappa` and `fx` columns, whose samples are its rows (a file without `kappa` and `fx` is averaged into slip-angle bins of `fy` and `mz`, and its `mx` left out); to fit it, give `mx` in a file with `kappa` and `fx` (on a cornering sweep, `kappa` = 0 and the rig's measured `fx`)"),
        "{said}"
    );
    assert!(!said.contains("in a file with `kappa` and `fx`)"), "{said}");
    // Given as said, the stage is fitted.
    let o = identify_to(
        &dir.path().join("kappa.csv"),
        "mf61",
        &dir.path().join("k.tir"),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(said.contains("  Mx              63 points"), "{said}");
}
