//! The words of small outcomes: shares removed, stated weights, axle
//! values without a unit.

use super::*;
use crate::diagnose::report::{ChannelNoise, ScaleSource};

#[test]
fn a_share_removed_at_or_below_zero_is_said_as_none() {
    assert_eq!(removal(30.04), "removes 30.0 % of it");
    assert_eq!(removal(-0.0), "removes none of it");
    assert_eq!(removal(0.04), "removes none of it");
    assert_eq!(
        removal(-0.5),
        "removes none of it (it leaves the held-out gap 0.5 % larger)"
    );
}

#[test]
fn a_stated_uncertainty_below_the_signal_floor_is_not_said_to_weigh_as_stated() {
    let note = |weighted| {
        note(&Note::UncertaintyBelowScatter {
            channel: crate::diagnose::model::channels::Channel::Beta,
            stated: 1e-6,
            scatter: 3.2e-4,
            weighted,
        })
    };
    let floored = note(3.22e-4);
    assert!(
        floored.contains("it is weighted by 0.00032 rad instead, 2 % of the channel's RMS signal")
            && !floored.contains("weighted as stated"),
        "{floored}"
    );
    assert!(note(1e-6).contains("it is weighted as stated"));
}

#[test]
fn a_dimensionless_axle_value_is_written_without_a_unit() {
    use crate::diagnose::base::identify::AxleValue;
    let value = |name, unit, value, std_error| AxleValue {
        name,
        unit,
        value,
        std_error,
        limit: None,
        held: false,
    };
    let said = axle_values(&[
        value("peak friction", "-", 1.129, 0.122),
        value("front cornering coefficient", "1/rad", 12.04, 2.51),
        value("peak friction", "-", 1.129, f64::NAN),
    ]);
    assert_eq!(said[0], "peak friction 1.129 ± 0.122");
    assert!(said[1].ends_with(" 1/rad"), "{}", said[1]);
    assert_eq!(said[2], "peak friction 1.129 (not pinned)");
}

#[test]
fn a_tiny_stated_uncertainty_and_the_scatter_are_said_with_their_digits_and_units() {
    use crate::diagnose::model::channels::Channel;
    let trust = |noise_floor, source, scatter| {
        channel_trust(&ChannelNoise {
            channel: Channel::Beta,
            unit: "rad",
            noise_floor,
            scale: noise_floor,
            source,
            scatter,
            runs: 2,
            other_side: 0,
            stated_excess: None,
        })
    };
    // Stated below its scatter: what judges the gap is said where the
    // floor is (round 43: a note's "weighted by … instead" read as it).
    assert_eq!(
        trust(1e-6, ScaleSource::Stated, 2e-4),
        "beta 1e-6 rad (stated), below its scatter 0.00020 rad: its gap is judged against the stated 1e-6 rad, the fits weigh it by that too"
    );
    assert_eq!(
        trust(0.004, ScaleSource::Stated, 2e-4),
        "beta 0.0040 rad (stated)"
    );
    assert_eq!(
        trust(0.0017, ScaleSource::SensorFloor, 0.00041),
        "beta 0.0017 rad (its sensor type's floor; scatter 0.00041 rad)"
    );
    assert_eq!(
        trust(0.005, ScaleSource::Estimated, 2.3e-5),
        "beta 0.0050 rad (an estimated output's: its scatter 2.3e-5 rad is below any sensor's)"
    );
}

#[test]
fn a_channel_read_near_the_line_between_sensor_and_estimate_says_so_and_how_to_settle_it() {
    use crate::diagnose::model::channels::Channel;
    // A sideslip at 0.54 of the slip sensor's floor, a sensor, with 7 of
    // its 23 runs reading alone as an estimated output.
    let said = channel_trust(&ChannelNoise {
        channel: Channel::Beta,
        unit: "rad",
        noise_floor: 0.0017,
        scale: 0.0027,
        source: ScaleSource::SensorFloor,
        scatter: 0.00092,
        runs: 23,
        other_side: 7,
        stated_excess: None,
    });
    assert_eq!(
        said,
        "beta 0.0017 rad (its sensor type's floor; scatter 0.00092 rad; near the line between a sensor and an estimated output: its scatter is 0.54 of its sensor type's floor, the line at 0.5; 7 of its 23 runs read alone fall on the side of an estimated output; read as a sensor, a shorter or calmer stretch may read it as an estimated output: where you know which it is, state its uncertainty under [channels])"
    );
    // A quiet gyro (0.28 of its floor) is a sensor, far from its line
    // (0.05 of the floor: a yaw rate is measured, not estimated).
    let said = channel_trust(&ChannelNoise {
        channel: Channel::YawRate,
        unit: "rad/s",
        noise_floor: 0.0017,
        scale: 0.0027,
        source: ScaleSource::SensorFloor,
        scatter: 0.00047,
        runs: 1,
        other_side: 0,
        stated_excess: None,
    });
    assert_eq!(
        said,
        "yaw_rate 0.0017 rad/s (its sensor type's floor; scatter 0.00047 rad/s, a quiet gyro's (a yaw rate is measured, not an estimator's output))"
    );
}

#[test]
fn a_stated_uncertainty_far_above_the_channels_scatter_is_said_where_it_is_trusted() {
    use crate::diagnose::model::channels::Channel;
    use crate::diagnose::model::scale::stated_excess;
    let excess = stated_excess(Channel::YawRate, ScaleSource::Stated, 0.04, 0.0025);
    let said = channel_trust(&ChannelNoise {
        channel: Channel::YawRate,
        unit: "rad/s",
        noise_floor: 0.04,
        scale: 0.04,
        source: ScaleSource::Stated,
        scatter: 0.0025,
        runs: 2,
        other_side: 0,
        stated_excess: excess,
    });
    assert_eq!(
        said,
        "yaw_rate 0.0400 rad/s (stated; 16× the channel's own scatter, 0.0025 rad/s: a gap below it is called insignificant only because of the statement)"
    );
}

/// A partial verdict whose rest lies above 1.3 × the noise level leaves
/// a share no candidate explains (below it, `tests.rs`: not shown to be a
/// gap).
#[test]
fn a_partial_verdicts_significant_rest_is_what_no_candidate_explains() {
    let mut v = super::tests::explained(42.0);
    if let Verdict::Explained(e) = &mut v {
        e.heldout_error_after = 2.006;
    }
    assert_eq!(
        statement(&v),
        "sensor_delay+relaxation_length explains part of the gap: held-out error 3.628 → 2.006 (noise level 0.941), 42.0 % of the gap above noise removed; the other 58.0 % no candidate explains"
    );
}
