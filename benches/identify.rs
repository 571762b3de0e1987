//! Identification speed: a PAC89 lateral fit (PSO + Levenberg–Marquardt) on
//! Zhang & Li's (2017) three loads × 85 points (the target: under 2 s on one
//! core), and the cost of one objective evaluation.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use handling::identify::data::identification_conditions;
use handling::identify::{fit_lateral, FitProblem, FitSettings};
use handling::optim::local::Residuals;
use handling::tyre::{Pac89, Parameterised, Tyre};

fn pac89_fit(c: &mut Criterion) {
    let truth = Tyre::Pac89(Pac89::adams_example());
    let (data, _) = identification_conditions(&truth, 0.01, 1);
    let mut start = Pac89::adams_example();
    start
        .a
        .iter_mut()
        .enumerate()
        .filter(|(i, _)| ![5, 8, 11].contains(i))
        .for_each(|(_, v)| *v *= 1.1);
    let start = Tyre::Pac89(start);
    let mut settings = FitSettings::new(1);
    // One core, as the requirement is stated.
    settings.pso.parallel = false;
    let mut g = c.benchmark_group("identify");
    g.sample_size(10);
    g.bench_function("pac89_lateral_fit_3x85_one_core", |b| {
        b.iter(|| fit_lateral(black_box(&start), &data, &settings).unwrap())
    });
    let free = start.lateral_free(3, 1);
    let problem = FitProblem::new(&start, &free, &data);
    let p: Vec<f64> = start
        .parameters()
        .iter()
        .zip(&free)
        .filter(|(_, f)| **f)
        .map(|(v, _)| *v)
        .collect();
    g.bench_function("pac89_objective_255_points", |b| {
        b.iter(|| problem.cost(black_box(&p)))
    });
    g.finish();
}

criterion_group!(benches, pac89_fit);
criterion_main!(benches);
