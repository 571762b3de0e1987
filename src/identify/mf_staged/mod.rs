//! Staged identification of a Magic Formula 6.1 / 6.2 tyre from rig data by
//! Levenberg–Marquardt, after Wei Yaobing, Zhao Xuemei and Jiang Zuxiao
//! (2010): five stages in the paper's order — pure longitudinal force
//! `Fx0(κ, γ, Fz)`, pure lateral force `Fy0(α, γ, Fz)`, pure aligning moment
//! `Mz0(α, γ, Fz)` (with the lateral parameters just fixed), combined-slip
//! longitudinal force (the weighting `Gxα`, with the pure `Fx` parameters
//! fixed) and combined-slip lateral force (`Gyκ` and `SVyκ`, with the pure
//! `Fy` parameters fixed). Each stage minimises `E = Σ(F_model − F_test)²`
//! over its rows. Three stages the paper leaves out follow in the same
//! manner: the combined-slip aligning moment's `Fx` arm `s` (`SSZ1..4`, on
//! the combined rows' `mz`, the pure `Mz` fixed), the overturning moment
//! `Mx` (`QSX*`, on every row with an `mx`, the `Fy` fixed) and the
//! rolling-resistance moment `My` (`QSY*`, on every row with an `my`;
//! `QSY3`, `QSY4`, the speed terms, held: one rig speed). `Mx`'s sine and
//! load terms start off zero, where their gradients would vanish together.
//!
//! What a stage fits is what its rows can identify: a load-dependent term
//! (`PDX2`, `PKY2`, …) needs two load levels, a load-squared one (`PEX3`,
//! `PKX3`, `QBZ3`, …) three; a camber term linear in γ two camber levels, a
//! second camber term of the same function (`γ²` beside `|γ|` or `γ`) three;
//! pressure terms two (three for the quadratic ones); `PKY4`, the curvature
//! of `Kyα(Fz)`, four loads (with three, `PKY1`, `PKY2`, `PKY4` fit the
//! three stiffnesses exactly and drift together along a near-null
//! direction). The rest are held at
//! the template's values (or their version defaults) and reported as held. The
//! paper counts 15 + 20 + 27 + 7 + 14 = 83 parameters; the lists here
//! (`STAGES`) are the TNO 6.1 ones of each function (22 for pure `Fy`,
//! 15 for combined `Fy`) plus the pressure terms `PPX*`, `PPY*`, `PPZ*`.
//! `QBZ9` is held: beside `QBZ10·By·Cy` it is a second constant in the
//! residual torque's slope that rig data barely separate.
//!
//! Rows: the wheel moments `mx`, `my` ride on the rows of files whose
//! samples are rows (with `kappa`, `fx`). A row is *pure longitudinal*
//! when `|α| ≤ 1e-3 rad`, *pure lateral* when `|κ| ≤ 1e-3`, *combined*
//! otherwise. The combined `Fy` and `Mz`
//! stages take every row with longitudinal slip, the pure longitudinal
//! ones included: at α = 0, `Fy = Gyκ·Fy0(0) + SVyκ` is what pins the
//! κ-induced side force `SVyκ`, and `Mz` carries `s·Fx` ([`Stage::takes`]).
//! Without a single combined row they are skipped (`stages.rs`): the α = 0
//! rows alone fitted `RBY1` = 27386 to an `fy` of zeros.
//! A stage whose columns or rows are missing is skipped and says why; it
//! is not an error.
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
//! Derivatives: each stage's Jacobian is exact, by forward-mode dual
//! numbers (`num-dual`): the stage's channel evaluated once per row with
//! the free coefficients as dual variables, in passes of up to 28 directions
//! ([`crate::tyre::mf::MagicFormula::channel_at`]), the parts of the
//! formula no free coefficient enters (the lateral force in the `Mz`
//! stage, …) prepared once per row in plain numbers. Forward differences
//! ([`Derivatives::Differences`], `n` evaluations of the rows per
//! Jacobian) stay selectable through [`identify_with`], for comparison. On
//! the Hoosier rig data the exact fit costs a sixth of the CPU time of the
//! differenced one; its `Fy` stage ends in a neighbouring minimum of the
//! stage's cost, 0.5 % above (σ 1.682 % against 1.678 %; pooled 3.553 %
//! against 3.551 %), its `Mz` stage where the differences end.
//!
//! Residual metric: the paper's residual table lost its formula in the
//! surviving text; this module reports `σ = sqrt(Σe²/ΣF_test²)·100 %` per
//! stage over its rows, and one overall figure, the same σ pooled over
//! every raw sample and measured channel ([`pooled_sigma`]), the
//! definition of Zhang & Li (2017) used throughout the crate
//! ([`super::sigma_of`]).
//!
//! Standard errors: `cov = s²·(JᵀJ)⁻¹` at the optimum with `s² = Σe²/(m−n)`,
//! computed on the column-scaled Jacobian (SVD, pseudo-inverse); a parameter
//! whose standard error reaches its magnitude *and*, alone, moves the
//! stage's channel by 1 % of its RMS is not identifiable (a parameter
//! pinned to zero is identified, as zero; `uncertainty.rs`): it is held at
//! a stated value — the template's, else Pacejka's (2012) book default —
//! and the stage refitted, one parameter at a time (`holds.rs`); a value
//! the user gives holds a parameter from the start. A stage whose scaled
//! Jacobian has a condition number above 1e8 is flagged as near-singular,
//! naming the parameters that dominate its weakest direction.
//!
//! Units: SI and radians in the rows (crate convention, `docs/FORMATS.md`);
//! the coefficients are the `.tir`'s ISO-W ones and are only evaluated
//! through [`MagicFormula`], which maps the signs at its boundary.
//!
//! Layout: this file has the public API and the report types; `params.rs`
//! the stages and what each may fit (levels needed, physical bounds);
//! `start.rs` the start values from the data; `problem.rs` a stage's
//! least-squares problem and its exact Jacobian; `stages.rs` one stage's
//! fit (`stage_fit.rs` its starts, `template_start.rs` a template's);
//! `uncertainty.rs` its standard errors and the identifiability rule;
//! `holds.rs` what a parameter is held at and why (`curvature_clip.rs`:
//! by `E ≤ 1`); `paper_lm.rs` the paper's own LM.

