//! The vehicle model driven by its inputs, as an ODE for [`super::ode`]:
//! the one place where the model's right-hand side
//! ([`VehicleModel::rates`]) meets an integrator, for every job — a
//! scenario's simulation (inputs from the manoeuvre, RK4 or Dormand–Prince)
//! and the diagnosis's replays of measured runs (inputs sampled once at the
//! stages of a fixed grid, [`Drive`], so repeated replays only evaluate the
//! model; RK4, or the linearly implicit ROS34PW2 for a model too stiff for
//! RK4 on that grid, [`FixedStep`]).
//!
//! The state has `N` = 2 reals (β, r) when no effect needs more, 6
//! ([`StateVector`]) otherwise: the extra states are then integrated, and
//! left out (zero) of the 2-state system, where they do not feed back.
//! Units: SI, rad.

mod seeds;
mod system;
mod watched;

use seeds::Adaptive;

use super::ode::{
    self, DenseSolution, OdeSystem, Pair, Tolerances, W_NODES, W_PROBE, W_TIME_PROBE,
};
use super::progress::Counted;
use super::{load_tolerance, Integrator, TimeHistory};
use crate::manoeuvre::{interpolate, Manoeuvre, Replay};
use crate::measured::derivative::{speed_derivative, speed_derivative_at};
use crate::vehicle::{
    Inputs, LoadTransferSeed, ModelScalars, Outputs, State, StateVector, SteerCosine, VehicleModel,
};
use std::sync::atomic::AtomicUsize;

/// A fixed-grid method of a replay.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FixedStep {
    /// The classical fourth-order Runge–Kutta method: 4 evaluations a step,
    /// stable while `h·ρ ≲ 2.8` (ρ the fastest mode's rate).
    Rk4,
    /// The Rosenbrock–W method ROS34PW2 ([`ode::rosenbrock_w`]): third
    /// order, L-stable at any step; 5 evaluations a step and a difference
    /// Jacobian every 4 steps.
    RosenbrockW,
}

impl FixedStep {
    /// Where a step's input samples lie, as fractions of the step.
    fn offsets(self) -> &'static [f64] {
        match self {
            Self::Rk4 => &[0.0, 0.5],
            Self::RosenbrockW => &W_NODES[..3],
        }
    }

    /// The sample index of stage `stage` of step `step` (a Jacobian probe
    /// reads the step's first).
    pub(super) fn index(self, step: usize, stage: usize) -> usize {
        match self {
            Self::Rk4 => 2 * step + STAGE_HALF_STEPS[stage],
            Self::RosenbrockW if stage == W_PROBE => 3 * step,
            Self::RosenbrockW if stage == W_TIME_PROBE => 3 * step + 1,
            Self::RosenbrockW => 3 * step + stage,
        }
    }
}

/// A run's inputs sampled at every stage of a fixed grid. Under RK4 index
/// `2i` is grid time `t0 + i·h` and `2i + 1` is `t0 + (i + ½)·h`; under
/// ROS34PW2 `3i + j` is `t0 + (i + c_j)·h` with `c_j` its nodes.
#[derive(Debug, Clone, PartialEq)]
pub struct Drive {
    /// The method it is sampled for.
    pub method: FixedStep,
    /// Integration step, s.
    pub step: f64,
    /// First time, s.
    pub start: f64,
    /// Number of steps.
    pub steps: usize,
    steer: Vec<f64>,
    speed: Vec<f64>,
    speed_rate: Vec<f64>,
    /// Longitudinal acceleration at the stage times: a replay's measured
    /// `ax`, else its speed's smoothed derivative ([`Drive::replay`]);
    /// empty for a manoeuvre, whose exact du/dt stands in.
    ax: Vec<f64>,
    /// Measured road bank at the stage times (empty: none).
    bank: Vec<f64>,
}

impl Drive {
    /// Samples `m` over its duration with step `step` for RK4.
    pub fn new(m: &Manoeuvre, step: f64) -> Self {
        Self::for_method(m, step, FixedStep::Rk4)
    }

