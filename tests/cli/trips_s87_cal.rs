//! What a user still tripped on in the calibration and the units of
//! measured runs: a 1 Hz slalom is no calibration straight; a
//! `[channels]` uncertainty far above the channel's own scatter is said; a
//! bank column in degrees is refused.

use super::*;

use super::calibration::Noise;

/// Yaw-rate and ay offsets the logs carry.
const OFFSETS: [f64; 2] = [0.004, -0.6];

/// A log at 100 Hz: parked 15 s, off to 20 m/s in 4 s, then to 60 s either
/// straight (`slalom` 0) or a slalom with the steer `slalom·sin(2π·1 Hz·t)`
/// rad. The yaw rate follows the steady-state gain `u/(L + K·u²)` with a
/// 0.15 s lag, ay = u·r, sideslip 0.1·steer; offsets [`OFFSETS`] and white
/// noise (0.002 rad/s, 0.05 m/s², 0.001 rad) on top.
fn log(seed: u64, slalom: f64) -> String {
    let mut noise = Noise(seed);
    let mut s = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    let mut r = 0.0;
    for i in 0..6000 {
        let t = i as f64 * 0.01;
        let u = (5.0 * (t - 15.0)).clamp(0.0, 20.0);
        let steer = if t > 19.0 {
            slalom * (std::f64::consts::TAU * t).sin()
        } else {
            0.0
        };
        r += (u * steer / (2.78 + 0.0025 * u * u) - r) * (1.0 - (-0.01f64 / 0.15).exp());
        s += &format!(
            "{t:.2},{u:.4},{steer:.5},{:.6},{:.5},{:.6}\n",
            r + OFFSETS[0] + 0.002 * noise.gauss(),
            u * r + OFFSETS[1] + 0.05 * noise.gauss(),
            0.1 * steer - 0.01 + 0.001 * noise.gauss()
        );
    }
    s
}

/// A campaign (linear tyres, the sensor-bias effect only) with `runs`.
fn campaign(runs: &[(&str, String)]) -> tempfile::TempDir {
    let v = format!(
        "{VEHICLE}\n[tyres]\nfile = \"tyre.toml\"\n\n[diagnose]\neffects = [\"sensor_bias\"]\n"
    );
    let dir = scratch(&[("vehicle.toml", &v)]);
    linear_tyre(dir.path());
    fs::create_dir(dir.path().join("runs")).unwrap();
    for (name, text) in runs {
        fs::write(dir.path().join("runs").join(name), text).unwrap();
    }
    dir
}

/// The calibration spans of `kind` in `run` (a file name).
fn spans<'a>(d: &'a serde_json::Value, run: &str, kind: &str) -> Vec<&'a serde_json::Value> {
    d["calibration"]["spans"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["kind"] == kind && s["run"].as_str().unwrap().ends_with(run))
        .collect()
}

#[test]
fn a_one_hertz_slalom_is_no_calibration_straight() {
    // slalom.csv weaves at 1 Hz with ±0.01 rad of steer (±0.039 rad/s of
    // yaw rate, ±0.77 m/s² of ay at 20 m/s) from 19 s on: its 1 s running
    // medians of steer and yaw rate are near 0, so it passed as a 37 s
    // straight and its means were offsets. straight.csv drives straight.
    let dir = campaign(&[("slalom.csv", log(1, 0.01)), ("straight.csv", log(2, 0.0))]);
    let (stdout, d) = diagnose(dir.path());
    assert_eq!(
        spans(&d, "slalom.csv", "straight").len(),
        0,
        "{}",
        d["calibration"]
    );
    assert_eq!(spans(&d, "slalom.csv", "standstill").len(), 1);
    assert_eq!(
        spans(&d, "straight.csv", "straight").len(),
        1,
        "{}",
        d["calibration"]
    );
    assert_eq!(spans(&d, "straight.csv", "standstill").len(), 1);
    // Refused, and why: the raw steer's RMS beyond its noise is the sine's,
    // 0.01/√2 = 0.0071 rad; the yaw rate's 0.01·5.29 (the steady gain at
    // 20 m/s) ·0.728 (the 0.15 s lag at 1 Hz, 1/√(1 + (2π·0.15)²)) /√2 =
    // 0.027 rad/s.
    let rejected = d["calibration"]["rejected"].as_array().unwrap();
    assert_eq!(rejected.len(), 1, "{rejected:?}");
    let reasons = rejected[0]["reasons"].as_array().unwrap();
    assert_eq!(reasons[0]["reason"], "steer_swings", "{reasons:?}");
    let steer = reasons[0]["rms"].as_f64().unwrap();
    assert!((steer / (0.01 / 2f64.sqrt()) - 1.0).abs() < 0.03, "{steer}");
    assert_eq!(reasons[0]["limit"], 0.005);
    assert_eq!(reasons[1]["reason"], "yaw_rate_swings", "{reasons:?}");
    let yaw = reasons[1]["rms"].as_f64().unwrap();
    let gain = 20.0 / (2.78 + 0.0025 * 400.0);
    let lag = 1.0 / (1.0 + (std::f64::consts::TAU * 0.15f64).powi(2)).sqrt();
    assert!(
        (yaw / (0.01 * gain * lag / 2f64.sqrt()) - 1.0).abs() < 0.03,
        "{yaw}"
    );
    let refused = stdout
        .lines()
        .find(|l| l.contains("candidate straight(s) refused"))
        .unwrap_or_else(|| panic!("{stdout}"));
    assert!(
        refused.contains("slalom.csv")
            && refused
                .contains("the steer swings by 0.0071 rad RMS beyond its noise (limit 0.0050"),
        "{refused}"
    );
    // The straights' offsets come from straight.csv alone: one straight.
    let ay = stdout
        .lines()
        .find(|l| l.starts_with("  calibration: ay"))
        .unwrap_or_else(|| panic!("{stdout}"));
    assert!(ay.contains(" on 1 straight ("), "{ay}");
}

