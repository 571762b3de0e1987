//! Staged identification of a Magic Formula 6.1 / 6.2 tyre from rig data by
//! Levenberg–Marquardt, after Wei Yaobing, Zhao Xuemei and Jiang Zuxiao
//! (2010): five stages in the paper's order — pure longitudinal force
//! `Fx0(κ, γ, Fz)`, pure lateral force `Fy0(α, γ, Fz)`, pure aligning moment
//! `Mz0(α, γ, Fz)` (with the lateral parameters just fixed), combined-slip
//! longitudinal force (the weighting `Gxα`, with the pure `Fx` parameters
//! fixed) and combined-slip lateral force (`Gyκ` and `SVyκ`, with the pure
//! `Fy` parameters fixed). Each stage minimises `E = Σ(F_model − F_test)²`
//! over its rows.
//!
//! What a stage fits is what its rows can identify: a load-dependent term
//! (`PDX2`, `PKY2`, …) needs two load levels, a load-squared one (`PEX3`,
//! `PKX3`, `QBZ3`, …) three; a camber term linear in γ two camber levels, a
//! second camber term of the same function (`γ²` beside `|γ|` or `γ`) three;
//! pressure terms two (three for the quadratic ones); `PKY4`, the curvature
//! of `Kyα(Fz)`, four loads (with three, `PKY1`, `PKY2`, `PKY4` fit the
//! three stiffnesses exactly and drift together along a near-null
//! direction). The rest are held at
//! the template's values (or their defaults) and reported as held. The
//! paper counts 15 + 20 + 27 + 7 + 14 = 83 parameters; the lists here
//! (`STAGES`) are the TNO 6.1 ones of each function (22 for pure `Fy`,
//! 15 for combined `Fy`) plus the pressure terms `PPX*`, `PPY*`, `PPZ*`.
//! `QBZ9` is held: beside `QBZ10·By·Cy` it is a second constant in the
//! residual torque's slope that rig data barely separate.
//!
//! Rows: a row is *pure longitudinal* when `|α| ≤ 1e-3 rad`, *pure lateral*
//! when `|κ| ≤ 1e-3`, *combined* otherwise. A stage whose columns or rows
//! are missing is skipped and says why; it is not an error.
//!
//! Starts: [`StartScheme::Paper`] is the paper's — every fitted parameter 1,
//! and its Levenberg–Marquardt `(JᵀJ + μI)Δ = −Jᵀe` with μ = 0.1, μ ← μ/β on
//! an accepted step and μ ← β·μ on a rejected one, β = 5, stopping when `E`
//! falls below ε (1 N² here; the paper's 1–10) or stops falling.
//! [`StartScheme::Data`] (default) estimates friction, slip stiffness and
//! trail per load level from the data (peak force over load; slope of the
//! force, or of `Mz` over `Fy`, near zero slip), solves their load laws by
//! least squares, takes textbook shape factors (Pacejka 2012, §4.3) for the
//! rest, and releases the parameters in steps — the terms without
//! load/camber/pressure conditions, then with the load terms, then all —
//! each by a projected Levenberg–Marquardt within physical bounds
//! ([`crate::optim::bounded`]: shape factors `C ≥ 1` for the pure forces,
//! curvatures `E ≤ 1`, positive friction, see `physical_bounds`) that stops
//! on a relative cost decrease below 1e-12 rather than on its iteration
//! cap. (Before, MINPACK's unbounded LM in two steps stopped on its cap on
//! the Hoosier data with `PCY1` ≈ 0.5, `PDY1` ≈ 2.3 and `PEY1·PEY3` trading
//! along a ridge; raw-sample σ 3.89 % against 3.56 % now.)
//!
//! Residual metric: the paper's residual table lost its formula in the
//! surviving text; this module reports `σ = sqrt(Σe²/ΣF_test²)·100 %` per
//! stage, the definition of Zhang & Li (2017) used throughout the crate
//! ([`super::sigma_of`]), which is what a percentage residual of a force
//! channel means there.
//!
//! Standard errors: `cov = s²·(JᵀJ)⁻¹` at the optimum with `s² = Σe²/(m−n)`,
//! computed on the column-scaled Jacobian (SVD, pseudo-inverse); a parameter
//! whose standard error exceeds its magnitude is flagged as not identifiable,
//! and a stage whose scaled Jacobian has a condition number above 1e8 is
//! flagged as near-singular, naming the parameters that dominate its weakest
//! direction.
//!
//! Units: SI and radians in the rows (crate convention, `docs/FORMATS.md`);
//! the coefficients are the `.tir`'s ISO-W ones and are only evaluated
//! through [`MagicFormula`], which maps the signs at its boundary.

use super::data::RigData;
use super::grouping::{group, levels, Grouping, GroupingReport, SlipAxis, Variable};
use crate::error::InputError;
use crate::io::tir::{write_new, TirDocument};
use crate::optim::bounded::BoundedLm;
use crate::optim::local::{jacobian, LocalResult, Residuals};
use crate::tyre::mf::{MagicFormula, MfCoefficients, MfInput, MfOptions, MfVersion, TyreSide};
use rayon::prelude::*;
use serde::Serialize;
use std::path::Path;
use std::time::Instant;

/// Jacobians (iterations) per step of the projected Levenberg–Marquardt at
/// most; a step normally stops earlier, on its tolerance (a relative cost
/// decrease or parameter step below 1e-12). Enough for the synthetic stages
/// and for the Hoosier rig data's pure `Fy` (3,551 rows, 27 parameters:
/// the same σ with 600); the cap keeps a degenerate direction (`RVY1..4`
/// on data without small slip angles) from wandering for seconds.
pub const LM_ITERATIONS: usize = 150;

/// A slip below this is "zero" when rows are sorted into pure and combined.
pub const PURE_TOL: f64 = 1e-3;

/// One rig sample (crate convention, SI, rad); a force or moment that was
/// not measured is NaN.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MfRow {
    /// Vertical load, N.
    pub fz: f64,
    /// Slip ratio.
    pub kappa: f64,
    /// Slip angle, rad.
    pub alpha: f64,
    /// Inclination angle, rad.
    pub camber: f64,
    /// Speed, m/s.
    pub speed: f64,
    /// Inflation pressure, Pa (`None`: the model's own).
    pub pressure: Option<f64>,
    /// Longitudinal force, N.
    pub fx: f64,
    /// Lateral force, N.
    pub fy: f64,
    /// Aligning moment, N·m.
    pub mz: f64,
}

impl MfRow {
    fn input(&self) -> MfInput {
        MfInput {
            fz: self.fz,
            kappa: self.kappa,
            alpha: self.alpha,
            camber: self.camber,
            speed: self.speed,
            pressure: self.pressure,
        }
    }
}

