//! What a fresh user tripped on in `metrics` on measured step-steer logs:
//! a settled noise-free step logged at 20 Hz read as stuck sensors (its
//! steady window all masked, "do not use these metrics"), the samples of
//! a second step in the same log left uncounted, and the noise of `ay`
//! adding to `E_ay` and Er without a word where the yaw rate's is said.

use super::sedan_runs::{run_text, sedan_history, Noisy};
use super::*;

/// The stdout and stderr of `metrics file`, which must succeed.
fn said(file: &Path) -> String {
    let o = run(&["metrics", file.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o))
}

/// The bundled PAC89 GB/T 6323 step simulated into `dir`: its history
/// (1 kHz, noise-free, written to 9 digits) and its `metrics.json`.
fn pac89_step(dir: &Path) -> (PathBuf, serde_json::Value) {
    let sc = dir.join("step.toml");
    fs::write(&sc, bundled_scenario("step_gbt6323_pac89.toml")).unwrap();
    let out = dir.join("sim");
    succeeds(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    (
        out.join("history.csv"),
        read_json(&out.join("metrics.json")),
    )
}

/// `text` (a run file's) with the `ay` cell (column 4) of the rows at
/// times `from..=to` s set to its value at `from`: a logger that stopped
/// updating there.
fn freeze_ay(text: &str, from: f64, to: f64) -> String {
    let mut held: Option<String> = None;
    let mut out = String::new();
    for (k, line) in text.lines().enumerate() {
        let mut cells: Vec<String> = line.split(',').map(String::from).collect();
        if k > 0 {
            let t: f64 = cells[0].parse().unwrap();
            if t >= from - 1e-9 && t <= to + 1e-9 {
                cells[4] = held.get_or_insert_with(|| cells[4].clone()).clone();
            }
        }
        out += &(cells.join(",") + "\n");
    }
    out
}

/// The PAC89 step logged at 20 Hz: its yaw rate, `ay` and sideslip relax
/// onto their steady values within a few samples and then repeat them to
/// the last written digit. Each was "stuck" (yaw rate 66, `ay` 63,
/// sideslip 58 samples masked) and the whole steady window a fill ("do
/// not use these metrics"); now nothing is masked and the gain is the
/// simulation's. A noisy log whose `ay` freezes while the yaw rate and
/// sideslip go on moving by their noise is still stuck, within the run
/// and to its end.
#[test]
fn a_settled_step_at_20_hz_is_no_stuck_sensor_and_a_frozen_noisy_ay_still_is() {
    let dir = tempfile::tempdir().unwrap();
    let (history, sim) = pac89_step(dir.path());
    let file = dir.path().join("step20.csv");
    fs::write(&file, run_text(&history, 50, None)).unwrap();
    let (j, warnings) = metrics_json(&file);
    let c = &j["cleaning"];
    assert_eq!(c["samples_read"], 121, "{c}");
    assert_eq!(c["counts"]["stuck"], 0, "{c}");
    assert_eq!(c["samples_masked"], 0, "{c}");
    assert!(
        !warnings
            .iter()
            .any(|w| w.contains("do not use these metrics")),
        "{warnings:?}"
    );
    let (gain, simulated) = (
        j["yaw_rate_gain"].as_f64().unwrap(),
        sim["yaw_rate_gain"].as_f64().unwrap(),
    );
    assert!(
        (gain - simulated).abs() < 1e-4 * simulated,
        "{gain} {simulated}"
    );
    // Noise on the yaw rate and `ay`; `ay` frozen for 1 s of the steady
    // state, then to the end of the record.
    let noisy = Noisy {
        yaw: 5e-4,
        ay: 0.02,
        seed: 3,
        ay_gain: 1.0,
    };
    let text = run_text(&history, 50, Some(noisy));
    for (to, samples) in [(5.0, 21), (6.0, 41)] {
        fs::write(&file, freeze_ay(&text, 4.0, to)).unwrap();
        let (j, _) = metrics_json(&file);
        let c = &j["cleaning"];
        assert_eq!(c["counts"]["stuck"], 1, "{c}");
        let g = &c["glitches"][0];
        assert_eq!(
            (g["channel"].as_str(), g["t"].as_f64()),
            (Some("ay"), Some(4.0)),
            "{c}"
        );
        assert_eq!(g["samples"], samples, "{c}");
        assert_eq!(c["samples_masked"], samples, "{c}");
    }
}

/// The sedan's step (100 Hz, to 6 s) followed by its return (to 12 s):
/// "683 samples read", the 518 of the return gone without a word. All
/// 1201 are read now, and the return's part is a piece dropped, with its
/// span and its reason.
#[test]
fn the_later_steps_of_a_log_are_counted_and_dropped_with_their_reason() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let step = run_text(&history, 10, None);
    let rows: Vec<Vec<f64>> = step
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    let last = rows.last().unwrap().clone();
    // The return: every channel but time and speed mirrored about its
    // held value (a linear car's response to the steer going back).
    let mut text = step.clone();
    for r in rows.iter().skip(1) {
        let mut back = vec![r[0] + 6.0, r[1]];
        back.extend((2..6).map(|k| last[k] - r[k]));
        let cells: Vec<String> = back.iter().map(|v| v.to_string()).collect();
        text += &(cells.join(",") + "\n");
    }
    let file = dir.path().join("two_steps.csv");
    fs::write(&file, text).unwrap();
    let (j, warnings) = metrics_json(&file);
    let c = &j["cleaning"];
    assert_eq!(c["samples_read"], 1201, "{c}");
    assert_eq!(c["samples_kept"], 683, "{c}");
    assert_eq!(c["samples_in_dropped_pieces"], 518, "{c}");
    let p = &c["dropped_pieces"][0];
    assert_eq!(
        (p["t_start"].as_f64(), p["t_end"].as_f64()),
        (Some(6.83), Some(12.0)),
        "{p}"
    );
    assert_eq!(
        p["reason"],
        "it holds a later steer step (at 7.05 s): the metrics read the first step"
    );
    assert!(
        warnings
            .iter()
            .any(|w| w.contains("the run holds 2 steer steps")),
        "{warnings:?}"
    );
    let out = said(&file);
    assert!(out.contains("1201 samples read, 683 kept"), "{out}");
    assert!(out.contains("518 in 1 piece dropped"), "{out}");
    let line = format!(
        "piece {} (6.83–12.00 s, 518 samples) dropped: it holds a later steer step (at 7.05 s)",
        file.display()
    );
    assert!(out.contains(&line), "{out}");
}

