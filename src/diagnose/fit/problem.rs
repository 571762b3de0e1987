//! The output-error problem of a fit ([`Problem`]): model parameters
//! (effect parameters, or axle tyre characteristics) in, the scaled
//! residuals of every run's replay out. Each evaluation replays the runs
//! with the augmented model the parameters build and compares what its
//! sensors would read with what was measured. What the parameters set is
//! the problem's `build` (a [`Layout`]'s model of the vector, or the axle
//! tyres alone); with exact derivatives the problem also holds that layout
//! and the base model's effects it applies to.
//!
//! The residual of channel c at a sample is `(simulated − measured)/s_c`,
//! with `s_c` the channel's scale (its noise floor, at least 2 % of its RMS
//! signal, so that a very quiet channel does not drown the others). The
//! cost is `½·Σ r²` over every run and channel. Where the axle
//! characteristics are fitted, their prior's rows follow the data's
//! ([`Problem::with_prior`], [`PriorRows`]): the fit is regularised, and
//! [`Problem::prior_cost`] is what the rows add to the cost. Parameters are
//! clamped into their box. Units: SI, rad.

use crate::diagnose::fit::layout::Layout;
use crate::diagnose::fit::prior_rows::PriorRows;
use crate::diagnose::fit::tempering::Tempering;
use crate::diagnose::model::channels::ChannelErrors;
use crate::diagnose::model::replay::{Prepared, ReplayCache, SharedReplays};
use crate::diagnose::model::Augmented;
use crate::optim::local::{inward_jacobian, Derivatives, Residuals};
use crate::vehicle::Effects;
use nalgebra::DMatrix;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

/// Output-error least squares over a set of runs: `build` turns the
/// parameter vector into the model to replay. Each run's last replay is
/// kept ([`Problem::new`]), and one more on request
/// ([`Residuals::keep_last`]: a search's best, the polish's accepted
/// steps): a search over sensor parameters integrates the runs once, and
/// an evaluation repeated at such a point (the polish starting where the
/// search ended, the optimum's linearisation and errors) costs no
/// integration. Memory: two histories per run.
pub struct Problem<'a, F: Fn(&[f64]) -> Augmented + Sync> {
    /// The model of a parameter vector.
    pub build: F,
    /// The runs.
    pub runs: Vec<&'a Prepared>,
    /// Channel scales.
    pub scales: [f64; 3],
    /// Parameter bounds: parameters are clamped into them.
    pub bounds: Vec<(f64, f64)>,
    /// The last replay of each run, and one kept.
    last: Vec<ReplayCache>,
    /// Each run's cost at the last evaluation that replayed them all: an
    /// evaluation that may stop early replays the costliest first.
    run_costs: Mutex<Vec<f64>>,
    /// What the parameters set and the base model's effects they are set
    /// on, when the problem has exact derivatives ([`Problem::with_layout`]).
    layout: Option<(Layout, Effects)>,
    /// Whether each parameter only adds a constant to a measured channel
    /// ([`Layout::additive`]; empty: none known): its second derivatives
    /// are zero, and [`Problem::additive`] tells the second differences.
    additive: Vec<bool>,
    /// The prior's rows on the axle characteristics, after the data's.
    prior: Option<PriorRows>,
    /// Replays shared with the diagnosis's other problems on all runs
    /// ([`Problem::with_shared`]).
    shared: Option<&'a SharedReplays>,
    /// Rows of history the problem's replays have integrated, stopped
    /// ones included ([`Problem::integrated_rows`]).
    integrated: AtomicUsize,
}

impl<'a, F: Fn(&[f64]) -> Augmented + Sync> Problem<'a, F> {
    /// The problem of fitting `build`'s parameters within `bounds` to `runs`
    /// with channel scales `scales`.
    pub fn new(
        build: F,
        runs: Vec<&'a Prepared>,
        scales: [f64; 3],
        bounds: Vec<(f64, f64)>,
    ) -> Self {
        let last = runs.iter().map(|_| ReplayCache::default()).collect();
        let run_costs = Mutex::new(vec![0.0; runs.len()]);
        Self {
            build,
            runs,
            scales,
            bounds,
            last,
            run_costs,
            layout: None,
            additive: Vec::new(),
            prior: None,
            shared: None,
            integrated: AtomicUsize::new(0),
        }
    }

    /// Rows of history the problem's replays have integrated so far,
    /// stopped ones included (cached replays read cost none).
    #[cfg(test)]
    pub(crate) fn integrated_rows(&self) -> usize {
        self.integrated.load(Ordering::Relaxed)
    }

