//! A file of another kind given to `diagnose` as its campaign — a measured
//! run's CSV, a `.tir`, a scenario — named as what it is, where the TOML
//! reader would say only "expected `.`, `=`" or "unknown field
//! `manoeuvre`". Judged only once the campaign fails to read, so a
//! campaign is never refused for its name.

use crate::error::{CampaignFileProblem, InputError, InputProblem, NotCampaignKind};
use std::path::Path;

/// What the file at `path` (text `text`) is, when it is clearly no
/// campaign: a CSV or `.tir` by its name, a scenario by its `[manoeuvre]`
/// (and no `[runs]`), any other file not named `.toml` whose text is no
/// TOML.
fn kind_of(path: &Path, text: &str) -> Option<NotCampaignKind> {
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    let table = text.parse::<toml::Table>().ok();
    match ext.as_deref() {
        Some("csv") => Some(NotCampaignKind::Csv),
        Some("tir") => Some(NotCampaignKind::Tir),
        _ if table
            .as_ref()
            .is_some_and(|t| t.contains_key("manoeuvre") && !t.contains_key("runs")) =>
        {
            Some(NotCampaignKind::Scenario)
        }
        Some("toml") => None,
        _ => table.is_none().then_some(NotCampaignKind::NotToml),
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
