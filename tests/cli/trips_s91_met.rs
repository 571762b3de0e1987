//! What a fresh user tripped on in `metrics` (session 91, fresh-eyes
//! round 17, on logs of the tester's linear 2-DOF car): a 5 Hz log
//! refused by a limit of 5 Hz with advice to divide `t` by 1000, an
//! instant step's sideslip response masked as a spike and one channel's
//! spike refilling the other channels' sample, and an initial window
//! that took a steer sample on the ramp into the initial values.

use super::*;

/// The tester's linear car stepped by 0.01 rad at 25 m/s at 1 s over
/// `rise_time` s ([`crate::trips_s90_met::tester_step`]), its history.
fn tester_step(dir: &Path, rise_time: f64) -> PathBuf {
    crate::trips_s90_met::tester_step(dir, rise_time, "")
}

/// `history` (1 kHz) logged every `every` ms from row `from` (ms) on, its
/// first six columns (t, steer, speed, beta, yaw_rate, ay) with `beta`
/// taken through `beta(t, beta)`, written to `dir/name`.
fn logged(
    history: &Path,
    (every, from): (usize, usize),
    beta: impl Fn(f64, f64) -> f64,
    dir: &Path,
    name: &str,
) -> PathBuf {
    let text = fs::read_to_string(history).unwrap();
    let mut out = String::from("t,steer,speed,beta,yaw_rate,ay\n");
    for line in text.lines().skip(1 + from).step_by(every) {
        let mut c: Vec<f64> = line
            .split(',')
            .take(6)
            .map(|v| v.parse().unwrap())
            .collect();
        c[3] = beta(c[0], c[3]);
        let cells: Vec<String> = c.iter().map(|v| v.to_string()).collect();
        out.push_str(&format!("{}\n", cells.join(",")));
    }
    let path = dir.join(name);
    fs::write(&path, out).unwrap();
    path
}

use crate::trips_s90_met::measured;

/// The number `key` of a metrics report.
fn num(j: &serde_json::Value, key: &str) -> f64 {
    j[key].as_f64().unwrap_or_else(|| panic!("{key}: {j}"))
}

/// A 5 Hz log (median step 0.2 s, 1.8 − 1.6 = 0.20000000000000018) was
/// refused as "0.2 (5 Hz if in seconds), coarser than any handling run is
/// logged at (at most 0.2 s, 5 Hz)" and asked "is `t` in milliseconds
/// (0.2 ms: 5000 Hz)?". Now a step on the limit is measured (with the
/// coarse log's warnings), and a 4 Hz log is refused without the
/// milliseconds question (0.25 ms would be a 4 kHz log).
#[test]
fn a_5_hz_log_is_measured_and_a_4_hz_log_is_not_asked_about_milliseconds() {
    let dir = tempfile::tempdir().unwrap();
    let history = tester_step(dir.path(), 0.0);
    let csv = logged(&history, (200, 0), |_, b| b, dir.path(), "lin_5hz.csv");
    let (j, w) = measured(&csv, &[]);
    let gain = num(&j, "yaw_rate_gain");
    assert!((gain / 5.60416 - 1.0).abs() < 1e-3, "{gain}");
    assert!(w.contains("of a 5 Hz log"), "{w}");
    let csv = logged(&history, (250, 0), |_, b| b, dir.path(), "lin_4hz.csv");
    let o = run(&["metrics", csv.to_str().unwrap()]);
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("column `t`: the median time step is 0.25 (4 Hz if in seconds), coarser than any handling run is logged at (at most 0.2 s, 5 Hz): `t` is in seconds (FORMATS.md)"),
        "{e}"
    );
    assert!(!e.contains("milliseconds"), "{e}");
}

/// An instant step logged at 10 Hz: its sideslip's first sample after
/// the step (+0.00057 rad, then −0.00089 rad: the physical jump of an
/// instant steer) was masked as a spike, and the yaw rate and `ay` of
/// that sample refilled from their neighbours. Now no glitch is found.
#[test]
fn an_instant_steps_sideslip_response_is_no_spike() {
    let dir = tempfile::tempdir().unwrap();
    let history = tester_step(dir.path(), 0.0);
    let csv = logged(&history, (100, 0), |_, b| b, dir.path(), "lin_10hz.csv");
    let (j, _) = measured(&csv, &[]);
    let cleaning = &j["cleaning"];
    assert_eq!(cleaning["counts"]["spike"], 0, "{cleaning}");
    assert_eq!(cleaning["samples_masked"], 0, "{cleaning}");
}

