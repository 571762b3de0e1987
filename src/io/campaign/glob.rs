//! A wildcard in `[runs] files` (`runs/*.csv`): the list names files as
//! written, and a shell's glob is no file name, so the entry is answered
//! with the key that reads a folder's runs (`dir`), not with "does not
//! exist".

use crate::error::{CampaignFileProblem, InputError, InputProblem};
use crate::io::toml_file::TomlSource;
use std::path::{Path, PathBuf};

/// Refuses the first entry of `files` (as written, resolved beside `base`)
/// that holds a wildcard and names no file.
pub(super) fn refuse_globs(
    src: &TomlSource,
    files: &[PathBuf],
    base: &Path,
) -> Result<(), InputError> {
    for (i, f) in files.iter().enumerate() {
        let written = f.to_string_lossy();
        if !written.contains(['*', '?']) || crate::io::paths::beside(base, f).exists() {
            continue;
        }
        let problem = CampaignFileProblem::RunsGlob {
            pattern: written.into(),
        };
        return Err(src.located(
            src.key_span(&format!("runs.files[{i}]")),
            InputProblem::Campaign(Box::new(problem)),
        ));
    }
    Ok(())
}