    /// Samples `m` over its duration with step `step` for `method`.
    pub(crate) fn for_method(m: &Manoeuvre, step: f64, method: FixedStep) -> Self {
        let start = m.start_time();
        let steps = ((m.end_time() - start) / step).round().max(1.0) as usize;
        let times = Self::sample_times(method, start, step, steps);
        let drive = Self {
            method,
            step,
            start,
            steps,
            steer: times.iter().map(|&t| m.steer(t)).collect(),
            speed: times.iter().map(|&t| m.speed(t)).collect(),
            speed_rate: times.iter().map(|&t| m.speed_rate(t)).collect(),
            ax: Vec::new(),
            bank: Vec::new(),
        };
        // A replay's own measured channels, as a simulation reads them.
        match m {
            Manoeuvre::Replay(r) if r.ax.is_some() || r.bank.is_some() => {
                drive.with_channels(&r.t, r.ax.as_deref(), r.bank.as_deref())
            }
            _ => drive,
        }
    }

    /// The same drive with a measured longitudinal acceleration and road
    /// bank (sampled at `t`, linearly interpolated to the stage times) where
    /// given: they reach the model as [`Inputs::ax`] and [`Inputs::bank`],
    /// which only its longitudinal and bank-profile effects read. Without
    /// `ax` the drive keeps the acceleration it has (a replay's smoothed
    /// speed derivative).
    pub(crate) fn with_channels(
        mut self,
        t: &[f64],
        ax: Option<&[f64]>,
        bank: Option<&[f64]>,
    ) -> Self {
        if let Some(ax) = ax {
            self.ax = self.sampled(t, ax);
        }
        self.bank = bank.map_or_else(Vec::new, |b| self.sampled(t, b));
        self
    }

    /// `v` (sampled at `t`) linearly interpolated to the stage times.
    fn sampled(&self, t: &[f64], v: &[f64]) -> Vec<f64> {
        Self::sample_times(self.method, self.start, self.step, self.steps)
            .iter()
            .map(|&x| interpolate(t, v, x))
            .collect()
    }

    /// The replay of measured steer and speed by `method`. Its
    /// longitudinal acceleration ([`Inputs::ax`]) is the speed's smoothed
    /// derivative ([`speed_derivative`]: a local quadratic fit over 0.5 s,
    /// not the difference of two noisy samples) until a measured `ax`
    /// replaces it ([`Drive::with_channels`]); the speed's rate in the
    /// kinematics ([`Inputs::speed_rate`]) stays the slope of the
    /// interpolated speed the replay follows.
    pub fn replay(t: &[f64], steer: &[f64], speed: &[f64], step: f64, method: FixedStep) -> Self {
        let drive = Self::for_method(
            &Manoeuvre::Replay(Replay::of_inputs(
                t.to_vec(),
                steer.to_vec(),
                speed.to_vec(),
            )),
            step,
            method,
        );
        let ax = drive.sampled(t, &speed_derivative(t, speed));
        Self { ax, ..drive }
    }

    /// The times of its input samples (every stage of every step, in the
    /// order of [`Drive::steer_samples`]; not increasing within a ROS34PW2
    /// step, whose nodes are not), s.
    pub(crate) fn stage_times(&self) -> Vec<f64> {
        Self::sample_times(self.method, self.start, self.step, self.steps)
    }

    /// The steer at [`Drive::stage_times`], rad.
    pub(crate) fn steer_samples(&self) -> &[f64] {
        &self.steer
    }

    /// The same drive with the steer at [`Drive::stage_times`] replaced by
    /// `steer` (a steer path's output), rad.
    ///
    /// # Panics
    /// When `steer` has another length than the drive's samples.
    pub(crate) fn with_steer(mut self, steer: Vec<f64>) -> Self {
        assert_eq!(steer.len(), self.steer.len(), "one steer per stage sample");
        self.steer = steer;
        self
    }

    /// The times of the samples of `steps` steps of `step` from `start`.
    fn sample_times(method: FixedStep, start: f64, step: f64, steps: usize) -> Vec<f64> {
        let offsets = method.offsets();
        (0..=offsets.len() * steps)
            .map(|k| start + step * ((k / offsets.len()) as f64 + offsets[k % offsets.len()]))
            .collect()
    }

    /// Grid time of step `i`, s.
    pub fn time(&self, i: usize) -> f64 {
        self.start + self.step * i as f64
    }

