//! Cleaning a long measured log: the reliability test's 10⁶-row run (11 h
//! at 25 Hz) with a standstill every 30 min, stop-and-go traffic across the
//! minimum speed, a time gap every hour and a logger glitch every 997
//! samples (one generator, `tests/reliability/long_log_rows.rs`), cleaned as
//! `diagnose` cleans it (`measured/clean_1e6_rows`), and the step-steer
//! metrics of `metrics` on it (`measured/metrics_1e6_rows`). Both must stay
//! linear in the rows (the reliability tests check the ratio 10⁶ / 10⁵).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use handling::measured::clean::{clean_run, CleanSettings, CleaningReport};
use handling::measured::MeasuredRun;
use handling::metrics::measured::measured_step_metrics;
use handling::metrics::MetricSettings;
use std::path::PathBuf;

#[path = "../tests/reliability/long_log_rows.rs"]
mod long_log_rows;
use long_log_rows::long_log_rows;

/// The reliability test's long log, in memory.
fn long_log(n: usize) -> MeasuredRun {
    let mut run = MeasuredRun {
        path: PathBuf::from("long.csv"),
        t: Vec::with_capacity(n),
        speed: Vec::with_capacity(n),
        steer: Vec::with_capacity(n),
        yaw_rate: Vec::with_capacity(n),
        ay: Some(Vec::with_capacity(n)),
        beta: Some(Vec::with_capacity(n)),
        roll: None,
        bank: None,
        ax: None,
        masked: Vec::new(),
        clock: None,
    };
    long_log_rows(n, |[t, speed, steer, r, ay, beta]| {
        run.t.push(t);
        run.speed.push(speed);
        run.steer.push(steer);
        run.yaw_rate.push(r);
        run.ay.as_mut().expect("allocated").push(ay);
        run.beta.as_mut().expect("allocated").push(beta);
    });
    run
}

fn measured(c: &mut Criterion) {
    let run = long_log(1_000_000);
    let mut g = c.benchmark_group("measured");
    g.sample_size(10);
    g.bench_function("clean_1e6_rows", |b| {
        b.iter(|| {
            let mut report = CleaningReport::new(5.0);
            clean_run(
                black_box(run.clone()),
                &CleanSettings::diagnosis(5.0),
                &mut report,
            )
        })
    });
    g.bench_function("metrics_1e6_rows", |b| {
        b.iter(|| measured_step_metrics(black_box(run.clone()), 5.0, &MetricSettings::default()))
    });
    g.finish();
}

criterion_group!(benches, measured);
criterion_main!(benches);