/// The figure the `ay` warning says it adds to `E_ay`, s.
fn ay_figure(warnings: &[String]) -> Option<f64> {
    let w = warnings.iter().find(|w| w.starts_with("the ay noise ("))?;
    w.split("adds about ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .and_then(|v| v.parse().ok())
}

/// White noise on `ay` of 5 % of its steady value, the sedan's step at
/// 20 Hz (too slow for the 10 Hz low-pass: unfiltered): it raised `E_ay`
/// and Er by 0.009 s on average with no word. Now `ay_noise` is reported
/// and the warning says `W·σ²`, which over 16 seeds agrees with the mean
/// rise of `E_ay` within a third (its scatter is about a quarter). At
/// 100 Hz the low-pass cuts that noise to 2 % of the step, whose 0.002 s
/// is under a tenth of `E_ay`: not said. The clean run says nothing.
#[test]
fn metrics_says_what_ay_noise_adds_to_e_ay_and_er() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let file = dir.path().join("step.csv");
    fs::write(&file, run_text(&history, 50, None)).unwrap();
    let (clean, warnings) = metrics_json(&file);
    assert!(ay_figure(&warnings).is_none(), "{warnings:?}");
    let (e0, er0) = (
        clean["ay_total_variance"].as_f64().unwrap(),
        clean["er"].as_f64().unwrap(),
    );
    let steady = clean["ay_steady"].as_f64().unwrap();
    let noisy = |seed: u64| Noisy {
        yaw: 0.0,
        ay: 0.05 * steady,
        seed,
        ay_gain: 1.0,
    };
    let (mut rise, mut figure, mut said) = (0.0, 0.0, 0);
    for seed in 0..16 {
        fs::write(&file, run_text(&history, 50, Some(noisy(seed)))).unwrap();
        let (j, warnings) = metrics_json(&file);
        let sigma = j["ay_noise"].as_f64().unwrap();
        let added = 4.0 * sigma * sigma;
        if let Some(f) = ay_figure(&warnings) {
            assert!((f - added).abs() < 0.01 * added, "{f} {added}");
            said += 1;
        }
        let e = j["ay_total_variance"].as_f64().unwrap();
        // Er moves with E_ay alone: the yaw rate is untouched.
        assert!((j["er"].as_f64().unwrap() - er0 - (e - e0)).abs() < 1e-9);
        rise += (e - e0) / 16.0;
        figure += added / 16.0;
    }
    assert!(said >= 12, "said on {said} of 16 seeds");
    assert!((figure - rise).abs() < figure / 3.0, "{rise} {figure}");
    // At 100 Hz, filtered.
    fs::write(&file, run_text(&history, 10, Some(noisy(0)))).unwrap();
    let (j, warnings) = metrics_json(&file);
    let sigma = j["ay_noise"].as_f64().unwrap();
    assert!(sigma > 0.01 && sigma < 0.03, "{sigma}");
    assert!(ay_figure(&warnings).is_none(), "{warnings:?}");
}
