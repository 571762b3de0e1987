//! Integration of the vehicle model under a manoeuvre and the recorded time
//! history (and, under Dormand–Prince, the dense solution step-steer
//! metrics are measured on, in `metrics::simulated`).
//!
//! Three methods ([`Method`]):
//! - Dormand–Prince 5(4) (the default of scenario files) or 8(5,3)
//!   (DOP853, `method = "dop853"`: fewer evaluations at tight tolerances),
//!   with error control and dense output (Dormand & Prince 1980; Hairer,
//!   Nørsett & Wanner 1993; [`ode`]): the solution is restarted at the input's
//!   kinks, rows are the dense output at every output step, and metrics are
//!   measured on the dense output itself (`metrics::simulated`), so events are
//!   located to the tolerance rather than to the output grid;
//! - classical fixed-step RK4: inputs sampled at t, t + h/2 and t + h within
//!   each step; outputs recorded from the first stage of each step, so every
//!   recorded row is the model evaluated at exactly that state.
//!
//! A diagnosis's replay of a measured run ([`Drive`]) runs by RK4 or, for a
//! model too stiff for RK4 at the replay's step, by the Rosenbrock–W method
//! ROS34PW2 at that step ([`FixedStep`], [`ode::rosenbrock_w`]), recorded
//! the same way.
//!
//! The load-transfer loop (loads depend on ay, ay on the forces) is solved
//! at every stage of every method, not lagged (the Rosenbrock–W method's
//! Jacobian probes excepted, at the step's loads); under Dormand–Prince to a
//! tolerance tied to the integrator's ([`load_tolerance`]), each solve
//! started from the linear extrapolation in time of the last two. The RK4 step loop allocates nothing (the history's columns are
//! reserved before it starts); the adaptive one allocates only the dense
//! solution's growth. Units: SI, rad.

mod driven;
pub mod ode;
pub mod peer;
mod progress;
pub mod tangent;
#[cfg(test)]
mod trim_tests;

use driven::manoeuvre_inputs;
pub use driven::{Drive, FixedStep};
pub use ode::{DenseSolution, OdeSystem, Pair, Stats, Tolerances};

use crate::manoeuvre::{Manoeuvre, Replay};
use crate::vehicle::{Inputs, Outputs, State, VehicleModel};

/// A recorded simulation: one column per signal, one row per time step.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TimeHistory {
    /// Time, s.
    pub t: Vec<f64>,
    /// Front road-wheel steer, rad.
    pub steer: Vec<f64>,
    /// Forward speed, m/s.
    pub speed: Vec<f64>,
    /// Sideslip, rad.
    pub beta: Vec<f64>,
    /// Yaw rate, rad/s.
    pub yaw_rate: Vec<f64>,
    /// Lateral acceleration, m/s².
    pub ay: Vec<f64>,
    /// Front slip angle, rad.
    pub alpha_front: Vec<f64>,
    /// Rear slip angle, rad.
    pub alpha_rear: Vec<f64>,
    /// Front axle force, N.
    pub fy_front: Vec<f64>,
    /// Rear axle force, N.
    pub fy_rear: Vec<f64>,
    /// Wheel loads FL, FR, RL, RR, N.
    pub fz: [Vec<f64>; 4],
    /// Body roll, rad: recorded only when the roll state is integrated
    /// (empty otherwise).
    pub roll: Vec<f64>,
    /// Evaluations of the tyre set made by the load-transfer solves, over all
    /// RK stages (a cost diagnostic).
    pub load_evaluations: u64,
}

impl TimeHistory {
    fn with_capacity(n: usize, roll: bool) -> Self {
        let v = || Vec::with_capacity(n);
        Self {
            t: v(),
            steer: v(),
            speed: v(),
            beta: v(),
            yaw_rate: v(),
            ay: v(),
            alpha_front: v(),
            alpha_rear: v(),
            fy_front: v(),
            fy_rear: v(),
            fz: [v(), v(), v(), v()],
            roll: if roll { v() } else { Vec::new() },
            load_evaluations: 0,
        }
    }

