//! Integration of small ODE systems `ẋ = f(t, x)` with a state of `N`
//! reals: the error-controlled Dormand–Prince 5(4) pair with its continuous
//! (dense) output, the classical fixed-step RK4, and the fixed-step
//! linearly implicit Rosenbrock–W method ROS34PW2 for stiff systems.
//!
//! Methods:
//! - Dormand & Prince (1980), "A family of embedded Runge–Kutta formulae",
//!   J. Comp. Appl. Math. 6; step-size control (PI controller with β = 0.04,
//!   safety 0.9, growth within [0.2, 10]) and the fourth-order dense output
//!   as in Hairer, Nørsett & Wanner, *Solving Ordinary Differential
//!   Equations I* (2nd ed., 1993), §II.4–II.6. The local error is measured
//!   in the weighted RMS norm with weights `atol + rtol·max(|x_old|, |x_new|)`.
//! - ROS34PW2: Rang & Angermann (2005), "New Rosenbrock W-methods of order 3
//!   for partial differential algebraic equations of index 1", BIT Numer.
//!   Math. 45; the scheme's form as in Hairer & Wanner, *Solving Ordinary
//!   Differential Equations II* (2nd ed., 1996), §IV.7. Four stages and
//!   one inverse of `I − hγW` per Jacobian, L-stable and stiffly accurate.
//!   Being a W-method it keeps order 3 whatever the matrix `W` that stands
//!   in for the Jacobian: here forward differences of the system at the
//!   step's wheel loads, and `∂f/∂t` by a forward difference over the first
//!   stage's time (the autonomised system's time column; any approximation
//!   keeps the order). Stability against the stiff modes needs `W` only to
//!   be near the Jacobian; accuracy when a stiff mode follows its inputs
//!   needs `∂f/∂t` (without it, on a car 40 times as stiff as a sedan at a
//!   10 ms step, the fits of a diagnosis were measurably biased).
//!
//! Why not a crate: `ode_solvers` (the maintained Rust DOPRI5) records its
//! output at uniform intervals into vectors it allocates, has no output at
//! arbitrary times (measured runs are sampled irregularly), no event location
//! and no way to restart at the input's breakpoints, and has no Rosenbrock
//! method; each method is a table of published coefficients and a few dozen
//! lines of stepping logic.
//!
//! Inputs with kinks (a step steer's ramp start and end) are handled by
//! breakpoints: the solution is restarted at each, so no step straddles a
//! discontinuity of the right-hand side's derivatives. Nothing allocates per
//! step except the growth of the stored dense solution (one segment of
//! `5·N` reals per accepted step). Units are whatever the system uses.
//!
//! Layout: this file holds the system's trait, Dormand–Prince with its dense
//! output and RK4; `rosenbrock.rs` holds ROS34PW2.

mod rosenbrock;
pub mod sensitivity;

pub use rosenbrock::{rosenbrock_w, rosenbrock_w_dual, W_NODES, W_PROBE, W_TIME_PROBE};

/// An ODE system with `N` states. `&mut self` lets a system keep caches
/// (the load-transfer solve's starting point) between evaluations; the
/// result must not depend on them beyond the system's own tolerance.
pub trait OdeSystem<const N: usize> {
    /// The derivatives at time `t` and state `x`.
    fn derivatives(&mut self, t: f64, x: &[f64; N]) -> [f64; N];

    /// Called by [`rk4`] before each evaluation with the grid step `step`
    /// and the stage (0–3; stages 1 and 2 sit at the half step): a system can
    /// then read inputs sampled once per grid node and keep one
    /// load-transfer starting point per stage. The adaptive method does not
    /// call it.
    fn rk4_stage(&mut self, _step: usize, _stage: usize) {}

    /// Called by [`dopri5`] before each evaluation with its stage: 0–6 the
    /// seven of Dormand–Prince (0 a restart's first, 6 a step's end, whose
    /// value the next step reuses), [`DOPRI5_PROBE`] the starting step's
    /// probe. A system can then keep one load-transfer starting point per
    /// stage: a stage's state is off the solution by an amount of its own,
    /// about the same from one step to the next.
    fn dopri5_stage(&mut self, _stage: usize) {}

    /// Called by [`rosenbrock_w`] before each evaluation: `stage` 0–3 are
    /// the method's stages (at [`W_NODES`] of the step; stage 3 at the step's
    /// end), [`W_PROBE`] the difference quotients of the Jacobian at stage
    /// 0's time, [`W_TIME_PROBE`] the step's start state at stage 1's time.
    /// A system can read inputs sampled once per stage and keep its caches
    /// out of the probes. The other methods do not call it.
    fn w_stage(&mut self, _step: usize, _stage: usize) {}

