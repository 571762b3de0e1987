//! Simulation speed: a 10 s GB/T 6323 step steer with PAC89 tyres on four
//! wheels and load transfer (`step_steer_10s_pac89_load_transfer/…`):
//! fixed-step RK4 at 1 ms (`rk4_1ms`), Dormand–Prince 5(4) at the default
//! tolerances (`dopri5`: the dense solution; `dopri5_metrics`: and the
//! metrics from it; `dopri5_rows_1ms`: with 1 kHz rows; `solver_rtol_1e-10`:
//! the solver alone at SciPy's tolerances, the peer script's job), DOP853
//! beside them (`dop853`, `dop853_rows_1ms`, `solver_rtol_1e-10_dop853`); the older id
//! `step_steer_10s_1khz_pac89_load_transfer` (RK4 at 1 ms) is kept. Also the
//! cost of one lateral-force evaluation per tyre model and of one
//! stiffness-study combination.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use handling::manoeuvre::{Manoeuvre, StepSteer};
use handling::metrics::{simulated_step_metrics, MetricSettings};
use handling::sim::peer::PeerStepSteer;
use handling::sim::{Integrator, Method, Pair, Tolerances};
use handling::tyre::{Gim, Linear, MagicSimple, Pac89, SlipState, Tyre, TyreModel};
use handling::vehicle::{State, Vehicle, VehicleModel};

fn step_steer(c: &mut Criterion) {
    // The peer comparison's job (`handling::sim::peer`): its model and
    // manoeuvre for every id of the group.
    let job = PeerStepSteer::new();
    let (model, man) = (&job.model, &job.manoeuvre);
    let integ = Integrator {
        method: Method::Rk4,
        ..Integrator::default()
    };
    c.bench_function("step_steer_10s_1khz_pac89_load_transfer", |b| {
        b.iter(|| integ.run(black_box(model), black_box(man), State::default()))
    });
    let tol = Tolerances::default();
    let dopri = Integrator {
        method: Method::Dopri5(tol),
        ..Integrator::default()
    };
    // Stable ids: `<group>/<variant>`.
    let mut g = c.benchmark_group("step_steer_10s_pac89_load_transfer");
    g.bench_function("rk4_1ms", |b| {
        b.iter(|| integ.run(black_box(model), black_box(man), State::default()))
    });
    // The default: the error-controlled solution (what the metrics are
    // measured on), rows every 0.1 s.
    let coarse = Integrator { step: 0.1, ..dopri };
    g.bench_function("dopri5", |b| {
        b.iter(|| coarse.simulate(black_box(model), black_box(man), State::default()))
    });
    // The same and every GB/T 6323 metric from the dense output.
    g.bench_function("dopri5_metrics", |b| {
        let settings = MetricSettings::default();
        b.iter(|| {
            let sim = coarse.simulate(black_box(model), black_box(man), State::default());
            simulated_step_metrics(&coarse, model, man, &sim, &settings).unwrap()
        })
    });
    // With a row every 1 ms (the history a scenario writes by default).
    g.bench_function("dopri5_rows_1ms", |b| {
        b.iter(|| dopri.run(black_box(model), black_box(man), State::default()))
    });
    // The same two by DOP853 (`method = "dop853"`) at the same tolerances.
    let dop853 = Integrator {
        method: Method::Dop853(tol),
        ..coarse
    };
    g.bench_function("dop853", |b| {
        b.iter(|| dop853.simulate(black_box(model), black_box(man), State::default()))
    });
    let dop853_rows = Integrator {
        step: 1e-3,
        ..dop853
    };
    g.bench_function("dop853_rows_1ms", |b| {
        b.iter(|| dop853_rows.run(black_box(model), black_box(man), State::default()))
    });
    // The solver alone as `peer/scipy_peer.py` runs SciPy's `solve_ivp`
    // (RK45) against it: rtol 1e-10, atol 1e-13, no largest step, (β, r)
    // every 10 ms from the dense output. The job of the ≥ 300× SciPy target
    // (`examples/peer_jobs.rs` times the same).
    g.bench_function("solver_rtol_1e-10", |b| {
        let mut states = Vec::with_capacity(job.grid.len());
        b.iter(|| black_box(&job).solve_into(&coarse, Pair::Dopri5, &mut states))
    });
    // The same job by DOP853 (Dormand & Prince's 8(5,3) pair): about half
    // the right-hand sides, its error below SciPy's RK45's at the same
    // tolerance (`vehicle::tests::dop853`).
    g.bench_function("solver_rtol_1e-10_dop853", |b| {
        let mut states = Vec::with_capacity(job.grid.len());
        b.iter(|| black_box(&job).solve_into(&coarse, Pair::Dop853, &mut states))
    });
    g.finish();
}

fn tyre_evaluation(c: &mut Criterion) {
    let unitire: Tyre = toml::from_str(include_str!("../tyres/unitire.toml")).unwrap();
    let tyres = [
        ("gim", Tyre::Gim(Gim::new(57_296.0, 0.18, 1.0))),
        (
            "magic-simple",
            Tyre::MagicSimple(MagicSimple::new(10.0, 1.3)),
        ),
        ("unitire", unitire),
        ("pac89", Tyre::Pac89(Pac89::adams_example())),
        ("linear", Tyre::Linear(Linear::new(57_296.0))),
    ];
    let mut g = c.benchmark_group("tyre_lateral_force");
    for (name, t) in &tyres {
        g.bench_function(*name, |b| {
            let mut a = 0.0;
            b.iter(|| {
                a = if a > 0.2 { -0.2 } else { a + 1e-3 };
                t.lateral_force(black_box(&SlipState::lateral(a, 4000.0)))
            })
        });
    }
    g.finish();
}

/// One combination of the stiffness study (Gim, load transfer, 4.5 s at
/// 2 ms): the 100 × 100 map is 10,000 of these.
fn study_combination(c: &mut Criterion) {
    use handling::study::Study;
    let st = Study {
        model: VehicleModel::new(
            Vehicle::compact_sedan(),
            Tyre::Gim(Gim::new(28_648.0, 0.16, 1.0)),
            Tyre::Gim(Gim::new(30_940.0, 0.16, 1.0)),
        ),
        manoeuvre: Manoeuvre::StepSteer(StepSteer {
            speed: 22.2222,
            amplitude: 0.0174533,
            trim: 0.0,
            start: 0.5,
            rise_time: 0.1,
            end: 4.5,
        }),
        integrator: Integrator {
            step: 2e-3,
            friction: 1.0,
            method: Method::Rk4,
        },
        metrics: handling::metrics::MetricSettings::default(),
    };
    c.bench_function("study_one_combination_gim_2ms", |b| {
        b.iter(|| st.evaluate(black_box(30_000.0), black_box(32_000.0)))
    });
}

criterion_group!(benches, step_steer, tyre_evaluation, study_combination);
criterion_main!(benches);
