//! Scoring a candidate: its fit on all runs and its errors on held-out
//! runs, each fold refitted from the all-run optimum; the held-out gap
//! above noise `G = sqrt(J² − J_n²)` and an effect's reduction of it.
//! The folds: run i in fold i mod k, with k the number of runs up to
//! [`MAX_FOLDS`] (leave-one-run-out for up to that many runs). A
//! candidate's model of a vector is its [`Setting`]'s layout applied to the
//! base model of all runs or of the fold
//! ([`crate::diagnose::fit::layout::Layout::model`]).

use crate::diagnose::base::identify::axle_grid_best;
use crate::diagnose::base::prior::PriorRows;
use crate::diagnose::base::Bases;
use crate::diagnose::campaign::Campaign;
use crate::diagnose::effects::EffectKind;
use crate::diagnose::fit::fold_noise::{fold_noise_factors, held_rows};
use crate::diagnose::fit::global::global_best;
use crate::diagnose::fit::problem::Problem;
use crate::diagnose::fit::refit::{refit, training_rows};
use crate::diagnose::fit::{
    complete_curvature, fit_first_order, hold_stands, pinned, to_hold, FitOutcome, GlobalSearch,
};
use crate::diagnose::model::channels::ChannelErrors;
use crate::diagnose::model::replay::{Prepared, SharedReplays};
use crate::diagnose::model::{Augmented, Observed};
use crate::diagnose::report::CalibrationSource;
use crate::diagnose::timing::{record_split, Phase, Recorder, Stamps};
use crate::diagnose::verdict::candidate::Setting;
use crate::optim::local::{Derivatives, Residuals};
use crate::optim::pso::{Inertia, Pso, Stall};
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

mod base_folds;

/// Largest number of folds.
pub const MAX_FOLDS: usize = 8;

/// Everything scored for one candidate.
#[derive(Clone)]
pub(crate) struct Scored {
    pub(crate) kinds: Vec<EffectKind>,
    pub(crate) full: FitOutcome,
    /// Errors of the all-run fit on all runs.
    pub(crate) insample: ChannelErrors,
    pub(crate) heldout: ChannelErrors,
    pub(crate) fold_params: Vec<Vec<f64>>,
    /// Per parameter, how many standard errors the fold refits' jackknife
    /// reaches by the runs' noise alone and its degrees of freedom
    /// ([`fold_noise_factors`]; NaN where not fitted; empty where not
    /// cross-validated).
    pub(crate) fold_noise: Vec<(f64, f64)>,
    pub(crate) fold_converged: Vec<bool>,
    /// What the prior's rows were multiplied by in its fits (axles from
    /// the runs; [`crate::diagnose::fit::tempering`]).
    pub(crate) prior_weight: Option<f64>,
}

pub(crate) struct Context<'a> {
    pub(crate) runs: Vec<Prepared>,
    pub(crate) folds: Vec<Vec<usize>>,
    pub(crate) scales: [f64; 3],
    pub(crate) bases: &'a Bases,
    pub(crate) pso: Pso,
    pub(crate) progress: Option<&'a AtomicUsize>,
    /// Where the time goes, when the diagnosis is timed.
    pub(crate) timing: Option<&'a Recorder>,
    /// How the fits take their Jacobians.
    pub(crate) derivatives: Derivatives,
    /// The sensor offsets the runs' standstills and straights measured: a
    /// start of the sensor offsets' fit.
    pub(crate) calibrated: Calibrated,
    /// Replays the fits on all runs share: the base model's, each
    /// candidate's optimum and each global stage's best
    /// ([`SharedReplays`]).
    pub(crate) shared: SharedReplays,
}

/// Each response channel's offset measured on the runs' standstills (else
/// straights), with its standard error ([`crate::measured::calibration`]),
/// and the logged bank the standstills' `ay` was read through, its mean
/// there in rad (None: no bank column, or not `ay` on standstills).
pub(crate) type Calibrated = [Option<(f64, f64, CalibrationSource, Option<f64>)>; 3];

