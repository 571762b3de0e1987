//! The `--template` of a staged Magic Formula fit, read: a `.tir` whose
//! coefficients start the fit and whose layout and constants the written
//! file keeps. A file of another kind (a TOML tyre, a scenario, a rig
//! CSV) is named as what it is, with the command that reads it, as
//! `tyre-eval` names a file given as its tyre (`io/file_kind.rs`), in
//! place of the `.tir` reader's complaint at its first line ("is not a
//! key", "missing key FITTYP in [MODEL]"), which read as a broken `.tir`.

use crate::error::{InputError, Wanted};
use crate::io::tir::TirDocument;
use crate::tyre::mf::MagicFormula;
use std::path::Path;

/// The template given (`None`: no `--template`): its document and its
/// tyre, or the refusal of a file of another kind.
pub(super) fn read_given(
    path: Option<&Path>,
) -> Result<(Option<TirDocument>, Option<MagicFormula>), InputError> {
    match path.map(read).transpose()? {
        Some((doc, tyre)) => Ok((Some(doc), Some(tyre))),
        None => Ok((None, None)),
    }
}

/// The template at `path`: its document and its tyre, or the refusal of
/// a file of another kind.
fn read(path: &Path) -> Result<(TirDocument, MagicFormula), InputError> {
    let named =
        |e: InputError| crate::io::file_kind::not_a_tir(path, Wanted::Template).unwrap_or(e);
    let doc = TirDocument::read(path).map_err(named)?;
    let tyre = doc.template().map_err(named)?;
    Ok((doc, tyre))
}
