//! What a fresh-eyes check found after stop 74 in `simulate` and
//! `metrics` on absurd inputs, run as a user runs the tool: a sine too
//! slow to steer within its run, a record cut at its step, a racing log
//! read as a step steer, a yaw inertia ten times too large.

use super::*;

/// The bundled sedan (Gim tyres) with `manoeuvre` as its `[manoeuvre]`
/// table, written to `dir/<name>.toml`.
fn sedan_with(dir: &Path, name: &str, manoeuvre: &str) -> PathBuf {
    let text = bundled_scenario("sedan_step.toml");
    let head = text.split("[manoeuvre]").next().unwrap();
    let path = dir.join(format!("{name}.toml"));
    fs::write(&path, format!("{head}[manoeuvre]\n{manoeuvre}")).unwrap();
    path
}

/// A sine of 0.0001 Hz over 10 s steered 1.1e-4 rad of its 0.0175 rad
/// and ran straight without a word (the step steer's "no step" was for
/// steps only). It is refused at `frequency`, with the period against the
/// run and the steer reached; a sweep as slow likewise, at its higher
/// frequency; a sine whose quarter period fits runs.
#[test]
fn a_sine_too_slow_to_steer_within_its_run_is_refused_with_its_period() {
    let dir = tempfile::tempdir().unwrap();
    let sine = "kind = \"sine\"\nspeed = 20.0\namplitude = 0.0175\nfrequency = 0.0001\nstart = 0.0\nend = 10.0\n";
    let path = sedan_with(dir.path(), "slow", sine);
    let e = fails_cleanly("simulate", &path, dir.path());
    for said in [
        "slow.toml:23:13: `manoeuvre.frequency` = 0.0001: a sine of `frequency` = 0.0001 Hz has a period of 10000 s against a run of 10 s (`start` = 0 s to `end` = 10 s): within it the steer reaches only 0.00011 rad (0.006°), 0.63 % of its `amplitude` = 0.0175 rad (1.00°), less than the 0.00017 rad (0.010°) a manoeuvre must steer",
        "the car would run straight",
        "(`frequency` ≥ 0.025 Hz): is the frequency in Hz?",
    ] {
        assert!(e.contains(said), "{said}\n{e}");
    }
    let sweep = sine
        .replace("sine", "sweep")
        .replace("frequency = 0.0001", "f_start = 0.0\nf_end = 0.0002");
    let path = sedan_with(dir.path(), "slow_sweep", &sweep);
    let e = fails_cleanly("simulate", &path, dir.path());
    assert!(
        e.contains("slow_sweep.toml:24:9: `manoeuvre.f_end` = 0.0002: a sweep from `f_start` = 0 Hz to `f_end` = 0.0002 Hz (a mean of 0.0001 Hz) has a period of 10000 s against a run of 10 s"),
        "{e}"
    );
    let path = sedan_with(dir.path(), "quarter", &sine.replace("0.0001", "0.025"));
    let out = dir.path().join("ran");
    succeeds(&[
        "simulate",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
}

/// The sedan's history cut to start at `from` s (its step rises from 1.0
/// to 1.1 s), written as `dir/<name>.csv`.
fn cut_history(history: &str, dir: &Path, name: &str, from: f64) -> PathBuf {
    let mut lines = history.lines();
    let mut text = lines.next().unwrap().to_string() + "\n";
    for l in lines {
        let t: f64 = l.split(',').next().unwrap().parse().unwrap();
        if t >= from - 1e-9 {
            text += &format!("{l}\n");
        }
    }
    let path = dir.join(format!("{name}.csv"));
    fs::write(&path, text).unwrap();
    path
}

/// `metrics` on a record cut 0.01 s before its step advised "one of at
/// most 0.01 s ends before it moves" (an initial window of 0.01 s), and on
/// one cut after it said only that the steer stays at 1°. Both now say the
/// record starts in or after its step, with no straight running before it,
/// and the 0.5 s of it the metrics need.
#[test]
fn a_record_cut_at_its_step_says_it_holds_no_straight_running_before_it() {
    let dir = tempfile::tempdir().unwrap();
    let sc = sedan_with(
        dir.path(),
        "sedan",
        "kind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n",
    );
    let out = dir.path().join("run");
    succeeds(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let history = fs::read_to_string(out.join("history.csv")).unwrap();
    for from in [0.99, 1.05] {
        let cut = cut_history(&history, dir.path(), "during", from);
        let o = run(&["metrics", cut.to_str().unwrap()]);
        assert!(
            !o.status.success(),
            "{from}: a record cut at its step was measured"
        );
        let e = stderr(&o);
        assert!(
            e.contains("the record starts during its step"),
            "{from}: {e}"
        );
        assert!(
            e.contains("holds no steady straight running before the step"),
            "{e}"
        );
        assert!(
            e.contains("start the record at least 0.5 s before the steer moves"),
            "{e}"
        );
        assert!(!e.contains("ends before it moves"), "{e}");
    }
    let cut = cut_history(&history, dir.path(), "after", 1.1);
    let e = stderr(&run(&["metrics", cut.to_str().unwrap()]));
    assert!(
        e.contains("the wheels are already turned by 0.0175 rad (1.00°) in the initial window: a record that starts during or after its step holds no straight running before it"),
        "{e}"
    );
    assert!(e.contains("`pre_window` = 0.5 s before it"), "{e}");
}

/// `metrics` on the Putnam racing log described a step that is not there
/// ("after reaching 90 % of it at 2.04 s it is at 377 % of it"). It is
/// refused as no step steer, with the steer's span, its reversals and its
/// longest steady stretch.
#[test]
fn the_putnam_racing_log_is_no_step_steer() {
    let test = "the_putnam_racing_log_is_no_step_steer";
    let Some(log) = shared_data(test, "run_iac_putnam/putnam_run4_2.csv") else {
        return;
    };
    // The log's roll is in degrees (its README; the campaign declares
    // it): `metrics`, which levels ay by a logged roll, is told so.
    let o = run(&["metrics", log.to_str().unwrap(), "--degrees", "roll"]);
    assert_eq!(o.status.code(), Some(1));
    let e = stderr(&o);
    assert!(!e.contains("column `roll`"), "{e}");
    for said in [
        "no step steer in this record: the steer spans 0.4089 rad (23.43°), from -0.160 rad (-9.18°) to 0.2488 rad (14.25°), and reverses 13 times by more than 0.102 rad (5.86°)",
        "and holds within 0.0409 rad (2.34°) for at most 32.32 s (from 216.72 s)",
        "cut one such stretch out of the log to measure it",
    ] {
        assert!(e.contains(said), "{said}\n{e}");
    }
    assert!(!e.contains("377 %"), "{e}");
}

/// A yaw inertia ten times the sedan's passed (the dynamic index, 9.4,
/// was inside 0.1–10): refused at its line with the index and the inertia
/// an index of 1 gives.
#[test]
fn a_yaw_inertia_ten_times_too_large_is_refused_at_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let text = bundled_scenario("sedan_step.toml")
        .replace("yaw_inertia = 2315.0", "yaw_inertia = 23150.0");
    let path = dir.path().join("heavy.toml");
    fs::write(&path, text).unwrap();
    let e = fails_cleanly("simulate", &path, dir.path());
    assert!(
        e.contains("heavy.toml:8:15: `vehicle.yaw_inertia` = 23150: with mass = 1530 kg"),
        "{e}"
    );
    assert!(
        e.contains("yaw_inertia / (mass·a·b) = 8.16, outside 0.4–2.5"),
        "{e}"
    );
    assert!(
        e.contains("at an index of 1 the yaw inertia would be mass·a·b = 2836 kg·m²"),
        "{e}"
    );
}
