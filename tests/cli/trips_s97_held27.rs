//! What a fresh-eyes round on simulated real logs (round 27B) found in the
//! cleaning of held channels: a steer held at 20 Hz in a 50 Hz log turned
//! a log with no error in it into "a model-form error outside the library".
//! A quantised steer repeats its value at every update on a straight and
//! through a steady turn; the hold of many updates was interpolated as one
//! ramp from its value to the next, seconds ahead of the steer. On runs the
//! `simulate`d car drove (the linear tyre, the shared vehicle), logged as a
//! logger would, diagnosed as a user runs it.

use super::scenarios::simulated_rows;
use super::trips_s95_real::{campaign, logged};
use super::*;

/// The shared vehicle on the linear tyre driven at `speed` m/s through
/// turns of `amplitude` rad, simulated at 100 Hz in `dir`: straights of
/// 2 s, a turn-in of 0.6 s (a third of the steer over its first half), a
/// steady 1.9 s, a 0.4 s unwind, the sign turning each time; its
/// history's rows. The kinks fall between the updates of a 20 Hz logger.
fn turns(dir: &Path, name: &str, speed: f64, amplitude: f64) -> Vec<Vec<f64>> {
    let (mut t, mut steer) = (vec![0.0], vec![0.0]);
    for k in 0..3 {
        let (s, a) = (
            0.013 + 5.0 * k as f64,
            amplitude * if k == 1 { -1.0 } else { 1.0 },
        );
        t.extend([2.0, 2.3, 2.6, 4.5, 4.9].map(|d| s + d));
        steer.extend([0.0, a / 3.0, a, a, 0.0]);
    }
    t.push(18.0);
    steer.push(0.0);
    let list = |v: &[f64]| {
        v.iter()
            .map(|x| format!("{x:?}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let manoeuvre = format!(
        "kind = \"schedule\"\nt = [{}]\nsteer = [{}]\nspeed = [{}]\n",
        list(&t),
        list(&steer),
        list(&vec![speed; t.len()])
    );
    simulated_rows(dir, name, &manoeuvre)
}

/// Two runs of [`turns`] (20 m/s, 0.03 rad; 15 m/s, 0.04 rad) logged at
/// 50 Hz with `sensor_bias` the candidate, the steer written to the
/// encoder's 2e-4 rad: updated at 20 Hz and held between when `held`
/// (on time at every 0.1 s, 0.01 s late between), else at every row.
fn turns_campaign(dir: &Path, held: bool) -> PathBuf {
    let mut runs = Vec::new();
    for (k, (name, speed, amplitude)) in [("a", 20.0, 0.03), ("b", 15.0, 0.04)]
        .into_iter()
        .enumerate()
    {
        let rows = turns(dir, name, speed, amplitude);
        let steer = |i: usize| {
            let update = if held { i - i % 5 } else { i };
            (rows[update][1] / 2e-4).round() * 2e-4
        };
        let text = logged(&rows, (41 + k as u64, 1.0), |i, _| i % 2 == 0, steer);
        runs.push((format!("{name}.csv"), text));
    }
    campaign(dir, "\"sensor_bias\"", &runs)
}

/// Round 27B's `s_clean.toml`: a sedan's log at 50 Hz with the steer held
/// at 20 Hz, "a gap (held-out error 1.220, noise level 0.877) that no
/// candidate effect explains … a model-form error outside the library",
/// where the same log unheld has "no significant gap: held-out error
/// 0.939". The steer stood still on the straights and at its stop, and
/// each such hold was ramped to the next update over its seconds. Now the
/// value stays until its last repeat: the held log gets its unheld twin's
/// verdict and held-out error to 5 % (the old ramps, up to 0.0025 rad
/// ahead for two seconds of each steady turn, took it to several times).
#[test]
fn a_steer_held_at_20_hz_through_straights_and_steady_turns_reads_as_its_unheld_twin() {
    let dir = tempfile::tempdir().unwrap();
    let (held_dir, twin_dir) = (dir.path().join("held"), dir.path().join("twin"));
    fs::create_dir_all(&held_dir).unwrap();
    fs::create_dir_all(&twin_dir).unwrap();
    let (_, twin) = diagnose(&turns_campaign(&twin_dir, false));
    let (stdout, held) = diagnose(&turns_campaign(&held_dir, true));
    assert_eq!(twin["cleaning"]["held"].as_array().unwrap().len(), 0);
    let channels = held["cleaning"]["held"].as_array().unwrap();
    assert_eq!(channels.len(), 2, "{channels:?}");
    assert!(
        channels.iter().all(|h| h["channel"] == "steer"),
        "{channels:?}"
    );
    assert_eq!(
        twin["gap"]["significant"], false,
        "{}",
        twin["gap"]["heldout_error"]
    );
    assert_eq!(held["verdict"]["kind"], twin["verdict"]["kind"], "{stdout}");
    let j = |d: &serde_json::Value| d["gap"]["heldout_error"].as_f64().unwrap();
    assert!(
        (j(&held) / j(&twin) - 1.0).abs() < 0.05,
        "held {} against its twin's {}: {stdout}",
        j(&held),
        j(&twin)
    );
}
