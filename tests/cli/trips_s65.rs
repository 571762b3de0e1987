//! What a fresh-eyes user still tripped on in `metrics` and `simulate`
//! input handling (issue 41): a steady window reaching back over the step,
//! accepted and measured as if the steer were held.

use super::*;

/// The bundled sedan step steer (1° at 1.0–1.1 s, to 6 s) in `dir`, with
/// `extra` appended to its text.
fn sedan(dir: &Path, extra: &str) -> PathBuf {
    let path = dir.join("sedan_step.toml");
    fs::write(&path, bundled_scenario("sedan_step.toml") + extra).unwrap();
    path
}

/// The sedan's history, simulated into `dir/run`.
fn sedan_history(dir: &Path) -> PathBuf {
    let sc = sedan(dir, "");
    let out = dir.join("run");
    succeeds(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    out.join("history.csv")
}

/// `metrics <history> --filter-hz 0 --steady-window <window>`.
fn metrics_with_window(history: &Path, window: &str) -> Output {
    run(&[
        "metrics",
        history.to_str().unwrap(),
        "--filter-hz",
        "0",
        "--steady-window",
        window,
    ])
}

/// A 5 s steady window on a 6 s record whose steer ramps from 1.0 to 1.1 s
/// averaged the ramp into the "steady" values; it is refused with where the
/// steer settles and the longest window that starts after it, and that
/// window is measured (it reads the whole step, where the 5 s window read
/// less).
#[test]
fn a_steady_window_over_the_step_is_refused_with_where_the_steer_settles() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let o = metrics_with_window(&history, "5");
    assert!(!o.status.success(), "a window over the step was measured");
    let e = stderr(&o);
    assert!(
        e.contains("inside the steady window (1.00–6.00 s, `--steady-window` = 5 s)"),
        "{e}"
    );
    assert!(
        e.contains("only at 1.10 s, so a `--steady-window` of at most 4.90 s starts after it"),
        "{e}"
    );
    let ok = metrics_with_window(&history, "4.9");
    assert!(ok.status.success(), "{}", stderr(&ok));
    let stdout = String::from_utf8_lossy(&ok.stdout);
    // The whole step is read once the window no longer reaches back over it.
    let step = stdout.lines().find(|l| l.contains("steer step")).unwrap();
    assert!(step.ends_with(" 1.0000 deg"), "{stdout}");
}

/// The same window in a scenario's `[metrics]` is refused when the
/// scenario is read, at its key, before the run.
#[test]
fn a_scenarios_steady_window_over_the_step_is_refused_at_its_key() {
    let dir = tempfile::tempdir().unwrap();
    let sc = sedan(dir.path(), "\n[metrics]\nsteady_window = 5.2\n");
    let out = dir.path().join("out");
    let o = run(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = refused(&o, &out);
    assert!(e.contains("`metrics.steady_window` = 5.2"), "{e}");
    assert!(
        e.contains("starts before the steer settles at its step at 1.1 s (`start` + `rise_time`)"),
        "{e}"
    );
    assert!(
        e.contains("a `steady_window` of at most 4.90 s starts after it"),
        "{e}"
    );
}
