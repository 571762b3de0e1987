//! Numbers as the messages show them: the shortest decimal that reads back
//! as the value when it is short (a value as the user wrote it: `0.0174533`,
//! `57296`, `23150000`), else six significant digits with the trailing zeros trimmed (a
//! bound computed in floating point: `0.1875`, not `0.18749999999999997`);
//! very small and very large magnitudes in exponent form (`1e-16`). And the
//! ranges of the range checks, a bound that is zero less a rounding guard
//! shown as the closed bound 0.

use std::fmt;

/// Significant digits of a short value, shown as it is.
const SHORT_DIGITS: usize = 12;

/// Significant digits of a value that is not short (noise of a computation).
const DIGITS: usize = 6;

/// A lower bound below zero by at most this is a rounding guard: the check
/// means "not negative".
const GUARD: f64 = 1e-9;

/// A window length `seconds` rounded down to hundredths, as a refusal
/// offers the longest window that fits (never longer than `seconds`, never
/// below 0): one rule for the initial and steady windows of `metrics` and
/// a scenario's `[metrics]`. A caller whose difference may fall a hair
/// below a hundredth by rounding (6 − 4.9) adds its own guard.
pub(crate) fn hundredths_down(seconds: f64) -> String {
    crate::format::fixed((seconds * 100.0).floor().max(0.0) / 100.0, 2)
}

/// A number formatted for a message ([`Display`](fmt::Display)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&number(self.0))
    }
}

/// The significant digits of a decimal text (no sign, point or exponent;
/// leading zeros not counted).
fn significant_digits(text: &str) -> usize {
    let mantissa = text.split(['e', 'E']).next().unwrap_or("");
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    digits.trim_start_matches('0').len()
}

