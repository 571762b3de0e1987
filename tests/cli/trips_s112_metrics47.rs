//! Round 47's findings on `metrics` (session 112), on the bundled sedan's
//! 1° step (`simulate`, 1 kHz rows) logged at 100 Hz as the tester logged
//! it (t, speed, steer, yaw_rate, ay; noise of speed 0.05 m/s, steer
//! 0.0003 rad, yaw rate 0.003 rad/s, ay 0.08 m/s²):
//! 1. the noise lifts the overshoot (16.90 % clean, 18.9 % on average over
//!    five seeds) and makes the peak late, and the warning gave only a
//!    ± spread: the bias is now estimated from the noisy copies at three
//!    noise levels (SIMEX) and said, with the estimate without it;
//! 2. noise alone made "the response has not settled" (ay spread 2.2 %
//!    beyond its noise, one seed of five): the spread beyond the noise is
//!    now judged against its null distribution under the filtered noise;
//! 3. a record cut at 2.2 s marked only its response times: every value
//!    read from a moving window, and the total variances of a window the
//!    record ends inside, are marked in the table and in `marks`.

use super::*;

use crate::calibration::Noise;
use crate::trips_s111_metrics44::{measured, sedan_rows};

/// `rows` at 100 Hz up to `until` s, in the tester's layout, each row
/// through `f` (its time, steer, speed, yaw rate, ay in place), written
/// to `dir/name`.
fn logged(
    rows: &[[f64; 6]],
    dir: &Path,
    name: &str,
    until: f64,
    mut f: impl FnMut([f64; 6]) -> [f64; 6],
) -> PathBuf {
    let mut text = String::from("t,speed,steer,yaw_rate,ay\n");
    for r in rows.iter().step_by(10).filter(|r| r[0] <= until + 1e-9) {
        let c = f(*r);
        text.push_str(&format!(
            "{},{:.4},{:.6},{:.6},{:.4}\n",
            c[0], c[2], c[1], c[4], c[5]
        ));
    }
    let path = dir.join(name);
    fs::write(&path, text).unwrap();
    path
}

/// The tester's noise (`mknoise.py`) on `rows`, seeded by `seed`.
fn noisy(rows: &[[f64; 6]], dir: &Path, seed: u64, until: f64) -> PathBuf {
    let mut n = Noise(seed);
    logged(rows, dir, &format!("noisy_{seed}.csv"), until, |mut c| {
        c[2] += 0.05 * n.gauss();
        c[1] += 0.0003 * n.gauss();
        c[4] += 0.003 * n.gauss();
        c[5] += 0.08 * n.gauss();
        c
    })
}

/// The mean of `x` and its standard error.
fn mean_se(x: &[f64]) -> (f64, f64) {
    let n = x.len() as f64;
    let m = x.iter().sum::<f64>() / n;
    let var = x.iter().map(|v| (v - m).powi(2)).sum::<f64>() / (n - 1.0);
    (m, (var / n).sqrt())
}

const SEEDS: u64 = 20;

/// Finding 1: over 20 seeds of the tester's noise the overshoot read is
/// high on average by more than two standard errors of the clean record's
/// 16.90 % (18.75 ± 0.33 %); less its noise bias
/// (`yaw_rate_overshoot_noise_bias`) the mean is nearer it and within two
/// of its standard errors (17.56 ± 0.42 %). Not within one: on this
/// generator (a sum of 12 uniforms) the linear SIMEX removes about three
/// quarters of the lift (100 seeds: 18.76 ± 0.15 % read, 17.42 ± 0.19 %
/// less the bias), on Python's Gaussian all of it (50 seeds: 18.34 ±
/// 0.21 %, 16.90 ± 0.26 %). The warning says the bias and the estimate
/// without it. The clean record gets no bias and says none.
#[test]
fn the_noise_bias_of_the_overshoot_is_estimated_and_said() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let clean = logged(&rows, dir.path(), "clean100.csv", 10.0, |c| c);
    let (j, w, _) = measured(&clean, &[]);
    let truth = j["yaw_rate_overshoot"].as_f64().unwrap();
    assert!((truth - 16.90).abs() < 0.01, "{truth}");
    let bias = j["yaw_rate_overshoot_noise_bias"].as_f64().unwrap_or(0.0);
    assert!(bias.abs() < 0.005, "{bias}: {j}");
    assert!(!w.contains("biases the overshoot"), "{w}");
    let (mut read, mut corrected) = (Vec::new(), Vec::new());
    let mut said = 0;
    for seed in 1..=SEEDS {
        let (j, w, _) = measured(&noisy(&rows, dir.path(), seed, 10.0), &[]);
        let o = j["yaw_rate_overshoot"].as_f64().unwrap();
        let b = j["yaw_rate_overshoot_noise_bias"].as_f64().unwrap();
        read.push(o);
        corrected.push(o - b);
        if w.contains("biases the overshoot") {
            let without = format!("the overshoot is about {:.2} %", o - b);
            assert!(w.contains(&without), "{without}: {w}");
            said += 1;
        }
    }
    let ((m_read, se_read), (m_corr, se_corr)) = (mean_se(&read), mean_se(&corrected));
    assert!(
        (m_read - truth).abs() > 2.0 * se_read,
        "read {m_read} ± {se_read} of {truth}"
    );
    assert!(
        (m_corr - truth).abs() <= 2.0 * se_corr && (m_corr - truth).abs() < (m_read - truth).abs(),
        "corrected {m_corr} ± {se_corr} of {truth} (read {m_read} ± {se_read})"
    );
    assert!(said > 0, "no warning said the bias");
}

