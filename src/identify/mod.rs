//! Tyre parameter identification from rig data (Zhang & Li (2017), Zhang et al. (2021)): a
//! particle swarm over the model's bounded parameter box finds the
//! neighbourhood of the global optimum of `ε = ½·Σ(F_sim − F_test)²`, and a
//! local least-squares method polishes it (Levenberg–Marquardt by default, or
//! Zhang & Li's (2017) modified Gauss–Newton). Residual metric (Zhang & Li (2017)):
//! `σ = sqrt(Σ(F_sim − F_test)²/Σ F_test²)·100 %` per condition and overall.
//! Standard errors come from the Jacobian at the optimum, `cov = s²·(JᵀJ)⁻¹`
//! with `s² = Σe²/(m − n)`; a parameter on its bound or with a standard
//! error larger than itself is flagged.
//!
//! The lateral force of every model is fitted first; then, where the data
//! have `mz` and the model an aligning moment, its aligning parameters with
//! the lateral ones held. The parameters the data cannot identify stay at
//! their start values ([`crate::tyre::Tyre::lateral_free`]); with
//! [`FitSettings::hold_undetermined`] (as `identify` fits), those the data
//! do not determine when fitted are held at the model's start values and
//! the rest refitted (`undetermined.rs`). Units: SI inside; the models'
//! own units stay in their files.
//!
//! The least-squares problem (`problem.rs`): the lateral force's Jacobian
//! is exact, in dual numbers, for every model with a generic lateral force
//! ([`Derivatives`]); the aligning and longitudinal blocks difference
//! theirs.

mod aligning;
pub mod data;
pub mod determined;
pub mod grouping;
mod held;
pub mod lifted;
mod parameters;
pub mod pooled;
use parameters::parameter_reports;
pub mod mf_staged;
pub(crate) mod pac89_two_stage;
mod problem;
pub mod pure;
mod reach;
mod spare;
pub mod template_size;
mod undetermined;
use undetermined::Spread;
pub(crate) use undetermined::{hold_undetermined, start_tyre_of};

pub(crate) use held::{bounds_in, set_after_fits, value_in, with_value, LINEAR_TRAIL};
pub use held::{ConstantFrom, HeldFor};
pub use problem::{Channel, Derivatives, FitProblem};

use crate::error::{Error, FitError};
use crate::optim::bounded::BoundedLm;
use crate::optim::local::{levenberg_marquardt, GaussNewton, LocalResult, Residuals};
use crate::optim::{stats, Inertia, Pso};
use crate::tyre::Tyre;
use data::Condition;
use nalgebra::DMatrix;
use serde::Serialize;
use std::time::Instant;

/// The local polish after PSO.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum LocalMethod {
    /// Levenberg–Marquardt (crate).
    LevenbergMarquardt,
    /// Zhang & Li's (2017) modified Gauss–Newton.
    GaussNewton,
    /// PSO only.
    None,
}

/// Fit settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitSettings {
    /// The swarm (its seed is the fit's seed).
    pub pso: Pso,
    /// The polish.
    pub local: LocalMethod,
    /// The Jacobian's derivatives.
    pub derivatives: Derivatives,
    /// Whether a parameter the data do not determine is held at the
    /// start tyre's value and the rest refitted (`undetermined.rs`):
    /// `identify` does; off by default, so that a caller comparing free
    /// fits (`diagnose`, the benches) gets them as they are.
    pub hold_undetermined: bool,
}

impl FitSettings {
    /// Zhang et al.'s (2021) improved PSO (adaptive inertia, natural selection) sized for
    /// tyre fits, then Levenberg–Marquardt.
    pub fn new(seed: u64) -> Self {
        Self {
            pso: Pso {
                particles: 60,
                iterations: 300,
                inertia: Inertia::Adaptive,
                natural_selection: true,
                w_min: 0.4,
                w_max: 0.9,
                c1: 1.5,
                c2: 1.5,
                velocity_limit: 0.2,
                seed,
                parallel: true,
                ..Pso::default()
            },
            local: LocalMethod::LevenbergMarquardt,
            derivatives: Derivatives::Exact,
            hold_undetermined: false,
        }
    }
}

