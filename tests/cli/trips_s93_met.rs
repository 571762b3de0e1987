//! What fresh users tripped on in `metrics` and `diagnose` (session 93,
//! from fresh-eyes round 21): an unstable car's exponentially
//! growing yaw rate read as a gain "not settled", a one-sample speed
//! dropout taken for a standstill, and a coarse log's rate advice that
//! moved with where its samples fell on a ramped step.

use super::trips_s90_met::measured;
use super::*;
use std::fs;

/// The tester's car (1530 kg, 2315 kg·m², a = 1.11 m, b = 1.67 m) on
/// linear tyres of 57 296 N/rad per wheel in front and `rear` N/rad per
/// wheel behind, no load transfer, stepped by 0.001 rad at 1 s at `speed`
/// m/s to `end` s, simulated at 1 kHz in `dir`: its history.
pub(crate) fn stepped(dir: &Path, rear: f64, speed: f64, end: f64) -> PathBuf {
    let tyre = |c: f64| format!("model = \"linear\"\ncornering_stiffness = {c:?}\n");
    fs::write(dir.join("front.toml"), tyre(57296.0)).unwrap();
    fs::write(dir.join("rear.toml"), tyre(rear)).unwrap();
    let scenario = format!(
        "name = \"over\"\n{VEHICLE}[tyres]\nfront = \"front.toml\"\nrear = \"rear.toml\"\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n[manoeuvre]\nkind = \"step-steer\"\nspeed = {speed:?}\nsteer = 0.001\nstart = 1.0\nrise_time = 0.0\nend = {end:?}\n[simulation]\nstep = 0.001\n"
    );
    let path = dir.join("over.toml");
    fs::write(&path, scenario).unwrap();
    let out = dir.join(format!("sim_{speed}"));
    let o = run(&[
        "simulate",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    out.join("history.csv")
}

/// The linear 2-DOF car's state matrix (β, r) at `u` m/s with axle
/// stiffnesses 2 × 57 296 and 2 × `rear` N/rad: its larger eigenvalue,
/// 1/s, and its steady yaw-rate gain u/(l + K·u²), 1/s.
pub(crate) fn closed_form(rear: f64, u: f64) -> (f64, f64) {
    let (m, iz, a, b) = (1530.0, 2315.0, 1.11, 1.67);
    let (cf, cr) = (2.0 * 57296.0, 2.0 * rear);
    let a11 = -(cf + cr) / (m * u);
    let a12 = (b * cr - a * cf) / (m * u * u) - 1.0;
    let a21 = (b * cr - a * cf) / iz;
    let a22 = -(a * a * cf + b * b * cr) / (iz * u);
    let (tr, det) = (a11 + a22, a11 * a22 - a12 * a21);
    let l = a + b;
    let k = m / l * (b / cf - a / cr);
    (
        0.5 * (tr + (tr * tr - 4.0 * det).sqrt()),
        u / (l + k * u * u),
    )
}

/// An oversteering car (rear tyres 20 000 N/rad per wheel: K = −0.00725
/// rad/(m/s²), critical speed 19.6 m/s) stepped at 25 m/s: its yaw rate
/// grows as exp(1.065·t), and `metrics` read a yaw-rate gain of 256.4 1/s
/// "not settled" from the record's last second. Now the log is refused as
/// diverging, with the growth rate fitted from it (the closed form's
/// positive eigenvalue within 2 %), and no gain; the same car below its
/// critical speed (15 m/s) still reads its closed-form gain.
#[test]
fn an_unstable_cars_diverging_yaw_rate_is_said_with_its_growth_rate_not_a_gain() {
    let dir = tempfile::tempdir().unwrap();
    let history = stepped(dir.path(), 20000.0, 25.0, 4.0);
    let o = run(&["metrics", history.to_str().unwrap(), "--json"]);
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(e.contains("the yaw rate diverges after the step"), "{e}");
    assert!(
        !e.contains("has not settled") && !e.contains("yaw-rate gain"),
        "{e}"
    );
    let at = e.find("λ = ").expect(&e) + "λ = ".len();
    let rate: f64 = e[at..].split(' ').next().unwrap().parse().unwrap();
    let (exact, _) = closed_form(20000.0, 25.0);
    assert!((rate / exact - 1.0).abs() < 0.02, "{rate} against {exact}");
    let history = stepped(dir.path(), 20000.0, 15.0, 9.0);
    let (j, w) = measured(&history, &[]);
    let gain = j["yaw_rate_gain"].as_f64().unwrap();
    let (_, exact) = closed_form(20000.0, 15.0);
    assert!(
        (gain / exact - 1.0).abs() < 0.005,
        "{gain} against {exact}: {w}"
    );
}

/// `csv`'s speed column rewritten by `speed(t, u)`, in place: the other
/// cells kept as written.
fn respeeded(csv: &Path, speed: impl Fn(f64, f64) -> f64) {
    let (head, rows) = numeric_csv(csv);
    let (it, iu) = (column(&head, "t"), column(&head, "speed"));
    let text = fs::read_to_string(csv).unwrap();
    let mut out = format!("{}\n", head.join(","));
    for (line, row) in text.lines().skip(1).zip(&rows) {
        let mut cells: Vec<String> = line.split(',').map(String::from).collect();
        cells[iu] = speed(row[it], row[iu]).to_string();
        out.push_str(&format!("{}\n", cells.join(",")));
    }
    fs::write(csv, out).unwrap();
}

/// A dropout: the speed read as exactly 0 at the sample at `at` s.
fn dropout(csv: &Path, at: f64) {
    respeeded(csv, |t, u| if (t - at).abs() < 1e-9 { 0.0 } else { u });
}

/// The closed-form yaw-rate gain u/(l·(1 + K·u²)) of the tester's car
/// (C = 2 × 57 296 N/rad per axle) at `u` m/s, 1/s.
fn tester_gain(u: f64) -> f64 {
    let (m, a, b, c) = (1530.0, 1.11, 1.67, 2.0 * 57296.0);
    let l: f64 = a + b;
    u / (l * (1.0 + m / (l * l) * (b - a) / c * u * u))
}

/// The tester's 0.01 rad step at 20 m/s (ramped over 0.1 s at 1 s), logged
/// at 100 Hz, its speed read 0 at 2.00 s alone (neighbours 20 m/s: a stop
/// and a start within 0.01 s, 204 g): the sample was a standstill that cut
/// the record 1 s after its step, and `metrics` refused both pieces (the
/// first "too short for its steady window"). Now it is a zero read of the
/// speed, repaired and said, and the record reads the closed-form gain.
#[test]
fn a_one_sample_speed_dropout_is_a_zero_read_not_a_standstill() {
    let dir = tempfile::tempdir().unwrap();
    let history = super::trips_s90_met::tester_step_at(dir.path(), 20.0, 0.1, "");
    let csv = dir.path().join("drop.csv");
    let text = fs::read_to_string(&history).unwrap();
    let rows: Vec<&str> = text.lines().skip(1).step_by(10).collect();
    let mut out = String::from("t,steer,speed,beta,yaw_rate,ay\n");
    for r in rows {
        let cells: Vec<&str> = r.split(',').take(6).collect();
        out.push_str(&format!("{}\n", cells.join(",")));
    }
    fs::write(&csv, out).unwrap();
    dropout(&csv, 2.0);
    let (j, w) = measured(&csv, &[]);
    let gain = j["yaw_rate_gain"].as_f64().unwrap();
    assert!(
        (gain / tester_gain(20.0) - 1.0).abs() < 0.002,
        "{gain}: {w}"
    );
    let c = &j["cleaning"];
    assert!(c["slow"].as_array().unwrap().is_empty(), "{c}");
    let g = &c["glitches"][0];
    assert_eq!(
        (g["channel"].as_str(), g["kind"].as_str(), g["t"].as_f64()),
        (Some("speed"), Some("zero_read"), Some(2.0)),
        "{c}"
    );
    let o = run(&["metrics", csv.to_str().unwrap()]);
    assert!(
        stderr(&o).contains("drop.csv: speed 0 (1 sample, repaired)"),
        "{}",
        stderr(&o)
    );
}

/// The same dropout in a campaign's 100 km/h step (at 5.99 s) made
/// `diagnose` list a standstill of one sample, 5.99–5.99 s, and split the
/// run; a real standstill, braked at 8 m/s² from 80 km/h in the sweep and
/// held 6 s, is one. Now the dropout is a zero read of the speed, repaired,
/// and the braked standstill alone is a standstill, the calibration's too.
#[test]
fn diagnose_takes_a_speed_dropout_for_a_zero_read_and_a_braked_stop_for_a_standstill() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "handling", &["--seed", "1"]);
    dropout(&c.join("runs/step_100kph_2ms2.csv"), 5.99);
    respeeded(&c.join("runs/sweep_080kph.csv"), |t, u| {
        let (s, braking) = (t - 4.0, u / 8.0);
        match s {
            s if s <= 0.0 => u,
            s if s < braking => u - 8.0 * s,
            s if s < braking + 6.0 => 0.0,
            s => u.min(4.0 * (s - braking - 6.0)),
        }
    });
    let (out, d) = diagnose_to(&c, &dir.path().join("out"));
    let slow = d["cleaning"]["slow"].as_array().unwrap();
    assert_eq!(slow.len(), 1, "{slow:?}");
    assert!(slow[0]["run"]
        .as_str()
        .unwrap()
        .ends_with("sweep_080kph.csv"));
    assert_eq!(slow[0]["kind"], "standstill");
    let spans = d["calibration"]["spans"].as_array().unwrap();
    assert!(
        spans
            .iter()
            .filter(|s| s["kind"] == "standstill")
            .all(|s| s["run"].as_str().unwrap().ends_with("sweep_080kph.csv")),
        "{spans:?}"
    );
    assert!(
        out.contains("zero_read at 5.990 s in")
            && out.contains("step_100kph_2ms2.csv: speed 0 (1 sample, repaired)"),
        "{out}"
    );
}