/// How the file's samples became rows.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RowAccount {
    /// Samples in the file.
    pub samples: usize,
    /// Rows handed to the stages.
    pub rows: usize,
    /// The grouping and thinning of a lateral-only file (every sample
    /// accounted for: used, between levels, or not selected); `None` when the
    /// samples are used one row each.
    pub thinning: Option<GroupingReport>,
}

/// Rows ready for [`identify`].
#[derive(Debug, Clone, PartialEq)]
pub struct Prepared {
    /// The rows.
    pub rows: Vec<MfRow>,
    /// Where the samples went.
    pub account: RowAccount,
}

/// Turns rig data into rows. A file with slip ratio (`kappa`, `fx`) keeps
/// every sample as a row, so pure and combined sweeps stay intact. A
/// lateral-only file (the usual cornering rig test, tens of thousands of
/// samples) is grouped into load / camber / pressure conditions and thinned
/// by averaging within `alpha_bin` slip-angle bins
/// ([`super::grouping::group`]; 0: no thinning), the account reported.
/// Speed defaults to `default_speed` where the file has none.
pub fn prepare(
    path: &Path,
    d: &RigData,
    alpha_bin: f64,
    default_speed: f64,
) -> Result<Prepared, InputError> {
    let speed = |i: usize| d.speed.as_ref().map_or(default_speed, |s| s[i]);
    if let Some((kappa, fx)) = &d.longitudinal {
        let rows = (0..d.len())
            .map(|i| MfRow {
                fz: d.fz[i],
                kappa: kappa[i],
                alpha: d.alpha[i],
                camber: d.camber[i],
                speed: speed(i),
                pressure: d.pressure.as_ref().map(|p| p[i]),
                fx: fx[i],
                fy: d.fy[i],
                mz: d.mz.as_ref().map_or(f64::NAN, |m| m[i]),
            })
            .collect::<Vec<_>>();
        return Ok(Prepared {
            account: RowAccount {
                samples: d.len(),
                rows: rows.len(),
                thinning: None,
            },
            rows,
        });
    }
    let g = group(
        path,
        d,
        &Grouping {
            alpha_bin,
            default_speed,
            ..Grouping::default()
        },
        SlipAxis::Angle,
    )?;
    let rows: Vec<MfRow> = g
        .conditions
        .iter()
        .flat_map(|c| {
            c.points.iter().map(move |q| MfRow {
                fz: q[1],
                kappa: 0.0,
                alpha: q[0],
                camber: q[2],
                speed: q[3],
                pressure: c.pressure,
                fx: f64::NAN,
                fy: q[4],
                mz: q[5],
            })
        })
        .collect();
    Ok(Prepared {
        account: RowAccount {
            samples: d.len(),
            rows: rows.len(),
            thinning: Some(g.report),
        },
        rows,
    })
}

/// The five cases of Wei et al. (2010), in their order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Stage {
    /// Pure longitudinal force.
    PureFx,
    /// Pure lateral force.
    PureFy,
    /// Pure aligning moment.
    PureMz,
    /// Combined-slip longitudinal force.
    CombinedFx,
    /// Combined-slip lateral force.
    CombinedFy,
}

impl Stage {
    /// All stages in order.
    pub const ALL: [Stage; 5] = [
        Stage::PureFx,
        Stage::PureFy,
        Stage::PureMz,
        Stage::CombinedFx,
        Stage::CombinedFy,
    ];

    /// The residual Wei et al. (2010) report for this case, %.
    pub fn paper_sigma_percent(self) -> f64 {
        match self {
            Stage::PureFx => 1.03,
            Stage::PureFy => 1.20,
            Stage::PureMz => 4.82,
            Stage::CombinedFx => 1.96,
            Stage::CombinedFy => 3.01,
        }
    }

    /// A name people read.
    pub fn label(self) -> &'static str {
        match self {
            Stage::PureFx => "pure Fx",
            Stage::PureFy => "pure Fy",
            Stage::PureMz => "pure Mz",
            Stage::CombinedFx => "combined Fx",
            Stage::CombinedFy => "combined Fy",
        }
    }

    fn measured(self, r: &MfRow) -> f64 {
        match self {
            Stage::PureFx | Stage::CombinedFx => r.fx,
            Stage::PureFy | Stage::CombinedFy => r.fy,
            Stage::PureMz => r.mz,
        }
    }

    fn model(self, t: &MagicFormula, r: &MfRow) -> f64 {
        let o = t.evaluate(&r.input());
        match self {
            Stage::PureFx | Stage::CombinedFx => o.fx,
            Stage::PureFy | Stage::CombinedFy => o.fy,
            Stage::PureMz => o.mz,
        }
    }

    /// Whether a row belongs to this stage (its channel measured).
    fn takes(self, r: &MfRow) -> bool {
        let pure_a = r.alpha.abs() <= PURE_TOL;
        let pure_k = r.kappa.abs() <= PURE_TOL;
        self.measured(r).is_finite()
            && match self {
                Stage::PureFx => pure_a,
                Stage::PureFy | Stage::PureMz => pure_k,
                Stage::CombinedFx | Stage::CombinedFy => !pure_a && !pure_k,
            }
    }

    /// The stage whose parameters this one builds on.
    fn needs(self) -> Option<Stage> {
        match self {
            Stage::PureFx | Stage::PureFy => None,
            Stage::PureMz | Stage::CombinedFy => Some(Stage::PureFy),
            Stage::CombinedFx => Some(Stage::PureFx),
        }
    }

    fn parameters(self) -> &'static [(&'static str, Need)] {
        match self {
            Stage::PureFx => PURE_FX,
            Stage::PureFy => PURE_FY,
            Stage::PureMz => PURE_MZ,
            Stage::CombinedFx => COMBINED_FX,
            Stage::CombinedFy => COMBINED_FY,
        }
    }
}

/// The levels of load, camber and pressure a parameter needs to be
/// identifiable.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Need {
    loads: u8,
    cambers: u8,
    pressures: u8,
}

const fn n(loads: u8, cambers: u8, pressures: u8) -> Need {
    Need {
        loads,
        cambers,
        pressures,
    }
}
const ANY: Need = n(1, 1, 1);
const L2: Need = n(2, 1, 1);
const L3: Need = n(3, 1, 1);
const L4: Need = n(4, 1, 1);
const C2: Need = n(1, 2, 1);
const C3: Need = n(1, 3, 1);
const C2L2: Need = n(2, 2, 1);
const C3L2: Need = n(2, 3, 1);
const P2: Need = n(1, 1, 2);
const P3: Need = n(1, 1, 3);
const P2C2: Need = n(1, 2, 2);
/// Never fitted (see the module notes on `QBZ9`).
const HELD: Need = n(u8::MAX, u8::MAX, u8::MAX);

