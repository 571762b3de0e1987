//! Integration of small ODE systems `ẋ = f(t, x)` with a state of `N`
//! reals: two error-controlled embedded Runge–Kutta pairs with their
//! continuous (dense) output, Dormand–Prince 5(4) and 8(5,3), the classical
//! fixed-step RK4, and the fixed-step linearly implicit Rosenbrock–W method
//! ROS34PW2 for stiff systems.
//!
//! Methods:
//! - Dormand & Prince (1980), "A family of embedded Runge–Kutta formulae",
//!   J. Comp. Appl. Math. 6; step-size control (PI controller with β = 0.04,
//!   safety 0.9, growth within [0.2, 10]) and the fourth-order dense output
//!   as in Hairer, Nørsett & Wanner, *Solving Ordinary Differential
//!   Equations I* (2nd ed., 1993), §II.4–II.6 (`dopri5.rs`). The local
//!   error is measured in the weighted RMS norm with weights
//!   `atol + rtol·max(|x_old|, |x_new|)`.
//! - DOP853, Dormand & Prince's 8(5,3) pair with its seventh-order dense
//!   output, as in Hairer et al. (1993), §II.10 and Hairer's `dop853.f`
//!   (`dop853.rs`): at a tight tolerance it takes half the evaluations of
//!   the 5(4) pair for a 10 s step steer.
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
//! Layout: this file holds the system's trait, the dense solution, the
//! adaptive pairs' common step loop and RK4; `dopri5.rs` and `dop853.rs`
//! hold the pairs, `rosenbrock.rs` holds ROS34PW2.

mod dop853;
mod dopri5;
mod rosenbrock;
pub mod sensitivity;

pub use dop853::dop853;
pub use dopri5::dopri5;
pub use rosenbrock::{rosenbrock_w, rosenbrock_w_dual, W_NODES, W_PROBE, W_TIME_PROBE};

/// The embedded pair an adaptive integration steps by (a scenario file's
/// `method = "dopri5"` or `"dop853"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pair {
    /// Dormand–Prince 5(4) ([`dopri5`]).
    Dopri5,
    /// Dormand & Prince's 8(5,3) ([`dop853`]).
    Dop853,
}

/// Integrates `sys` by `pair` ([`dopri5`] or [`dop853`], same arguments).
pub fn solve<const N: usize, S: OdeSystem<N>>(
    pair: Pair,
    sys: &mut S,
    span: (f64, f64),
    x0: [f64; N],
    breakpoints: &[f64],
    tol: &Tolerances,
) -> DenseSolution<N> {
    let (t_start, t_end) = span;
    match pair {
        Pair::Dopri5 => dopri5(sys, t_start, t_end, x0, breakpoints, tol),
        Pair::Dop853 => dop853(sys, t_start, t_end, x0, breakpoints, tol),
    }
}

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

    /// Called by [`dopri5`] and [`dop853`] before each evaluation with its
    /// stage: 0–6 the seven of Dormand–Prince 5(4) (0 a restart's first, 6
    /// a step's end, whose value the next step reuses), [`DOPRI5_PROBE`]
    /// the starting step's probe (both pairs), [`DOP853_FIRST_STAGE`] + 0–15
    /// the sixteen of DOP853 (+12 a step's end, +13–15 its dense output's);
    /// fewer than [`ADAPTIVE_STAGES`] in all. A system can then keep one
    /// load-transfer starting point per stage: a stage's state is off the
    /// solution by an amount of its own, about the same from one step to
    /// the next.
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

/// The stage [`dop853`] tells [`OdeSystem::dopri5_stage`] for its first
/// stage; its others follow (after Dormand–Prince 5(4)'s and the probe).
pub const DOP853_FIRST_STAGE: usize = DOPRI5_PROBE + 1;

/// The stages [`OdeSystem::dopri5_stage`] can be told, 0 to this less one.
pub const ADAPTIVE_STAGES: usize = DOP853_FIRST_STAGE + 16;

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
/// `r0 + θ(r1 + (1−θ)(r2 + θ(r3 + (1−θ)(r4 + θ(r5 + (1−θ)(r6 + θ r7))))))`,
/// θ ∈ [0, 1]: Dormand–Prince 5(4)'s of order 4 (`r5..r7` zero, which
/// leaves its values to the bit), DOP853's of order 7 (Hairer's `contd8`).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Segment<const N: usize> {
    t0: f64,
    h: f64,
    r: [[f64; N]; 8],
}

