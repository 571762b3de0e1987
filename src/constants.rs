//! Physical constants shared by the models and the processing of measured
//! data. This module imports nothing, so that any layer (the vehicle model,
//! the measured runs, the readers) can use it without depending on another.
//!
//! Units: SI. Source: the conventional value of standard gravity adopted by
//! the 3rd CGPM (1901), as in ISO 80000-3 (2019).

/// Standard gravity, m/s².
pub const G: f64 = 9.80665;
