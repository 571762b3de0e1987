//! `handling`: a vehicle handling simulator and analysis toolkit around a
//! 2-DOF (sideslip β, yaw rate r) model with lateral load transfer and
//! pluggable nonlinear tyres (Gim, simplified Magic Formula, UniTire, PAC89).
//!
//! SI units and radians everywhere; ISO 8855 axes (x forward, y left, z up;
//! positive steer turns left). See the README for the file formats.

pub mod diagnose;
pub mod equilibria;
pub mod error;
pub mod identify;
pub mod io;
pub mod manoeuvre;
pub mod metrics;
pub mod optim;
pub mod report;
pub mod sim;
pub mod study;
pub mod tyre;
pub mod vehicle;
