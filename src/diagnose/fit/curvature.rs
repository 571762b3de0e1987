//! The second derivatives of a fit's residuals at its optimum, by forward
//! second differences: the curvature columns of a
//! [`Linearisation`](super::Linearisation) that the cross-validation's fold
//! refits read where their Gauss–Newton pass does not finish
//! (`refit`). Residuals are dimensionless (over channel scales), the
//! derivatives per unit of each parameter (SI, rad).

use crate::diagnose::fit::problem::Problem;
use crate::diagnose::model::Augmented;
use crate::optim::local::Residuals;
use nalgebra::DMatrix;

/// Step of the second differences, as a share of each parameter's box:
/// their truncation error is first order in it, and the replays' own
/// rounding (the load-transfer loop's 1e-9) divided by its square stays
/// three orders below the curvature of a residual over its box.
const CURVATURE_STEP: f64 = 1e-3;

/// Second derivatives of the residuals at `p` by forward second
/// differences, stepping into the box: `(r(p+2h_a) − 2r(p+h_a) + r(p))/h_a²`
/// and `(r(p+h_a+h_b) − r(p+h_a) − r(p+h_b) + r(p))/(h_a·h_b)`. The replays
/// are independent: they run in parallel. The columns of a parameter
/// marked in `skip` (missing: not marked) stay zero, as a pinned one's.
pub(super) fn curvature<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    p: &[f64],
    r0: &[f64],
    skip: &[bool],
) -> DMatrix<f64> {
    use rayon::prelude::*;
    let n = p.len();
    let h: Vec<f64> = (0..n)
        .map(|k| {
            let (lo, hi) = problem.bounds[k];
            let h = CURVATURE_STEP * (hi - lo);
            // A parameter pinned (a box of no width) has no curvature:
            // its columns stay zero below; nor has one skipped.
            if h == 0.0 || skip.get(k).copied().unwrap_or(false) {
                return 0.0;
            }
            if p[k] + 2.0 * h > hi {
                -h
            } else {
                h
            }
        })
        .collect();
    let shifted = |moves: &[(usize, f64)]| {
        let mut q = p.to_vec();
        for &(k, m) in moves {
            q[k] += m * h[k];
        }
        let mut r = vec![0.0; r0.len()];
        problem.residuals(&q, &mut r);
        r
    };
    let singles: Vec<(Vec<f64>, Vec<f64>)> = (0..n)
        .into_par_iter()
        .map(|k| {
            if h[k] == 0.0 {
                (Vec::new(), Vec::new())
            } else {
                (shifted(&[(k, 1.0)]), shifted(&[(k, 2.0)]))
            }
        })
        .collect();
    let pairs: Vec<(usize, usize)> = (0..n).flat_map(|a| (a..n).map(move |b| (a, b))).collect();
    let columns: Vec<Vec<f64>> = pairs
        .par_iter()
        .map(|&(a, b)| {
            if h[a] == 0.0 || h[b] == 0.0 {
                vec![0.0; r0.len()]
            } else if a == b {
                let (one, two) = &singles[a];
                let h2 = h[a] * h[a];
                (0..r0.len())
                    .map(|i| (two[i] - 2.0 * one[i] + r0[i]) / h2)
                    .collect()
            } else {
                let both = shifted(&[(a, 1.0), (b, 1.0)]);
                let (ra, rb) = (&singles[a].0, &singles[b].0);
                let hab = h[a] * h[b];
                (0..r0.len())
                    .map(|i| (both[i] - ra[i] - rb[i] + r0[i]) / hab)
                    .collect()
            }
        })
        .collect();
    DMatrix::from_fn(r0.len(), pairs.len(), |i, c| columns[c][i])
}