/// Finding 2: over 50 seeds of the tester's noise on the settled step (its
/// ay flat to 2e-7 m/s² over the last second) no run is called unsettled
/// (the threshold's false-alarm rate is 0.1 % a channel: 0.1 expected of
/// 50 runs of two channels) and no ay response time is marked; the record
/// cut at 2.2 s, and one whose yaw rate and ay drift by 15 % of their
/// steps a second from 3 s on, are still called unsettled.
#[test]
fn noise_alone_does_not_unsettle_a_settled_step() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let mut fired = Vec::new();
    for seed in 1..=50 {
        let (_, w, text) = measured(&noisy(&rows, dir.path(), seed, 10.0), &[]);
        if w.contains("has not settled") || text.contains("(moving window)") {
            fired.push(seed);
        }
    }
    assert!(
        fired.is_empty(),
        "unsettled by noise alone: seeds {fired:?}"
    );
    let (_, w, _) = measured(&noisy(&rows, dir.path(), 1, 2.2), &[]);
    assert!(w.contains("has not settled"), "{w}");
    let last = rows[rows.len() - 1];
    let mut n = Noise(7);
    let drift = logged(&rows, dir.path(), "drift.csv", 10.0, |mut c| {
        let ramp = 0.15 * (c[0] - 3.0).max(0.0);
        c[4] += ramp * last[4] + 0.003 * n.gauss();
        c[5] += ramp * last[5] + 0.08 * n.gauss();
        c[1] += 0.0003 * n.gauss();
        c
    });
    let (_, w, _) = measured(&drift, &[]);
    assert!(w.contains("has not settled"), "{w}");
}

/// Finding 3: the clean record cut at 2.2 s (the tester's `cut22.csv`):
/// the gain and steady ay read from the moving window are marked, and the
/// total variances, whose window the record ends inside, are marked cut
/// short, in the table and in `--json`'s `marks` alike, with the note
/// saying what each mark means; the whole record marks none.
#[test]
fn a_record_that_never_settles_marks_every_value_read_from_its_window() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let cut = logged(&rows, dir.path(), "cut22.csv", 2.2, |c| c);
    let (j, _, text) = measured(&cut, &[]);
    let line = |label: &str| {
        text.lines()
            .find(|l| l.trim_start().starts_with(label))
            .unwrap_or_else(|| panic!("{label}: {text}"))
            .to_string()
    };
    for label in ["yaw-rate gain", "steady ay", "E_r", "E_ay", "Er "] {
        assert!(line(label).contains("(moving window)"), "{label}: {text}");
    }
    for label in ["E_r", "E_ay", "Er "] {
        assert!(
            line(label).contains("(window cut short)"),
            "{label}: {text}"
        );
    }
    assert!(text.contains("window cut short: the record ends"), "{text}");
    let marks = &j["marks"];
    for key in ["yaw_rate_gain", "ay_steady", "er"] {
        let on = marks[key].to_string();
        assert!(on.contains("moving_window"), "{key}: {marks}");
    }
    for key in ["yaw_rate_total_variance", "ay_total_variance", "er"] {
        let on = marks[key].to_string();
        assert!(on.contains("window_cut"), "{key}: {marks}");
    }
    let cut_to = j["total_variance_window_cut"].as_f64().unwrap();
    assert!(cut_to > 1.0 && cut_to < 2.2, "{cut_to}");
    let whole = logged(&rows, dir.path(), "clean100.csv", 10.0, |c| c);
    let (j, _, text) = measured(&whole, &[]);
    assert_eq!(j["marks"], serde_json::json!({}), "{text}");
    assert!(j["total_variance_window_cut"].is_null(), "{j}");
    assert!(!text.contains("(moving window)") && !text.contains("(window cut short)"));
}
