//! Numbers as messages and reports print them: no negative zero (a camber
//! level a hair below 0 is "0.00°"), significant digits for values that
//! span decades, and two values compared in a sentence printed with the
//! digits that tell them apart; and a name the user mistyped answered
//! with the known one it is nearest ([`did_you_mean`]). This module imports
//! nothing, so that any layer (the errors, identification, the jobs) can
//! use it.

/// `n thing` or `n things`: a count with its noun in the number it takes
/// ("1 sample", "0 samples", "2 samples").
pub fn plural(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// `v` with `decimals` decimals; a value that rounds to zero prints as an
/// unsigned zero (a camber of −1e-5 rad is "0.00°", not "-0.00°").
pub fn fixed(v: f64, decimals: usize) -> String {
    unsigned_zero(format!("{v:.decimals$}"))
}

/// `v` to `decimals` decimals with its sign, `+` for a positive value
/// (`+3.5`, `-0.2`) and none for what rounds to zero (`0.0`, never `-0.0`
/// or `+0.0`): a change or an error read by its sign.
pub fn signed(v: f64, decimals: usize) -> String {
    let s = fixed(v, decimals);
    if s.starts_with('-') || s.chars().all(|c| c == '0' || c == '.') {
        s
    } else {
        format!("+{s}")
    }
}

/// `v` with `digits` significant digits in fixed notation (no negative
/// zero): slopes spanning 1e1–1e6 read naturally.
pub fn significant(v: f64, digits: usize) -> String {
    if v == 0.0 || !v.is_finite() {
        return fixed(v, 0);
    }
    let magnitude = v.abs().log10().floor() as i64;
    let decimals = (digits as i64 - 1 - magnitude).max(0) as usize;
    let written = fixed(v, decimals);
    // Rounding up across a power of ten (0.00999 to 0.0100) adds a
    // digit: the value is written with one decimal fewer, "0.010".
    let rolled_over = written
        .parse::<f64>()
        .is_ok_and(|w| w.abs() >= 10f64.powi((magnitude + 1) as i32));
    if rolled_over && decimals > 0 {
        fixed(v, decimals - 1)
    } else {
        written
    }
}

/// `v` to `digits` significant digits as a reader reads it: plain
/// decimals from 1e-4 to below 1e6 (`2.049`, not `2.049e0`; `0.000275`,
/// not `0.0000`), an exponent beyond (`1.68e7`, `2.7e-11`, `4e305`: no
/// number printed with hundreds of digits); zero as `0`.
pub fn readable(v: f64, digits: usize) -> String {
    if v == 0.0 || !v.is_finite() {
        return fixed(v, 0);
    }
    if (1e-4..1e6).contains(&v.abs()) {
        return significant(v, digits);
    }
    let s = format!("{v:.*e}", digits.max(1) - 1);
    // `1.50e5` reads as `1.5e5`: trailing zeros of the mantissa dropped.
    match s.split_once('e') {
        Some((m, e)) if m.contains('.') => {
            format!("{}e{e}", m.trim_end_matches('0').trim_end_matches('.'))
        }
        _ => s,
    }
}

/// `v` rounded to `digits` significant digits and written without the
/// zeros that rounding leaves (`50`, not `50.0`; `0.0025`, not
/// `0.00250`): a limit a user types back.
pub fn rounded(v: f64, digits: usize) -> String {
    readable(v, digits)
        .parse::<f64>()
        .map_or_else(|_| readable(v, digits), exact)
}

/// A positive `v` rounded down to `digits` significant digits, written as
/// [`rounded`] writes it: a limit that must not be exceeded (a step below
/// 0.016667 s reads `0.0166`, not `0.0167`).
pub fn rounded_down(v: f64, digits: usize) -> String {
    if !(v.is_finite() && v > 0.0) {
        return rounded(v, digits);
    }
    let scale = 10f64.powi(digits as i32 - 1 - v.log10().floor() as i32);
    // A hair of slack so that 0.0125 (stored a little below) stays 0.0125.
    rounded(((v * scale) * (1.0 + 1e-12)).floor() / scale, digits)
}

/// A positive `v` rounded up to `digits` significant digits, written as
/// [`rounded`] writes it: a least value to reach (a step of at least
/// 0.00301 s reads `0.0031`).
pub fn rounded_up(v: f64, digits: usize) -> String {
    if !(v.is_finite() && v > 0.0) {
        return rounded(v, digits);
    }
    let scale = 10f64.powi(digits as i32 - 1 - v.log10().floor() as i32);
    // A hair of slack so that 0.0125 (stored a little above) stays 0.0125.
    rounded(((v * scale) * (1.0 - 1e-12)).ceil() / scale, digits)
}

/// The decimals that reach a standard error `se`'s second significant
/// digit (`0.0378`: 3; `1.03`: 1; `25`: 0); 0 for no finite positive
/// error.
pub fn error_decimals(se: f64) -> usize {
    if !(se.is_finite() && se > 0.0) {
        return 0;
    }
    (1 - se.log10().floor() as i64).clamp(0, 15) as usize
}

/// `v` with at least `decimals` decimals, and more where its standard
/// error `se` is finer ([`error_decimals`]): a value is never rounded
/// coarser than its own uncertainty (`9.797 ± 0.0378`, not `9.8 ±
/// 0.0378`).
pub fn beside_error(v: f64, se: f64, decimals: usize) -> String {
    fixed(v, decimals.max(error_decimals(se)))
}

/// `written`, the text of `v`, written again with the decimals its
/// standard error `se` needs where it has fewer ([`beside_error`]); a
/// text in exponent notation is kept (its digits are significant ones).
pub fn finer_than_error(written: &str, v: f64, se: f64) -> String {
    if written.contains(['e', 'E']) {
        return written.to_string();
    }
    let have = written.split_once('.').map_or(0, |(_, d)| d.len());
    if error_decimals(se) > have {
        beside_error(v, se, have)
    } else {
        written.to_string()
    }
}

/// `v` with `decimals` decimals where they show two significant digits
/// or more, else with `digits` significant digits ([`readable`]): an RMS
/// of 2.7e-4 N reads `0.000275`, not `0.0`, one of 12.34 N `12.3`.
pub fn decimals_or_digits(v: f64, decimals: usize, digits: usize) -> String {
    if v != 0.0 && v.is_finite() && v.abs() < 10f64.powi(1 - decimals as i32) {
        readable(v, digits)
    } else {
        fixed(v, decimals)
    }
}

/// `v` rounded to the `digits` significant digits it carries, written as
/// [`exact`] writes that rounded value (`193.849121`, not
/// `193.84912128812175`): a physical result in a file meant for people,
/// whose further digits are the arithmetic's, not the model's.
pub fn carried(v: f64, digits: usize) -> String {
    if !v.is_finite() || v == 0.0 {
        return exact(v);
    }
    let r: f64 = format!("{v:.*e}", digits.max(1) - 1).parse().unwrap_or(v);
    exact(r)
}

/// `v` as a written file holds it: the shortest text that reads back as
/// the same `f64`, in plain decimals from 1e-4 to below 1e9 (`4000`,
/// `0.3`, `-0.00123`) and with an exponent beyond (`1.5e-7`, `2.5e12`),
/// so that no value is written with hundreds of digits or as `1e0`; zero
/// as `0`.
pub fn exact(v: f64) -> String {
    let size = v.abs();
    if v == 0.0 {
        "0".into()
    } else if (1e-4..1e9).contains(&size) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// `a` and `b` with at least `decimals` decimals and as many more, up to
/// `max_decimals`, as make the printed values differ, so a sentence saying
/// one is below the other does not print two equal numbers. The flag is
/// false when they agree to `max_decimals`.
pub(crate) fn distinct(
    a: f64,
    b: f64,
    decimals: usize,
    max_decimals: usize,
) -> (String, String, bool) {
    let mut d = decimals;
    loop {
        let (sa, sb) = (fixed(a, d), fixed(b, d));
        if sa != sb {
            return (sa, sb, true);
        }
        if d >= max_decimals {
            return (sa, sb, false);
        }
        d += 1;
    }
}

/// `values` each with at least `decimals` decimals, and as many more (up
/// to 15) as it takes for two different values never to print alike and a
/// value that is not zero never to print as zero: the numbers of a
/// sentence that compares them never contradict it ("at 49.6 % of it,
/// where a step steer stays between 50 % and 150 %", not "at 50 %"; "a
/// record 0.004 s longer", not "0.00 s longer"). Values that agree print
/// as [`fixed`] prints them.
pub fn fixed_apart(values: &[f64], decimals: usize) -> Vec<String> {
    apart(values, decimals, 15, fixed)
}

/// `values` each with at least `digits` significant digits as
/// [`readable`] writes them, and as many more (up to 17) as it takes for
/// two different values never to print alike: "0.000169 rad, less than
/// the 0.00017 rad of a step", not "0.00017 rad, less than the 0.00017
/// rad".
pub fn readable_apart(values: &[f64], digits: usize) -> Vec<String> {
    apart(values, digits, 17, readable)
}

/// `values` written by `write` at the least precision from `least` to
/// `most` under which no two different values print alike and no value
/// that is not zero prints as zero.
fn apart(
    values: &[f64],
    least: usize,
    most: usize,
    write: fn(f64, usize) -> String,
) -> Vec<String> {
    let differ = |a: f64, b: f64| a != b && !(a.is_nan() && b.is_nan());
    let clash = |shown: &[String]| {
        values.iter().zip(shown).enumerate().any(|(i, (&v, s))| {
            let as_zero = v != 0.0 && !v.is_nan() && s.chars().all(|c| "-0.".contains(c));
            as_zero
                || values[i + 1..]
                    .iter()
                    .zip(&shown[i + 1..])
                    .any(|(&w, t)| differ(v, w) && t == s)
        })
    };
    let mut n = least;
    loop {
        let shown: Vec<String> = values.iter().map(|&v| write(v, n)).collect();
        if n >= most || !clash(&shown) {
            return shown;
        }
        n += 1;
    }
}

fn unsigned_zero(s: String) -> String {
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => s,
    }
}

/// The edit distance of `a` and `b` in characters, case ignored: the
/// fewest insertions, deletions, substitutions and transpositions of two
/// neighbours (optimal string alignment; Damerau 1964) that turn one into
/// the other — `pac98` is one from `pac89`.
pub fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.to_lowercase().chars().collect();
    let b: Vec<char> = b.to_lowercase().chars().collect();
    // Three rows of the table: two back (transpositions), one back, this.
    let mut back2 = vec![0; b.len() + 1];
    let mut back: Vec<usize> = (0..=b.len()).collect();
    for i in 1..=a.len() {
        let mut row = vec![i; b.len() + 1];
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            row[j] = (back[j] + 1).min(row[j - 1] + 1).min(back[j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                row[j] = row[j].min(back2[j - 2] + 1);
            }
        }
        back2 = std::mem::replace(&mut back, row);
    }
    back[b.len()]
}

