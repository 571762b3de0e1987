//! Parameters of a swarm fit the data do not determine, held at a stated
//! value rather than left where the optimiser wandered: the rule of the
//! staged Magic Formula fit (`mf_staged/holds.rs`) for the swarm fit of
//! one channel (lateral force, aligning moment, longitudinal force).
//!
//! After the channel's fit (swarm and polish), a free parameter is *not
//! determined* when its standard error (`cov = s²·(JᵀJ)⁻¹` at the optimum)
//! reaches its magnitude and one standard error, alone, moves the channel
//! by at least 1 % of its RMS over the points (`‖J_k‖·se/‖F‖ ≥ 0.01`, the
//! √n of both RMS cancelling), or when it has no standard error (the
//! Jacobian is singular along it); not one on its search bound, which
//! the data press against (its warning says so). Of the parameters so
//! flagged, the four
//! with the largest relative standard error are tried: each held at its
//! stated value with the rest refitted from the optimum (the configured
//! local polish, Levenberg–Marquardt for `--local none`: no new swarm),
//! and the hold that raises the cost least is kept, unless it raises the
//! cost past the guard of `spare.rs` (twice the residual variance), when
//! the parameter is left free with its warning; this repeats until no
//! free parameter is flagged or left to try. Holds whose costs differ by less than half
//! a residual variance (the data cannot tell them apart) go to the one
//! with the largest relative standard error, the least determined: the
//! staged fit gives them to the coefficient latest in its stage's order,
//! which for the Magic Formula is a secondary term, but the swarm models'
//! orders do not rank their terms so (PAC89's `a1`, a load variation,
//! comes before `a2`, the friction).
//!
//! The stated value is the start tyre's, the model's own start values at
//! the data's median load (`start_tyre_of`; the swarm route has no
//! template), with a value given with `--hold` or by PAC89's curvature
//! rule set there already and so never free here. Two parameters that
//! trade along one near-null direction thus lose the one the fit can best
//! spare, and the other is determined again. A held line says the value
//! held, the stated value and how many standard errors that lay from the
//! free fit (`spare.rs`, [`HeldFor`]'s words).
//!
//! The trying and choosing of holds is the staged fit's own code
//! (`spare.rs`); this module builds the channel's problems and refits.

use super::determined::{Determination, Partner, STRONG_CORRELATION};
use super::parameters::{parameter_reports, EFFECT_FLOOR};
use super::spare::{self, candidates, held_value, standard_errors_away, LEAN_STANDARD_ERRORS};
use super::spare::{HoldFit, HoldWays, Spared, TieBreak};
use super::{curves_of, polish, sigma_of, Fit, FitProblem, FitSettings, HeldFor};
use super::{data::Condition, LocalMethod};
use crate::error::{Error, OptionsError};
use crate::optim::bounded::BoundedLm;
use crate::optim::local::{LocalResult, Residuals};
use crate::optim::stats;
use crate::tyre::{Identification, ModelName, Tyre};
use nalgebra::DMatrix;
use std::time::Instant;

/// How well the points determine a problem's free parameters at a point.
pub(super) struct Spread {
    /// Their covariance (NaN where the Jacobian is singular).
    pub(super) covariance: Option<DMatrix<f64>>,
    /// One standard error's effect, alone, as a fraction of the measured
    /// values' norm (NaN without a standard error).
    pub(super) effect: Vec<f64>,
    /// The Gauss–Newton step of each free parameter alone, the others
    /// held (`−Jₖ·e/‖Jₖ‖²`, 0 where the data do not see it): where the
    /// data pull a value on a bound.
    pub(super) pull: Vec<f64>,
}

