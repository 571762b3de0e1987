//! Fitting a [`Problem`]'s parameters by output error: a global stage
//! ([`global::global_search`]) that hands the polish a start in the optimum's basin,
//! polished by Levenberg–Marquardt within the bounds ([`fit`]). The parameters'
//! standard errors come from the Jacobian at the optimum,
//! `s²·(JᵀJ)⁻¹` with `s²` the residual variance, those pressed onto a
//! bound held there; the optimum's quadratic model of the residuals
//! ([`Linearisation`]: residuals, Jacobian and second derivatives) is what
//! the cross-validation's fold refits start from (`refit`). Model selection
//! by the Bayesian information criterion (Schwarz 1978) of a Gaussian error
//! model ([`FitOutcome::bic`]).

mod curvature;
pub(crate) mod fold_check;
#[cfg(test)]
mod fold_check_tests;
pub(crate) mod fold_noise;
pub(crate) mod global;
pub(crate) mod layout;
pub(crate) mod prior_rows;
pub(crate) mod problem;
pub(crate) mod refit;
#[cfg(test)]
mod std_error_tests;
pub(crate) mod tangent;
pub mod tempering;
#[cfg(test)]
mod unseen_tests;

use crate::diagnose::fit::curvature::curvature;
use crate::diagnose::fit::problem::Problem;
use crate::diagnose::model::Augmented;
use crate::optim::bounded::{BoundedLm, Jacobians};
use crate::optim::local::Residuals;
use crate::optim::stats::{sandwich_covariance, seen_columns, standard_errors};
use nalgebra::DMatrix;
use serde::Serialize;

/// How the global stage of a fit searched its parameters (reported with
/// each candidate: the grid is deterministic, the swarm seeded).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum GlobalSearch {
    /// Nothing to search: every parameter held, or the polish started from
    /// a nearby optimum.
    None,
    /// A grid of cell centres over the box, `points` replays of the runs
    /// (with the start's).
    Grid {
        /// Cells per searched parameter.
        per_parameter: usize,
        /// Replays made.
        points: usize,
    },
    /// The particle swarm, for a search along more parameters than a grid
    /// affords.
    Swarm {
        /// Replays made.
        evaluations: usize,
    },
}

/// The outcome of a fit.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FitOutcome {
    /// Parameters.
    pub params: Vec<f64>,
    /// Standard errors (NaN when not identifiable).
    pub std_errors: Vec<f64>,
    /// ½·Σ e² of the scaled data residuals (without a prior's rows).
    pub cost: f64,
    /// Number of residuals.
    pub residuals: usize,
    /// Replays of the whole run set made.
    pub evaluations: usize,
    /// Whether the polish stopped on its convergence test.
    pub converged: bool,
    /// How the global stage searched (set by the caller that ran it).
    pub global: GlobalSearch,
    /// Whether each parameter is held at its off value because no residual
    /// responds to it (an offset of a channel no run measures): reported as
    /// held, not counted in the BIC (empty: none held, as in a refit).
    #[serde(skip)]
    pub unseen: Vec<bool>,
    /// Parameters held at their off value because the free fit left them
    /// undetermined ([`to_hold`]): the standard error each had there
    /// (empty, or None: fitted). Counted in the BIC
    /// ([`FitOutcome::free_count`]).
    #[serde(skip)]
    pub held: Vec<Option<f64>>,
    /// The data residuals and their Jacobian at the optimum (fits polished
    /// to convergence): the fold refits start from them.
    #[serde(skip)]
    pub linear: Option<Linearisation>,
    /// The standard errors robust to residuals correlated over time
    /// ([`robust_covariance`]; empty where not linearised): the ones
    /// reported.
    pub robust_std_errors: Vec<f64>,
    /// Their covariance (None where not linearised): what a sum of two
    /// parameters that trade against each other is determined to.
    #[serde(skip)]
    pub robust_covariance: Option<DMatrix<f64>>,
}

