//! Sensor offsets from the standstills and straights of runs read from
//! files: `handling diagnose` prints one `calibration:` line per channel and
//! `diagnosis.json` carries the report.

use super::*;

/// Offsets the logs carry: yaw rate, ay, beta.
const OFFSETS: [f64; 3] = [0.004, -0.6, -0.01];

/// Deterministic near-Gaussian noise of unit deviation (sum of uniforms),
/// the same on every machine.
pub(crate) struct Noise(pub(crate) u64);

impl Noise {
    pub(crate) fn gauss(&mut self) -> f64 {
        (0..12)
            .map(|_| {
                self.0 = self
                    .0
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (self.0 >> 11) as f64 / (1u64 << 53) as f64
            })
            .sum::<f64>()
            - 6.0
    }
}

/// A log at 100 Hz: parked for 15 s on a road banked by `parked_bank`
/// (rad), off to 20 m/s in 4 s (the bank easing to 0), straight to 35 s;
/// then, when `corner`, a 0.02 rad step steer to 45 s and straight again to
/// 60 s. The yaw rate follows the steady-state gain `u/(L + K·u²)` with a
/// 0.15 s lag, ay = u·r + g·sin(bank), sideslip 0.1·steer; the offsets
/// [`OFFSETS`] and white noise (0.002 rad/s, 0.05 m/s², 0.001 rad) on top.
/// The `bank` column is written when `bank_logged`; no `ax`.
pub(crate) fn log(seed: u64, parked_bank: f64, corner: bool, bank_logged: bool) -> String {
    log_banks(
        seed,
        parked_bank,
        bank_logged.then_some(parked_bank),
        corner,
    )
}

/// As [`log`], with the car parked on `felt` and the `bank` column (when
/// given) logging `logged`, both easing to 0 as the car drives off.
fn log_banks(seed: u64, felt: f64, logged: Option<f64>, corner: bool) -> String {
    let bank_logged = logged.is_some();
    let mut noise = Noise(seed);
    let seconds = if corner { 60.0 } else { 35.0 };
    let mut s = String::from(if bank_logged {
        "t,speed,steer,yaw_rate,ay,beta,bank\n"
    } else {
        "t,speed,steer,yaw_rate,ay,beta\n"
    });
    let mut r = 0.0;
    for i in 0..(seconds * 100.0) as usize {
        let t = i as f64 * 0.01;
        let u = (5.0 * (t - 15.0)).clamp(0.0, 20.0);
        let easing = (1.0 - (t - 15.0) / 4.0).clamp(0.0, 1.0);
        let bank = felt * easing;
        let steer = if corner && (35.0..45.0).contains(&t) {
            0.02
        } else {
            0.0
        };
        r += (u * steer / (2.78 + 0.0025 * u * u) - r) * (1.0 - (-0.01f64 / 0.15).exp());
        let ay = u * r + 9.80665 * bank.sin();
        s += &format!(
            "{t:.2},{u:.4},{steer:.5},{:.6},{:.5},{:.6}",
            r + OFFSETS[0] + 0.002 * noise.gauss(),
            ay + OFFSETS[1] + 0.05 * noise.gauss(),
            0.1 * steer + OFFSETS[2] + 0.001 * noise.gauss()
        );
        if bank_logged {
            s += &format!(",{:.6}", logged.unwrap_or(0.0) * easing);
        }
        s += "\n";
    }
    s
}

/// A campaign folder (linear tyres, one candidate: the point is the
/// calibration, not the search) with the runs `runs`, diagnosed.
pub(crate) fn diagnosed(runs: &[(&str, String)]) -> (tempfile::TempDir, String, serde_json::Value) {
    let v = format!(
        "{VEHICLE}\n[tyres]\nfile = \"tyre.toml\"\n\n[diagnose]\neffects = [\"sensor_bias\"]\n"
    );
    let dir = scratch(&[("vehicle.toml", &v)]);
    linear_tyre(dir.path());
    fs::create_dir(dir.path().join("runs")).unwrap();
    for (name, text) in runs {
        fs::write(dir.path().join("runs").join(name), text).unwrap();
    }
    let (stdout, d) = diagnose(dir.path());
    (dir, stdout, d)
}

