//! `handling`: a vehicle handling simulator and analysis toolkit around a
//! 2-DOF (sideslip β, yaw rate r) model with lateral load transfer and
//! pluggable nonlinear tyres (Gim, simplified Magic Formula, UniTire, PAC89).
//!
//! SI units and radians everywhere; ISO 8855 axes (x forward, y left, z up;
//! positive steer turns left). The measured-data formats are in
//! the book's chapter on file formats (`docs/src/formats.md`), which also
//! describes the project's own files.
//!
//! # Capabilities and where they live
//! | capability | module |
//! |---|---|
//! | tyre models (one file each) and their parameter vectors | [`tyre`] |
//! | vehicle parameters, the one right-hand side (2-DOF with load transfer, optional effects and extra states) | [`vehicle`] |
//! | the one integrator (RK4, Dormand–Prince 5(4) with dense output) for every job | [`sim`] |
//! | step, ramp, sine, sweep and replayed manoeuvres | [`manoeuvre`] |
//! | GB/T 6323 / ISO 7401 step-steer metrics, total variances, Er | [`metrics`] |
//! | PSO variants, Levenberg–Marquardt, modified Gauss–Newton | [`optim`] |
//! | steering equilibria, stability, bifurcations | [`equilibria`] |
//! | tyre identification from rig data | [`identify`] |
//! | cornering stiffness ↔ handling maps and their inverse | [`study`] |
//! | the sim-to-real gap of measured runs | [`diagnose`] |
//! | reading and validating files | [`io`] |
//! | CSV, JSON and PNG outputs | [`report`] |
//! | the commands of the binary, each one function with a typed report | [`jobs`] |
//! | the library's one error type | [`error`] |
//! | physical constants (standard gravity) | [`constants`] |
//! | numbers as messages print them | [`format`] |
//!
//! # References
//! - Zhang Jiaxu, Li Jing (2017): UniTire parameter identification by a
//!   hybrid of PSO and a modified Gauss–Newton method. J. Jilin Univ.
//!   (Eng. Techn.) 47(1). Used in [`identify`], [`tyre`] (UniTire), [`optim`].
//! - Zhang Lixia, Liu Jiaqi, Pan Fuquan, Zhang Wencai, Zheng Chaoyi (2021):
//!   two-stage identification of PAC89 parameters by an improved PSO. Science
//!   Technology and Engineering 21(16). Used in [`identify`], [`optim`].
//! - Wei Yaobing et al. (2010): MF-Tyre 6.1.1 identification by
//!   Levenberg–Marquardt, with a survey of tyre models.
//! - Li Jie, Jia Changwang, Zhao Qi (Jilin University, undated): nonlinear
//!   steering equilibria of a 2-DOF vehicle by PSO. Used in [`equilibria`].
//! - Wang Guolin, Liang Xinxin (Jiangsu University, undated): tyre cornering
//!   stiffness and handling by inverse dynamics. Used in [`study`],
//!   [`metrics`].

#![warn(missing_docs)]

pub mod constants;
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
pub mod study;
pub mod tyre;
pub mod vehicle;
