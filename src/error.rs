//! Error types: [`Error`], the one error of the library's public functions,
//! wraps the parameter errors ([`ParamError`]: the key, the value and why it
//! is wrong), the input errors ([`InputError`]: the file, line and column the
//! I/O layer adds) and the failures of the jobs themselves.

use crate::metrics::MetricsError;
use std::path::PathBuf;
use thiserror::Error;

/// The library's error: why a job (a command of the binary, or any public
/// function that reads, fits or writes) could not be done. Its message is
/// complete on its own; wrapped errors keep their own messages and sources.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum Error {
    /// A parameter value that is not physical.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// An input file that cannot be read or holds wrong content.
    #[error(transparent)]
    Input(#[from] InputError),
    /// The step-steer metrics of a response could not be computed.
    #[error("step-steer metrics: {0}")]
    StepMetrics(MetricsError),
    /// A fit that cannot be made (too few loads or points, nothing to fit)
    /// or whose stages failed.
    #[error("{0}")]
    Fit(String),
    /// A job that failed on an input: it holds nothing the job can use, or
    /// a fit to it failed.
    #[error("{path}: {message}")]
    Data {
        /// The input.
        path: PathBuf,
        /// What it lacks, or why the fit failed.
        message: String,
    },
    /// Options that contradict each other or name nothing known.
    #[error("{0}")]
    Options(String),
    /// The diagnosis could not be made.
    #[error("{0}")]
    Diagnosis(String),
    /// An output that is one of the run's inputs.
    #[error("{path}: is an input of this run; refusing to overwrite it")]
    Overwrite {
        /// The output.
        path: PathBuf,
    },
    /// An output that exists and that the job never writes over.
    #[error("{path}: exists; {why}")]
    Exists {
        /// The output.
        path: PathBuf,
        /// Why the job does not overwrite it.
        why: String,
    },
    /// An output that could not be written.
    #[error("{path}: {message}")]
    Output {
        /// The output.
        path: PathBuf,
        /// What failed.
        message: String,
    },
}

impl Error {
    /// A failure to write `path`, with what failed.
    pub fn output(path: &std::path::Path, message: impl std::fmt::Display) -> Self {
        Error::Output {
            path: path.to_path_buf(),
            message: message.to_string(),
        }
    }
}

/// The member of the closed set `all` whose name (`name`) is `s`, or the
/// message that names `s` and every member: "unknown {what} `s`: one of
/// a, b, c". The one parser of the names of closed sets (metrics, units,
/// tyre models).
pub fn by_name<T: Copy>(
    all: &[T],
    name: impl Fn(T) -> &'static str,
    what: &str,
    s: &str,
) -> Result<T, String> {
    all.iter().copied().find(|&m| name(m) == s).ok_or_else(|| {
        let names: Vec<&str> = all.iter().map(|&m| name(m)).collect();
        format!("unknown {what} `{s}`: one of {}", names.join(", "))
    })
}

/// The value of a [`ParamError`]: a number, or none to show (a name, a
/// table, a missing key).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ParamValue {
    /// The offending number (itself NaN or infinite when that is what is
    /// wrong).
    Number(f64),
    /// The value is not a number.
    NotANumber,
}

impl ParamValue {
    /// The number, if the value is one.
    pub fn number(self) -> Option<f64> {
        match self {
            ParamValue::Number(v) => Some(v),
            ParamValue::NotANumber => None,
        }
    }
}

impl std::fmt::Display for ParamValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ParamValue::Number(v) => write!(f, "{v}"),
            ParamValue::NotANumber => f.write_str("(not a number)"),
        }
    }
}

/// A parameter value that is not physical, or a key whose value is wrong in
/// another way (a name, a missing table).
#[derive(Debug, Clone, PartialEq, Error)]
pub struct ParamError {
    /// Dotted key path, e.g. `vehicle.mass` or `a[4]`.
    pub key: String,
    /// The offending value.
    pub value: ParamValue,
    /// Why it is wrong.
    pub reason: String,
}

impl std::fmt::Display for ParamError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.value {
            ParamValue::Number(v) => write!(f, "`{}` = {v}: {}", self.key, self.reason),
            ParamValue::NotANumber => write!(f, "`{}`: {}", self.key, self.reason),
        }
    }
}

impl ParamError {
    /// A parameter error for `key` holding the number `value`.
    pub fn new(key: &str, value: f64, reason: &str) -> Self {
        Self {
            key: key.to_string(),
            value: ParamValue::Number(value),
            reason: reason.to_string(),
        }
    }
    /// An error for `key` whose value is not a number (a name, a table).
    pub fn without_value(key: &str, reason: &str) -> Self {
        Self {
            key: key.to_string(),
            value: ParamValue::NotANumber,
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
