//! Optimisers shared by identification, equilibria and diagnosis: particle
//! swarm optimisation in the papers' variants (seed 000, 001, 003) and local
//! least-squares polish (Levenberg–Marquardt, seed 000's modified
//! Gauss–Newton). Every random search takes a seed and is reproducible.

pub mod bounded;
pub mod local;
pub mod pso;

pub use pso::{Boundary, Inertia, Pso, PsoResult, Topology};
