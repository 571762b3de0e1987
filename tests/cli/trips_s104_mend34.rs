//! Small defects the last stop noticed (session 104): a body roll logged
//! in degrees under 1° read as radians (up to 57°) and levelled `ay` by
//! it; an instant step's ay response time printed as the half interval
//! where the samples fall ("0.000 s"); a verdict's parameter a hair
//! inside its search bound not said to press on it.

use super::*;
use crate::trips_s90_met::{measured, tester_step, tester_step_at};
use std::f64::consts::PI;

/// The tester's step history (its first six columns) every 10 ms, its
/// body rolled by `phi(ay)` rad: `ay` as the rolled accelerometer reads
/// it, ay·cos φ + g·sin φ, and a `roll` column of φ times `unit` (1 for
/// radians, 180/π for degrees), written to `dir/name`.
fn with_roll(
    history: &Path,
    (dir, name): (&Path, &str),
    unit: f64,
    phi: impl Fn(f64) -> f64,
) -> PathBuf {
    let text = fs::read_to_string(history).unwrap();
    let mut out = String::from("t,steer,speed,beta,yaw_rate,ay,roll\n");
    for line in text.lines().skip(1).step_by(10) {
        let c: Vec<&str> = line.split(',').take(6).collect();
        let ay: f64 = c[5].parse().unwrap();
        let p = phi(ay);
        let read = ay * p.cos() + 9.80665 * p.sin();
        out.push_str(&format!("{},{read},{}\n", c[..5].join(","), p * unit));
    }
    written(dir, name, &out)
}

