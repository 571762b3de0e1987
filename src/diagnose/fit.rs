//! Fitting model parameters (effect parameters, or axle tyre
//! characteristics) to measured runs by output error: every evaluation
//! replays the runs with the augmented model and compares what its sensors
//! would read with what was measured.
//!
//! The residual of channel c at a sample is `(simulated − measured)/s_c`,
//! with `s_c` the channel's scale (its noise floor, at least 2 % of its RMS
//! signal, so that a very quiet channel does not drown the others).
//! Residuals are taken at a fixed rate (default 25 Hz) rather than at every
//! sample: neighbouring samples of a 100 Hz log say nearly the same thing.
//! The search is the crate's PSO (the box of each parameter, one particle at
//! the start point, so the fit is never worse than the model it starts
//! from), polished by Levenberg–Marquardt; the parameters' standard errors
//! come from the Jacobian at the optimum, `s²·(JᵀJ)⁻¹`. Units: SI, rad.

use super::model::{Augmented, Drive, Observed};
use crate::io::MeasuredRun;
use crate::optim::local::{jacobian, levenberg_marquardt, levenberg_marquardt_within, Residuals};
use crate::optim::pso::Pso;
use serde::Serialize;

/// A measured channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Channel {
    /// Yaw rate, rad/s.
    YawRate,
    /// Lateral acceleration (accelerometer), m/s².
    Ay,
    /// Sideslip, rad.
    Beta,
}

impl Channel {
    /// All channels.
    pub const ALL: [Channel; 3] = [Channel::YawRate, Channel::Ay, Channel::Beta];
    /// Name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Channel::YawRate => "yaw_rate",
            Channel::Ay => "ay",
            Channel::Beta => "beta",
        }
    }
    /// Unit.
    pub fn unit(self) -> &'static str {
        match self {
            Channel::YawRate => "rad/s",
            Channel::Ay => "m/s²",
            Channel::Beta => "rad",
        }
    }
    /// Index in per-channel arrays.
    pub fn index(self) -> usize {
        self as usize
    }
    /// The channel of a run, if measured.
    pub fn of(self, run: &MeasuredRun) -> Option<&[f64]> {
        match self {
            Channel::YawRate => Some(&run.yaw_rate),
            Channel::Ay => run.ay.as_deref(),
            Channel::Beta => run.beta.as_deref(),
        }
    }
}

/// A run made ready for repeated replays.
#[derive(Debug, Clone)]
pub struct Prepared {
    /// Name (the file).
    pub name: String,
    /// Its inputs on the replay grid.
    pub drive: Drive,
    /// Times at which residuals are taken, s.
    pub times: Vec<f64>,
    /// Measured channels at those times.
    pub measured: Vec<(Channel, Vec<f64>)>,
    /// Initial sideslip (measured, else 0) and yaw rate.
    pub start: (f64, f64),
}

impl Prepared {
    /// Prepares `run` for replays with RK4 step `step` and residuals taken
    /// at `rate` Hz (at the samples nearest to it).
    /// Masked samples (logger glitches in a response channel) are skipped:
    /// the next unmasked sample takes their place.
    pub fn new(run: &MeasuredRun, step: f64, rate: f64) -> Self {
        let mut masked = vec![false; run.t.len()];
        for &i in &run.masked {
            masked[i] = true;
        }
        let first = (0..run.t.len()).find(|&i| !masked[i]).unwrap_or(0);
        let mut idx = vec![first];
        for (i, (&t, &m)) in run.t.iter().zip(&masked).enumerate().skip(first + 1) {
            if !m && t - run.t[*idx.last().unwrap()] >= 1.0 / rate - 1e-9 {
                idx.push(i);
            }
        }
        let times: Vec<f64> = idx.iter().map(|&i| run.t[i]).collect();
        let measured = Channel::ALL
            .into_iter()
            .filter_map(|c| c.of(run).map(|v| (c, idx.iter().map(|&i| v[i]).collect())))
            .collect();
        Self {
            name: run.path.display().to_string(),
            drive: Drive::replay(&run.t, &run.steer, &run.speed, step),
            times,
            measured,
            start: (
                run.beta.as_ref().map_or(0.0, |b| b[first]),
                run.yaw_rate[first],
            ),
        }
    }

    /// Number of residuals of this run.
    pub fn count(&self) -> usize {
        self.measured.iter().map(|(_, v)| v.len()).sum()
    }

    /// Replays the run with `model` from its first measured state (less the
    /// model's sensor offsets) and returns what the sensors would read at
    /// the residual times.
    pub fn observe(&self, model: &Augmented) -> Observed {
        let sensors = &model.effects.sensors;
        let x0 = model.initial_state(
            &self.drive,
            self.start.0 - sensors.beta_bias,
            self.start.1 - sensors.yaw_rate_bias,
        );
        model.observe(&model.simulate(&self.drive, x0), &self.times)
    }

