//! The words of a road estimate's offsets ([`super::road`]): the sensor
//! offsets removed from `ay` (m/s²), the yaw rate (rad/s) and the sideslip
//! (rad) before the bank was estimated from `ay − u·r − d(u·β)/dt` (ISO
//! 8855), those not 0 only; and a bank estimate that no other run of the
//! campaign shows, as the bank, `ay` offset or yaw-rate offset it reads
//! alike with (round 39: a yaw-rate offset of +0.02 rad/s in one run on
//! flat ground said as a bank of −2.0°).

use super::road::{BankApart, BySpeed};

/// The offsets removed, in words: those not 0 only (an offset the
/// calibration did not take, as an `ay` beyond a mounted sensor's, is not
/// removed, and is not said to be).
pub(super) fn removed(ay: f64, yaw_rate: f64, beta: f64) -> String {
    let mut parts = Vec::new();
    if ay != 0.0 {
        parts.push(format!("ay {ay:.3} m/s²"));
    }
    if yaw_rate != 0.0 {
        // Four decimals, as the calibration's line; a smaller offset to
        // two significant digits in plain decimals as the calibration's
        // line writes it (0.000073, not 0.0000, nor 7.3e-5 beside its
        // "0.00007 ± 0.00012").
        let r = if yaw_rate.abs() >= 1e-3 {
            format!("{yaw_rate:.4}")
        } else {
            crate::format::significant(yaw_rate, 2)
        };
        parts.push(format!("yaw rate {r} rad/s"));
    }
    if beta != 0.0 {
        parts.push(format!("beta {} rad", crate::format::readable(beta, 3)));
    }
    let what = if parts.len() == 1 {
        "offset"
    } else {
        "offsets"
    };
    format!(
        " less the {what} the calibration measured ({})",
        parts.join(", ")
    )
}

/// A bank estimate no other run shows ([`BankApart`]), in words: the three
/// things one run's `ay − u·r` reads alike, and what would tell them
/// apart, from the run's speeds (`by_speed`) where they vary. `speed`:
/// the run's median, m/s.
pub(super) fn apart(a: &BankApart, speed: f64, by_speed: Option<BySpeed>) -> String {
    let deg = |x: f64| crate::format::fixed(x.to_degrees(), 1);
    let alike = format!(
        "; a steady {}° that the other {} runs do not show (their median {}°): a bank of {}°, an ay offset of {} m/s² or a yaw-rate offset of {} rad/s at its {} m/s read alike in one run's ay − u·r",
        deg(a.bank),
        a.other_runs,
        deg(a.others),
        deg(a.bank - a.others),
        crate::format::signed(a.ay_offset, 3),
        crate::format::signed(a.yaw_rate_offset, 4),
        crate::format::fixed(speed, 1)
    );
    let tell = match by_speed {
        None => "; at one speed the run cannot tell them apart: a yaw-rate offset's bank grows with the speed, a bank's and an ay offset's do not (the same ground at another speed tells it), and a standstill in the run shows a sensor's offset (the calibration's)".to_string(),
        Some(b) => {
            let read = format!(
                "over its speeds it reads {}° at {} m/s and {}° at {} m/s",
                deg(b.slow_bank),
                crate::format::fixed(b.slow_speed, 1),
                deg(b.fast_bank),
                crate::format::fixed(b.fast_speed, 1)
            );
            match b.scales_with_speed() {
                true => format!("; {read}, growing with the speed as a yaw-rate offset's does (a bank's and an ay offset's would not)"),
                false => format!("; {read}, not growing with the speed as a yaw-rate offset's would: a bank or an ay offset, which a standstill in the run tells apart (an offset reads there, a bank does not)"),
            }
        }
    };
    alike + &tell
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_small_yaw_rate_offset_reads_in_plain_decimals() {
        assert_eq!(
            super::removed(0.0, 7.3e-5, 0.0),
            " less the offset the calibration measured (yaw rate 0.000073 rad/s)"
        );
    }
}