    fn push(&mut self, t: f64, x: &State, inp: &Inputs, o: &Outputs) {
        self.t.push(t);
        self.steer.push(inp.steer);
        self.speed.push(inp.speed);
        self.beta.push(x.beta);
        self.yaw_rate.push(x.yaw_rate);
        self.ay.push(o.ay);
        self.alpha_front.push(o.alpha_front);
        self.alpha_rear.push(o.alpha_rear);
        self.fy_front.push(o.fy_front);
        self.fy_rear.push(o.fy_rear);
        for (c, f) in self.fz.iter_mut().zip(o.fz) {
            c.push(f);
        }
    }

    /// Number of recorded rows.
    pub fn len(&self) -> usize {
        self.t.len()
    }

    /// True when nothing was recorded.
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    /// What a body-fixed accelerometer at the centre of gravity reads
    /// where the model rolls, m/s²: `a_y·cos φ + g·sin φ` (ISO 8855, φ
    /// positive with the right side down, as in a left turn; the specific
    /// force resolved in the rolled frame, Groves 2013), the inverse of the
    /// levelling a measured run's logged roll gets
    /// ([`crate::measured::calibration::roll::levelled`]). None without
    /// roll: the body does not tilt and the reading is [`Self::ay`].
    pub fn accelerometer_ay(&self) -> Option<Vec<f64>> {
        (!self.roll.is_empty()).then(|| {
            self.ay
                .iter()
                .zip(&self.roll)
                .map(|(a, p)| a * p.cos() + crate::constants::G * p.sin())
                .collect()
        })
    }

    /// Column names and columns as `history.csv` holds them (`FORMATS.md`
    /// read back): where the model rolls, `ay` is what an accelerometer on
    /// the rolled body reads (`accelerometer`, [`Self::accelerometer_ay`]),
    /// as a measured run's `ay` is, and the body frame's lateral
    /// acceleration (the metrics' `ay`, the tyres' force over the mass)
    /// follows the roll as `ay_body`; without roll, [`Self::columns`].
    pub fn written_columns<'a>(
        &'a self,
        accelerometer: Option<&'a [f64]>,
    ) -> Vec<(&'static str, &'a [f64])> {
        let mut columns = self.columns();
        if let Some(read) = accelerometer {
            for c in &mut columns {
                if c.0 == "ay" {
                    c.1 = read;
                }
            }
            columns.push(("ay_body", &self.ay));
        }
        columns
    }

    /// Column names and columns, in output order (for CSV): the model's
    /// own values (`ay` in the body frame).
    pub fn columns(&self) -> Vec<(&'static str, &[f64])> {
        let mut columns: Vec<(&'static str, &[f64])> = vec![
            ("t", &self.t),
            ("steer", &self.steer),
            ("speed", &self.speed),
            ("beta", &self.beta),
            ("yaw_rate", &self.yaw_rate),
            ("ay", &self.ay),
            ("alpha_front", &self.alpha_front),
            ("alpha_rear", &self.alpha_rear),
            ("fy_front", &self.fy_front),
            ("fy_rear", &self.fy_rear),
            ("fz_fl", &self.fz[0]),
            ("fz_fr", &self.fz[1]),
            ("fz_rl", &self.fz[2]),
            ("fz_rr", &self.fz[3]),
        ];
        if !self.roll.is_empty() {
            columns.push(("roll", &self.roll));
        }
        columns
    }
}

/// A wheel of the four-wheel load model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Wheel {
    /// Front left.
    FrontLeft,
    /// Front right.
    FrontRight,
    /// Rear left.
    RearLeft,
    /// Rear right.
    RearRight,
}

impl Wheel {
    /// The wheels in the order of [`TimeHistory::fz`].
    pub const ALL: [Wheel; 4] = [
        Wheel::FrontLeft,
        Wheel::FrontRight,
        Wheel::RearLeft,
        Wheel::RearRight,
    ];
}

/// An interval during which a wheel carried no load.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LiftOff {
    /// The wheel off the ground.
    pub wheel: Wheel,
    /// First recorded time with zero load, s.
    pub start: f64,
    /// Last recorded time with zero load, s.
    pub end: f64,
}