/// A car rolling 0.8° at the step's 1.40 m/s², logged in degrees: its
/// roll (0 to 0.8) passed the 1 rad size check, was read as up to 0.8 rad
/// (46°), and levelled `ay` by g·sin φ, 7 m/s², after which the
/// accelerometer was blamed ("disagrees with the speed times that of the
/// yaw rate"). Now body roll has its own plausibility, 0.2 rad (11.5°):
/// refused as degrees at its column, naming `--degrees roll`; so said,
/// the run is measured. A roll in radians of a soft car (0.05 rad, 2.9°)
/// is read as before.
#[test]
fn a_roll_logged_in_degrees_under_one_degree_is_refused_as_degrees() {
    let dir = tempfile::tempdir().unwrap();
    let history = tester_step(dir.path(), 0.1, "");
    // 0.8° at the steady ay of 1.40104 m/s².
    let phi = |ay: f64| 0.8f64.to_radians() * ay / 1.40104;
    let degrees = with_roll(&history, (dir.path(), "deg.csv"), 180.0 / PI, phi);
    let o = run(&["metrics", degrees.to_str().unwrap()]);
    assert!(
        !o.status.success(),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    let e = stderr(&o);
    assert!(
        e.contains("column `roll`: ") && e.contains("is beyond ±11°"),
        "{e}"
    );
    assert!(e.contains("`--degrees roll` to `metrics`"), "{e}");
    // Levelled by the roll as logged, `ay` is the body's again.
    let (j, w) = measured(&degrees, &["--degrees", "roll"]);
    let ay = j["ay_steady"].as_f64().unwrap_or(f64::NAN);
    assert!((ay - 1.40104).abs() < 2e-3, "{ay} {w}");
    let soft = |ay: f64| 0.05 * ay / 1.40104;
    let radians = with_roll(&history, (dir.path(), "rad.csv"), 1.0, soft);
    let (j, w) = measured(&radians, &[]);
    let ay = j["ay_steady"].as_f64().unwrap_or(f64::NAN);
    assert!((ay - 1.40104).abs() < 2e-3, "{ay} {w}");
}

/// The tester's car stepped instantly at 10 m/s, where the front tyres'
/// force at the step (2 × 57 296 N/rad × 0.01 rad over 1530 kg, 0.75
/// m/s²) is past 90 % of the steady ay (0.33 m/s²): logged at 1 kHz and
/// read unfiltered, `ay` is at 90 % at the first sample after the step,
/// and its response time read 0.0005 s (the half interval from the
/// steer's interpolated half-way point), said as "0.000 s". Now it is
/// below one sample interval, in the table, the JSON and the warning
/// alike; the yaw rate's, 0.13 s, is read as before.
#[test]
fn an_instant_steps_ay_response_time_is_said_below_one_sample_interval() {
    let dir = tempfile::tempdir().unwrap();
    let history = tester_step_at(dir.path(), 10.0, 0.0, "");
    let (j, w) = measured(&history, &["--filter-hz", "0"]);
    assert!(j["ay_response_time"].is_null(), "{j}");
    // The log's median interval, 0.001 s to round-off.
    let below = j["ay_response_time_below"].as_f64().unwrap_or(f64::NAN);
    assert!((below - 0.001).abs() < 1e-12, "{j}");
    let r = j["yaw_rate_response_time"].as_f64().unwrap();
    assert!((r - 0.13).abs() < 0.01, "{r}");
    assert!(
        w.contains("its response time is only known to be under 0.001 s"),
        "{w}"
    );
    assert!(!w.contains("the ay response time, 0.000 s"), "{w}");
    let o = run(&["metrics", history.to_str().unwrap(), "--filter-hz", "0"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let table = String::from_utf8_lossy(&o.stdout);
    let line = table
        .lines()
        .find(|l| l.contains("ay response time"))
        .unwrap_or_else(|| panic!("{table}"));
    assert!(line.trim_end().ends_with("< 0.001 s"), "{line}");
}

/// The racing log against the road prior, its gyro trusted to 0.003
/// rad/s: the verdict's sensor delay, 0.2991 ± 0.0165 s, stops a
/// thousandth of a second inside its 0.3 s search bound (the fit's own
/// tolerance), within its standard error of it, and was given as a
/// measurement. Now the verdict warns of it as of one on the bound, saying
/// how near, in the terminal and the JSON alike. One candidate keeps the
/// test short (the verdict is the full library's, 54.5 % removed, the
/// same delay).
#[test]
fn a_verdict_parameter_within_its_standard_error_of_its_search_bound_is_said_to_press_on_it() {
    let test =
        "a_verdict_parameter_within_its_standard_error_of_its_search_bound_is_said_to_press_on_it";
    let Some(log) = shared_data(test, "run_iac_putnam/putnam_run4_2.csv") else {
        return;
    };
    let text = putnam_campaign(&log, "effects = [\"sensor_delay\"]\nmax_effects = 1")
        .replace("class = \"racing_slick\"", "class = \"road\"")
        .replace("\nbeta = 0.005\n", "\nbeta = 0.005\nyaw_rate = 0.003\n");
    assert!(text.contains("yaw_rate = 0.003") && text.contains("class = \"road\""));
    let dir = scratch(&[("putnam.toml", &text)]);
    let (stdout, d) = diagnose_to(&dir.path().join("putnam.toml"), &dir.path().join("out"));
    let v = &d["verdict"];
    assert_eq!(v["effects"], serde_json::json!(["sensor_delay"]), "{v}");
    let delay = v["parameters"][0]["value"].as_f64().unwrap();
    assert!(delay > 0.29 && delay < 0.3, "{delay}");
    let said = "(its bound 0.3 s lies within its standard error, ";
    let warned: Vec<&str> = v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|w| w.as_str())
        .filter(|w| w.starts_with("sensor_delay.delay = 0.29") && w.contains(said))
        .collect();
    assert_eq!(warned.len(), 1, "{v}");
    assert!(
        warned[0].contains("s) on its search bound: the data would take it further"),
        "{}",
        warned[0]
    );
    assert!(
        stdout.contains(&format!("  warning: {}", warned[0])),
        "{}",
        without_temp_names(&stdout)
    );
}
