//! What round 40's fresh-eyes tester tripped on in `metrics` (session
//! 108), on the bundled sedan step (`scenarios/sedan_step.toml`: 1° at
//! 80 km/h) logged at 100 Hz with the noise of a MEMS gyro and
//! accelerometer added: a noisy steer cut the initial window to a few
//! samples and moved the yaw-rate gain by up to 11 %; response times the
//! noise moves by 5–19 % printed to four digits without a word; a yaw
//! rate drifting linearly bounded as "off by up to about 4.9 %".

use super::*;

use crate::calibration::Noise;

/// The bundled sedan step simulated into `dir`: its history's rows
/// (1 kHz) of t, steer, speed, beta, yaw_rate, ay.
pub(crate) fn sedan_rows(dir: &Path) -> Vec<[f64; 6]> {
    let scenario = dir.join("sedan_step.toml");
    fs::write(&scenario, bundled_scenario("sedan_step.toml")).unwrap();
    let out = dir.join("sedan");
    succeeds(&[
        "simulate",
        scenario.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    history_rows(&out)
}

/// The rows (t, steer, speed, beta, yaw_rate, ay) of the `history.csv`
/// a `simulate` wrote into `out`.
pub(crate) fn history_rows(out: &Path) -> Vec<[f64; 6]> {
    let text = fs::read_to_string(out.join("history.csv")).unwrap();
    text.lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').take(6).map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3], v[4], v[5]]
        })
        .collect()
}

/// `rows` logged at 100 Hz through `f` into `dir/name`.
pub(crate) fn logged(
    rows: &[[f64; 6]],
    dir: &Path,
    name: &str,
    mut f: impl FnMut([f64; 6]) -> [f64; 6],
) -> PathBuf {
    let mut text = String::from("t,steer,speed,beta,yaw_rate,ay\n");
    for r in rows.iter().step_by(10) {
        let c = f(*r);
        let cells: Vec<String> = c.iter().map(|v| format!("{v:.7e}")).collect();
        text.push_str(&format!("{}\n", cells.join(",")));
    }
    let path = dir.join(name);
    fs::write(&path, text).unwrap();
    path
}

/// The tester's noise: gyro 0.012 rad/s, ay 0.3 m/s², β 0.003 rad,
/// steer 0.0006 rad (3.4 % of the 1° step), seeded by `seed`.
fn noisy(rows: &[[f64; 6]], dir: &Path, seed: u64) -> PathBuf {
    let mut n = Noise(seed);
    logged(rows, dir, &format!("noisy_{seed}.csv"), |mut c| {
        c[1] += 0.0006 * n.gauss();
        c[3] += 0.003 * n.gauss();
        c[4] += 0.012 * n.gauss();
        c[5] += 0.3 * n.gauss();
        c
    })
}

/// The mean of column `k` of the 100 Hz log `rows` over [from, to] s.
fn mean(rows: &[[f64; 6]], k: usize, (from, to): (f64, f64)) -> f64 {
    let v: Vec<f64> = rows
        .iter()
        .step_by(10)
        .filter(|r| r[0] >= from && r[0] <= to)
        .map(|r| r[k])
        .collect();
    v.iter().sum::<f64>() / v.len() as f64
}

/// The book's steady values are "means over the last steady_window (1 s),
/// initial values means over the first pre_window (0.5 s)". A steer
/// logged with noise of 3.4 % of its step strays past 5 % of it by noise
/// alone, and the initial window was cut there, a few samples long: the
/// yaw rate's initial value then carried their noise, and the tester's
/// seeds read the gain 3.40–4.13 1/s about the noise-free 3.71 (the
/// steady yaw rate 0.0710 rad/s where the book's means give 0.0644). Now
/// every seed's steady yaw rate is the book's means' to 1.5 %.
#[test]
fn a_noisy_steers_run_reads_its_steady_values_as_the_book_defines_them() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let clean =
        crate::trips_s90_met::measured(&logged(&rows, dir.path(), "clean.csv", |c| c), &[]).0;
    let clean_gain = clean["yaw_rate_gain"].as_f64().unwrap();
    for seed in 1..=6u64 {
        let csv = noisy(&rows, dir.path(), seed);
        let (j, _) = crate::trips_s90_met::measured(&csv, &[]);
        let text = fs::read_to_string(&csv).unwrap();
        let logged: Vec<[f64; 6]> = text
            .lines()
            .skip(1)
            .flat_map(|l| {
                let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
                std::iter::repeat_n([v[0], v[1], v[2], v[3], v[4], v[5]], 10)
            })
            .collect();
        let end = logged.last().unwrap()[0];
        let book = mean(&logged, 4, (end - 1.0, end)) - mean(&logged, 4, (0.0, 0.5));
        let read = j["yaw_rate_steady"].as_f64().unwrap();
        assert!(
            (read / book - 1.0).abs() < 0.015,
            "seed {seed}: {read} against the book's means {book}"
        );
        let gain = j["yaw_rate_gain"].as_f64().unwrap();
        let spread = j["yaw_rate_gain_spread"].as_f64().unwrap();
        // The stated spread covers the gain's distance from the
        // noise-free one (about 3.5 % here, an upper estimate).
        assert!(
            (gain / clean_gain - 1.0).abs() < 2.5 * spread,
            "seed {seed}: {gain} against {clean_gain} ± {spread}"
        );
    }
}