/// The printed calibration line of `channel`.
fn line<'a>(stdout: &'a str, channel: &str) -> &'a str {
    let (offset, doubted) = (
        format!("  calibration: {channel} offset"),
        format!("  calibration: {channel}: "),
    );
    stdout
        .lines()
        .find(|l| l.starts_with(&offset) || l.starts_with(&doubted))
        .unwrap_or_else(|| panic!("no {channel} line in\n{stdout}"))
}

/// The first number after `after` in `line`.
fn number_after(line: &str, after: &str) -> f64 {
    let rest = &line[line
        .find(after)
        .unwrap_or_else(|| panic!("{after}: {line}"))
        + after.len()..];
    rest.split_whitespace().next().unwrap().parse().unwrap()
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap()
}

/// The campaign's calibration of `channel` in diagnosis.json.
fn channel<'a>(d: &'a serde_json::Value, channel: &str) -> &'a serde_json::Value {
    d["calibration"]["channels"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["channel"] == channel)
        .unwrap_or_else(|| panic!("no {channel} in {}", d["calibration"]))
}

#[test]
fn diagnose_reports_the_offsets_of_a_banked_standstill_and_the_straights() {
    // Run a parks on the flat, run b on a 0.15 rad banking (the bank
    // logged): with g·sin(bank) removed both standstills read the offset.
    let (_dir, stdout, d) = diagnosed(&[
        ("a.csv", log(1, 0.0, true, true)),
        ("b.csv", log(2, 0.15, false, true)),
    ]);
    let spans = d["calibration"]["spans"].as_array().unwrap();
    let kinds: Vec<(&str, &str)> = spans
        .iter()
        .map(|s| (s["run"].as_str().unwrap(), s["kind"].as_str().unwrap()))
        .map(|(r, k)| (&r[r.len() - 5..], k))
        .collect();
    assert_eq!(
        kinds,
        [
            ("a.csv", "standstill"),
            ("a.csv", "straight"),
            ("a.csv", "straight"),
            ("b.csv", "standstill"),
            ("b.csv", "straight")
        ]
    );
    // The banked standstill's ay had g·sin(0.15) = 1.466 m/s² removed.
    let b_ay = &spans[3]["channels"][1];
    assert_eq!(b_ay["channel"], "ay");
    assert!((f(&b_ay["bank_term"]) - 9.80665 * 0.15f64.sin()).abs() < 1e-3);
    for (name, k) in [("yaw_rate", 0), ("ay", 1), ("beta", 2)] {
        let c = channel(&d, name);
        let kinds: &[&str] = if name == "beta" {
            &["straight"]
        } else {
            &["standstill", "straight"]
        };
        for kind in kinds {
            let p = &c[kind];
            let (mean, se) = (f(&p["mean"]), f(&p["std_error"]));
            assert!((mean - OFFSETS[k]).abs() < 4.0 * se, "{name} {kind}: {p}");
            assert!(se > 0.0 && p["consistent"] == true, "{name} {kind}: {p}");
            // The printed value is the JSON's, to the printed digits.
            let l = line(&stdout, name);
            let printed = if *kind == "straight" && name != "beta" {
                number_after(l, "s), ")
            } else {
                number_after(l, if name == "ay" { "removed) " } else { "offset " })
            };
            assert!((printed - mean).abs() <= se, "{l}: {mean}");
        }
        if name != "beta" {
            assert_eq!(c["agreement"]["agree"], true, "{c}");
        }
    }
    let ay = line(&stdout, "ay");
    assert!(ay.contains("(g·sin(bank) removed)"), "{ay}");
    assert!(ay.contains(" m/s² at 2 standstills (26 s), "), "{ay}");
    assert!(ay.contains(" on 3 straights ("), "{ay}");
    assert!(ay.ends_with(": agree"), "{ay}");
    // Sideslip has no standstill value.
    let beta = line(&stdout, "beta");
    assert!(beta.contains(" rad on 3 straights ("), "{beta}");
    assert!(channel(&d, "beta")["standstill"].is_null());
}

