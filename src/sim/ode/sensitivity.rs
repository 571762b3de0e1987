//! Forward sensitivities of the fixed-step RK4 ([`super::rk4`]) by dual
//! numbers (the `num-dual` crate): the same grid, the same stages and the
//! same combination of them, every state carried as a dual number whose
//! derivative part is the state's derivative with respect to the variables
//! seeded (a model's parameters, the initial state). The arithmetic being
//! RK4's own, the derivative is that of the discrete solution — not of the
//! exact flow of the ODE — to rounding, which is what a least-squares fit
//! of a replay wants: the variational equations `S' = f_x·S + f_p`
//! integrated by the same stages, without writing `f_x` or `f_p` by hand.
//!
//! A fixed-size dual (`DualSVec64<N>`) allocates nothing: one replay with
//! the derivatives costs a constant factor of a plain one, not a replay per
//! variable.

use num_dual::DualNum;

/// An ODE system whose right-hand side is written in a dual scalar `T`.
pub trait DualSystem<T, const N: usize> {
    /// The derivatives at time `t` and state `x`.
    fn derivatives(&mut self, t: f64, x: &[T; N]) -> [T; N];

    /// Called before each evaluation with the grid step and the stage, as
    /// [`super::OdeSystem::rk4_stage`] is.
    fn rk4_stage(&mut self, _step: usize, _stage: usize) {}

    /// Called before each evaluation of [`super::rosenbrock_w_dual`], as
    /// [`super::OdeSystem::w_stage`] is.
    fn w_stage(&mut self, _step: usize, _stage: usize) {}

    /// The states whose Jacobian columns ROS34PW2 differences, as
    /// [`super::OdeSystem::implicit_states`].
    fn implicit_states(&self) -> [bool; N] {
        [true; N]
    }
}

/// RK4 in the scalar `T` ([`super::rk4`] is its plain-number case): the grid `t0 + i·h`, `i = 0..=n`, from
/// `x0`; `record(sys, i, t, x)` at every grid point after its first stage
/// (false stops). Returns the last state reached.
pub fn rk4_dual<T, const N: usize, S>(
    sys: &mut S,
    t0: f64,
    h: f64,
    n: usize,
    x0: [T; N],
    mut record: impl FnMut(&mut S, usize, f64, &[T; N]) -> bool,
) -> [T; N]
where
    T: DualNum<f64> + Copy,
    S: DualSystem<T, N>,
{
    // `s·k` as RK4 writes it (multiplication commutes in floating point).
    let add =
        |x: &[T; N], k: &[T; N], s: f64| -> [T; N] { std::array::from_fn(|j| x[j] + k[j] * s) };
    let mut x = x0;
    for i in 0..=n {
        let t = t0 + i as f64 * h;
        sys.rk4_stage(i, 0);
        let k1 = sys.derivatives(t, &x);
        if !record(sys, i, t, &x) || i == n {
            break;
        }
        sys.rk4_stage(i, 1);
        let k2 = sys.derivatives(t + 0.5 * h, &add(&x, &k1, 0.5 * h));
        sys.rk4_stage(i, 2);
        let k3 = sys.derivatives(t + 0.5 * h, &add(&x, &k2, 0.5 * h));
        sys.rk4_stage(i, 3);
        let k4 = sys.derivatives(t + h, &add(&x, &k3, h));
        for j in 0..N {
            x[j] += (k1[j] + k2[j] * 2.0 + k3[j] * 2.0 + k4[j]) * (h / 6.0);
        }
    }
    x
}

#[cfg(test)]
mod tests;
