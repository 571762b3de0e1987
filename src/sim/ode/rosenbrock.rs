//! The fixed-step linearly implicit Rosenbrock–W method ROS34PW2 for stiff
//! systems `ẋ = f(t, x)`: Rang & Angermann (2005), "New Rosenbrock
//! W-methods of order 3 for partial differential algebraic equations of
//! index 1", BIT Numer. Math. 45, in the form of Hairer & Wanner, *Solving
//! Ordinary Differential Equations II* (2nd ed., 1996), §IV.7. Four stages
//! and one inverse of `I − hγW` per Jacobian, L-stable and stiffly
//! accurate; order 3 whatever the matrix `W` standing in for the Jacobian
//! (here forward differences of the system), with `∂f/∂t` by a forward
//! difference over the first stage's time. Units are whatever the system
//! uses.

use super::sensitivity::DualSystem;
use super::{OdeSystem, Plain};
use nalgebra::{ComplexField, SMatrix, SVector};
use num_dual::DualNum;

// ROS34PW2 (Rang & Angermann 2005): γ, α_ij, γ_ij, b_i, with the
// published digits (more than an f64 holds, kept so they can be checked).
#[allow(clippy::excessive_precision)]
const W_GAMMA: f64 = 0.435_866_521_508_459;
#[allow(clippy::excessive_precision)]
const W_ALPHA: [[f64; 3]; 4] = [
    [0.0, 0.0, 0.0],
    [0.871_733_043_016_918_01, 0.0, 0.0],
    [0.844_570_600_153_694_23, -0.112_990_642_364_841_85, 0.0],
    [0.0, 0.0, 1.0],
];
#[allow(clippy::excessive_precision)]
const W_GAMMAS: [[f64; 3]; 4] = [
    [0.0, 0.0, 0.0],
    [-0.871_733_043_016_918_01, 0.0, 0.0],
    [-0.903_380_570_130_440_82, 0.054_180_672_388_095_326, 0.0],
    [
        0.242_123_807_060_953_46,
        -1.223_250_583_904_514_7,
        0.545_260_255_335_102_14,
    ],
];
#[allow(clippy::excessive_precision)]
const W_B: [f64; 4] = [
    0.242_123_807_060_953_46,
    -1.223_250_583_904_514_7,
    1.545_260_255_335_102_0,
    0.435_866_521_508_459,
];

/// `γ_i = Σ_j γ_ij` with the diagonal `γ`: the weights of `h²·∂f/∂t`.
const W_GAMMA_SUMS: [f64; 4] = [
    W_GAMMA,
    W_GAMMA + W_GAMMAS[1][0],
    W_GAMMA + W_GAMMAS[2][0] + W_GAMMAS[2][1],
    W_GAMMA + W_GAMMAS[3][0] + W_GAMMAS[3][1] + W_GAMMAS[3][2],
];

/// The times of ROS34PW2's four stages as fractions of the step.
pub const W_NODES: [f64; 4] = [0.0, W_ALPHA[1][0], W_ALPHA[2][0] + W_ALPHA[2][1], 1.0];

/// The stage number [`OdeSystem::w_stage`] announces for the Jacobian's
/// difference quotients.
pub const W_PROBE: usize = 4;

/// The stage number [`OdeSystem::w_stage`] announces for the evaluation
/// at the step's start state and its second stage's time, which gives
/// `∂f/∂t` by a difference quotient.
pub const W_TIME_PROBE: usize = 5;

/// The Rosenbrock–W method ROS34PW2 on the grid `t0 + i·h`, `i = 0..=n`,
/// from `x0`, with `record` called as [`super::rk4`] calls it (at every grid
/// point, right after the first stage); one more evaluation a step gives
/// `∂f/∂t`. The matrix `W` is the system's Jacobian by forward
/// differences, over the columns
/// [`OdeSystem::implicit_states`] names, at the start of every `refresh`-th
/// step; the steps between reuse it and its LU (the order stays 3; the
/// stiff modes stay damped while the Jacobian changes little over
/// `refresh` steps). A step whose `I − hγW` is singular (an unstable model
/// with an eigenvalue at `1/(hγ)`) leaves the state NaN from there on.
/// Returns the last state reached. Allocates nothing. It is
/// [`rosenbrock_w_dual`] in plain numbers.
pub fn rosenbrock_w<const N: usize, S: OdeSystem<N>>(
    sys: &mut S,
    t0: f64,
    h: f64,
    n: usize,
    x0: [f64; N],
    refresh: usize,
    mut record: impl FnMut(&mut S, usize, f64, &[f64; N]) -> bool,
) -> [f64; N] {
    rosenbrock_w_dual(&mut Plain(sys), t0, h, n, x0, refresh, |p, i, t, x| {
        record(p.0, i, t, x)
    })
}

