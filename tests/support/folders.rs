//! Folders a test copies: a bundled input folder into a scratch copy, a
//! campaign generated once into each test's own folder.

use std::fs;
use std::path::Path;

/// Copies folder `from` (its files and sub-folders) into `to`, created if
/// missing.
pub(crate) fn copy_folder(from: &Path, to: &Path) {
    fs::create_dir_all(to).unwrap();
    for entry in fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let target = to.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            copy_folder(&entry.path(), &target);
        } else {
            fs::copy(entry.path(), target).unwrap();
        }
    }
}