impl Spread {
    /// The spread of `problem`'s free parameters at `p`.
    pub(super) fn at(problem: &FitProblem, p: &[f64]) -> Self {
        let mut res = vec![0.0; problem.count()];
        problem.residuals(p, &mut res);
        let unbounded = vec![(f64::NEG_INFINITY, f64::INFINITY); p.len()];
        // One Jacobian for both (the aligning and longitudinal blocks
        // difference theirs): as `covariance_at` takes it.
        let j = problem.jacobian(p, &res, &unbounded);
        let sum_squares: f64 = res.iter().map(|e| e * e).sum();
        let covariance = (!p.is_empty())
            .then(|| stats::covariance(&j, sum_squares))
            .flatten();
        let y = problem.measured_norm().max(f64::MIN_POSITIVE);
        let effect = (0..p.len())
            .map(|k| {
                let se = covariance.as_ref().map_or(f64::NAN, |c| c[(k, k)].sqrt());
                j.column(k).norm() * se / y
            })
            .collect();
        let pull = (0..p.len())
            .map(|k| {
                let (g, h) = res
                    .iter()
                    .zip(j.column(k).iter())
                    .fold((0.0, 0.0), |(g, h), (e, d)| (g + e * d, h + d * d));
                if h > 0.0 {
                    -g / h
                } else {
                    0.0
                }
            })
            .collect();
        Self {
            covariance,
            effect,
            pull,
        }
    }

    /// The standard error of free parameter `k` (`None`: none).
    fn std_error(&self, k: usize) -> Option<f64> {
        let c = self.covariance.as_ref()?;
        // NaN (singular along it) stays none: `NaN.max(0)` would be 0.
        Some(c[(k, k)])
            .filter(|v| v.is_finite())
            .map(|v| v.max(0.0).sqrt())
    }

    /// Whether free parameter `k` at `value` is not determined (module
    /// notes).
    pub(super) fn flagged(&self, k: usize, value: f64) -> bool {
        match self.std_error(k) {
            None => true,
            Some(se) => se >= value.abs() && self.effect[k] >= EFFECT_FLOOR,
        }
    }

    /// The change of every free parameter that best keeps the fit when
    /// `k` moves by `dv`: to first order the others' regression on it,
    /// `Σ_jk/Σ_kk·dv`; only `dv` where the covariance does not say.
    fn compensating(&self, k: usize, dv: f64) -> Vec<f64> {
        let n = self.effect.len();
        let mut d = vec![0.0; n];
        d[k] = dv;
        if let (Some(c), Some(_)) = (&self.covariance, self.std_error(k)) {
            for (j, dj) in d.iter_mut().enumerate() {
                let shift = c[(j, k)] / c[(k, k)] * dv;
                if j != k && shift.is_finite() {
                    *dj = shift;
                }
            }
        }
        d
    }
}

/// `fit` with the parameters the data do not determine held at `start`'s
/// values and the rest refitted (module notes), its report redone; `fit`
/// as it is when none is flagged. `conditions` are the fit's.
///
/// A fit with a parameter more left free can never end worse than the
/// same fit with it held, as the free set includes the held point: where
/// the held fit beats the free one (UniTire's aligning moment with `c3`
/// held, σ 0.9808 % against 0.9855 % free under `--local none`, whose
/// free fit is the swarm's best unpolished), the free fit stopped short.
/// It is then polished again from the held fit's optimum, and the holds
/// are judged anew from that better free optimum (at most
/// [`RESTARTS`] times); the report keeps the swarm start's σ beside
/// (`free_swarm_sigma_percent`), so the held σ is never below the free.
pub(crate) fn hold_undetermined(
    fit: Fit,
    start: &Tyre,
    conditions: &[Condition],
    settings: &FitSettings,
) -> Fit {
    let mut free = fit;
    let mut swarm_sigma = None;
    for round in 1..=RESTARTS {
        let held = held_from(free.clone(), start, conditions, settings);
        let beaten = held.free_sigma_percent.is_some() && held.sigma_percent < free.sigma_percent;
        let again = beaten
            .then(|| restarted(&held, &free, start, conditions, settings))
            .filter(|again| again.sigma_percent < free.sigma_percent);
        let Some(again) = again else {
            return Fit {
                free_swarm_sigma_percent: swarm_sigma,
                ..held
            };
        };
        swarm_sigma.get_or_insert(free.sigma_percent);
        if round == RESTARTS {
            // The holds stay those judged last; the free σ is the
            // restart's, which began at the held optimum.
            return Fit {
                free_sigma_percent: Some(again.sigma_percent),
                free_swarm_sigma_percent: swarm_sigma,
                ..held
            };
        }
        free = again;
    }
    unreachable!("the last round returns")
}

