//! The jobs that `peer/scipy_peer.py` times in SciPy, timed here in the
//! crate on the same machine, printed as one JSON object:
//! - a 10 s GB/T 6323 step steer (80 km/h, 0.012 rad, 0.1 s rise) of the
//!   compact sedan on four PAC89 wheels (the Adams example) with lateral load
//!   transfer and exact kinematics, by Dormand–Prince 5(4) at the default
//!   tolerances; its yaw rate every 10 ms goes to `peer/out/step_crate.csv`
//!   so the script checks it against its own tight reference;
//! - the same step steer as SciPy's job is: the solver alone at SciPy's
//!   tolerances (rtol 1e-6 / atol 1e-9, and 1e-10 / 1e-13) with no largest
//!   step, (β, r) every 10 ms from the dense output
//!   (`peer/out/step_solver_<rtol>.csv`), and at rtol 1e-4 / atol 1e-7, the
//!   loosest of ours whose error stays below SciPy's at rtol 1e-6 (the
//!   script checks that it does); and at rtol 1e-10 by DOP853
//!   (`solve_dop853`, `method` "dop853" in the JSON);
//! - the three steering-equilibrium sweeps of Li, Jia & Zhao (steer,
//!   friction, speed; `scenarios/equilibria_*.toml`, without the bifurcation
//!   search), equilibria per condition;
//! - a PAC89 lateral fit (PSO + Levenberg–Marquardt) of 3 loads × 85 slip
//!   angles with 1 % noise, from the Adams example scaled by 1.1, and the
//!   Levenberg–Marquardt polish alone from that start (SciPy's job); the
//!   data go to `peer/out/fit_data.csv` so the script fits the same points.
//!
//! Run: `cargo run --release --example peer_jobs -- [repeats]`.

use handling::equilibria::sweep;
use handling::identify::data::identification_conditions;
use handling::identify::{fit_lateral, FitSettings};
use handling::io::sweep::load_sweep;
use handling::optim::Pso;
use handling::sim::peer::PeerStepSteer;
use handling::sim::{Integrator, Method, Pair, Tolerances};
use handling::tyre::{Pac89, Tyre};
use handling::vehicle::State;
use std::path::Path;
use std::sync::atomic::AtomicUsize;
use std::time::Instant;

/// A pair's name in the JSON and what its states file's name carries
/// after the tolerance.
fn names(pair: Pair) -> (&'static str, &'static str) {
    match pair {
        Pair::Dopri5 => ("dopri5", ""),
        Pair::Dop853 => ("dop853", "_dop853"),
    }
}