    /// The same problem reading and sharing replays in `shared`, whose
    /// slots are the campaign's runs in order: the problem's runs must be
    /// all of them, in that order (a fit on all runs).
    pub(crate) fn with_shared(mut self, shared: &'a SharedReplays) -> Self {
        self.shared = Some(shared);
        self
    }

    /// Shares the last replay of every run with the diagnosis's other
    /// problems on all runs (nothing without [`Problem::with_shared`]).
    pub(crate) fn share_last(&self) {
        if let Some(shared) = self.shared {
            shared.share(&self.last);
        }
    }

    /// The same problem with the prior's rows `prior` after the data's
    /// residuals (none for `None`).
    pub fn with_prior(mut self, prior: Option<PriorRows>) -> Self {
        self.prior = prior;
        self
    }

    /// The prior's rows appended to the data residuals (0 without a prior).
    pub fn prior_count(&self) -> usize {
        self.prior.map_or(0, |_| PriorRows::ROWS)
    }

    /// What the prior's rows add to the cost at `p`, `½·Σ r²`.
    pub fn prior_cost(&self, p: &[f64]) -> f64 {
        self.prior.map_or(0.0, |rows| {
            let mut r = [0.0; PriorRows::ROWS];
            rows.write(&self.clamp(p), &mut r);
            0.5 * r.iter().map(|e| e * e).sum::<f64>()
        })
    }

    /// The friction share an axle grid starts from: a held friction's, else
    /// `free`.
    pub fn grid_friction(&self, free: f64) -> f64 {
        self.prior.map_or(free, |rows| rows.grid_friction(free))
    }

    /// The same problem with exact derivatives when `derivatives` asks
    /// for them and the model has a generic form (the axle
    /// characteristics fitted, or tyres with a generic force; else forward
    /// differences): `layout` says what the parameters set on `base` (as
    /// `build` sets them), and the Jacobian comes from one replay of each
    /// run in dual numbers ([`crate::diagnose::fit::tangent`]) instead of
    /// one per parameter. Either way the layout marks the parameters that
    /// only add a constant to a channel ([`Problem::additive`]).
    pub fn with_layout(
        mut self,
        layout: Layout,
        base: &Augmented,
        derivatives: Derivatives,
    ) -> Self {
        // What a parameter sets is known whatever the derivatives.
        self.additive = layout.additive();
        let m = &base.model;
        let generic = layout.axle
            || (m.front.lateral_parameters().is_some() && m.rear.lateral_parameters().is_some());
        if derivatives == Derivatives::Exact && generic {
            self.layout = Some((layout, *base.effects()));
        }
        self
    }

    /// Whether parameter `i` only adds a constant to a measured channel
    /// ([`Problem::with_layout`]; false without a layout).
    pub(crate) fn additive(&self, i: usize) -> bool {
        self.additive.get(i).copied().unwrap_or(false)
    }

    /// Whether the Jacobian is exact ([`Problem::with_layout`]).
    fn exact(&self) -> bool {
        self.layout.is_some()
    }

    pub(crate) fn clamp(&self, p: &[f64]) -> Vec<f64> {
        p.iter()
            .zip(&self.bounds)
            .map(|(x, (lo, hi))| x.clamp(*lo, *hi))
            .collect()
    }

    /// Number of data residuals.
    pub fn data_count(&self) -> usize {
        self.runs.iter().map(|r| r.count()).sum()
    }

    /// How the data residuals at `p` weigh against a prior: their mean
    /// square and correlation time over every run's channels.
    pub fn tempering(&self, p: &[f64]) -> Tempering {
        let mut r = vec![0.0; self.data_count()];
        self.data_residuals(&self.clamp(p), &mut r);
        self.tempering_of(&r)
    }

    /// How the data residuals `r` (laid out as [`Problem::data_residuals`]
    /// writes them) weigh against a prior.
    pub fn tempering_of(&self, r: &[f64]) -> Tempering {
        Tempering::of_residuals(r, &self.sequence_lengths())
    }

    /// The lengths of the data residuals' sequences, in their order: each
    /// run's channel, in time order.
    pub fn sequence_lengths(&self) -> Vec<usize> {
        self.runs
            .iter()
            .flat_map(|run| run.measured.iter().map(|(_, v)| v.len()))
            .collect()
    }
}

