//! The sim-to-real gap (issue 6): where a replayed run and its measurement
//! disagree ([`gap`]), the library of candidate effects ([`effects`]) and
//! the augmented model that carries them ([`model`]), the sensor effects
//! ([`sensors`]).

pub mod effects;
pub mod gap;
pub mod model;
pub mod sensors;
