//! A file of another kind given to `diagnose` as its campaign — a measured
//! run's CSV, rig data, a `.tir` or tyre file, a scenario, a sweep — named as what it is, where the TOML
//! reader would say only "expected `.`, `=`" or "unknown field
//! `manoeuvre`". Judged only once the campaign fails to read, so a
//! campaign is never refused for its name.

use crate::error::{CampaignFileProblem, FileKind, InputError, InputProblem, NotCampaignKind};
use std::path::Path;

/// What the file at `path` (text `text`) is, when it is clearly no
/// campaign ([`crate::io::file_kind::recognise`]), or any other file not
/// named `.toml` whose text is no TOML.
fn kind_of(path: &Path, text: &str) -> Option<NotCampaignKind> {
    match crate::io::file_kind::recognise(path) {
        Some(FileKind::Campaign | FileKind::Folder { .. }) => None,
        Some(kind) => Some(NotCampaignKind::Seen(kind)),
        None => {
            let toml = path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("toml"));
            (!toml && text.parse::<toml::Table>().is_err()).then_some(NotCampaignKind::NotToml)
        }
    }
}

/// `e`, the error of reading the campaign at `path`, or the file's kind in
/// its place where the file is clearly no campaign.
pub(super) fn named_kind(path: &Path, text: &str, e: InputError) -> InputError {
    match kind_of(path, text) {
        Some(kind) => InputError::problem(
            path,
            InputProblem::Campaign(Box::new(CampaignFileProblem::NotACampaign { kind })),
        ),
        None => e,
    }
}
