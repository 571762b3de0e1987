//! The cross-validation's fold refits: a candidate fitted on all runs is
//! refitted on each fold's training runs (all but the held-out ones)
//! from the all-run optimum ([`refit`]), on the all-run quadratic model of
//! the training residuals while it holds, by Levenberg–Marquardt where it
//! does not. [`training_rows`] picks the training runs' rows out of the
//! all-run residuals. The counts of replays quoted below were measured on
//! the Putnam racing log (`campaigns/putnam.toml`). Units: SI, rad.

pub(crate) use crate::diagnose::fit::fold_check::training_rows;
use crate::diagnose::fit::fold_check::{against_start, start_cost, FoldRefit};
use crate::diagnose::fit::problem::Problem;
use crate::diagnose::fit::{fit, pair_index, FitOutcome, GlobalSearch, Polish};
use crate::diagnose::model::Augmented;
use crate::optim::bounded::ProjectedModel;
use crate::optim::local::Residuals;
use nalgebra::{DMatrix, DVector};

/// The all-run quadratic model of a fold's training residuals.
struct FoldModel {
    jacobian: DMatrix<f64>,
    curvature: DMatrix<f64>,
    p0: Vec<f64>,
    /// The parameters the all-run fit held (unseen, or undetermined): the
    /// folds keep them, so the model has no columns for them.
    fixed: Vec<usize>,
}

impl FoldModel {
    /// Zeroes the columns of the [`FoldModel::fixed`] parameters. A
    /// relaxation length held at 0 has a zero Jacobian column there (its
    /// lag is below any replay's resolution) but not a zero second
    /// derivative: left in, `Σ r·∇²r` made the Newton model indefinite
    /// along it, no damping of a zero diagonal could cure that, and the
    /// fold stopped at the all-run optimum, its held-out error the
    /// in-sample one (measured on Putnam).
    fn hold(&mut self) {
        let n = self.p0.len();
        let curved = self.curvature.ncols() > 0;
        for &k in &self.fixed {
            self.jacobian.column_mut(k).fill(0.0);
            for b in (0..n).filter(|_| curved) {
                self.curvature.column_mut(pair_index(n, k, b)).fill(0.0);
            }
        }
    }

    /// Takes the problem's Jacobian afresh at `p` (residuals `r`) and builds
    /// the model there; the all-run second derivatives are kept.
    fn relinearise<F: Fn(&[f64]) -> Augmented + Sync>(
        &mut self,
        problem: &Problem<F>,
        p: &[f64],
        r: &[f64],
    ) {
        self.jacobian = problem.jacobian(p, r, &problem.bounds);
        self.p0 = p.to_vec();
        self.hold();
    }

    /// The Newton model of the cost at `p` with residuals `r` (replayed).
    fn at(&self, p: &[f64], r: &[f64], bounds: &[(f64, f64)]) -> ProjectedModel {
        let n = p.len();
        let delta: Vec<f64> = p.iter().zip(&self.p0).map(|(p, q)| p - q).collect();
        // The Jacobian at p: J + ∇²r·δ, row by row.
        let mut j = self.jacobian.clone();
        if delta.iter().any(|&d| d != 0.0) {
            for a in 0..n {
                for (b, &d) in delta.iter().enumerate() {
                    if d != 0.0 {
                        let col = self.curvature.column(pair_index(n, a, b));
                        j.column_mut(a).axpy(d, &col, 1.0);
                    }
                }
            }
        }
        let rv = DVector::from_column_slice(r);
        let g = j.transpose() * &rv;
        let gauss_newton = j.transpose() * &j;
        let scale = gauss_newton.diagonal();
        // Σ r·∇²r: the curvature columns weighted by the residuals.
        let weighted = self.curvature.transpose() * &rv;
        let hessian = DMatrix::from_fn(n, n, |a, b| {
            gauss_newton[(a, b)] + weighted[pair_index(n, a, b)]
        });
        ProjectedModel::newton(hessian, g, scale, p, bounds)
    }
}

/// A fold refit has converged when the next step of its linear model
/// would lower the training cost by less than this share: far below what
/// moves a reported held-out error.
const REFIT_DECREASE: f64 = 1e-6;

