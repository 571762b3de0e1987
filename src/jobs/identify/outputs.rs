//! Where `identify` writes: the tyre file (`--out`, else
//! `out/<data stem>_<model>.toml`, `.tir` for the Magic Formula), its
//! `.report.json` and figure beside it, checked before any fit (a folder
//! or any extension but the format's named as the file is refused), and the
//! lock that keeps two fits from writing them at once.

use super::Options;
use crate::error::{Error, OutputError};
use crate::report::OutputLock;
use std::path::PathBuf;

impl Options {
    /// Ok when `out` can name the tyre file: not a folder, and with the
    /// extension of the model's format (`.toml`, `.tir`) or none.
    pub(super) fn validate_out(&self) -> Result<(), Error> {
        let Some(out) = &self.out else {
            return Ok(());
        };
        let expected = self.extension();
        OutputError::unless_a_file(out, "fit", expected)?;
        match out
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase())
        {
            // Any other extension (`x.csv`) names a file the readers take
            // for another format: a TOML tyre under `.csv` is refused by
            // `tyre-eval` as a CSV.
            Some(given) if given != expected => Err(OutputError::Extension {
                path: out.clone(),
                model: self.model.to_string(),
                expected,
                given,
            }
            .into()),
            _ => Ok(()),
        }
    }

    /// The extension of the tyre file: `toml`, or `tir` for the Magic Formula.
    fn extension(&self) -> &'static str {
        if self.model.swarm_model().is_some() {
            "toml"
        } else {
            "tir"
        }
    }

    /// The tyre file written: `out`, else `out/<data stem>_<model>.toml`
    /// (`.tir` for the Magic Formula).
    pub(crate) fn output_path(&self) -> PathBuf {
        let ext = self.extension();
        self.out.clone().unwrap_or_else(|| {
            let stem = self
                .data
                .file_stem()
                .map_or("data".into(), |s| s.to_string_lossy().into_owned());
            PathBuf::from("out").join(format!("{stem}_{}.{ext}", self.model))
        })
    }
}

/// The tyre file, `<out>.report.json` and, with a figure, `<out>.png`.
pub(super) fn outputs(o: &Options, figure: bool) -> Vec<PathBuf> {
    let out = o.output_path();
    let mut files = vec![out.clone(), out.with_extension("report.json")];
    if figure {
        files.push(out.with_extension("png"));
    }
    files
}

/// The outputs of the fit (the fitted file and the files named after it),
/// held for this run: two fits writing them at once are refused.
pub(super) fn output_lock(o: &Options) -> Result<OutputLock, Error> {
    let out = o.output_path();
    let dir = out.parent().filter(|d| !d.as_os_str().is_empty());
    let stem = out.file_stem().map(|s| s.to_string_lossy().into_owned());
    OutputLock::acquire_outputs(
        dir.unwrap_or(std::path::Path::new(".")),
        stem.as_deref().unwrap_or("identify"),
    )
}