mod book_defaults;
mod curvature_clip;
mod determination;
mod fit_warnings;
mod hold_guard;
mod hold_refusal;
mod hold_rounds;
mod holds;
mod paper_lm;
pub use fit_warnings::{LARGE_SIGMA_PERCENT, MIN_POINTS_PER_PARAMETER};
mod params;
mod problem;
mod release;
mod sigma;
mod sigma_moves;
mod spread;
mod stage_fit;
mod stages;
mod start;
mod template_start;
mod uncertainty;

pub use crate::identify::determined::{Determination, Partner};
pub use book_defaults::pacejka_book_default;
pub use curvature_clip::{AtClip, CurvatureFactor};
pub(crate) use hold_refusal::sigma_limit;
pub use hold_refusal::{GuardLimit, MoreData, RefusedHold};
pub use holds::{HoldReason, HoldSource, Holding};
pub use paper_lm::paper_lm;
pub(crate) use params::fixed_bounds;
pub use params::Stage;
pub use problem::Derivatives;
pub use sigma::{
    channel_unit, pooled_sigma, raw_rows, rms_text, round_trip_difference, ChannelSigma,
    PooledSigma,
};
pub use sigma_moves::{sigma_said, SigmaMove};
pub use spread::{sweeps_slip_angle, ErrorSpread, LoadSigma};
pub use template_start::{SecondStart, SecondStartWhy, REPRODUCED_SIGMA_PERCENT};