#[test]
fn without_its_bank_column_a_banked_standstill_reads_g_sin_bank_and_drifts() {
    // The same runs without the bank column: the banked standstill reads
    // the offset plus g·sin(0.15), the flat one the offset alone.
    let (_dir, stdout, d) = diagnosed(&[
        ("a.csv", log(1, 0.0, true, false)),
        ("b.csv", log(2, 0.15, false, false)),
    ]);
    let ay = channel(&d, "ay");
    assert_eq!(ay["bank_removed"], false);
    let p = &ay["standstill"];
    assert_eq!(p["consistent"], false, "{p}");
    let g = 9.80665 * 0.15f64.sin();
    assert!((f(&p["least"]) - OFFSETS[1]).abs() < 0.01, "{p}");
    assert!((f(&p["greatest"]) - (OFFSETS[1] + g)).abs() < 0.01, "{p}");
    let l = line(&stdout, "ay");
    assert!(!without_temp_names(l).contains("bank"), "{l}");
    assert!(l.contains("; the standstills drift (-0.6"), "{l}");
    // Their pooled error spans the drift (Birge ratio).
    assert!(f(&p["std_error"]) > 0.3 * g, "{p}");
}

#[test]
fn a_logged_bank_the_accelerometer_does_not_feel_is_named_not_taken_for_an_offset() {
    // Parked on the flat while the bank column logs 0.35 rad (20°): read
    // as logged, the accelerometer would carry an offset of −0.6 − 3.36.
    let runs = |felt: f64, logged: f64| {
        [3, 4].map(|seed| {
            (
                ["a.csv", "b.csv"][seed - 3],
                log_banks(seed as u64, felt, Some(logged), true),
            )
        })
    };
    let (_dir, stdout, d) = diagnosed(&runs(0.0, 0.35));
    let ay = channel(&d, "ay");
    assert_eq!(ay["bank"]["seen"], "not_acting", "{ay}");
    let term = 9.80665 * 0.35f64.sin();
    assert!((f(&ay["bank"]["bank_term"]) - term).abs() < 1e-3, "{ay}");
    assert!((f(&ay["bank"]["read"]) - OFFSETS[1]).abs() < 0.01, "{ay}");
    // The offset the calibration gives is the straights' (the bank has
    // eased to 0 there), not the standstills' read with the bank as logged.
    assert_eq!(ay["offset"]["from"], "straight", "{ay}");
    assert!((f(&ay["offset"]["mean"]) - OFFSETS[1]).abs() < 0.02, "{ay}");
    assert!(
        (f(&ay["standstill"]["mean"]) - (OFFSETS[1] - term)).abs() < 0.02,
        "{ay}"
    );
    let l = line(&stdout, "ay");
    assert!(
        l.starts_with("  calibration: ay: no offset taken, not used as evidence: parked where the logged bank gives g·sin(bank) = 3.36 m/s², the accelerometer reads -0.60 m/s², an offset of -3.96 m/s², beyond the 1 m/s² a mounted sensor shows, so the logged bank does not act on the car"),
        "{l}"
    );
    // Logged with the other sign: named as reversed.
    let (_dir, stdout, d) = diagnosed(&runs(0.35, -0.35));
    assert_eq!(channel(&d, "ay")["bank"]["seen"], "reversed");
    assert!(line(&stdout, "ay").contains("the bank channel's sign is reversed"));
    // Felt as logged: taken, no doubt printed.
    let (_dir, stdout, d) = diagnosed(&runs(0.35, 0.35));
    assert_eq!(channel(&d, "ay")["bank"]["seen"], "as_logged");
    assert_eq!(channel(&d, "ay")["offset"]["from"], "standstill");
    assert!(!line(&stdout, "ay").contains("no offset taken"));
}
