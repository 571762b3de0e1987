//! What a path a key names leads to ([`super::InputProblem::MissingFile`]).

/// What a path a key names leads to, when it is not what the key wants.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PathFound {
    /// Nothing.
    Nothing,
    /// A folder where a file was wanted.
    FolderNotFile,
    /// A file where a folder was wanted.
    FileNotFolder,
}

impl PathFound {
    pub(super) fn describe(self) -> &'static str {
        match self {
            PathFound::Nothing => "which does not exist",
            PathFound::FolderNotFile => "which is a folder, not a file",
            PathFound::FileNotFolder => "which is a file, not a folder",
        }
    }
}