const PURE_FX: &[(&str, Need)] = &[
    ("PCX1", ANY),
    ("PDX1", ANY),
    ("PDX2", L2),
    ("PDX3", C2),
    ("PEX1", ANY),
    ("PEX2", L2),
    ("PEX3", L3),
    ("PEX4", ANY),
    ("PKX1", ANY),
    ("PKX2", L2),
    ("PKX3", L3),
    ("PHX1", ANY),
    ("PHX2", L2),
    ("PVX1", ANY),
    ("PVX2", L2),
    ("PPX1", P2),
    ("PPX2", P3),
    ("PPX3", P2),
    ("PPX4", P3),
];

const PURE_FY: &[(&str, Need)] = &[
    ("PCY1", ANY),
    ("PDY1", ANY),
    ("PDY2", L2),
    ("PDY3", C2),
    ("PEY1", ANY),
    ("PEY2", L2),
    ("PEY3", ANY),
    ("PEY4", C2),
    ("PEY5", C3),
    ("PKY1", ANY),
    ("PKY2", L2),
    ("PKY3", C2),
    ("PKY4", L4),
    ("PKY5", C3),
    ("PKY6", C2),
    ("PKY7", C2L2),
    ("PHY1", ANY),
    ("PHY2", L2),
    ("PVY1", ANY),
    ("PVY2", L2),
    ("PVY3", C2),
    ("PVY4", C2L2),
    ("PPY1", P2),
    ("PPY2", P2),
    ("PPY3", P2),
    ("PPY4", P3),
    ("PPY5", P2C2),
];

const PURE_MZ: &[(&str, Need)] = &[
    ("QBZ1", ANY),
    ("QBZ2", L2),
    ("QBZ3", L3),
    ("QBZ4", C2),
    ("QBZ5", C3),
    ("QBZ9", HELD),
    ("QBZ10", ANY),
    ("QCZ1", ANY),
    ("QDZ1", ANY),
    ("QDZ2", L2),
    ("QDZ3", C2),
    ("QDZ4", C3),
    ("QDZ6", ANY),
    ("QDZ7", L2),
    ("QDZ8", C2),
    ("QDZ9", C2L2),
    ("QDZ10", C3),
    ("QDZ11", C3L2),
    ("QEZ1", ANY),
    ("QEZ2", L2),
    ("QEZ3", L3),
    ("QEZ4", ANY),
    ("QEZ5", C2),
    ("QHZ1", ANY),
    ("QHZ2", L2),
    ("QHZ3", C2),
    ("QHZ4", C2L2),
    ("PPZ1", P2),
    ("PPZ2", P2C2),
];

const COMBINED_FX: &[(&str, Need)] = &[
    ("RBX1", ANY),
    ("RBX2", ANY),
    ("RBX3", C2),
    ("RCX1", ANY),
    ("REX1", ANY),
    ("REX2", L2),
    ("RHX1", ANY),
];

const COMBINED_FY: &[(&str, Need)] = &[
    ("RBY1", ANY),
    ("RBY2", ANY),
    ("RBY3", ANY),
    ("RBY4", C2),
    ("RCY1", ANY),
    ("REY1", ANY),
    ("REY2", L2),
    ("RHY1", ANY),
    ("RHY2", L2),
    ("RVY1", ANY),
    ("RVY2", L2),
    ("RVY3", C2),
    ("RVY4", ANY),
    ("RVY5", ANY),
    ("RVY6", ANY),
];

/// Coefficients whose sign the model cannot see (they enter through
/// `cos(atan(·))` or a `sin(C·atan(B·x))` whose `B` flips with `C`); they are
/// reported positive (and `RVY5`, `RVY6`, which flip together, with `RVY5`
/// positive).
const EVEN: [&str; 7] = ["PCX1", "PCY1", "RCX1", "RCY1", "RBX2", "RBY2", "RVY4"];

/// Where the fitted parameters start.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum StartScheme {
    /// Wei et al. (2010): every fitted parameter 1, their LM (μ = 0.1, β = 5).
    Paper,
    /// Estimates from the data, then the bounded, staged LM (default).
    #[default]
    Data,
    /// The template's values, then the bounded, staged LM.
    Template,
}

/// Settings of a staged identification.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    /// The version written (6.1 or 6.2: the same steady-state equations).
    pub version: MfVersion,
    /// The start scheme.
    pub start: StartScheme,
    /// A tyre whose constants (`FNOMIN`, `UNLOADED_RADIUS`, `NOMPRES`,
    /// `LONGVL`, side) and non-fitted coefficients are kept; without one,
    /// `FNOMIN` is the median load, `NOMPRES` the median pressure,
    /// `UNLOADED_RADIUS` 0.3 m and every other coefficient its default.
    pub template: Option<MagicFormula>,
    /// Levenberg–Marquardt iterations (Jacobians) per step at most
    /// ([`LM_ITERATIONS`] by default; the paper's scheme runs at least 500).
    pub max_iterations: usize,
}

/// A fitted or held parameter of a stage.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StageParameter {
    /// `.tir` name.
    pub name: &'static str,
    /// Value (ISO-W, as in the file).
    pub value: f64,
    /// Its start value.
    pub start: f64,
    /// Fitted (false: held, see `held_because`).
    pub free: bool,
    /// Approximate standard error (free parameters).
    pub std_error: Option<f64>,
    /// Why a parameter was held.
    pub held_because: Option<String>,
    /// An identifiability warning.
    pub warning: Option<String>,
}

/// The outcome of one stage.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StageReport {
    /// Which stage.
    pub stage: Stage,
    /// Skipped, and why (`None`: fitted).
    pub skipped: Option<String>,
    /// Rows fitted.
    pub points: usize,
    /// Load, camber and pressure levels in them.
    pub levels: [usize; 3],
    /// σ = sqrt(Σe²/ΣF²)·100 % at the start.
    pub sigma_start_percent: f64,
    /// σ at the end, %.
    pub sigma_percent: f64,
    /// Wei et al. (2010)'s residual for this case, %.
    pub paper_sigma_percent: f64,
    /// RMS error (N or N·m).
    pub rms: f64,
    /// Condition number of the column-scaled Jacobian at the optimum.
    pub condition_number: f64,
    /// Whether LM stopped on its own test.
    pub converged: bool,
    /// Residual evaluations of the stage's rows.
    pub evaluations: usize,
    /// Wall time, s.
    pub seconds: f64,
    /// The stage's parameters.
    pub parameters: Vec<StageParameter>,
    /// Stage-level warnings (near-singular Jacobian).
    pub warnings: Vec<String>,
}