/// Replays of a fold refit on its quadratic model before it falls back to
/// Levenberg–Marquardt. A model step costs one replay, an iteration of
/// Levenberg–Marquardt `n + 1` or more: where one run of a real log
/// leaving moves the optimum far (a 20 s piece of a racing log), the model's
/// steps go on lowering the cost as predicted, a share of 1e-3 to 1e-5 a
/// step, well past a handful of them (measured on the Putnam log).
const REFIT_MODEL_STEPS: usize = 60;

/// Rejected model steps in a row (the damping ten times higher after each)
/// after which the model no longer serves. On the Putnam log, 3 handed 54
/// of its 264 fold refits to Levenberg–Marquardt, at 40–100 replays each,
/// where damping on reaches a step that lowers the cost.
const REFIT_MODEL_REJECTIONS: usize = 8;

/// Times a fold refit that has moved differences its Jacobian afresh (`n`
/// replays, the all-run second derivatives kept): when its steps stall, or
/// when a model that mispredicted its last step sees a minimum. On the
/// Putnam log, with these limits, 256 of 264 fold refits converge on their
/// models and 8 are handed over, 2,673 replays in all where the all-run
/// model alone (3 rejections, 20 steps) took 3,597.
const REFIT_RELINEARISATIONS: usize = 4;

/// Refits `problem` (the training runs of a fold, whose residual rows are
/// `rows` of the all-run problem's) from the all-run fit `full`. The
/// optimum moves little when one run of several leaves, so the all-run
/// quadratic model of the residuals restricted to those rows
/// ([`Linearisation`](crate::diagnose::fit::Linearisation)) stands in for their
/// derivatives: at `p0 + δ` the Jacobian is `J + ∇²r·δ` and the Hessian of
/// the cost `JᵀJ + Σ r·∇²r` with the replayed residuals `r`, exact to
/// second order in δ. The second-order
/// term matters: the residuals of a real log stay far above the noise (a
/// model-form gap), where Gauss–Newton alone, which drops it, converges
/// slowly. Damped Newton steps projected into the bounds, each costing one
/// replay of the training runs, the damping raised after a step that does
/// not lower the cost and lowered after one that does, until the model
/// predicts a decrease below [`REFIT_DECREASE`] of the cost; that test is
/// believed only where the model predicted its last step's decrease to a
/// factor of 2. A refit that has moved takes a fresh Jacobian (at most
/// [`REFIT_RELINEARISATIONS`] times) when [`REFIT_MODEL_REJECTIONS`] steps
/// in a row fail, or when a model it does not believe sees a minimum.
/// Where the model has not converged within [`REFIT_MODEL_STEPS`] replays,
/// or cannot go on, Levenberg–Marquardt (fresh Jacobians) goes on from
/// there within its budget. Without a linearisation (`full` not polished)
/// it is Levenberg–Marquardt from `full`. Checked against its start
/// ([`refit_checked`]): one that ends above it is put back there.
pub fn refit<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    full: &FitOutcome,
    rows: &[std::ops::Range<usize>],
) -> FitOutcome {
    refit_checked(problem, full, rows).0
}

/// [`refit`] and its check against its start ([`FoldRefit`]).
pub fn refit_checked<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    full: &FitOutcome,
    rows: &[std::ops::Range<usize>],
) -> (FitOutcome, FoldRefit) {
    let start = start_cost(problem, full, rows);
    against_start(problem, full, start, descend(problem, full, rows))
}

