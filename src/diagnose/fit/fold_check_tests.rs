//! Tests of the fold refits' check against their start
//! ([`super::fold_check`]): on the five axle runs of the refit tests
//! (simplified Magic Formula fitted to a PAC89 car, costs dimensionless).

use crate::diagnose::fit::fold_check::against_start;
use crate::diagnose::fit::problem::Problem;
use crate::diagnose::fit::refit::refit_checked;
use crate::diagnose::fit::refit::tests::{axle_model, runs, AXLES, SCALES};
use crate::diagnose::fit::refit::training_rows;
use crate::diagnose::fit::FitOutcome;
use crate::diagnose::fit::{fit, Polish};
use crate::diagnose::model::replay::Prepared;
use crate::optim::local::Residuals;

/// Each fold of the five axle runs: the refit ends below its start
/// (the all-run parameters replayed on the training runs), is kept,
/// and its moves are the parameter changes over the standard errors.
#[test]
fn a_fold_refit_ends_below_the_all_run_fit_on_its_training_runs() {
    let runs = runs();
    let all = Problem::new(axle_model, runs.iter().collect(), SCALES, AXLES.to_vec());
    let full = fit(&all, &[10.0, 10.0, 1.0], None, Polish::LevenbergMarquardt);
    for held in 0..runs.len() {
        let train: Vec<&Prepared> = (0..runs.len())
            .filter(|&i| i != held)
            .map(|i| &runs[i])
            .collect();
        let fold = Problem::new(axle_model, train, SCALES, AXLES.to_vec());
        let (f, c) = refit_checked(&fold, &full, &training_rows(&runs, &[held], 0));
        let replayed = fold.cost(&full.params);
        assert!(
            (c.start_cost - replayed).abs() <= 1e-9 * replayed,
            "fold {held}: {} against {replayed}",
            c.start_cost
        );
        assert!(!c.put_back && c.cost <= c.start_cost, "fold {held}: {c:?}");
        assert!((c.cost - f.cost).abs() <= 1e-12 * f.cost);
        let m0 = (f.params[0] - full.params[0]).abs() / full.std_errors[0];
        assert!((c.moved_std_errors[0] - m0).abs() <= 1e-12 * m0.max(1.0));
    }
}

/// A refit that ended above its start (here made so by hand: a fold
/// "optimum" far off in a worse valley) is put back at the all-run
/// parameters, its cost the start's, and said so.
#[test]
fn a_fold_refit_that_ends_above_its_start_is_put_back_there() {
    let runs = runs();
    let all = Problem::new(axle_model, runs.iter().collect(), SCALES, AXLES.to_vec());
    let full = fit(&all, &[10.0, 10.0, 1.0], None, Polish::LevenbergMarquardt);
    let fold = Problem::new(
        axle_model,
        runs.iter().skip(1).collect(),
        SCALES,
        AXLES.to_vec(),
    );
    let start = fold.cost(&full.params);
    let far = [30.0, 5.0, 2.0];
    let worse = FitOutcome {
        params: far.to_vec(),
        cost: fold.cost(&far),
        linear: None,
        ..full.clone()
    };
    assert!(worse.cost > start);
    let (f, c) = against_start(&fold, &full, start, worse);
    assert!(c.put_back);
    assert_eq!(f.params, full.params);
    assert_eq!((f.cost, c.cost), (start, start));
    assert!(c.moved_std_errors.iter().all(|&m| m == 0.0));
}
