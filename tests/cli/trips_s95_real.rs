//! What a fresh-eyes round on real logs (round 24B) left: a steer held at
//! 20 Hz in a log whose rate changes mid-run, a held steer that sticks,
//! and a steer path whose delay and lag only their sum is determined of.
//! Each on runs the `simulate`d car drove (the linear tyre, the shared
//! vehicle), logged as a logger would, diagnosed as a user runs it.

use super::scenarios::simulated_rows;
use super::*;

/// Deterministic white noise: a 64-bit linear congruential generator
/// (Knuth's MMIX constants), Box–Muller for the Gaussian.
struct Lcg(u64);

impl Lcg {
    fn uniform(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    fn gauss(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (2.0 * std::f64::consts::PI * v).cos()
    }
}

/// The shared vehicle on the linear tyre driven through a steer sine of
/// `amplitude` rad at `frequency` Hz from 1 s to 31 s at `speed` m/s,
/// simulated at 100 Hz in `dir`: its history's rows (t, steer, speed,
/// beta, yaw_rate, ay).
fn sine(dir: &Path, name: &str, speed: f64, amplitude: f64, frequency: f64) -> Vec<Vec<f64>> {
    let manoeuvre = format!(
        "kind = \"sine\"\nspeed = {speed:?}\namplitude = {amplitude:?}\nfrequency = {frequency:?}\nstart = 1.0\nend = 31.0\n"
    );
    simulated_rows(dir, name, &manoeuvre)
}

/// A campaign folder `dir/campaign` on the same car and tyre, with
/// `effects` the candidates and `runs` (name, CSV text) its runs.
pub(crate) fn campaign(dir: &Path, effects: &str, runs: &[(String, String)]) -> PathBuf {
    let c = dir.join("campaign");
    fs::create_dir_all(c.join("runs")).unwrap();
    linear_tyre(&c);
    fs::write(
        c.join("vehicle.toml"),
        format!("{VEHICLE}\n[tyres]\nfile = \"tyre.toml\"\n\n[diagnose]\neffects = [{effects}]\n"),
    )
    .unwrap();
    for (name, text) in runs {
        fs::write(c.join("runs").join(name), text).unwrap();
    }
    c
}

/// A logger's CSV of history rows: the rows `keep` keeps, the steer of
/// each as `steer` gives it (by row index), white noise of `k` times
/// 0.002 rad/s, 0.05 m/s² and 0.002 rad on the responses.
pub(crate) fn logged(
    rows: &[Vec<f64>],
    (seed, k): (u64, f64),
    keep: impl Fn(usize, f64) -> bool,
    steer: impl Fn(usize) -> f64,
) -> String {
    let mut noise = Lcg(seed);
    let mut s = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    for (i, c) in rows.iter().enumerate() {
        let (r, ay, beta) = (
            c[4] + k * 0.002 * noise.gauss(),
            c[5] + k * 0.05 * noise.gauss(),
            c[3] + k * 0.002 * noise.gauss(),
        );
        if keep(i, c[0]) {
            s += &format!(
                "{:.2},{:.6},{:.6},{r:.6},{ay:.6},{beta:.6}\n",
                c[0],
                c[2],
                steer(i)
            );
        }
    }
    s
}

/// A steer written every fifth row of a 100 Hz history (20 Hz), held
/// between, to the encoder's 2e-4 rad.
fn held_20_hz(rows: &[Vec<f64>], i: usize) -> f64 {
    (rows[i - i % 5][1] / 2e-4).round() * 2e-4
}

/// A campaign of two sine runs (20 m/s at 0.5 Hz, 15 m/s at 0.3 Hz) with
/// `sensor_bias` the candidate, each logged with the rows `keep` takes
/// (their noise seeded from `seed`) and the steer held at 20 Hz.
pub(crate) fn held_steer_campaign(
    dir: &Path,
    seed: u64,
    keep: impl Fn(usize, f64) -> bool + Copy,
) -> PathBuf {
    let mut runs = Vec::new();
    for (k, (name, speed, amplitude, frequency)) in [("a", 20.0, 0.03, 0.5), ("b", 15.0, 0.04, 0.3)]
        .into_iter()
        .enumerate()
    {
        let rows = sine(dir, name, speed, amplitude, frequency);
        let text = logged(&rows, (seed + k as u64, 1.0), keep, |i| {
            held_20_hz(&rows, i)
        });
        runs.push((format!("{name}.csv"), text));
    }
    campaign(dir, "\"sensor_bias\"", &runs)
}

/// Round 24B's `rate_hold.toml`: a log whose rate halves mid-run (100 Hz,
/// then 50 Hz) with the steer held at 20 Hz. The holds went from 5
/// samples to 2 or 3, no length held four in five of them, and the steer
/// was replayed held (the axles came out 14.4 / 20.8 against 14 / 20).
/// Now the holds are judged in time, every one 0.05 s: the steer is
/// interpolated between its updates on both stretches, said so, and the
/// car the runs came from leaves no significant gap.
#[test]
fn a_steer_held_at_20_hz_in_a_log_whose_rate_halves_is_interpolated_throughout() {
    let dir = tempfile::tempdir().unwrap();
    // 100 Hz to 15 s, every other row (50 Hz) after.
    let c = held_steer_campaign(dir.path(), 11, |i, t| t < 15.0 || i % 2 == 0);
    let (stdout, d) = diagnose(&c);
    let held = d["cleaning"]["held"].as_array().unwrap();
    assert_eq!(held.len(), 2, "{held:?}");
    for h in held {
        assert_eq!(h["channel"], "steer", "{h}");
        assert_eq!(h["log_rate_changes"], true, "{h}");
        let rate = h["update_rate"].as_f64().unwrap();
        assert!((rate / 20.0 - 1.0).abs() < 1e-3, "{h}");
    }
    assert!(
        stdout.contains("updates every 0.05 s (20 Hz) in a log whose rate changes (100 Hz at its median interval)"),
        "{stdout}"
    );
    // Replayed held, the steer lagged its updates by half an interval on
    // average: at 0.5 Hz and 0.2 rad/s of yaw rate, 0.016 rad/s.
    assert_eq!(
        d["gap"]["significant"], false,
        "{}",
        d["gap"]["heldout_error"]
    );
}

/// Round 24B's `glitch.toml`: a steer held at 20 Hz that stuck at one
/// value for 40 samples (8 updates) while the car kept turning went
/// undetected ("0 stuck values"): the held channel's own holds hid it,
/// and it was interpolated as one long hold. Now a hold of 5 or more
/// update periods among holds of one, left with a step of the signal's
/// change over the hold, is a stuck glitch: listed, counted, repaired;
/// the same log unstuck has none.
#[test]
fn a_held_steer_stuck_for_eight_updates_is_listed_as_stuck_and_repaired() {
    let dir = tempfile::tempdir().unwrap();
    // 0.5 Hz from 1 s: at 10 s the sine crosses zero at its fastest.
    let rows = sine(dir.path(), "a", 20.0, 0.03, 0.5);
    let stuck = |i: usize| held_20_hz(&rows, if (1000..1040).contains(&i) { 1000 } else { i });
    let other = sine(dir.path(), "b", 15.0, 0.04, 0.3);
    let runs = vec![
        (
            "a.csv".to_string(),
            logged(&rows, (21, 1.0), |_, _| true, stuck),
        ),
        (
            "b.csv".to_string(),
            logged(&other, (22, 1.0), |_, _| true, |i| held_20_hz(&other, i)),
        ),
    ];
    let c = campaign(dir.path(), "\"sensor_bias\"", &runs);
    let (stdout, d) = diagnose(&c);
    let cleaning = &d["cleaning"];
    assert_eq!(cleaning["counts"]["stuck"], 1, "{}", cleaning["glitches"]);
    let g = &cleaning["glitches"][0];
    assert_eq!(g["channel"], "steer", "{g}");
    assert_eq!(g["kind"], "stuck", "{g}");
    assert_eq!(g["treatment"], "repaired", "{g}");
    // The update at 10.00 s is read; its 39 repeats after it are stuck.
    assert!((g["t"].as_f64().unwrap() - 10.01).abs() < 1e-9, "{g}");
    assert_eq!(g["samples"], 39, "{g}");
    assert!(stdout.contains("1 stuck value"), "{stdout}");
    assert!(stdout.contains("stuck at 10.010 s in"), "{stdout}");
}

/// A campaign of four sines at `frequencies` Hz driven by the car whose
/// steer is the logged one through a 0.06 s delay and a 0.04 s
/// first-order lag (the logged steer made from the car's as `s + τ·ds/dt`
/// 0.06 s later), logged with `k` times the noise, diagnosed with the steer
/// path alone: stdout and the steer path's parameters.
fn delayed_and_lagged(
    dir: &Path,
    frequencies: [f64; 4],
    k: f64,
) -> (String, Vec<serde_json::Value>) {
    let (shift, lag) = (6, 0.04);
    let mut runs = Vec::new();
    let cars = [(20.0, 0.03), (15.0, 0.04), (25.0, 0.02), (18.0, 0.03)];
    for (j, ((speed, amplitude), frequency)) in cars.into_iter().zip(frequencies).enumerate() {
        let name = format!("r{j}");
        let rows = sine(dir, &name, speed, amplitude, frequency);
        let n = rows.len();
        // The lag inverted: s + τ·ds/dt (central differences), 0.06 s on.
        let logged_steer = |i: usize| {
            let j = (i + shift).clamp(1, n - 2);
            rows[j][1] + lag * (rows[j + 1][1] - rows[j - 1][1]) / 0.02
        };
        let text = logged(
            &rows,
            (31 + j as u64, k),
            |i, _| i + shift < n - 1,
            logged_steer,
        );
        runs.push((format!("{name}.csv"), text));
    }
    let c = campaign(dir, "\"steer_path\"", &runs);
    let (stdout, d) = diagnose(&c);
    let p = fitted_row(&d, "steer_path")["parameters"]
        .as_array()
        .unwrap()
        .clone();
    (stdout, p)
}

/// Round 24B's `delay.toml`: a steer path fitted "delay = 0.0670 ±
/// 0.0117 s, lag = 0.0331 ± 0.0114 s" where the runs determine only their
/// sum (at a driver's frequencies a lag τ delays by about τ). Here a
/// delay of 0.06 s and a lag of 0.04 s: on sines of 0.1 to 0.3 Hz with
/// four times the noise the runs cannot split the 0.10 s, and the lag is
/// reported with its correlation with the delay, their sum with the
/// standard error that determines it, and "not how it splits"; on sines
/// of 0.2 to 0.8 Hz they split it (each within four standard errors of
/// its truth), and the sum is said to be known better than either.
#[test]
fn a_steer_paths_delay_and_lag_are_reported_as_the_sum_the_runs_determine() {
    for (frequencies, k, split) in [
        ([0.1, 0.15, 0.2, 0.3], 4.0, false),
        ([0.2, 0.35, 0.5, 0.8], 1.0, true),
    ] {
        let dir = tempfile::tempdir().unwrap();
        let (stdout, p) = delayed_and_lagged(dir.path(), frequencies, k);
        assert_eq!(p[1]["name"], "steer_path.lag", "{p:?}");
        let t = &p[1]["traded"];
        assert_eq!(t["with"], "steer_path.delay", "{p:?}");
        let (sum, se) = (
            t["sum"].as_f64().unwrap(),
            t["sum_std_error"].as_f64().unwrap(),
        );
        // The sum recovers delay + lag within 4 of its standard errors,
        // which is below half of either parameter's own.
        assert!((sum - 0.10).abs() < 4.0 * se, "{t}");
        for q in &p {
            assert!(se < 0.5 * q["std_error"].as_f64().unwrap(), "{t} {q}");
        }
        assert!(t["correlation"].as_f64().unwrap() < -0.9, "{t}");
        assert_eq!(t["split_undetermined"], !split, "{p:?}");
        assert!(
            stdout.contains(
                "with steer_path.delay: the runs determine their sum, the equivalent delay, "
            ),
            "{stdout}"
        );
        if split {
            for (q, truth) in p.iter().zip([0.06, 0.04]) {
                let (v, e) = (
                    q["value"].as_f64().unwrap(),
                    q["std_error"].as_f64().unwrap(),
                );
                assert!((v - truth).abs() < 4.0 * e, "{q}");
            }
            assert!(stdout.contains("better than either"), "{stdout}");
        } else {
            assert!(
                stdout.contains("not how it splits between them"),
                "{stdout}"
            );
        }
    }
}