impl StageReport {
    fn skipped(stage: Stage, why: String) -> Self {
        Self {
            stage,
            skipped: Some(why),
            points: 0,
            levels: [0; 3],
            sigma_start_percent: f64::NAN,
            sigma_percent: f64::NAN,
            paper_sigma_percent: stage.paper_sigma_percent(),
            rms: f64::NAN,
            condition_number: f64::NAN,
            converged: false,
            evaluations: 0,
            seconds: 0.0,
            parameters: Vec::new(),
            warnings: Vec::new(),
        }
    }
}

/// The whole identification.
#[derive(Debug, Clone, Serialize)]
pub struct StagedReport {
    /// Version written.
    pub version: MfVersion,
    /// Start scheme.
    pub start: StartScheme,
    /// Whether a template gave the constants.
    pub template: bool,
    /// `FNOMIN`, N.
    pub fnomin: f64,
    /// `NOMPRES`, Pa.
    pub nompres: f64,
    /// The stages in order.
    pub stages: Vec<StageReport>,
    /// σ over the fitted lateral force and aligning moment rows together,
    /// each channel's squared errors relative to its own ΣF² —
    /// `sqrt((Σe²_Fy/ΣFy² + Σe²_Mz/ΣMz²)/2)·100 %` — so the moment counts as
    /// much as the force (`None` unless both were fitted).
    pub sigma_fy_mz_percent: Option<f64>,
    /// Wall time, s.
    pub seconds: f64,
}

/// The least-squares problem of one stage.
struct StageProblem<'a> {
    base: MagicFormula,
    stage: Stage,
    names: Vec<&'static str>,
    rows: Vec<&'a MfRow>,
}

impl StageProblem<'_> {
    fn tyre(&self, p: &[f64]) -> MagicFormula {
        let mut t = self.base.clone();
        for (k, v) in self.names.iter().zip(p) {
            t.coefficients.set(k, *v);
        }
        t
    }
}

impl Residuals for StageProblem<'_> {
    fn count(&self) -> usize {
        self.rows.len()
    }
    fn residuals(&self, p: &[f64], out: &mut [f64]) {
        let t = self.tyre(p);
        let f = |(o, r): (&mut f64, &&MfRow)| {
            *o = self.stage.model(&t, r) - self.stage.measured(r);
        };
        // Parallel only where the rows are many enough to pay for it.
        if self.rows.len() >= 2048 {
            out.par_iter_mut().zip(self.rows.par_iter()).for_each(f);
        } else {
            out.iter_mut().zip(self.rows.iter()).for_each(f);
        }
    }
}

/// σ (%) and RMS of a stage's channel over rows.
fn sigma(stage: Stage, t: &MagicFormula, rows: &[&MfRow]) -> (f64, f64, f64, f64) {
    let (mut e2, mut y2) = (0.0, 0.0);
    for r in rows {
        let e = stage.model(t, r) - stage.measured(r);
        e2 += e * e;
        y2 += stage.measured(r).powi(2);
    }
    (
        100.0 * (e2 / y2).sqrt(),
        (e2 / rows.len().max(1) as f64).sqrt(),
        e2,
        y2,
    )
}

fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The template, or a bare tyre sized from the rows.
fn base_tyre(rows: &[MfRow], s: &Settings) -> MagicFormula {
    let mut t = s.template.clone().unwrap_or_else(|| {
        let mut c = MfCoefficients {
            FNOMIN: (median(rows.iter().map(|r| r.fz).collect()) / 10.0).round() * 10.0,
            ..MfCoefficients::default()
        };
        let p = median(rows.iter().filter_map(|r| r.pressure).collect());
        if p.is_finite() {
            c.NOMPRES = (p / 100.0).round() * 100.0;
        }
        let v = median(rows.iter().map(|r| r.speed).collect());
        if v.is_finite() && v > 0.0 {
            c.LONGVL = v;
        }
        MagicFormula {
            version: s.version,
            side: TyreSide::Left,
            options: MfOptions::default(),
            coefficients: c,
        }
    });
    t.version = s.version;
    t
}

/// Counts of load, camber and pressure levels in rows.
fn level_counts(rows: &[&MfRow]) -> [usize; 3] {
    let fz: Vec<f64> = rows.iter().map(|r| r.fz).collect();
    let ga: Vec<f64> = rows.iter().map(|r| r.camber).collect();
    let p: Vec<f64> = rows.iter().filter_map(|r| r.pressure).collect();
    [
        levels(Variable::Load, &fz, 10.0).levels.len().max(1),
        levels(Variable::Camber, &ga, 0.1f64.to_radians())
            .levels
            .len()
            .max(1),
        if p.len() == rows.len() && !p.is_empty() {
            levels(Variable::Pressure, &p, 1000.0).levels.len().max(1)
        } else {
            1
        },
    ]
}

/// Rows grouped by load level (nominal loads ascending), at the camber
/// closest to zero and the pressure closest to nominal.
fn by_load<'a>(rows: &[&'a MfRow], nompres: f64) -> Vec<(f64, Vec<&'a MfRow>)> {
    let gmin = rows
        .iter()
        .map(|r| r.camber.abs())
        .fold(f64::INFINITY, f64::min);
    let pbest = rows
        .iter()
        .filter_map(|r| r.pressure)
        .min_by(|a, b| (a - nompres).abs().total_cmp(&(b - nompres).abs()));
    let sel: Vec<&MfRow> = rows
        .iter()
        .copied()
        .filter(|r| (r.camber.abs() - gmin).abs() < 0.05f64.to_radians())
        .filter(|r| match (pbest, r.pressure) {
            (Some(pb), Some(p)) => (p - pb).abs() < 3000.0,
            _ => true,
        })
        .collect();
    let fz: Vec<f64> = sel.iter().map(|r| r.fz).collect();
    let lv = levels(Variable::Load, &fz, 10.0);
    let mut out: Vec<(f64, Vec<&MfRow>)> =
        lv.levels.iter().map(|l| (l.nominal, Vec::new())).collect();
    for r in sel {
        if let Some(k) = (0..out.len()).min_by(|a, b| {
            (out[*a].0 - r.fz)
                .abs()
                .total_cmp(&(out[*b].0 - r.fz).abs())
        }) {
            out[k].1.push(r);
        }
    }
    out.retain(|(_, v)| v.len() >= 3);
    out
}

