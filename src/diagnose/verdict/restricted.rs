//! The restricted fit that screens a greedy step without polishing its sets.
//!
//! A greedy step ([`crate::diagnose::verdict::search`]) tries the current
//! set with each remaining effect added. Where no set can be added (every
//! one removes less than [`ACCEPT`] − [`SCREEN_MARGIN`] of the in-sample gap
//! the current set leaves, [`screened_additions`]) the sets are screened and
//! their full fits served only that: on the racing log (`handling diagnose
//! campaigns/putnam.toml`) 31 of the 49 candidates fitted, and two thirds of
//! the replays. The restricted fit screens them for less.
//!
//! The fit. Each set's global stage is the full fit's own
//! ([`Context::started`]: along the added effect's parameters, the current
//! set's held at its best start's values); from the better on the runs of
//! its best and of the current set at its own fit with the added effect
//! off, Levenberg–Marquardt along the added effect's parameters only
//! ([`RESTRICTED_ITERATIONS`] at most), the current set's and the axles'
//! held. The second start is needed: the global stage weighs the prior's
//! rows as the base model's fit did (×274 on a sedan whose runs count as
//! 9 samples), the current set's fit as its own residuals temper them, so
//! the global stage's best can hold axles nearer the prior's centre that
//! fit the runs worse than the current set's. Held there, the restricted
//! fit (which weighs the runs alone) ended worse than the set it extends:
//! `sensor_bias+accelerometer_position+sensor_delay` −17.5 % of what the
//! pair leaves, the delay at 0. From the current set's own fit it ends at
//! least as well as that set, so a screened row's share is never below 0
//! (to the polish's tolerance). Its optimum is a point of the full fit's
//! box, which the full polish, refitting everything, improves on but for
//! the prior's rows: the restricted fit's in-sample reduction `R_r` is
//! about at most the full fit's `R_f`.
//!
//! Why it can still screen. What the full polish adds to `R_r` is what
//! refitting the current set (and the axles) beside the added effect
//! gains. The current set sits at its own optimum, where the cost's
//! gradient along its parameters vanishes with the added effect off; the
//! added effect moves that gradient only through how the two couple, and
//! the refit recovers a second-order amount of it. On the racing log the
//! full fits of the 31 sets removed at most 1.5 points more of the gap than
//! the restricted ones (`steer_path+sensor_bias`, 6.8 % against 5.3 %;
//! where the full fit removes less, by up to 0.4 points, the prior's rows
//! on its refitted axles cost it: `benchmarks.md`). A step is screened by the restricted
//! fits only where every set's `R_r` stays below [`ACCEPT`] −
//! [`SCREEN_MARGIN`] − [`RESTRICTED_MARGIN`] ([`rules::screened_restricted`]):
//! ten points more than the full fits' screen, several times what the
//! coupling was seen to add. Otherwise every set is polished and the full
//! fits' screening and search run as before (the same fits, from the same
//! global stages): a step in which a set could be added is decided on full
//! fits alone, so no set a full fit would accept is dropped for the
//! restricted fits' sake.
//!
//! The screened rows then report the restricted fits (in-sample error,
//! share of what the current set leaves, ΔBIC): a lower bound on what the
//! sets remove, as the rows say.

use crate::diagnose::fit::layout::Layout;
use crate::diagnose::fit::problem::Problem;
use crate::diagnose::fit::{FitOutcome, FIT_TOLERANCE};
use crate::diagnose::model::channels::ChannelErrors;
use crate::diagnose::report::Screened;
use crate::diagnose::timing::{Phase, Stamps};
use crate::diagnose::verdict::baseline::Baseline;
use crate::diagnose::verdict::rules;
#[cfg(doc)]
use crate::diagnose::verdict::rules::{ACCEPT, RESTRICTED_MARGIN, SCREEN_MARGIN};
use crate::diagnose::verdict::score::{Context, Scored, Started};
#[cfg(doc)]
use crate::diagnose::verdict::screening::screened_additions;
use crate::diagnose::verdict::screening::screened_row;
use crate::optim::bounded::{BoundedLm, Jacobians};
use crate::optim::local::Residuals;
use std::time::Instant;

/// Iteration budget of a restricted fit: its one to four parameters start
/// at the global stage's best, in the optimum's basin.
pub const RESTRICTED_ITERATIONS: usize = 20;

