//! The window test counts a slow sideslip floor as the bias test does
//! (session 102): an estimator's smooth sideslip trusted to the assumed
//! 0.005 rad is a gap in no window and no bias while its mean stays inside
//! three floors, and both tests find an offset of four. A sideslip whose
//! record is white, however quiet, and its uncertainty unstated, is a
//! sensor's: its floor stays white.

use super::trips_s101_beta39::{channel, replayed};
use super::*;

/// The estimator's sideslip two floors off (0.01 rad) on two seeds: its
/// floor counts slow in both tests, so no window of the run is beyond its
/// threshold (about three floors) and the mean is no bias; the line says
/// neither "a gap along the run" nor "a bias of". The binary of
/// session 101 counted the floor slow in the bias test only and white in
/// the windows, which averaged it down over each window's samples: every
/// window "a gap along the run" beside no bias (Putnam's page); main
/// counts it white in both and calls the mean "a bias". Four floors off
/// (0.02 rad): a bias, and a gap in every window.
#[test]
fn an_estimator_s_sideslip_two_floors_off_is_a_gap_in_no_window_and_no_bias() {
    for seed in [5, 6] {
        let dir = tempfile::tempdir().unwrap();
        let (stdout, gap) = replayed(dir.path(), seed, 0.01);
        let (line, beta) = channel(&stdout, &gap, "beta");
        assert_eq!(beta["bias_counting"], "slow", "{line}");
        assert_eq!(beta["bias_significant"], false, "{seed}: {line}");
        let w = &beta["worst_window"];
        assert_eq!(w["significant"], false, "{seed}: {line}");
        assert_eq!(w["windows_significant"], 0, "{seed}: {line}");
        assert_eq!(beta["gap_found"], false, "{seed}: {line}");
        assert!(
            !line.contains("a gap along the run") && !line.contains("a bias of"),
            "{seed}: {line}"
        );
    }
    let dir = tempfile::tempdir().unwrap();
    let (stdout, gap) = replayed(dir.path(), 5, 0.02);
    let (line, beta) = channel(&stdout, &gap, "beta");
    assert_eq!(beta["bias_significant"], true, "{line}");
    let w = &beta["worst_window"];
    assert_eq!(w["significant"], true, "{line}");
    assert_eq!(w["windows_significant"], w["windows_tested"], "{line}");
}

/// A sideslip logged with white noise of 0.0005 rad (a third of a slip
/// sensor's floor, so trusted to an estimated output's 0.005 rad) but
/// white, its differences correlated −½: a quiet sensor's record, not an
/// estimator's, so its floor counts white and a mean 1.5 floors off
/// (0.0075 rad) over 79 s is a bias of many standard errors. The binary of
/// session 101 counted it slow, once over the run, and called it none.
#[test]
fn a_quiet_white_sideslip_is_a_sensor_s_and_its_floor_counts_white() {
    let dir = tempfile::tempdir().unwrap();
    let noise = super::calibration::Noise(3);
    let scenario = noisy_step_replay(dir.path(), 80.0, noise, |n| {
        [
            0.0008 * n.gauss(),
            0.03 * n.gauss(),
            0.0005 * n.gauss() + 0.0075,
        ]
    });
    let out = dir.path().join("out");
    let stdout = super::scenarios::simulate_to(&scenario, &out);
    let gap = read_json(&out.join("gap.json"));
    let (line, beta) = channel(&stdout, &gap, "beta");
    assert!(
        (beta["noise_floor"].as_f64().unwrap() - 0.005).abs() < 1e-12,
        "{line}"
    );
    assert_eq!(beta["bias_counting"], "white", "{line}");
    assert_eq!(beta["bias_significant"], true, "{line}");
    assert!(line.contains("the floor counted as white noise"), "{line}");
}
