//! Whether the straights' `ay` offset is one an accelerometer has: the
//! book's automotive MEMS biases are 0.01–0.5 m/s² (`docs/src/diagnose.md`,
//! on the standstills' bank), and the straights' criteria let up to
//! [`super::STRAIGHT_AY`] through. An offset beyond [`MEMS_AY_BIAS`] there
//! that no agreeing standstill confirms is said with what it more likely
//! is: a turn read as a straight (its yaw rate read too small, a unit), an
//! unlogged crossfall or crown, a sensor tilted on its mount. Units: m/s².

use crate::measured::clean::RunChannel;

/// The largest bias of an automotive MEMS lateral accelerometer, m/s²
/// (the book's 0.01–0.5 m/s²).
pub const MEMS_AY_BIAS: f64 = 0.5;

/// The words appended to `channel`'s line where its straights read an
/// offset `straight` beyond [`MEMS_AY_BIAS`] in `ay` that no standstill
/// confirms (`confirmed`: standstills agree); empty otherwise.
pub(super) fn beyond_a_sensor(
    channel: RunChannel,
    straight: Option<f64>,
    confirmed: bool,
) -> String {
    let Some(mean) = straight.filter(|_| channel == RunChannel::Ay) else {
        return String::new();
    };
    // Standstills that agree confirm it: a sensor's own (a tilted mount),
    // no turn read as a straight.
    if mean.abs() <= MEMS_AY_BIAS || confirmed {
        return String::new();
    }
    format!(
        "; the straights' {} m/s² is beyond the 0.01–{MEMS_AY_BIAS} m/s² of an automotive MEMS accelerometer's bias: more likely a turn read as a straight (a yaw rate read too small: is its unit right?), an unlogged crossfall or crown, or the sensor tilted on its mount",
        crate::format::fixed(mean, 2)
    )
}