/// Data residuals `r`, their Jacobian `J` and second derivatives of a
/// problem at a point, rows in the order of the problem's runs: a quadratic
/// model of every residual, `r(p + δ) ≈ r + J·δ + ½·δᵀ∇²r·δ`.
#[derive(Debug, Clone, PartialEq)]
pub struct Linearisation {
    /// Residuals.
    pub residuals: Vec<f64>,
    /// Jacobian (finite differences stepping into the box at a bound).
    pub jacobian: DMatrix<f64>,
    /// Second derivatives `∂²r/∂p_a∂p_b`, one column per pair `a ≤ b` in
    /// the order of [`pair_index`].
    pub curvature: DMatrix<f64>,
}

/// The column of the pair `(a, b)` of `n` parameters in
/// [`Linearisation::curvature`]: `(0,0), (0,1), …, (0,n−1), (1,1), …`.
pub fn pair_index(n: usize, a: usize, b: usize) -> usize {
    let (a, b) = if a <= b { (a, b) } else { (b, a) };
    a * n - a * (a + 1) / 2 + b
}

impl FitOutcome {
    /// The standard errors as reported: robust to residuals correlated
    /// over time where the fit was linearised ([`robust_covariance`]),
    /// else the Jacobian's. The rules that hold a parameter, call an
    /// effect idle or folds far keep the Jacobian's (their thresholds
    /// were set on them; the likelihood-ratio test of a hold checks them).
    pub fn reported_std_errors(&self) -> Vec<f64> {
        if self.robust_std_errors.len() == self.std_errors.len() {
            self.robust_std_errors.clone()
        } else {
            self.std_errors.clone()
        }
    }

    /// Bayesian information criterion of a Gaussian error model with the
    /// variance estimated: `N·ln(RSS/N) + k·ln N`, `k` the parameters the
    /// data see (one held because no residual responds to it costs
    /// nothing: it is no degree of freedom of the fit).
    pub fn bic(&self) -> f64 {
        let n = self.residuals.max(1) as f64;
        n * (2.0 * self.cost / n).max(1e-300).ln() + self.free_count() as f64 * n.ln()
    }

    /// The parameters the data see (all but the [`FitOutcome::unseen`]).
    /// One [`FitOutcome::held`] counts: it belongs to the effect's form,
    /// which these runs see but cannot resolve (a steer path whose lag
    /// the runs do not determine is no simpler hypothesis than a sensor
    /// delay); the BIC and the parsimony rule compare forms, and holding
    /// it only fixes what the report and the folds take for its value.
    pub fn free_count(&self) -> usize {
        self.params.len() - self.unseen.iter().filter(|&&u| u).count()
    }

    /// The standard error, fitted free, of parameter `i` where it is held
    /// because that fit left it undetermined ([`to_hold`]).
    pub fn held_for(&self, i: usize) -> Option<f64> {
        self.held.get(i).copied().flatten()
    }

    /// Whether parameter `i` is held because no residual responds to it.
    pub fn is_unseen(&self, i: usize) -> bool {
        self.unseen.get(i).copied().unwrap_or(false)
    }
}

/// Relative tolerance of the fits' cost and step. A fit's scaled cost is
/// half a chi-square of `m` residuals (thousands), whose noise alone moves
/// it by about `√(2/m)` relative, a percent or more: a step that lowers it
/// by less than 1e-6 of itself is four orders below what the data can
/// resolve, and no figure the diagnosis reports moves with it. The earlier
/// 1.5e-8 (a finite-difference Jacobian's √ε) spent fresh Jacobians on
/// changes of 1e-8–1e-9.
pub const FIT_TOLERANCE: f64 = 1e-6;

/// Iteration budget of a fit on all runs.
pub const FIT_ITERATIONS: usize = 100;

/// Iteration budget of a fold refit (it starts next to its optimum; a fold
/// that needs more is reported as not converged).
pub const REFIT_ITERATIONS: usize = 8;

/// A fold refit has converged when the next step of its model would lower
/// the training cost `C` of its `m` rows by at most `τ·C/m`, this `τ`: each
/// parameter is then within `√τ` ≈ 0.03 of its standard error of the
/// fold's optimum ([`refit`]'s doc), far below the standard error itself.
/// Against the `1e-4` before it (0.01 of a standard error): the 8-run
/// campaign's fold refits 67 → 49 replays, every reduction within 0.01
/// point (`tests/cli/trips_s91_perf.rs`); the 600 s sedan: see CHANGELOG.
pub(crate) const REFIT_SETTLED: f64 = 1e-3;

