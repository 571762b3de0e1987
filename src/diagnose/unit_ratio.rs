//! A unit hint for a replay's yaw-rate gain that is off by the ratio of a
//! degree to a radian: a gain of 180/π ≈ 57.3 (+35.2 dB) or π/180 ≈ 1/57.3
//! (−35.2 dB) between simulated and measured is what a channel in degrees
//! read as radians (or the other way) gives, not a vehicle the model
//! misses. The steer's unit check stops most such inputs first; a yaw rate
//! logged in deg/s that stays within a plausible rad/s range, or a steer
//! scaled within its bounds, passes it and shows here instead. Said only
//! within ±2 % of the ratio (±0.17 dB), where no vehicle effect lands by
//! chance.

/// The ratio of a degree to a radian, 180/π.
const DEGREES_PER_RADIAN: f64 = 180.0 / std::f64::consts::PI;

/// How close to 180/π (or its inverse), relative, a gain must be for the
/// hint: 2 %.
const WITHIN: f64 = 0.02;

/// The hint for a gain error of `gain_error_db` dB (simulated against
/// measured), where the gain ratio is within ±2 % of 180/π or π/180; None
/// elsewhere (and for no number).
pub(crate) fn degree_ratio_hint(gain_error_db: f64) -> Option<&'static str> {
    let ratio = 10f64.powf(gain_error_db.abs() / 20.0);
    ((ratio / DEGREES_PER_RADIAN - 1.0).abs() <= WITHIN).then_some(
        "a ratio of 180/π: is the steer (or the yaw rate) in degrees where radians are read, or the other way?",
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// dB of a gain ratio.
    fn db(ratio: f64) -> f64 {
        20.0 * ratio.log10()
    }

    #[test]
    fn a_gain_of_180_over_pi_either_way_gets_the_hint_within_two_percent() {
        for r in [
            DEGREES_PER_RADIAN,
            1.0 / DEGREES_PER_RADIAN,
            57.3,
            1.0 / 57.3,
        ] {
            assert!(degree_ratio_hint(db(r)).is_some(), "{r}");
        }
        // ±35.2 dB as the report rounds it.
        assert!(degree_ratio_hint(35.2).is_some() && degree_ratio_hint(-35.2).is_some());
        for r in [1.019, 0.981] {
            assert!(
                degree_ratio_hint(db(DEGREES_PER_RADIAN * r)).is_some(),
                "{r}"
            );
            assert!(degree_ratio_hint(db(1.0 / (DEGREES_PER_RADIAN * r))).is_some());
        }
    }

    #[test]
    fn other_gains_get_no_hint() {
        for r in [1.021, 0.979] {
            assert!(
                degree_ratio_hint(db(DEGREES_PER_RADIAN * r)).is_none(),
                "{r}"
            );
        }
        for g in [
            0.0,
            1.0,
            -7.0,
            20.0,
            30.0,
            40.0,
            -60.0,
            f64::NAN,
            f64::INFINITY,
        ] {
            assert!(degree_ratio_hint(g).is_none(), "{g}");
        }
    }
}
