//! A table a TOML file's kind requires and the file does not have (a
//! campaign or a scenario without `[vehicle]`): serde says "missing field
//! `vehicle`" of the whole document, which was put at the file's first key
//! (`name`, 1:1) as if that key were wrong. Said as the table missing, with
//! the tables the file has and their lines, so the reader sees where the
//! missing one belongs or which one is misnamed.

use std::fmt;

/// The table missing and the file's own tables.
#[derive(Debug, Clone, PartialEq)]
pub struct MissingTable {
    /// The table's name (`vehicle`).
    pub table: String,
    /// The file's table headers as written (`tyres`, `model.effects`),
    /// with their 1-based lines.
    pub tables: Vec<(String, usize)>,
}

impl fmt::Display for MissingTable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let has = match self.tables.as_slice() {
            [] => "the file has no tables".to_string(),
            t => format!(
                "the file's tables: {}",
                t.iter()
                    .map(|(name, line)| format!("[{name}] at line {line}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        };
        write!(
            f,
            "the table `[{}]` is missing ({has}): add it, with its keys, as a `[{}]` header and the `key = value` lines under it",
            self.table, self.table
        )
    }
}