use super::data::RigData;
use super::grouping::{group, Grouping, GroupingReport, SlipAxis};
use crate::error::{FitError, InputError, SkipReason, StageSkip};
use crate::tyre::mf::{MagicFormula, MfCoefficients, MfInput, MfVersion};
use params::EVEN;
use release::sigma;
use serde::Serialize;
use stage_fit::StageRun;
use stages::run_stage;
use start::base_tyre;
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
    /// Overturning moment, N·m (ISO-W, of a left tyre).
    pub mx: f64,
    /// Rolling-resistance moment, N·m (ISO-W: negative rolling forward).
    pub my: f64,
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
/// Speed defaults to `default_speed` where the file has none. The wheel
/// moments `moments` (`mx`, `my`, one per sample, if measured) are kept on
/// the rows of a file whose samples are rows; thinning averages only the
/// forces and `mz`, so a lateral-only file's rows carry none.
pub fn prepare(
    path: &Path,
    d: &RigData,
    moments: &[Option<Vec<f64>>; 2],
    alpha_bin: f64,
    default_speed: f64,
) -> Result<Prepared, InputError> {
    let moment = |k: usize, i: usize| moments[k].as_ref().map_or(f64::NAN, |m| m[i]);
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
                mx: moment(0, i),
                my: moment(1, i),
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
                fz: q.fz,
                kappa: 0.0,
                alpha: q.slip(),
                camber: q.camber,
                speed: q.speed,
                pressure: c.pressure,
                fx: f64::NAN,
                fy: q.fy(),
                mz: q.mz(),
                mx: f64::NAN,
                my: f64::NAN,
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
    /// Whether `max_iterations` is the user's: honoured as given. The
    /// default cap is not: a stage stopped on it short of its optimum is
    /// continued (`stage_fit::continued_cap`).
    pub cap_given: bool,
    /// The values the user gives and the keys the template gives
    /// (`holds.rs`: what a parameter the data do not determine is held at).
    pub holding: Holding,
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
    /// Fitted (false: held, see `held`).
    pub free: bool,
    /// Approximate standard error (free parameters).
    pub std_error: Option<f64>,
    /// Why a parameter was held, and at what (`value`).
    pub held: Option<HoldReason>,
    /// The physical bound a fitted parameter ends on (the fit would take
    /// it beyond: the value is the bound's, not the data's).
    pub on_bound: Option<f64>,
    /// How the data determine it (fitted parameters; `determination.rs`).
    pub determination: Option<Determination>,
    /// An identifiability warning.
    pub warning: Option<String>,
    /// A hold of this free parameter the guard refused: the value tried,
    /// what it cost, and what the user can do (`None`: none refused).
    pub hold_refused: Option<RefusedHold>,
}

/// The outcome of one stage.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StageReport {
    /// Which stage.
    pub stage: Stage,
    /// Skipped, and why (`None`: fitted).
    pub skipped: Option<SkipReason>,
    /// Rows fitted.
    pub points: usize,
    /// Load, camber and pressure levels in them.
    pub levels: [usize; 3],
    /// σ = sqrt(Σe²/ΣF²)·100 % at the start.
    pub sigma_start_percent: f64,
    /// σ of the identified tyre over the stage's rows, %.
    pub sigma_percent: f64,
    /// σ at the end of its own fit and holds, % (`None`: skipped).
    pub sigma_own_percent: Option<f64>,
    /// The later stages that moved its σ from there (`sigma_moves.rs`).
    pub sigma_moved_by: Vec<SigmaMove>,
    /// Wei et al. (2010)'s residual for this case, %.
    pub paper_sigma_percent: f64,
    /// RMS error (N or N·m).
    pub rms: f64,
    /// Condition number of the column-scaled Jacobian at the optimum.
    pub condition_number: f64,
    /// Whether LM stopped on its own test, or where a Gauss–Newton step
    /// would barely improve the fit (`None`: the stage was skipped).
    pub converged: Option<bool>,
    /// Evaluations of the stage's channel at its rows (one per row per
    /// residual vector; a differenced Jacobian counts its columns, an
    /// exact one nothing).
    pub evaluations: usize,
    /// Wall time, s.
    pub seconds: f64,
    /// The stage's parameters.
    pub parameters: Vec<StageParameter>,
    /// Stage-level warnings (near-singular Jacobian).
    pub warnings: Vec<String>,
    /// Where the fitted stage's squared error lies (`None`: skipped).
    pub error_spread: Option<ErrorSpread>,
    /// The stage fitted again from the template's values, the σ of both
    /// starts, the one kept (`None`: none; `template_start.rs`).
    pub second_start: Option<SecondStart>,
}

