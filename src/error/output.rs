//! Output errors: an output that may not or could not be written (an input
//! of the run, a folder that exists, a failed write, a report that could
//! not be encoded).

use crate::format::plural;
use std::path::PathBuf;
use thiserror::Error;

/// The file-system step of a write that failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WriteStep {
    /// Creating the file or folder.
    Create,
    /// Creating the output's parent folder.
    CreateFolder,
    /// Writing the bytes.
    Write,
    /// Renaming the temporary file into place.
    MoveIntoPlace,
    /// Removing a stale output an earlier run left.
    RemoveStale,
}

impl WriteStep {
    /// The step as the messages name it, with its separator.
    fn prefix(self) -> &'static str {
        match self {
            WriteStep::Create => "cannot create: ",
            WriteStep::CreateFolder => "cannot create folder: ",
            WriteStep::Write => "",
            WriteStep::MoveIntoPlace => "cannot move into place: ",
            WriteStep::RemoveStale => "cannot remove a stale output: ",
        }
    }
}

/// Why an output could not be written.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum OutputError {
    /// An output that is one of the run's inputs.
    #[error("{}: is an input of this run; refusing to overwrite it", path.display())]
    Overwrite {
        /// The output.
        path: PathBuf,
    },
    /// A campaign folder that exists (synth never writes over one).
    #[error("{}: exists; synth writes a new campaign folder and does not overwrite one", path.display())]
    CampaignExists {
        /// The folder.
        path: PathBuf,
    },
    /// An output folder that is the folder a campaign reads its runs from:
    /// the next diagnosis would read the written `overlays.csv` as a run.
    #[error("{}: is the folder this campaign reads its runs from (each *.csv in it is a run), so the next diagnosis would read this one's overlays.csv as a run; write the diagnosis elsewhere (without --out it goes to {})", path.display(), default.display())]
    IntoRunsFolder {
        /// The output folder.
        path: PathBuf,
        /// Where the diagnosis goes without `--out`.
        default: PathBuf,
    },
    /// A file to write named by a folder that exists.
    #[error("{}: is a folder; name the file to write in it (e.g. {})", path.display(), path.join(format!("{stem}.{extension}")).display())]
    IsAFolder {
        /// The output.
        path: PathBuf,
        /// A name for the file, without its extension (`fit`, `forces`).
        stem: &'static str,
        /// The extension the file takes.
        extension: &'static str,
    },
    /// A file to write named with another format's extension than the
    /// one it is written in (`tyre-eval --out forces.tir`, a CSV).
    #[error("{}: {stem} are written as a .{extension} file, not .{given} (a .{extension} text under this name would not read back as a .{given}); name it {}", path.display(), path.with_extension(extension).display())]
    NotOfExtension {
        /// The output.
        path: PathBuf,
        /// What the file holds (`tyre-eval's forces`).
        stem: &'static str,
        /// The extension the file takes.
        extension: &'static str,
        /// The extension given.
        given: String,
    },
    /// A file named with another format's extension.
    #[error("{}: the {model} model is written as a .{expected} file, not .{given} (`--out {}` names the tyre file; a .{expected} text under this name would not read back as a .{given}): name it {}", path.display(), path.display(), path.with_extension(expected).display())]
    Extension {
        /// The output.
        path: PathBuf,
        /// The model written.
        model: String,
        /// Its format's extension.
        expected: &'static str,
        /// The extension given.
        given: String,
    },
    /// An output below a file where its folder would be.
    #[error("{}: cannot write: {} is a file, not a folder", path.display(), file.display())]
    NotAFolder {
        /// The output.
        path: PathBuf,
        /// The file in the way.
        file: PathBuf,
    },
    /// An output folder another run is writing into (its lock file is
    /// held by a live process).
    #[error(
        "{}: another run ({holder}) is writing into this folder; wait for it or choose another --out (if no run is going, remove {})",
        folder.display(),
        lock.display()
    )]
    Busy {
        /// The output folder.
        folder: PathBuf,
        /// Who holds it (`process 1234`, `another run`).
        holder: String,
        /// The lock file.
        lock: PathBuf,
    },
    /// A folder where the output folder's lock file should be: no run
    /// can hold the folder through it, and it is no stale lock to remove.
    #[error(
        "{}: cannot take the folder: {} is a folder where this tool's lock file should be (not a lock left by a run); remove that folder or choose another --out",
        folder.display(),
        lock.display()
    )]
    LockIsAFolder {
        /// The output folder.
        folder: PathBuf,
        /// The folder in the lock file's place.
        lock: PathBuf,
    },
    /// A file-system step that failed.
    #[error("{}: {}{source}", path.display(), step.prefix())]
    Io {
        /// The output.
        path: PathBuf,
        /// The step.
        step: WriteStep,
        /// The OS error.
        source: std::io::Error,
    },
    /// A report that could not be encoded (JSON, CSV, TOML).
    #[error("{}: {source}", path.display())]
    Encode {
        /// The output.
        path: PathBuf,
        /// The encoder's error.
        source: Box<dyn std::error::Error + Send + Sync>,
    },
    /// A fitted tyre that could not be written as TOML.
    #[error("{}: serialising the fitted tyre: {source}", path.display())]
    Tyre {
        /// The tyre file.
        path: PathBuf,
        /// The encoder's error.
        source: toml::ser::Error,
    },
    /// A figure that could not be drawn.
    #[error("{}: {detail}", path.display())]
    Draw {
        /// The image.
        path: PathBuf,
        /// The plotting library's description.
        detail: String,
    },
    /// A CSV row with another number of cells than the header.
    #[error("{}: a row of {} under {}", path.display(), plural(*cells, "cell", "cells"), plural(*columns, "column", "columns"))]
    RowLength {
        /// The CSV file.
        path: PathBuf,
        /// Cells of the row.
        cells: usize,
        /// Columns of the header.
        columns: usize,
    },
    /// Columns of unequal length.
    #[error("{}: columns of unequal length", path.display())]
    UnequalColumns {
        /// The CSV file.
        path: PathBuf,
    },
}