/// How many times the free fit is restarted from a held fit that beat it.
const RESTARTS: usize = 3;

/// The free fit `free` polished again from the optimum of `held` (the
/// same parameters free as in `free`), its report built as the first
/// fit's: the configured polish, Levenberg–Marquardt for `--local none`,
/// as the holds' refits are.
fn restarted(
    held: &Fit,
    free: &Fit,
    start: &Tyre,
    conditions: &[Condition],
    settings: &FitSettings,
) -> Fit {
    let t0 = Instant::now();
    let channel = free.channel;
    let mask: Vec<bool> = free.parameters.iter().map(|p| p.free).collect();
    let problem = FitProblem::for_channel(&held.tyre, channel, &mask, conditions)
        .with_derivatives(settings.derivatives);
    let all = channel.parameters(&held.tyre);
    let x: Vec<f64> = problem.free.iter().map(|&i| all[i]).collect();
    let all_bounds = channel.bounds(start);
    let bounds: Vec<(f64, f64)> = problem.free.iter().map(|&i| all_bounds[i]).collect();
    let l = refit(&problem, &x, &bounds, settings.local);
    let tyre = problem.tyre(&l.params).canonical();
    Fit {
        evaluations: held.evaluations + l.evaluations,
        seconds: held.seconds + t0.elapsed().as_secs_f64(),
        ..super::parameters::fit_carrying_holds(tyre, start, &problem, conditions, free)
    }
}

/// [`hold_undetermined`]'s one pass: the holds judged from the free fit
/// `fit` and the rest refitted.
fn held_from(fit: Fit, start: &Tyre, conditions: &[Condition], settings: &FitSettings) -> Fit {
    let t0 = Instant::now();
    let rounds = hold_rounds(&fit, start, conditions, settings);
    if rounds.held.is_empty() {
        return refusals_said(fit, &rounds.tried_at);
    }
    let HoldRounds {
        problem,
        p,
        free,
        held,
        tried_at,
        evaluations,
    } = rounds;
    let channel = fit.channel;
    let tyre = problem.tyre(&p).canonical();
    let all = channel.parameters(&tyre);
    let p: Vec<f64> = problem.free.iter().map(|&i| all[i]).collect();
    let spread = Spread::at(&problem, &p);
    let mut parameters = parameter_reports(start, &tyre, channel, &free, &spread);
    for (new, old) in parameters.iter_mut().zip(&fit.parameters) {
        if !old.free {
            new.held = old.held;
            new.warning.clone_from(&old.warning);
        }
    }
    for (i, why) in held {
        parameters[i].held = Some(why);
    }
    let (s, rms) = sigma_of(channel, &tyre, &problem.points);
    let fit = Fit {
        curves: curves_of(channel, &tyre, conditions),
        parameters,
        free_sigma_percent: Some(fit.sigma_percent),
        sigma_percent: s,
        rms,
        evaluations: fit.evaluations + evaluations,
        seconds: fit.seconds + t0.elapsed().as_secs_f64(),
        covariance: spread.covariance,
        tyre,
        ..fit
    };
    refusals_said(fit, &tried_at)
}