/// A real spike of the sideslip at 1.2 s (0.02 rad) of the same 10 Hz
/// log is found and masked in the sideslip only: the yaw rate of that
/// sample was refilled from its neighbours with it, and its response
/// time and E_r moved. Now the yaw-rate metrics are those of the log
/// without the spike.
#[test]
fn one_channels_spike_masks_that_channel_only() {
    let dir = tempfile::tempdir().unwrap();
    let history = tester_step(dir.path(), 0.0);
    let clean = logged(&history, (100, 0), |_, b| b, dir.path(), "clean.csv");
    let spiked = |t: f64, b: f64| if (t - 1.2).abs() < 1e-9 { 0.02 } else { b };
    let csv = logged(&history, (100, 0), spiked, dir.path(), "spiked.csv");
    let (a, _) = measured(&clean, &[]);
    let (b, _) = measured(&csv, &[]);
    let glitches = b["cleaning"]["glitches"].as_array().unwrap();
    assert_eq!(glitches.len(), 1, "{glitches:?}");
    assert_eq!(glitches[0]["channel"], "beta", "{glitches:?}");
    assert!((glitches[0]["t"].as_f64().unwrap() - 1.2).abs() < 1e-9);
    for key in [
        "yaw_rate_response_time",
        "yaw_rate_total_variance",
        "ay_response_time",
        "ay_total_variance",
    ] {
        assert!(
            (num(&a, key) - num(&b, key)).abs() < 1e-12,
            "{key}: {a} {b}"
        );
    }
}

/// A step ramped over 0.1 s logged at 12.5 Hz with a sample 20 % up the
/// ramp (1.02 s) inside the default initial window (0.54–1.04 s): that
/// sample was taken into the initial values, and the steer step read
/// 0.5566° for 0.5730° (−2.9 %), the gain 2.7 % high and E_r 16 % high.
/// Now the initial window ends at the last sample before the steer moves,
/// and the metrics are those of a window that ends there.
#[test]
fn the_initial_window_ends_before_the_steer_moves() {
    let dir = tempfile::tempdir().unwrap();
    let history = tester_step(dir.path(), 0.1);
    let csv = logged(&history, (80, 540), |_, b| b, dir.path(), "ramp_12hz.csv");
    let (j, _) = measured(&csv, &[]);
    let step = num(&j, "steer_step");
    assert!((step / 0.01 - 1.0).abs() < 1e-6, "{step}");
    let gain = num(&j, "yaw_rate_gain");
    assert!((gain / 5.60416 - 1.0).abs() < 1e-4, "{gain}");
    let (short, _) = measured(&csv, &["--pre-window", "0.45"]);
    for key in ["yaw_rate_total_variance", "ay_total_variance", "er"] {
        assert!(
            (num(&j, key) - num(&short, key)).abs() < 1e-12,
            "{key}: {j} {short}"
        );
    }
}

/// The gain and how far its yaw rate is said to move in the window (a
/// deviation, no bound: round 44) on a record ending 0.6 s after an
/// instant step read with `--steady-window` `w`: (gain, move %).
fn gain_and_bound(csv: &Path, w: &str) -> (f64, f64) {
    let (j, warnings) = measured(csv, &["--steady-window", w]);
    let gain = num(&j, "yaw_rate_gain");
    let said = format!("the yaw-rate gain, {gain:.4} 1/s, is no steady-state gain: read over a window its yaw rate still moves in, by ");
    let bound = warnings
        .split(&said)
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("{w}: {warnings}"));
    (gain, bound)
}

/// A record ending 0.6 s after an instant step read with a stated
/// `--steady-window 0.3`: the window sits on the yaw rate's overshoot as
/// it decays (its spread 1.2 % of the step), and the gain read 4.4 % high
/// with the yaw rate called settled. Now the window's turn is read: the
/// gain is said to be no steady-state gain, its yaw rate moving there by
/// its window's range (4.2 % for 4.4 %).
#[test]
fn a_stated_steady_window_on_an_overshoot_is_said_to_read_no_steady_gain() {
    let dir = tempfile::tempdir().unwrap();
    let history = tester_step(dir.path(), 0.0);
    let csv = logged(&history, (1, 0), |_, b| b, dir.path(), "cut06.csv");
    let text = fs::read_to_string(&csv).unwrap();
    let cut: Vec<&str> = text
        .lines()
        .take_while(|l| {
            l.split(',')
                .next()
                .unwrap()
                .parse::<f64>()
                .map_or(true, |t| t <= 1.6 + 1e-9)
        })
        .collect();
    fs::write(&csv, cut.join("\n") + "\n").unwrap();
    let (gain, bound) = gain_and_bound(&csv, "0.3");
    let off = 100.0 * (gain / 5.60416 - 1.0);
    assert!(off > 4.0, "{gain}");
    assert!(
        bound >= 0.9 * off && bound <= 1.5 * off,
        "{bound} % for {off} %"
    );
}