/// Per-condition residuals.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurveReport {
    /// Nominal load, N.
    pub fz: f64,
    /// Nominal camber, rad.
    pub camber: f64,
    /// Nominal pressure, Pa.
    pub pressure: Option<f64>,
    /// Points fitted.
    pub points: usize,
    /// Raw samples behind them.
    pub samples: usize,
    /// σ, %.
    pub sigma_percent: f64,
    /// RMS error, N.
    pub rms: f64,
}

/// A fitted parameter.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ParameterReport {
    /// Name.
    pub name: String,
    /// Value.
    pub value: f64,
    /// Whether it was fitted (false: held, see `held`).
    pub free: bool,
    /// Why it was held, and so at what (`value`): `None` when fitted.
    pub held: Option<HeldFor>,
    /// Approximate standard error.
    pub std_error: Option<f64>,
    /// One standard error's effect alone, % of the channel's RMS (`‖∂F/∂p‖·se/‖F‖`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub effect_percent: Option<f64>,
    /// Search bounds.
    pub bounds: (f64, f64),
    /// Warning, if any.
    pub warning: Option<String>,
    /// Fixed by the data beyond its linearisation, where a hold within its
    /// ±2 standard errors was refused (`determined.rs`); else `None`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub determination: Option<determined::Determination>,
    /// What the data leave of it unsettled where the fit hardly feels it
    /// (a standard error past the value, an effect under 1 % of the
    /// channel's RMS): said, not warned of.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// The outcome of a fit.
#[derive(Debug, Clone, Serialize)]
pub struct Fit {
    /// The channel fitted.
    pub channel: Channel,
    /// Model name.
    pub model: &'static str,
    /// Random seed.
    pub seed: u64,
    /// The fitted tyre.
    #[serde(skip)]
    pub tyre: Tyre,
    /// σ overall after the polish, %.
    pub sigma_percent: f64,
    /// σ overall after PSO alone, %.
    pub sigma_pso_percent: f64,
    /// σ overall before the undetermined parameters were held, % (or none).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub free_sigma_percent: Option<f64>,
    /// σ free from the swarm's start, %, where a restart won (`undetermined.rs`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub free_swarm_sigma_percent: Option<f64>,
    /// RMS error overall, N.
    pub rms: f64,
    /// Per condition.
    pub curves: Vec<CurveReport>,
    /// Parameters.
    pub parameters: Vec<ParameterReport>,
    /// Model evaluations of the whole data set (PSO + polish).
    pub evaluations: usize,
    /// Wall time, s.
    pub seconds: f64,
    /// The polish used.
    pub local: LocalMethod,
    /// Covariance of the free parameters (in their order), from the Jacobian.
    #[serde(skip)]
    pub covariance: Option<nalgebra::DMatrix<f64>>,
}

/// σ (%) and RMS (N) of a tyre's lateral force on some points.
pub fn sigma(t: &Tyre, points: &[data::Point]) -> (f64, f64) {
    sigma_of(Channel::LateralForce, t, points)
}

/// σ (%) and RMS of one channel on the points where it was measured.
pub fn sigma_of(ch: Channel, t: &Tyre, points: &[data::Point]) -> (f64, f64) {
    let (mut e2, mut y2, mut n) = (0.0, 0.0, 0usize);
    for q in points.iter().filter(|q| ch.measured(q).is_finite()) {
        let e = ch.model(t, q) - ch.measured(q);
        e2 += e * e;
        y2 += ch.measured(q) * ch.measured(q);
        n += 1;
    }
    (100.0 * (e2 / y2).sqrt(), (e2 / n.max(1) as f64).sqrt())
}

/// Fits `start`'s lateral-force parameters to the conditions.
pub fn fit_lateral(
    start: &Tyre,
    conditions: &[Condition],
    settings: &FitSettings,
) -> Result<Fit, Error> {
    fit_channel(start, Channel::LateralForce, conditions, settings)
}

/// Fits `start`'s parameters of `channel` to the conditions (for the
/// aligning moment, with the lateral-force parameters held at `start`'s):
/// the swarm, then the local polish, then standard errors from the Jacobian
/// at the optimum.
pub(crate) fn fit_channel(
    start: &Tyre,
    channel: Channel,
    conditions: &[Condition],
    settings: &FitSettings,
) -> Result<Fit, Error> {
    fit_channel_holding(start, channel, conditions, settings, &[])
}