/// Where [`hold_rounds`] ends: the problem and its free values with the
/// holds made, which parameters (full index) are free, those held and
/// why, those whose hold the guard refused with the value tried, and the
/// evaluations spent.
struct HoldRounds {
    problem: FitProblem,
    p: Vec<f64>,
    free: Vec<bool>,
    held: Vec<(usize, HeldFor)>,
    tried_at: Vec<Tried>,
    evaluations: usize,
}

/// A hold the guard refused: the parameter (full index), the value tried,
/// and whether that lay within the free fit's ±2 linearised standard
/// errors then (its stated value within them, or their edge nearest it),
/// so that the refusal shows the data fix it beyond that linearisation
/// (`determined.rs`).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Tried {
    i: usize,
    value: f64,
    within: bool,
}

/// The rounds of holds from the free fit `fit`: each round holds the
/// parameter the data determine least (`spare`) at its stated value (the
/// start's) and refits the rest, until none is left to hold.
fn hold_rounds(
    fit: &Fit,
    start: &Tyre,
    conditions: &[Condition],
    settings: &FitSettings,
) -> HoldRounds {
    let channel = fit.channel;
    let mut free: Vec<bool> = fit.parameters.iter().map(|p| p.free).collect();
    let mut problem = FitProblem::for_channel(&fit.tyre, channel, &free, conditions)
        .with_derivatives(settings.derivatives);
    let now = channel.parameters(&fit.tyre);
    let mut p: Vec<f64> = problem.free.iter().map(|&i| now[i]).collect();
    let stated = channel.parameters(start);
    let bounds = channel.bounds(start);
    let mut held: Vec<(usize, HeldFor)> = Vec::new();
    // Parameters (full index) whose hold the guard refused, with the
    // value tried: left free, with their warning, and not tried again at
    // that value (`spare.rs`). A later round, with others held, may narrow
    // a parameter's interval and so try it nearer its free value (UniTire's
    // aligning `c9` on the Hoosier file: refused at its start value 0.0708,
    // 63 standard errors off once the rest were held, where its ±2 edge
    // 0.00244 costs less than the free fit's holds).
    let mut refused: Vec<(usize, f64)> = Vec::new();
    // With the value each was tried at, for its warning.
    let mut tried_at: Vec<Tried> = Vec::new();
    let mut evaluations = 0;
    while p.len() > 1 {
        let spread = Spread::at(&problem, &p);
        if spread.covariance.is_none() {
            break;
        }
        let values = Stated {
            values: &stated,
            bounds: &bounds,
            refused: &refused,
        };
        let round = spare(&problem, &p, &spread, &values, settings.local);
        evaluations += round.evaluations;
        let now_refused = tried_values(&round.refused, (&problem, &p), &spread, &values);
        tried_at.extend(&now_refused);
        refused.extend(now_refused.iter().map(|t| (t.i, t.value)));
        let Some(t) = round.kept else {
            if round.refused.is_empty() {
                break;
            }
            continue;
        };
        let i = problem.free[t.k];
        let se = spread.std_error(t.k);
        held.push((
            i,
            HeldFor::Undetermined {
                fitted: p[t.k],
                std_error: se,
                effect_percent: se.map(|_| 100.0 * spread.effect[t.k]),
                stated: stated[i],
                held_at: t.value,
                standard_errors_away: standard_errors_away(stated[i], p[t.k], se),
            },
        ));
        free[i] = false;
        problem = t.problem;
        p = t.p;
    }
    HoldRounds {
        problem,
        p,
        free,
        held,
        tried_at,
        evaluations,
    }
}

/// The parameters (free indices `refused`) whose hold the guard refused
/// this round, each by its full index with the value it was tried at
/// ([`held_value`]: its stated value, or the edge of its ±2 standard
/// errors nearest it) and whether that lay within them.
fn tried_values(
    refused: &[usize],
    (problem, p): (&FitProblem, &[f64]),
    spread: &Spread,
    stated: &Stated,
) -> Vec<Tried> {
    refused
        .iter()
        .map(|&k| {
            let i = problem.free[k];
            let se = spread.std_error(k);
            let value = held_value(stated.values[i], p[k], se, stated.bounds[i]);
            let z = standard_errors_away(stated.values[i], p[k], se);
            let within = match z {
                Some(z) => value != stated.values[i] || z <= LEAN_STANDARD_ERRORS,
                None => false,
            };
            Tried { i, value, within }
        })
        .collect()
}