/// Whether a step predicted to lower the training cost `cost` of `rows`
/// residual rows by `predicted` leaves a fold refit's parameters settled
/// ([`REFIT_SETTLED`]): its model's steps ([`refit`]) and the
/// Levenberg–Marquardt that takes over from them stop by it.
pub(crate) fn settled(predicted: f64, cost: f64, rows: usize) -> bool {
    predicted <= REFIT_SETTLED * cost / rows.max(1) as f64
}

/// The local polish of a fit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Polish {
    /// Levenberg–Marquardt to convergence.
    LevenbergMarquardt,
    /// A refit from a nearby optimum (the cross-validation folds start from
    /// the all-run fit): Levenberg–Marquardt to convergence, without the
    /// standard errors.
    Refit,
}

/// Fits `problem` from `start` by the polish (the start comes from a
/// swarm, [`swarm`], or a nearby optimum). A parameter the data cannot
/// see is reported at its value in `off` (the effect off; `start` when
/// None), which fits as well. Standard errors are those of the parameters
/// inside their bounds: one the fit pressed onto a bound is held there
/// (NaN), as a constrained least-squares fit's active set is.
pub fn fit<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    start: &[f64],
    off: Option<&[f64]>,
    polish: Polish,
) -> FitOutcome {
    fit_with(problem, start, off, polish, true).0
}

/// [`fit`] by Levenberg–Marquardt whose linearisation leaves out the
/// second derivatives (`n·(n + 3)/2` replays that only the fold refits
/// read: a candidate screened out of its cross-validation never needs
/// them), with the point it was linearised at (None: no linearisation);
/// [`complete_curvature`] adds them there. The curvature left out has no
/// columns.
pub(crate) fn fit_first_order<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    start: &[f64],
    off: Option<&[f64]>,
) -> (FitOutcome, Option<Vec<f64>>) {
    fit_with(problem, start, off, Polish::LevenbergMarquardt, false)
}

/// The second derivatives of a linearisation `linear` of `problem` at `p`
/// that [`fit_first_order`] left out, as [`fit`] would have taken them,
/// but for the columns of the parameters marked in `unseen`
/// ([`FitOutcome::unseen`]), left zero: the fold refits hold those
/// parameters and zero their columns (`refit`), so their replays (a
/// combined slip's two unseen shares: 13 of its 27) bought nothing. The
/// columns of a parameter that only adds a constant to a channel are zero
/// too ([`unknown_curvature`]).
pub(crate) fn complete_curvature<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    p: &[f64],
    linear: &mut Linearisation,
    unseen: &[bool],
) {
    let skip = unknown_curvature(problem, p.len(), unseen);
    linear.curvature = curvature(problem, p, &linear.residuals, &skip);
}

/// The parameters of `problem` (`n` of them) whose second derivatives are
/// not taken: those marked in `skip`, and those that only add a constant
/// to a measured channel ([`Problem::additive`]: the lateral-acceleration
/// offset), whose residuals are affine in them with a slope nothing else
/// moves, so that every second derivative with them is zero (their second
/// differences were rounding: 9 of the 44 replays of the 600 s sedan's
/// `sensor_bias+accelerometer_position+steering_ratio`).
fn unknown_curvature<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    n: usize,
    skip: &[bool],
) -> Vec<bool> {
    (0..n)
        .map(|i| skip.get(i).copied().unwrap_or(false) || problem.additive(i))
        .collect()
}