impl OutputError {
    /// [`OutputError::IsAFolder`] where the file to write, `path`, names a
    /// folder: one that exists, or any path written with a trailing `/`
    /// (`stem.extension` the name offered in it), checked before the job's
    /// work rather than at the rename after it ("Not a directory").
    pub fn unless_a_file(
        path: &std::path::Path,
        stem: &'static str,
        extension: &'static str,
    ) -> Result<(), OutputError> {
        let written = path.as_os_str().to_string_lossy();
        let as_folder = written.ends_with('/') || written.ends_with(std::path::MAIN_SEPARATOR);
        match path.is_dir() || as_folder {
            true => Err(OutputError::IsAFolder {
                path: path.to_path_buf(),
                stem,
                extension,
            }),
            false => Ok(()),
        }
    }

    /// Refuses a file `path` to be written as `extension` whose name has
    /// the extension of another format the tool reads or writes (`.tir`,
    /// `.toml`, `.json`, `.png`, `.svg`: a CSV under it would be taken for
    /// one); another name (`forces.out`, none) is the user's choice.
    /// `stem` says what it holds.
    pub fn unless_extension(
        path: &std::path::Path,
        stem: &'static str,
        extension: &'static str,
    ) -> Result<(), OutputError> {
        const OTHER_FORMATS: [&str; 5] = ["tir", "toml", "json", "png", "svg"];
        let given = path.extension().map(|e| e.to_string_lossy().to_string());
        let other = |g: &str| OTHER_FORMATS.iter().any(|f| g.eq_ignore_ascii_case(f));
        match given {
            Some(g) if other(&g) && !g.eq_ignore_ascii_case(extension) => {
                Err(OutputError::NotOfExtension {
                    path: path.to_path_buf(),
                    stem,
                    extension,
                    given: g,
                })
            }
            _ => Ok(()),
        }
    }

    /// The output.
    pub fn path(&self) -> &std::path::Path {
        match self {
            OutputError::Overwrite { path }
            | OutputError::IntoRunsFolder { path, .. }
            | OutputError::CampaignExists { path }
            | OutputError::NotAFolder { path, .. }
            | OutputError::IsAFolder { path, .. }
            | OutputError::Extension { path, .. }
            | OutputError::NotOfExtension { path, .. }
            | OutputError::Io { path, .. }
            | OutputError::Encode { path, .. }
            | OutputError::Tyre { path, .. }
            | OutputError::Draw { path, .. }
            | OutputError::RowLength { path, .. }
            | OutputError::UnequalColumns { path } => path,
            OutputError::Busy { folder, .. } | OutputError::LockIsAFolder { folder, .. } => folder,
        }
    }

    /// A failed file-system `step` of writing `path`.
    pub fn io(path: &std::path::Path, step: WriteStep, source: std::io::Error) -> Self {
        OutputError::Io {
            path: path.to_path_buf(),
            step,
            source,
        }
    }

    /// A report for `path` that could not be encoded.
    pub(crate) fn encode(
        path: &std::path::Path,
        source: impl std::error::Error + Send + Sync + 'static,
    ) -> Self {
        OutputError::Encode {
            path: path.to_path_buf(),
            source: Box::new(source),
        }
    }
}
