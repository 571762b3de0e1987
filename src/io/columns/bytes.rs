//! Where in a CSV file's bytes a reader's finding lies: a byte that is
//! not UTF-8 (its line and field), a header further down under lines of
//! metadata.

/// Where the CSV reader found a byte that is not UTF-8: the byte, its
/// 1-based line and its 1-based CSV column (field).
pub(super) struct BadByte {
    pub(super) byte: u8,
    pub(super) line: usize,
    pub(super) column: usize,
}

/// The byte that is not UTF-8 behind the reader's error `e`, if that is
/// what `e` is: the reader gives the record and the field, not the byte
/// or its line (the first bad byte from the record's start is the one,
/// and a quoted field may span lines, so the line is counted to it).
/// A comment line the reader skips may hold any bytes: only a record's
/// are refused.
pub(super) fn not_utf8(bytes: &[u8], e: &csv::Error) -> Option<BadByte> {
    let csv::ErrorKind::Utf8 { pos, err } = e.kind() else {
        return None;
    };
    let start = pos
        .as_ref()
        .map_or(0, |p| p.byte() as usize)
        .min(bytes.len());
    let offset = std::str::from_utf8(&bytes[start..]).err()?.valid_up_to();
    let at = start + offset;
    Some(BadByte {
        byte: bytes[at],
        line: bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1,
        column: err.field() + 1,
    })
}

/// The first line after `header_line` (1-based, among the next 100) whose
/// comma-separated cells name the column `name` (unquoted, any case; `t`
/// also as `time`): a header under lines of metadata.
pub(super) fn header_further_down(
    bytes: &[u8],
    header_line: usize,
    name: &str,
) -> Option<std::num::NonZeroU32> {
    let text = String::from_utf8_lossy(bytes);
    text.lines()
        .enumerate()
        .skip(header_line)
        .take(100)
        .find(|(_, l)| {
            l.split(',').any(|c| {
                let c = c.trim().trim_matches('"');
                c.eq_ignore_ascii_case(name) || (name == "t" && c.eq_ignore_ascii_case("time"))
            })
        })
        .and_then(|(i, _)| std::num::NonZeroU32::new(u32::try_from(i + 1).ok()?))
}