/// [`fit`], the second derivatives of its linearisation taken when
/// `second` (else left empty), and the point it was linearised at.
fn fit_with<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    start: &[f64],
    off: Option<&[f64]>,
    polish: Polish,
    second: bool,
) -> (FitOutcome, Option<Vec<f64>>) {
    let p0 = problem.clamp(start);
    let (mut params, cost, converged, mut evaluations, last_jacobian) = if start.is_empty() {
        (Vec::new(), problem.cost(&[]), true, 0, None)
    } else {
        polished(problem, &p0, polish)
    };
    let at = (polish == Polish::LevenbergMarquardt && !params.is_empty()).then(|| params.clone());
    let mut outcome = FitOutcome {
        std_errors: vec![f64::NAN; params.len()],
        cost,
        residuals: problem.data_count(),
        evaluations: 0,
        converged,
        global: GlobalSearch::None,
        unseen: Vec::new(),
        held: Vec::new(),
        linear: None,
        robust_std_errors: Vec::new(),
        robust_covariance: None,
        params: Vec::new(),
    };
    if at.is_some() {
        // A parameter the data cannot see (an accelerometer offset of a
        // run set without ay) is wherever the swarm left it: report its
        // off value (the effect off), which fits as well.
        let off = problem.clamp(off.unwrap_or(start));
        evaluations += linearised(
            problem,
            &mut params,
            &off,
            (second, last_jacobian),
            &mut outcome,
        );
    }
    outcome.params = params;
    outcome.evaluations = evaluations + 1;
    (outcome, at)
}

/// The polish of `problem` from `p0` (clamped into the box): its
/// parameters, data cost, whether it converged, its replays, and its last
/// Jacobian where it was differenced at the optimum (the linearisation's
/// own: the same replays, the same numbers).
fn polished<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    p0: &[f64],
    polish: Polish,
) -> (Vec<f64>, f64, bool, usize, Option<DMatrix<f64>>) {
    // A refit starts next to its optimum: a bounded budget (a fold
    // that needs more is reported as not converged).
    let iterations = match polish {
        Polish::LevenbergMarquardt => FIT_ITERATIONS,
        Polish::Refit => REFIT_ITERATIONS,
    };
    // A fit's Jacobian costs a replay of the runs per parameter: an
    // accepted step updates it (Broyden) where its model still serves,
    // and the convergence test reads a fresh one. A refit keeps a
    // fresh one each iteration: its budget is a handful of them.
    let jacobians = match polish {
        Polish::LevenbergMarquardt => Jacobians::Secant,
        Polish::Refit => Jacobians::Every,
    };
    // A refit stops as its model's steps do ([`settled`]), an accepted
    // step's decrease at `τ/m` of the cost rather than FIT_TOLERANCE.
    let m = problem.count();
    let (tolerance, stop): (f64, &dyn Fn(f64, f64) -> bool) = match polish {
        Polish::LevenbergMarquardt => (FIT_TOLERANCE, &|_, _| false),
        Polish::Refit => (REFIT_SETTLED / m.max(1) as f64, &|p, c| settled(p, c, m)),
    };
    let (lm, jacobian) = BoundedLm {
        iterations,
        tolerance,
        jacobians,
    }
    .minimize_settled(problem, p0, &problem.bounds, stop);
    // The polish accepts only steps that lower the cost (and returns its
    // start when its cost is not finite): it ends no worse than it began.
    // The cost reported is the data's: the prior's rows regularise
    // the fit, they are no misfit of the runs.
    let data_cost = lm.cost - problem.prior_cost(&lm.params);
    (lm.params, data_cost, lm.converged, lm.evaluations, jacobian)
}