/// The tester's step ramped over 0.1 s at 25 m/s, logged at 10 Hz (its
/// interval as long as the ramp) from five placings within one interval:
/// where the ramp fell between two samples the steer read as an instant
/// step and the advice was "log at 50 Hz", elsewhere "log at 12.5 Hz".
/// The log cannot tell the two apart: now every placing is advised the
/// stricter rate, and says why.
#[test]
fn a_10_hz_logs_rate_advice_does_not_move_with_the_placing_of_a_ramped_step() {
    let dir = tempfile::tempdir().unwrap();
    let ramp = super::trips_s90_met::tester_step(dir.path(), 0.1, "");
    let advice: Vec<(String, String)> = [0.01, 0.03, 0.05, 0.07, 0.09]
        .iter()
        .map(|&t0| {
            let name = format!("r10_{t0}.csv");
            let csv = super::trips_s92_met::resampled(&ramp, 10.0, t0, dir.path(), &name);
            let (_, w) = measured(&csv, &[]);
            let at = w.find("or faster to read it finer").expect(&w);
            (w[at.saturating_sub(30)..at].to_string(), w)
        })
        .collect();
    assert!(
        advice.iter().all(|(a, _)| a.ends_with("log at 50 Hz ")),
        "{:?}",
        advice.iter().map(|(a, _)| a).collect::<Vec<_>>()
    );
    for (_, w) in &advice {
        assert!(
            w.contains("a 10 Hz log cannot tell a step ramped over 0.1 s from an instant one"),
            "{w}"
        );
    }
}