impl StageReport {
    fn skipped(stage: Stage, why: SkipReason) -> Self {
        Self {
            stage,
            skipped: Some(why),
            points: 0,
            levels: [0; 3],
            sigma_start_percent: f64::NAN,
            sigma_percent: f64::NAN,
            sigma_own_percent: None,
            sigma_moved_by: Vec::new(),
            paper_sigma_percent: stage.paper_sigma_percent(),
            rms: f64::NAN,
            condition_number: f64::NAN,
            converged: None,
            evaluations: 0,
            seconds: 0.0,
            parameters: Vec::new(),
            warnings: Vec::new(),
            error_spread: None,
            second_start: None,
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
    /// Wall time, s.
    pub seconds: f64,
}

/// The identified tyre and the report.
#[derive(Debug, Clone)]
pub struct Identified {
    /// The tyre (version as requested; side and constants from the template).
    pub tyre: MagicFormula,
    /// The report.
    pub report: StagedReport,
}

/// Runs the stages on `rows` with exact Jacobians. Fails only when no
/// stage could run.
pub fn identify(rows: &[MfRow], settings: &Settings) -> Result<Identified, FitError> {
    identify_with(rows, settings, Derivatives::Exact)
}

/// As [`identify`], with the stages' Jacobians computed as `derivatives`
/// says (finite differences for comparison).
pub fn identify_with(
    rows: &[MfRow],
    settings: &Settings,
    derivatives: Derivatives,
) -> Result<Identified, FitError> {
    let t0 = Instant::now();
    let mut tyre = base_tyre(rows, settings);
    for (name, value) in &settings.holding.given {
        tyre.coefficients.set(name, *value);
    }
    let run = StageRun {
        start: settings.start,
        max_iterations: settings.max_iterations,
        cap_given: settings.cap_given,
        derivatives,
        holding: &settings.holding,
        template: settings.template.as_ref(),
    };
    let mut reports = run_stages(rows, &mut tyre, &run);
    if let Some(e) = none_fitted(rows, &reports) {
        return Err(e);
    }
    // Each stage's σ and RMS of the final tyre (a later stage may move a
    // channel an earlier one fitted: `SSZ*` the pure rows' `Mz` through
    // their small `Fx`), so that the written file reproduces them.
    for r in reports.iter_mut().filter(|r| r.skipped.is_none()) {
        let sel: Vec<&MfRow> = rows.iter().filter(|row| r.stage.takes(row)).collect();
        let (sigma_percent, rms, _, _) = sigma(r.stage, &tyre, &sel);
        r.sigma_percent = sigma_percent;
        r.rms = rms;
        r.error_spread = Some(spread::error_spread(r.stage, &tyre, &sel));
        r.warnings.extend(fit_warnings::fit_warnings(r));
    }
    Ok(Identified {
        report: StagedReport {
            version: tyre.version,
            start: settings.start,
            template: settings.template.is_some(),
            fnomin: tyre.coefficients.FNOMIN,
            nompres: tyre.coefficients.NOMPRES,
            stages: reports,
            seconds: t0.elapsed().as_secs_f64(),
        },
        tyre,
    })
}

/// Each stage in order on the rows it takes, updating `tyre`; a stage
/// that builds on a skipped one skipped too.
fn run_stages(rows: &[MfRow], tyre: &mut MagicFormula, run: &StageRun) -> Vec<StageReport> {
    let mut reports: Vec<StageReport> = Vec::new();
    for stage in Stage::ALL {
        let skipped = |need: &&Stage| {
            reports
                .iter()
                .any(|r| r.stage == **need && r.skipped.is_some())
        };
        if let Some(need) = stage.needs().iter().find(skipped) {
            let why = SkipReason::BuildsOnSkipped {
                stage: need.label(),
            };
            reports.push(StageReport::skipped(stage, why));
            continue;
        }
        let sel: Vec<&MfRow> = rows.iter().filter(|r| stage.takes(r)).collect();
        reports.push(run_stage(stage, tyre, &sel, run));
        let n = reports.len() - 1;
        sigma_moves::record_moves(&mut reports[..n], stage, tyre, rows);
    }
    reports
}

/// The error of a fit whose every stage was skipped (each with why, and
/// the rows and combined-slip rows there were), or `None`.
fn none_fitted(rows: &[MfRow], reports: &[StageReport]) -> Option<FitError> {
    if !reports.iter().all(|r| r.skipped.is_some()) {
        return None;
    }
    let skips: Vec<StageSkip> = reports
        .iter()
        .filter_map(|r| {
            r.skipped.map(|reason| StageSkip {
                stage: r.stage.label(),
                reason,
            })
        })
        .collect();
    let combined = rows
        .iter()
        .filter(|r| r.kappa.abs() > 1e-3 && r.alpha.abs() > 1e-3)
        .count();
    Some(FitError::NoStageFitted {
        skips,
        rows: rows.len(),
        combined,
    })
}

/// The sign-blind coefficients of `c` (`EVEN`, and `RVY5`, `RVY6`
/// together) in one conventional sign. Set after each stage, before its
/// report is made, so that its warnings, its held lines and the written
/// file give each the same sign (`--start paper`'s summary said
/// `RBX2 = -303` where the file had 302.99).
pub(super) fn conventional_signs(c: &mut MfCoefficients) {
    for name in EVEN {
        c.set(name, c.get(name).unwrap_or(0.0).abs());
    }
    // sin(RVY5·atan(RVY6·κ)) is unchanged when both flip.
    if c.RVY5 < 0.0 {
        c.RVY5 = -c.RVY5;
        c.RVY6 = -c.RVY6;
    }
}
