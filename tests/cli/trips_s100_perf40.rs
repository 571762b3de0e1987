//! `synth --duration`: an analogue programme's runs lengthened to a total
//! duration, so that the performance targets' long logs (600 s at 100 Hz
//! in three runs) are made by a command; refused, with the programmes that
//! take it, where the runs cannot be lengthened or would be shortened.

use super::*;

/// The number of rows (samples) of a run file.
fn samples(path: &Path) -> usize {
    fs::read_to_string(path).unwrap().lines().count() - 1
}

#[test]
fn a_sedan_campaign_lengthened_to_600_s_has_three_runs_of_600_s_together_at_100_hz() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("long");
    let said = succeeds(&[
        "synth",
        "--programme",
        "sedan-winding",
        "--duration",
        "600",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(said.contains("3 sedan-winding runs"), "{said}");
    // In proportion to the runs' own 120, 135 and 115 s, to whole seconds.
    let runs = out.join("runs");
    let lengths: Vec<usize> = ["winding_lap", "winding_stop", "winding_mirrored"]
        .iter()
        .map(|r| samples(&runs.join(format!("{r}.csv"))))
        .collect();
    assert_eq!(lengths, [19501, 21901, 18601]);
    // 100 Hz: the last sample of the first run at 195 s.
    let text = fs::read_to_string(runs.join("winding_lap.csv")).unwrap();
    let last = text.lines().last().unwrap().split(',').next().unwrap();
    assert!(
        (last.parse::<f64>().unwrap() - 195.0).abs() < 1e-9,
        "{last}"
    );
    // The campaign file says how it was made.
    let header = fs::read_to_string(out.join("vehicle.toml")).unwrap();
    assert!(
        header.contains("--programme sedan-winding --duration 600)"),
        "{header}"
    );
}

#[test]
fn a_duration_for_a_programme_of_fixed_runs_is_refused_naming_those_that_take_one() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("so");
    let o = run(&[
        "synth",
        "--programme",
        "slow-oval",
        "--duration",
        "900",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("--duration 900: the slow-oval programme's runs are fixed")
            && e.contains("sedan-winding (370 s by default), racing-rear-steer (300 s by default)"),
        "{e}"
    );
    assert!(!out.exists());
}

#[test]
fn a_duration_shorter_than_the_programmes_own_is_refused_and_a_non_number_too() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("short");
    let o = run(&[
        "synth",
        "--programme",
        "sedan-winding",
        "--duration",
        "200",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("--duration 200: the sedan-winding programme's runs last 370 s together")
            && e.contains("give 370 or more"),
        "{e}"
    );
    for bad in ["-5", "inf", "ten"] {
        let o = run(&[
            "synth",
            "--programme",
            "sedan-winding",
            "--duration",
            bad,
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(!o.status.success());
        let e = stderr(&o);
        assert!(
            e.contains("expected a number of seconds above 0"),
            "{bad}: {e}"
        );
    }
    assert!(!out.exists());
}
