//! A table the file's type requires and the file does not have (a
//! campaign or a scenario without `[vehicle]`): serde says "missing field
//! `vehicle`" of the whole document, which was put at the key on the
//! file's first line (`name`, 1:1) as if that key were wrong. Told from a
//! missing key by reading the file again with an empty `[vehicle]`
//! appended: a table's absence then gives way to another message (its
//! first key missing), a plain key's to "invalid type" (a table where a
//! value is wanted). Said with the file's tables and their lines.

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
            };
            self.located(None, InputProblem::MissingTable(Box::new(problem)))
        })
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
        // A required key written in capitals is no missing table.
        let said = parsed("Name = \"x\"\n[vehicle]\nmass = 1.0\n");
        assert!(
            said.contains("`Name`") && !said.contains("is missing"),
            "{said}"
        );
    }
}
