//! A table a TOML file's kind requires and the file does not have (a
//! campaign or a scenario without `[vehicle]`): serde says "missing field
//! `vehicle`" of the whole document, which was put at the file's first key
//! (`name`, 1:1) as if that key were wrong. Said as the table missing, with
//! the tables the file has and their lines, so the reader sees where the
//! missing one belongs or which one is misnamed. Where only the header
//! line was lost, its keys read as the file's own (serde: "unknown field
//! `mass`" at the first of them): said as the same missing table, with the
//! line its header belongs above.

use std::fmt;

/// The table missing and the file's own tables.
#[derive(Debug, Clone, PartialEq)]
pub struct MissingTable {
    /// The table's name (`vehicle`).
    pub table: String,
    /// The file's table headers as written (`tyres`, `model.effects`),
    /// with their 1-based lines.
    pub tables: Vec<(String, usize)>,
    /// The table's first key where the file has it without its header
    /// (read as a top-level key), with its 1-based line.
    pub headless: Option<(String, usize)>,
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
        match &self.headless {
            Some((key, line)) => write!(
                f,
                "the table `[{}]` is missing ({has}), and `{key}` at line {line} is one of its keys, read as a key of the file itself: add the header `[{}]` above line {line}",
                self.table, self.table
            ),
            None => write!(
                f,
                "the table `[{}]` is missing ({has}): add it, with its keys, as a `[{}]` header and the `key = value` lines under it",
                self.table, self.table
            ),
        }
    }
}
