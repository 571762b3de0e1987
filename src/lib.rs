//! `handling`: a vehicle handling simulator and analysis toolkit around a
//! 2-DOF (sideslip β, yaw rate r) model with lateral load transfer
//! (longitudinal load transfer among its optional effects) and pluggable
//! nonlinear tyres: Gim (brush model), the simplified
//! Magic Formula, the linear tyre, UniTire, PAC89 and the Magic Formula
//! 5.2 / 6.1 / 6.2 of `.tir` files, one registry of them ([`tyre`]) to which
//! a model from outside the crate is added with [`tyre::register`].
//!
//! SI units and radians everywhere; ISO 8855 axes (x forward, y left, z up;
//! positive steer turns left). The measured-data formats are in
//! the book's chapter on file formats (`docs/src/formats.md`), which also
//! describes the project's own files.
//!
//! # Capabilities and where they live
//! The modules in their layers, lowest first: a module imports only from
//! the layers below its own (`tests/architecture.rs` checks it; the book's
//! architecture chapter draws it).
//!
//! | capability | module |
//! |---|---|
//! | physical constants (standard gravity) | [`constants`] |
//! | numbers as messages print them | [`format`] |
//! | the scalar the models are written in: `f64`, or a dual number for exact derivatives | [`scalar`] |
//! | sample statistics the checks share: centred sums and Pearson correlation, pooled over runs | [`stats`] |
//! | the library's one error type, by kind (input, parameter, options, fit, metrics, diagnosis, output) | [`error`] |
//! | tyre models (one file each, one registry), their parameter vectors and `.tir` coefficients | [`tyre`] |
//! | PSO variants, Levenberg–Marquardt (bounded, with exact or difference Jacobians), modified Gauss–Newton, standard errors | [`optim`] |
//! | step, ramp, sine, sweep and replayed manoeuvres | [`manoeuvre`] |
//! | CSV, JSON, PNG, SVG and HTML outputs, written atomically, one run per output folder | [`report`] |
//! | vehicle parameters and the one right-hand side (2-DOF with load transfer, optional effects and extra states) | [`vehicle`] |
//! | measured runs as the jobs take them: cleaning (standstills, glitches), longitudinal acceleration, road geometry | [`measured`] |
//! | the integrators (RK4, Dormand–Prince 5(4) with dense output, ROS34PW2 for stiff replays) and the replay in dual numbers | [`sim`] |
//! | GB/T 6323 / ISO 7401 step-steer metrics, total variances, Er, of simulations and measured runs | [`metrics`] |
//! | steering equilibria, stability, bifurcations | [`equilibria`] |
//! | tyre identification from rig data (grouping, swarm fits, PAC89's two stages, the staged Magic Formula fit) | [`identify`] |
//! | cornering stiffness ↔ handling maps, the RBF network and the inverse | [`study`] |
//! | the sim-to-real gap of measured runs and its diagnosis | [`diagnose`] |
//! | the virtual proving ground: campaigns with known, withheld effects | [`proving_ground`] |
//! | the next test to drive: manoeuvres that separate confounded candidates, with their predicted separation | [`design`] |
//! | reading and validating files (scenarios, tyre and `.tir` files, rig data, runs, campaigns) | [`io`] |
//! | the commands of the binary, each one function with a typed report | [`jobs`] |
//!
//! The command line (`src/cli`, the `cli` feature) sits above them in the
//! binary: it parses, calls a job, writes and prints.
//!
//! # References
//! - Zhang Jiaxu, Li Jing (2017): UniTire parameter identification by a
//!   hybrid of PSO and a modified Gauss–Newton method. J. Jilin Univ.
//!   (Eng. Techn.) 47(1). Used in [`identify`], [`tyre`] (UniTire), [`optim`].
//! - Zhang Lixia, Liu Jiaqi, Pan Fuquan, Zhang Wencai, Zheng Chaoyi (2021):
//!   two-stage identification of PAC89 parameters by an improved PSO. Science
//!   Technology and Engineering 21(16). Used in [`identify`], [`optim`].
//! - Wei Yaobing et al. (2010): MF-Tyre 6.1.1 identification by
//!   Levenberg–Marquardt, with a survey of tyre models. Used in
//!   [`identify`] (the staged Magic Formula fit).
//! - Pacejka (2012): *Tire and Vehicle Dynamics*, 3rd ed., ch. 4.3, with
//!   the TNO MF-Tyre 6.1/6.2 equations as MFeval (M. Furlan) implements
//!   them. Used in [`tyre`] (the Magic Formula).
//! - Li Jie, Jia Changwang, Zhao Qi (Jilin University, undated): nonlinear
//!   steering equilibria of a 2-DOF vehicle by PSO. Used in [`equilibria`].
//! - Wang Guolin, Liang Xinxin (Jiangsu University, undated): tyre cornering
//!   stiffness and handling by inverse dynamics. Used in [`study`],
//!   [`metrics`].

#![warn(missing_docs)]

pub mod constants;
pub mod design;
pub mod diagnose;
pub mod equilibria;
pub mod error;
pub mod format;
pub mod identify;
pub mod io;
pub mod jobs;
pub mod manoeuvre;
pub mod measured;
pub mod metrics;
pub mod optim;
pub mod proving_ground;
pub mod report;
pub mod scalar;
pub mod sim;
pub mod stats;
pub mod study;
pub mod tyre;
pub mod vehicle;