impl<F: Fn(&[f64]) -> Augmented + Sync> Residuals for Problem<'_, F> {
    /// The data residuals of the parameters clamped into their bounds (the
    /// polish, [`BoundedLm`](crate::optim::bounded::BoundedLm), stays
    /// inside them).
    fn count(&self) -> usize {
        self.data_count() + self.prior_count()
    }
    fn residuals(&self, p: &[f64], out: &mut [f64]) {
        let q = self.clamp(p);
        let (data, prior) = out.split_at_mut(self.data_count());
        self.data_residuals(&q, data);
        if let Some(rows) = &self.prior {
            rows.write(&q, prior);
        }
    }
    /// Exact (one dual replay of each run) with a layout whose tyres have
    /// a generic force, else forward differences into the box.
    fn jacobian(&self, p: &[f64], r0: &[f64], bounds: &[(f64, f64)]) -> DMatrix<f64> {
        if let Some((layout, base)) = &self.layout {
            let q = self.clamp(p);
            // The plain model of `q`, built once through `build` (whose
            // callers count and time-stamp their evaluations: the dual
            // replay is one evaluation in the fits' work reports).
            let plain = (self.build)(&q);
            if let Some(j) = crate::diagnose::fit::tangent::jacobian(
                (layout, base, &plain),
                &self.runs,
                &self.scales,
                &q,
            ) {
                return match &self.prior {
                    Some(rows) => {
                        let n = q.len();
                        let mut all = j.resize_vertically(self.count(), 0.0);
                        let tail = rows.jacobian(&q, n);
                        all.rows_mut(self.data_count(), PriorRows::ROWS)
                            .copy_from(&tail);
                        all
                    }
                    None => j,
                };
            }
        }
        inward_jacobian(self, p, r0, bounds)
    }
    /// One replay (in dual numbers) when exact.
    fn jacobian_evaluations(&self, n: usize) -> usize {
        if self.exact() {
            1
        } else {
            n
        }
    }
    /// The runs replayed costliest first, stopping once the cost of those
    /// replayed (and of the prior's rows) shows the whole is at or above
    /// `bound`: most of a search's points and many rejected trial steps
    /// need only a few of the runs.
    fn residuals_below(&self, p: &[f64], out: &mut [f64], bound: f64) -> bool {
        let q = self.clamp(p);
        let (data, prior) = out.split_at_mut(self.data_count());
        let mut floor = 0.0;
        if let Some(rows) = &self.prior {
            rows.write(&q, prior);
            floor = 0.5 * prior.iter().map(|e| e * e).sum::<f64>();
        }
        self.data_residuals_below(&q, data, floor, bound)
    }
    fn keep_last(&self) {
        for c in &self.last {
            c.keep_last();
        }
    }
}

/// How far above a bound the cost of the runs replayed so far must be for
/// an evaluation to stop ([`Problem::residuals_below`]): those costs are
/// sums of squares, so the whole cost is at least theirs, up to the
/// rounding of sums taken in another order (below 1e-9 relative for a
/// billion residuals); this margin is far above it, so a stop never
/// decides otherwise than the whole cost would.
const STOP_MARGIN: f64 = 1e-6;

