//! Cost of one steering-equilibrium condition: the exact reference solver and
//! the PSO search, for the simplified Magic Formula without load transfer
//! (Li, Jia & Zhao's model) and PAC89 with load transfer (the most expensive case).
//! The dense-grid wall time is measured by `handling equilibria
//! scenarios/dense_grid_*.toml` (README).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use handling::equilibria::pso::{search, PsoSearch};
use handling::equilibria::{exact, Condition, SearchBox};
use handling::tyre::{MagicSimple, Pac89, Tyre};
use handling::vehicle::{Kinematics, ModelOptions, Vehicle, VehicleModel};

fn models() -> Vec<(&'static str, VehicleModel)> {
    let mut ms = VehicleModel::new(
        Vehicle::compact_sedan(),
        Tyre::MagicSimple(MagicSimple::new(10.0, 1.3)),
        Tyre::MagicSimple(MagicSimple::new(10.0, 1.3)),
    );
    ms.options = ModelOptions {
        kinematics: Kinematics::SmallAngle,
        load_transfer: false,
        ..ModelOptions::default()
    };
    let pac = VehicleModel::new(
        Vehicle::compact_sedan(),
        Tyre::Pac89(Pac89::adams_example()),
        Tyre::Pac89(Pac89::adams_example()),
    );
    vec![("magic_simple", ms), ("pac89_load_transfer", pac)]
}

fn equilibria(c: &mut Criterion) {
    let cond = Condition {
        steer: 0.05,
        friction: 0.8,
        speed: 70.0 / 3.6,
    };
    let bx = SearchBox {
        beta_max: 0.6,
        yaw_rate_max: 1.5,
    };
    let mut g = c.benchmark_group("equilibria_one_condition");
    for (name, m) in models() {
        g.bench_function(format!("exact/{name}"), |b| {
            b.iter(|| exact::solve(black_box(&m), &cond))
        });
        g.bench_function(format!("pso/{name}"), |b| {
            b.iter(|| search(black_box(&m), &cond, &bx, &PsoSearch::default(), &[]))
        });
    }
    g.finish();
}

criterion_group!(benches, equilibria);
criterion_main!(benches);
