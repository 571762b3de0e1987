//! The gap's words where a whole campaign shows what no run shows alone:
//! a channel within noise per run under a significant combined gap, and
//! a frequency band off in many runs said once.

use super::*;
use crate::diagnose::report::outcome::CombinedGap;
use crate::diagnose::report::Part;

/// A channel within noise alone under a significant combined gap is
/// neither said to be right nor called a gap: the table calls it "not
/// significant alone", and its line says the same, naming where the
/// combined gap lies (round 35: beta at 1.2 noise floors was "a gap spread
/// over the runs" beside the table's "not significant alone").
#[test]
fn a_channel_within_noise_alone_under_a_significant_combined_gap_is_no_gap_of_its_own() {
    use crate::diagnose::model::channels::Channel;
    let f = |alone: Vec<Channel>| GapFinding::Channel {
        channel: Channel::Beta,
        rms: 0.0046,
        noise_floor: 0.002,
        significant_runs: 0,
        significant_in: Vec::new(),
        within_in: Vec::new(),
        runs: 8,
        wrong: vec![],
        right: vec![Part::All],
        off_in_right: Vec::new(),
        offset: None,
        combined: Some(CombinedGap {
            heldout_error: 1.52,
            noise_level: 0.941,
            significant_alone: alone,
        }),
    };
    let head = "beta: RMS 0.0046 rad (noise floor 0.0020); significant in 0 of 8 runs: within noise alone (2.3 noise floors over the runs, below the 3 a channel, run or part needs alone), so no gap of its own";
    assert_eq!(
        finding(&f(vec![Channel::YawRate, Channel::Ay])),
        format!("{head}; the significant gap lies in yaw_rate and ay")
    );
    // No channel significant alone: the combination is, and its numbers
    // are named.
    assert_eq!(
        finding(&f(vec![])),
        format!("{head}; no channel is significant alone over all runs, but the channels together are (held-out error 1.520 against a noise level of 0.941): a gap spread thinly over the channels and runs, not in one place (the frequency bands and offsets below say more)")
    );
}

#[test]
fn a_band_off_in_several_runs_is_said_once_with_its_runs_counted() {
    let band = |run: &str, f_low: f64, gain: f64, phase: f64| GapFinding::Band {
        run: run.into(),
        f_low,
        f_high: 2.0 * f_low,
        gain_error_db: gain,
        phase_error_deg: phase,
    };
    let findings = [
        band("a.csv", 0.6, 0.9, 56.0),
        band("a.csv", 0.3, 0.4, 31.0),
        band("b.csv", 0.3, 1.6, 19.0),
        band("c.csv", 0.3, -0.2, 25.0),
        band("c.csv", 0.1, 0.0, 14.0),
    ];
    assert_eq!(
        band_lines(&findings, 29),
        [
            "c.csv: yaw-rate response 0.10–0.20 Hz off by 0.0 dB, +14° (simulated against measured: + the model leads)",
            "yaw-rate response 0.30–0.60 Hz off in 3 of 29 runs: -0.2 to +1.6 dB, +19 to +31° (simulated against measured: + the model leads; each run's in diagnosis.json)",
            "a.csv: yaw-rate response 0.60–1.20 Hz off by +0.9 dB, +56° (simulated against measured: + the model leads)",
        ]
    );
}

/// A few significant runs are named, with their RMS in noise
/// floors: a gap one run shows is not lost where no part over all runs
/// isolates it (round 24: "significant in 1 of 4 runs; wrong in:
/// nowhere", the run never named).
#[test]
fn a_gap_in_a_few_runs_names_them() {
    let finding = |n: usize| GapFinding::Channel {
        channel: crate::diagnose::model::channels::Channel::Beta,
        rms: 0.0040,
        noise_floor: 0.002,
        significant_runs: n,
        significant_in: (0..n).map(|k| (format!("run{k}.csv"), 0.0065)).collect(),
        within_in: (n..8).map(|k| (format!("run{k}.csv"), 0.0045)).collect(),
        runs: 8,
        wrong: vec![],
        right: vec![Part::All],
        off_in_right: Vec::new(),
        offset: None,
        combined: None,
    };
    let one = gap::channel(&finding(1));
    assert!(
        one.contains("significant in 1 of 8 runs (run0.csv: 0.0065 rad, 3.2 noise floors; RMS over all of each run's samples); wrong in: no part over all runs"),
        "{one}"
    );
    let three = gap::channel(&finding(3));
    assert!(three.contains("(run0.csv: 0.0065 rad, 3.2 noise floors; run1.csv: 0.0065 rad, 3.2 noise floors; run2.csv: 0.0065 rad, 3.2 noise floors; RMS over all of each run's samples)"), "{three}");
    // Four are named too (round 38: "significant in 4 of 8 runs" named
    // none); more in `cause_tests`.
    let four = gap::channel(&finding(4));
    assert!(
        four.contains(
            "significant in 4 of 8 runs (run0.csv: 0.0065 rad, 3.2 noise floors; run1.csv"
        ),
        "{four}"
    );
}
