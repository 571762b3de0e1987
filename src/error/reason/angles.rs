//! Steer angles as every message writes them: rad to two significant
//! digits, or as many as its degrees show (up to four), with its degrees
//! to two decimals, "0.0175 rad (1.00°)", "0.0017 rad (0.10°)", one
//! format for one quantity wherever it is said (a sine's refusal wrote
//! "0.0100 rad (0.010°)", the metrics "0.010 rad (0.57°)"); and two angles
//! a sentence compares with the digits that tell them apart ("0.00015 rad
//! (0.009°), less than the 0.00017 rad (0.010°)", not "0.01° … 0.01°").

use crate::format::significant;

/// Below this a steer is a mean of rounding (a sweep's mean of 7.2e-16
/// rad), written 0, rad.
const ROUNDING: f64 = 1e-9;

/// The most digits or decimals a compared pair is written with: angles
/// that agree to six differ by less than any sensor resolves.
const MAX_DIGITS: usize = 6;

/// `v` rad with `digits` significant digits and its degrees with
/// `decimals` decimals; one below 1e-5 rad, far below any sensor's
/// resolution, in exponent form, not with sixteen zeros.
fn written(v: f64, digits: usize, decimals: usize) -> String {
    let v = if v.abs() < ROUNDING { 0.0 } else { v };
    let deg = crate::format::fixed(v.to_degrees(), decimals);
    let rad = if v != 0.0 && v.abs() < 1e-5 {
        format!("{v:.*e}", digits.max(1) - 1)
    } else {
        significant(v, digits)
    };
    format!("{rad} rad ({deg}°)")
}

/// The most significant digits an angle's rad takes to match its
/// degrees: four match a degree to two decimals up to 100°.
const RAD_DIGITS_FOR_DEGREES: usize = 4;

/// The significant digits of `v` rad that match its degrees to two
/// decimals (two at least, four at most): "0.10 rad (5.86°)" read as a
/// wrong conversion of 0.10 rad (5.73°).
fn rad_digits(v: f64) -> usize {
    let deg = crate::format::fixed(v.to_degrees(), 2);
    let digits: String = deg.chars().filter(char::is_ascii_digit).collect();
    digits
        .trim_start_matches('0')
        .len()
        .clamp(2, RAD_DIGITS_FOR_DEGREES)
}

/// An angle in rad with its degrees: "0.0017 rad (0.10°)".
pub(crate) fn angle(v: f64) -> String {
    written(v, rad_digits(v), 2)
}

/// `a` and `b` as [`angle`] writes them, each part (rad, degrees) with
/// as many more digits as make the two differ, both with the same number
/// so they read side by side: a sentence saying one is below the other
/// never prints two equal numbers.
pub(crate) fn compared(a: f64, b: f64) -> (String, String) {
    let (digits, decimals) = places(a, b);
    (written(a, digits, decimals), written(b, digits, decimals))
}

/// `v` with the digits and decimals [`compared`] writes `a` and `b` with:
/// an angle of the same sentence (the steady steer beside the change it
/// equals) in the same format as the pair.
pub(crate) fn compared_like(v: f64, a: f64, b: f64) -> String {
    let (digits, decimals) = places(a, b);
    written(v, digits, decimals)
}

/// The significant digits (rad) and decimals (degrees) that set `a` and
/// `b` apart, at least [`angle`]'s.
fn places(a: f64, b: f64) -> (usize, usize) {
    // Apart in rad, and in degrees with neither nonzero angle written as
    // zero degrees (0.000063 rad read "0.00°" beside "0.01°").
    let zero =
        |v: f64, deg: &str| v.abs() >= ROUNDING && !deg.chars().any(|c| ('1'..='9').contains(&c));
    let differ = |d: usize, e: usize| {
        let (x, y) = (written(a, d, e), written(b, d, e));
        let split = |s: &str| {
            s.split_once(" rad")
                .map(|(r, g)| (r.to_string(), g.to_string()))
        };
        match (split(&x), split(&y)) {
            (Some((ra, ga)), Some((rb, gb))) => {
                (ra != rb, ga != gb && !zero(a, &ga) && !zero(b, &gb))
            }
            _ => (true, true),
        }
    };
    let (mut digits, mut decimals) = (rad_digits(a).max(rad_digits(b)), 2);
    while digits < MAX_DIGITS && !differ(digits, decimals).0 {
        digits += 1;
    }
    while decimals < MAX_DIGITS && !differ(digits, decimals).1 {
        decimals += 1;
    }
    (digits, decimals)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compared_angles_print_apart_and_a_lone_one_in_the_one_format() {
        assert_eq!(angle(0.0174533), "0.0175 rad (1.00°)");
        // The rad as precise as the degrees beside it.
        assert_eq!(angle(0.1023), "0.102 rad (5.86°)");
        assert_eq!(angle(0.409), "0.4090 rad (23.43°)");
        assert_eq!(angle(0.0017), "0.0017 rad (0.10°)");
        assert_eq!(angle(1e-12), "0 rad (0.00°)");
        let (a, b) = compared(0.00015, 1.745e-4);
        assert_eq!(
            (a.as_str(), b.as_str()),
            ("0.00015 rad (0.009°)", "0.00017 rad (0.010°)")
        );
        // Equal to two digits in rad: a third.
        let (a, b) = compared(0.0172, 0.0174533);
        assert_eq!(
            (a.as_str(), b.as_str()),
            ("0.0172 rad (0.99°)", "0.0175 rad (1.00°)")
        );
        // A nonzero angle is not written as zero degrees.
        let (a, b) = compared(0.0000628, 1.745e-4);
        assert_eq!(
            (a.as_str(), b.as_str()),
            ("0.000063 rad (0.004°)", "0.00017 rad (0.010°)")
        );
        // Already apart: as `angle` writes them.
        assert_eq!(compared(0.1, 0.15).0, angle(0.1));
    }
}