    /// The inputs at the first grid time, with road friction `friction`.
    pub(crate) fn first_inputs(&self, friction: f64) -> Inputs {
        self.inputs_at(0, friction)
    }

    /// The longitudinal acceleration the model reads ([`Inputs::ax`]) at
    /// every stage sample, in the order of the stage times, m/s².
    pub fn ax_samples(&self) -> Vec<f64> {
        (0..self.speed.len())
            .map(|k| self.inputs_at(k, 1.0).ax)
            .collect()
    }

    pub(super) fn inputs_at(&self, k: usize, friction: f64) -> Inputs {
        Inputs {
            steer: self.steer[k],
            speed: self.speed[k],
            speed_rate: self.speed_rate[k],
            friction,
            ax: self.ax.get(k).copied().unwrap_or(self.speed_rate[k]),
            bank: self.bank.get(k).copied().unwrap_or(0.0),
        }
    }
}

/// The inputs of manoeuvre `m` at time `t` on a road of friction
/// `friction`. The longitudinal acceleration is du/dt; a replayed run's is
/// its measured `ax` where it logs one, else its speed's smoothed
/// derivative ([`speed_derivative_at`], as [`Drive::replay`] samples it),
/// and its road bank its measured `bank` (as [`Drive::with_channels`]
/// gives `diagnose`'s replays both).
pub(super) fn manoeuvre_inputs(m: &Manoeuvre, t: f64, friction: f64) -> Inputs {
    let speed_rate = m.speed_rate(t);
    let (ax, bank) = match m {
        Manoeuvre::Replay(r) => (
            r.ax_at(t)
                .unwrap_or_else(|| speed_derivative_at(&r.t, &r.speed, t)),
            r.bank_at(t),
        ),
        _ => (speed_rate, 0.0),
    };
    Inputs {
        steer: m.steer(t),
        speed: m.speed(t),
        speed_rate,
        friction,
        ax,
        bank,
    }
}

/// Where the inputs come from.
#[derive(Clone, Copy)]
enum Source<'a> {
    Manoeuvre(&'a Manoeuvre),
    Sampled(&'a Drive),
}

/// Offset in half steps of RK4's stages from the step's grid time.
const STAGE_HALF_STEPS: [usize; 4] = [0, 1, 1, 2];

/// The vehicle model driven by a manoeuvre or a sampled drive.
struct Driven<'a> {
    model: &'a VehicleModel,
    source: Source<'a>,
    friction: f64,
    /// The model's numbers on this road ([`VehicleModel::scalars`]):
    /// the same at every evaluation, built once.
    scalars: ModelScalars<f64>,
    /// One load-transfer seed per stage of a fixed-step method: stage j of
    /// step n is predicted from stage j of steps n − 1 and n − 2, which sit
    /// at evenly spaced times. The adaptive method uses the first only.
    seeds: [LoadTransferSeed; 4],
    /// The fixed-step (step, stage) being evaluated; None under
    /// Dormand–Prince.
    stage: Option<(usize, usize)>,
    /// The last two (t, ay) solutions of the load-transfer loop (adaptive).
    history: [(f64, f64); 2],
    /// The adaptive method's seeds ([`Adaptive`]).
    adaptive: Adaptive,
    load_tolerance: f64,
    /// The cosine of the last front steer ([`SteerCosine`]).
    cosine: SteerCosine,
    load_evaluations: u64,
    /// The inputs and outputs of the last evaluation.
    last: (Inputs, Outputs),
    /// Where a run shows its progress (`simulate` on a terminal).
    progress: Option<Counted<'a>>,
}

impl<'a> Driven<'a> {
    fn new(model: &'a VehicleModel, source: Source<'a>, friction: f64, tolerance: f64) -> Self {
        Self {
            model,
            source,
            friction,
            scalars: model.scalars(friction),
            seeds: [LoadTransferSeed::default(); 4],
            stage: None,
            history: [(f64::NAN, 0.0); 2],
            adaptive: Adaptive::default(),
            load_tolerance: tolerance,
            cosine: SteerCosine::default(),
            load_evaluations: 0,
            last: (Inputs::steady(0.0, 0.0, friction), Outputs::default()),
            progress: None,
        }
    }

