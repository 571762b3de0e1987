//! The words of a road estimate's offsets ([`super::road`]): the sensor
//! offsets removed from `ay` (m/s²), the yaw rate (rad/s) and the sideslip
//! (rad) before the bank was estimated from `ay − u·r − d(u·β)/dt` (ISO
//! 8855), those not 0 only.

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
