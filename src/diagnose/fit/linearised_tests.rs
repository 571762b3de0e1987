//! The optimum's linearisation read from the polish's last Jacobian
//! ([`BoundedLm::minimize_linearised`]) where that Jacobian was taken at
//! the optimum: it is the one differenced afresh there, to the bit, and
//! the fit spends no replays on differencing it again.

use super::refit::tests::{axle_model, runs, AXLES, SCALES};
use super::{fit, linearise, Polish, Problem, FIT_ITERATIONS, FIT_TOLERANCE};
use crate::optim::bounded::{BoundedLm, Jacobians};

#[test]
fn the_linearisation_reads_the_polishs_last_jacobian_as_if_differenced_afresh() {
    let runs = runs();
    let problem = Problem::new(axle_model, runs.iter().collect(), SCALES, AXLES.to_vec());
    let start = [10.0, 10.0, 1.0];
    let (lm, last) = BoundedLm {
        iterations: FIT_ITERATIONS,
        tolerance: FIT_TOLERANCE,
        jacobians: Jacobians::Secant,
    }
    .minimize_linearised(&problem, &start, &problem.bounds);
    assert!(lm.converged);
    let last = last.expect("the polish stopped on a Jacobian of its optimum");
    let afresh = linearise(&problem, &lm.params);
    assert_eq!(last, afresh.jacobian);
    // The fit is that polish, then the optimum's residuals (kept: no
    // integration) and the count of its outcome; no Jacobian's 3 replays.
    let f = fit(&problem, &start, None, Polish::LevenbergMarquardt);
    assert_eq!(f.params, lm.params);
    assert_eq!(f.evaluations, lm.evaluations + 2);
    let linear = f.linear.as_ref().unwrap();
    assert_eq!(
        (&linear.residuals, &linear.jacobian),
        (&afresh.residuals, &afresh.jacobian)
    );
}
