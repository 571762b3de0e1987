//! Dormand & Prince's 5(4) pair with its fourth-order continuous
//! extension: the coefficients, one step's stages, its error estimate and
//! its dense-output segment, as [`super::adaptive`] steps them.
//!
//! Dormand & Prince (1980), "A family of embedded Runge–Kutta formulae",
//! J. Comp. Appl. Math. 6; the dense output as in Hairer, Nørsett & Wanner,
//! *Solving Ordinary Differential Equations I* (2nd ed., 1993), §II.6. The
//! step-size control (PI, β = 0.04, safety 0.9, step within [h/5, 10h]) is
//! Hairer's `dopri5.f` default. Units: the system's.

use super::{adaptive, rms_norm, DenseSolution, Embedded, OdeSystem, Segment, Tolerances};

/// Integrates `sys` from `x0` at `t_start` to `t_end` with Dormand–Prince
/// 5(4), restarting at every breakpoint inside the interval (sorted or not),
/// and returns the dense solution.
pub fn dopri5<const N: usize, S: OdeSystem<N>>(
    sys: &mut S,
    t_start: f64,
    t_end: f64,
    x0: [f64; N],
    breakpoints: &[f64],
    tol: &Tolerances,
) -> DenseSolution<N> {
    adaptive::<N, S, Dopri5>(sys, t_start, t_end, x0, breakpoints, tol)
}

/// The 5(4) pair as [`adaptive`] steps it.
pub(super) struct Dopri5;

impl<const N: usize> Embedded<N> for Dopri5 {
    type Stages = [[f64; N]; 7];
    const FIRST_STAGE: usize = 0;
    const STEP_EVALUATIONS: usize = 6;
    const EXPONENT: f64 = 0.2;
    const BETA: f64 = 0.04;
    const FAC_MIN: f64 = 0.1;
    const FAC_MAX: f64 = 5.0;
    // Hairer's start: the scenarios' counts of steps stay as they were.
    const AT_REST_WHOLE_SPAN: bool = false;

    #[inline]
    fn step<S: OdeSystem<N>>(
        sys: &mut S,
        t: f64,
        x: &[f64; N],
        h: f64,
        k1: [f64; N],
        t_right: f64,
    ) -> (Self::Stages, [f64; N]) {
        dopri5_stages(sys, t, x, h, k1, t_right)
    }
    #[inline]
    fn next_first(stages: &Self::Stages) -> [f64; N] {
        stages[6]
    }
    #[inline]
    fn error(
        h: f64,
        stages: &Self::Stages,
        x: &[f64; N],
        x_new: &[f64; N],
        tol: &Tolerances,
    ) -> f64 {
        step_error(h, stages, x, x_new, tol)
    }
    #[inline]
    fn segment<S: OdeSystem<N>>(
        _sys: &mut S,
        t: f64,
        t_new: f64,
        h: f64,
        x: &[f64; N],
        x_new: &[f64; N],
        stages: &Self::Stages,
    ) -> (Segment<N>, usize) {
        (dense_segment(t, t_new, h, x, x_new, stages), 0)
    }
}

// Dormand–Prince 5(4) coefficients (Dormand & Prince 1980).
const C: [f64; 7] = [0.0, 0.2, 0.3, 0.8, 8.0 / 9.0, 1.0, 1.0];
const A2: [f64; 1] = [0.2];
const A3: [f64; 2] = [3.0 / 40.0, 9.0 / 40.0];
const A4: [f64; 3] = [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0];
const A5: [f64; 4] = [
    19372.0 / 6561.0,
    -25360.0 / 2187.0,
    64448.0 / 6561.0,
    -212.0 / 729.0,
];
const A6: [f64; 5] = [
    9017.0 / 3168.0,
    -355.0 / 33.0,
    46732.0 / 5247.0,
    49.0 / 176.0,
    -5103.0 / 18656.0,
];
/// Fifth-order weights (also the seventh stage's row: first same as last).
const B: [f64; 6] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
];
/// Fifth- minus fourth-order weights, stages 1..7.
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];
/// Dense-output weights, stages 1..7 (Hairer et al. 1993, §II.6).
const D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

fn combine<const N: usize>(x: &[f64; N], h: f64, ks: &[[f64; N]], w: &[f64]) -> [f64; N] {
    std::array::from_fn(|i| {
        let mut s = 0.0;
        for (k, wj) in ks.iter().zip(w) {
            s += wj * k[i];
        }
        x[i] + h * s
    })
}

/// One Dormand–Prince step from `(t, x)` with first stage `k1`: the seven
/// stages and the fifth-order solution at `t + h`, the last two stages
/// evaluated at `t_right` (the input's left limit at a breakpoint). Inlined, on
/// fixed arrays, so the hot loop is what it was.
#[inline]
fn dopri5_stages<const N: usize, S: OdeSystem<N>>(
    sys: &mut S,
    t: f64,
    x: &[f64; N],
    h: f64,
    k1: [f64; N],
    t_right: f64,
) -> ([[f64; N]; 7], [f64; N]) {
    let mut stage = |j: usize, t: f64, x: &[f64; N]| {
        sys.dopri5_stage(j);
        sys.derivatives(t, x)
    };
    let k2 = stage(1, t + C[1] * h, &combine(x, h, &[k1], &A2));
    let k3 = stage(2, t + C[2] * h, &combine(x, h, &[k1, k2], &A3));
    let k4 = stage(3, t + C[3] * h, &combine(x, h, &[k1, k2, k3], &A4));
    let k5 = stage(4, t + C[4] * h, &combine(x, h, &[k1, k2, k3, k4], &A5));
    let k6 = stage(5, t_right, &combine(x, h, &[k1, k2, k3, k4, k5], &A6));
    let x_new = combine(x, h, &[k1, k2, k3, k4, k5, k6], &B);
    let k7 = stage(6, t_right, &x_new);
    ([k1, k2, k3, k4, k5, k6, k7], x_new)
}

/// The scaled RMS norm of the step's embedded error estimate (fifth minus
/// fourth order).
#[inline]
fn step_error<const N: usize>(
    h: f64,
    ks: &[[f64; N]; 7],
    x: &[f64; N],
    x_new: &[f64; N],
    tol: &Tolerances,
) -> f64 {
    let e: [f64; N] =
        std::array::from_fn(|i| h * ks.iter().zip(&E).map(|(k, w)| w * k[i]).sum::<f64>());
    rms_norm(&e, x, x_new, tol)
}

/// The dense-output segment of an accepted step from `(t, x)` to
/// `(t_new, x_new)` with stages `ks` (Hairer's continuous extension of
/// order 4).
#[inline]
fn dense_segment<const N: usize>(
    t: f64,
    t_new: f64,
    h: f64,
    x: &[f64; N],
    x_new: &[f64; N],
    ks: &[[f64; N]; 7],
) -> Segment<N> {
    let (k1, k7) = (&ks[0], &ks[6]);
    let dx: [f64; N] = std::array::from_fn(|i| x_new[i] - x[i]);
    let bspl: [f64; N] = std::array::from_fn(|i| h * k1[i] - dx[i]);
    Segment {
        t0: t,
        h: t_new - t,
        r: [
            *x,
            dx,
            bspl,
            std::array::from_fn(|i| dx[i] - h * k7[i] - bspl[i]),
            std::array::from_fn(|i| h * ks.iter().zip(&D).map(|(k, w)| w * k[i]).sum::<f64>()),
            [0.0; N],
            [0.0; N],
            [0.0; N],
        ],
    }
}