/// [`rosenbrock_w`] in the scalar `T` of a [`DualSystem`]: in dual numbers
/// every operation — the difference quotients of `W` and `∂f/∂t`, the
/// inverse of `I − hγW`, the stages — carries its derivatives, so the
/// result's derivative is that of the discrete solution this method
/// computes, to rounding (the matrix `W` is a function of the state and the
/// parameters like any other quantity of the step).
pub fn rosenbrock_w_dual<T, const N: usize, S>(
    sys: &mut S,
    t0: f64,
    h: f64,
    n: usize,
    x0: [T; N],
    refresh: usize,
    mut record: impl FnMut(&mut S, usize, f64, &[T; N]) -> bool,
) -> [T; N]
where
    T: DualNum<f64> + Copy + ComplexField,
    S: DualSystem<T, N>,
{
    let implicit = sys.implicit_states();
    let c = |v: f64| T::from(v);
    let mut x = SVector::<T, N>::from(x0);
    let mut w = SMatrix::<T, N, N>::zeros();
    // (I − hγW)⁻¹: formed once per Jacobian, each stage is then a product
    // (a few dozen multiply-adds, where the LU's two triangular solves per
    // stage took a quarter of a replay).
    let mut inverse = SMatrix::<T, N, N>::identity();
    for i in 0..=n {
        let t = t0 + i as f64 * h;
        sys.w_stage(i, 0);
        let f0 = SVector::<T, N>::from(sys.derivatives(t, &x.into()));
        if !record(sys, i, t, &x.into()) || i == n {
            break;
        }
        if i % refresh.max(1) == 0 {
            inverse = refresh_w(sys, i, t, h, &x, &implicit, &mut w);
        }
        // ∂f/∂t over the step's first part: without it the stiff modes,
        // which follow their inputs quasi-statically, lag them by a share of
        // the step.
        // (Against the stage: a mismatch of the load solve's tolerance over
        // most of a step is negligible.)
        sys.w_stage(i, W_TIME_PROBE);
        let dt = W_NODES[1] * h;
        let ft = (SVector::<T, N>::from(sys.derivatives(t + dt, &x.into())) - f0) / c(dt);
        let mut k = [SVector::<T, N>::zeros(); 4];
        for s in 0..4 {
            let f = if s == 0 {
                f0
            } else {
                sys.w_stage(i, s);
                let mut xs = x;
                for (j, kj) in k.iter().enumerate().take(s) {
                    xs += kj * c(W_ALPHA[s][j]);
                }
                SVector::<T, N>::from(sys.derivatives(t + W_NODES[s] * h, &xs.into()))
            };
            let mut g = SVector::<T, N>::zeros();
            for (j, kj) in k.iter().enumerate().take(s) {
                g += kj * c(W_GAMMAS[s][j]);
            }
            k[s] = inverse * ((f + w * g) * c(h) + ft * c(W_GAMMA_SUMS[s] * h * h));
        }
        for (kj, b) in k.iter().zip(W_B) {
            x += kj * c(b);
        }
    }
    x.into()
}

/// Step `i`'s refresh of `W`: forward differences at `(t, x)` in the
/// implicit states' columns (the others keep what they held), and the
/// returned (I − hγW)⁻¹ (NaN where singular). Apart from
/// [`rosenbrock_w_dual`] so that its loop reads on a screen; inlined, on
/// fixed-size matrices, so the hot loop is what it was.
#[inline]
fn refresh_w<T, const N: usize, S>(
    sys: &mut S,
    i: usize,
    t: f64,
    h: f64,
    x: &SVector<T, N>,
    implicit: &[bool; N],
    w: &mut SMatrix<T, N, N>,
) -> SMatrix<T, N, N>
where
    T: DualNum<f64> + Copy + ComplexField,
    S: DualSystem<T, N>,
{
    let c = |v: f64| T::from(v);
    sys.w_stage(i, W_PROBE);
    // The quotients' base is a probe too: a system whose probes
    // differ from its stages (the vehicle's freeze the wheel loads
    // that its stages solve for) differences like with like.
    let base = SVector::<T, N>::from(sys.derivatives(t, &(*x).into()));
    for j in 0..N {
        if !implicit[j] {
            continue;
        }
        // The states are angles and rates of order 0.01–1: a fixed
        // relative step well above the load solve's tolerance.
        let d = if x[j].re().abs() > 1.0 {
            num_traits_abs(x[j]) * 1e-7
        } else {
            c(1e-7)
        };
        let mut xp = *x;
        xp[j] += d;
        let fp = SVector::<T, N>::from(sys.derivatives(t, &xp.into()));
        w.set_column(j, &((fp - base) / d));
    }
    (SMatrix::<T, N, N>::identity() - *w * c(h * W_GAMMA))
        .try_inverse()
        .unwrap_or_else(|| SMatrix::<T, N, N>::repeat(c(f64::NAN)))
}

/// |x| of a scalar (the `Signed` absolute value every `num-dual` scalar has;
/// named apart from nalgebra's, which returns the real field).
fn num_traits_abs<T: DualNum<f64>>(x: T) -> T {
    if x.re() < 0.0 {
        -x
    } else {
        x
    }
}