    // Not cached between stages (RK4's mid-stages share a sample): copying
    // the cached inputs back out stalled on store forwarding and cost four
    // times the six loads it saved (profiled).
    fn inputs(&self, t: f64) -> Inputs {
        match self.source {
            Source::Manoeuvre(m) => manoeuvre_inputs(m, t, self.friction),
            Source::Sampled(d) => {
                let k = match self.stage {
                    Some((i, j)) => d.method.index(i, j),
                    None => ((t - d.start) / (0.5 * d.step)).round().max(0.0) as usize,
                };
                d.inputs_at(k.min(d.steer.len() - 1), self.friction)
            }
        }
    }

    /// The seed of this evaluation: the RK4 stage's own, or under the
    /// adaptive method the first, set to one of two predictions
    /// ([`Adaptive::choose`]): the linear extrapolation in time of the last
    /// two solutions of any stage (the stages of an adaptive step are not
    /// evenly spaced, so the seed's extrapolation over equal intervals would
    /// not fit; from the last one alone when they are far apart or at the
    /// same time), or the quadratic one of the same stage's last three
    /// ([`seeds::stage_prediction`]).
    fn seed(&mut self, t: f64) -> usize {
        if let Some((_, j)) = self.stage {
            return j;
        }
        let [(t1, a1), (t0, a0)] = self.history;
        let linear = if t1 != t0 && (t - t1).abs() <= 2.0 * (t1 - t0).abs() {
            a1 + (a1 - a0) / (t1 - t0) * (t - t1)
        } else {
            a1
        };
        self.seeds[0].ay = [self.adaptive.choose(t, linear); 3];
        0
    }
}

impl Driven<'_> {
    /// Whether the rows of an `N`-state run carry the body roll: a replay
    /// of a measured run always (the diagnosis compares it with a logged
    /// roll); a manoeuvre only where a roll effect (roll steer, roll
    /// camber) makes the body roll matter. A tyre lag alone integrates the
    /// roll state too, but needs no body roll: its history's `ay` is then
    /// the body frame's, as the diagnosis's lag candidate reads it.
    fn records_roll<const N: usize>(&self) -> bool {
        N > 4
            && (matches!(self.source, Source::Sampled(_)) || self.model.options.effects.uses_roll())
    }
}

/// Records the row of grid time `t` from the system's last evaluation.
fn record<const N: usize>(hist: &mut TimeHistory, sys: &Driven, t: f64, x: &[f64; N]) {
    let (inp, o) = &sys.last;
    let state = State {
        beta: x[0],
        yaw_rate: x[1],
    };
    hist.push(t, &state, inp, o);
    if sys.records_roll::<N>() {
        hist.roll.push(x[4]);
    }
}

/// RK4 of `sys` on `n` steps of `h` from `t0`, recording every grid point.
fn run_rk4<const N: usize>(
    sys: &mut Driven,
    t0: f64,
    h: f64,
    n: usize,
    x0: [f64; N],
) -> TimeHistory {
    let mut hist = TimeHistory::with_capacity(n + 1, sys.records_roll::<N>());
    ode::rk4(sys, t0, h, n, x0, |sys, _, t, x| {
        record(&mut hist, sys, t, x);
        true
    });
    hist.load_evaluations = sys.load_evaluations;
    hist
}

/// Steps a replay's ROS34PW2 Jacobian serves: at a replay step of 10–40 ms
/// the speed and the tyres' slopes change little over this many.
pub(super) const W_REFRESH: usize = 4;

/// ROS34PW2 of the full state on `n` steps of `h` from `t0`, recording
/// every grid point.
fn run_w(sys: &mut Driven, t0: f64, h: f64, n: usize, x0: StateVector) -> TimeHistory {
    let mut hist = TimeHistory::with_capacity(n + 1, true);
    ode::rosenbrock_w(sys, t0, h, n, x0, W_REFRESH, |sys, _, t, x| {
        record(&mut hist, sys, t, x);
        true
    });
    hist.load_evaluations = sys.load_evaluations;
    hist
}