/// Names vehicle-dynamics engineers also give a known name, and that name:
/// spelling cannot find them (`tyre_lag` is nine edits from
/// `relaxation_length`, the length of the first-order tyre lag).
/// Asked only where the name it stands for is among the known ones.
const ALSO_CALLED: &[(&str, &str)] = &[
    ("tyre_lag", "relaxation_length"),
    ("tire_lag", "relaxation_length"),
    ("slip_lag", "relaxation_length"),
    ("tyre_relaxation", "relaxation_length"),
    ("steer_lag", "steer_path"),
    ("steering_lag", "steer_path"),
    ("steer_delay", "steer_path"),
    ("actuator_lag", "steer_path"),
    ("sensor_offset", "sensor_bias"),
    ("sensor_offsets", "sensor_bias"),
    ("latency", "sensor_delay"),
    ("sensor_latency", "sensor_delay"),
    ("time_delay", "sensor_delay"),
    ("downforce", "aero_load"),
    ("aero_downforce", "aero_load"),
    ("friction", "road_friction"),
    ("mu", "road_friction"),
    ("steering_stiffness", "steering_compliance"),
    ("camber_thrust", "roll_camber"),
    ("sine_steer", "sine"),
    ("chirp", "sweep"),
    ("frequency_sweep", "sweep"),
];

