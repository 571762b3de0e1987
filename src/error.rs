//! Error types. Parameter errors name the key, the value and why it is wrong;
//! the I/O layer adds the file, line and column.

use std::path::PathBuf;
use thiserror::Error;

/// A parameter value that is not physical.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("`{key}` = {value}: {reason}")]
pub struct ParamError {
    /// Dotted key path, e.g. `vehicle.mass` or `a[4]`.
    pub key: String,
    /// The offending value (NaN when it is not a number).
    pub value: f64,
    /// Why it is wrong.
    pub reason: String,
}

impl ParamError {
    /// A parameter error for `key`.
    pub fn new(key: &str, value: f64, reason: &str) -> Self {
        Self {
            key: key.to_string(),
            value,
            reason: reason.to_string(),
        }
    }
    /// Prefixes the key with a table name: `mass` → `vehicle.mass`.
    pub fn within(mut self, table: &str) -> Self {
        self.key = format!("{table}.{}", self.key);
        self
    }
    /// Ok when `v` is finite.
    pub fn finite(key: &str, v: f64) -> Result<(), Self> {
        if v.is_finite() {
            Ok(())
        } else {
            Err(Self::new(key, v, "must be a finite number"))
        }
    }
    /// Ok when `v` is finite and > 0.
    pub fn positive(key: &str, v: f64) -> Result<(), Self> {
        Self::finite(key, v)?;
        if v > 0.0 {
            Ok(())
        } else {
            Err(Self::new(key, v, "must be positive"))
        }
    }
    /// Ok when `v` is finite and ≥ 0.
    pub fn non_negative(key: &str, v: f64) -> Result<(), Self> {
        Self::finite(key, v)?;
        if v >= 0.0 {
            Ok(())
        } else {
            Err(Self::new(key, v, "must not be negative"))
        }
    }
    /// Ok when `lo < v ≤ hi`.
    pub fn in_range(key: &str, v: f64, lo: f64, hi: f64, why: &str) -> Result<(), Self> {
        Self::finite(key, v)?;
        if v > lo && v <= hi {
            Ok(())
        } else {
            Err(Self::new(
                key,
                v,
                &format!("must lie in ({lo}, {hi}]: {why}"),
            ))
        }
    }
}

/// Errors from reading input files, located in the file.
#[derive(Debug, Error)]
pub enum InputError {
    /// The file could not be read.
    #[error("{path}: cannot read: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The OS error.
        source: std::io::Error,
    },
    /// Wrong content at a known place.
    #[error("{path}:{line}:{column}: {message}")]
    At {
        /// The file.
        path: PathBuf,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What is wrong, naming the key or column and the value.
        message: String,
    },
    /// Wrong content with no single place (a missing key or column).
    #[error("{path}: {message}")]
    File {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
}
