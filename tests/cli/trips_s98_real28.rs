//! What a fresh-eyes round tripped on with a logged body roll (session 98):
//! the roll was "compared with nothing" while the accelerometer read
//! `g·sin φ` of gravity in roll, so the fit took the roll for whatever
//! else grows with `ay`; a sideslip offset stayed in the bank estimate's
//! `d(u·β)/dt`.

use super::calibration::{diagnosed, log};

const G: f64 = 9.80665;

/// The ay offset [`log`] writes, m/s².
const AY_OFFSET: f64 = -0.6;

/// The columns of a CSV line.
fn cells(l: &str) -> Vec<String> {
    l.split(',').map(str::to_string).collect()
}

/// `text` (a [`log`] run) as a body-fixed accelerometer on a body rolling
/// by `per_ay` rad per m/s² of its lateral acceleration (the logged `ay`
/// less its offset) reads it, `ay·cos φ + g·sin φ`, with a `roll` column
/// logging φ plus the roll sensor's own offset `roll_offset` rad.
fn rolled(text: &str, per_ay: f64, roll_offset: f64) -> String {
    let mut lines = text.lines();
    let head = lines.next().unwrap();
    let ay = cells(head).iter().position(|h| h == "ay").unwrap();
    let mut out = format!("{head},roll\n");
    for l in lines {
        let mut c = cells(l);
        let a: f64 = c[ay].parse().unwrap();
        let phi = per_ay * (a - AY_OFFSET);
        c[ay] = format!("{:.9}", a * phi.cos() + G * phi.sin());
        out.push_str(&format!("{},{:.9}\n", c.join(","), phi + roll_offset));
    }
    out
}

/// Each replayed piece's estimated bank (rad): 5th and 95th percentiles.
fn banks(d: &serde_json::Value) -> Vec<(f64, f64)> {
    d["road"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            let b = &r["bank"];
            (b["p05"].as_f64().unwrap(), b["p95"].as_f64().unwrap())
        })
        .collect()
}

/// The verdict's fitted parameter `name`.
fn fitted(d: &serde_json::Value, name: &str) -> f64 {
    d["verdict"]["parameters"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["name"] == name)
        .and_then(|p| p["value"].as_f64())
        .unwrap_or_else(|| panic!("no {name} in {}", d["verdict"]))
}

/// Before: two runs whose accelerometer rolls with the body (3.5°/g, a
/// step steer to 2.4 m/s²: 0.15 m/s² of gravity in the turn) and whose
/// roll is logged (its sensor 0.01 rad off) were diagnosed as if the roll
/// were not there: "the logged roll is compared with nothing", the base's
/// held-out error above its level twin's and the turn read as 0.9° of
/// bank. Now `ay` is levelled by the logged roll less its standstill
/// offset, and the twins read the same: base error, fitted ay offset and
/// estimated bank.
#[test]
fn a_logged_roll_levels_the_accelerometer_before_the_fit() {
    let level = [
        ("a.csv", log(1, 0.0, true, false)),
        ("b.csv", log(2, 0.0, true, false)),
    ];
    let k = 3.5_f64.to_radians() / G;
    let tilted: Vec<(&str, String)> = level
        .iter()
        .map(|(n, t)| (*n, rolled(t, k, 0.01)))
        .collect();
    let (_a, _, flat) = diagnosed(&level);
    let (_b, stdout, roll) = diagnosed(&tilted);
    let j = |d: &serde_json::Value| d["gap"]["heldout_error"].as_f64().unwrap();
    let (j_flat, j_roll) = (j(&flat), j(&roll));
    assert!(
        (j_roll / j_flat - 1.0).abs() < 0.01,
        "{j_roll} against {j_flat}"
    );
    let (ay_flat, ay_roll) = (
        fitted(&flat, "sensor_bias.ay"),
        fitted(&roll, "sensor_bias.ay"),
    );
    assert!((ay_flat - AY_OFFSET).abs() < 0.02, "{ay_flat}");
    assert!(
        (ay_roll - ay_flat).abs() < 0.002,
        "{ay_roll} against {ay_flat}"
    );
    for (f, r) in banks(&flat).iter().zip(banks(&roll)) {
        // 0.1° apart at most; the roll's 0.15 m/s² is 0.9°.
        assert!((f.1 - r.1).abs() < 0.1_f64.to_radians(), "{f:?} {r:?}");
        assert!((f.0 - r.0).abs() < 0.1_f64.to_radians(), "{f:?} {r:?}");
    }
    let said = "roll: logged in 2 of 2 runs: ay levelled by it before every fit and the bank's estimate, (ay − g·sin φ)/cos φ with φ the logged roll less its own offset, 0.0100 ± ";
    assert!(stdout.contains(&format!("note: {said}")), "{stdout}");
    assert!(
        stdout.contains("rad, its mean at 2 standstills ("),
        "{stdout}"
    );
}

/// `text` (a [`log`] run) speeding up at 2.5 m/s² from 50 s on (straight:
/// the yaw rate, ay and sideslip as logged), its sideslip `extra` rad
/// further off.
fn speeding_up(text: &str, extra: f64) -> String {
    let mut lines = text.lines();
    let head = lines.next().unwrap();
    let h = cells(head);
    let at = |n: &str| h.iter().position(|x| x == n).unwrap();
    let (t, speed, beta) = (at("t"), at("speed"), at("beta"));
    let mut out = format!("{head}\n");
    for l in lines {
        let mut c = cells(l);
        let s: f64 = c[t].parse().unwrap();
        if s >= 50.0 {
            c[speed] = format!("{:.4}", 20.0 + 2.5 * (s - 50.0));
        }
        let b: f64 = c[beta].parse().unwrap();
        c[beta] = format!("{:.6}", b + extra);
        out.push_str(&format!("{}\n", c.join(",")));
    }
    out
}

/// Before: a sideslip offset stayed in the bank estimate's `d(u·β)/dt`,
/// `b_β·u̇` of lateral acceleration wherever the car speeds up: the same
/// runs with a sideslip sensor 0.04 rad further off read 0.6° more bank
/// while accelerating at 2.5 m/s². Now the straights' sideslip offset is
/// removed first, the line says so, and the twins' banks agree.
#[test]
fn a_sideslip_offset_reads_no_bank_where_the_car_speeds_up() {
    let runs = |extra: f64| -> Vec<(&str, String)> {
        vec![
            ("a.csv", speeding_up(&log(1, 0.0, true, false), extra)),
            ("b.csv", speeding_up(&log(2, 0.0, true, false), extra)),
        ]
    };
    let (_a, _, near) = diagnosed(&runs(0.0));
    let (_b, stdout, far) = diagnosed(&runs(-0.04));
    for (n, f) in banks(&near).iter().zip(banks(&far)) {
        assert!((n.1 - f.1).abs() < 0.05_f64.to_radians(), "{n:?} {f:?}");
        assert!((n.0 - f.0).abs() < 0.05_f64.to_radians(), "{n:?} {f:?}");
    }
    assert!(stdout.contains("rad/s, beta -0.0"), "{stdout}");
    let removed = far["road"][0]["offsets_removed"]["beta"].as_f64().unwrap();
    assert!((removed + 0.05).abs() < 0.002, "{removed}");
}