/// `fit` with the warning of each parameter (full index) whose hold the
/// guard refused (`tried_at`, with the value tried) saying so: flagged as
/// not determined, it met the rule, and a bare "not identified" would
/// leave the reader asking why it was not held. The refit behind the
/// refusal starts at the free optimum (no new swarm), so the words give
/// the `--hold` that fits the rest from a new one (UniTire's aligning
/// `c9` on the Hoosier file at 83.4 kPa and 0°: refused, σ 9.733 %; with
/// `--hold aligning.c9=0`, 9.685 %).
fn refusals_said(mut fit: Fit, tried_at: &[Tried]) -> Fit {
    // Each parameter's last refusal: the value the data allowed last.
    let mut said = Vec::new();
    for t in tried_at.iter().rev() {
        if said.contains(&t.i) {
            continue;
        }
        said.push(t.i);
        let fixed = fixed_beyond(&fit, t);
        let p = &mut fit.parameters[t.i];
        let (true, Some(w)) = (p.free, p.warning.as_mut()) else {
            continue;
        };
        let v = crate::format::readable(t.value, 4);
        let refusal = format!(
            "held at {v} with the rest refitted from this fit's optimum, it raised the channel's σ past what the rule lets a hold cost (5 % of itself, or 2.25 standard errors' worth), so it is left free: --hold {}={v} (or a value of your own) fits the rest from a new swarm instead",
            p.name
        );
        // Refused within its ±2: the words (and the type) the staged fit
        // gives such a coefficient replace "not identified" (one
        // function, `Determination::said`).
        match fixed.as_ref().and_then(|d| d.said(p.std_error)) {
            Some(head) => *w = format!("{head}; {refusal}"),
            None => w.push_str(&format!("; {refusal}")),
        }
        if fixed.is_some() {
            p.determination = fixed;
        }
    }
    fit
}

/// The determination of a parameter of `fit` whose hold `t` was refused
/// within its ±2 linearised standard errors, still flagged with a
/// standard error and off its search bound: fixed beyond its
/// linearisation, with the free parameter it trades with (`|r| ≥`
/// [`STRONG_CORRELATION`] by the fit's covariance). `None` otherwise.
fn fixed_beyond(fit: &Fit, t: &Tried) -> Option<Determination> {
    let p = &fit.parameters[t.i];
    let effect_percent = p.effect_percent.filter(|_| p.std_error.is_some())?;
    let off_bound = !super::parameters::on_search_bound(p.value, p.bounds);
    (t.within && p.free && p.warning.is_some() && off_bound).then(|| {
        let free: Vec<usize> = (0..fit.parameters.len())
            .filter(|&j| fit.parameters[j].free)
            .collect();
        let k = free.iter().position(|&j| j == t.i);
        let partner = fit.covariance.as_ref().zip(k).and_then(|(c, k)| {
            (0..free.len())
                .filter(|&j| j != k && c[(j, j)] > 0.0 && c[(k, k)] > 0.0)
                .map(|j| (j, c[(j, k)] / (c[(j, j)] * c[(k, k)]).sqrt()))
                .filter(|(_, r)| r.is_finite() && r.abs() >= STRONG_CORRELATION)
                .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        });
        Determination::FixedBeyondLinearisation {
            effect_percent,
            partner: partner.map(|(j, correlation)| Partner {
                name: fit.parameters[free[j]].name.clone(),
                correlation,
                on_bound: None,
            }),
        }
    })
}

