//! Files a TOML file names by a key (`[tyres] front`, `[runs] dir`):
//! checked to exist and be a file (or a folder), and a tyre file checked to
//! be one, each refusal at the key, naming the value as written.

use super::TomlSource;
use crate::error::{FileKind, InputError, InputProblem, KindProblem, PathFound};
use std::path::Path;

impl TomlSource {
    /// The file `path` that the value of `key_path` names, checked to
    /// exist and be a file: when it is not, an error at that key naming the
    /// value and the path it resolved to (a relative path is read from the
    /// TOML file's folder).
    pub(crate) fn referenced_file(&self, key_path: &str, path: &Path) -> Result<(), InputError> {
        self.referenced(key_path, path, false)
    }

    /// [`Self::referenced_file`] for a folder.
    pub(crate) fn referenced_folder(&self, key_path: &str, path: &Path) -> Result<(), InputError> {
        self.referenced(key_path, path, true)
    }

    fn referenced(&self, key_path: &str, path: &Path, folder: bool) -> Result<(), InputError> {
        let found = match (path.exists(), path.is_dir(), folder) {
            (true, true, true) | (true, false, false) => return Ok(()),
            (false, ..) => PathFound::Nothing,
            (true, true, false) => PathFound::FolderNotFile,
            (true, false, true) => PathFound::FileNotFolder,
        };
        // The path as written (a key holding one string) beside the path
        // it resolved to, made absolute: a path relative to the working
        // directory read as one relative to the file's folder.
        let span = self.key_span(key_path);
        let written = span
            .clone()
            .and_then(|s| self.text.get(s))
            .and_then(|t| t.parse::<toml_edit::Value>().ok())
            .and_then(|v| v.as_str().map(Box::from));
        let problem = InputProblem::MissingFile {
            key: key_path.to_string(),
            written,
            target: crate::io::paths::normalised(
                &std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf()),
            )
            .into_boxed_path(),
            base: self.path.clone().into_boxed_path(),
            found,
        };
        Err(self.located(span, problem))
    }

    /// [`Self::referenced_file`] for a tyre file (`[tyres] front`, `rear`,
    /// `file`; of a `campaign` or a scenario), refused at the key where it is plainly another kind of
    /// file ([`crate::io::file_kind::recognise`]): a tyre's TOML reader
    /// would answer rig data with "expected `.`, `=`" at its header.
    pub(crate) fn referenced_tyre(
        &self,
        key_path: &str,
        path: &Path,
        campaign: bool,
    ) -> Result<(), InputError> {
        self.referenced_file(key_path, path)?;
        // Only what its content shows (a header, tables, a NUL byte): a
        // file is never refused for its name, which its reader may take.
        let kind = match crate::io::file_kind::recognise(path) {
            Some(
                kind @ (FileKind::RigCsv
                | FileKind::RunCsv
                | FileKind::HistoryCsv
                | FileKind::Scenario
                | FileKind::Campaign
                | FileKind::Sweep
                | FileKind::Study
                | FileKind::Binary { .. }
                | FileKind::Text { .. }),
            ) => kind,
            _ => return Ok(()),
        };
        let written = self
            .key_span(key_path)
            .and_then(|s| self.text.get(s))
            .and_then(|t| t.parse::<toml_edit::Value>().ok())
            .and_then(|v| v.as_str().map(str::to_string))
            .unwrap_or_else(|| path.display().to_string());
        let problem = KindProblem::NotATyre {
            key: key_path.to_string(),
            written,
            kind,
            campaign,
        };
        let span = self.key_span(key_path);
        Err(self.located(span, InputProblem::Kind(Box::new(problem))))
    }
}