/// The names of every parameter a swarm fit of `t` can fit: the lateral
/// force's, then the aligning moment's and the longitudinal force's.
pub fn fitted_names(t: &Tyre) -> Vec<String> {
    [
        Channel::LateralForce,
        Channel::AligningMoment,
        Channel::LongitudinalForce,
    ]
    .into_iter()
    .flat_map(|c| c.names(t))
    .fold(Vec::new(), |mut all, n| {
        // A parameter two blocks share (GIM's contact length) once.
        if !all.contains(&n) {
            all.push(n);
        }
        all
    })
}

/// [`fit_channel`] with the parameters named in `hold` (name, value in the
/// model's units) set to their values and not fitted; a name of another
/// channel's block is left to that channel's fit.
pub(crate) fn fit_channel_holding(
    start: &Tyre,
    channel: Channel,
    conditions: &[Condition],
    settings: &FitSettings,
    hold: &[(String, f64)],
) -> Result<Fit, Error> {
    let t0 = Instant::now();
    let (start, held) = holding(start, channel, hold);
    let start = &start;
    // A held value the model refuses (a negative friction) is refused
    // before the fit, at its name, not fitted around.
    if held.iter().any(|h| *h) {
        start.validate()?;
    }
    let (mut free, mut reasons) = free_parameters(start, channel, conditions)?;
    for ((f, r), h) in free.iter_mut().zip(&mut reasons).zip(&held) {
        if *h {
            *f = false;
            *r = Some(HeldFor::Given);
        }
    }
    let problem = FitProblem::for_channel(start, channel, &free, conditions)
        .with_derivatives(settings.derivatives);
    if problem.count() <= problem.free.len() {
        return Err(FitError::TooFewPoints {
            points: problem.count(),
            quantity: channel.quantity(),
            parameters: problem.free.len(),
        }
        .into());
    }
    let all_bounds = channel.bounds(start);
    let start_all = channel.parameters(start);
    let start_p: Vec<f64> = problem.free.iter().map(|&i| start_all[i]).collect();
    let found = search(&problem, &all_bounds, &start_p, settings);
    let tyre = problem.tyre(&found.params).canonical();
    let full = channel.parameters(&tyre);
    let p: Vec<f64> = problem.free.iter().map(|&i| full[i]).collect();
    let spread = Spread::at(&problem, &p);
    let mut parameters = parameter_reports(start, &tyre, channel, &free, &spread);
    for (p, why) in parameters.iter_mut().zip(reasons) {
        p.held = why;
    }
    for (p, _) in parameters.iter_mut().zip(&held).filter(|(_, h)| **h) {
        p.warning = Some("held at the value given".into());
    }
    let curves = curves_of(channel, &tyre, conditions);
    let (s, rms) = sigma_of(channel, &tyre, &problem.points);
    let fit = Fit {
        channel,
        model: start.model_name(),
        seed: settings.pso.seed,
        tyre,
        sigma_percent: s,
        sigma_pso_percent: found.sigma_pso,
        free_sigma_percent: None,
        free_swarm_sigma_percent: None,
        rms,
        curves,
        parameters,
        evaluations: found.evaluations,
        seconds: t0.elapsed().as_secs_f64(),
        local: settings.local,
        covariance: spread.covariance,
    };
    Ok(if settings.hold_undetermined {
        hold_undetermined(fit, start, conditions, settings)
    } else {
        fit
    })
}

/// `start` with the parameters of `channel`'s block named in `hold` (name,
/// value in the model's units) set to their values, and which of the
/// block's parameters, in its order, are so held; a name of another
/// channel's block is left as it is.
fn holding(start: &Tyre, channel: Channel, hold: &[(String, f64)]) -> (Tyre, Vec<bool>) {
    let names = channel.names(start);
    let held: Vec<bool> = names
        .iter()
        .map(|n| hold.iter().any(|(h, _)| h == n))
        .collect();
    let mut t = start.clone();
    let mut p = channel.parameters(&t);
    for (name, v) in hold {
        if let Some(i) = names.iter().position(|n| n == name) {
            p[i] = *v;
        }
    }
    channel.set(&mut t, &p);
    (t, held)
}