/// The known name nearest `given`, when it is near enough to be what was
/// meant: another name engineers give it ([`ALSO_CALLED`]); one edit away
/// in a name of three characters or more (a slip); else the one known
/// name that holds every word of `given` (`slick` for `racing_slick`) or
/// whose every word `given` holds (`sine-steer` for `sine`), words split
/// at `_`, `-` and spaces, names that differ only in their separators
/// (`step-steer`, `step_steer`) counted as one, and none where the word
/// is several names' (`steer`); else at most one edit
/// per three characters of the longer name (`3·d ≤ n + 1`), so a slip or
/// two in a long name is caught and an unrelated short word is not; the
/// first of equally near names.
pub fn nearest_name<'a>(given: &str, known: &[&'a str]) -> Option<&'a str> {
    let plain = |s: &str| s.to_lowercase().replace(['-', ' '], "_");
    let also = ALSO_CALLED
        .iter()
        .filter(|(other, _)| *other == plain(given))
        .find_map(|(_, name)| known.iter().find(|k| plain(k) == plain(name)));
    if let Some(k) = also {
        return Some(k);
    }
    let closest = known
        .iter()
        .map(|k| (edit_distance(given, k), *k))
        .min_by_key(|(d, _)| *d);
    // One edit in a name of three characters or more: a slip (in `x` for
    // `y` it is a different name).
    let longest = |k: &str| given.chars().count().max(k.chars().count());
    if let Some((_, k)) = closest.filter(|(d, k)| *d <= 1 && longest(k) >= 3) {
        return Some(k);
    }
    let words = |s: &str| -> Vec<String> {
        s.to_lowercase()
            .split(['_', '-', ' '])
            .filter(|w| !w.is_empty())
            .map(String::from)
            .collect()
    };
    let g = words(given);
    let within = |a: &[String], b: &[String]| !a.is_empty() && a.iter().all(|w| b.contains(w));
    let sharing: Vec<&str> = known
        .iter()
        .filter(|k| {
            let kw = words(k);
            within(&g, &kw) || within(&kw, &g)
        })
        .copied()
        .collect();
    // A word several names share names none of them, and spelling must
    // not then pick a stranger (`steer` is no slip of `sweep`).
    if let Some((first, rest)) = sharing.split_first() {
        return rest
            .iter()
            .all(|k| plain(k) == plain(first))
            .then_some(*first);
    }
    closest
        .filter(|(d, k)| 3 * d <= given.chars().count().max(k.chars().count()) + 1)
        .map(|(_, k)| k)
}

