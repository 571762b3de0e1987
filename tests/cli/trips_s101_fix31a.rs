//! What a user trips on in `synth`, as the round-31 tester found it:
//! `--duration` had no upper limit (1e9 s aborted on a failed allocation of
//! gigabytes) and took fractions of a second where the book says whole
//! seconds (370.5 made a last run of 115.5 s); the book said "white noise
//! on every measured channel" where the inputs, `steer` and `speed`, are
//! written as the driver gave them. The files are checked against the
//! book's words.

use super::*;

/// The synth chapter's text on one line (its sentences wrap).
fn book() -> String {
    let text = fs::read_to_string(root().join("docs/src/synth.md")).unwrap();
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// A run file's columns by name.
fn columns(path: &Path) -> std::collections::HashMap<String, Vec<f64>> {
    let (head, rows) = numeric_csv(path);
    head.iter()
        .enumerate()
        .map(|(i, h)| (h.clone(), rows.iter().map(|r| r[i]).collect()))
        .collect()
}

/// The scatter of `v`'s white noise: the standard deviation of its
/// successive differences over √2 (a smooth signal's differences vanish).
fn white_scatter(v: &[f64]) -> f64 {
    let d: Vec<f64> = v.windows(2).map(|w| w[1] - w[0]).collect();
    let mean = d.iter().sum::<f64>() / d.len() as f64;
    let var = d.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / d.len() as f64;
    (var / 2.0).sqrt()
}

/// `synth --programme sedan-winding --duration D`'s refusal.
fn duration_refused(d: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("long");
    let o = run(&[
        "synth",
        "--programme",
        "sedan-winding",
        "--duration",
        d,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success(), "{d}: ran");
    assert!(!out.exists(), "{d}: wrote {}", out.display());
    stderr(&o)
}

#[test]
fn a_duration_beyond_an_hour_is_refused_naming_the_value_and_the_limit() {
    for d in ["3601", "1e9"] {
        let e = duration_refused(d);
        assert!(
            e.contains("the sedan-winding programme's runs last at most 3600 s together")
                && e.contains("give a whole number of seconds from 370 to 3600"),
            "{d}: {e}"
        );
        assert!(!e.contains("memory allocation"), "{d}: {e}");
    }
    assert!(duration_refused("3601").contains("--duration 3601: "));
    assert!(book().contains("The longest total is 3600 s"));
}

#[test]
fn a_duration_of_a_fraction_of_a_second_is_refused_with_the_whole_seconds_beside_it() {
    let e = duration_refused("370.5");
    assert!(
        e.contains("--duration 370.5: the runs are lengthened to whole seconds")
            && e.contains("give 370 or 371"),
        "{e}"
    );
    assert!(book().contains("lengthens them to that total, a whole number of seconds"));
}

#[test]
fn the_handling_runs_noise_their_responses_and_write_steer_and_speed_as_driven() {
    let said = book();
    for words in [
        "The responses carry white Gaussian noise (seeded): `yaw_rate` 0.003 rad/s, `ay` 0.05 m/s², `beta` 0.002 rad",
        "The inputs, `steer` and `speed`, are written as the driver gave them, without noise",
        "On `handling` a run's `speed` is one value throughout and its `steer` the manoeuvre's exact shape (a step's: 0 before the step, its rise, then held)",
    ] {
        assert!(said.contains(words), "the book lacks: {words}");
    }
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "handling", &["--effects", "none"]);
    let run = columns(&c.join("runs/step_060kph_2ms2.csv"));
    // The responses: white noise of the stated size, over the held step's
    // last 2 s (the response settled: its own change is far below it).
    for (name, sigma) in [("yaw_rate", 0.003), ("ay", 0.05), ("beta", 0.002)] {
        let v = &run[name];
        let s = white_scatter(&v[v.len() - 200..]);
        assert!(
            (s / sigma - 1.0).abs() < 0.2,
            "{name}: scatter {s}, the book {sigma}"
        );
    }
    // The inputs as driven: one speed; a steer of 0, its rise, then held.
    let speed = &run["speed"];
    assert!(speed.iter().all(|u| *u == speed[0]), "speed varies");
    let steer = &run["steer"];
    let held = *steer.last().unwrap();
    assert!(steer[0] == 0.0 && held > 0.0);
    let first_held = steer.iter().position(|d| *d == held).unwrap();
    assert!(steer[first_held..].iter().all(|d| *d == held));
    assert!(steer[..first_held].windows(2).all(|w| w[1] >= w[0]));
}

#[test]
fn the_sedan_analogue_logs_speed_with_noise_and_steer_quantised_and_held_as_the_book_says() {
    let said = book();
    let words = "`sedan-winding`'s `speed` with 0.02 m/s of noise while moving and 0 at rest (wheel speeds), its `steer` quantised at 0.1° of steering wheel and held at the sensor's 20 Hz (five samples alike at 100 Hz; 0 on the straights)";
    assert!(said.contains(words), "the book lacks: {words}");
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "sedan", &["--programme", "sedan-winding"]);
    let run = columns(&c.join("runs/winding_lap.csv"));
    // Parked for its first 10 s (the driver moves off at about 9.7 s):
    // exactly 0; moving: noise of 0.02 m/s.
    let speed = &run["speed"];
    assert!(speed[..900].iter().all(|u| *u == 0.0));
    let moving: Vec<f64> = speed.iter().copied().filter(|u| *u > 1.0).collect();
    let s = white_scatter(&moving);
    assert!((s / 0.02 - 1.0).abs() < 0.25, "speed scatter {s}");
    // The steer: whole steps of 0.1° of steering wheel at the 16:1 ratio,
    // changing only every fifth sample (20 Hz held in the 100 Hz log).
    let step = 0.1_f64.to_radians() / 16.0;
    let steer = &run["steer"];
    assert!(steer
        .iter()
        .all(|d| (d / step - (d / step).round()).abs() < 1e-6));
    let changes: Vec<usize> = (1..steer.len())
        .filter(|&i| steer[i] != steer[i - 1])
        .collect();
    assert!(changes.len() > 100 && changes.iter().all(|i| i % 5 == 0));
}
