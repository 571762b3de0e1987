//! Cost of one full combined-slip Magic Formula 6.1 evaluation (fx, fy, mz,
//! mx, my) of MFeval's public 6.1 file, over a cycle of 64 operating points;
//! and of one pure-lateral evaluation (κ = 0, the vehicle model's case) at
//! the same points; and of the slip part alone at a load prepared once
//! (`MagicFormula::at_load`, for callers that evaluate one load at many slips).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use handling::io::tir::load_tir;
use handling::tyre::mf::MfInput;
use std::path::Path;

fn combined(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let tyre = load_tir(&path).expect("fixture loads");
    let points: Vec<MfInput> = (0..64)
        .map(|i| {
            let f = i as f64;
            MfInput {
                fz: 3000.0 + 80.0 * f,
                kappa: -0.15 + 0.005 * f,
                alpha: -0.2 + 0.006 * f,
                camber: 0.03 * (f * 0.3).sin(),
                speed: 20.0,
                pressure: Some(240_000.0),
            }
        })
        .collect();
    let mut i = 0;
    c.bench_function("mf61_combined_slip_one_evaluation", |b| {
        b.iter(|| {
            i = (i + 1) & 63;
            black_box(tyre.evaluate(black_box(&points[i])))
        })
    });
    let lateral: Vec<MfInput> = points
        .iter()
        .map(|p| MfInput { kappa: 0.0, ..*p })
        .collect();
    c.bench_function("mf61_pure_lateral_one_evaluation", |b| {
        b.iter(|| {
            i = (i + 1) & 63;
            black_box(tyre.evaluate(black_box(&lateral[i])))
        })
    });
    let prepared = tyre.at_load(4500.0, Some(240_000.0), 0.02);
    c.bench_function("mf61_combined_slip_at_prepared_load", |b| {
        b.iter(|| {
            i = (i + 1) & 63;
            let p = black_box(&points[i]);
            black_box(prepared.forces(p.kappa, p.alpha, p.speed))
        })
    });
}

criterion_group!(benches, combined);
criterion_main!(benches);
