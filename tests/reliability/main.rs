//! Reliability of the readers, the outputs and the long-log paths: every
//! reader fuzzed with structured mutations of valid files (no panic, every
//! refusal located in its file), outputs that survive a SIGKILL at any
//! moment, one run per output folder, memory and time linear in a long log,
//! and no NaN or infinity in a JSON report built from degenerate runs.
//!
//! Case counts: `HANDLING_FUZZ_CASES` (default 200 per reader) and
//! `HANDLING_KILL_MOMENTS` (default 10 per command).

mod finite;
mod fuzz;
mod fuzz_toml;
mod inputs;
mod kill;
mod locks;
mod long_log;
mod long_log_rows;
mod mutate;
mod no_nan;

pub(crate) use std::fs;
pub(crate) use std::path::{Path, PathBuf};

/// The repository root.
pub(crate) fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A number from the environment variable `name`, or `default`.
pub(crate) fn env_count(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}
