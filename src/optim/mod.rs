//! Optimisers shared by identification, equilibria and diagnosis: particle
//! swarm optimisation in the papers' variants (Zhang & Li 2017; Zhang et al. 2021; Li, Jia & Zhao) and local
//! least-squares polish (Levenberg–Marquardt, Zhang & Li's (2017) modified
//! Gauss–Newton). Every random search takes a seed and is reproducible.

pub(crate) mod bounded;
pub mod local;
pub(crate) mod pso;
pub(crate) mod stats;

pub use pso::{Boundary, Inertia, Pso, PsoResult, Topology};
