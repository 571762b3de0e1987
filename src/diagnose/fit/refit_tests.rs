//! Tests of the fold refits ([`super`]): five runs of a PAC89 car fitted
//! with simplified-Magic-Formula axles (a model-form gap far above the
//! noise, as on a real log); costs dimensionless, SI units.

use super::*;
use crate::diagnose::fit::{hold_stands, linearise, pinned, to_hold, REFIT_SETTLED};
use crate::diagnose::model::replay::tests::sine_run;
use crate::diagnose::model::replay::Prepared;
use crate::manoeuvre::SineSteer;
use crate::optim::bounded::{BoundedLm, Jacobians};
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
pub(in crate::diagnose::fit) const AXLES: [(f64, f64); 3] = [(2.0, 80.0), (2.0, 80.0), (0.3, 3.5)];
pub(in crate::diagnose::fit) const SCALES: [f64; 3] = [2e-4, 5e-3, 1.0];

/// A refit lands on Levenberg–Marquardt's optimum: the cost to a few
/// times what Levenberg–Marquardt's stopping test leaves (a step's
/// decrease below `FIT_TOLERANCE` of the cost; the refit's own test is
/// tighter), the parameters to a small share of their standard errors.
fn assert_same_optimum(quick: &FitOutcome, slow: &FitOutcome, what: &str) {
    assert!(
        (quick.cost - slow.cost).abs() <= 3.0 * crate::diagnose::fit::FIT_TOLERANCE * slow.cost,
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
        // Three model steps, and a fresh Jacobian (3 replays) where the
        // fold moved more than REFIT_FAR all-run standard errors.
        assert!(
            quick.evaluations <= 3 + 3,
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

/// Thirty runs (the five six times over: `m` = 11,220 rows), their
/// optimum (Levenberg–Marquardt to a tolerance of 1e-13) and its standard
/// errors, and an all-run fit linearised `z` standard errors of the first
/// parameter off it, along the direction in which the others follow it;
/// its fold is every row.
struct Displaced<'a> {
    all: Problem<'a, fn(&[f64]) -> Augmented>,
    best: Vec<f64>,
    se: Vec<f64>,
    off: FitOutcome,
    rows: Vec<std::ops::Range<usize>>,
}

fn displaced(five: &[Prepared], z: f64) -> Displaced<'_> {
    let thirty: Vec<&Prepared> = five.iter().cycle().take(30).collect();
    let build: fn(&[f64]) -> Augmented = axle_model;
    let all = Problem::new(build, thirty, SCALES, AXLES.to_vec());
    let m = all.count();
    let tight = BoundedLm {
        iterations: 200,
        tolerance: 1e-13,
        jacobians: Jacobians::Every,
    };
    let lm = fit(&all, &[10.0, 10.0, 1.0], None, Polish::LevenbergMarquardt);
    let best = tight.minimize(&all, &lm.params, &all.bounds).params;
    let jacobian = linearise(&all, &best).jacobian;
    let s2 = 2.0 * all.cost(&best) / (m - 3) as f64;
    let cov = (jacobian.transpose() * &jacobian).try_inverse().unwrap() * s2;
    let se: Vec<f64> = (0..3).map(|i| cov[(i, i)].sqrt()).collect();
    let start: Vec<f64> = (0..3).map(|k| best[k] + z * cov[(k, 0)] / se[0]).collect();
    let off = FitOutcome {
        params: start.clone(),
        std_errors: se.clone(),
        cost: all.cost(&start),
        residuals: m,
        evaluations: 0,
        converged: true,
        global: GlobalSearch::None,
        unseen: Vec::new(),
        held: Vec::new(),
        linear: Some(linearise(&all, &start)),
        robust_std_errors: Vec::new(),
        robust_covariance: None,
    };
    Displaced {
        all,
        best,
        se,
        off,
        rows: std::iter::once(0..m).collect(),
    }
}

/// A fold refit started 0.7 of what the earlier stop (a predicted
/// decrease of `1e-6·C`) let lie from its optimum, `√(1e-6·(m − n))`
/// standard errors of one parameter along the direction in which the
/// others follow it: that stop took no step there, 0.074 standard errors
/// off; the stop at `τ·C/m` goes on to within 0.05 of them (its bound is
/// `√τ` ≈ 0.03).
#[test]
fn a_fold_refit_a_fraction_of_a_standard_error_off_goes_on_to_its_optimum() {
    let five = runs();
    let m = 11_220;
    let a = 0.7 * (1e-6 * (m - 3) as f64).sqrt();
    assert!(a > 0.07, "{m} rows: {a}");
    let d = displaced(&five, a);
    assert_eq!(d.all.count(), m);
    // The premise: the model there predicts a decrease the earlier stop
    // took for converged.
    let (model, at) = fold_model(&d.off, &d.rows).unwrap();
    let (_, predicted) = model.at(&at.p, &at.r, &d.all.bounds).step(0.0).unwrap();
    assert!(
        predicted <= 1e-6 * at.cost,
        "{predicted} against {}",
        at.cost
    );
    let quick = refit(&d.all, &d.off, &d.rows);
    assert!(quick.converged);
    for k in 0..3 {
        let z = (quick.params[k] - d.best[k]).abs() / d.se[k];
        assert!(
            z <= 0.05,
            "parameter {k}: {z} standard errors off ({:?} against {:?} ± {:?})",
            quick.params,
            d.best,
            d.se
        );
    }
}

/// A fold refit 0.018 standard errors from its optimum (within `√τ` ≈
/// 0.032 of them, beyond the 0.01 of the `τ = 1e-4` before) is settled:
/// it stops where it starts, no replay spent, on its model and by
/// Levenberg–Marquardt alike (which takes its Jacobian there, then no
/// trial step); the `1e-4` stop, and Levenberg–Marquardt's earlier one (a
/// step's decrease below 1e-6 of the cost), each took a step.
#[test]
fn a_fold_refit_within_the_settled_reach_of_its_optimum_spends_no_step() {
    let five = runs();
    let d = displaced(&five, 0.018);
    let m = d.all.count();
    // The premise: both models predict a decrease between the two stops.
    let (model, at) = fold_model(&d.off, &d.rows).unwrap();
    let (_, newton) = model.at(&at.p, &at.r, &d.all.bounds).step(0.0).unwrap();
    let linear = d.off.linear.as_ref().unwrap();
    let gauss = ProjectedModel::new(&linear.jacobian, &at.r, &at.p, &d.all.bounds);
    let (_, gauss) = gauss.step(1e-3).unwrap();
    for predicted in [newton, gauss] {
        let share = predicted * m as f64 / at.cost;
        assert!((1e-4..=0.9e-3).contains(&share), "{share}");
    }
    let quick = refit(&d.all, &d.off, &d.rows);
    assert!(quick.converged);
    assert_eq!(quick.evaluations, 0);
    assert_eq!(quick.params, d.off.params);
    let handed = fit(&d.all, &d.off.params, None, Polish::Refit);
    assert!(handed.converged);
    assert_eq!(handed.params, d.off.params);
    for k in 0..3 {
        let z = (handed.params[k] - d.best[k]).abs() / d.se[k];
        assert!(z <= REFIT_SETTLED.sqrt(), "parameter {k}: {z}");
    }
}