fn median_seconds(repeats: usize, mut job: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..repeats)
        .map(|_| {
            let s = Instant::now();
            job();
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

fn main() {
    let repeats: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(50);
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    std::fs::create_dir_all(root.join("peer/out")).expect("peer/out");

    // Step steer (`handling::sim::peer`: its model and manoeuvre).
    let job = PeerStepSteer::new();
    let (model, man) = (&job.model, &job.manoeuvre);
    let tol = Tolerances::default();
    let integ = Integrator {
        step: 0.01,
        method: Method::Dopri5(tol),
        ..Integrator::default()
    };
    let (h, sol) = integ.run_dopri5(model, man, State::default(), &tol);
    let sol = sol.expect("a (β, r) model has a dense solution");
    let csv: String = std::iter::once("t,yaw_rate,beta\n".to_string())
        .chain(
            h.t.iter()
                .zip(&h.yaw_rate)
                .zip(&h.beta)
                .map(|((t, r), b)| format!("{t},{r:e},{b:e}\n")),
        )
        .collect();
    std::fs::write(root.join("peer/out/step_crate.csv"), csv).expect("write");
    let step_steer = median_seconds(repeats * 10, || {
        std::hint::black_box(integ.run_dopri5(model, man, State::default(), &tol));
    });

    // The same step steer as SciPy runs it: the solver alone, (β, r) at the
    // 10 ms grid from the dense output, at SciPy's own tolerances and with no
    // largest step (the job above evaluates the whole model at every output
    // time, for ay, forces and loads, which SciPy's job does not return).
    let grid = &job.grid;
    let mut solver_only = Vec::new();
    let jobs = [
        (1e-6, 1e-9, Pair::Dopri5),
        (1e-10, 1e-13, Pair::Dopri5),
        (1e-10, 1e-13, Pair::Dop853),
        (1e-4, 1e-7, Pair::Dopri5),
    ];
    for (rtol, atol, pair) in jobs {
        let tol = Tolerances {
            rtol,
            atol,
            max_step: f64::INFINITY,
        };
        let solve = |out: &mut Vec<[f64; 2]>| {
            let sol = job.solution(&integ, pair, &tol);
            sol.states_into(grid, out);
            sol.stats
        };
        let mut states = Vec::with_capacity(grid.len());
        let stats = solve(&mut states);
        let csv: String = std::iter::once("t,yaw_rate,beta\n".to_string())
            .chain(
                grid.iter()
                    .zip(&states)
                    .map(|(t, x)| format!("{t},{:e},{:e}\n", x[1], x[0])),
            )
            .collect();
        let (name, suffix) = names(pair);
        let file = format!("peer/out/step_solver_{rtol:e}{suffix}.csv");
        std::fs::write(root.join(&file), csv).expect("write");
        let seconds = median_seconds(repeats * 10, || {
            std::hint::black_box(solve(&mut states));
        });
        solver_only.push(format!(
            "{{\"file\": \"{file}\", \"method\": \"{name}\", \"rtol\": {rtol:e}, \"atol\": {atol:e}, \"seconds\": {seconds:e}, \"steps\": {}, \"evaluations\": {}}}",
            stats.accepted, stats.evaluations
        ));
    }

    // Equilibrium sweeps.
    let mut sweeps = Vec::new();
    for name in ["steer", "friction", "speed"] {
        let s = load_sweep(&root.join(format!("scenarios/equilibria_{name}.toml"))).expect("sweep");
        let run = || {
            sweep::run(
                &s.model,
                &s.grid,
                &s.search_box,
                &s.pso,
                false,
                &AtomicUsize::new(0),
            )
        };
        let r = run();
        let counts: Vec<usize> = r
            .points
            .iter()
            .map(|p| p.found.iter().filter(|f| f.in_box).count())
            .collect();
        let seconds = median_seconds(repeats.div_ceil(5).max(3), || {
            std::hint::black_box(run());
        });
        sweeps.push(format!(
            "{{\"sweep\": \"{name}\", \"seconds\": {seconds:e}, \"equilibria_in_box\": {counts:?}}}"
        ));
    }

    // PAC89 fit.
    let truth = Tyre::Pac89(Pac89::adams_example());
    let (data, noise_sigma) = identification_conditions(&truth, 0.01, 1);
    let mut start = Pac89::adams_example();
    start
        .a
        .iter_mut()
        .enumerate()
        .filter(|(i, _)| ![5, 8, 11].contains(i))
        .for_each(|(_, v)| *v *= 1.1);
    let start = Tyre::Pac89(start);
    let rows: String = std::iter::once("alpha,fz,fy\n".to_string())
        .chain(
            data.iter()
                .flat_map(|c| c.points.iter())
                .map(|p| format!("{:e},{:e},{:e}\n", p.slip(), p.fz, p.fy())),
        )
        .collect();
    std::fs::write(root.join("peer/out/fit_data.csv"), rows).expect("write");
    let settings = FitSettings::new(1);
    let fit = fit_lateral(&start, &data, &settings).expect("fit");
    let fit_seconds = median_seconds(3, || {
        std::hint::black_box(fit_lateral(&start, &data, &settings).unwrap());
    });
    // SciPy's job: the local polish alone from the same start (a swarm of
    // one particle that does not move, which the polish starts from).
    let local = FitSettings {
        pso: Pso {
            particles: 1,
            iterations: 0,
            ..settings.pso
        },
        ..settings
    };
    let local_fit = fit_lateral(&start, &data, &local).expect("fit");
    let local_seconds = median_seconds(repeats.max(3), || {
        std::hint::black_box(fit_lateral(&start, &data, &local).unwrap());
    });
    println!(
        "{{\"threads\": {}, \"step_steer\": {{\"seconds\": {step_steer:e}, \"steps\": {}, \"evaluations\": {}, \"rtol\": {:e}}}, \
         \"step_steer_solver\": [{}], \"equilibria\": [{}], \"pac89_fit\": {{\"seconds\": {fit_seconds:e}, \"sigma_percent\": {}, \"noise_sigma_percent\": {noise_sigma}, \
         \"local_seconds\": {local_seconds:e}, \"local_sigma_percent\": {}, \"local_evaluations\": {}}}}}",
        rayon::current_num_threads(),
        sol.stats.accepted,
        sol.stats.evaluations,
        tol.rtol,
        solver_only.join(", "),
        sweeps.join(", "),
        fit.sigma_percent,
        local_fit.sigma_percent,
        local_fit.evaluations,
    );
}