/// The response times of the same noisy runs scatter about the
/// noise-free ones by what the noise allows; each run now states how far
/// its noise moves them (32 noisy copies, as for the peak), said where
/// that reaches a twentieth of the time, and the stated figure is the
/// seeds' own scatter to within the factors below (a copy carries the
/// noise twice: an upper estimate).
#[test]
fn a_response_time_the_noise_moves_is_said_with_the_spread_the_seeds_show() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let keys = [
        ("yaw_rate_response_time", "the yaw-rate response time, "),
        ("ay_response_time", "the ay response time, "),
    ];
    let (mut times, mut stated) = ([vec![], vec![]], [vec![], vec![]]);
    for seed in 11..=20u64 {
        let (j, w) = crate::trips_s90_met::measured(&noisy(&rows, dir.path(), seed), &[]);
        for (k, (key, words)) in keys.iter().enumerate() {
            let (t, sd) = (
                j[key].as_f64().unwrap(),
                j[format!("{key}_spread")].as_f64().unwrap(),
            );
            times[k].push(t);
            stated[k].push(sd);
            assert_eq!(
                w.contains(words),
                sd >= 0.05 * t,
                "seed {seed}, {key} {t} ± {sd}: {w}"
            );
        }
    }
    for k in 0..2 {
        let m = times[k].iter().sum::<f64>() / times[k].len() as f64;
        let n = times[k].len() as f64;
        let scatter = (times[k].iter().map(|t| (t - m).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
        stated[k].sort_by(f64::total_cmp);
        let median = stated[k][stated[k].len() / 2];
        assert!(
            scatter > 0.5 * median && scatter < 1.6 * median,
            "{}: seeds scatter {scatter} s, stated {median} s ({:?})",
            keys[k].0,
            stated[k]
        );
    }
    // The noise-free run says nothing of it.
    let (_, w) =
        crate::trips_s90_met::measured(&logged(&rows, dir.path(), "clean.csv", |c| c), &[]);
    assert!(!w.contains("the run's noise moves what it reads"), "{w}");
}

/// A yaw rate and ay rising linearly after the step (0.004 rad/s per s)
/// never settle; the warning bounded the gain read "off by up to about
/// 4.9 %" (the trend over one window) where it stood 28 % above the
/// car's. Now a drift that does not slow bounds nothing.
#[test]
fn a_drift_that_does_not_slow_bounds_no_gain() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let csv = logged(&rows, dir.path(), "drift.csv", |mut c| {
        let ramp = 0.004 * (c[0] - 1.0).max(0.0);
        c[4] += ramp;
        c[5] += 22.22 * ramp;
        c
    });
    let (j, w) = crate::trips_s90_met::measured(&csv, &[]);
    assert_eq!(j["settling"]["yaw_rate"]["converging"], false, "{j}");
    assert!(w.contains("and it drifts without slowing, so this record bounds neither where it settles nor whether it does"), "{w}");
    assert!(!w.contains("may be off by up to"), "{w}");
}

/// A steer range written in degrees as radians, `{ from = 0.0, to = 10.0,
/// step = 1.0 }`, was refused as "`sweep.steer` = 1: must lie within
/// ±0.785398", naming a value the file does not hold (the range's second
/// value, which reads like its `step`). Now the range's end is named at
/// its own key with the value written.
#[test]
fn a_steer_range_past_the_road_wheel_limit_names_the_end_the_file_writes() {
    let text = bundled_scenario("equilibria_steer.toml").replace(
        "steer = { from = 0.0, to = 0.2, step = 0.02 }",
        "steer = { from = 0.0, to = 10.0, step = 1.0 }",
    );
    let dir = scratch(&[("sweep.toml", &text)]);
    let e = fails_cleanly("equilibria", &dir.path().join("sweep.toml"), dir.path());
    assert!(
        e.contains("`sweep.steer.to` = 10: must lie within ±0.785398"),
        "{e}"
    );
    assert!(!e.contains("= 1:"), "{e}");
}