    /// Replays the run with `model` and writes the scaled residuals into
    /// `out` (length [`Prepared::count`]).
    pub fn residuals(&self, model: &Augmented, scales: &[f64; 3], out: &mut [f64]) {
        let obs = self.observe(model);
        let mut k = 0;
        for (c, m) in &self.measured {
            let sim = match c {
                Channel::YawRate => &obs.yaw_rate,
                Channel::Ay => &obs.ay,
                Channel::Beta => &obs.beta,
            };
            let s = scales[c.index()];
            for (y, x) in sim.iter().zip(m) {
                // A diverged replay is a very bad fit, not a NaN for LM.
                out[k] = if y.is_finite() { (y - x) / s } else { 1e6 };
                k += 1;
            }
        }
    }

    /// Sum of squared unscaled residuals and sample count per channel.
    pub fn errors(&self, model: &Augmented) -> ChannelErrors {
        let mut r = vec![0.0; self.count()];
        self.residuals(model, &[1.0; 3], &mut r);
        let mut e = ChannelErrors::default();
        let mut k = 0;
        for (c, v) in &self.measured {
            for _ in 0..v.len() {
                e.sum_sq[c.index()] += r[k] * r[k];
                e.count[c.index()] += 1;
                k += 1;
            }
        }
        e
    }
}

/// Squared residuals and counts per channel, to be pooled over runs.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ChannelErrors {
    /// Σ e² per channel (units²).
    pub sum_sq: [f64; 3],
    /// Samples per channel.
    pub count: [usize; 3],
}

impl ChannelErrors {
    /// Adds another run's errors.
    pub fn add(&mut self, o: &ChannelErrors) {
        for c in 0..3 {
            self.sum_sq[c] += o.sum_sq[c];
            self.count[c] += o.count[c];
        }
    }
    /// RMS of a channel (None when not measured).
    pub fn rms(&self, c: Channel) -> Option<f64> {
        let i = c.index();
        (self.count[i] > 0).then(|| (self.sum_sq[i] / self.count[i] as f64).sqrt())
    }
    /// The combined error `J = sqrt(Σ_c n_c·(rms_c/s_c)² / Σ n_c)`.
    pub fn combined(&self, scales: &[f64; 3]) -> f64 {
        let n: usize = self.count.iter().sum();
        let s: f64 = (0..3)
            .map(|c| self.sum_sq[c] / (scales[c] * scales[c]))
            .sum();
        (s / n.max(1) as f64).sqrt()
    }
}

/// Output-error least squares over a set of runs: `build` turns the
/// parameter vector into the model to replay.
pub struct Problem<'a, F: Fn(&[f64]) -> Augmented + Sync> {
    /// The model of a parameter vector.
    pub build: F,
    /// The runs.
    pub runs: Vec<&'a Prepared>,
    /// Channel scales.
    pub scales: [f64; 3],
    /// Parameter bounds: parameters are clamped into them.
    pub bounds: Vec<(f64, f64)>,
}

impl<F: Fn(&[f64]) -> Augmented + Sync> Problem<'_, F> {
    fn clamp(&self, p: &[f64]) -> Vec<f64> {
        p.iter()
            .zip(&self.bounds)
            .map(|(x, (lo, hi))| x.clamp(*lo, *hi))
            .collect()
    }
}

/// Weight of the bound residuals: a step one thousandth of a parameter's
/// range outside its box costs as much as one scaled data residual of 1.
const BOUND_PENALTY: f64 = 1e3;

impl<F: Fn(&[f64]) -> Augmented + Sync> Problem<'_, F> {
    /// Residuals of the data (without the bound residuals).
    pub fn data_count(&self) -> usize {
        self.runs.iter().map(|r| r.count()).sum()
    }
}

impl<F: Fn(&[f64]) -> Augmented + Sync> Residuals for Problem<'_, F> {
    /// The data residuals, then one residual per parameter that is zero
    /// inside its bounds and grows outside: the model sees clamped
    /// parameters, and without these a least-squares step toward an optimum
    /// on a bound would meet a flat cost beyond it and shrink its trust
    /// region hundreds of times instead of stopping there.
    fn count(&self) -> usize {
        self.data_count() + self.bounds.len()
    }
    fn residuals(&self, p: &[f64], out: &mut [f64]) {
        let q = self.clamp(p);
        let model = (self.build)(&q);
        let mut k = 0;
        for r in &self.runs {
            let n = r.count();
            r.residuals(&model, &self.scales, &mut out[k..k + n]);
            k += n;
        }
        for ((x, c), (lo, hi)) in p.iter().zip(&q).zip(&self.bounds) {
            out[k] = BOUND_PENALTY * (x - c) / (hi - lo).max(1e-300);
            k += 1;
        }
    }
}

