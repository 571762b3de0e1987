//! The replay of a sampled drive ([`Drive`]) in a dual scalar: the same
//! grid, the same method (RK4 or ROS34PW2, [`super::ode::rk4_dual`] /
//! [`super::ode::rosenbrock_w_dual`]), the same stage inputs and the same
//! load-transfer seeds as the plain replay ([`super::Integrator::replay`]),
//! with every state and output carrying its derivatives with respect to
//! the variables the model's numbers ([`ModelScalars`]), its tyres'
//! parameters ([`ParamTyres`]), the road-wheel steer and the initial state
//! were seeded with. The derivative is that of the discrete replay (forward
//! sensitivities by automatic differentiation: the variational equations
//! on the same steps), to rounding; the load-transfer loop and a compliant
//! front's slip are differentiated at their roots, not through their
//! iterations ([`crate::vehicle::scalar`]).
//!
//! What a fit of a replay needs is recorded: sideslip, yaw rate, lateral
//! acceleration and roll at every grid time. Units: SI, rad.

use super::driven::{Drive, FixedStep, W_REFRESH};
use super::ode::sensitivity::{rk4_dual, DualSystem};
use super::ode::{rosenbrock_w_dual, W_PROBE, W_TIME_PROBE};
use crate::vehicle::scalar::{ModelScalars, Scalar};
use crate::vehicle::wheels::ParamTyres;
use crate::vehicle::{LoadSolve, LoadTransferSeed, VehicleModel};
use nalgebra::ComplexField;

/// A vehicle model with its numbers and tyres in a scalar.
#[derive(Debug, Clone)]
pub struct ModelOf<'a, T> {
    /// The model (its structure and plain values).
    pub model: &'a VehicleModel,
    /// Its numbers, with their derivatives.
    pub scalars: ModelScalars<T>,
    /// Its tyres, with their parameters' derivatives.
    pub tyres: ParamTyres<'a, T>,
    /// Relative tolerance of the load-transfer loop on g(ay), as the plain
    /// replay's ([`crate::vehicle::LOAD_TOLERANCE`] by default).
    pub load_tolerance: f64,
}

/// A replay's response in a scalar, at every grid time.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TangentHistory<T> {
    /// Grid times, s.
    pub t: Vec<f64>,
    /// Sideslip, rad.
    pub beta: Vec<T>,
    /// Yaw rate, rad/s.
    pub yaw_rate: Vec<T>,
    /// Lateral acceleration of the tyres' force, m/s².
    pub ay: Vec<T>,
    /// Body roll, rad.
    pub roll: Vec<T>,
}

/// The model driven by a sampled drive, in scalar `T`.
struct Tangent<'a, T> {
    m: &'a ModelOf<'a, T>,
    drive: &'a Drive,
    /// Road-wheel steer at the drive's stage samples (a steer path's
    /// output), replacing the drive's own.
    steer: Option<&'a [T]>,
    seeds: [LoadTransferSeed; 4],
    stage: (usize, usize),
    /// The lateral acceleration of the last evaluation that solved for it.
    last_ay: T,
}

impl<T: Scalar> DualSystem<T, 6> for Tangent<'_, T> {
    fn derivatives(&mut self, _t: f64, x: &[T; 6]) -> [T; 6] {
        let (i, j) = self.stage;
        let d = self.drive;
        let k = d.method.index(i, j).min(d.steer_samples().len() - 1);
        let inp = d.inputs_at(k, self.m.scalars.friction.re());
        let steer = self.steer.map_or(T::from(inp.steer), |s| s[k]);
        let (model, sc, tyres) = (self.m.model, &self.m.scalars, &self.m.tyres);
        if j == W_PROBE || j == W_TIME_PROBE {
            // As the plain replay: at the wheel loads of the step's own
            // solution, which carries its derivatives.
            let solve = LoadSolve::At(self.last_ay);
            return model.rates_of(sc, tyres, x, &inp, steer, solve).dx;
        }
        let solve = LoadSolve::Solved(&mut self.seeds[j], self.m.load_tolerance);
        let o = model.rates_of(sc, tyres, x, &inp, steer, solve);
        self.last_ay = o.ay;
        o.dx
    }

    fn rk4_stage(&mut self, step: usize, stage: usize) {
        self.stage = (step, stage);
    }

    fn w_stage(&mut self, step: usize, stage: usize) {
        self.stage = (step, stage);
    }

    fn implicit_states(&self) -> [bool; 6] {
        let e = &self.m.model.options.effects;
        std::array::from_fn(|i| match i {
            0 | 1 => true,
            2 | 3 => e.lagged(),
            _ => e.uses_roll(),
        })
    }
}

impl<T: Scalar + ComplexField> ModelOf<'_, T> {
    /// Replays `drive` from the full state `x0` by the drive's method, the
    /// road-wheel steer at the drive's stage samples `steer` when given
    /// (else the drive's own): [`super::Integrator::replay`] with
    /// derivatives.
    pub fn replay(&self, drive: &Drive, steer: Option<&[T]>, x0: [T; 6]) -> TangentHistory<T> {
        let n = drive.steps + 1;
        let mut h = TangentHistory {
            t: Vec::with_capacity(n),
            beta: Vec::with_capacity(n),
            yaw_rate: Vec::with_capacity(n),
            ay: Vec::with_capacity(n),
            roll: Vec::with_capacity(n),
        };
        let mut sys = Tangent {
            m: self,
            drive,
            steer,
            seeds: [LoadTransferSeed::default(); 4],
            stage: (0, 0),
            last_ay: T::from(0.0),
        };
        let record = |sys: &mut Tangent<T>, _: usize, t: f64, x: &[T; 6]| {
            h.t.push(t);
            h.beta.push(x[0]);
            h.yaw_rate.push(x[1]);
            h.ay.push(sys.last_ay);
            h.roll.push(x[4]);
            true
        };
        let (t0, step, steps) = (drive.start, drive.step, drive.steps);
        match drive.method {
            FixedStep::Rk4 => rk4_dual(&mut sys, t0, step, steps, x0, record),
            FixedStep::RosenbrockW => {
                rosenbrock_w_dual(&mut sys, t0, step, steps, x0, W_REFRESH, record)
            }
        };
        h
    }
}
