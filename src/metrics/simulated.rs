//! Step-steer metrics of a simulation: measured on its Dormand–Prince dense
//! solution (events located to the integrator's tolerance, integrals by
//! quadrature, [`super::continuous`]) when there is one and no low-pass is
//! asked for, on its recorded rows otherwise (crossings interpolated
//! between rows). The dense record evaluates the vehicle model at every
//! sample for ay and the yaw acceleration, its load-transfer loop solved
//! to the tolerance the integration used. Units: SI, rad.

use super::continuous::{step_metrics_continuous, ContinuousRecord, Sample};
use super::{step_metrics, MetricSettings, MetricsError, StepMetrics};
use crate::manoeuvre::Manoeuvre;
use crate::sim::{load_tolerance, DenseSolution, Integrator, Method, Simulation};
use crate::vehicle::{LoadTransferSeed, State, VehicleModel};

/// The dense solution of a simulation as a continuous record of its
/// signals: states from the solution's continuous extension, ay and the yaw
/// acceleration from the model evaluated there (the load-transfer loop
/// solved at every sample), steer from the manoeuvre.
pub struct DenseRecord<'a> {
    model: &'a VehicleModel,
    manoeuvre: &'a Manoeuvre,
    integrator: &'a Integrator,
    solution: &'a DenseSolution<2>,
    knots: Vec<f64>,
    seed: LoadTransferSeed,
    load_tolerance: f64,
}

impl<'a> DenseRecord<'a> {
    /// The record of `solution`, integrated by `integrator` from `model`
    /// under `manoeuvre`.
    pub fn new(
        model: &'a VehicleModel,
        manoeuvre: &'a Manoeuvre,
        integrator: &'a Integrator,
        solution: &'a DenseSolution<2>,
    ) -> Self {
        let (t0, t1) = (solution.start(), solution.end());
        let mut knots: Vec<f64> = solution
            .step_times()
            .chain(manoeuvre.breakpoints())
            .filter(|t| (t0..=t1).contains(t))
            .collect();
        knots.sort_by(f64::total_cmp);
        knots.dedup();
        let load_tolerance = match integrator.method {
            Method::Dopri5(tol) | Method::Dop853(tol) => load_tolerance(&tol),
            Method::Rk4 => 1e-9,
        };
        Self {
            model,
            manoeuvre,
            integrator,
            solution,
            knots,
            seed: LoadTransferSeed::default(),
            load_tolerance,
        }
    }
}

impl ContinuousRecord for DenseRecord<'_> {
    fn span(&self) -> (f64, f64) {
        (self.solution.start(), self.solution.end())
    }
    fn knots(&self) -> &[f64] {
        &self.knots
    }
    fn sample(&mut self, t: f64) -> Sample {
        let x = self.solution.state(t);
        let state = State {
            beta: x[0],
            yaw_rate: x[1],
        };
        let inp = self.integrator.inputs(self.manoeuvre, t);
        self.seed.ay = [self.seed.ay[0]; 3];
        let o = self
            .model
            .evaluate_to(&state, &inp, &mut self.seed, self.load_tolerance);
        Sample {
            steer: inp.steer,
            yaw_rate: x[1],
            yaw_acceleration: o.yaw_acceleration,
            ay: o.ay,
            beta: x[0],
        }
    }
}

/// Step-steer metrics of a simulation `sim` of `manoeuvre` made by
/// `integrator`: from the dense solution when there is one and no
/// low-pass is asked for (events to the tolerance), from the rows
/// otherwise (crossings interpolated between rows).
pub fn simulated_step_metrics(
    integrator: &Integrator,
    model: &VehicleModel,
    manoeuvre: &Manoeuvre,
    sim: &Simulation,
    settings: &MetricSettings,
) -> Result<StepMetrics, MetricsError> {
    match (&sim.dense, settings.filter_hz) {
        (Some(sol), None) => step_metrics_continuous(
            &mut DenseRecord::new(model, manoeuvre, integrator, sol),
            settings,
        ),
        _ => {
            let h = &sim.history;
            step_metrics(
                &h.t,
                &h.steer,
                &h.yaw_rate,
                Some(&h.ay),
                Some(&h.beta),
                settings,
            )
        }
    }
}
