//! The sim-to-real gap (issue 6). So far: where the gap lies ([`gap`]) for a
//! measured run replayed with its own steer and speed, and the sensor effects
//! ([`sensors`]); the vehicle-side effects live in
//! [`crate::vehicle::Effects`]. The candidate-effect fitting and ranking and
//! the synthetic proving ground are not built yet.

pub mod gap;
pub mod sensors;
