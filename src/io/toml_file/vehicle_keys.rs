//! The `[vehicle]` keys no vehicle of this tool reads. FORMATS.md lets a
//! vehicle description carry more keys than the model's (a roll stiffness,
//! a steering ratio): a file written for another tool must not be refused
//! for them. A key one slip of spelling from a key the vehicle reads
//! (`cg_heigth`) is still refused, with the key meant, as serde refuses it;
//! any other is set aside — blanked in the text the file is parsed from,
//! byte for byte, so that every line and column of an error stays where it
//! is in the file — and the reader reports it (a campaign's notes,
//! `simulate`'s warnings): nothing a file says is dropped unsaid.

use super::home::{belongs, Reparse};
use super::{line_col, TomlSource};

/// The keys of `[vehicle]` the tool reads ([`crate::vehicle::Vehicle`]'s
/// fields; a unit test holds the two to each other).
pub(crate) const VEHICLE_KEYS: &[&str] = &[
    "mass",
    "yaw_inertia",
    "a",
    "b",
    "track_front",
    "track_rear",
    "cg_height",
    "wheelbase",
    "load_transfer_front_share",
    "steering_ratio",
];

/// A `[vehicle]` key the tool does not read, set aside.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnreadKey {
    /// The file.
    pub file: std::path::PathBuf,
    /// The key.
    pub key: String,
    /// Its line in the file, 1-based.
    pub line: usize,
}

impl UnreadKey {
    /// What a reader says of it.
    pub fn note(&self) -> String {
        format!(
            "{}:{}: [vehicle] `{}` is no key this tool reads (FORMATS.md allows more): set aside, not used",
            self.file.display(),
            self.line,
            self.key
        )
    }
}

impl TomlSource {
    /// The `[vehicle]` keys of the file that the tool does not read and
    /// that are no slip of one it reads, in the file's order, each with
    /// the byte range of its `key = value` (none where the text does not
    /// parse or has no `[vehicle]` table: the parse says what is wrong).
    fn unread_vehicle_spans(&self) -> Vec<(UnreadKey, std::ops::Range<usize>)> {
        let Ok(doc) = toml_edit::ImDocument::parse(self.text.as_str()) else {
            return Vec::new();
        };
        let Some(vehicle) = doc.get("vehicle").and_then(|v| v.as_table_like()) else {
            return Vec::new();
        };
        let mut out: Vec<_> = vehicle
            .iter()
            .filter(|(k, item)| {
                item.is_value()
                    && !VEHICLE_KEYS.contains(k)
                    && crate::format::nearest_name(k, VEHICLE_KEYS).is_none()
            })
            .filter_map(|(k, item)| {
                let (key, _) = vehicle.get_key_value(k)?;
                let start = key.span()?.start;
                let end = item.span()?.end;
                let line = line_col(&self.text, start).0;
                let unread = UnreadKey {
                    file: self.path.clone(),
                    key: k.to_string(),
                    line,
                };
                Some((unread, start..end))
            })
            .collect();
        out.sort_by_key(|(u, _)| u.line);
        out
    }

    /// The `[vehicle]` keys the tool does not read and sets aside
    /// ([`UnreadKey`]), for the reader to report.
    pub fn unread_vehicle_keys(&self) -> Vec<UnreadKey> {
        self.unread_vehicle_spans()
            .into_iter()
            .map(|(u, _)| u)
            .collect()
    }

    /// The file with every unread `[vehicle]` key's `key = value` blanked
    /// in its text (spaces, newlines kept: every byte where it was); None
    /// when there is none. A key another table of the file reads (`speed`,
    /// a manoeuvre's) is left for the parse to refuse with the table it
    /// belongs in (`reparse` reads the file as its type).
    pub(super) fn without_unread_vehicle_keys(&self, reparse: &Reparse) -> Option<TomlSource> {
        let mut spans = self.unread_vehicle_spans();
        spans
            .retain(|(u, _)| belongs(&self.text, &format!("vehicle.{}", u.key), reparse).is_none());
        if spans.is_empty() {
            return None;
        }
        let mut bytes = self.text.clone().into_bytes();
        for (_, range) in spans {
            for b in &mut bytes[range] {
                if *b != b'\n' && *b != b'\r' {
                    *b = b' ';
                }
            }
        }
        // Only ASCII bytes of whole `key = value` runs were replaced, each
        // byte of a multi-byte character by a space: still UTF-8.
        let text = String::from_utf8(bytes).ok()?;
        Some(TomlSource {
            path: self.path.clone(),
            text,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vehicle::Vehicle;

    fn source(text: &str) -> TomlSource {
        TomlSource {
            path: "v.toml".into(),
            text: text.into(),
        }
    }

    const SEDAN: &str = "[vehicle]\nmass = 1530.0\nyaw_inertia = 2315.0\na = 1.11\nb = 1.67\ntrack_front = 1.55\ntrack_rear = 1.55\ncg_height = 0.55\n";

    #[test]
    fn the_keys_read_are_the_vehicles_fields() {
        let full = format!(
            "{SEDAN}wheelbase = 2.78\nload_transfer_front_share = 0.6\nsteering_ratio = 16.0\n"
        );
        let v: Vehicle = toml::from_str::<toml::Table>(&full).unwrap()["vehicle"]
            .clone()
            .try_into()
            .unwrap();
        let written = toml::Table::try_from(&v).unwrap();
        let mut keys: Vec<&str> = written.keys().map(String::as_str).collect();
        let mut known = VEHICLE_KEYS.to_vec();
        keys.sort_unstable();
        known.sort_unstable();
        assert_eq!(keys, known);
    }

    #[test]
    fn a_key_no_vehicle_reads_is_set_aside_where_it_was_and_a_slip_is_not() {
        let text = format!(
            "{SEDAN}roll_stiffness = 80000.0\nnotes = [\n  \"a\",\n  \"ü\",\n]\ncg_heigth = 0.5\n[road]\nfriction = 1.0\n"
        );
        let src = source(&text);
        let unread = src.unread_vehicle_keys();
        let keys: Vec<(&str, usize)> = unread.iter().map(|u| (u.key.as_str(), u.line)).collect();
        assert_eq!(keys, [("roll_stiffness", 9), ("notes", 10)]);
        let none = |_: &str| None;
        let blanked = src.without_unread_vehicle_keys(&none).unwrap().text;
        assert_eq!(blanked.len(), text.len());
        assert_eq!(blanked.lines().count(), text.lines().count());
        assert!(!blanked.contains("roll_stiffness") && !blanked.contains("\"a\""));
        // The slip stays, for the parse to refuse with the key meant.
        assert!(blanked.contains("cg_heigth = 0.5"));
        assert_eq!(line_col(&blanked, blanked.find("cg_heigth").unwrap()).0, 14);
    }

    #[test]
    fn a_file_without_unread_keys_is_parsed_as_written() {
        assert!(source(SEDAN)
            .without_unread_vehicle_keys(&|_| None)
            .is_none());
        assert!(source("[vehicle\nmass = 1")
            .unread_vehicle_keys()
            .is_empty());
    }
}