/// ` (did you mean `x`?)` for the known name nearest `given`
/// ([`nearest_name`]), or nothing: the clause an error about an unknown
/// name puts after the name.
pub fn did_you_mean(given: &str, known: &[&str]) -> String {
    nearest_name(given, known).map_or(String::new(), |k| format!(" (did you mean `{k}`?)"))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A value beside its standard error is written to the error's
    /// second significant digit, never coarser ("9.8 ± 0.0378" was), and
    /// never with fewer decimals than asked; a text in exponent notation
    /// or already fine enough is kept.
    #[test]
    fn a_value_is_written_no_coarser_than_its_standard_error() {
        assert_eq!(error_decimals(0.0378), 3);
        assert_eq!(error_decimals(1.03), 1);
        assert_eq!(error_decimals(25.0), 0);
        assert_eq!(error_decimals(f64::NAN), 0);
        assert_eq!(beside_error(9.79687, 0.0378, 1), "9.797");
        assert_eq!(beside_error(17.7, 0.110, 1), "17.70");
        assert_eq!(beside_error(9.8, 3.0, 1), "9.8");
        assert_eq!(finer_than_error("1.3038", 1.30381, 0.00327), "1.3038");
        assert_eq!(finer_than_error("1.3038", 1.303812, 0.0000327), "1.303812");
        assert_eq!(finer_than_error("8.9e-5", 8.9e-5, 1e-7), "8.9e-5");
    }

    /// A number printed beside the ones it is compared with, or in a
    /// sentence that says it is not zero, never rounds onto them: the
    /// fewest decimals (digits) from those asked that tell them apart.
    #[test]
    fn numbers_said_together_never_round_onto_each_other_or_onto_zero() {
        // 49.6 % of a step beside the band 50–150 %: one decimal more.
        assert_eq!(
            fixed_apart(&[49.6, 50.0, 150.0], 0),
            ["49.6", "50.0", "150.0"]
        );
        // Apart already: as `fixed` prints them.
        assert_eq!(fixed_apart(&[31.0, 50.0, 150.0], 0), ["31", "50", "150"]);
        // A small duration is not "0.00 s", nor a small negative "-0.00".
        assert_eq!(fixed_apart(&[0.004], 2), ["0.004"]);
        assert_eq!(fixed_apart(&[-0.0031], 2), ["-0.003"]);
        // Zero stays zero, equal values stay alike.
        assert_eq!(fixed_apart(&[0.0, 0.0], 2), ["0.00", "0.00"]);
        assert_eq!(fixed_apart(&[0.2, 0.2], 2), ["0.20", "0.20"]);
        assert_eq!(fixed_apart(&[0.2004, 0.2], 2), ["0.2004", "0.2000"]);
        // Significant digits: a span just under the least step.
        assert_eq!(
            readable_apart(&[0.000169, 0.00017], 2),
            ["0.000169", "0.000170"]
        );
        assert_eq!(readable_apart(&[0.0095, 0.01], 2), ["0.0095", "0.010"]);
        assert_eq!(readable_apart(&[0.01, 0.01], 2), ["0.010", "0.010"]);
        assert_eq!(readable_apart(&[f64::NAN, f64::NAN], 2), ["NaN", "NaN"]);
    }

    #[test]
    fn a_signed_value_that_rounds_to_zero_has_no_sign() {
        assert_eq!(signed(-0.29, 0), "0");
        assert_eq!(signed(0.04, 1), "0.0");
        assert_eq!(signed(-0.4, 0), "0");
        assert_eq!(signed(-35.14, 1), "-35.1");
        assert_eq!(signed(3.5, 1), "+3.5");
    }

    #[test]
    fn exact_values_read_back_bit_for_bit_without_noise() {
        assert_eq!(exact(1.0), "1");
        assert_eq!(exact(4000.0), "4000");
        assert_eq!(exact(-0.0), "0");
        assert_eq!(exact(1.5e-7), "1.5e-7");
        assert_eq!(exact(1e300), "1e300");
        assert_eq!(exact(0.1 + 0.2), "0.30000000000000004");
        for v in [
            0.1 + 0.2,
            -1.0 / 3.0,
            1e-4,
            9.999e8,
            1e9,
            6.02e23,
            -2.5e-300,
        ] {
            assert_eq!(exact(v).parse::<f64>().unwrap(), v, "{v}");
        }
    }

    #[test]
    fn a_word_of_a_known_name_or_a_known_name_with_words_around_it_is_suggested() {
        let classes = ["passenger_car", "racing_slick", "truck"];
        assert_eq!(nearest_name("slick", &classes), Some("racing_slick"));
        assert_eq!(nearest_name("racing", &classes), Some("racing_slick"));
        let kinds = ["step-steer", "sine", "ramp", "sweep"];
        assert_eq!(nearest_name("sine-steer", &kinds), Some("sine"));
        // A slip still wins, and a word two names share suggests neither.
        assert_eq!(nearest_name("step-stear", &kinds), Some("step-steer"));
        assert_eq!(nearest_name("car", &["passenger_car", "race_car"]), None);
        assert_eq!(nearest_name("wheel", &classes), None);
        // One edit between one-letter names is another name, not a slip.
        assert_eq!(nearest_name("x", &["y", "z"]), None);
        // A name spelt two ways is one name: a word of it suggests it,
        // and its words in another order too.
        let kinds = [
            "step-steer",
            "step_steer",
            "ramp-steer",
            "ramp_steer",
            "sine",
            "sweep",
        ];
        assert_eq!(nearest_name("step", &kinds), Some("step-steer"));
        assert_eq!(nearest_name("steer-step", &kinds), Some("step-steer"));
        assert_eq!(nearest_name("ramp", &kinds), Some("ramp-steer"));
        assert_eq!(nearest_name("steer", &kinds), None);
        // What engineers also call a name, where spelling cannot find it.
        let effects = ["relaxation_length", "sensor_delay", "steer_path"];
        assert_eq!(
            nearest_name("tyre_lag", &effects),
            Some("relaxation_length")
        );
        assert_eq!(
            nearest_name("Tire-Lag", &effects),
            Some("relaxation_length")
        );
        assert_eq!(nearest_name("tyre_lag", &["sensor_delay"]), None);
        assert_eq!(nearest_name("fy", &["fx", "mz"]), Some("fx"));
    }

    #[test]
    fn a_count_of_one_takes_the_singular() {
        assert_eq!(plural(1, "sample", "samples"), "1 sample");
        assert_eq!(plural(0, "sample", "samples"), "0 samples");
        assert_eq!(plural(2, "equilibrium", "equilibria"), "2 equilibria");
    }

    #[test]
    fn zero_prints_unsigned() {
        assert_eq!(fixed(-0.0, 2), "0.00");
        assert_eq!(fixed(-0.0001, 2), "0.00");
        assert_eq!(fixed(-0.006, 2), "-0.01");
        assert_eq!(fixed(1.5, 1), "1.5");
        assert_eq!(fixed(-0.4, 0), "0");
        assert_eq!(format!("{:>5}", fixed(-1e-9, 2)), " 0.00");
    }

    #[test]
    fn significant_digits() {
        assert_eq!(significant(-69_813.4, 4), "-69813");
        assert_eq!(significant(1234.56, 4), "1235");
        assert_eq!(significant(12.3456, 4), "12.35");
        assert_eq!(significant(-0.012345, 3), "-0.0123");
        assert_eq!(significant(0.0, 4), "0");
        // A rounding that carries into the next power of ten keeps the
        // digits asked for.
        assert_eq!(significant(0.00999, 2), "0.010");
        assert_eq!(significant(-9.996, 3), "-10.0");
        assert_eq!(significant(99.96, 3), "100");
        assert_eq!(significant(0.0995, 2), "0.10");
    }

    #[test]
    fn readable_numbers_have_no_e0_and_no_300_digits() {
        assert_eq!(readable(2.04912, 4), "2.049");
        assert_eq!(readable(168075.77, 3), "168076");
        assert_eq!(readable(1.68e7, 3), "1.68e7");
        assert_eq!(readable(1.5e7, 3), "1.5e7");
        assert_eq!(readable(2.7e-11, 2), "2.7e-11");
        assert_eq!(readable(4e305, 3), "4e305");
        assert_eq!(readable(0.000275123, 3), "0.000275");
        assert_eq!(readable(-0.0, 3), "0");
        assert_eq!(rounded(49.999999, 3), "50");
        assert_eq!(carried(193.84912128812175, 9), "193.849121");
        assert_eq!(carried(-0.2085668456133224, 9), "-0.208566846");
        assert_eq!(carried(4000.0, 9), "4000");
        assert_eq!(carried(1.23456789012e-7, 9), "1.23456789e-7");
        assert_eq!(rounded(0.0025, 3), "0.0025");
        assert_eq!(rounded(1.0 / 3.0, 3), "0.333");
        assert_eq!(rounded_down(0.5 / 30.0, 3), "0.0166");
        assert_eq!(rounded_down(0.5 / 40.0, 3), "0.0125");
        assert_eq!(rounded_down(0.4 / 30.0, 2), "0.013");
        assert_eq!(rounded_down(0.1 / 30.0, 2), "0.0033");
        assert_eq!(rounded_up(0.1 / 30.0, 2), "0.0034");
        assert_eq!(rounded_up(0.5 / 40.0, 3), "0.0125");
        assert_eq!(rounded_up(6e5 / 2e6, 2), "0.3");
        assert_eq!(decimals_or_digits(0.000275123, 1, 3), "0.000275");
        assert_eq!(decimals_or_digits(12.34, 1, 3), "12.3");
        assert_eq!(decimals_or_digits(0.0, 1, 3), "0.0");
    }

    #[test]
    fn distinct_adds_digits_until_the_values_differ() {
        assert_eq!(
            distinct(2.51162, 2.51204, 3, 6),
            ("2.5116".into(), "2.5120".into(), true)
        );
        assert_eq!(
            distinct(1.0, 2.0, 3, 6),
            ("1.000".into(), "2.000".into(), true)
        );
        let (a, b, differ) = distinct(2.5, 2.5 + 1e-9, 3, 6);
        assert_eq!(
            (a.as_str(), b.as_str(), differ),
            ("2.500000", "2.500000", false)
        );
    }

    #[test]
    fn a_mistyped_name_is_answered_with_the_nearest_known_one() {
        assert_eq!(edit_distance("pac98", "pac89"), 1);
        assert_eq!(edit_distance("sensor_dely", "sensor_delay"), 1);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(edit_distance("PAC89", "pac89"), 0);
        let models = ["gim", "magic-simple", "pac89", "unitire", "linear"];
        assert_eq!(nearest_name("pac98", &models), Some("pac89"));
        assert_eq!(nearest_name("unitrie", &models), Some("unitire"));
        assert_eq!(nearest_name("brush", &models), None);
        assert_eq!(nearest_name("x", &["metric", "unit"]), None);
        assert_eq!(
            did_you_mean("relaxation_lenght", &["sensor_delay", "relaxation_length"]),
            " (did you mean `relaxation_length`?)"
        );
        assert_eq!(did_you_mean("brush", &models), "");
    }
}