    /// The states whose Jacobian columns [`rosenbrock_w`] differences: a
    /// state that is constant (a lag or roll state a model does not use)
    /// can be left out, its column taken as zero.
    fn implicit_states(&self) -> [bool; N] {
        [true; N]
    }
}

/// The stage [`dopri5`] tells [`OdeSystem::dopri5_stage`] for the starting
/// step's probe (after the method's seven, 0–6).
pub const DOPRI5_PROBE: usize = 7;

/// Error tolerances of the adaptive integrator.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Tolerances {
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance, in the states' units.
    pub atol: f64,
    /// Largest step, s (also bounds how coarsely events are bracketed).
    pub max_step: f64,
}

/// The defaults give every GB/T 6323 step-steer metric of the bundled
/// scenarios within 1e-6 relative of a 1e-10 reference, a tiny overshoot
/// (0.05 %, the most sensitive) included: measured 1.4e-7 at worst, where
/// rtol 1e-8 gives 3e-6 (tests/cli/scenarios.rs).
impl Default for Tolerances {
    fn default() -> Self {
        Self {
            rtol: 1e-9,
            atol: 1e-11,
            max_step: 0.05,
        }
    }
}

/// Counts of the work an integration did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, serde::Serialize)]
pub struct Stats {
    /// Accepted steps.
    pub accepted: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Right-hand-side evaluations.
    pub evaluations: usize,
    /// Whether the integration stopped short of its end, its step budget
    /// ([`step_budget`]) spent: the solution ends where it stopped.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub stalled: bool,
}

/// The steps (accepted and rejected) an integration over `span` seconds
/// may take before it is called stalled: 100,000, and 200 per largest
/// step. A smooth run takes a few per largest step; a right-hand side
/// that is not smooth (a wheel lifting off under load transfer, linear
/// tyres at a 0.5 rad step: about 6 g) drove the step towards zero and
/// the run on for ever, its dense output growing without bound (2.7 GB in
/// 12 minutes, `simulate` never ending).
pub fn step_budget(span: f64, tol: &Tolerances) -> usize {
    let per_largest = (span / tol.max_step).ceil();
    100_000 + (200.0 * per_largest.clamp(0.0, 1e9)) as usize
}

/// One accepted step's continuous extension: the state at `t0 + θ·h` is
/// `r0 + θ(r1 + (1−θ)(r2 + θ(r3 + (1−θ) r4)))`, fourth order in θ ∈ [0, 1].
#[derive(Debug, Clone, Copy, PartialEq)]
struct Segment<const N: usize> {
    t0: f64,
    h: f64,
    r: [[f64; N]; 5],
}

impl<const N: usize> Segment<N> {
    fn at(&self, t: f64) -> [f64; N] {
        let th = ((t - self.t0) / self.h).clamp(0.0, 1.0);
        let th1 = 1.0 - th;
        let r = &self.r;
        std::array::from_fn(|i| {
            r[0][i] + th * (r[1][i] + th1 * (r[2][i] + th * (r[3][i] + th1 * r[4][i])))
        })
    }
}

/// The continuous solution of an adaptive integration over [t_start, t_end].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DenseSolution<const N: usize> {
    segments: Vec<Segment<N>>,
    /// Work done.
    pub stats: Stats,
}