impl TimeHistory {
    /// Every interval of recorded rows in which a wheel's load is zero, in
    /// wheel order then time order.
    pub(crate) fn lift_offs(&self) -> Vec<LiftOff> {
        let mut out = Vec::new();
        for (wheel, fz) in Wheel::ALL.iter().zip(&self.fz) {
            let mut start = None;
            for (i, &f) in fz.iter().enumerate() {
                match (f <= 0.0, start) {
                    (true, None) => start = Some(i),
                    (false, Some(s)) => {
                        out.push(LiftOff {
                            wheel: *wheel,
                            start: self.t[s],
                            end: self.t[i - 1],
                        });
                        start = None;
                    }
                    _ => {}
                }
            }
            if let Some(s) = start {
                out.push(LiftOff {
                    wheel: *wheel,
                    start: self.t[s],
                    end: self.t[fz.len() - 1],
                });
            }
        }
        out
    }
}

/// The integration methods by name, as a scenario file's `method` names them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum MethodName {
    /// Dormand–Prince 5(4), error-controlled, dense output (the default).
    Dopri5,
    /// Dormand & Prince's 8(5,3) (DOP853), error-controlled, dense output
    /// of order 7: fewer evaluations at tight tolerances.
    Dop853,
    /// Classical fixed-step RK4.
    Rk4,
}

impl MethodName {
    /// The method as `simulate` names it.
    pub fn title(self) -> &'static str {
        match self {
            MethodName::Dopri5 => "Dormand–Prince 5(4)",
            MethodName::Dop853 => "Dormand–Prince 8(5,3)",
            MethodName::Rk4 => "RK4",
        }
    }
}

/// The default method's name: that of [`Method::default`].
impl Default for MethodName {
    fn default() -> Self {
        Method::default().name()
    }
}

/// How the vehicle model is integrated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Method {
    /// Classical RK4 at the output step.
    Rk4,
    /// Dormand–Prince 5(4) with error control; rows are the dense output at
    /// every output step.
    Dopri5(Tolerances),
    /// Dormand & Prince's 8(5,3) (DOP853), as [`Method::Dopri5`] otherwise:
    /// at rtol 1e-10 about half the right-hand sides of the 5(4) pair on
    /// a step steer (docs/src/benchmarks.md, session 111).
    Dop853(Tolerances),
}

/// The default of every simulation, scenario files' included:
/// Dormand–Prince at the default tolerances (the step-steer metrics measured
/// on its dense output, events located to the tolerance).
impl Default for Method {
    fn default() -> Self {
        Method::Dopri5(Tolerances::default())
    }
}

impl Method {
    /// The method's name.
    pub fn name(&self) -> MethodName {
        match self {
            Method::Rk4 => MethodName::Rk4,
            Method::Dopri5(_) => MethodName::Dopri5,
            Method::Dop853(_) => MethodName::Dop853,
        }
    }

    /// The pair and tolerances of an error-controlled method; None for
    /// RK4.
    pub fn adaptive(&self) -> Option<(Pair, Tolerances)> {
        match *self {
            Method::Rk4 => None,
            Method::Dopri5(tol) => Some((Pair::Dopri5, tol)),
            Method::Dop853(tol) => Some((Pair::Dop853, tol)),
        }
    }
}

/// The default interval of recorded rows (and RK4 step), s.
pub(crate) const DEFAULT_STEP: f64 = 1e-3;

/// Integration settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Integrator {
    /// Step, s: the RK4 step, and the interval of recorded rows for both
    /// methods.
    pub step: f64,
    /// Road friction scale.
    pub friction: f64,
    /// The integration method.
    pub method: Method,
}

/// What a scenario file without a `[simulation]` table gets: the default
/// [`Method`] (Dormand–Prince) with rows every [`DEFAULT_STEP`], on a road
/// of friction scale 1.
impl Default for Integrator {
    fn default() -> Self {
        Self {
            step: DEFAULT_STEP,
            friction: 1.0,
            method: Method::default(),
        }
    }
}

/// Tolerance of the load-transfer loop under Dormand–Prince with `tol`: the
/// relative tolerance itself, bounded by the model's own 1e-9 and by
/// rounding (1e-13). The loop's residual acts as noise on the right-hand
/// side at that level; solving it a hundred times tighter moved no
/// step-steer metric of the bundled PAC89 scenario by more than rounding
/// in its leading digits and cost 15 % more tyre evaluations (measured).
pub(crate) fn load_tolerance(tol: &Tolerances) -> f64 {
    tol.rtol.clamp(1e-13, 1e-9)
}

