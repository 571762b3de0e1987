//! The staged Magic Formula 6.1 fit (Wei et al. 2010) of the Hoosier rig
//! file (59,965 samples thinned to 3,551 rows over every load, camber and
//! pressure), as `identify <file> --model mf61` runs it, with the stages'
//! Jacobians exact (forward-mode dual numbers) and by forward differences,
//! back to back: `identify/mf61_hoosier_rig_exact` and
//! `identify/mf61_hoosier_rig_differences`. The rows are prepared once,
//! outside the timing. Read from the data folder beside the checkout:
//! skipped, with a line saying so, when the file is missing.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use handling::identify::mf_staged::{
    identify_with, prepare, Derivatives, Settings, StartScheme, LM_ITERATIONS,
};
use handling::io::rig::read_rig;
use handling::tyre::mf::MfVersion;
use std::time::Duration;

fn mf61_hoosier(c: &mut Criterion) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/data/tyre_ttc_hoosier_43075/cornering.csv");
    if !path.is_file() {
        eprintln!(
            "identify/mf61_hoosier_rig_* skipped: {} is missing",
            path.display()
        );
        return;
    }
    let data = read_rig(&path).expect("the rig file reads");
    // A cornering file: no wheel moments (`mx`, `my`), the command's
    // 0.25° slip-angle bins and speed default.
    let rows = prepare(&path, &data, &[None, None], 0.25f64.to_radians(), 16.7)
        .expect("the rows prepare")
        .rows;
    let settings = Settings {
        version: MfVersion::Mf61,
        start: StartScheme::Data,
        template: None,
        max_iterations: LM_ITERATIONS,
        cap_given: false,
        holding: Default::default(),
    };
    let mut g = c.benchmark_group("identify");
    g.sample_size(10);
    g.measurement_time(Duration::from_secs(60));
    for (id, derivatives) in [
        ("mf61_hoosier_rig_exact", Derivatives::Exact),
        ("mf61_hoosier_rig_differences", Derivatives::Differences),
    ] {
        g.bench_function(id, |b| {
            b.iter(|| identify_with(black_box(&rows), &settings, derivatives).unwrap())
        });
    }
    g.finish();
}

criterion_group!(benches, mf61_hoosier);
criterion_main!(benches);
