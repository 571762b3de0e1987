//! Round 44's findings on `metrics` (session 111), each on records made
//! from the bundled sedan's 1° step (`simulate`, 1 kHz rows):
//! 1. a steer logged 80 ms late on a clean record read a response time of
//!    0.1076 s (0.1876 s aligned) and Er 0.0595 s (0.1251 s) without a
//!    word, its yaw rate at 21 % of its step while the steer still read
//!    its initial value: now the lead is measured and said, and the
//!    metrics timed from the steer are marked (text and JSON);
//! 2. at 20–25 Hz the steer's one or two ramp samples were read as a 0.2°
//!    grid ("±10 %") or set a noise on a noise-free steer (the gain
//!    "±6.2 %"): a grid is now read from held levels only;
//! 3. a record cut inside the overshoot read "overshoot < 14.6 %" where
//!    it is 16.9 %: a window the yaw rate still moves in bounds no
//!    overshoot, and the times read against it are marked.

use super::*;

use crate::calibration::Noise;
use crate::trips_s108_lead::history_rows;

/// The bundled sedan step simulated in `dir`: its 1 kHz rows (t, steer,
/// speed, beta, yaw_rate, ay).
pub(crate) fn sedan_rows(dir: &Path) -> Vec<[f64; 6]> {
    let out = dir.join("sedan");
    let scenario = root().join("scenarios/sedan_step.toml");
    succeeds(&[
        "simulate",
        scenario.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    history_rows(&out)
}

/// `rows` written to `dir/name`, every `every`-th row, through `f`.
pub(crate) fn written(
    rows: &[[f64; 6]],
    dir: &Path,
    name: &str,
    every: usize,
    mut f: impl FnMut(usize, [f64; 6]) -> [f64; 6],
) -> PathBuf {
    let mut text = String::from("t,steer,speed,beta,yaw_rate,ay\n");
    for (i, r) in rows.iter().enumerate().step_by(every) {
        let cells: Vec<String> = f(i, *r).iter().map(|v| format!("{v:.9e}")).collect();
        text.push_str(&format!("{}\n", cells.join(",")));
    }
    let path = dir.join(name);
    fs::write(&path, text).unwrap();
    path
}

/// `metrics --json` (with `args`) on `run`: the report, its warnings as
/// one string, and the terminal's table (the same run without `--json`).
pub(crate) fn measured(run: &Path, args: &[&str]) -> (serde_json::Value, String, String) {
    let mut all = vec!["metrics", run.to_str().unwrap()];
    all.extend(args);
    let text = run_ok(&all);
    all.push("--json");
    let j: serde_json::Value = serde_json::from_str(&run_ok(&all)).unwrap();
    let w = j["warnings"].to_string();
    (j, w, text)
}

/// The stdout of a run that succeeds.
fn run_ok(args: &[&str]) -> String {
    let o = super::run(args);
    assert!(o.status.success(), "{}", stderr(&o));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

const LATE: &str = "the steer is logged late against it";
const MISALIGNED: &str = "(steer misaligned)";

/// Finding 1: the steer column shifted 80 rows (80 ms) later, as the
/// tester's `m_lead.csv`: unfiltered and through the default low-pass, the
/// lead read is within 10 ms of 80 ms and said, with the fix, and the
/// response times and total variances are marked in the table; the same
/// record unshifted reads none (null in JSON, no mark, no word).
#[test]
fn a_steer_logged_80_ms_late_is_said_with_its_lead_and_the_aligned_record_is_not() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let lagged = written(&rows, dir.path(), "lead.csv", 1, |i, mut c| {
        c[1] = rows[i.saturating_sub(80)][1];
        c
    });
    for args in [&["--filter-hz", "0"][..], &[][..]] {
        let (j, w, text) = measured(&lagged, args);
        let lead = j["steer_logged_late"].as_f64().unwrap();
        assert!((lead - 0.080).abs() <= 0.010, "{args:?}: {lead}");
        assert!(w.contains(LATE) && w.contains("sensor_delay"), "{w}");
        assert!(w.contains("shift the steer column"), "{w}");
        for line in ["yaw-rate response time", "ay response time", "Er   "] {
            let said = text.lines().find(|l| l.contains(line)).unwrap();
            assert!(said.ends_with(MISALIGNED), "{line}: {text}");
        }
    }
    let aligned = written(&rows, dir.path(), "aligned.csv", 1, |_, c| c);
    for args in [&["--filter-hz", "0"][..], &[][..]] {
        let (j, w, text) = measured(&aligned, args);
        assert!(j["steer_logged_late"].is_null(), "{args:?}: {j}");
        assert!(
            !w.contains(LATE) && !text.contains(MISALIGNED),
            "{w}\n{text}"
        );
    }
}

/// Finding 1's other side: the aligned record logged at 100 Hz with
/// noise (gyro 0.003 rad/s, 4.6 % of the step; ay 0.1 m/s², β 0.001 rad,
/// steer 0.0002 rad) over eight seeds: the noise moves no yaw rate out of
/// its band before the steer, so no lead is said. The steer shifted
/// 150 ms later is said, its lead a lower bound (each band hides the
/// start of a move): at most the shift and one sample, more than two.
#[test]
fn noisy_records_with_their_channels_aligned_read_no_lead() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let noisy = |seed: u64, shift: usize| {
        let mut n = Noise(seed);
        let name = format!("n{seed}_{shift}.csv");
        written(&rows, dir.path(), &name, 10, |i, mut c| {
            c[1] = rows[i.saturating_sub(shift)][1] + 0.0002 * n.gauss();
            c[3] += 0.001 * n.gauss();
            c[4] += 0.003 * n.gauss();
            c[5] += 0.1 * n.gauss();
            c
        })
    };
    for seed in 1..=8 {
        let (j, w, _) = measured(&noisy(seed, 0), &[]);
        assert!(
            j["steer_logged_late"].is_null() && !w.contains(LATE),
            "seed {seed}: {w}"
        );
    }
    let (j, w, _) = measured(&noisy(1, 150), &[]);
    let lead = j["steer_logged_late"]
        .as_f64()
        .unwrap_or_else(|| panic!("{w}"));
    assert!(lead > 0.02 && lead <= 0.16, "{lead}");
}

/// Finding 2: the clean step resampled at 20 Hz and 25 Hz: no grid is
/// claimed of the steer, and the gain, equal to the 1 kHz record's within
/// 0.01 %, is given no ±6 % (its spread, where one is read, contains the
/// 1 kHz gain and stays under 1 %). The steer rounded to 0.2° at 1 kHz,
/// each level held on the ramp, still gets its note.
#[test]
fn a_slow_log_of_a_ramp_claims_no_grid_and_a_rounded_steer_still_does() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let full = written(&rows, dir.path(), "full.csv", 1, |_, c| c);
    let (j, _, _) = measured(&full, &[]);
    let gain = j["yaw_rate_gain"].as_f64().unwrap();
    for every in [50, 40] {
        let slow = written(&rows, dir.path(), &format!("s{every}.csv"), every, |_, c| c);
        let (j, w, _) = measured(&slow, &[]);
        assert!(!w.contains("steer is written in steps"), "{every}: {w}");
        assert!(!w.contains("the yaw-rate gain, "), "{every}: {w}");
        let read = j["yaw_rate_gain"].as_f64().unwrap();
        let spread = j["yaw_rate_gain_spread"].as_f64().unwrap_or(0.0);
        assert!(spread < 0.01, "{every}: {spread}");
        assert!(
            (read - gain).abs() <= (spread * read).max(1e-4 * gain),
            "{every}: {read} against {gain} ± {spread}"
        );
    }
    let q = 0.2f64.to_radians();
    let rounded = written(&rows, dir.path(), "rounded.csv", 1, |_, mut c| {
        c[1] = (c[1] / q).round() * q;
        c
    });
    let (_, w, _) = measured(&rounded, &[]);
    assert!(
        w.contains("steer is written in steps of 0.2 deg and its step is 1.000 deg, 5 of them"),
        "{w}"
    );
}

