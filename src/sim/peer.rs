//! The peer comparison's step-steer job, set up once for the four places
//! that time or test it (`examples/peer_jobs.rs`, `examples/peer_jobs_step.rs`,
//! `benches/simulate.rs`, `vehicle::tests`): the 10 s GB/T 6323 step steer
//! (80 km/h, 0.012 rad in 0.1 s from 1 s) of the compact sedan on four
//! PAC89 wheels (the Adams example) with lateral load transfer and exact
//! kinematics, solved alone (no model outputs) at SciPy's tolerances (rtol
//! 1e-10, atol 1e-13, no largest step) with (β, r) read every 10 ms from
//! the dense output: the job `peer/scipy_peer.py` times SciPy's RK45 on.
//! Units: SI, rad.

use super::{DenseSolution, Integrator, Pair, Stats, Tolerances};
use crate::manoeuvre::{Manoeuvre, StepSteer};
use crate::tyre::{Pac89, Tyre};
use crate::vehicle::{Kinematics, State, Vehicle, VehicleModel};

/// The step steer's model, manoeuvre, tolerances and output grid.
#[derive(Debug, Clone)]
pub struct PeerStepSteer {
    /// The compact sedan on four PAC89 wheels, load transfer on, exact
    /// kinematics.
    pub model: VehicleModel,
    /// 0.012 rad at 22.2222 m/s, ramped over 0.1 s from 1 s, to 10 s.
    pub manoeuvre: Manoeuvre,
    /// SciPy's: rtol 1e-10, atol 1e-13, no largest step.
    pub tolerances: Tolerances,
    /// Every 10 ms from 0 to 10 s (1001 times).
    pub grid: Vec<f64>,
}

impl PeerStepSteer {
    /// The job as the peer script runs it.
    pub fn new() -> Self {
        let mut model = VehicleModel::new(
            Vehicle::compact_sedan(),
            Tyre::Pac89(Pac89::adams_example()),
            Tyre::Pac89(Pac89::adams_example()),
        );
        // The defaults, stated: the job is defined by them.
        model.options.kinematics = Kinematics::Exact;
        model.options.load_transfer = true;
        let manoeuvre = Manoeuvre::StepSteer(StepSteer {
            speed: 22.2222,
            amplitude: 0.012,
            trim: 0.0,
            start: 1.0,
            rise_time: 0.1,
            end: 10.0,
        });
        Self {
            model,
            manoeuvre,
            tolerances: Tolerances {
                rtol: 1e-10,
                atol: 1e-13,
                max_step: f64::INFINITY,
            },
            grid: (0..=1000).map(|i| f64::from(i) * 0.01).collect(),
        }
    }

    /// The dense (β, r) solution by `pair` at tolerances `tol` (the job's
    /// own, or another for a reference), from rest.
    pub fn solution(&self, integ: &Integrator, pair: Pair, tol: &Tolerances) -> DenseSolution<2> {
        let (m, man, x0) = (&self.model, &self.manoeuvre, State::default());
        match pair {
            Pair::Dopri5 => integ.solve_dopri5(m, man, x0, tol),
            Pair::Dop853 => integ.solve_dop853(m, man, x0, tol),
        }
        .expect("a (β, r) model has a dense solution")
    }

    /// The job: the solution by `pair` at the job's tolerances, (β, r) at
    /// the grid into `states` (reused, not reallocated once it holds the
    /// grid), and the solver's counts.
    pub fn solve_into(&self, integ: &Integrator, pair: Pair, states: &mut Vec<[f64; 2]>) -> Stats {
        let sol = self.solution(integ, pair, &self.tolerances);
        sol.states_into(&self.grid, states);
        sol.stats
    }
}

impl Default for PeerStepSteer {
    fn default() -> Self {
        Self::new()
    }
}