impl<const N: usize> DenseSolution<N> {
    /// Start of the solution, s.
    pub fn start(&self) -> f64 {
        self.segments.first().map_or(f64::NAN, |s| s.t0)
    }
    /// End of the solution, s.
    pub fn end(&self) -> f64 {
        self.segments.last().map_or(f64::NAN, |s| s.t0 + s.h)
    }
    /// The solution with its times moved by `dt`, s (one integrated from
    /// a run's start, told in its own time).
    pub(crate) fn shifted(mut self, dt: f64) -> Self {
        self.segments.iter_mut().for_each(|s| s.t0 += dt);
        self
    }
    /// Accepted step boundaries (start, every step end).
    pub(crate) fn step_times(&self) -> impl Iterator<Item = f64> + '_ {
        self.segments
            .first()
            .map(|s| s.t0)
            .into_iter()
            .chain(self.segments.iter().map(|s| s.t0 + s.h))
    }
    fn segment(&self, t: f64) -> &Segment<N> {
        let k = self.segments.partition_point(|s| s.t0 + s.h < t);
        &self.segments[k.min(self.segments.len() - 1)]
    }
    /// The state at `t` (clamped to the solution's interval).
    pub fn state(&self, t: f64) -> [f64; N] {
        self.segment(t).at(t)
    }
    /// States at sorted times `ts`, written into `out` (one walk over the
    /// segments, no search per time).
    pub fn states_into(&self, ts: &[f64], out: &mut Vec<[f64; N]>) {
        out.clear();
        out.reserve(ts.len());
        let mut k = 0;
        for &t in ts {
            while k + 1 < self.segments.len() && self.segments[k].t0 + self.segments[k].h < t {
                k += 1;
            }
            out.push(self.segments[k].at(t));
        }
    }
    /// The first time after `after` at which `g(t, x(t))` changes sign
    /// (from the value it has at `after`), located by bisection on the dense
    /// output to `tol` seconds; `g` is sampled at least at every step end and
    /// `probe` apart, so a crossing and recrossing inside one probe interval
    /// can be missed.
    pub fn first_crossing(
        &self,
        after: f64,
        probe: f64,
        tol: f64,
        mut g: impl FnMut(f64, &[f64; N]) -> f64,
    ) -> Option<f64> {
        let end = self.end();
        let mut t_a = after.max(self.start());
        let mut g_a = g(t_a, &self.state(t_a));
        while t_a < end {
            let step_end = self.segment(t_a).t0 + self.segment(t_a).h;
            let t_b = if step_end > t_a + 1e-15 {
                step_end
            } else {
                end
            }
            .min(t_a + probe)
            .min(end);
            let g_b = g(t_b, &self.state(t_b));
            if g_a == 0.0 {
                return Some(t_a);
            }
            if g_a.signum() != g_b.signum() {
                let (mut lo, mut hi, g_lo) = (t_a, t_b, g_a);
                while hi - lo > tol {
                    let mid = 0.5 * (lo + hi);
                    let g_mid = g(mid, &self.state(mid));
                    if g_mid.signum() == g_lo.signum() && g_mid != 0.0 {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                return Some(0.5 * (lo + hi));
            }
            (t_a, g_a) = (t_b, g_b);
        }
        None
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

fn rms_norm<const N: usize>(e: &[f64; N], x0: &[f64; N], x1: &[f64; N], tol: &Tolerances) -> f64 {
    let mut s = 0.0;
    for i in 0..N {
        let w = tol.atol + tol.rtol * x0[i].abs().max(x1[i].abs());
        s += (e[i] / w).powi(2);
    }
    (s / N as f64).sqrt()
}

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
    let mut sol = DenseSolution {
        segments: Vec::with_capacity(64),
        stats: Stats::default(),
    };
    let cuts = stops(breakpoints, t_start, t_end);
    let (mut t, mut x) = (t_start, x0);
    let mut h = 0.0;
    let budget = step_budget(t_end - t_start, tol);
    for &stop in &cuts {
        if stop <= t {
            continue;
        }
        sys.dopri5_stage(0);
        let mut k1 = sys.derivatives(t, &x);
        sol.stats.evaluations += 1;
        if h == 0.0 {
            h = initial_step(sys, t, &x, &k1, stop - t, tol, &mut sol.stats);
        }
        let mut err_old: f64 = 1e-4;
        let mut last_rejected = false;
        while t < stop {
            if sol.stats.accepted + sol.stats.rejected >= budget {
                sol.stats.stalled = true;
                return sol;
            }
            h = h.min(tol.max_step);
            // Land exactly on the stop; avoid a sliver step before it.
            let remaining = stop - t;
            let last = h >= remaining * (1.0 - 1e-12) || remaining - h < 1e-3 * h;
            if last {
                h = remaining;
            }
            // A step that ends on a breakpoint sees the input's left limit
            // there (an ideal step steer acts from the next step on).
            let t_new = if last { stop } else { t + h };
            let t_right = if last { stop.next_down() } else { t_new };
            let (ks, x_new) = dopri5_stages(sys, t, &x, h, k1, t_right);
            let k7 = ks[6];
            sol.stats.evaluations += 6;
            let err = step_error(h, &ks, &x, &x_new, tol);
            if !err.is_finite() {
                h *= 0.1;
                sol.stats.rejected += 1;
                last_rejected = true;
                continue;
            }
            // PI step-size control.
            let fac11 = err.powf(0.2 - 0.04 * 0.75);
            if err <= 1.0 {
                let fac = (fac11 / err_old.powf(0.04) / 0.9).clamp(0.1, 5.0);
                let mut h_new = h / fac;
                if last_rejected {
                    h_new = h_new.min(h);
                }
                err_old = err.max(1e-4);
                sol.segments
                    .push(dense_segment(t, t_new, h, &x, &x_new, &ks));
                sol.stats.accepted += 1;
                (t, x, k1) = (t_new, x_new, k7);
                if !last {
                    h = h_new;
                }
                last_rejected = false;
            } else {
                h /= (fac11 / 0.9).min(5.0);
                sol.stats.rejected += 1;
                last_rejected = true;
            }
        }
    }
    sol
}
/// The ends of the integration's pieces: the breakpoints strictly inside
/// `(t_start, t_end)`, sorted and without repeats, then `t_end`. Apart
/// from [`dopri5`] so that its loop reads on a screen.
fn stops(breakpoints: &[f64], t_start: f64, t_end: f64) -> Vec<f64> {
    let mut cuts: Vec<f64> = breakpoints
        .iter()
        .copied()
        .filter(|b| *b > t_start && *b < t_end)
        .collect();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    cuts.push(t_end);
    cuts
}

/// One Dormand–Prince step from `(t, x)` with first stage `k1`: the seven
/// stages and the fifth-order solution at `t + h`, the last two stages
/// evaluated at `t_right` (the input's left limit at a breakpoint). Apart
/// from [`dopri5`]'s step-size control so that each reads on a screen;
/// inlined, on fixed arrays, so the hot loop is what it was.
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
/// fourth order). Apart from [`dopri5`] so that its loop reads on a screen.
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
/// order 4). Apart from [`dopri5`] so that its loop reads on a screen.
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
        ],
    }
}

