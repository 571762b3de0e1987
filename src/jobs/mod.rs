//! The commands of the binary as library functions: each reads its inputs,
//! does the work and returns a typed, serialisable report that writes its
//! own outputs (`write`) and says what it found in lines of text
//! (`summary`). The binary only parses arguments, calls, writes and prints.
//!
//! | command | function | report |
//! |---|---|---|
//! | `simulate` | [`simulate::run`] | [`simulate::SimulateReport`] |
//! | `metrics` | [`metrics::run`] | [`metrics::MeasuredMetricsReport`] |
//! | `equilibria` | [`equilibria::run`] | [`equilibria::EquilibriaReport`] |
//! | `identify` | [`identify::run`] | [`identify::IdentifyReport`] |
//! | `study` | [`study::run`] | [`study::StudyReport`] |
//! | `diagnose` | [`diagnose::run`] | [`diagnose::DiagnoseReport`] |
//! | `synth` | [`synth::run`] | [`synth::SynthReport`] |
//! | `design` | [`design::run`] | [`design::DesignReport`] |
//! | `tyre-eval` | [`tyre_eval::run`] | [`tyre_eval::TyreEvalReport`] |
//! | `diagnose --batch DIR [--shard K/N]` | [`fleet::run_batch`], [`fleet::merge`] | [`fleet::FleetReport`] |
//! | `equilibria --shard K/N`, `merge` | [`equilibria::run_shard`], [`equilibria::merge`] | [`shard::ShardReport`], [`equilibria::EquilibriaReport`] |
//!
//! `identify` and `study` live in their own modules; the jobs here combine
//! modules (a scenario, the integrator and the metrics; the diagnosis and
//! its figures) and hold their figures beside them.

pub mod design;
pub mod diagnose;
mod diagnose_gap_map;
mod diagnose_overlays;
pub mod diagnose_page;
pub mod equilibria;
pub mod fleet;
pub mod identify;
pub mod metrics;
pub mod shard;
pub mod simulate;
pub mod study;
pub mod synth;
pub mod tyre_eval;