impl<F: Fn(&[f64]) -> Augmented + Sync> Problem<'_, F> {
    /// The data residuals at `q` (inside the bounds), the runs replayed in
    /// parallel: the steps of a fit (Levenberg–Marquardt's trials, a fold
    /// refit's model steps) follow one another, and a slow candidate's
    /// would otherwise leave a core idle once the others are done.
    fn data_residuals(&self, q: &[f64], out: &mut [f64]) {
        let complete = self.data_residuals_below(q, out, 0.0, f64::INFINITY);
        debug_assert!(complete);
    }

    /// The data residuals at `q` (inside the bounds) into `out`, unless the
    /// runs replayed so far show that the cost, with `floor` (the prior
    /// rows' share), is at or above `bound` (false; `out` partly written).
    /// The runs are taken costliest first (as the last complete evaluation
    /// found them) from a queue shared by the pool's threads, so that a
    /// stop comes after as few replays as it can; the residuals written are
    /// the same whichever thread writes them. Under a finite bound a replay
    /// is also scored while it runs ([`Prepared::residuals_watched`]): the
    /// residuals it has settled count with the other runs' at every chunk,
    /// and every thread stops once they show the bound passed.
    fn data_residuals_below(&self, q: &[f64], out: &mut [f64], floor: f64, bound: f64) -> bool {
        use rayon::prelude::*;
        let model = (self.build)(q);
        let mut pieces = Vec::with_capacity(self.runs.len());
        let mut rest = out;
        for r in &self.runs {
            let (piece, tail) = rest.split_at_mut(r.count());
            pieces.push(Mutex::new(piece));
            rest = tail;
        }
        let order = self.costliest_first();
        // A bound that is not finite stops nothing (NaN compares false):
        // not even a cost that overflows.
        let limit = if bound.is_finite() {
            bound + bound.abs() * STOP_MARGIN
        } else {
            f64::NAN
        };
        let next = AtomicUsize::new(0);
        let spent = Spent {
            stopped: AtomicBool::new(false),
            limit,
            costs: Mutex::new((
                floor,
                vec![0.0; self.runs.len()],
                vec![0.0; self.runs.len()],
            )),
        };
        let work = |_| loop {
            let k = next.fetch_add(1, Ordering::Relaxed);
            if k >= order.len() || spent.stopped.load(Ordering::Relaxed) {
                break;
            }
            let i = order[k];
            let mut piece = pieces[i].lock().unwrap_or_else(|e| e.into_inner());
            if !self.run_residuals(&model, i, &mut piece, &spent) {
                break;
            }
        };
        let workers = rayon::current_num_threads().clamp(1, order.len().max(1));
        (0..workers).into_par_iter().for_each(work);
        if spent.stopped.into_inner() {
            return false;
        }
        let (_, costs, _) = spent.costs.into_inner().unwrap_or_else(|e| e.into_inner());
        *self.run_costs.lock().unwrap_or_else(|e| e.into_inner()) = costs;
        true
    }

    /// Run `i`'s residuals at `model` into `out`, its replay watched under
    /// a finite limit: false where it, or another run's, stopped the
    /// evaluation.
    fn run_residuals(&self, model: &Augmented, i: usize, out: &mut [f64], spent: &Spent) -> bool {
        let (run, cache) = (self.runs[i], &self.last[i]);
        let caches = (cache, self.shared.map(|s| (s, i)));
        let mut watch = |partial: f64| spent.add(i, partial, false);
        let watch: Option<&mut dyn FnMut(f64) -> bool> = if spent.limit.is_nan() {
            None
        } else {
            Some(&mut watch)
        };
        let done = run.residuals_watched(model, caches, &self.scales, out, watch);
        self.integrated.fetch_add(done.rows, Ordering::Relaxed);
        done.complete && spent.add(i, 0.5 * out.iter().map(|e| e * e).sum::<f64>(), true)
    }

    /// The runs' indices, the costliest at the last complete evaluation
    /// first (run order among equals).
    fn costliest_first(&self) -> Vec<usize> {
        let costs = self
            .run_costs
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone();
        let mut order: Vec<usize> = (0..costs.len()).collect();
        order.sort_by(|&a, &b| costs[b].total_cmp(&costs[a]));
        order
    }

    /// Sum of squared unscaled residuals and sample count per channel of
    /// every run at `p` (clamped), through the runs' cached replays: the
    /// errors of an optimum the fit has just replayed cost no integration.
    pub(crate) fn errors(&self, p: &[f64]) -> ChannelErrors {
        let model = (self.build)(&self.clamp(p));
        let mut e = ChannelErrors::default();
        for (i, (r, cache)) in self.runs.iter().zip(&self.last).enumerate() {
            let shared = self.shared.map(|s| (s, i));
            e.add(&r.errors_of(&r.observe_reusing(&model, cache, shared)));
        }
        e
    }
}

/// What an evaluation's runs have cost so far ([`Problem::residuals_below`]),
/// shared by the threads that replay them.
struct Spent {
    /// Set once the costs shown pass the limit: every thread stops.
    stopped: AtomicBool,
    /// The bound with its margin (NaN: none).
    limit: f64,
    /// The prior rows' cost and the runs replayed whole; each run's cost
    /// whole; the cost of the residuals a replay still running has settled.
    costs: Mutex<(f64, Vec<f64>, Vec<f64>)>,
}

impl Spent {
    /// Counts `cost` for run `i` (its whole cost where `whole`, else what
    /// its running replay has settled); false once the evaluation stops.
    fn add(&self, i: usize, cost: f64, whole: bool) -> bool {
        if self.stopped.load(Ordering::Relaxed) {
            return false;
        }
        let mut s = self.costs.lock().unwrap_or_else(|e| e.into_inner());
        if whole {
            s.0 += cost;
            s.1[i] = cost;
            s.2[i] = 0.0;
        } else {
            s.2[i] = cost;
        }
        if s.0 + s.2.iter().sum::<f64>() >= self.limit {
            self.stopped.store(true, Ordering::Relaxed);
            return false;
        }
        true
    }
}

#[cfg(test)]
#[path = "problem_tests.rs"]
mod tests;
