//! The sim-to-real gap of measured runs and its diagnosis: where a
//! replayed run and its measurement disagree, and which candidate effects,
//! added to the base model, close that gap on held-out runs.
//!
//! The diagnosis is a pipeline of stages ([`pipeline`] runs them in
//! order); each room of this folder answers one question:
//!
//! | room | question |
//! |---|---|
//! | [`campaign`] | what the diagnosis is given: vehicle, base tyres, runs, settings |
//! | [`effects`] | which candidate effects exist: each defined once (parameters, units, bounds, off values, signature, needs, truth, how it sets the vehicle model's effects) |
//! | `model` | how a run is replayed: the augmented model, its axle characteristics, the measured channels, a run made ready for replays |
//! | `fit` | how a parameter vector is fitted: the output-error problem, its layout, exact Jacobians, swarm and Levenberg–Marquardt, the fold refits |
//! | `base` | how the base model is found: given tyres, a rig fit, or axles identified from the runs |
//! | `verdict` | how the verdict is chosen: candidates scored on held-out runs, screening, the search, its rules as pure functions, and the verdict's case |
//! | [`report`] | what the report says: its types, the typed outcome (the verdict's cases, refusals, warnings, notes), where the gap lies (per run, channel, window, regime), the tables, and the words made from them in one place |
//! | [`pipeline`] | the stages in order, and [`timing`] where their time goes |
//! | `unit_ratio` | a band gain of 180/π said as a unit slip (degrees read as radians), beside `effects` and `timing` in the first stage |
//!
//! The virtual proving ground that generates campaigns with known effects
//! to check the diagnosis against is not part of it: it lives above it, in
//! [`crate::proving_ground`].
//!
//! The public surface is what the command line, the benches, the tests and
//! the Python package use: [`diagnose`] and its [`Diagnosis`] with the
//! report's types ([`Verdict`], [`Ranked`], …, and their words), the
//! campaign's types, the effects, and the replay of a run ([`Prepared`],
//! [`Augmented`]) the benches time.

mod base;
pub mod campaign;
pub mod effects;
pub(crate) mod fit;
pub(crate) mod model;
pub mod pipeline;
pub mod report;
pub mod timing;
mod unit_ratio;
mod verdict;
pub(crate) use verdict::rules;

pub use base::identify::{AxleIdentification, AxleLimit, AxleValue};
pub use campaign::{BaseTyres, Campaign, DiagnoseSettings};
pub use model::channels::Channel;
pub use model::replay::Prepared;
pub use model::Augmented;
pub use pipeline::{diagnose, diagnose_timed, Diagnosis};
pub use report::{Ranked, Verdict, VerdictKind};