/// A log at 100 Hz on a road banked by `bank` rad (throughout, or when
/// `parked_only` while parked, easing to 0 over the 4 s the car drives
/// off), the `bank` column holding `logged` times the bank over `bank` (the
/// same bank in another unit, or not): parked
/// 15 s, off to 20 m/s in 4 s, straight to 35 s, a 0.02 rad step steer to
/// 45 s, straight to 60 s. ay = u·r + g·sin(bank) + the offset -0.6 m/s²;
/// the yaw-rate offset 0.004 rad/s; white noise as [`log`].
fn banked_log(seed: u64, bank: f64, logged: f64, parked_only: bool) -> String {
    let mut noise = Noise(seed);
    let mut s = String::from("t,speed,steer,yaw_rate,ay,beta,bank\n");
    let mut r = 0.0;
    for i in 0..6000 {
        let t = i as f64 * 0.01;
        let u = (5.0 * (t - 15.0)).clamp(0.0, 20.0);
        let steer = if (35.0..45.0).contains(&t) { 0.02 } else { 0.0 };
        let easing = match parked_only {
            true => (1.0 - (t - 15.0) / 4.0).clamp(0.0, 1.0),
            false => 1.0,
        };
        let (bank, logged) = (bank * easing, logged * easing);
        r += (u * steer / (2.78 + 0.0025 * u * u) - r) * (1.0 - (-0.01f64 / 0.15).exp());
        s += &format!(
            "{t:.2},{u:.4},{steer:.5},{:.6},{:.5},{:.6},{logged}\n",
            r + OFFSETS[0] + 0.002 * noise.gauss(),
            u * r + 9.80665 * bank.sin() + OFFSETS[1] + 0.05 * noise.gauss(),
            0.1 * steer - 0.01 + 0.001 * noise.gauss()
        );
    }
    s
}