/// Least-squares slope of `y` on `x` (with intercept) over the points whose
/// `|x|` is within `range`, or the four smallest `|x|` if fewer than three.
fn slope(pts: &[(f64, f64)], range: f64) -> Option<f64> {
    let mut p: Vec<(f64, f64)> = pts.iter().copied().filter(|q| q.0.abs() <= range).collect();
    if p.len() < 3 {
        let mut all = pts.to_vec();
        all.sort_by(|a, b| a.0.abs().total_cmp(&b.0.abs()));
        p = all.into_iter().take(4).collect();
    }
    let n = p.len() as f64;
    let (mx, my) = (
        p.iter().map(|q| q.0).sum::<f64>() / n,
        p.iter().map(|q| q.1).sum::<f64>() / n,
    );
    let sxx: f64 = p.iter().map(|q| (q.0 - mx).powi(2)).sum();
    let sxy: f64 = p.iter().map(|q| (q.0 - mx) * (q.1 - my)).sum();
    (sxx > 0.0).then(|| sxy / sxx).filter(|s| s.is_finite())
}

/// `y ≈ a + b·x` by least squares (`b = 0` from one point).
fn line(pts: &[(f64, f64)]) -> (f64, f64) {
    let n = pts.len() as f64;
    let (mx, my) = (
        pts.iter().map(|q| q.0).sum::<f64>() / n,
        pts.iter().map(|q| q.1).sum::<f64>() / n,
    );
    let sxx: f64 = pts.iter().map(|q| (q.0 - mx).powi(2)).sum();
    let sxy: f64 = pts.iter().map(|q| (q.0 - mx) * (q.1 - my)).sum();
    if pts.len() < 2 || sxx <= 0.0 {
        (my, 0.0)
    } else {
        let b = sxy / sxx;
        (my - b * mx, b)
    }
}

/// Start values estimated from a stage's rows (only names it sets).
fn data_start(stage: Stage, base: &MagicFormula, rows: &[&MfRow]) -> Vec<(&'static str, f64)> {
    let c = &base.coefficients;
    let fz0 = c.FNOMIN * c.LFZO;
    let dfz = |fz: f64| (fz - fz0) / fz0;
    let groups = by_load(rows, c.NOMPRES);
    let mut out: Vec<(&'static str, f64)> = Vec::new();
    match stage {
        Stage::PureFx | Stage::PureFy => {
            let lat = stage == Stage::PureFy;
            let slip = |r: &MfRow| if lat { r.alpha } else { r.kappa };
            let force = |r: &MfRow| if lat { r.fy } else { r.fx };
            let mut mu = Vec::new();
            let mut stiff = Vec::new();
            for (fz, g) in &groups {
                let peak = g.iter().map(|r| force(r).abs()).fold(0.0, f64::max);
                mu.push((dfz(*fz), peak / fz));
                let pts: Vec<(f64, f64)> = g.iter().map(|r| (slip(r), force(r))).collect();
                let range = if lat { 1.5f64.to_radians() } else { 0.02 };
                if let Some(k) = slope(&pts, range).filter(|k| *k > 0.0) {
                    stiff.push((*fz, k));
                }
            }
            let (d1, d2) = if mu.is_empty() { (1.0, 0.0) } else { line(&mu) };
            if lat {
                out.extend([("PCY1", 1.3), ("PDY1", d1), ("PDY2", d2), ("PEY1", 0.0)]);
                // Kyα(Fz) = PKY1·Fz0·sin(PKY4·atan(Fz/(PKY2·Fz0))) (ISO-W:
                // negative for a positive crate slope): PKY2 on a grid, PKY1
                // by least squares for each.
                let pky4 = c.PKY4;
                let mut best = (f64::INFINITY, -20.0, 2.0);
                if !stiff.is_empty() {
                    for i in 0..=150 {
                        let pky2 = 0.5 + 0.05 * i as f64;
                        let shape: Vec<f64> = stiff
                            .iter()
                            .map(|(fz, _)| fz0 * (pky4 * (fz / (pky2 * fz0)).atan()).sin())
                            .collect();
                        let num: f64 = stiff.iter().zip(&shape).map(|(s, h)| -s.1 * h).sum();
                        let den: f64 = shape.iter().map(|h| h * h).sum();
                        let pky1 = num / den;
                        let err: f64 = stiff
                            .iter()
                            .zip(&shape)
                            .map(|(s, h)| ((pky1 * h + s.1) / s.1).powi(2))
                            .sum();
                        if err < best.0 {
                            best = (err, pky1, pky2);
                        }
                    }
                }
                out.extend([("PKY1", best.1), ("PKY2", best.2)]);
            } else {
                let kx: Vec<(f64, f64)> = stiff.iter().map(|(fz, k)| (dfz(*fz), k / fz)).collect();
                let (k1, k2) = if kx.is_empty() {
                    (20.0, 0.0)
                } else {
                    line(&kx)
                };
                out.extend([
                    ("PCX1", 1.65),
                    ("PDX1", d1),
                    ("PDX2", d2),
                    ("PEX1", 0.0),
                    ("PKX1", k1),
                    ("PKX2", k2),
                ]);
            }
        }
        Stage::PureMz => {
            // Pneumatic trail near zero slip: the slope of mz over fy; with
            // Dt = Fz·(R0/Fz0)·(QDZ1 + QDZ2·dfz) (the trail at α = 0).
            let r0 = c.UNLOADED_RADIUS;
            let trail: Vec<(f64, f64)> = groups
                .iter()
                .filter_map(|(fz, g)| {
                    let pts: Vec<(f64, f64)> = g
                        .iter()
                        .filter(|r| r.alpha.abs() <= 2f64.to_radians())
                        .map(|r| (r.fy, r.mz))
                        .collect();
                    let t = slope(&pts, f64::INFINITY)?;
                    Some((dfz(*fz), t * fz0 / (r0 * fz)))
                })
                .collect();
            let (q1, q2) = if trail.is_empty() {
                (0.1, 0.0)
            } else {
                line(&trail)
            };
            // QBZ10 must start off zero: at Br = 0 the residual torque's
            // cos(atan(Br·αr)) has no slope in Br.
            out.extend([
                ("QBZ1", 10.0),
                ("QBZ10", 1.0),
                ("QCZ1", 1.2),
                ("QDZ1", q1),
                ("QDZ2", q2),
                ("QEZ1", 0.0),
            ]);
        }
        Stage::CombinedFx => {
            out.extend([("RBX1", 10.0), ("RBX2", 8.0), ("RCX1", 1.0), ("REX1", 0.0)]);
        }
        Stage::CombinedFy => {
            out.extend([
                ("RBY1", 10.0),
                ("RBY2", 8.0),
                ("RCY1", 1.0),
                ("REY1", 0.0),
                ("RVY4", 50.0),
                ("RVY5", 2.0),
                ("RVY6", 10.0),
            ]);
        }
    }
    out
}

/// Wei et al. (2010)'s Levenberg–Marquardt: `(JᵀJ + μI)Δ = −Jᵀe`, μ0 = 0.1,
/// μ ← μ/β after an accepted step, μ ← β·μ after a rejected one (β = 5);
/// stops when `E = Σe²` falls below `eps`, stops falling (relative change
/// below 1e-12 over an accepted step), μ exceeds 1e16, or after `max_iter`
/// Jacobians.
pub fn paper_lm(problem: &dyn Residuals, p0: &[f64], eps: f64, max_iter: usize) -> LocalResult {
    let (m, n) = (problem.count(), p0.len());
    let mut x = p0.to_vec();
    let mut r = vec![0.0; m];
    problem.residuals(&x, &mut r);
    let e_of = |r: &[f64]| r.iter().map(|e| e * e).sum::<f64>();
    let mut e = e_of(&r);
    let (mut mu, beta) = (0.1, 5.0);
    let mut evaluations = 1;
    let mut converged = false;
    let mut trial = vec![0.0; m];
    'outer: for _ in 0..max_iter {
        if e < eps {
            converged = true;
            break;
        }
        let j = jacobian(problem, &x, &r);
        evaluations += n;
        let jtj = j.transpose() * &j;
        let g = j.transpose() * nalgebra::DVector::from_column_slice(&r);
        loop {
            let a = &jtj + nalgebra::DMatrix::identity(n, n) * mu;
            let step = a.cholesky().map(|ch| ch.solve(&(-&g)));
            let Some(dx) = step else {
                mu *= beta;
                if mu > 1e16 {
                    break 'outer;
                }
                continue;
            };
            let xt: Vec<f64> = x.iter().zip(dx.iter()).map(|(a, b)| a + b).collect();
            problem.residuals(&xt, &mut trial);
            evaluations += 1;
            let et = e_of(&trial);
            if et.is_finite() && et < e {
                let small = (e - et) <= 1e-12 * e;
                x = xt;
                std::mem::swap(&mut r, &mut trial);
                e = et;
                mu /= beta;
                if small {
                    converged = true;
                    break 'outer;
                }
                break;
            }
            mu *= beta;
            if mu > 1e16 {
                converged = true;
                break 'outer;
            }
        }
    }
    LocalResult {
        cost: 0.5 * e,
        params: x,
        evaluations,
        converged,
    }
}

