//! The library's integration tests: jobs and analyses called as functions
//! of `handling`, without the binary, on the bundled files and on
//! campaigns the proving ground generates in memory. What a user sees of
//! the command line is tested in `tests/cli/`; the unit tests sit beside
//! their code in `src/`.

use std::path::PathBuf;

/// The repository root.
pub(crate) fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

mod derivatives;
mod diagnose;
mod identify;
mod screening;