impl<const N: usize> Segment<N> {
    fn at(&self, t: f64) -> [f64; N] {
        let th = ((t - self.t0) / self.h).clamp(0.0, 1.0);
        let th1 = 1.0 - th;
        let r = &self.r;
        std::array::from_fn(|i| {
            let tail = r[4][i] + th * (r[5][i] + th1 * (r[6][i] + th * r[7][i]));
            r[0][i] + th * (r[1][i] + th1 * (r[2][i] + th * (r[3][i] + th1 * tail)))
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

/// An embedded Runge–Kutta pair as [`adaptive`] steps it: one step's
/// stages, its error estimate, its dense-output segment and the constants
/// of its step-size control (Hairer's PI controller: the step grows by
/// `1/fac`, `fac = err^(EXPONENT − 0.75·BETA) / err_old^BETA / 0.9` within
/// `[FAC_MIN, FAC_MAX]`, and shrinks after a rejection by at most
/// `FAC_MAX`).
trait Embedded<const N: usize> {
    /// The stages of one step.
    type Stages;
    /// The stage [`OdeSystem::dopri5_stage`] is told for a restart's first
    /// evaluation; the step's other stages follow it.
    const FIRST_STAGE: usize;
    /// Evaluations of one step after its first stage (reused from the
    /// last step's end).
    const STEP_EVALUATIONS: usize;
    /// `1/(q + 1)`, `q` the order of the error estimate.
    const EXPONENT: f64;
    /// The PI controller's β (0: the classical controller).
    const BETA: f64;
    /// Bounds of `fac`: the step's growth (`1/FAC_MIN`) and shrink.
    const FAC_MIN: f64;
    const FAC_MAX: f64;
    /// Whether a piece that starts at rest (the derivative zero at its
    /// start and at the starting step's probe) is tried in one step:
    /// Hairer's starting step of 1e-6 s then takes seven or eight steps,
    /// growing, to cross it (a step steer's second before the steer).
    const AT_REST_WHOLE_SPAN: bool;

    /// One step from `(t, x)` with first stage `k1`: the stages and the
    /// solution at `t + h`, the stages at the step's end evaluated at
    /// `t_right` (the input's left limit at a breakpoint).
    #[rustfmt::skip] // one line: the architecture test reads a bodiless `fn` by its line
    fn step<S: OdeSystem<N>>(sys: &mut S, t: f64, x: &[f64; N], h: f64, k1: [f64; N], t_right: f64) -> (Self::Stages, [f64; N]);
    /// The derivative at the step's end: the next step's first stage.
    fn next_first(stages: &Self::Stages) -> [f64; N];
    /// The scaled norm of the step's error estimate.
    #[rustfmt::skip] // one line: the architecture test reads a bodiless `fn` by its line
    fn error(h: f64, stages: &Self::Stages, x: &[f64; N], x_new: &[f64; N], tol: &Tolerances) -> f64;
    /// The accepted step's dense-output segment and the evaluations it
    /// took beyond the step's.
    #[rustfmt::skip] // one line: the architecture test reads a bodiless `fn` by its line
    fn segment<S: OdeSystem<N>>(sys: &mut S, t: f64, t_new: f64, h: f64, x: &[f64; N], x_new: &[f64; N], stages: &Self::Stages) -> (Segment<N>, usize);
}

/// Integrates `sys` from `x0` at `t_start` to `t_end` with the pair `P`,
/// restarting at every breakpoint inside the interval (sorted or not),
/// and returns the dense solution.
fn adaptive<const N: usize, S: OdeSystem<N>, P: Embedded<N>>(
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
        sys.dopri5_stage(P::FIRST_STAGE);
        let mut k1 = sys.derivatives(t, &x);
        sol.stats.evaluations += 1;
        if h == 0.0 {
            h = initial_step::<N, S, P>(sys, t, &x, &k1, stop - t, tol);
            sol.stats.evaluations += 1;
        }
        let mut err_old: f64 = 1e-4;
        let mut last_rejected = false;
        while t < stop {
            if sol.stats.accepted + sol.stats.rejected >= budget {
                sol.stats.stalled = true;
                return sol;
            }
            let (last, t_new, t_right);
            (h, last, t_new, t_right) = landing(t, h.min(tol.max_step), stop);
            let (ks, x_new) = P::step(sys, t, &x, h, k1, t_right);
            sol.stats.evaluations += P::STEP_EVALUATIONS;
            let err = P::error(h, &ks, &x, &x_new, tol);
            if !err.is_finite() {
                h *= 0.1;
                sol.stats.rejected += 1;
                last_rejected = true;
                continue;
            }
            let fac11 = err.powf(P::EXPONENT - P::BETA * 0.75);
            if err <= 1.0 {
                let damping = if P::BETA > 0.0 {
                    err_old.powf(P::BETA)
                } else {
                    1.0
                };
                let fac = (fac11 / damping / 0.9).clamp(P::FAC_MIN, P::FAC_MAX);
                let mut h_new = h / fac;
                if last_rejected {
                    h_new = h_new.min(h);
                }
                err_old = err.max(1e-4);
                let (segment, dense_evaluations) = P::segment(sys, t, t_new, h, &x, &x_new, &ks);
                sol.segments.push(segment);
                sol.stats.evaluations += dense_evaluations;
                sol.stats.accepted += 1;
                (t, x, k1) = (t_new, x_new, P::next_first(&ks));
                if !last {
                    h = h_new;
                }
                last_rejected = false;
            } else {
                h /= (fac11 / 0.9).min(P::FAC_MAX);
                sol.stats.rejected += 1;
                last_rejected = true;
            }
        }
    }
    sol
}

/// The step from `t` of about `h` towards `stop`: its length, whether it
/// is the piece's last, its end and the time its end's stages see. It
/// lands exactly on the stop and avoids a sliver step before it; a step
/// that ends on a breakpoint sees the input's left limit there (an ideal
/// step steer acts from the next step on).
#[inline]
fn landing(t: f64, h: f64, stop: f64) -> (f64, bool, f64, f64) {
    let remaining = stop - t;
    let last = h >= remaining * (1.0 - 1e-12) || remaining - h < 1e-3 * h;
    if last {
        (remaining, true, stop, stop.next_down())
    } else {
        (h, false, t + h, t + h)
    }
}

/// The ends of the integration's pieces: the breakpoints strictly inside
/// `(t_start, t_end)`, sorted and without repeats, then `t_end`. Apart
/// from [`adaptive`] so that its loop reads on a screen.
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

fn rms_norm<const N: usize>(e: &[f64; N], x0: &[f64; N], x1: &[f64; N], tol: &Tolerances) -> f64 {
    let mut s = 0.0;
    for i in 0..N {
        let w = tol.atol + tol.rtol * x0[i].abs().max(x1[i].abs());
        s += (e[i] / w).powi(2);
    }
    (s / N as f64).sqrt()
}

/// Hairer's starting step: small enough that an explicit Euler step's
/// error stays near the tolerance, the exponent the pair's (1/order). A
/// system at rest (no derivative at the start nor at the probe) starts
/// with a millionth of a second, or under a pair that says so
/// ([`Embedded::AT_REST_WHOLE_SPAN`]) with the whole piece, which the error
/// control then accepts or cuts. It evaluates `sys` once (the caller
/// counts it).
fn initial_step<const N: usize, S: OdeSystem<N>, P: Embedded<N>>(
    sys: &mut S,
    t: f64,
    x: &[f64; N],
    f0: &[f64; N],
    span: f64,
    tol: &Tolerances,
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
    let diff: [f64; N] = std::array::from_fn(|i| f1[i] - f0[i]);
    let d2 = norm(&diff) / h0;
    let h1 = if d1.max(d2) <= 1e-15 {
        if P::AT_REST_WHOLE_SPAN {
            return span.min(tol.max_step);
        }
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / d1.max(d2)).powf(P::EXPONENT)
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