/// The identified tyre and the report.
#[derive(Debug, Clone)]
pub struct Identified {
    /// The tyre (version as requested; side and constants from the template).
    pub tyre: MagicFormula,
    /// The report.
    pub report: StagedReport,
}

/// Runs the stages on `rows`. Fails only when no stage could run.
pub fn identify(rows: &[MfRow], settings: &Settings) -> Result<Identified, String> {
    let t0 = Instant::now();
    let mut tyre = base_tyre(rows, settings);
    let mut reports: Vec<StageReport> = Vec::new();
    let mut fy_mz: [Option<(f64, f64)>; 2] = [None, None];
    for stage in Stage::ALL {
        if let Some(need) = stage.needs() {
            if reports
                .iter()
                .any(|r| r.stage == need && r.skipped.is_some())
            {
                reports.push(StageReport::skipped(
                    stage,
                    format!("it builds on the {} stage, which was skipped", need.label()),
                ));
                continue;
            }
        }
        let sel: Vec<&MfRow> = rows.iter().filter(|r| stage.takes(r)).collect();
        let rep = run_stage(
            stage,
            &mut tyre,
            &sel,
            settings.start,
            settings.max_iterations,
        );
        if rep.skipped.is_none() {
            let (_, _, e2, y2) = sigma(stage, &tyre, &sel);
            match stage {
                Stage::PureFy => fy_mz[0] = Some((e2, y2)),
                Stage::PureMz => fy_mz[1] = Some((e2, y2)),
                _ => {}
            }
        }
        reports.push(rep);
    }
    if reports.iter().all(|r| r.skipped.is_some()) {
        let why: Vec<String> = reports
            .iter()
            .map(|r| {
                format!(
                    "{}: {}",
                    r.stage.label(),
                    r.skipped.as_deref().unwrap_or("")
                )
            })
            .collect();
        return Err(format!("no stage could be fitted ({})", why.join("; ")));
    }
    // Report the sign-blind coefficients in one conventional sign.
    let c = &mut tyre.coefficients;
    for name in EVEN {
        c.set(name, c.get(name).unwrap_or(0.0).abs());
    }
    // sin(RVY5·atan(RVY6·κ)) is unchanged when both flip.
    let flip_rvy = c.RVY5 < 0.0;
    if flip_rvy {
        c.RVY5 = -c.RVY5;
        c.RVY6 = -c.RVY6;
    }
    for r in &mut reports {
        for p in &mut r.parameters {
            if EVEN.contains(&p.name) || (flip_rvy && (p.name == "RVY5" || p.name == "RVY6")) {
                p.value = tyre.coefficients.get(p.name).unwrap_or(p.value);
            }
        }
    }
    let sigma_fy_mz_percent = match fy_mz {
        [Some((e1, y1)), Some((e2, y2))] => Some(100.0 * ((e1 / y1 + e2 / y2) / 2.0).sqrt()),
        _ => None,
    };
    Ok(Identified {
        report: StagedReport {
            version: tyre.version,
            start: settings.start,
            template: settings.template.is_some(),
            fnomin: tyre.coefficients.FNOMIN,
            nompres: tyre.coefficients.NOMPRES,
            stages: reports,
            sigma_fy_mz_percent,
            seconds: t0.elapsed().as_secs_f64(),
        },
        tyre,
    })
}

/// Why parameter `need` cannot be fitted with `have` levels.
fn held_reason(need: Need, have: [usize; 3]) -> Option<String> {
    if need == HELD {
        return Some("held by design (see the module notes)".into());
    }
    let mut why = Vec::new();
    for (k, (want, what)) in [
        (need.loads, "load"),
        (need.cambers, "camber"),
        (need.pressures, "pressure"),
    ]
    .into_iter()
    .enumerate()
    {
        if (want as usize) > have[k] {
            why.push(format!(
                "needs {want} {what} levels, the data have {}",
                have[k]
            ));
        }
    }
    (!why.is_empty()).then(|| why.join(", "))
}

