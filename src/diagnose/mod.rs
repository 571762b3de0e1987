//! The sim-to-real gap: where a replayed run and its measurement
//! disagree ([`gap`]), the library of candidate effects ([`effects`]) and
//! the augmented model that carries them ([`model`]), the base model
//! identified from the runs when there are no tyre data (`base`), the sensor effects
//! ([`sensors`]), output-error fits over runs ([`fit`]) and the diagnosis
//! that ranks the effects on held-out runs ([`diagnosis`]; its search for
//! a verdict in `search`).

mod base;
pub mod campaign;
mod candidates;
pub mod channels;
mod crossval;
pub mod diagnosis;
pub mod effects;
pub mod fit;
pub mod gap;
pub mod model;
pub mod parts;
mod problem;
pub mod proving_ground;
mod refit;
pub mod replay;
pub mod report;
mod search;
pub mod sensors;
mod summary;
pub mod synth;

pub use base::{AxleIdentification, AxleLimit, AxleValue};
pub use campaign::{BaseTyres, Campaign, DiagnoseSettings};
pub use diagnosis::{diagnose, Diagnosis};