/// What the holds of a channel start from: the stated `values` and the
/// search `bounds` of its full vector, and the parameters (full index)
/// whose hold the guard refused.
struct Stated<'a> {
    values: &'a [f64],
    bounds: &'a [(f64, f64)],
    refused: &'a [(usize, f64)],
}

/// The flagged parameter of `problem` at `p` whose hold (at the value
/// `spare.rs` gives from its stated one) the fit can best spare, with the
/// rest refitted within their bounds, and the holds the guard refused
/// (module notes; the rule's core is `spare.rs`).
fn spare(
    problem: &FitProblem,
    p: &[f64],
    spread: &Spread,
    stated: &Stated,
    local: LocalMethod,
) -> Spared<FitProblem> {
    let relative = |k: usize| {
        spread
            .std_error(k)
            .map_or(f64::INFINITY, |s| s / p[k].abs().max(f64::MIN_POSITIVE))
    };
    // A value on its search bound is where the box stopped the data, not
    // where they leave it free: its standard error means nothing there,
    // and its warning says so (`parameters.rs`).
    let on_bound = |k: usize| {
        let (lo, hi) = stated.bounds[problem.free[k]];
        p[k] < lo || p[k] > hi || super::parameters::on_search_bound(p[k], (lo, hi))
    };
    let flagged: Vec<usize> = (0..p.len())
        .filter(|&k| spread.flagged(k, p[k]) && !on_bound(k))
        .filter(|&k| {
            // Refused at the value it would be tried at now: not again.
            let i = problem.free[k];
            let now = held_value(
                stated.values[i],
                p[k],
                spread.std_error(k),
                stated.bounds[i],
            );
            !stated.refused.contains(&(i, now))
        })
        .collect();
    let free_bounds: Vec<(f64, f64)> = problem.free.iter().map(|&i| stated.bounds[i]).collect();
    let std_errors: Vec<Option<f64>> = (0..p.len()).map(|k| spread.std_error(k)).collect();
    let fit = HoldFit {
        problem,
        p,
        std_errors: &std_errors,
        bounds: &free_bounds,
        clamp_starts: false,
        tie: TieBreak::LeastDetermined,
        guarded: true,
        stated_first: false,
    };
    let ways = HoldWays {
        without: |k: usize, value: f64| problem.holding(p, k, value),
        stated: |k: usize| stated.values[problem.free[k]],
        compensating: |k: usize, dv: f64| spread.compensating(k, dv),
        refit: |sub: &FitProblem, x: &[f64], b: &[(f64, f64)]| refit(sub, x, b, local),
    };
    spare::spare(&fit, &candidates(flagged, relative), &ways)
}

/// The refit of `problem` from `x` within `bounds`: the fit's own polish,
/// or Levenberg–Marquardt within the box where the fit has none (a hold
/// with the rest left where they traded against it is no fit).
fn refit(
    problem: &FitProblem,
    x: &[f64],
    bounds: &[(f64, f64)],
    local: LocalMethod,
) -> LocalResult {
    polish(problem, x, bounds, local)
        .unwrap_or_else(|| BoundedLm::default().minimize(problem, x, bounds))
}

/// The start tyre of a fit of `model` to data whose median load is `fz`
/// (each model's own, [`ModelName::start_tyre`]): the lateral parameters
/// only, so that no borrowed aligning or longitudinal coefficients are
/// written. A model without a swarm fit is refused with what fits it.
pub(crate) fn start_tyre_of(model: ModelName, fz: f64) -> Result<Tyre, Error> {
    model.start_tyre(fz).ok_or_else(|| {
        Error::Options(match model.identification() {
            Identification::Staged(fits) => OptionsError::StagedFitOnly {
                model: model.to_string(),
                fits: fits.iter().map(|f| f.name).collect(),
            },
            _ => OptionsError::NotIdentified {
                model: model.to_string(),
            },
        })
    })
}

#[cfg(test)]
#[path = "undetermined_tests.rs"]
mod tests;
