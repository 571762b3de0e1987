//! The Levenberg–Marquardt of Wei et al. (2010), as the paper describes it
//! (the `--start paper` scheme).

use crate::optim::local::{LocalResult, Residuals};

/// Wei et al. (2010)'s Levenberg–Marquardt: `(JᵀJ + μI)Δ = −Jᵀe`, μ0 = 0.1,
/// μ ← μ/β after an accepted step, μ ← β·μ after a rejected one (β = 5);
/// stops when `E = Σe²` falls below `eps`, stops falling (relative change
/// below 1e-12 over an accepted step), μ exceeds 1e16, or after `max_iter`
/// Jacobians (the problem's own, [`Residuals::jacobian`]).
pub fn paper_lm(problem: &dyn Residuals, p0: &[f64], eps: f64, max_iter: usize) -> LocalResult {
    let (m, n) = (problem.count(), p0.len());
    let mut x = p0.to_vec();
    let mut r = vec![0.0; m];
    problem.residuals(&x, &mut r);
    let e_of = |r: &[f64]| r.iter().map(|e| e * e).sum::<f64>();
    let mut e = e_of(&r);
    let (mut mu, beta) = (0.1, 5.0);
    let mut evaluations = 1;
    let mut converged = false;
    let mut trial = vec![0.0; m];
    'outer: for _ in 0..max_iter {
        if e < eps {
            converged = true;
            break;
        }
        let j = problem.jacobian(&x, &r, &super::problem::unbounded(n));
        evaluations += problem.jacobian_evaluations(n);
        let jtj = j.transpose() * &j;
        let g = j.transpose() * nalgebra::DVector::from_column_slice(&r);
        loop {
            let a = &jtj + nalgebra::DMatrix::identity(n, n) * mu;
            let step = a.cholesky().map(|ch| ch.solve(&(-&g)));
            let Some(dx) = step else {
                mu *= beta;
                if mu > 1e16 {
                    break 'outer;
                }
                continue;
            };
            let xt: Vec<f64> = x.iter().zip(dx.iter()).map(|(a, b)| a + b).collect();
            problem.residuals(&xt, &mut trial);
            evaluations += 1;
            let et = e_of(&trial);
            if et.is_finite() && et < e {
                let small = (e - et) <= 1e-12 * e;
                x = xt;
                std::mem::swap(&mut r, &mut trial);
                e = et;
                mu /= beta;
                if small {
                    converged = true;
                    break 'outer;
                }
                break;
            }
            mu *= beta;
            if mu > 1e16 {
                converged = true;
                break 'outer;
            }
        }
    }
    LocalResult {
        cost: 0.5 * e,
        params: x,
        evaluations,
        converged,
    }
}
