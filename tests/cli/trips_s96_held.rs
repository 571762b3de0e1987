//! What a fresh-eyes round on simulated real logs (round 26B) left in the
//! cleaning of held channels: a 20 Hz steer in a 50 Hz log, held for 3
//! samples and 2 in turn, read at 16.7 Hz and replayed late. On runs the
//! `simulate`d car drove (the linear tyre, the shared vehicle), logged as
//! a logger would, diagnosed as a user runs it.

use super::trips_s95_real::held_steer_campaign;
use super::*;

/// Round 26B's `sedan_x0.toml`: "held: steer … updates every 3 samples of
/// the 50 Hz log (every 0.06 s, 16.7 Hz)" — the median hold, where a
/// 20 Hz update read at 50 Hz is held for 3 samples and 2 in turn — and
/// the steer interpolated between the samples where it changed, half of
/// its updates seen 0.01 s late. Now the mean update rate, 20 Hz, 2.5
/// samples, and the updates put back at their instants.
#[test]
fn a_steer_at_20_hz_in_a_50_hz_log_is_read_at_20_hz() {
    let dir = tempfile::tempdir().unwrap();
    // Every other row of the 100 Hz history: a 50 Hz log.
    let c = held_steer_campaign(dir.path(), 31, |i, _| i % 2 == 0);
    let (stdout, d) = diagnose(&c);
    let held = d["cleaning"]["held"].as_array().unwrap();
    assert_eq!(held.len(), 2, "{held:?}");
    for h in held {
        assert_eq!(h["channel"], "steer", "{h}");
        let rate = h["update_rate"].as_f64().unwrap();
        assert!((rate / 20.0 - 1.0).abs() < 2e-3, "{h}");
        let per = h["samples_per_update"].as_f64().unwrap();
        assert!((per - 2.5).abs() < 5e-3, "{h}");
    }
    assert!(
        stdout.contains("updates every 2.5 samples of the 50 Hz log (every 0.05 s, 20 Hz)"),
        "{stdout}"
    );
}
