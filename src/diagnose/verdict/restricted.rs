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
//! set's held at their fit); from its best, Levenberg–Marquardt along the
//! same parameters only ([`RESTRICTED_ITERATIONS`] at most), the current
//! set's and the axles' held. Its optimum is a point of the full fit's
//! box, so the full polish, which starts at the same global stage's best
//! and only lowers the cost, ends at least as low: the restricted fit's
//! in-sample reduction `R_r` is at most the full fit's `R_f` (to the
//! polishes' tolerance).
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
    pub(crate) fn restricted(&self, started: &Started) -> Scored {
        let s = &started.setting;
        let held = s.layout.restricted_from();
        let at = &started.start;
        let stamps = self.timing.map(|_| Stamps::default());
        let t0 = Instant::now();
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
