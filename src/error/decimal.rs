//! A number written with a decimal comma (`0,05`, `PDY1 = 1,0184`), as a
//! spreadsheet set to a comma writes it: the value with a decimal point
//! the CSV and `.tir` readers' messages suggest in its place.

/// `cell` with its one comma made a point, where that reads as a number
/// and the comma is a decimal one (digits on both sides: `0,05`, `-1,5`;
/// not a thousands separator's `1,000`, which a decimal point would make
/// one, not a thousand).
pub(super) fn decimal_comma(cell: &str) -> Option<String> {
    let (whole, fraction) = cell.split_once(',')?;
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    let unsigned = whole.strip_prefix(['-', '+']).unwrap_or(whole);
    let thousands = fraction.len() == 3 && unsigned != "0";
    (digits(unsigned) && digits(fraction) && !thousands).then(|| format!("{whole}.{fraction}"))
}

/// The hint after a `.tir` value that is not a number where it reads as
/// one written with a decimal comma, as the CSV and TOML readers give it.
pub(super) fn tir_comma(text: &str) -> String {
    decimal_comma(text).map_or(String::new(), |point| {
        format!(": a decimal comma? write {point} (a .tir number takes a decimal point)")
    })
}