/// The outcome of a fit.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FitOutcome {
    /// Parameters.
    pub params: Vec<f64>,
    /// Standard errors (NaN when not identifiable).
    pub std_errors: Vec<f64>,
    /// ½·Σ e² of the scaled residuals.
    pub cost: f64,
    /// Number of residuals.
    pub residuals: usize,
    /// Replays of the whole run set made.
    pub evaluations: usize,
    /// Whether the polish stopped on its convergence test.
    pub converged: bool,
}

impl FitOutcome {
    /// Bayesian information criterion of a Gaussian error model with the
    /// variance estimated: `N·ln(RSS/N) + k·ln N`.
    pub fn bic(&self) -> f64 {
        let n = self.residuals.max(1) as f64;
        n * (2.0 * self.cost / n).max(1e-300).ln() + self.params.len() as f64 * n.ln()
    }
}

/// Evaluation budget of a fold refit, in units of n + 1 residual
/// evaluations (about one LM iteration each).
pub const REFIT_PATIENCE: usize = 8;

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

/// Fits `problem` from `start`: PSO over the bounds (when `pso` is given;
/// `(swarm, held)` holds the first `held` parameters at their start values
/// during the swarm search — the axle characteristics, which the polish
/// then frees) then the polish.
pub fn fit<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    start: &[f64],
    pso: Option<(&Pso, usize)>,
    polish: Polish,
) -> FitOutcome {
    let mut evaluations = 0;
    let mut p0 = problem.clamp(start);
    if let Some((pso, held)) = pso.filter(|(_, held)| start.len() > *held) {
        let full = |q: &[f64]| {
            let mut p = p0[..held].to_vec();
            p.extend_from_slice(q);
            p
        };
        let r = pso.minimize_from(
            |q| problem.cost(&full(q)),
            &problem.bounds[held..],
            &[p0[held..].to_vec()],
        );
        evaluations += r.evaluations;
        p0 = full(&r.best);
    }
    let (params, cost, converged) = if start.is_empty() {
        (Vec::new(), problem.cost(&[]), true)
    } else {
        // A refit starts next to its optimum: a bounded budget (a fold
        // that needs more is reported as not converged).
        let lm = match polish {
            Polish::LevenbergMarquardt => levenberg_marquardt(problem, &p0),
            Polish::Refit => levenberg_marquardt_within(problem, &p0, REFIT_PATIENCE),
        };
        evaluations += lm.evaluations;
        // LM may leave the box, where the residuals are clamped.
        let p = problem.clamp(&lm.params);
        let c = problem.cost(&p);
        let c0 = problem.cost(&p0);
        if c <= c0 {
            (p, c, lm.converged)
        } else {
            (p0, c0, lm.converged)
        }
    };
    let std_errors = match polish {
        Polish::LevenbergMarquardt => standard_errors(problem, &params, cost),
        Polish::Refit => vec![f64::NAN; params.len()],
    };
    FitOutcome {
        params,
        std_errors,
        cost,
        residuals: problem.data_count(),
        evaluations: evaluations + 1,
        converged,
    }
}

fn standard_errors<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    p: &[f64],
    cost: f64,
) -> Vec<f64> {
    let k = p.len();
    if k == 0 {
        return Vec::new();
    }
    let n = problem.count();
    let mut r = vec![0.0; n];
    problem.residuals(p, &mut r);
    let j = jacobian(problem, p, &r);
    let s2 = 2.0 * cost / (n.saturating_sub(k)).max(1) as f64;
    // A parameter the data cannot see (an ay offset without an ay channel,
    // a parameter pinned at its bound) has a zero column: it gets NaN and
    // the others are computed without it.
    let norms: Vec<f64> = (0..k).map(|c| j.column(c).norm()).collect();
    let largest = norms.iter().copied().fold(0.0, f64::max);
    let seen: Vec<usize> = (0..k).filter(|&c| norms[c] > 1e-9 * largest).collect();
    let mut out = vec![f64::NAN; k];
    if seen.is_empty() {
        return out;
    }
    let js = j.select_columns(seen.iter());
    if let Some(inv) = (js.transpose() * &js).try_inverse() {
        for (i, &c) in seen.iter().enumerate() {
            let v = s2 * inv[(i, i)];
            if v.is_finite() && v >= 0.0 {
                out[c] = v.sqrt();
            }
        }
    }
    out
}