/// [`refit`]'s descent, unchecked.
pub(super) fn descend<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    full: &FitOutcome,
    rows: &[std::ops::Range<usize>],
) -> FitOutcome {
    let Some(linear) = full.linear.as_ref().filter(|_| !full.params.is_empty()) else {
        return fit(problem, &full.params, None, Polish::Refit);
    };
    let n = full.params.len();
    let picked: Vec<usize> = rows.iter().flat_map(|r| r.clone()).collect();
    let mut model = FoldModel {
        jacobian: linear.jacobian.select_rows(picked.iter()),
        curvature: linear.curvature.select_rows(picked.iter()),
        p0: full.params.clone(),
        fixed: (0..n)
            .filter(|&i| full.is_unseen(i) || full.held_for(i).is_some())
            .collect(),
    };
    model.hold();
    let mut relinearised = 0;
    let bounds = &problem.bounds;
    let mut p = full.params.clone();
    let mut r: Vec<f64> = picked.iter().map(|&i| linear.residuals[i]).collect();
    let mut cost = 0.5 * r.iter().map(|e| e * e).sum::<f64>();
    let mut trial = vec![0.0; r.len()];
    let mut lambda = 0.0;
    let mut evaluations = 0;
    // Damping raised without a replay when the model is not positive
    // definite: a bounded number of tries in all.
    let mut rejected = 0;
    // Whether the model predicted the last accepted step's decrease (to a
    // factor of 2), or was just differenced here: only then is its
    // convergence test believed. A model far from where it was built can
    // see a minimum that is not there.
    let mut trusted = true;
    // A minimum seen by a model that is not believed.
    let mut doubted = false;
    for _ in 0..4 * REFIT_MODEL_STEPS {
        let can_relinearise = relinearised < REFIT_RELINEARISATIONS
            && p != model.p0
            && evaluations + n < REFIT_MODEL_STEPS;
        // Stalled or doubted after moving: the Jacobian no longer holds here.
        if (rejected == REFIT_MODEL_REJECTIONS || doubted) && can_relinearise {
            model.relinearise(problem, &p, &r);
            evaluations += problem.jacobian_evaluations(n);
            relinearised += 1;
            (rejected, lambda, trusted, doubted) = (0, 0.0, true, false);
        }
        if doubted || evaluations >= REFIT_MODEL_STEPS || rejected == REFIT_MODEL_REJECTIONS {
            break;
        }
        let Some((d, predicted)) = model.at(&p, &r, bounds).step(lambda) else {
            lambda = (lambda * 10.0).max(1e-3);
            continue;
        };
        if predicted <= REFIT_DECREASE * cost {
            if trusted {
                return FitOutcome {
                    std_errors: vec![f64::NAN; n],
                    cost: cost - problem.prior_cost(&p),
                    params: p,
                    residuals: problem.data_count(),
                    evaluations,
                    converged: true,
                    global: GlobalSearch::None,
                    unseen: Vec::new(),
                    held: full.held.clone(),
                    linear: None,
                    robust_std_errors: Vec::new(),
                    robust_covariance: None,
                };
            }
            doubted = true;
            continue;
        }
        let q: Vec<f64> = problem.clamp(&p.iter().zip(&d).map(|(p, d)| p + d).collect::<Vec<_>>());
        // Only a step below the cost is taken: the replays may stop once
        // they show it is not.
        let below = problem.residuals_below(&q, &mut trial, cost);
        evaluations += 1;
        let c = if below {
            0.5 * trial.iter().map(|e| e * e).sum::<f64>()
        } else {
            f64::INFINITY
        };
        if c.is_finite() && c < cost {
            trusted = (0.5..=2.0).contains(&((cost - c) / predicted));
            (p, cost) = (q, c);
            std::mem::swap(&mut r, &mut trial);
            // Its replays are kept: Levenberg–Marquardt, if it takes over
            // from here, starts without integrating them again.
            problem.keep_last();
            lambda *= 0.1;
            rejected = 0;
        } else {
            lambda = (lambda * 10.0).max(1e-3);
            rejected += 1;
        }
    }
    let mut f = fit(problem, &p, None, Polish::Refit);
    f.evaluations += evaluations;
    f
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::diagnose::fit::{hold_stands, linearise, pinned, to_hold};
    use crate::diagnose::model::replay::tests::sine_run;
    use crate::diagnose::model::replay::Prepared;
    use crate::manoeuvre::SineSteer;
    use crate::tyre::{Pac89, Tyre};
    use crate::vehicle::{Vehicle, VehicleModel};

    /// Axles of stiffness factors `B_f`, `B_r` and peak friction `D`.
    pub(in crate::diagnose::fit) fn axle_model(p: &[f64]) -> Augmented {
        let tyre = |b: f64| Tyre::MagicSimple(crate::tyre::MagicSimple { b, c: 1.3, d: p[2] });
        Augmented::new(
            VehicleModel::new(Vehicle::compact_sedan(), tyre(p[0]), tyre(p[1])),
            1.0,
        )
    }

    /// Runs of a PAC89 car fitted with simplified-Magic-Formula axles: a
    /// model-form gap far above the noise, as on a real log.
    pub(in crate::diagnose::fit) fn runs() -> Vec<Prepared> {
        let pac89 = Tyre::Pac89(Pac89::adams_example());
        let truth = Augmented::new(
            VehicleModel::new(Vehicle::compact_sedan(), pac89.clone(), pac89),
            1.0,
        );
        (0..5)
            .map(|k| {
                let m = SineSteer {
                    speed: 15.0 + 4.0 * k as f64,
                    amplitude: 0.02 + 0.01 * k as f64,
                    frequency: 0.3 + 0.15 * k as f64,
                    start: 0.5,
                    end: 8.0,
                };
                sine_run(&truth, k, m)
            })
            .collect()
    }

    /// The axle characteristics' box (B front, B rear, D) and the channel
    /// scales of the fold-refit tests.
    pub(in crate::diagnose::fit) const AXLES: [(f64, f64); 3] =
        [(2.0, 80.0), (2.0, 80.0), (0.3, 3.5)];
    pub(in crate::diagnose::fit) const SCALES: [f64; 3] = [2e-4, 5e-3, 1.0];

    /// A refit lands on Levenberg–Marquardt's optimum: the cost to a few
    /// times what the refit's stopping test leaves (REFIT_DECREASE,
    /// predicted), the parameters to a small share of their standard errors.
    fn assert_same_optimum(quick: &FitOutcome, slow: &FitOutcome, what: &str) {
        assert!(
            (quick.cost - slow.cost).abs() <= 3.0 * REFIT_DECREASE * slow.cost,
            "{what}: {} against {}",
            quick.cost,
            slow.cost
        );
        for i in 0..3 {
            assert!(
                (quick.params[i] - slow.params[i]).abs() <= 0.1 * slow.std_errors[i],
                "{what}: {:?} against {:?} ± {:?}",
                quick.params,
                slow.params,
                slow.std_errors
            );
        }
    }

    #[test]
    fn a_fold_refit_on_the_quadratic_model_lands_where_levenberg_marquardt_does() {
        let runs = runs();
        let all = Problem::new(axle_model, runs.iter().collect(), SCALES, AXLES.to_vec());
        let full = fit(&all, &[10.0, 10.0, 1.0], None, Polish::LevenbergMarquardt);
        assert!(full.converged);
        // Far above the noise: the term Gauss–Newton drops matters.
        assert!(full.cost > 100.0 * full.residuals as f64, "{}", full.cost);
        for held in 0..runs.len() {
            let train: Vec<&Prepared> = (0..runs.len())
                .filter(|&i| i != held)
                .map(|i| &runs[i])
                .collect();
            let fold = Problem::new(axle_model, train, SCALES, AXLES.to_vec());
            let quick = refit(&fold, &full, &training_rows(&runs, &[held], 0));
            let slow = fit(&fold, &full.params, None, Polish::LevenbergMarquardt);
            assert!(quick.converged);
            assert!(
                quick.evaluations <= 3,
                "fold {held}: {} replays",
                quick.evaluations
            );
            assert_same_optimum(&quick, &slow, &format!("fold {held}"));
        }
    }

    /// Started from a point well off the fold's optimum (3 % above its
    /// cost), where the start's quadratic model stops holding on the way,
    /// a refit does not stop where that model sees a minimum: it takes a
    /// fresh Jacobian and lands where Levenberg–Marquardt does. (Without
    /// the trust test, the other limits as they are, it stopped at 726,179
    /// against 703,075, parameters 6 standard errors off.)
    #[test]
    fn a_fold_refit_from_afar_does_not_stop_where_its_model_no_longer_holds() {
        let runs = runs();
        let all = Problem::new(axle_model, runs.iter().collect(), SCALES, AXLES.to_vec());
        let start = [12.0, 12.0, 1.3];
        let far = FitOutcome {
            params: start.to_vec(),
            std_errors: vec![f64::NAN; 3],
            cost: all.cost(&start),
            residuals: all.data_count(),
            evaluations: 0,
            converged: false,
            global: GlobalSearch::None,
            unseen: Vec::new(),
            held: Vec::new(),
            linear: Some(linearise(&all, &start)),
            robust_std_errors: Vec::new(),
            robust_covariance: None,
        };
        let fold = Problem::new(
            axle_model,
            runs.iter().skip(1).collect(),
            SCALES,
            AXLES.to_vec(),
        );
        let rows = training_rows(&runs, &[0], 0);
        let quick = refit(&fold, &far, &rows);
        let slow = fit(&fold, &start, None, Polish::LevenbergMarquardt);
        assert!(quick.converged && slow.converged);
        assert_same_optimum(&quick, &slow, "from afar");
    }

    /// A fourth parameter no residual responds to (an offset of a channel
    /// no run measures) is held at its off value, marked unseen, given no
    /// standard error and not counted: the fit's BIC is that of the three
    /// the data see.
    #[test]
    fn a_parameter_no_residual_responds_to_is_held_at_its_off_value_and_not_counted() {
        let runs = runs();
        let three = Problem::new(axle_model, runs.iter().collect(), SCALES, AXLES.to_vec());
        let mut bounds = AXLES.to_vec();
        bounds.push((-1.0, 1.0));
        let four = Problem::new(
            |p: &[f64]| axle_model(&p[..3]),
            runs.iter().collect(),
            SCALES,
            bounds,
        );
        let f3 = fit(&three, &[10.0, 10.0, 1.0], None, Polish::LevenbergMarquardt);
        let start = [10.0, 10.0, 1.0, 0.7];
        let off = [10.0, 10.0, 1.0, 0.0];
        let f4 = fit(&four, &start, Some(&off), Polish::LevenbergMarquardt);
        assert_eq!(f4.unseen, [false, false, false, true]);
        assert_eq!(f4.params[3], 0.0);
        assert!(f4.std_errors[3].is_nan() && f4.std_errors[..3].iter().all(|s| s.is_finite()));
        assert_eq!((f4.free_count(), f3.free_count()), (3, 3));
        assert!(f3.unseen.iter().all(|&u| !u));
        assert!(
            (f4.bic() - f3.bic()).abs() <= 1e-9 * f3.bic().abs(),
            "{} against {}",
            f4.bic(),
            f3.bic()
        );
        // Counted, the idle parameter would have cost ln N.
        let counted = FitOutcome {
            unseen: Vec::new(),
            ..f4.clone()
        };
        let ln_n = (f4.residuals as f64).ln();
        assert!((counted.bic() - f4.bic() - ln_n).abs() < 1e-9 * ln_n);
    }

    /// Of the effect parameters whose standard error exceeds their box,
    /// the one fewest standard errors from its off value is held first,
    /// then the next; one unseen, on a bound, already held, determined or
    /// among the axles (before `from`) is not.
    #[test]
    fn the_parameter_held_first_is_the_undetermined_one_cheapest_to_hold() {
        let bounds = [
            (2.0, 80.0),
            (0.3, 3.5),
            (-1.0, 1.0),
            (0.0, 2.0),
            (-1.0, 1.0),
            (0.0, 1.0),
        ];
        let off = [10.0, 1.0, 0.0, 0.0, 0.0, 0.0];
        let mut f = FitOutcome {
            // An axle past its box (index 0), two undetermined (2: 0.06
            // standard errors from off; 3: 0.17), one unseen (4), one on
            // its bound (5).
            params: vec![40.0, 1.0, 0.3, 0.5, 0.9, 1.0],
            std_errors: vec![100.0, 0.01, 5.0, 3.0, 9.0, 9.0],
            cost: 1.0,
            residuals: 100,
            evaluations: 0,
            converged: true,
            global: GlobalSearch::None,
            unseen: vec![false, false, false, false, true, false],
            held: Vec::new(),
            linear: None,
            robust_std_errors: Vec::new(),
            robust_covariance: None,
        };
        assert_eq!(to_hold(&f, &bounds, &off, 1), Some(2));
        f.held = vec![None, None, Some(5.0), None, None, None];
        assert_eq!(to_hold(&f, &bounds, &off, 1), Some(3));
        // The unseen one is not counted; the held one is (the effect's
        // form has it).
        assert_eq!(f.free_count(), 5);
        f.std_errors[3] = 1.9;
        assert_eq!(to_hold(&f, &bounds, &off, 1), None);
        // From the axles on, the axle past its box would be held too.
        assert_eq!(to_hold(&f, &bounds, &off, 0), Some(0));
    }

    /// A fourth parameter pinned (a box of no width) at its off value
    /// stays there: it has no standard error and no curvature, the three
    /// others fit as the three-parameter model's (the fourth enters only
    /// through its sum with the third, as a steer path's lag with its
    /// delay), and the hold stands against that fit.
    #[test]
    fn a_pinned_parameter_stays_at_its_value_without_standard_error_or_curvature() {
        let runs = runs();
        let three = Problem::new(axle_model, runs.iter().collect(), SCALES, AXLES.to_vec());
        let f3 = fit(&three, &[10.0, 10.0, 1.0], None, Polish::LevenbergMarquardt);
        let mut bounds = AXLES.to_vec();
        bounds.push((-1.0, 1.0));
        let twin = |p: &[f64]| axle_model(&[p[0], p[1], p[2] + p[3]]);
        let four = Problem::new(twin, runs.iter().collect(), SCALES, pinned(&bounds, 3, 0.0));
        let off = [10.0, 10.0, 1.0, 0.0];
        let held = fit(
            &four,
            &[10.0, 10.0, 1.0, 0.0],
            Some(&off),
            Polish::LevenbergMarquardt,
        );
        assert!(held.converged);
        assert_eq!(held.params[3], 0.0);
        assert!(held.std_errors[3].is_nan());
        for i in 0..3 {
            assert!(
                (held.params[i] - f3.params[i]).abs() <= 0.1 * f3.std_errors[i],
                "{:?} against {:?}",
                held.params,
                f3.params
            );
        }
        assert!((held.cost - f3.cost).abs() <= 1e-6 * f3.cost);
        assert!(hold_stands(&f3, &held));
        let linear = held.linear.as_ref().unwrap();
        for b in 0..4 {
            let column = linear.curvature.column(pair_index(4, b, 3));
            assert!(column.iter().all(|&c| c == 0.0), "pair ({b}, 3)");
        }
    }

    /// The hold stands while the held fit's `2·cost` exceeds the free
    /// fit's by at most 3.84 residual variances of the free fit.
    #[test]
    fn a_hold_the_data_reject_does_not_stand() {
        // 1,002 residuals, 2 free parameters: s² = 2·500/1000 = 1.
        let free = FitOutcome {
            params: vec![0.0, 0.0],
            std_errors: vec![1.0, 1.0],
            cost: 500.0,
            residuals: 1002,
            evaluations: 0,
            converged: true,
            global: GlobalSearch::None,
            unseen: Vec::new(),
            held: Vec::new(),
            linear: None,
            robust_std_errors: Vec::new(),
            robust_covariance: None,
        };
        let at = |cost: f64| FitOutcome {
            cost,
            ..free.clone()
        };
        assert!(hold_stands(&free, &at(500.0 + 1.9)));
        assert!(!hold_stands(&free, &at(500.0 + 1.93)));
    }

    /// A parameter the all-run fit held because no residual responds to
    /// it, whose second derivative is not zero (a relaxation length held
    /// at 0, whose lag below a replay's resolution leaves its Jacobian
    /// column zero but not its curvature): the fold refits keep it and
    /// land where Levenberg–Marquardt does, not at the all-run optimum.
    #[test]
    fn a_fold_refit_keeps_a_held_parameter_out_of_its_model() {
        let runs = runs();
        let mut bounds = AXLES.to_vec();
        bounds.push((0.0, 1.0));
        let four = Problem::new(
            |p: &[f64]| axle_model(&p[..3]),
            runs.iter().collect(),
            SCALES,
            bounds.clone(),
        );
        let off = [10.0, 10.0, 1.0, 0.0];
        let mut full = fit(
            &four,
            &[10.0, 10.0, 1.0, 0.0],
            Some(&off),
            Polish::LevenbergMarquardt,
        );
        assert_eq!(full.unseen, [false, false, false, true]);
        // Its second derivative along the held parameter, against the
        // residuals: Σ r·∇²r strongly negative there.
        let linear = full.linear.as_mut().unwrap();
        let r = DVector::from_column_slice(&linear.residuals);
        linear
            .curvature
            .column_mut(pair_index(4, 3, 3))
            .copy_from(&(-1e3 * &r));
        let train: Vec<&Prepared> = runs.iter().skip(1).collect();
        let fold = Problem::new(|p: &[f64]| axle_model(&p[..3]), train, SCALES, bounds);
        let quick = refit(&fold, &full, &training_rows(&runs, &[0], 0));
        let slow = fit(&fold, &full.params, Some(&off), Polish::LevenbergMarquardt);
        assert_eq!(quick.params[3], 0.0);
        assert!(
            quick.params[..3] != full.params[..3],
            "the fold did not move"
        );
        assert!(
            (quick.cost - slow.cost).abs() <= 1e-6 * slow.cost,
            "{} against {}",
            quick.cost,
            slow.cost
        );
    }
}