/// The linearisation of a polished fit at `params` (its second
/// derivatives when `second`, its Jacobian the polish's last where it has
/// one) and what comes of it in `out`: the unseen parameters (set to
/// their value in `off`), the standard errors (a parameter on a bound
/// held there), the robust ones and their covariance. Returns the replays
/// it made.
fn linearised<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    params: &mut [f64],
    off: &[f64],
    (second, last_jacobian): (bool, Option<DMatrix<f64>>),
    out: &mut FitOutcome,
) -> usize {
    let mut evaluations = 0;
    if last_jacobian.is_none() {
        evaluations += problem.jacobian_evaluations(params.len());
    }
    let linear = linearise_with(problem, params, second, last_jacobian);
    evaluations += 1;
    let (unseen, probes) = unseen_at(problem, params, &linear);
    evaluations += probes;
    for (i, &u) in unseen.iter().enumerate() {
        if u {
            params[i] = off[i];
        }
    }
    let mut free = linear.jacobian.clone();
    for (i, &b) in problem.bounds.iter().enumerate() {
        if crate::diagnose::effects::on_bound(params[i], b).is_some() {
            free.column_mut(i).fill(0.0);
        }
    }
    let covariance = robust_covariance(problem, &linear, &free);
    out.robust_std_errors = match &covariance {
        Some(v) => (0..params.len())
            .map(|i| {
                if v[(i, i)] >= 0.0 {
                    v[(i, i)].sqrt()
                } else {
                    f64::NAN
                }
            })
            .collect(),
        None => vec![f64::NAN; params.len()],
    };
    out.robust_covariance = covariance;
    out.std_errors = standard_errors(&free, 2.0 * out.cost);
    out.unseen = unseen;
    out.linear = Some(linear);
    evaluations
}

/// The step, as a share of a parameter's range, at which a parameter on a
/// bound whose Jacobian column there is zero is probed: 1 % of the range
/// is 1 cm of a relaxation length's 0–1 m, a lag the runs see.
const PROBE: f64 = 0.01;

/// The parameters no measured channel responds to at `p`: a zero column
/// of the Jacobian, except at a bound where a probe [`PROBE`] of the range
/// into the box changes the residuals. An effect that switches off at its
/// bound (a relaxation length below 1 mm is no lag) has a zero derivative
/// there though the runs see it one step inside: it is on its bound, not
/// unseen.
fn unseen_at<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    p: &[f64],
    linear: &Linearisation,
) -> (Vec<bool>, usize) {
    let j = &linear.jacobian;
    let mut probes = 0;
    let largest = j.column_iter().map(|c| c.norm()).fold(0.0, f64::max);
    let mut unseen: Vec<bool> = seen_columns(j).iter().map(|s| !s).collect();
    for (i, u) in unseen.iter_mut().enumerate() {
        let b = problem.bounds[i];
        let Some(upper) = (*u)
            .then(|| crate::diagnose::effects::on_bound(p[i], b))
            .flatten()
        else {
            continue;
        };
        let step = PROBE * (b.1 - b.0);
        let mut q = p.to_vec();
        q[i] += if upper { -step } else { step };
        let mut r = vec![0.0; linear.residuals.len()];
        problem.residuals(&q, &mut r);
        probes += 1;
        let change = r
            .iter()
            .zip(&linear.residuals)
            .map(|(a, b)| (a - b).powi(2))
            .sum::<f64>()
            .sqrt();
        // The seen test of [`seen_columns`], on the probe's difference
        // quotient; a step with no seen column at all is judged on its own.
        let quotient = change / step;
        *u = !(quotient.is_finite() && quotient > 1e-9 * largest.max(f64::MIN_POSITIVE));
    }
    (unseen, probes)
}

/// How far past its whole range a parameter's standard error must be for
/// it to be held: at 1 the free fit moves it across its whole box for
/// less than one standard deviation of the data, which is what "the runs
/// do not determine it" means in the report.
pub const UNDETERMINED: f64 = 1.0;

/// How much the held fit's `2·cost` may exceed the free fit's, in units of
/// the free fit's residual variance `s²`, for the hold to stand: a
/// likelihood-ratio test of one parameter at about 95 % (`χ²₁` = 3.84).
/// Past it the data reject the held value after all (the linear picture
/// that made the standard error large was wrong over the box), and the
/// parameter stays fitted.
pub const HOLD_REJECTED: f64 = 3.84;