/// A candidate whose global stage is done ([`Context::started`]), its
/// polish not yet: the setting, the polish's start, how it was searched.
pub(crate) struct Started<'a> {
    pub(crate) setting: Setting<'a>,
    pub(crate) start: Vec<f64>,
    pub(crate) global: GlobalSearch,
}

/// A candidate fitted on all runs, not yet cross-validated: its
/// setting, its fit (with the optimum's linearisation the fold refits
/// start from) and its errors on all runs.
pub(crate) struct Fitted<'a> {
    setting: Setting<'a>,
    pub(crate) full: FitOutcome,
    pub(crate) insample: ChannelErrors,
    /// The prior's rows as this candidate's fit weighed them (its folds
    /// weigh them alike).
    prior: Option<PriorRows>,
    /// Where `full` was linearised, its second derivatives not yet taken
    /// (only a cross-validation reads them: [`Context::cross_validate`]
    /// takes them there, as the fit would have).
    linearised_at: Option<Vec<f64>>,
    /// The box it was fitted in: the setting's, pinned at the off value
    /// where a parameter is held ([`Context::hold_undetermined`]); its
    /// folds are refitted in the same.
    bounds: Vec<(f64, f64)>,
}

impl Fitted<'_> {
    /// The candidate as scored without its folds: no held-out errors (a
    /// screened candidate, whose all-run fit the greedy additions use).
    pub(crate) fn unscored(&self) -> Scored {
        Scored {
            kinds: self.setting.layout.kinds.clone(),
            full: FitOutcome {
                linear: None,
                ..self.full.clone()
            },
            insample: self.insample,
            heldout: ChannelErrors::default(),
            fold_params: Vec::new(),
            fold_noise: Vec::new(),
            fold_converged: Vec::new(),
            prior_weight: self.prior.map(|r| r.weight()),
        }
    }
}

impl<'a> Context<'a> {
    pub(crate) fn tick(&self) {
        if let Some(p) = self.progress {
            p.fetch_add(1, Ordering::Relaxed);
        }
    }

    /// The parameter vector of `kinds` switched off (axle characteristics
    /// and roll dynamics at the base's).
    pub(crate) fn off(&self, kinds: &[EffectKind]) -> Vec<f64> {
        Setting::new(self.bases, kinds.to_vec()).off()
    }

    pub(crate) fn training(&self, fold: usize) -> Vec<&Prepared> {
        (0..self.runs.len())
            .filter(|i| !self.folds[fold].contains(i))
            .map(|i| &self.runs[i])
            .collect()
    }

    /// Fits a candidate on all runs ([`Context::fit_all`]) and scores it on
    /// every fold ([`Context::cross_validate`]).
    pub(crate) fn score(&self, kinds: Vec<EffectKind>, starts: &[Vec<f64>], salt: u64) -> Scored {
        self.cross_validate(&self.fit_all(kinds, starts, salt))
    }

