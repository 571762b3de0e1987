//! Runs a campaign selects twice under two names: a file copied byte for
//! byte (`run_2.csv` saved again as `run_2_copy.csv`). Held out, the copy
//! is scored on the very samples its twin was fitted on, so a candidate's
//! held-out gain is its in-sample gain again: evidence counted twice. A
//! copy is refused at its `[runs]` entry, as the same file listed twice is
//! ([`super::runs`]). Files are compared by their bytes (a hash first, then
//! the bytes of the pairs it matches).

use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::path::PathBuf;

/// The first pair of indices of `files` whose contents are the same bytes,
/// in order (a file that cannot be read is left to the reading, which says
/// why).
pub(super) fn copied_run(files: &[PathBuf]) -> Option<(usize, usize)> {
    let mut seen: Vec<(u64, usize, Vec<u8>)> = Vec::new();
    for (i, f) in files.iter().enumerate() {
        let Ok(bytes) = std::fs::read(f) else {
            continue;
        };
        let mut h = DefaultHasher::new();
        bytes.hash(&mut h);
        let hash = h.finish();
        if let Some((_, k, _)) = seen.iter().find(|(g, _, b)| *g == hash && *b == bytes) {
            return Some((*k, i));
        }
        seen.push((hash, i, bytes));
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_copy_is_found_and_a_file_differing_by_one_byte_is_not() {
        let dir = tempfile::tempdir().unwrap();
        let write = |name: &str, text: &str| {
            let p = dir.path().join(name);
            std::fs::write(&p, text).unwrap();
            p
        };
        let a = write("a.csv", "t,steer\n0,0.01\n");
        let b = write("b.csv", "t,steer\n0,0.02\n");
        let c = write("c.csv", "t,steer\n0,0.01\n");
        assert_eq!(copied_run(&[a.clone(), b.clone()]), None);
        assert_eq!(copied_run(&[a, b, c]), Some((0, 2)));
    }
}
