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

use super::OdeSystem;
use nalgebra::{SMatrix, SVector};

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
/// Returns the last state reached. Allocates nothing.
pub fn rosenbrock_w<const N: usize, S: OdeSystem<N>>(
    sys: &mut S,
    t0: f64,
    h: f64,
    n: usize,
    x0: [f64; N],
    refresh: usize,
    mut record: impl FnMut(&mut S, usize, f64, &[f64; N]) -> bool,
) -> [f64; N] {
    let implicit = sys.implicit_states();
    let mut x = SVector::<f64, N>::from(x0);
    let mut w = SMatrix::<f64, N, N>::zeros();
    // (I − hγW)⁻¹: formed once per Jacobian, each stage is then a product
    // (a few dozen multiply-adds, where the LU's two triangular solves per
    // stage took a quarter of a replay).
    let mut inverse = SMatrix::<f64, N, N>::identity();
    for i in 0..=n {
        let t = t0 + i as f64 * h;
        sys.w_stage(i, 0);
        let f0 = SVector::<f64, N>::from(sys.derivatives(t, &x.into()));
        if !record(sys, i, t, &x.into()) || i == n {
            break;
        }
        if i % refresh.max(1) == 0 {
            sys.w_stage(i, W_PROBE);
            // The quotients' base is a probe too: a system whose probes
            // differ from its stages (the vehicle's freeze the wheel loads
            // that its stages solve for) differences like with like.
            let base = SVector::<f64, N>::from(sys.derivatives(t, &x.into()));
            for j in 0..N {
                if !implicit[j] {
                    continue;
                }
                // The states are angles and rates of order 0.01–1: a fixed
                // relative step well above the load solve's tolerance.
                let d = 1e-7 * x[j].abs().max(1.0);
                let mut xp = x;
                xp[j] += d;
                let fp = SVector::<f64, N>::from(sys.derivatives(t, &xp.into()));
                w.set_column(j, &((fp - base) / d));
            }
            inverse = (SMatrix::<f64, N, N>::identity() - w * (h * W_GAMMA))
                .try_inverse()
                .unwrap_or_else(|| SMatrix::<f64, N, N>::repeat(f64::NAN));
        }
        // ∂f/∂t over the step's first part: without it the stiff modes,
        // which follow their inputs quasi-statically, lag them by a share of
        // the step.
        // (Against the stage: a mismatch of the load solve's tolerance over
        // most of a step is negligible.)
        sys.w_stage(i, W_TIME_PROBE);
        let dt = W_NODES[1] * h;
        let ft = (SVector::<f64, N>::from(sys.derivatives(t + dt, &x.into())) - f0) / dt;
        let mut k = [SVector::<f64, N>::zeros(); 4];
        for s in 0..4 {
            let f = if s == 0 {
                f0
            } else {
                sys.w_stage(i, s);
                let mut xs = x;
                for (j, kj) in k.iter().enumerate().take(s) {
                    xs += kj * W_ALPHA[s][j];
                }
                SVector::<f64, N>::from(sys.derivatives(t + W_NODES[s] * h, &xs.into()))
            };
            let mut g = SVector::<f64, N>::zeros();
            for (j, kj) in k.iter().enumerate().take(s) {
                g += kj * W_GAMMAS[s][j];
            }
            k[s] = inverse * ((f + w * g) * h + ft * (W_GAMMA_SUMS[s] * h * h));
        }
        for (kj, b) in k.iter().zip(W_B) {
            x += kj * b;
        }
    }
    x.into()
}