/// Finding 3: the record cut at 2.2 s, 1.2 s after the step, its yaw rate
/// still falling from its 16.9 % overshoot through the steady window: the
/// overshoot is not measured ("—", null), never "< x %", and the response
/// time read against the moving window is marked (text and JSON); the
/// whole record reads its overshoot, 16.9 %, unmarked.
#[test]
fn a_record_cut_inside_the_overshoot_bounds_no_overshoot_and_marks_its_times() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let cut: Vec<[f64; 6]> = rows
        .iter()
        .copied()
        .filter(|r| r[0] <= 2.2 + 1e-9)
        .collect();
    let short = written(&cut, dir.path(), "short.csv", 1, |_, c| c);
    let (j, _, text) = measured(&short, &[]);
    assert!(j["yaw_rate_overshoot"].is_null(), "{j}");
    assert_eq!(j["yaw_rate_window_moving"], true, "{j}");
    let line = |name: &str| text.lines().find(|l| l.contains(name)).unwrap().to_string();
    let overshoot = line("yaw-rate overshoot");
    assert!(
        !overshoot.contains('<') && overshoot.contains('—'),
        "{text}"
    );
    assert!(
        line("yaw-rate response time").ends_with("(moving window)"),
        "{text}"
    );
    assert!(
        !text.contains("no overshoot: no yaw-rate maximum"),
        "{text}"
    );
    assert!(text.contains("the overshoot may be larger"), "{text}");
    let full = written(&rows, dir.path(), "whole.csv", 1, |_, c| c);
    let (j, _, text) = measured(&full, &[]);
    let percent = j["yaw_rate_overshoot"].as_f64().unwrap();
    assert!((percent - 16.9).abs() < 0.1, "{percent}");
    assert_eq!(j["yaw_rate_window_moving"], false, "{j}");
    assert!(!text.contains("(moving window)"), "{text}");
}