/// A simulation: the recorded rows and, for an adaptive method, the dense
/// solution they were sampled from.
#[derive(Debug, Clone, PartialEq)]
pub struct Simulation {
    /// Rows every output step.
    pub history: TimeHistory,
    /// The continuous solution (Dormand–Prince with the (β, r) state only:
    /// with extra states the metrics are measured on the rows).
    pub dense: Option<DenseSolution<2>>,
    /// The work of an adaptive integration (None for RK4), of the full
    /// state where there is no dense (β, r) solution.
    pub work: Option<Stats>,
}

impl Simulation {
    /// Work of the adaptive integration (None for RK4).
    pub fn stats(&self) -> Option<Stats> {
        self.work
    }
}

impl Integrator {
    /// The inputs of `m` at time `t` on this integrator's road.
    pub(crate) fn inputs(&self, m: &Manoeuvre, t: f64) -> Inputs {
        manoeuvre_inputs(m, t, self.friction)
    }

    /// Simulates `manoeuvre` from `x0` over its duration, recording a row
    /// every `step`.
    pub fn run(&self, model: &VehicleModel, manoeuvre: &Manoeuvre, x0: State) -> TimeHistory {
        if let Some((origin, from_zero)) = from_origin(manoeuvre) {
            let mut h = self.run(model, &from_zero, x0);
            h.t.iter_mut().for_each(|t| *t += origin);
            return h;
        }
        match self.method.adaptive() {
            None => self.run_rk4(model, manoeuvre, x0, None),
            Some(pair) => self.run_adaptive(model, manoeuvre, x0, pair, None).0,
        }
    }

    /// Simulates `manoeuvre` from `x0`: the rows and, under Dormand–Prince,
    /// the dense solution.
    pub fn simulate(&self, model: &VehicleModel, manoeuvre: &Manoeuvre, x0: State) -> Simulation {
        self.simulate_counted(model, manoeuvre, x0, None)
    }

    /// The work units of [`Integrator::simulate_counted`] on `manoeuvre`:
    /// its rows, twice under Dormand–Prince (the integration, then the
    /// rows evaluated at its dense output).
    pub fn work_units(&self, manoeuvre: &Manoeuvre) -> usize {
        let span = manoeuvre.end_time() - manoeuvre.start_time();
        let rows = (span / self.step).round().max(0.0) as usize;
        match self.method {
            Method::Rk4 => rows,
            Method::Dopri5(_) | Method::Dop853(_) => 2 * rows,
        }
    }

    /// [`Integrator::simulate`], counting its work into `progress` as it
    /// goes ([`Integrator::work_units`] in all).
    pub fn simulate_counted(
        &self,
        model: &VehicleModel,
        manoeuvre: &Manoeuvre,
        x0: State,
        progress: Option<&std::sync::atomic::AtomicUsize>,
    ) -> Simulation {
        if let Some((origin, from_zero)) = from_origin(manoeuvre) {
            let mut sim = self.simulate_counted(model, &from_zero, x0, progress);
            sim.history.t.iter_mut().for_each(|t| *t += origin);
            sim.dense = sim.dense.map(|d| d.shifted(origin));
            return sim;
        }
        match self.method.adaptive() {
            None => Simulation {
                history: self.run_rk4(model, manoeuvre, x0, progress),
                dense: None,
                work: None,
            },
            Some(pair) => {
                let (history, dense, work) =
                    self.run_adaptive(model, manoeuvre, x0, pair, progress);
                Simulation {
                    history,
                    dense,
                    work: Some(work),
                }
            }
        }
    }
}

/// A replay whose time does not start at zero, moved to start there, with
/// its origin, s: integrated in time from the run's start, so that a log
/// on Unix-epoch time (1.69e9 s) is stepped as the same log from zero is
/// (at 1.69e9 s an f64 resolves only 2.4e-7 s, and the step-size control
/// rejected steps it would not have). The history is told in the log's
/// own time.
fn from_origin(manoeuvre: &Manoeuvre) -> Option<(f64, Manoeuvre)> {
    match manoeuvre {
        Manoeuvre::Replay(r) if r.t.first().is_some_and(|t| *t != 0.0) => {
            let origin = r.t[0];
            let t = r.t.iter().map(|t| t - origin).collect();
            Some((origin, Manoeuvre::Replay(Replay { t, ..r.clone() })))
        }
        _ => None,
    }
}
