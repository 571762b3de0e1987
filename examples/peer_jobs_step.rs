//! The peer comparison's step-steer job alone, repeated, for a profiler
//! (`perf record`) and for timing without the other peer jobs: the 10 s
//! GB/T 6323 step steer (80 km/h, 0.012 rad, 0.1 s rise) of the compact
//! sedan on four PAC89 wheels with load transfer and exact kinematics, the
//! solver alone at SciPy's rtol 1e-10 / atol 1e-13 with no largest step,
//! (β, r) every 10 ms from the dense output (`handling::sim::peer`, as
//! `peer_jobs`'s `step_steer_solver` rows). Prints the pair, its counts,
//! the median and lowest time of one solve and the median per right-hand
//! side (the integrator's share included).
//!
//! Run: `cargo run --release --example peer_jobs_step -- [dop853|dopri5] [repeats]`.

use handling::sim::peer::PeerStepSteer;
use handling::sim::{Integrator, Pair};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let pair = match args.get(1).map(String::as_str) {
        Some("dopri5") => Pair::Dopri5,
        _ => Pair::Dop853,
    };
    let repeats: usize = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(2000);
    let job = PeerStepSteer::new();
    let integ = Integrator::default();
    let mut states = Vec::with_capacity(job.grid.len());
    let stats = job.solve_into(&integ, pair, &mut states);
    let mut t: Vec<f64> = (0..repeats)
        .map(|_| {
            let s = Instant::now();
            std::hint::black_box(job.solve_into(&integ, pair, &mut states));
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    let median = t[t.len() / 2];
    println!(
        "{}: {} steps, {} rejected, {} evaluations; median {:.3} ms, lowest {:.3} ms of {repeats}; {:.0} ns a right-hand side",
        match pair {
            Pair::Dopri5 => "dopri5",
            Pair::Dop853 => "dop853",
        },
        stats.accepted,
        stats.rejected,
        stats.evaluations,
        median * 1e3,
        t[0] * 1e3,
        median * 1e9 / stats.evaluations as f64
    );
}
