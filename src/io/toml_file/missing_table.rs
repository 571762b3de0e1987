//! A table the file's type requires and the file does not have (a
//! campaign or a scenario without `[vehicle]`): serde says "missing field
//! `vehicle`" of the whole document, which was put at the key on the
//! file's first line (`name`, 1:1) as if that key were wrong. Told from a
//! missing key by reading the file again with an empty `[vehicle]`
//! appended: a table's absence then gives way to another message (its
//! first key missing), a plain key's to "invalid type" (a table where a
//! value is wanted). Said with the file's tables and their lines.
//!
//! A table whose header line alone was deleted leaves its keys at the top
//! level, refused as "unknown field `mass`" at the first: a table the file
//! lacks whose header, written above that key's line, makes the key read
//! is the table missing, said with the line its header belongs above.

use super::home::Reparse;
use super::{Span, TomlSource};
use crate::error::{InputError, InputProblem, MissingTable};

impl TomlSource {
    /// `message` (serde's, for the error at `span`) as a required table
    /// the file lacks, where it is one.
    pub(super) fn missing_table(
        &self,
        message: &str,
        span: Option<&Span>,
        reparse: &Reparse,
    ) -> Option<InputError> {
        let name = message
            .strip_prefix("missing field `")?
            .strip_suffix('`')
            // serde's message alone, not one already said further.
            .filter(|n| n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'))?;
        // A table's own missing key is placed at that table.
        if span.is_some_and(|s| s.start != 0) {
            return None;
        }
        let again = reparse(&format!("{}\n[{name}]\n", self.text));
        let table = match again.as_deref() {
            None => true,
            Some(m) => {
                m != message && !m.starts_with("invalid type") && !m.starts_with("unknown field")
            }
        };
        table.then(|| {
            let problem = MissingTable {
                table: name.to_string(),
                tables: self.table_headers(),
                headless: None,
            };
            self.located(None, InputProblem::MissingTable(Box::new(problem)))
        })
    }

    /// serde's "unknown field `key`, expected one of …" for a key before
    /// the file's first header, as the table it belongs to with its header
    /// lost: the required table the file lacks with the key's lines set
    /// aside, under which, written above the key's line, the key reads.
    pub(super) fn headless_table(
        &self,
        message: &str,
        span: Option<&Span>,
        reparse: &Reparse,
    ) -> Option<InputError> {
        let (key, rest) = message.strip_prefix("unknown field `")?.split_once('`')?;
        let expected = rest.split_once(", expected ")?.1;
        let start = span?.start;
        let headers = self.table_headers();
        let line = self.text[..start].matches('\n').count() + 1;
        // Only a key the file holds before any header is read as its own.
        if headers.first().is_some_and(|(_, at)| *at < line) {
            return None;
        }
        let line_start = self.text[..start].rfind('\n').map_or(0, |i| i + 1);
        // The file without the key and the lines after it up to its first
        // header: a table it then lacks is required (serde: "missing field
        // `vehicle`"); an optional one (`[integrator]`, `[simulation]`
        // written already) is no table lost, and the key is sent home.
        let first_header = headers.first().map_or(self.text.len(), |(_, at)| {
            self.text
                .split_inclusive('\n')
                .take(at - 1)
                .map(str::len)
                .sum()
        });
        let without = format!("{}{}", &self.text[..line_start], &self.text[first_header..]);
        let lacked = reparse(&without)?;
        let table = lacked
            .strip_prefix("missing field `")?
            .strip_suffix('`')
            .filter(|t| super::home::listed(expected).contains(t))?;
        let mut probe = self.text.clone();
        probe.insert_str(line_start, &format!("[{table}]\n"));
        let reads = reparse(&probe).is_none_or(|m| {
            !m.starts_with(&format!("unknown field `{key}`"))
                && !m.starts_with("invalid type")
                && !m.starts_with("duplicate key")
        });
        if !reads {
            return None;
        }
        let problem = MissingTable {
            table: table.to_string(),
            tables: headers,
            headless: Some((key.to_string(), line)),
        };
        Some(self.located(None, InputProblem::MissingTable(Box::new(problem))))
    }

    /// The file's `[table]` headers as written, with their 1-based lines.
    fn table_headers(&self) -> Vec<(String, usize)> {
        self.text
            .lines()
            .enumerate()
            .filter_map(|(i, l)| {
                let l = l.trim();
                let inner = l.strip_prefix('[')?;
                let name = inner.split(']').next()?.trim_matches(['[', ' ']);
                (!name.is_empty()).then(|| (name.to_string(), i + 1))
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    #[derive(Debug, Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Car {
        mass: f64,
    }

    #[derive(Debug, Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct File {
        name: String,
        vehicle: Car,
        runs: Option<Car>,
    }

    fn parsed(text: &str) -> String {
        let src = TomlSource {
            path: "c.toml".into(),
            text: text.into(),
        };
        src.parse::<File>().unwrap_err().to_string()
    }

    #[test]
    fn a_missing_table_is_said_as_one_with_the_files_tables() {
        let said = parsed("name = \"x\"\n\n[runs]\nmass = 1.0\n");
        assert_eq!(said, "c.toml: the table `[vehicle]` is missing (the file's tables: [runs] at line 3): add it, with its keys, as a `[vehicle]` header and the `key = value` lines under it");
        // A missing plain key stays a missing key.
        let said = parsed("[vehicle]\nmass = 1.0\n");
        assert!(said.contains("missing field `name`"), "{said}");
        // A table's missing key is said at the table.
        let said = parsed("name = \"x\"\n[vehicle]\n");
        assert!(said.contains(":2:1: missing field `mass`"), "{said}");
        // A table whose header line alone is lost: its keys read as the
        // file's own.
        let said = parsed("name = \"x\"\n\nmass = 1.0\n[runs]\nmass = 2.0\n");
        assert_eq!(said, "c.toml: the table `[vehicle]` is missing (the file's tables: [runs] at line 4), and `mass` at line 3 is one of its keys, read as a key of the file itself: add the header `[vehicle]` above line 3");
        // A key no missing table takes stays an unknown key.
        let said = parsed("name = \"x\"\nmas = 1.0\n[vehicle]\nmass = 1.0\n");
        assert!(said.contains("unknown field `mas`"), "{said}");
        let said = parsed("name = \"x\"\nmas = 1.0\n");
        assert!(!said.contains("is missing"), "{said}");
        // A required key written in capitals is no missing table.
        let said = parsed("Name = \"x\"\n[vehicle]\nmass = 1.0\n");
        assert!(
            said.contains("`Name`") && !said.contains("is missing"),
            "{said}"
        );
    }
}
