//! What a fresh user tripped on in the words of `metrics`, `simulate
//! --measured`, `diagnose` and `equilibria` (session 95): a
//! speed sample read with its sign flipped taken for a crawl that split
//! the run, a stretch reversing called a crawl, a gain error said as a
//! constant offset and a dynamic error at once, and an equilibria box of
//! ±1e9 rad/s searched without a word.

use super::*;
use crate::trips_s90_met::{measured, tester_step};
use crate::trips_s94_met::{on_grid, rewritten};

/// The tester's step (0.01 rad at 25 m/s at 1 s) logged at 100 Hz as
/// `dir/name`, its speed at time `t` s made `speed(t, u)`.
fn step_with_speed(dir: &Path, name: &str, speed: impl Fn(f64, f64) -> f64) -> PathBuf {
    let history = tester_step(dir, 0.1, "");
    rewritten(
        &history,
        dir,
        name,
        "t,speed,steer,yaw_rate,ay,beta",
        |c| on_grid(c, 10),
        // history: t, steer, speed, beta, yaw_rate, ay.
        |c| vec![c[0], speed(c[0], c[2]), c[1], c[4], c[5], c[3]],
    )
}

/// One speed sample read as −25 m/s among samples at +25 m/s (a logger's
/// sign glitch) was "crawl 5.00–5.00 s (1 sample, at most -25.00 m/s,
/// below min_speed = 5 m/s) excluded", the run split in two and its
/// second half dropped. No car reverses its 25 m/s within 0.01 s and
/// back (5,000 m/s² each way): it is a spike of the speed channel,
/// repaired, and the whole run is measured.
#[test]
fn a_speed_sample_with_its_sign_flipped_is_a_spike_not_a_crawl() {
    let dir = tempfile::tempdir().unwrap();
    let csv = step_with_speed(dir.path(), "flip.csv", |t, u| {
        if (t - 5.0).abs() < 1e-6 {
            -u
        } else {
            u
        }
    });
    let (j, w) = measured(&csv, &[]);
    let c = &j["cleaning"];
    assert_eq!(c["slow"].as_array().map(Vec::len), Some(0), "{c}");
    assert_eq!(c["samples_kept"], 901, "{c}");
    assert_eq!(c["counts"]["spike"], 1, "{c}");
    let g = &c["glitches"][0];
    assert_eq!(
        (&g["channel"], &g["kind"], &g["value"], &g["treatment"]),
        (
            &serde_json::json!("speed"),
            &serde_json::json!("spike"),
            &serde_json::json!(-25.0),
            &serde_json::json!("repaired")
        ),
        "{c}"
    );
    assert!(!w.contains("runs past the end"), "{w}");
    // The terminal says it as other spikes are said.
    let o = run(&["metrics", csv.to_str().unwrap()]);
    let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    assert!(
        said.contains("spike at 5.000 s in ")
            && said.contains("flip.csv: speed -25 (1 sample, repaired)"),
        "{said}"
    );
    assert!(!said.contains("crawl 5.00"), "{said}");
}

/// A stretch driven backwards (3 m/s from 6 s to the end) was "crawl
/// 6.00–9.00 s (301 samples, at most -3.00 m/s, below min_speed = 5
/// m/s)": a crawl is slow forwards. It is said as reversing, excluded
/// because the model drives forwards only, with its speed backwards.
#[test]
fn a_stretch_driven_backwards_is_said_as_reversing_not_a_crawl() {
    let dir = tempfile::tempdir().unwrap();
    let csv = step_with_speed(
        dir.path(),
        "rev.csv",
        |t, u| if t > 5.995 { -3.0 } else { u },
    );
    let (j, _) = measured(&csv, &[]);
    let slow = &j["cleaning"]["slow"];
    assert_eq!(slow.as_array().map(Vec::len), Some(1), "{slow}");
    assert_eq!(slow[0]["kind"], "reversing", "{slow}");
    assert_eq!(slow[0]["samples"], 301, "{slow}");
    assert_eq!(slow[0]["min_speed"], -3.0, "{slow}");
    let o = run(&["metrics", csv.to_str().unwrap()]);
    let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    assert!(
        said.contains("(0 standstill spans, 0 crawl spans and 1 reversing span)"),
        "{said}"
    );
    assert!(
        said.contains("rev.csv (301 samples, backwards at up to 3.00 m/s: the model drives forwards only, from min_speed = 5 m/s) excluded"),
        "{said}"
    );
    assert!(!said.contains("crawl 6.00"), "{said}");
}

/// The percentage in "the simulation reads X % of the measurement".
fn reads_percent(line: &str) -> f64 {
    line.split("the simulation reads ")
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{line}"))
}