/// The first `N` reals of a full state.
fn head<const N: usize>(x: &StateVector) -> [f64; N] {
    std::array::from_fn(|i| x[i])
}

impl Integrator {
    /// The full initial state of a simulation from `x0`: the extra states at
    /// their quasi-static values, a lagged compliant front's at its steady
    /// slip ([`VehicleModel::steady_state_vector`]).
    fn initial(&self, model: &VehicleModel, manoeuvre: &Manoeuvre, x0: State) -> StateVector {
        model.steady_state_vector(&x0, &self.inputs(manoeuvre, manoeuvre.start_time()))
    }

    /// RK4 at the output step, rows recorded from the first stage of each
    /// step (every row is the model evaluated at exactly that state).
    pub(super) fn run_rk4(
        &self,
        model: &VehicleModel,
        manoeuvre: &Manoeuvre,
        x0: State,
        progress: Option<&AtomicUsize>,
    ) -> TimeHistory {
        let h = self.step;
        let t0 = manoeuvre.start_time();
        let n = ((manoeuvre.end_time() - t0) / h).round().max(0.0) as usize;
        let tol = crate::vehicle::LOAD_TOLERANCE;
        let mut sys = Driven::new(model, Source::Manoeuvre(manoeuvre), self.friction, tol);
        sys.progress = progress.map(|c| Counted::new(c, t0, h, 0));
        let x = self.initial(model, manoeuvre, x0);
        if model.options.effects.extra_states() {
            run_rk4::<6>(&mut sys, t0, h, n, x)
        } else {
            run_rk4::<2>(&mut sys, t0, h, n, head(&x))
        }
    }

    /// Replays `drive` from the full state `x0` by the drive's method on
    /// its own grid (whatever this integrator's method and step), all six
    /// states integrated and the roll recorded: the diagnosis's replay of a
    /// run.
    pub fn replay(&self, model: &VehicleModel, drive: &Drive, x0: StateVector) -> TimeHistory {
        self.replay_to(model, drive, x0, crate::vehicle::LOAD_TOLERANCE)
    }

    /// [`Integrator::replay`] with the load-transfer loop solved to relative
    /// tolerance `tol` on g(ay) (a check of derivatives against differences
    /// wants it at rounding).
    pub fn replay_to(
        &self,
        model: &VehicleModel,
        drive: &Drive,
        x0: StateVector,
        tol: f64,
    ) -> TimeHistory {
        let mut sys = Driven::new(model, Source::Sampled(drive), self.friction, tol);
        match drive.method {
            FixedStep::Rk4 => run_rk4::<6>(&mut sys, drive.start, drive.step, drive.steps, x0),
            FixedStep::RosenbrockW => run_w(&mut sys, drive.start, drive.step, drive.steps, x0),
        }
    }

    /// The error-controlled (β, r) solution of `manoeuvre` from `x0`
    /// (restarted at the manoeuvre's breakpoints) by Dormand–Prince 5(4)
    /// and nothing else: what an ODE solver returns, for a user who wants
    /// the states at chosen times ([`DenseSolution::states_into`]) without
    /// the model's other signals. None when the model has states beyond
    /// (β, r).
    pub fn solve_dopri5(
        &self,
        model: &VehicleModel,
        manoeuvre: &Manoeuvre,
        x0: State,
        tol: &Tolerances,
    ) -> Option<DenseSolution<2>> {
        self.solve_with(model, manoeuvre, x0, tol, Pair::Dopri5)
    }

    /// [`Integrator::solve_dopri5`] by Dormand & Prince's 8(5,3) pair
    /// ([`ode::dop853`]): at a tight tolerance (rtol 1e-10) about half the
    /// right-hand sides, its dense output seventh order.
    pub fn solve_dop853(
        &self,
        model: &VehicleModel,
        manoeuvre: &Manoeuvre,
        x0: State,
        tol: &Tolerances,
    ) -> Option<DenseSolution<2>> {
        self.solve_with(model, manoeuvre, x0, tol, Pair::Dop853)
    }

