//! The sim-to-real gap of measured runs and its diagnosis: where a
//! replayed run and its measurement disagree, and which candidate effects,
//! added to the base model, close that gap on held-out runs.
//!
//! In the order the data flow:
//! - the campaign (`campaign`: vehicle, base tyres, runs, settings);
//! - the candidate effects (`effects`, the sensor effects in `sensors`)
//!   and the augmented 2-DOF model that carries them (`model`);
//! - the gap of a replay, by channel and by part of a run (`gap`,
//!   `parts`);
//! - fitting: the measured channels (`channels`), a run made ready for
//!   replays (`replay`), the output-error problem (`problem`), the swarm
//!   search, Levenberg–Marquardt polish and standard errors (`fit`), the
//!   cross-validation's fold refits (`refit`), and the base model's axles
//!   identified from the runs when there are no tyre data (`base`);
//! - the diagnosis: the candidates and their starts (`candidates`), their
//!   scores on held-out runs (`crossval`), the search for a verdict
//!   (`search`), the singles screened before their cross-validation
//!   (`screening`), the gap tables (`summary`), the report's types
//!   (`report`), the whole (`diagnosis`) and where its time goes
//!   ([`timing`]);
//! - the virtual proving ground that generates campaigns with known
//!   effects ([`synth`]; its independent four-wheel truth in
//!   `proving_ground`).
//!
//! The public surface is what the command line, the benches, the tests and
//! the Python package use: [`diagnose`] and its [`Diagnosis`], the
//! campaign's types, the effects, the proving ground, and the replay of a
//! run ([`Prepared`], [`Augmented`]) the benches time.

mod axles;
mod base;
pub(crate) mod campaign;
mod candidates;
pub(crate) mod channels;
mod crossval;
pub(crate) mod diagnosis;
pub mod effects;
mod fit;
pub(crate) mod gap;
mod layout;
mod model;
mod parts;
mod problem;
mod proving_ground;
mod refit;
mod replay;
pub(crate) mod report;
mod screening;
mod search;
mod sensors;
mod summary;
pub mod synth;
mod tangent;
pub mod timing;

pub use base::{AxleIdentification, AxleLimit, AxleValue};
pub use campaign::{BaseTyres, Campaign, DiagnoseSettings};
pub use diagnosis::{diagnose, diagnose_timed, Diagnosis};
pub use model::Augmented;
pub use replay::Prepared;