/// The parameter of `f` (fitted within `bounds`) to hold next, if any:
/// among those from `from` on (the effect parameters, not the axles) that
/// are not already held, unseen or on a bound, whose standard error
/// exceeds [`UNDETERMINED`] times their range, the one whose value is the
/// fewest standard errors from its value in `off` (the cheapest to hold:
/// of a steer path's delay and lag, which the runs see only as their sum,
/// the lag at a few microseconds).
pub fn to_hold(f: &FitOutcome, bounds: &[(f64, f64)], off: &[f64], from: usize) -> Option<usize> {
    (from..f.params.len())
        .filter(|&i| !f.is_unseen(i) && f.held_for(i).is_none())
        .filter(|&i| {
            let (lo, hi) = bounds[i];
            let se = f.std_errors[i];
            crate::diagnose::effects::on_bound(f.params[i], bounds[i]).is_none()
                && se.is_finite()
                && se > UNDETERMINED * (hi - lo)
        })
        .min_by(|&a, &b| {
            let z = |i: usize| (f.params[i] - off[i]).abs() / f.std_errors[i];
            z(a).total_cmp(&z(b))
        })
}

/// Whether a fit holding one more parameter (`held`, its data cost) stands
/// against the `free` fit: its `2·cost` exceeds the free fit's by at most
/// [`HOLD_REJECTED`] residual variances of the free fit.
pub fn hold_stands(free: &FitOutcome, held: &FitOutcome) -> bool {
    let dof = free.residuals.saturating_sub(free.free_count()).max(1) as f64;
    let s2 = 2.0 * free.cost / dof;
    2.0 * (held.cost - free.cost) <= HOLD_REJECTED * s2
}

/// `bounds` with parameter `i` pinned at `value` (a box of no width: the
/// polish and the fold refits keep it there).
pub fn pinned(bounds: &[(f64, f64)], i: usize, value: f64) -> Vec<(f64, f64)> {
    let mut b = bounds.to_vec();
    b[i] = (value, value);
    b
}

/// The data residuals, their Jacobian and their second derivatives at `p`
/// (`1 + n + n·(n + 3)/2` replays of the runs, the second differences in
/// parallel).
#[cfg(test)]
pub(super) fn linearise<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    p: &[f64],
) -> Linearisation {
    linearise_with(problem, p, true, None)
}

/// The covariance of the fit linearised as `linear` (its Jacobian's
/// columns of parameters on a bound zeroed: `free`), robust to residuals
/// correlated over time (its diagonal the standard errors reported): the block sandwich
/// ([`sandwich_covariance`]) over blocks of each run's channel of
/// twice the residuals' integrated autocorrelation time (Sokal 1997;
/// [`tempering::Tempering`]), the prior's rows each a block of its own. A
/// misfit that lasts a manoeuvre carries the evidence of `N/τ` samples,
/// not of `N`: the Jacobian's standard errors, which count every sample
/// as independent, are optimistic (3 to 4.5 times against the jackknife
/// in `std_error_tests`, 23 times on the sedan analogue's axles).
fn robust_covariance<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    linear: &Linearisation,
    free: &DMatrix<f64>,
) -> Option<DMatrix<f64>> {
    let n = problem.data_count();
    let tau = problem
        .tempering_of(&linear.residuals[..n])
        .correlation_samples;
    let length = (2.0 * tau).ceil().max(1.0) as usize;
    let mut blocks = Vec::new();
    let mut start = 0;
    for len in problem.sequence_lengths() {
        let mut k = 0;
        while k < len {
            let end = (k + length).min(len);
            blocks.push(start + k..start + end);
            k = end;
        }
        start += len;
    }
    sandwich_covariance(free, &linear.residuals, &blocks)
}

/// [`linearise`], the second derivatives left out (no columns) unless
/// `second`, the Jacobian `known` where given (taken at `p` within the
/// problem's bounds: the polish's last).
fn linearise_with<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    p: &[f64],
    second: bool,
    known: Option<DMatrix<f64>>,
) -> Linearisation {
    // The optimum's replays are kept (the polish's accepted step): its
    // residuals cost no integration, and leave it the problem's last.
    let mut r = vec![0.0; problem.count()];
    problem.residuals(p, &mut r);
    let jacobian = known.unwrap_or_else(|| problem.jacobian(p, &r, &problem.bounds));
    let curvature = if second {
        curvature(problem, p, &r, &unknown_curvature(problem, p.len(), &[]))
    } else {
        DMatrix::zeros(r.len(), 0)
    };
    Linearisation {
        residuals: r,
        jacobian,
        curvature,
    }
}