#[test]
fn a_bank_column_in_degrees_is_refused_at_its_value_and_read_when_declared() {
    // The road is banked 0.5°; the column says 0.5. Read in radians (28.6°)
    // it took g·sin(0.5) = 4.70 m/s² out of ay and the calibration named a
    // −5.3 m/s² accelerometer offset.
    let dir = campaign(&[
        ("banked.csv", banked_log(3, 0.5f64.to_radians(), 0.5, false)),
        ("second.csv", banked_log(6, 0.5f64.to_radians(), 0.5, false)),
    ]);
    let out = dir.path().join("out");
    let o = run_in(
        dir.path(),
        &[
            "diagnose",
            dir.path().to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ],
    );
    assert!(
        !o.status.success(),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    assert!(!out.join("diagnosis.json").exists());
    let e = stderr(&o);
    // File, line (the first data row: the bank is 0.5 throughout), column
    // 7 (`bank`), the value, the offsets each reading implies (the medians
    // over the half-second means, the yaw-rate offset's 0.004 × 20 m/s in
    // the moving ones: radians -0.6 + 0.086 - 4.70 (- 0.08) = -5.26;
    // degrees -0.64; within the noise of the bins' medians), the question.
    assert!(
        e.contains("banked.csv:2:7: column `bank`: 0.5 read in radians is 28.6°"),
        "{e}"
    );
    let after = |what: &str| -> f64 {
        let rest = &e[e.find(what).unwrap_or_else(|| panic!("{what}: {e}")) + what.len()..];
        rest.split_whitespace().next().unwrap().parse().unwrap()
    };
    let as_radians = after("has a median of ");
    assert!((as_radians + 5.26).abs() < 0.03, "{e}");
    let as_degrees = after("where with the bank in degrees it is ");
    assert!((as_degrees + 0.64).abs() < 0.03, "{e}");
    assert!(e.contains("is the column in degrees?"), "{e}");
    assert!(e.contains("`degrees = [\"bank\"]` under [runs]"), "{e}");
    // Declared, the same run is read: the ay offset is the sensor's.
    let v = format!(
        "{VEHICLE}\n[tyres]\nfile = \"tyre.toml\"\n\n[runs]\ndegrees = [\"bank\"]\n\n[diagnose]\neffects = [\"sensor_bias\"]\n"
    );
    fs::write(dir.path().join("vehicle.toml"), v).unwrap();
    let (_, d) = diagnose(dir.path());
    let ay = d["calibration"]["channels"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["channel"] == "ay")
        .unwrap();
    let offset = ay["offset"]["mean"].as_f64().unwrap();
    assert!((offset - OFFSETS[1]).abs() < 0.01, "{ay}");
}

#[test]
fn a_bank_steeper_than_any_road_is_said() {
    // Parked on 0.7 rad (40°) in radians, felt by the accelerometer: read,
    // with a note, since no road is banked beyond 35°.
    let dir = campaign(&[
        ("steep.csv", banked_log(4, 0.7, 0.7, true)),
        ("flat.csv", banked_log(7, 0.0, 0.0, true)),
    ]);
    let (stdout, _) = diagnose(dir.path());
    let note = stdout
        .lines()
        .find(|l| l.contains("steep.csv: `bank` reaches 0.7 rad (40°) at t = 15 s"))
        .unwrap_or_else(|| panic!("{stdout}"));
    assert!(note.contains("steeper than any road (35°"), "{note}");
    // A real bank of 0.15 rad (8.6°) logged in radians is read without a
    // word.
    let dir = campaign(&[
        ("banked.csv", banked_log(5, 0.15, 0.15, true)),
        ("flat.csv", banked_log(8, 0.0, 0.0, true)),
    ]);
    let (stdout, d) = diagnose(dir.path());
    assert!(!stdout.contains("`bank` reaches"), "{stdout}");
    let ay = d["calibration"]["channels"][1]["offset"]["mean"]
        .as_f64()
        .unwrap();
    assert!((ay - OFFSETS[1]).abs() < 0.01, "{}", d["calibration"]);
}

#[test]
fn an_uncertainty_stated_far_above_the_channels_scatter_is_said_and_the_verdict_rests_on_it() {
    // The runs scatter by 0.002 rad/s, 0.05 m/s² and 0.001 rad; stated
    // 0.04, 1.0 and 0.02: 20 times each. The user may, but the gap within
    // noise is then the statement's, and the report says so.
    let runs = [
        ("a.csv", banked_log(9, 0.0, 0.0, true)),
        ("b.csv", banked_log(10, 0.0, 0.0, true)),
    ];
    let dir = campaign(&runs);
    let v = format!(
        "{VEHICLE}\n[tyres]\nfile = \"tyre.toml\"\n\n[channels]\nyaw_rate = 0.04\nay = 1.0\nbeta = 0.02\n\n[diagnose]\neffects = [\"sensor_bias\"]\n"
    );
    fs::write(dir.path().join("vehicle.toml"), v).unwrap();
    let (stdout, d) = diagnose(dir.path());
    assert_eq!(
        d["verdict"]["kind"], "no_significant_gap",
        "{}",
        d["verdict"]
    );
    let resting = d["verdict"]["resting_on"].as_array().unwrap();
    let names: Vec<&str> = resting
        .iter()
        .map(|e| e["channel"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["yaw_rate", "ay", "beta"], "{resting:?}");
    // The scatter the tool measures is the noise put in: 20 times, to the
    // estimate's own spread.
    for e in resting {
        let times = e["times"].as_f64().unwrap();
        assert!((times / 20.0 - 1.0).abs() < 0.1, "{e}");
        assert_eq!(e["estimated"], false, "{e}");
    }
    // In the noise table and the notes too, typed.
    let noise = d["gap"]["noise"].as_array().unwrap();
    assert!(noise
        .iter()
        .all(|n| n["stated_excess"]["times"].as_f64().unwrap() > 10.0));
    let notes: Vec<&serde_json::Value> = d["note_details"]
        .as_array()
        .unwrap_or_else(|| panic!("{d}"))
        .iter()
        .filter(|n| n["kind"] == "uncertainty_above_own")
        .collect();
    assert_eq!(notes.len(), 3, "{}", d["note_details"]);
    assert_eq!(notes[0]["channel"], "yaw_rate");
    assert_eq!(notes[0]["stated"], 0.04);
    // On the terminal: the note, the trust line and the verdict.
    let note = stdout
        .lines()
        .find(|l| l.contains("note: [channels] yaw_rate = 0.04 rad/s: the stated uncertainty is"))
        .unwrap_or_else(|| panic!("{stdout}"));
    assert!(
        note.contains("× the channel's own scatter, 0.00")
            && note
                .ends_with("a gap below it is called insignificant only because of the statement"),
        "{note}"
    );
    let trust = stdout
        .lines()
        .find(|l| l.starts_with("channels trusted to:"))
        .unwrap_or_else(|| panic!("{stdout}"));
    assert!(trust.contains("yaw_rate 0.0400 rad/s (stated; "), "{trust}");
    let verdict = stdout
        .lines()
        .find(|l| l.contains("no significant gap: held-out error"))
        .unwrap_or_else(|| panic!("{stdout}"));
    assert!(
        verdict.contains(
            "; this rests on the uncertainty stated under [channels] for yaw_rate, 0.0400 rad/s, "
        ),
        "{verdict}"
    );
}
