//! Where a duplicated column or key first appears: a CSV header naming a
//! column twice, a `.tir` section giving a key two values
//! ([`super::InputProblem::Duplicate`]).

use thiserror::Error;

/// The first appearance of a name given twice.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum DuplicateAt {
    /// A 1-based column of the header.
    #[error("column {0}")]
    Column(usize),
    /// A 1-based line of the file.
    #[error("line {0}")]
    Line(usize),
    /// A 1-based line of the file, in another section: a reader takes the
    /// key from one section only, and the other's value is lost.
    #[error("line {line}, in section [{section}]: a parameter belongs to one section")]
    LineInSection {
        /// The line.
        line: usize,
        /// Its section.
        section: String,
    },
}
