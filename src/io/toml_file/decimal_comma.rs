//! A number written with a decimal comma (`mass = 1530,0`, as a German or
//! French keyboard writes it): toml reads `1530` and stops at the comma,
//! "unexpected `,` after the value", which names no slip. Said as the
//! number meant, with the point to write.

/// The message for a value that stops at a comma at byte `pos` of `text`
/// where the key's value reads as a number with a decimal comma (whole
/// digits, the comma, digits, then nothing but a comment): `None` for
/// any other text at `pos`.
pub(super) fn hint(text: &str, pos: usize) -> Option<String> {
    let start = text.get(..pos)?.rfind('\n').map_or(0, |i| i + 1);
    let (_, whole) = text.get(start..pos)?.split_once('=')?;
    let whole = whole.trim();
    let digits = |s: &str| !s.is_empty() && s.chars().all(|c| c.is_ascii_digit() || c == '_');
    let unsigned = whole.strip_prefix(['-', '+']).unwrap_or(whole);
    if !digits(unsigned) {
        return None;
    }
    let after = text.get(pos..)?.strip_prefix(',')?;
    let line = after.lines().next().unwrap_or("");
    let end = line
        .find(|c: char| !c.is_ascii_digit())
        .unwrap_or(line.len());
    let (fraction, rest) = line.split_at(end);
    let rest = rest.trim();
    if fraction.is_empty() || !(rest.is_empty() || rest.starts_with('#')) {
        return None;
    }
    Some(format!(
        "`{whole},{fraction}`: a decimal comma? write {whole}.{fraction} (a TOML number takes a decimal point; the comma ends the number at {whole})"
    ))
}

#[cfg(test)]
mod tests {
    use super::hint;

    #[test]
    fn a_decimal_comma_is_said_with_the_point_and_a_list_is_not() {
        let text = "[vehicle]\nmass = 1530,0   # kg\n";
        let at = text.find(',').unwrap();
        assert_eq!(
            hint(text, at).as_deref(),
            Some("`1530,0`: a decimal comma? write 1530.0 (a TOML number takes a decimal point; the comma ends the number at 1530)")
        );
        assert!(hint("a = -0,5\n", 6).is_some_and(|h| h.contains("write -0.5")));
        let list = "a = 1, 2\n";
        assert_eq!(hint(list, list.find(',').unwrap()), None);
        let word = "a = 1,b\n";
        assert_eq!(hint(word, word.find(',').unwrap()), None);
    }
}
