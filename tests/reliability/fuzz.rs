//! Fuzzing of every reader: proptest feeds each one mutations
//! ([`crate::mutate`]) of a valid file and checks that it never panics and
//! that every refusal names the file and, when it points at a place, a line
//! inside the file and a column ≥ 1 (and, for the CSV readers, the column by
//! name, the header or the malformed row). `HANDLING_FUZZ_CASES` sets the
//! cases per reader (default 200); a watchdog aborts, printing the input,
//! if one case takes longer than 20 s (a reader that hangs).
//!
//! The CSV readers are here, the TOML readers in [`crate::fuzz_toml`].

use crate::mutate::{apply, mutations};
use crate::{env_count, fs, inputs, Path};
use handling::error::InputError;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// What kind of file a reader reads, for the checks of its messages.
#[derive(Clone, Copy, PartialEq)]
pub enum Kind {
    Csv,
    Text,
}

/// Tallies of a fuzzing session.
#[derive(Debug, Default)]
pub struct Tally {
    pub accepted: usize,
    pub refused: usize,
}

/// The case being read and when it started, for the watchdog.
type Current = Arc<Mutex<(Instant, Vec<u8>)>>;

fn watchdog(name: &'static str, current: Current, done: Arc<AtomicBool>) {
    std::thread::spawn(move || {
        while !done.load(Ordering::Relaxed) {
            std::thread::sleep(Duration::from_millis(500));
            let (t0, bytes) = current
                .lock()
                .map(|g| g.clone())
                .unwrap_or_else(|p| p.into_inner().clone());
            if t0.elapsed() > Duration::from_secs(20) && !done.load(Ordering::Relaxed) {
                eprintln!(
                    "{name}: one case has run for 20 s; the input:\n{}",
                    String::from_utf8_lossy(&bytes)
                );
                std::process::abort();
            }
        }
    });
}

/// Checks a refusal of `path` (whose content was `bytes`).
pub fn check_refusal(e: &InputError, path: &Path, bytes: &[u8], kind: Kind) -> Result<(), String> {
    let msg = e.to_string();
    let name = path.display().to_string();
    if !msg.contains(&name) {
        return Err(format!("the message does not name {name}: {msg}"));
    }
    if let Some(at) = e.location() {
        let lines = bytes.split(|&c| c == b'\n').count();
        if at.line < 1 || at.line > lines + 1 || at.column < 1 {
            return Err(format!("a place outside the file ({lines} lines): {msg}"));
        }
        let named = ["column `", "header", "malformed CSV", "UTF-8"];
        if kind == Kind::Csv && !named.iter().any(|n| msg.contains(n)) {
            return Err(format!("a CSV error naming no column: {msg}"));
        }
        // A value refused on its merits names its key (a byte that is not
        // UTF-8 is the file's encoding, at its line and column, no value).
        let encoding = msg.contains("is not UTF-8");
        if kind == Kind::Text && msg.contains(" must ") && !msg.contains('`') && !encoding {
            return Err(format!("a value error naming no key: {msg}"));
        }
    }
    if msg.trim_end().ends_with(':') || msg.trim() == name {
        return Err(format!("an empty message: {msg}"));
    }
    Ok(())
}

/// Runs `HANDLING_FUZZ_CASES` (default 200) mutations of `valid` written to
/// `path` through `read`; panics on the first failing case (shrunk).
pub fn fuzz<T>(
    name: &'static str,
    path: &Path,
    valid: &[u8],
    kind: Kind,
    read: impl Fn(&Path) -> Result<T, InputError>,
) -> Tally {
    // The valid file reads.
    fs::write(path, valid).unwrap();
    if let Err(e) = read(path) {
        panic!("{name}: the valid file is refused: {e}");
    }
    let cases = env_count("HANDLING_FUZZ_CASES", 200) as u32;
    // Seeded: a failure in CI reproduces (`HANDLING_FUZZ_SEED`, default 0).
    let seed = env_count("HANDLING_FUZZ_SEED", 0);
    let mut key = [0u8; 32];
    key[..8].copy_from_slice(&seed.to_le_bytes());
    let config = Config {
        cases,
        failure_persistence: None,
        max_shrink_iters: 2000,
        ..Config::default()
    };
    let mut runner =
        TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &key));
    let current: Current = Arc::new(Mutex::new((Instant::now(), Vec::new())));
    let done = Arc::new(AtomicBool::new(false));
    watchdog(name, current.clone(), done.clone());
    let (accepted, refused) = (AtomicUsize::new(0), AtomicUsize::new(0));
    let t0 = Instant::now();
    let result = runner.run(&mutations(), |ms| {
        let bytes = apply(valid, &ms);
        *current.lock().unwrap() = (Instant::now(), bytes.clone());
        fs::write(path, &bytes).unwrap();
        let seen = accepted.load(Ordering::Relaxed) + refused.load(Ordering::Relaxed);
        if seen > 0 && seen % 10_000 == 0 {
            eprintln!("{name}: {seen} cases, {:.0} s", t0.elapsed().as_secs_f64());
        }
        match read(path) {
            Ok(_) => accepted.fetch_add(1, Ordering::Relaxed),
            Err(e) => {
                check_refusal(&e, path, &bytes, kind).map_err(TestCaseError::fail)?;
                refused.fetch_add(1, Ordering::Relaxed)
            }
        };
        Ok(())
    });
    done.store(true, Ordering::Relaxed);
    if let Err(e) = result {
        panic!("{name}: {e}");
    }
    let tally = Tally {
        accepted: accepted.into_inner(),
        refused: refused.into_inner(),
    };
    eprintln!(
        "{name}: {cases} cases (seed {seed}) in {:.1} s, {} accepted, {} refused, no panic",
        t0.elapsed().as_secs_f64(),
        tally.accepted,
        tally.refused
    );
    // The mutations must bite: most of them break a valid file.
    assert!(tally.refused * 4 >= tally.accepted, "{name}: {tally:?}");
    tally
}

#[test]
fn measured_run_reader_survives_mutations() {
    let dir = tempfile::tempdir().unwrap();
    let valid = inputs::run_csv(60, 25.0);
    fuzz(
        "run",
        &dir.path().join("run.csv"),
        valid.as_bytes(),
        Kind::Csv,
        handling::io::read_run,
    );
}

#[test]
fn rig_reader_survives_mutations() {
    let dir = tempfile::tempdir().unwrap();
    let valid = inputs::rig_csv();
    fuzz(
        "rig",
        &dir.path().join("rig.csv"),
        valid.as_bytes(),
        Kind::Csv,
        handling::io::rig::read_rig,
    );
}
