//! Identification speed: a PAC89 lateral fit (PSO + Levenberg–Marquardt) on
//! Zhang & Li's (2017) three loads × 85 points (the target: under 2 s on one
//! core), and the cost of one objective evaluation; the same fit with the
//! polish's Jacobian exact (dual numbers) and by forward differences, back
//! to back, for their ratio. And
//! `identify --model mf61` on the Hoosier rig file (`mf61_hoosier_rig`:
//! 59,965 samples over every pressure and camber, Wei et al.'s (2010)
//! staged fit), read from the data folder beside the checkout: skipped,
//! with a line saying so, when the file is missing.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use handling::identify::data::identification_conditions;
use handling::identify::{fit_lateral, Derivatives, FitProblem, FitSettings};
use handling::jobs::identify::{self as job, IdentifyModel, Options, Polish, StartArg};
use handling::optim::local::Residuals;
use handling::tyre::{Pac89, Parameterised, Tyre};
use std::time::Duration;

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
    for (id, derivatives) in [
        ("pac89_lateral_fit_exact_jacobian", Derivatives::Exact),
        (
            "pac89_lateral_fit_difference_jacobian",
            Derivatives::Differences,
        ),
    ] {
        let settings = FitSettings {
            derivatives,
            ..settings
        };
        g.bench_function(id, |b| {
            b.iter(|| fit_lateral(black_box(&start), &data, &settings).unwrap())
        });
    }
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

/// The Hoosier rig file, as the command line's `identify <file> --model
/// mf61` fits it (its default options; nothing written).
fn mf61_hoosier(c: &mut Criterion) {
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/data/tyre_ttc_hoosier_43075/cornering.csv");
    if !data.is_file() {
        eprintln!(
            "identify/mf61_hoosier_rig skipped: {} is missing",
            data.display()
        );
        return;
    }
    let options = Options {
        data,
        model: IdentifyModel::Mf61,
        seed: 1,
        out: Some(std::env::temp_dir().join("mf61_hoosier_rig_bench.tir")),
        load: None,
        pressure: None,
        camber: None,
        local: Polish::Lm,
        alpha_bin_deg: 0.25,
        kappa_bin: 0.0025,
        start: StartArg::Data,
        template: None,
        max_iterations: None,
        hold: Vec::new(),
    };
    let mut g = c.benchmark_group("identify");
    g.sample_size(10);
    g.measurement_time(Duration::from_secs(150));
    g.bench_function("mf61_hoosier_rig", |b| {
        b.iter(|| job::run(black_box(&options)).unwrap())
    });
    g.finish();
}

criterion_group!(benches, pac89_fit, mf61_hoosier);
criterion_main!(benches);