/// The covariance of the free parameters `p` of `problem` from its
/// Jacobian there and the residual variance (None: not determined).
fn covariance_at(problem: &FitProblem, p: &[f64]) -> Option<DMatrix<f64>> {
    let mut res = vec![0.0; problem.count()];
    problem.residuals(p, &mut res);
    let sum_squares: f64 = res.iter().map(|e| e * e).sum();
    let unbounded = vec![(f64::NEG_INFINITY, f64::INFINITY); p.len()];
    (!p.is_empty())
        .then(|| stats::covariance(&problem.jacobian(p, &res, &unbounded), sum_squares))
        .flatten()
}

/// σ and RMS of `tyre`'s `channel` on each condition.
pub(super) fn curves_of(
    channel: Channel,
    tyre: &Tyre,
    conditions: &[Condition],
) -> Vec<CurveReport> {
    conditions
        .iter()
        .map(|c| {
            let (s, rms) = sigma_of(channel, tyre, &c.points);
            CurveReport {
                fz: c.fz,
                camber: c.camber,
                pressure: c.pressure,
                points: c.points.len(),
                samples: c.samples,
                sigma_percent: s,
                rms,
            }
        })
        .collect()
}

/// The report of `tyre` as a fit of `channel` to `conditions` made by
/// another method than `like`'s (PAC89's two stages beside the direct
/// fit): its values, σ and curves, the standard errors of the parameters
/// `like` fitted from the Jacobian at `tyre`, those `like` held held
/// alike; `like`'s seed, work and swarm σ.
pub fn fit_report_of(tyre: Tyre, channel: Channel, conditions: &[Condition], like: &Fit) -> Fit {
    let free: Vec<bool> = like.parameters.iter().map(|p| p.free).collect();
    let problem = FitProblem::for_channel(&tyre, channel, &free, conditions);
    let start = tyre.clone();
    Fit {
        free_sigma_percent: None,
        free_swarm_sigma_percent: None,
        ..parameters::fit_carrying_holds(tyre, &start, &problem, conditions, like)
    }
}

/// Which of `channel`'s parameters the conditions can identify and why
/// each other is held, or why the model or the data cannot be fitted at
/// all.
fn free_parameters(
    start: &Tyre,
    channel: Channel,
    conditions: &[Condition],
) -> Result<(Vec<bool>, Vec<Option<HeldFor>>), Error> {
    if channel.names(start).is_empty() {
        return Err(FitError::NothingToFit {
            model: start.model_name(),
            quantity: channel.quantity(),
        }
        .into());
    }
    let mut loads: Vec<f64> = conditions.iter().map(|c| c.fz).collect();
    loads.sort_by(f64::total_cmp);
    loads.dedup_by(|a, b| (*a - *b).abs() < 1.0);
    let mut cambers: Vec<f64> = conditions.iter().map(|c| c.camber).collect();
    cambers.sort_by(f64::total_cmp);
    cambers.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
    if loads.len() < start.loads_needed() {
        return Err(FitError::TooFewLoads {
            model: start.model_name(),
            needed: start.loads_needed(),
            loads,
        }
        .into());
    }
    let free = channel.free(start, loads.len(), cambers.len());
    let reasons = held::held_reasons(start, channel, loads.len(), cambers.len(), &free);
    Ok((free, reasons))
}

/// The best point of a fit's search and what it cost.
struct Found {
    params: Vec<f64>,
    evaluations: usize,
    sigma_pso: f64,
}

/// The swarm from `start_p`, then the local polish of the swarm's best and,
/// as a second start, of the user's start values; the better is kept (a
/// cheap guard against a swarm that settled in a neighbouring basin).
fn search(
    problem: &FitProblem,
    all_bounds: &[(f64, f64)],
    start_p: &[f64],
    settings: &FitSettings,
) -> Found {
    let bounds: Vec<(f64, f64)> = problem.free.iter().map(|&i| all_bounds[i]).collect();
    if bounds.is_empty() {
        // Every parameter held: nothing to search, the start is the fit.
        let (sigma_pso, _) = sigma_of(problem.channel, &problem.tyre(&[]), &problem.points);
        return Found {
            params: Vec::new(),
            evaluations: 1,
            sigma_pso,
        };
    }
    let r = settings
        .pso
        .minimize_from(|p| problem.cost(p), &bounds, &[start_p.to_vec()]);
    let (sigma_pso, _) = sigma_of(problem.channel, &problem.tyre(&r.best), &problem.points);
    let polish = |x: &[f64]| polish(problem, x, &bounds, settings.local);
    let mut found = Found {
        params: r.best.clone(),
        evaluations: r.evaluations,
        sigma_pso,
    };
    let mut best_cost = r.value;
    // From the start too (the swarm's best can lie in another basin),
    // unless the swarm left it the best: the same polish twice.
    let from_start = (r.best != start_p).then(|| polish(start_p)).flatten();
    for l in [polish(&r.best), from_start].into_iter().flatten() {
        found.evaluations += l.evaluations;
        if l.cost.is_finite() && l.cost < best_cost {
            best_cost = l.cost;
            found.params = l.params;
        }
    }
    found
}