    /// Fits a candidate on all runs (a grid or a swarm from `start`, then
    /// Levenberg–Marquardt) and scores the fit on them. A combination
    /// comes with `starts` (its members' single fits, the set it extends
    /// with the added effect off, the added effect's own axles): the global
    /// stage then starts from the best of them, and the polish from the lowest
    /// cost found ([`Context::start`]).
    pub(crate) fn fit_all(
        &self,
        kinds: Vec<EffectKind>,
        starts: &[Vec<f64>],
        salt: u64,
    ) -> Fitted<'a> {
        self.polish(self.started(kinds, starts, salt))
    }

    /// A candidate's global stage ([`Context::start`]) from `starts`, its
    /// swarm seeded by `salt`: where its polish ([`Context::polish`]) and a
    /// restricted fit (`crate::diagnose::verdict::restricted`) start.
    pub(crate) fn started(
        &self,
        kinds: Vec<EffectKind>,
        starts: &[Vec<f64>],
        salt: u64,
    ) -> Started<'a> {
        let s = Setting::new(self.bases, kinds);
        let stamps = self.timing.map(|_| Stamps::default());
        let t0 = Instant::now();
        let problem = self.all_runs(&s, stamps.as_ref(), self.bases.prior, s.bounds());
        let pso = Pso {
            seed: self.pso.seed ^ salt.wrapping_mul(0x9E37_79B9_7F4A_7C15),
            ..self.pso
        };
        let (start, global) = self.start(&problem, &s, starts, &pso);
        // The polish (or restricted fit) starts there on a problem of its
        // own: the start's replay is shared, not integrated again (the
        // global stage kept it where it was its best, else it is replayed
        // here, as the polish would).
        problem.cost(&start);
        problem.share_last();
        drop(problem);
        if let (Some(rec), Some(st)) = (self.timing, &stamps) {
            rec.add(Phase::CandidateSearch, t0.elapsed(), st.count());
        }
        Started {
            setting: s,
            start,
            global,
        }
    }

    /// The polish of a candidate whose global stage is done (`started`):
    /// Levenberg–Marquardt on all runs, undetermined parameters held, and
    /// its errors on all runs.
    pub(crate) fn polish(&self, started: Started<'a>) -> Fitted<'a> {
        let Started {
            setting: s,
            start,
            global,
        } = started;
        let stamps = self.timing.map(|_| Stamps::default());
        let problem = self.all_runs(&s, stamps.as_ref(), self.bases.prior, s.bounds());
        let mark = (Instant::now(), 0);
        // The prior weighed against the evidence the runs carry about this
        // candidate (`crate::diagnose::fit::tempering`): its residuals at the
        // global stage's best, so that a candidate that leaves white noise
        // fits as if untempered and one that leaves a correlated misfit
        // cannot buy a small gain by leaving the prior's range.
        let prior = self
            .bases
            .prior
            .map(|rows| rows.tempered(problem.tempering(&start).prior_weight));
        let problem = problem.with_prior(prior);
        let free = fit_first_order(&problem, &start, Some(&s.off()));
        let (full, linearised_at, bounds) =
            self.hold_undetermined(&s, prior, stamps.as_ref(), free);
        let full = FitOutcome { global, ..full };
        if let (Some(rec), Some(st)) = (self.timing, &stamps) {
            let phases = [
                Phase::CandidatePolish,
                Phase::CandidateJacobian,
                Phase::CandidateCurvature,
            ];
            let n = full.params.len();
            let jacobian = 1 + problem.jacobian_evaluations(n);
            let linear = if full.linear.is_some() { jacobian } else { 0 };
            record_split(rec, st, mark, (linear, 0), phases);
        }
        // The optimum was just replayed (its linearisation's residuals):
        // its errors come from the problem's kept replays, which are
        // shared: the sets that extend this candidate start from it.
        let insample = problem.errors(&full.params);
        problem.share_last();
        drop(problem);
        self.tick();
        Fitted {
            setting: s,
            full,
            insample,
            prior,
            linearised_at,
            bounds,
        }
    }

    /// A fit `free` of setting `s` (on all runs, with the prior's rows
    /// `prior`) with each effect parameter it leaves undetermined held at
    /// its off value, one at a time ([`to_hold`]: the cheapest first, the
    /// rest refitted), for as long as the data do not reject the held
    /// value ([`hold_stands`]). Engineers identifying a real log hold what
    /// it cannot show rather than report where an optimiser wandered, and
    /// the folds refit the rest around it instead of wandering off along
    /// it. The held parameter still counts in the candidate's BIC and
    /// parsimony ([`FitOutcome::free_count`]), so the choice between
    /// effects is that of their forms. Returns the fit, where it was
    /// linearised, and its box (pinned where held).
    fn hold_undetermined(
        &self,
        s: &Setting,
        prior: Option<PriorRows>,
        stamps: Option<&Stamps>,
        free: (FitOutcome, Option<Vec<f64>>),
    ) -> (FitOutcome, Option<Vec<f64>>, Vec<(f64, f64)>) {
        let (mut full, mut at) = free;
        let mut bounds = s.bounds();
        let off = s.off();
        let from = s.layout.effects().start;
        while let Some(i) = to_hold(&full, &bounds, &off, from) {
            let box_held = pinned(&bounds, i, off[i]);
            let problem = self.all_runs(s, stamps, prior, box_held.clone());
            let mut start = full.params.clone();
            start[i] = off[i];
            let (mut held, held_at) = fit_first_order(&problem, &start, Some(&off));
            if !held.converged || !hold_stands(&full, &held) {
                break;
            }
            let mut marks = full.held.clone();
            marks.resize(full.params.len(), None);
            marks[i] = Some(full.std_errors[i]);
            // A pinned parameter's difference column is zero: it is held
            // because the free fit could not place it, not unseen.
            for (u, m) in held.unseen.iter_mut().zip(&marks) {
                *u &= m.is_none();
            }
            held.held = marks;
            (full, at, bounds) = (held, held_at, box_held);
        }
        (full, at, bounds)
    }

    /// The problem of fitting setting `s` on all runs with the prior's rows
    /// `prior`, its evaluations stamped on `stamps`: the same for a fit and
    /// for the second derivatives its cross-validation takes later.
    fn all_runs<'s>(
        &'s self,
        s: &'s Setting,
        stamps: Option<&'s Stamps>,
        prior: Option<PriorRows>,
        bounds: Vec<(f64, f64)>,
    ) -> Problem<'s, impl Fn(&[f64]) -> Augmented + Sync + 's> {
        Problem::new(
            move |p: &[f64]| {
                if let Some(st) = stamps {
                    st.tick();
                }
                s.layout.model(&self.bases.all, p)
            },
            self.runs.iter().collect(),
            self.scales,
            bounds,
        )
        .with_layout(s.layout.clone(), &self.bases.all, self.derivatives)
        .with_prior(prior)
        .with_shared(&self.shared)
    }

    /// `fitted`'s all-run fit with the second derivatives of its
    /// linearisation, taken now if the fit left them out.
    fn with_curvature(&self, fitted: &Fitted) -> FitOutcome {
        let full = &fitted.full;
        let (Some(at), Some(linear)) = (&fitted.linearised_at, &full.linear) else {
            return full.clone();
        };
        if linear.curvature.ncols() > 0 {
            return full.clone();
        }
        let t0 = Instant::now();
        let stamps = self.timing.map(|_| Stamps::default());
        let problem = self.all_runs(
            &fitted.setting,
            stamps.as_ref(),
            fitted.prior,
            fitted.bounds.clone(),
        );
        let mut linear = linear.clone();
        complete_curvature(&problem, at, &mut linear, &full.unseen);
        if let (Some(rec), Some(st)) = (self.timing, &stamps) {
            rec.add(Phase::CandidateCurvature, t0.elapsed(), st.count());
        }
        FitOutcome {
            linear: Some(linear),
            ..full.clone()
        }
    }

    /// Scores a candidate fitted on all runs on every fold, refitted from
    /// the all-run optimum ([`refit`]: its linearisation first,
    /// Levenberg–Marquardt within a budget when that does not converge;
    /// non-converged folds are counted and warned about).
    pub(crate) fn cross_validate(&self, fitted: &Fitted) -> Scored {
        let s = &fitted.setting;
        if let (Some(rec), false) = (self.timing, s.kinds().is_empty()) {
            rec.candidate(true);
        }
        // The base's own folds where they serve: no fold refit, so no
        // second derivatives to take (`n·(n + 3)/2` replays nothing reads).
        let known = self.base_folds(fitted, &fitted.full);
        let full = &if known.is_some() {
            fitted.full.clone()
        } else {
            self.with_curvature(fitted)
        };
        // Folds in parallel too: a candidate whose fit is slow (a steering
        // compliance solves for the wheel's slip at every force) would
        // otherwise leave one core idle at the end of the singles.
        let per_fold: Vec<(ChannelErrors, Vec<f64>, bool)> = (0..self.folds.len())
            .into_par_iter()
            .map(|k| {
                let t0 = Instant::now();
                let base = &self.bases.folds[k];
                if let Some(q) = known.map(|folds| folds[k].clone()) {
                    self.tick();
                    return (self.heldout_errors(k, &s.layout.model(base, &q)), q, true);
                }
                let stamps = self.timing.map(|_| Stamps::default());
                let problem = Problem::new(
                    |p: &[f64]| {
                        if let Some(st) = &stamps {
                            st.tick();
                        }
                        s.layout.model(base, p)
                    },
                    self.training(k),
                    self.scales,
                    fitted.bounds.clone(),
                )
                .with_layout(s.layout.clone(), base, self.derivatives)
                .with_prior(fitted.prior);
                let rows = training_rows(&self.runs, &self.folds[k], problem.prior_count());
                let f = refit(&problem, full, &rows);
                let e = self.heldout_errors(k, &s.layout.model(base, &f.params));
                self.tick();
                if let (Some(rec), Some(st)) = (self.timing, &stamps) {
                    rec.add(Phase::CandidateFolds, t0.elapsed(), st.count());
                }
                (e, f.params, f.converged)
            })
            .collect();
        let mut heldout = ChannelErrors::default();
        for (e, _, _) in &per_fold {
            heldout.add(e);
        }
        // The quadratic model served the folds: a kept candidate need not
        // hold its Jacobian and second derivatives (rows × n² reals).
        Scored {
            heldout,
            fold_noise: self.fold_noise(full),
            fold_converged: per_fold.iter().map(|f| f.2).collect(),
            fold_params: per_fold.into_iter().map(|(_, p, _)| p).collect(),
            ..fitted.unscored()
        }
    }

    /// The fold refits' jackknife that the runs' noise alone gives each
    /// parameter of the all-run fit `full`, in its standard errors
    /// ([`fold_noise_factors`]): the folds' held-out rows taken from its
    /// linearisation's Jacobian, the fitted parameters inside their box.
    fn fold_noise(&self, full: &FitOutcome) -> Vec<(f64, f64)> {
        let Some(linear) = &full.linear else {
            return Vec::new();
        };
        let free: Vec<bool> = (0..full.params.len())
            .map(|i| {
                full.std_errors[i].is_finite() && full.held_for(i).is_none() && !full.is_unseen(i)
            })
            .collect();
        let held: Vec<_> = self
            .folds
            .iter()
            .map(|f| held_rows(&self.runs, f))
            .collect();
        fold_noise_factors(&linear.jacobian, &held, &free)
    }

    /// The start of a candidate's polish and how its global stage searched:
    /// the lowest cost of `starts` and of the global stage from the best of
    /// them (from the effect off without them) over the parameters
    /// [`crate::diagnose::fit::layout::Layout::global_stage`] leaves free ([`global_best`]: a grid along one to
    /// three parameters, a swarm with one particle at that point along more).
    /// Where the axle characteristics are fitted, the start must be
    /// consistent with the candidate rather than with the base: the axle
    /// grid is rerun at the global stage's effect values and, for an effect that
    /// takes a measured input, at the input as logged ([`as_logged`]);
    /// the lowest cost of them all starts the polish.
    fn start<F: Fn(&[f64]) -> crate::diagnose::model::Augmented + Sync>(
        &self,
        problem: &Problem<F>,
        s: &Setting,
        starts: &[Vec<f64>],
        pso: &Pso,
    ) -> (Vec<f64>, GlobalSearch) {
        let held = s.layout.restricted_from();
        // Each start replayed, the lowest so far kept (the global stage starts
        // there, no replay again); one above it stops early: only it is read.
        let mut tried: Vec<(f64, Vec<f64>)> = Vec::with_capacity(starts.len() + 3);
        let lowest = |t: &[(f64, Vec<f64>)]| t.iter().map(|t| t.0).fold(f64::INFINITY, f64::min);
        for p in starts {
            let c = problem.cost_below(p, lowest(&tried));
            if tried.iter().all(|(t, _)| c < *t) {
                problem.keep_last();
            }
            tried.push((c, p.clone()));
        }
        // A single's global stage starts from the effect off, the base
        // model every single shares: replayed once for them all.
        let off_cost = starts.is_empty().then(|| {
            let c = problem.cost(&s.off());
            problem.share_last();
            c
        });
        // A single's global stage starts from the effect off; a
        // combination's from its best start, along the added effect's own
        // parameters (the current set's stay at that start's values).
        let from = tried
            .iter()
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map_or_else(|| s.off(), |(_, p)| p.clone());
        // The global stage's best was replayed and kept: its cost as found
        // (the same number a replay would give) where it was evaluated.
        let (p, cost, global) = global_best(problem, &from, pso, s.layout.global_stage());
        let cost = cost
            .filter(|c| c.is_finite())
            .unwrap_or_else(|| problem.cost(&p));
        tried.push((cost, p));
        // The sensor offsets as the standstills and straights measured
        // them: a start in the basin a real log's offsets are in.
        if let Some(i) = s.kinds().iter().position(|k| *k == EffectKind::SensorBias) {
            if self.calibrated.iter().any(Option::is_some) {
                let mut q = from.clone();
                for (slot, c) in q[s.layout.effect(i)].iter_mut().zip(&self.calibrated) {
                    if let Some((mean, ..)) = c {
                        *slot = *mean;
                    }
                }
                tried.push((problem.cost_below(&q, lowest(&tried)), q));
            }
        }
        // A single's axles are regridded at its effect values where its
        // global stage found them worth something (at the base's axles they
        // lower the cost by REGRID_GAIN; below that the grid would be the
        // base's own again), and at the input as logged; a combination's
        // starts already carry each member's axles.
        if let (true, [kind]) = (s.layout.axle, s.kinds()) {
            let off = off_cost.unwrap_or_else(|| problem.cost(&s.off()));
            let (cost, p) = tried
                .iter()
                .min_by(|a, b| a.0.total_cmp(&b.0))
                .expect("the global stage's best is tried");
            let near = p[..held].to_vec();
            let gained = (*cost < (1.0 - REGRID_GAIN) * off).then(|| p[held..].to_vec());
            for tail in gained.into_iter().chain(as_logged(*kind)) {
                tried.extend(axle_grid_best(problem, &tail, &near));
            }
        }
        let best = tried
            .into_iter()
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map_or_else(|| s.off(), |(_, p)| p);
        (best, global)
    }

    /// Held-out replays of every run with a candidate's fold parameters.
    pub(crate) fn heldout_observed(&self, sc: Option<&Scored>) -> Vec<Observed> {
        let mut out = vec![Observed::default(); self.runs.len()];
        for (k, fold) in self.folds.iter().enumerate() {
            let model = match sc {
                Some(sc) => Setting::new(self.bases, sc.kinds.clone())
                    .layout
                    .model(&self.bases.folds[k], &sc.fold_params[k]),
                None => self.bases.folds[k].clone(),
            };
            for &i in fold {
                let r = &self.runs[i];
                out[i] = r.observe(&model);
            }
        }
        out
    }
}

