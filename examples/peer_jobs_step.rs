//! The peer comparison's step-steer job alone, repeated, for a profiler
//! (`perf record`) and for timing without the other peer jobs: the 10 s
//! GB/T 6323 step steer (80 km/h, 0.012 rad, 0.1 s rise) of the compact
//! sedan on four PAC89 wheels with load transfer and exact kinematics, the
//! solver alone at SciPy's rtol 1e-10 / atol 1e-13 with no largest step,
//! (β, r) every 10 ms from the dense output (as `peer_jobs`'s
//! `step_steer_solver` rows). Prints the pair, its counts and the median
//! and lowest time of one solve.
//!
//! Run: `cargo run --release --example peer_jobs_step -- [dop853|dopri5] [repeats]`.

use handling::manoeuvre::{Manoeuvre, StepSteer};
use handling::sim::{Integrator, Tolerances};
use handling::tyre::{Pac89, Tyre};
use handling::vehicle::{Kinematics, State, Vehicle, VehicleModel};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let eighth = args.get(1).is_none_or(|a| a != "dopri5");
    let repeats: usize = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(2000);
    let mut model = VehicleModel::new(
        Vehicle::compact_sedan(),
        Tyre::Pac89(Pac89::adams_example()),
        Tyre::Pac89(Pac89::adams_example()),
    );
    model.options.kinematics = Kinematics::Exact;
    model.options.load_transfer = true;
    let man = Manoeuvre::StepSteer(StepSteer {
        speed: 22.2222,
        amplitude: 0.012,
        trim: 0.0,
        start: 1.0,
        rise_time: 0.1,
        end: 10.0,
    });
    let tol = Tolerances {
        rtol: 1e-10,
        atol: 1e-13,
        max_step: f64::INFINITY,
    };
    let integ = Integrator::default();
    let grid: Vec<f64> = (0..=1000).map(|i| f64::from(i) * 0.01).collect();
    let mut states = Vec::with_capacity(grid.len());
    let mut solve = || {
        let sol = if eighth {
            integ.solve_dop853(&model, &man, State::default(), &tol)
        } else {
            integ.solve_dopri5(&model, &man, State::default(), &tol)
        }
        .expect("a (β, r) model has a dense solution");
        sol.states_into(&grid, &mut states);
        sol.stats
    };
    let stats = solve();
    let mut t: Vec<f64> = (0..repeats)
        .map(|_| {
            let s = Instant::now();
            std::hint::black_box(solve());
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    println!(
        "{}: {} steps, {} rejected, {} evaluations; median {:.3} ms, lowest {:.3} ms of {repeats}",
        if eighth { "dop853" } else { "dopri5" },
        stats.accepted,
        stats.rejected,
        stats.evaluations,
        t[t.len() / 2] * 1e3,
        t[0] * 1e3
    );
}