fn names_of(free: &[(&'static str, Need)]) -> Vec<&'static str> {
    free.iter().map(|(k, _)| *k).collect()
}

/// Bounds that keep a fitted coefficient physical (ISO-W signs): shape
/// factors `C ≥ 1` for the pure forces (below 1 the sine never reaches its
/// peak, `D` stops being the peak force and `B`, `C`, `D` trade along a
/// ridge — the drift seen on the Hoosier data, `PCY1` → 0.5 with `PDY1` →
/// 2.3), positive friction, curvatures `E ≤ 1` (the formula clips above),
/// a sign factor `(1 ∓ PEY3)` or `(1 − PEX4·sgn κ)` that keeps its sign,
/// positive `PKY2`, `PKY4` and positive stiffness factors `QBZ1`, `RBX1`,
/// `RBY1`. Every other coefficient may move 10⁴ times its
/// start's magnitude (at least ±10⁴) either way: finite, so the projected
/// LM's step test has a scale, and wide enough not to bind on camber terms
/// that are large by nature (MFeval's `RBY4` is 1,747).
fn physical_bounds(name: &str, start: f64) -> (f64, f64) {
    match name {
        "PCX1" | "PCY1" => (1.0, 3.0),
        "RCX1" | "RCY1" | "QCZ1" => (0.1, 5.0),
        "PDX1" | "PDY1" => (0.05, 6.0),
        "PKY2" => (0.05, 20.0),
        "PKY4" => (0.1, 5.0),
        // Stiffness factors of the trail and the combined-slip weights are
        // positive (their cosines are nearly even in them, so without a
        // bound the sign is a coin toss).
        "QBZ1" | "RBX1" | "RBY1" => (0.0, 1e4 * start.abs().max(1.0)),
        "PEX1" | "PEY1" | "QEZ1" | "REX1" | "REY1" => (-50.0, 1.0),
        "PEY3" | "PEX4" => (-1.0, 1.0),
        _ => {
            let w = 1e4 * start.abs().max(1.0);
            (start - w, start + w)
        }
    }
}

/// Projected Levenberg–Marquardt within `bounds`, converged on a relative
/// cost decrease (or a step relative to the bounds' width) below 1e-12, or
/// when no damped step lowers the cost; at most `iterations` Jacobians.
fn bounded(
    problem: &StageProblem,
    p0: &[f64],
    bounds: &[(f64, f64)],
    iterations: usize,
) -> LocalResult {
    BoundedLm {
        iterations,
        tolerance: 1e-12,
    }
    .minimize(problem, p0, bounds)
}

/// The staged release of a stage's parameters, each step within the
/// physical bounds and stopped by tolerance: the terms without conditions
/// (from three curvature starts, E = 0, −1, 0.5: a curvature started on
/// the wrong side of a kink — E is clipped at 1 — or of a flat trail curve
/// can stall LM in a local minimum), then with the load terms, then all
/// (camber and pressure terms too). Returns the result and the residual
/// evaluations spent.
fn released_fit(
    problem: &StageProblem,
    free: &[(&'static str, Need)],
    starts: &[f64],
    bounds: &[(f64, f64)],
    iterations: usize,
) -> (LocalResult, usize) {
    let mut evaluations = 0;
    let mut converged = true;
    let mut p: Vec<f64> = starts
        .iter()
        .zip(bounds)
        .map(|(v, (lo, hi))| v.clamp(*lo, *hi))
        .collect();
    let steps: [&dyn Fn(Need) -> bool; 3] = [
        &|n: Need| n == ANY,
        &|n: Need| n.cambers == 1 && n.pressures == 1,
        &|_| true,
    ];
    let mut last = None;
    for (s, takes) in steps.iter().enumerate() {
        let idx: Vec<usize> = (0..free.len()).filter(|&i| takes(free[i].1)).collect();
        if idx.is_empty() || (s > 0 && last == Some(idx.len())) {
            continue;
        }
        last = Some(idx.len());
        let sub = StageProblem {
            base: problem.tyre(&p),
            stage: problem.stage,
            names: idx.iter().map(|&i| problem.names[i]).collect(),
            rows: problem.rows.clone(),
        };
        let b: Vec<(f64, f64)> = idx.iter().map(|&i| bounds[i]).collect();
        let q0: Vec<f64> = idx.iter().map(|&i| p[i]).collect();
        let curvature = sub
            .names
            .iter()
            .position(|k| matches!(*k, "PEX1" | "PEY1" | "QEZ1" | "REX1" | "REY1"));
        let e0s: &[f64] = match (s, curvature) {
            (0, Some(_)) => &[0.0, -1.0, 0.5],
            _ => &[f64::NAN],
        };
        let mut best = (sub.cost(&q0), q0.clone(), true);
        for &e0 in e0s {
            let mut q = q0.clone();
            if let (Some(k), false) = (curvature, e0.is_nan()) {
                q[k] = e0;
            }
            let r = bounded(&sub, &q, &b, iterations);
            evaluations += r.evaluations;
            if r.cost.is_finite() && r.cost < best.0 {
                best = (r.cost, r.params, r.converged);
            }
        }
        converged &= best.2;
        for (k, &i) in idx.iter().enumerate() {
            p[i] = best.1[k];
        }
    }
    let cost = problem.cost(&p);
    (
        LocalResult {
            cost,
            params: p,
            evaluations,
            converged,
        },
        evaluations,
    )
}

fn run_stage(
    stage: Stage,
    tyre: &mut MagicFormula,
    rows: &[&MfRow],
    start: StartScheme,
    max_iterations: usize,
) -> StageReport {
    let t0 = Instant::now();
    let table = stage.parameters();
    let have = level_counts(rows);
    let free: Vec<(&'static str, Need)> = table
        .iter()
        .copied()
        .filter(|(_, need)| held_reason(*need, have).is_none())
        .collect();
    if rows.len() <= free.len() + 5 {
        return StageReport::skipped(
            stage,
            if rows.is_empty() {
                match stage {
                    Stage::PureFx => {
                        "no pure longitudinal rows (columns `kappa` and `fx`, |α| ≤ 1e-3 rad)"
                            .into()
                    }
                    Stage::PureFy => {
                        "no pure lateral rows (columns `alpha` and `fy`, |κ| ≤ 1e-3)".into()
                    }
                    Stage::PureMz => "no pure lateral rows with a measured `mz`".into(),
                    Stage::CombinedFx => {
                        "no combined-slip rows with a measured `fx` (both |κ| and |α| above 1e-3)"
                            .into()
                    }
                    Stage::CombinedFy => {
                        "no combined-slip rows with a measured `fy` (both |κ| and |α| above 1e-3)"
                            .into()
                    }
                }
            } else {
                format!("{} rows cannot fit {} parameters", rows.len(), free.len())
            },
        );
    }
    // Start values.
    let mut base = tyre.clone();
    let starts: Vec<f64> = match start {
        StartScheme::Paper => vec![1.0; free.len()],
        StartScheme::Template => free
            .iter()
            .map(|(name, _)| base.coefficients.get(name).unwrap_or(0.0))
            .collect(),
        StartScheme::Data => {
            // The data's estimates, else the coefficient's version default
            // (0 but for PKY4 = 2): never the template's fitted values.
            let est = data_start(stage, &base, rows);
            let defaults = MfCoefficients::default();
            free.iter()
                .map(|(name, _)| {
                    est.iter()
                        .find(|(k, _)| k == name)
                        .map_or(defaults.get(name).unwrap_or(0.0), |e| e.1)
                })
                .collect()
        }
    };
    for ((name, _), v) in free.iter().zip(&starts) {
        base.coefficients.set(name, *v);
    }
    // A held coefficient still at 0 that the formula cannot live with at 0
    // (`PKY2` divides the load) takes the data's estimate.
    for (name, v) in data_start(stage, &base, rows) {
        if !names_of(&free).contains(&name) && base.coefficients.get(name) == Some(0.0) {
            base.coefficients.set(name, v);
        }
    }
    let names: Vec<&'static str> = free.iter().map(|(k, _)| *k).collect();
    let problem = StageProblem {
        base: base.clone(),
        stage,
        names: names.clone(),
        rows: rows.to_vec(),
    };
    let (sigma_start, ..) = sigma(stage, &base, rows);
    let mut evaluations = 0;
    let result = match start {
        StartScheme::Paper => paper_lm(&problem, &starts, 1.0, max_iterations.max(500)),
        StartScheme::Data | StartScheme::Template => {
            let bounds: Vec<(f64, f64)> = names
                .iter()
                .zip(&starts)
                .map(|(k, v)| physical_bounds(k, *v))
                .collect();
            let (r, e) = released_fit(&problem, &free, &starts, &bounds, max_iterations);
            evaluations += e;
            r
        }
    };
    evaluations += result.evaluations;
    let p = result.params.clone();
    *tyre = problem.tyre(&p);
    let (sigma_end, rms, ..) = sigma(stage, tyre, rows);
    // Standard errors on the column-scaled Jacobian.
    let mut res = vec![0.0; problem.count()];
    problem.residuals(&p, &mut res);
    let j = jacobian(&problem, &p, &res);
    let (m, nf) = (problem.count(), p.len());
    let s2 = res.iter().map(|e| e * e).sum::<f64>() / (m - nf).max(1) as f64;
    let norms: Vec<f64> = (0..nf).map(|k| j.column(k).norm()).collect();
    let mut js = j.clone();
    for (k, nk) in norms.iter().enumerate() {
        if *nk > 0.0 {
            js.column_mut(k).scale_mut(1.0 / nk);
        }
    }
    let svd = js.clone().svd(false, true);
    let sv = &svd.singular_values;
    let (smax, smin) = (sv.max(), sv.min());
    let cond = if smin > 0.0 {
        smax / smin
    } else {
        f64::INFINITY
    };
    let jtj = js.transpose() * &js;
    let cov = jtj.pseudo_inverse(1e-14).ok();
    let mut warnings = Vec::new();
    if cond > 1e8 {
        // The weakest direction: the right singular vector of the smallest
        // singular value names the parameters that trade off.
        let mut weak = String::new();
        if let Some(vt) = &svd.v_t {
            let kmin = (0..sv.len())
                .min_by(|a, b| sv[*a].total_cmp(&sv[*b]))
                .unwrap_or(0);
            let row = vt.row(kmin);
            let mut w: Vec<(usize, f64)> = row.iter().map(|v| v.abs()).enumerate().collect();
            w.sort_by(|a, b| b.1.total_cmp(&a.1));
            weak = w
                .iter()
                .take(3)
                .filter(|x| x.1 > 0.2)
                .map(|x| names[x.0])
                .collect::<Vec<_>>()
                .join(", ");
        }
        warnings.push(format!(
            "near-singular Jacobian (condition number {cond:.2e}): the data barely separate {weak}"
        ));
    }
    let parameters = table
        .iter()
        .map(|(name, need)| {
            let value = tyre.coefficients.get(name).unwrap_or(0.0);
            match names.iter().position(|k| k == name) {
                Some(k) => {
                    let se = cov.as_ref().and_then(|c| {
                        (norms[k] > 0.0).then(|| (s2 * c[(k, k)]).max(0.0).sqrt() / norms[k])
                    });
                    let warning = match se {
                        None => Some("no sensitivity: the data do not move it".into()),
                        Some(s) if !s.is_finite() || s > value.abs() => Some(format!(
                            "not identifiable from these data (standard error {s:.3e} ≥ |value|)"
                        )),
                        _ => None,
                    };
                    StageParameter {
                        name,
                        value,
                        start: starts[k],
                        free: true,
                        std_error: se,
                        held_because: None,
                        warning,
                    }
                }
                None => StageParameter {
                    name,
                    value,
                    start: value,
                    free: false,
                    std_error: None,
                    held_because: held_reason(*need, have),
                    warning: None,
                },
            }
        })
        .collect();
    StageReport {
        stage,
        skipped: None,
        points: rows.len(),
        levels: have,
        sigma_start_percent: sigma_start,
        sigma_percent: sigma_end,
        paper_sigma_percent: stage.paper_sigma_percent(),
        rms,
        condition_number: cond,
        converged: result.converged,
        evaluations: evaluations * m,
        seconds: t0.elapsed().as_secs_f64(),
        parameters,
        warnings,
    }
}

/// The `.tir` text of an identified tyre: the template's file with the
/// values replaced (its comments and other keys kept), or a fresh file.
pub fn tir_text(tyre: &MagicFormula, template: Option<&TirDocument>) -> Result<String, InputError> {
    match template {
        Some(doc) => doc.write(tyre),
        None => Ok(write_new(tyre)),
    }
}

/// Reads `text` back as a `.tir` and returns the largest difference of
/// `fx`, `fy`, `mz` between it and `tyre` over `rows`, relative to the
/// largest magnitude of each channel (0 when the file reproduces the tyre).
pub fn round_trip_difference(
    tyre: &MagicFormula,
    text: &str,
    rows: &[MfRow],
) -> Result<f64, InputError> {
    let back = TirDocument::parse(Path::new("<written .tir>"), text)?.magic_formula()?;
    let mut worst: f64 = 0.0;
    let mut scale = [1e-9f64; 3];
    let mut diff = [0.0f64; 3];
    for r in rows {
        let (a, b) = (tyre.evaluate(&r.input()), back.evaluate(&r.input()));
        for (k, (x, y)) in [(a.fx, b.fx), (a.fy, b.fy), (a.mz, b.mz)]
            .iter()
            .enumerate()
        {
            scale[k] = scale[k].max(x.abs());
            diff[k] = diff[k].max((x - y).abs());
        }
    }
    for k in 0..3 {
        worst = worst.max(diff[k] / scale[k]);
    }
    Ok(worst)
}
