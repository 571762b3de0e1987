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
//! coupling was seen to add. Otherwise only the sets whose restricted fit
//! stays at or above that are polished ([`screen_step`]): a set below it
//! would be screened by its full fit too, by the same argument. Where
//! their full fits are all screened ([`screened_additions`]), so is the
//! step. Where one is not, the rest are polished too, and the full fits'
//! search runs as before (the same fits, from the same global stages): a
//! step in which a set could be added is decided on full fits alone, so no
//! set a full fit would accept is dropped for the restricted fits' sake.
//! On the racing log one set of the greedy step from `steer_path`
//! (`steer_path+steering_ratio`, 15 % in its full fit) had made all 18
//! sets of the step be polished (`benchmarks.md`).
//!
//! The screened rows then report the restricted fits (in-sample error,
//! share of what the current set leaves, ΔBIC) where those screened them,
//! a lower bound on what the sets remove, as the rows say; the full fits'
//! where the set was polished.

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
use crate::diagnose::verdict::score::{Context, Fitted, Scored, Started};
use crate::diagnose::verdict::screening::{screened_additions, screened_row};
use crate::optim::bounded::{BoundedLm, Jacobians};
use crate::optim::local::Residuals;
use rayon::prelude::*;
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
            fold_converged: Vec::new(),
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

/// What screening a greedy step found ([`screen_step`]).
pub(crate) enum Step<'a> {
    /// No set of the step can be added: every set's row as screened.
    Screened(Vec<Screened>),
    /// A set could be added: every set polished, in the order tried.
    Polished(Vec<Fitted<'a>>),
}

/// A greedy step's screening (`started`: the current set with each
/// remaining effect added, their global stages done). Without `screening`,
/// every set is polished. With it, every set's restricted fit first
/// ([`Context::restricted`]); a set whose restricted fit removes less than
/// [`ACCEPT`] − [`SCREEN_MARGIN`] − [`RESTRICTED_MARGIN`] of the in-sample
/// gap above noise `current` leaves ([`rules::screened_restricted`]) would
/// be screened by its full fit too, so only the others are polished. Where
/// their full fits are screened as well ([`screened_additions`]), none of
/// the step can be added: the rows, the restricted fits' where they
/// screened, the full fits' elsewhere. Otherwise the rest are polished too
/// and every set the step's pick can read is cross-validated, as without
/// screening: a step in which a set could be added is decided on full
/// fits alone.
pub(crate) fn screen_step<'a>(
    ctx: &Context<'a>,
    base: &Baseline,
    current: &Scored,
    started: Vec<Started<'a>>,
    screening: bool,
) -> Step<'a> {
    let polish_all = |s: Vec<Started<'a>>| s.into_par_iter().map(|s| ctx.polish(s)).collect();
    if !screening {
        return Step::Polished(polish_all(started));
    }
    let restricted: Vec<Scored> = started
        .par_iter()
        .map(|s| ctx.restricted(s, current))
        .collect();
    let extra: Option<Vec<f64>> = restricted
        .iter()
        .map(|sc| base.insample_extra(&current.insample, &sc.insample))
        .collect();
    let Some(extra) = extra else {
        return Step::Polished(polish_all(started));
    };
    let low: Vec<bool> = extra
        .iter()
        .map(|&x| rules::screened_restricted(x))
        .collect();
    // The sets the restricted fits do not screen, polished first.
    let (high, rest): (Vec<_>, Vec<_>) = started.into_iter().zip(&low).partition(|(_, l)| !**l);
    let high: Vec<Fitted> = polish_all(high.into_iter().map(|(s, _)| s).collect());
    if let Some(full_rows) = screened_additions(ctx, base, current, &high, true) {
        let mut full_rows = full_rows.into_iter();
        let rows = restricted
            .iter()
            .zip(extra)
            .zip(&low)
            .filter_map(|((sc, x), &l)| {
                if !l {
                    return full_rows.next();
                }
                if let Some(rec) = ctx.timing {
                    rec.candidate(false);
                }
                // Its fit and the folds it was spared count as done.
                for _ in 0..=ctx.folds.len() {
                    ctx.tick();
                }
                Some(screened_row(sc, x, Some(&current.kinds), base))
            })
            .collect();
        return Step::Screened(rows);
    }
    // A set could be added: the rest polished too, every set in its place.
    let mut rest: Vec<Fitted> = polish_all(rest.into_iter().map(|(s, _)| s).collect());
    let (mut high, mut fitted) = (high.into_iter(), Vec::with_capacity(low.len()));
    rest.reverse();
    for l in low {
        fitted.extend(if l { rest.pop() } else { high.next() });
    }
    Step::Polished(fitted)
}
