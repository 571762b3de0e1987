//! Simulation speed: a 10 s step steer at 1 kHz with PAC89 tyres and load
//! transfer (issue #2 asks for ≥ 1000× real time on one core), and the cost
//! of one lateral-force evaluation per tyre model.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use handling::manoeuvre::{Manoeuvre, StepSteer};
use handling::sim::Integrator;
use handling::tyre::{Gim, Linear, MagicSimple, Pac89, SlipState, Tyre, TyreModel};
use handling::vehicle::{State, Vehicle, VehicleModel};

fn step_steer(c: &mut Criterion) {
    let model = VehicleModel::new(
        Vehicle::seed004_sedan(),
        Tyre::Pac89(Pac89::adams_example()),
        Tyre::Pac89(Pac89::adams_example()),
    );
    let man = Manoeuvre::StepSteer(StepSteer {
        speed: 22.2222,
        amplitude: 0.012,
        trim: 0.0,
        start: 1.0,
        rise_time: 0.1,
        end: 10.0,
    });
    let integ = Integrator::default();
    c.bench_function("step_steer_10s_1khz_pac89_load_transfer", |b| {
        b.iter(|| integ.run(black_box(&model), black_box(&man), State::default()))
    });
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

criterion_group!(benches, step_steer, tyre_evaluation);
criterion_main!(benches);