/// The local polish of `problem` from `x` by `local` (`None`: no
/// polish), kept within `bounds` as [`within_box`] says.
fn polish(
    problem: &FitProblem,
    x: &[f64],
    bounds: &[(f64, f64)],
    local: LocalMethod,
) -> Option<LocalResult> {
    let l = match local {
        LocalMethod::LevenbergMarquardt => levenberg_marquardt(problem, x),
        LocalMethod::GaussNewton => GaussNewton::default().minimize(problem, x),
        LocalMethod::None => return None,
    };
    Some(within_box(problem, x, l, bounds))
}

/// The polish `l` from `x` when it stayed in the parameter box, or when
/// its tyre is valid and the data take each value past the box (a value
/// past a box that is narrower than the model, as PAC89's aligning `c4`,
/// reported as beyond its bound); else the same start polished within the
/// box (a projected Levenberg–Marquardt), widened for each value the data
/// do take past it, so that no value the model refuses is written (a GIM
/// `friction_decay` of −0.64, which no tyre file holds) and none is left
/// where the polish wandered along a direction the data do not see
/// (PAC89's `a0` of 0.0068 on the Hoosier file, traded against `a1` and
/// `a2` for a 0.01 % lower σ).
fn within_box(
    problem: &FitProblem,
    x: &[f64],
    l: LocalResult,
    bounds: &[(f64, f64)],
) -> LocalResult {
    let beyond: Vec<usize> = (0..l.params.len())
        .filter(|&i| !(bounds[i].0..=bounds[i].1).contains(&l.params[i]))
        .collect();
    if beyond.is_empty() {
        return l;
    }
    // A tyre the model or the tyre file refuses is polished within the
    // box as it is (a GIM contact length of 1.17 m, which the aligning
    // moment of a file with its `fy` in lbf asked for, lost the fit); so is
    // a fit to a sweep short of the peak (`reach.rs`).
    let t = problem.tyre(&l.params);
    let valid = t.validate().and_then(|()| t.check_sizes()).is_ok();
    let asked = if valid && !reach::short_of_peak(problem) {
        asked_past(problem, &l.params, &beyond, bounds)
    } else {
        Vec::new()
    };
    if asked.len() == beyond.len() {
        return l;
    }
    // Each value the data ask past its bound may go twice as far past it
    // as the polish took it; the rest keep the box.
    let mut widened = bounds.to_vec();
    for &i in &asked {
        let (v, (lo, hi)) = (l.params[i], bounds[i]);
        widened[i] = if v < lo {
            (2.0 * v - lo, hi)
        } else {
            (lo, 2.0 * v - hi)
        };
    }
    let mut boxed = BoundedLm::default().minimize(problem, x, &widened);
    boxed.evaluations += l.evaluations;
    boxed
}

/// The parameters `beyond` their bounds at `p` that lie past them by more
/// than twice their standard error, a standard error smaller than the
/// value: the data ask for them there. A singular Jacobian (the value one
/// of many that fit alike, its standard error NaN) or a wide standard
/// error says the polish drifted.
fn asked_past(
    problem: &FitProblem,
    p: &[f64],
    beyond: &[usize],
    bounds: &[(f64, f64)],
) -> Vec<usize> {
    let Some(cov) = covariance_at(problem, p) else {
        return Vec::new();
    };
    beyond
        .iter()
        .copied()
        .filter(|&i| {
            let se = cov[(i, i)].sqrt();
            let past = (p[i] - bounds[i].1).max(bounds[i].0 - p[i]);
            se.is_finite() && se < p[i].abs() && past > 2.0 * se
        })
        .collect()
}

#[cfg(test)]
mod tests;
