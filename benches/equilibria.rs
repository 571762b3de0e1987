//! Cost of one steering-equilibrium condition: the exact reference solver and
//! the PSO search, for the simplified Magic Formula without load transfer
//! (Li, Jia & Zhao's model) and PAC89 with load transfer (the most expensive case).
//! And one line of the dense PAC89 load-transfer grid
//! (`equilibria_dense_grid/pac89_load_transfer_one_line`: 201 steers at one
//! friction and speed, exact solver and PSO certification, the rear half of
//! the scan shared along the line); the grid is 323 such lines, so its wall
//! time on 2 cores is about 160 times this. The whole grid's wall time is
//! measured by `handling equilibria scenarios/dense_grid_*.toml` (`docs/src/equilibria.md`).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use handling::equilibria::pso::{search, PsoSearch};
use handling::equilibria::{exact, sweep, Condition, SearchBox};
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
    let (_, pac) = models().pop().expect("the PAC89 model");
    let line = sweep::Grid {
        steer: (0..=200).map(|i| 0.001 * i as f64).collect(),
        friction: vec![0.8],
        speed: vec![70.0 / 3.6],
    };
    let mut g = c.benchmark_group("equilibria_dense_grid");
    g.sample_size(10);
    g.bench_function("pac89_load_transfer_one_line", |b| {
        b.iter(|| {
            sweep::solve_lines(
                black_box(&pac),
                &line,
                &bx,
                &PsoSearch::default(),
                &[0],
                &std::sync::atomic::AtomicUsize::new(0),
            )
        })
    });
    g.finish();
}

criterion_group!(benches, equilibria);
criterion_main!(benches);
