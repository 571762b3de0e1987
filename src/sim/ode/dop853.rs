//! Dormand & Prince's 8(5,3) pair (DOP853) with its seventh-order
//! continuous extension, as [`super::adaptive`] steps it: twelve stages a
//! step (the derivative at its end reused as the next step's first), an
//! error estimate of order 7 built from a fifth- and a third-order one, and
//! three more stages on an accepted step for the dense output.
//!
//! Source: Hairer, Nørsett & Wanner, *Solving Ordinary Differential
//! Equations I* (2nd ed., 1993), §II.10, and Hairer's `dop853.f`: the
//! error norm `|h|·E5²/√(N·(E5² + 0.01·E3²))` (E5, E3 the weighted sums of
//! squares of the fifth- and third-order estimates, weights
//! `atol + rtol·max(|x_old|, |x_new|)`), the step-size control's defaults
//! (safety 0.9, exponent 1/8, no PI term) and the dense output `contd8`;
//! the step within [h/5, 10h] as SciPy's DOP853 and our 5(4) pair. Coefficients in `dop853/coefficients.rs`.
//!
//! Why a second pair: at a tight tolerance (rtol 1e-10) an eighth-order
//! step is about four times as long as a fifth-order one, so a 10 s step
//! steer takes about half the right-hand sides of Dormand–Prince 5(4),
//! its dense output's three extra stages included. Units: the system's.

mod coefficients;

use super::DOP853_FIRST_STAGE as FIRST;
use super::{adaptive, DenseSolution, Embedded, OdeSystem, Segment, Tolerances};
use coefficients::{A, BHH, C, D, E5};

/// Integrates `sys` from `x0` at `t_start` to `t_end` with DOP853,
/// restarting at every breakpoint inside the interval (sorted or not), and
/// returns the dense solution (seventh order between the steps).
pub fn dop853<const N: usize, S: OdeSystem<N>>(
    sys: &mut S,
    t_start: f64,
    t_end: f64,
    x0: [f64; N],
    breakpoints: &[f64],
    tol: &Tolerances,
) -> DenseSolution<N> {
    adaptive::<N, S, Dop853>(sys, t_start, t_end, x0, breakpoints, tol)
}

/// The 8(5,3) pair as [`adaptive`] steps it.
pub(super) struct Dop853;

/// `x + h·Σ a_j k_j` over one row of `(j, a_j)`.
#[inline]
fn combine<const N: usize>(
    x: &[f64; N],
    h: f64,
    ks: &[[f64; N]],
    row: &[(usize, f64)],
) -> [f64; N] {
    std::array::from_fn(|i| {
        let mut s = 0.0;
        for &(j, a) in row {
            s += a * ks[j][i];
        }
        x[i] + h * s
    })
}

impl<const N: usize> Embedded<N> for Dop853 {
    /// The twelve stages and the derivative at the step's end.
    type Stages = [[f64; N]; 13];
    const FIRST_STAGE: usize = FIRST;
    const STEP_EVALUATIONS: usize = 12;
    const EXPONENT: f64 = 1.0 / 8.0;
    const BETA: f64 = 0.0;
    // SciPy's bounds (`scipy/integrate/_ivp/rk.py`: a step grows at most
    // tenfold, shrinks at most fivefold), as the 5(4) pair's; Hairer's
    // `dop853.f` has 6 and 3. The step steer's settling tail grows faster.
    const FAC_MIN: f64 = 0.1;
    const FAC_MAX: f64 = 5.0;
    const AT_REST_WHOLE_SPAN: bool = true;

    #[inline]
    fn step<S: OdeSystem<N>>(
        sys: &mut S,
        t: f64,
        x: &[f64; N],
        h: f64,
        k1: [f64; N],
        t_right: f64,
    ) -> (Self::Stages, [f64; N]) {
        let mut ks = [[0.0; N]; 13];
        ks[0] = k1;
        for s in 1..12 {
            let xs = combine(x, h, &ks[..s], A[s]);
            // Stage 11 sits at the step's end (c = 1).
            let ts = if C[s] == 1.0 { t_right } else { t + C[s] * h };
            sys.dopri5_stage(FIRST + s);
            ks[s] = sys.derivatives(ts, &xs);
        }
        // Row 12 of A is the eighth-order weights b.
        let x_new = combine(x, h, &ks[..12], A[12]);
        sys.dopri5_stage(FIRST + 12);
        ks[12] = sys.derivatives(t_right, &x_new);
        (ks, x_new)
    }

    #[inline]
    fn next_first(stages: &Self::Stages) -> [f64; N] {
        stages[12]
    }

    #[inline]
    fn error(h: f64, ks: &Self::Stages, x: &[f64; N], x_new: &[f64; N], tol: &Tolerances) -> f64 {
        let sum = |row: &[(usize, f64)], i: usize| row.iter().map(|&(j, a)| a * ks[j][i]).sum();
        let (mut e5, mut e3) = (0.0, 0.0);
        for i in 0..N {
            let scale = tol.atol + tol.rtol * x[i].abs().max(x_new[i].abs());
            let err5: f64 = sum(&E5, i);
            let err3: f64 = sum(A[12], i) - sum(&BHH, i);
            e5 += (err5 / scale).powi(2);
            e3 += (err3 / scale).powi(2);
        }
        if e5 == 0.0 && e3 == 0.0 {
            return 0.0;
        }
        h.abs() * e5 / ((e5 + 0.01 * e3) * N as f64).sqrt()
    }

    /// Hairer's `contd8`: three more stages (at 0.1, 0.2 and 7/9 of the
    /// step), then the coefficients of the seventh-order polynomial.
    #[inline]
    fn segment<S: OdeSystem<N>>(
        sys: &mut S,
        t: f64,
        t_new: f64,
        h: f64,
        x: &[f64; N],
        x_new: &[f64; N],
        ks: &Self::Stages,
    ) -> (Segment<N>, usize) {
        let mut all = [[0.0; N]; 16];
        all[..13].copy_from_slice(ks);
        for s in 13..16 {
            let xs = combine(x, h, &all[..s], A[s]);
            sys.dopri5_stage(FIRST + s);
            all[s] = sys.derivatives(t + C[s] * h, &xs);
        }
        let (f0, f1) = (&all[0], &all[12]);
        let dx: [f64; N] = std::array::from_fn(|i| x_new[i] - x[i]);
        let d = |row: &[(usize, f64)]| -> [f64; N] {
            std::array::from_fn(|i| h * row.iter().map(|&(j, a)| a * all[j][i]).sum::<f64>())
        };
        let r = [
            *x,
            dx,
            std::array::from_fn(|i| h * f0[i] - dx[i]),
            std::array::from_fn(|i| 2.0 * dx[i] - h * (f1[i] + f0[i])),
            d(D[0]),
            d(D[1]),
            d(D[2]),
            d(D[3]),
        ];
        let segment = Segment {
            t0: t,
            h: t_new - t,
            r,
        };
        (segment, 3)
    }
}

#[cfg(test)]
mod tests;
