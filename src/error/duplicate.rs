//! Where a duplicated column or key first appears: a CSV header naming a
//! column twice, a `.tir` section giving a key two values
//! ([`super::InputProblem::Duplicate`]).

use thiserror::Error;

/// The first appearance of a name given twice.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Error)]
pub enum DuplicateAt {
    /// A 1-based column of the header.
    #[error("column {0}")]
    Column(usize),
    /// A 1-based line of the file.
    #[error("line {0}")]
    Line(usize),
}