/// `v` with at most `digits` significant digits, trailing zeros trimmed.
fn rounded(v: f64, digits: usize) -> String {
    let exponent = v.abs().log10().floor() as i32;
    let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
    let s = format!("{v:.decimals$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

/// `v` in exponent form, at most `digits` significant digits (`1e-16`,
/// `2.5e9`).
fn exponent_form(v: f64, digits: usize) -> String {
    let shortest = format!("{v:e}");
    if significant_digits(&shortest) <= SHORT_DIGITS {
        return shortest;
    }
    let s = format!("{v:.*e}", digits - 1);
    let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
    let mantissa = if mantissa.contains('.') {
        mantissa.trim_end_matches('0').trim_end_matches('.')
    } else {
        mantissa
    };
    format!("{mantissa}e{exp}")
}

/// `v` as the messages show it (see the module's documentation).
pub fn number(v: f64) -> String {
    if !v.is_finite() || v == 0.0 {
        return if v == 0.0 { "0".into() } else { format!("{v}") };
    }
    let size = v.abs();
    if !(1e-4..1e16).contains(&size) {
        return exponent_form(v, DIGITS);
    }
    let shortest = format!("{v}");
    if significant_digits(&shortest) <= SHORT_DIGITS {
        shortest
    } else {
        rounded(v, DIGITS)
    }
}

/// `v` as [`number`] shows it, at `digits` significant digits where it
/// has more than [`SHORT_DIGITS`].
fn number_at(v: f64, digits: usize) -> String {
    if !v.is_finite() || v == 0.0 {
        return number(v);
    }
    let shortest = format!("{v}");
    if !(1e-4..1e16).contains(&v.abs()) {
        exponent_form(v, digits)
    } else if significant_digits(&shortest) <= SHORT_DIGITS {
        shortest
    } else {
        rounded(v, digits)
    }
}

/// `v` and `bounds` as [`number`] shows them, at the fewest digits (six or
/// more) that tell `v` from each bound it is not (`1.5708 rad is outside
/// -1.570796 to 1.570796`, not `1.5708 … 1.5708`): a refused value never
/// reads as the limit it broke.
pub fn numbers_apart(v: f64, bounds: &[f64]) -> (String, Vec<String>) {
    let at = |d: usize| {
        (
            number_at(v, d),
            bounds.iter().map(|&b| number_at(b, d)).collect(),
        )
    };
    (DIGITS..=17)
        .map(at)
        .find(|(shown, b): &(String, Vec<String>)| {
            bounds.iter().zip(b).all(|(&x, t)| x == v || t != shown)
        })
        .unwrap_or_else(|| at(17))
}

/// What the check `lo < v ≤ hi` asks, after "must": `lie in (lo, hi]`;
/// `lie in [0, hi]` when `lo` is 0 less a rounding guard; `be greater than
/// lo` when `hi` is infinite.
pub fn range(lo: f64, hi: f64) -> String {
    let guard = (-GUARD..0.0).contains(&lo);
    if hi.is_finite() && lo == -hi && hi > 0.0 {
        return format!("lie within ±{}", Num(hi));
    }
    match (guard, hi.is_finite()) {
        (true, true) => format!("lie in [0, {}]", Num(hi)),
        (true, false) => "not be negative".into(),
        (false, true) => format!("lie in ({}, {}]", Num(lo), Num(hi)),
        (false, false) => format!("be greater than {}", Num(lo)),
    }
}

/// `v` beside the end of `lo..=hi` it passes, each with its unit and the
/// digits that tell them apart: "6000000 Pa is above 5000000 Pa, the
/// largest", not "outside 0 to 5000000 Pa" (a range whose other end a
/// reader takes for the least value accepted).
pub(crate) fn past_end(v: f64, lo: f64, hi: f64, unit: &str) -> String {
    let (v_text, b) = numbers_apart(v, &[lo, hi]);
    let u = |x: &str| match unit {
        "" => x.to_string(),
        _ => format!("{x} {unit}"),
    };
    // An angle's symmetric range is said as `identify` and the degrees
    // check say theirs, "beyond ±90°" with the end in radians beside: one
    // limit said two ways ("beyond ±90°" at 3 rad, "above 1.5708 rad" at
    // 1e300) read as two limits.
    if unit == "rad" && lo == -hi && v.abs() > hi {
        return format!(
            "{} is beyond ±{}° (±{}), the largest",
            u(&v_text),
            number(hi.to_degrees()),
            u(&b[1])
        );
    }
    match v > hi {
        true => format!("{} is above {}, the largest", u(&v_text), u(&b[1])),
        false => format!("{} is below {}, the least", u(&v_text), u(&b[0])),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_value_beside_its_bound_shows_the_digits_that_tell_them_apart() {
        let quarter = std::f64::consts::FRAC_PI_2;
        let past = quarter + 1e-12;
        assert_eq!(number(past), number(quarter));
        let (v, b) = numbers_apart(past, &[-quarter, quarter]);
        assert_eq!(
            (v.as_str(), b[1].as_str()),
            ("1.5707963268", "1.57079632679")
        );
        // A value typed short is shown as typed, the bound to the digits
        // that differ from it.
        #[allow(clippy::approx_constant)]
        let typed = 1.5708;
        let (v, b) = numbers_apart(typed, &[-quarter, quarter]);
        assert_eq!(
            (v.as_str(), b[0].as_str(), b[1].as_str()),
            ("1.5708", "-1.570796", "1.570796")
        );
        let (v, b) = numbers_apart(1e308, &[-1e6, 1e6]);
        assert_eq!((v.as_str(), b[1].as_str()), ("1e308", "1000000"));
        let (v, b) = numbers_apart(quarter, &[quarter]);
        assert_eq!(v, b[0]);
    }

    #[test]
    fn a_symmetric_range_reads_as_plus_or_minus() {
        assert_eq!(range(-45.0, 45.0), "lie within ±45");
        assert_eq!(range(0.0, 2.0), "lie in (0, 2]");
    }

    #[test]
    fn short_values_show_as_written_and_computed_noise_is_rounded() {
        assert_eq!(number(0.0174533), "0.0174533");
        assert_eq!(number(57296.0), "57296");
        assert_eq!(number(-2.5), "-2.5");
        assert_eq!(number(0.15 / 0.8), "0.1875");
        assert_eq!(number(0.1 + 0.2), "0.3");
        assert_eq!(number(240.00000000000003), "240");
        assert_eq!(number(1.0 / 3.0), "0.333333");
        assert_eq!(number(-2.0 / 3.0 * 1000.0), "-666.667");
        assert_eq!(number(0.0), "0");
        assert_eq!(number(-0.0), "0");
        assert_eq!(number(f64::NAN), "NaN");
        assert_eq!(number(f64::INFINITY), "inf");
    }

    #[test]
    fn tiny_and_huge_values_take_exponent_form() {
        assert_eq!(number(1e-16), "1e-16");
        assert_eq!(number(-1e-12), "-1e-12");
        assert_eq!(number(1e-14 / 3.0), "3.33333e-15");
        assert_eq!(number(2.315e7), "23150000");
        assert_eq!(number(2.5e16), "2.5e16");
        assert_eq!(number(1e30), "1e30");
        assert_eq!(number(0.0001), "0.0001");
    }

    #[test]
    fn a_guarded_zero_bound_is_the_closed_zero() {
        assert_eq!(range(-1e-12, 0.15 / 0.8), "lie in [0, 0.1875]");
        assert_eq!(range(1e-4, 0.05), "lie in (0.0001, 0.05]");
        assert_eq!(range(0.0, f64::INFINITY), "be greater than 0");
        assert_eq!(range(-1.0, 0.5), "lie in (-1, 0.5]");
    }
}