impl Context<'_> {
    /// The restricted fit of a set whose global stage is done (`started`):
    /// Levenberg–Marquardt along the parameters its global stage searched
    /// ([`crate::diagnose::fit::layout::Layout::restricted_from`] on), the rest held at the start, on all runs
    /// (the data's residuals: the prior's rows weigh only the axles, held
    /// here). The set as scored without its folds.
    pub(crate) fn restricted(&self, started: &Started, current: &Scored) -> Scored {
        let s = &started.setting;
        let held = s.layout.restricted_from();
        let stamps = self.timing.map(|_| Stamps::default());
        let t0 = Instant::now();
        let at = &self.restricted_start(started, current);
        let full_vector = |q: &[f64]| {
            let mut p = at.clone();
            p[held..].copy_from_slice(q);
            p
        };
        let problem = Problem::new(
            |q: &[f64]| {
                if let Some(st) = &stamps {
                    st.tick();
                }
                s.layout.model(&self.bases.all, &full_vector(q))
            },
            self.runs.iter().collect(),
            self.scales,
            s.bounds()[held..].to_vec(),
        )
        // Its start is the global stage's best, whose replays the global
        // stage shared ([`Context::started`]).
        .with_shared(&self.shared);
        let lm = BoundedLm {
            iterations: RESTRICTED_ITERATIONS,
            tolerance: FIT_TOLERANCE,
            jacobians: Jacobians::Secant,
        }
        .minimize(&problem, &at[held..], &problem.bounds);
        let insample: ChannelErrors = problem.errors(&lm.params);
        let residuals = problem.data_count();
        drop(problem);
        if let (Some(rec), Some(st)) = (self.timing, &stamps) {
            rec.add(Phase::CandidatePolish, t0.elapsed(), st.count());
        }
        let params = full_vector(&lm.params);
        let n = params.len();
        Scored {
            kinds: s.layout.kinds.clone(),
            full: FitOutcome {
                params,
                std_errors: vec![f64::NAN; n],
                cost: lm.cost,
                residuals,
                evaluations: lm.evaluations,
                converged: lm.converged,
                global: started.global,
                unseen: Vec::new(),
                held: Vec::new(),
                linear: None,
                robust_std_errors: Vec::new(),
                robust_covariance: None,
            },
            insample,
            heldout: ChannelErrors::default(),
            fold_params: Vec::new(),
            fold_noise: Vec::new(),
            folds_converged: 0,
            prior_weight: None,
        }
    }
}

impl Context<'_> {
    /// Where a restricted fit starts: the better on the runs alone (no
    /// prior's rows, as the restricted fit weighs them) of the global
    /// stage's best and of `current` at its own fit with the added effect
    /// off, where the set fits the runs exactly as `current` does.
    fn restricted_start(&self, started: &Started, current: &Scored) -> Vec<f64> {
        let s = &started.setting;
        let Some(added) = s.kinds().last().filter(|_| s.kinds().len() > 1) else {
            return started.start.clone();
        };
        let current_layout = Layout::new(&current.kinds, s.layout.axle);
        let off = self.off(&[*added]);
        let own = current_layout.combined(&current.full.params, *added, &off);
        if own.len() != started.start.len() {
            return started.start.clone();
        }
        let problem = Problem::new(
            |p: &[f64]| s.layout.model(&self.bases.all, p),
            self.runs.iter().collect(),
            self.scales,
            s.bounds(),
        )
        .with_shared(&self.shared);
        let (c_best, c_own) = (problem.cost(&started.start), problem.cost(&own));
        if c_own < c_best {
            own
        } else {
            started.start.clone()
        }
    }
}

/// The greedy step's screening by restricted fits (`restricted`, one per
/// set of the step, [`Context::restricted`]): where every set removes less
/// than [`ACCEPT`] − [`SCREEN_MARGIN`] − [`RESTRICTED_MARGIN`] of the
/// in-sample gap above noise `current` leaves, their rows as screened
/// (their folds and polish spared); None: the sets are to be polished.
pub(crate) fn screened_restricted(
    ctx: &Context,
    base: &Baseline,
    current: &Scored,
    restricted: &[Scored],
) -> Option<Vec<Screened>> {
    let extra: Vec<f64> = restricted
        .iter()
        .map(|sc| base.insample_extra(&current.insample, &sc.insample))
        .collect::<Option<_>>()?;
    if !extra.iter().all(|&x| rules::screened_restricted(x)) {
        return None;
    }
    let rows = restricted
        .iter()
        .zip(extra)
        .map(|(sc, x)| {
            if let Some(rec) = ctx.timing {
                rec.candidate(false);
            }
            // Its fit and the folds it was spared count as done.
            for _ in 0..=ctx.folds.len() {
                ctx.tick();
            }
            screened_row(sc, x, Some(&current.kinds), base)
        })
        .collect();
    Some(rows)
}
