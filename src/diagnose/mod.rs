//! The sim-to-real gap (issue 6). So far: where the gap lies ([`gap`]) for a
//! measured run replayed with its own steer and speed. The library of
//! candidate effects, their fitting and ranking, and the synthetic proving
//! ground are not built yet.

pub mod gap;