    /// The (β, r) solution by `pair`.
    fn solve_with(
        &self,
        model: &VehicleModel,
        manoeuvre: &Manoeuvre,
        x0: State,
        tol: &Tolerances,
        pair: Pair,
    ) -> Option<DenseSolution<2>> {
        if model.options.effects.extra_states() {
            return None;
        }
        let x = head(&self.initial(model, manoeuvre, x0));
        let source = Source::Manoeuvre(manoeuvre);
        let mut sys = Driven::new(model, source, self.friction, load_tolerance(tol));
        let (t0, t1) = (manoeuvre.start_time(), manoeuvre.end_time());
        let breakpoints = manoeuvre.breakpoints();
        Some(ode::solve(pair, &mut sys, (t0, t1), x, &breakpoints, tol))
    }

    /// The error-controlled solution of `manoeuvre` from `x0` (restarted at
    /// the manoeuvre's breakpoints) and its history sampled every `step`;
    /// the dense solution when the state is (β, r) alone.
    pub fn run_dopri5(
        &self,
        model: &VehicleModel,
        manoeuvre: &Manoeuvre,
        x0: State,
        tol: &Tolerances,
    ) -> (TimeHistory, Option<DenseSolution<2>>) {
        let (hist, sol, _) = self.run_adaptive(model, manoeuvre, x0, (Pair::Dopri5, *tol), None);
        (hist, sol)
    }

    /// [`Integrator::run_dopri5`] by either pair, with the work of the
    /// integration, of the full state too (a lag or roll effect's six
    /// states): its report said "RK4" for a Dormand–Prince run it had no
    /// dense (β, r) solution of.
    pub(super) fn run_adaptive(
        &self,
        model: &VehicleModel,
        manoeuvre: &Manoeuvre,
        x0: State,
        pair: (Pair, Tolerances),
        progress: Option<&AtomicUsize>,
    ) -> (TimeHistory, Option<DenseSolution<2>>, ode::Stats) {
        let x = self.initial(model, manoeuvre, x0);
        if model.options.effects.extra_states() {
            let (hist, sol) = self.adaptive_n::<6>(model, manoeuvre, x, pair, progress);
            (hist, None, sol.stats)
        } else {
            let (hist, sol) = self.adaptive_n::<2>(model, manoeuvre, head(&x), pair, progress);
            let stats = sol.stats;
            (hist, Some(sol), stats)
        }
    }

    fn adaptive_n<const N: usize>(
        &self,
        model: &VehicleModel,
        manoeuvre: &Manoeuvre,
        x0: [f64; N],
        (pair, tol): (Pair, Tolerances),
        progress: Option<&AtomicUsize>,
    ) -> (TimeHistory, DenseSolution<N>) {
        let load_tol = load_tolerance(&tol);
        let source = Source::Manoeuvre(manoeuvre);
        let mut sys = Driven::new(model, source, self.friction, load_tol);
        let (t0, t1) = (manoeuvre.start_time(), manoeuvre.end_time());
        let n = ((t1 - t0) / self.step).round().max(0.0) as usize;
        // The integration counts the first n, the rows the next n.
        sys.progress = progress.map(|c| Counted::new(c, t0, self.step, 0));
        let sol = ode::solve(pair, &mut sys, (t0, t1), x0, &manoeuvre.breakpoints(), &tol);
        let mut hist = TimeHistory::with_capacity(n + 1, sys.records_roll::<N>());
        // A stalled integration's rows end where it stopped: beyond, the
        // dense output would be its last step's polynomial extrapolated.
        let end = if sol.stats.stalled { sol.end() } else { t1 };
        let times: Vec<f64> = (0..=n)
            .map(|i| (t0 + i as f64 * self.step).min(t1))
            .filter(|&t| t <= end)
            .collect();
        let mut states = Vec::new();
        sol.states_into(&times, &mut states);
        // Rows: the model evaluated at the dense output, each load-transfer
        // solve started from the previous row's.
        let mut rows = Driven::new(model, source, self.friction, load_tol);
        rows.stage = Some((0, 0));
        rows.progress = progress.map(|c| Counted::new(c, t0, self.step, n));
        for (&t, x) in times.iter().zip(&states) {
            OdeSystem::<N>::derivatives(&mut rows, t, x);
            record(&mut hist, &rows, t, x);
        }
        hist.load_evaluations = sys.load_evaluations;
        (hist, sol)
    }
}
