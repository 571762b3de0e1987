//! The reported standard errors against an independent measure of how far
//! the fit moves with the data: the jackknife over runs (Efron & Stein
//! 1981), which assumes nothing of how the residuals are correlated.
//! About a model that lacks something (a PAC89 car fitted with simplified
//! Magic Formula axles), the Jacobian's standard errors, which count every
//! sample as independent, are a third to a fifth of it; the reported ones
//! (the block sandwich) are of its size.

use super::refit::tests::{axle_model, runs, AXLES, SCALES};
use super::{fit, Polish, Problem};
use crate::diagnose::model::replay::Prepared;

#[test]
fn reported_standard_errors_are_of_the_size_of_the_jackknife_over_runs() {
    let runs = runs();
    let all = Problem::new(axle_model, runs.iter().collect(), SCALES, AXLES.to_vec());
    let full = fit(&all, &[10.0, 10.0, 1.0], None, Polish::LevenbergMarquardt);
    assert!(full.converged);
    let n = runs.len();
    let leave_one_out: Vec<Vec<f64>> = (0..n)
        .map(|held| {
            let train: Vec<&Prepared> = (0..n).filter(|&i| i != held).map(|i| &runs[i]).collect();
            let fold = Problem::new(axle_model, train, SCALES, AXLES.to_vec());
            fit(&fold, &full.params, None, Polish::LevenbergMarquardt).params
        })
        .collect();
    let reported = full.reported_std_errors();
    for i in 0..3 {
        let mean = leave_one_out.iter().map(|p| p[i]).sum::<f64>() / n as f64;
        let spread: f64 = leave_one_out.iter().map(|p| (p[i] - mean).powi(2)).sum();
        let jackknife = ((n - 1) as f64 / n as f64 * spread).sqrt();
        let what = format!(
            "parameter {i}: jackknife {jackknife:.4}, reported {:.4}, Jacobian's {:.4}",
            reported[i], full.std_errors[i]
        );
        // Five runs: the jackknife's own relative error is about 35 %.
        assert!((0.5..2.0).contains(&(reported[i] / jackknife)), "{what}");
        assert!(full.std_errors[i] < 0.45 * jackknife, "{what}");
    }
}