/// Share of the cost a single's global stage must remove at the base's axles
/// for its axles to be regridded at its values.
const REGRID_GAIN: f64 = 0.01;

/// The values of an effect that takes a measured input as logged (the
/// bank channel at scale 1), if it takes one: the start that keeps the
/// joint axle fit out of the basin of the model without the input.
fn as_logged(kind: EffectKind) -> Option<Vec<f64>> {
    (kind == EffectKind::BankProfile).then(|| vec![1.0, 0.0])
}

/// The swarm of a fit only hands its best to Levenberg–Marquardt, which
/// needs a start in the optimum's basin, not the optimum: once its best has
/// gained less than this over these iterations the swarm has settled (most
/// candidates are not the answer and their swarms settle within a few
/// iterations; the answer's keeps improving and runs on).
const SWARM_STALL: Stall = Stall {
    iterations: 3,
    tolerance: 1e-3,
};

/// The runs prepared for replay (sampled on the replay grid, residual
/// times picked), the cross-validation folds (run i in fold i mod k) and
/// the swarm of the fits whose global stage searches more parameters than
/// a grid affords.
pub(crate) fn prepare(c: &Campaign) -> (Vec<Prepared>, Vec<Vec<usize>>, Pso) {
    let set = &c.settings;
    let runs = Prepared::campaign_runs(c);
    let k = runs.len().min(MAX_FOLDS);
    let folds: Vec<Vec<usize>> = (0..k)
        .map(|f| (0..runs.len()).filter(|i| i % k == f).collect())
        .collect();
    let pso = Pso {
        particles: set.particles,
        iterations: set.iterations,
        inertia: Inertia::LinearDecreasing,
        seed: set.seed,
        parallel: false,
        stall: Some(SWARM_STALL),
        ..Pso::default()
    };
    (runs, folds, pso)
}