/// Hairer's starting step: small enough that an explicit Euler step's
/// error stays near the tolerance.
fn initial_step<const N: usize, S: OdeSystem<N>>(
    sys: &mut S,
    t: f64,
    x: &[f64; N],
    f0: &[f64; N],
    span: f64,
    tol: &Tolerances,
    stats: &mut Stats,
) -> f64 {
    let scale = |i: usize| tol.atol + tol.rtol * x[i].abs();
    let norm =
        |v: &[f64; N]| ((0..N).map(|i| (v[i] / scale(i)).powi(2)).sum::<f64>() / N as f64).sqrt();
    let (d0, d1) = (norm(x), norm(f0));
    let h0 = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6
    } else {
        0.01 * d0 / d1
    }
    .min(span)
    .min(tol.max_step);
    let x1: [f64; N] = std::array::from_fn(|i| x[i] + h0 * f0[i]);
    sys.dopri5_stage(DOPRI5_PROBE);
    let f1 = sys.derivatives(t + h0, &x1);
    stats.evaluations += 1;
    let diff: [f64; N] = std::array::from_fn(|i| f1[i] - f0[i]);
    let d2 = norm(&diff) / h0;
    let h1 = if d1.max(d2) <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / d1.max(d2)).powf(0.2)
    };
    (100.0 * h0).min(h1).min(span).min(tol.max_step)
}

/// The classical fourth-order Runge–Kutta method on the grid `t0 + i·h`,
/// `i = 0..=n`, from `x0`. At every grid point, right after the first stage
/// has been evaluated there, `record(sys, i, t, x)` is called (so a system
/// can hand out that evaluation's by-products without a second one); it
/// returns false to stop. Returns the last state reached. Allocates nothing.
/// It is [`sensitivity::rk4_dual`] in plain numbers: one RK4, whose dual
/// replay differentiates exactly what this one computes.
pub fn rk4<const N: usize, S: OdeSystem<N>>(
    sys: &mut S,
    t0: f64,
    h: f64,
    n: usize,
    x0: [f64; N],
    mut record: impl FnMut(&mut S, usize, f64, &[f64; N]) -> bool,
) -> [f64; N] {
    sensitivity::rk4_dual(&mut Plain(sys), t0, h, n, x0, |p, i, t, x| {
        record(p.0, i, t, x)
    })
}

/// An [`OdeSystem`] seen as a system in the plain scalar.
struct Plain<'a, S>(&'a mut S);

impl<const N: usize, S: OdeSystem<N>> sensitivity::DualSystem<f64, N> for Plain<'_, S> {
    fn derivatives(&mut self, t: f64, x: &[f64; N]) -> [f64; N] {
        self.0.derivatives(t, x)
    }
    fn rk4_stage(&mut self, step: usize, stage: usize) {
        self.0.rk4_stage(step, stage);
    }
    fn w_stage(&mut self, step: usize, stage: usize) {
        self.0.w_stage(step, stage);
    }
    fn implicit_states(&self) -> [bool; N] {
        self.0.implicit_states()
    }
}

#[cfg(test)]
mod tests;
