//! Parameter errors: a key (dotted, `vehicle.mass`), the value it holds and
//! why that value is not physical (a [`ParamReason`]). The checks every
//! reader and constructor shares (finite, positive, non-negative, in a
//! range) live here.

use super::number::Num;
use super::reason::{Limit, ParamReason};
use thiserror::Error;

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
            ParamValue::Number(v) => write!(f, "{}", Num(*v)),
            ParamValue::NotANumber => f.write_str("(not a number)"),
        }
    }
}

/// A parameter value that is not physical, or a key whose value is wrong in
/// another way (a name, a missing table).
#[derive(Debug, Clone, PartialEq, Error)]
pub struct ParamError {
    /// Dotted key path, e.g. `vehicle.mass` or `a4` (PAC89's, as `--hold` names it).
    pub key: String,
    /// The offending value.
    pub value: ParamValue,
    /// Why it is wrong.
    pub reason: ParamReason,
}

impl std::fmt::Display for ParamError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.value {
            ParamValue::Number(v) => write!(f, "`{}` = {}: {}", self.key, Num(v), self.reason),
            ParamValue::NotANumber => write!(f, "`{}`: {}", self.key, self.reason),
        }
    }
}

impl ParamError {
    /// A parameter error for `key` holding the number `value`.
    pub fn new(key: &str, value: f64, reason: impl Into<ParamReason>) -> Self {
        Self {
            key: key.to_string(),
            value: ParamValue::Number(value),
            reason: reason.into(),
        }
    }
    /// An error for `key` whose value is not a number (a name, a table).
    pub(crate) fn without_value(key: &str, reason: impl Into<ParamReason>) -> Self {
        Self {
            key: key.to_string(),
            value: ParamValue::NotANumber,
            reason: reason.into(),
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
            Err(Self::new(key, v, ParamReason::NotFinite))
        }
    }
    /// Ok when `v` is finite and > 0.
    pub fn positive(key: &str, v: f64) -> Result<(), Self> {
        Self::finite(key, v)?;
        if v > 0.0 {
            Ok(())
        } else {
            Err(Self::new(key, v, ParamReason::NotPositive))
        }
    }
    /// Ok when `v` is finite and ≥ 0.
    pub(crate) fn non_negative(key: &str, v: f64) -> Result<(), Self> {
        Self::finite(key, v)?;
        if v >= 0.0 {
            Ok(())
        } else {
            Err(Self::new(key, v, ParamReason::Negative))
        }
    }
    /// Ok when `lo < v ≤ hi`; `why` says why the range is what it is.
    pub(crate) fn in_range(key: &str, v: f64, lo: f64, hi: f64, why: Limit) -> Result<(), Self> {
        Self::finite(key, v)?;
        if v > lo && v <= hi {
            Ok(())
        } else {
            Err(Self::new(key, v, ParamReason::OutOfRange { lo, hi, why }))
        }
    }
}