/// The tester's step (front and rear 57 296 N/rad per wheel) logged at
/// 100 Hz with a quiet gyro (0.0005 rad/s of noise), replayed on a front
/// tyre 20 % soft: the yaw rate's residual is the measured yaw rate times
/// a constant, and was said as "mostly a constant offset … above the
/// noise floor" and, in the same line, "a dynamic error (gain, lag or
/// stiffness)". It is a gain error: the residual is a line through the
/// measured channel with no intercept, and its slope is the closed form's
/// ratio of the steady yaw-rate gains, u/(L + K·u²) with K = m/L·(b/C_f −
/// a/C_r): 4.4610 / 5.7142 = 78.07 %, within 0.5 points (the transient
/// and the noise). `ay`, noise-free, reads the same ratio.
#[test]
fn a_gain_error_is_said_as_one_not_as_an_offset_and_a_dynamic_error() {
    use super::sedan_runs::{run_text, Noisy};
    let dir = tempfile::tempdir().unwrap();
    let history = tester_step(dir.path(), 0.1, "");
    let noisy = Noisy {
        yaw: 0.0005,
        ay: 0.0,
        seed: 15,
        ay_gain: 1.0,
    };
    std::fs::write(
        dir.path().join("run.csv"),
        run_text(&history, 10, Some(noisy)),
    )
    .unwrap();
    std::fs::write(
        dir.path().join("soft.toml"),
        "model = \"linear\"\ncornering_stiffness = 45836.8\npneumatic_trail = 0.03\n",
    )
    .unwrap();
    let scenario = format!(
        "name = \"rep\"\n{VEHICLE}[tyres]\nfront = \"soft.toml\"\nrear = \"linear.toml\"\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n[manoeuvre]\nkind = \"replay\"\nrun = \"run.csv\"\n"
    );
    std::fs::write(dir.path().join("replay.toml"), scenario).unwrap();
    let o = run_in(dir.path(), &["simulate", "replay.toml", "--out", "rep"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout).to_string();
    let closed_form = 100.0 * 4.4610 / 5.7142;
    for channel in ["  yaw_rate:", "  ay:"] {
        let line = said
            .lines()
            .find(|l| l.starts_with(channel))
            .unwrap_or_else(|| panic!("{said}"));
        assert!(
            line.contains("the gap grows with the response, not a constant offset")
                && line.contains("a gain error"),
            "{line}"
        );
        assert!(!line.contains("mostly a constant offset"), "{line}");
        assert!(!line.contains("a dynamic error (gain"), "{line}");
        let percent = reads_percent(line);
        assert!((percent - closed_form).abs() < 0.5, "{percent}: {line}");
    }
}

/// The bundled speed sweep (simplified Magic Formula, μ_peak = D = 1,
/// friction 0.8, 30 to 120 km/h) with `[box] yaw_rate_max = value`, run
/// by `equilibria` in a scratch folder: whether it ran, what it said and
/// the line of the key.
fn swept_with_yaw_box(value: &str) -> (bool, String, usize) {
    let text = format!(
        "{}\n[box]\nyaw_rate_max = {value}\n",
        bundled_scenario("equilibria_speed.toml")
    );
    let line = text.lines().count();
    let dir = scratch(&[("sweep.toml", &text)]);
    let o = run_in(dir.path(), &["equilibria", "sweep.toml", "--out", "out"]);
    let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    (o.status.success(), said, line)
}

/// `[box] yaw_rate_max = 1e9` searched a box of ±1e9 rad/s without a
/// word. No equilibrium turns faster than μ_peak·μ·g/u_min (steady,
/// m·u·r is the tyres' force): 1 × 0.8 × 9.80665 / 8.3333 = 0.9414 rad/s
/// here, and a box over ten times that is refused at its line, with the
/// bound; 60 (deg/s where rad/s is read) is asked about as 1.047 rad/s;
/// 5 rad/s, inside, runs.
#[test]
fn an_equilibria_box_beyond_any_steady_yaw_rate_is_refused_at_its_line() {
    let (ran, said, line) = swept_with_yaw_box("1e9");
    assert!(!ran, "{said}");
    assert!(
        said.contains(&format!("sweep.toml:{line}:"))
            && said.contains("`box.yaw_rate_max`")
            && said.contains("must lie in (0, 9.414] rad/s")
            && said.contains("μ_peak·μ·g/u_min = 0.9414 rad/s"),
        "{said}"
    );
    assert!(!said.contains("did you mean"), "{said}");
    let (ran, said, _) = swept_with_yaw_box("60");
    assert!(!ran, "{said}");
    assert!(
        said.contains("did you mean 1.047 rad/s (60 deg/s)?"),
        "{said}"
    );
    let (ran, said, _) = swept_with_yaw_box("5");
    assert!(ran, "{said}");
}
