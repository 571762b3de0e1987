//! Cleaning a long measured log: a 10⁶-row run (11 h at 25 Hz) with a
//! standstill every 30 min, stop-and-go traffic across the minimum speed,
//! a time gap every hour and a logger glitch every 997 samples, cleaned as
//! `diagnose` cleans it (`measured/clean_1e6_rows`), and the step-steer
//! metrics of `metrics` on it (`measured/metrics_1e6_rows`). Both must stay
//! linear in the rows (the reliability tests check the ratio 10⁶ / 10⁵).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use handling::measured::clean::{clean_run, CleanSettings, CleaningReport};
use handling::measured::MeasuredRun;
use handling::metrics::measured::measured_step_metrics;
use handling::metrics::MetricSettings;
use std::path::PathBuf;

/// The long log, in memory (deterministic).
fn long_log(n: usize) -> MeasuredRun {
    let mut x: u64 = 0x2545_F491_4F6C_DD1D;
    let mut noise = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let mut run = MeasuredRun {
        path: PathBuf::from("long.csv"),
        t: Vec::with_capacity(n),
        speed: Vec::with_capacity(n),
        steer: Vec::with_capacity(n),
        yaw_rate: Vec::with_capacity(n),
        ay: Some(Vec::with_capacity(n)),
        beta: None,
        roll: None,
        bank: None,
        ax: None,
        masked: Vec::new(),
    };
    for i in 0..n {
        let t = (i + 50 * (i / 90_000)) as f64 / 25.0;
        let stopped = t > 600.0 && t % 1800.0 < 60.0;
        let traffic = t > 600.0 && (t % 1800.0 - 100.0).abs() < 60.0;
        let speed = match (stopped, traffic) {
            (true, _) => 0.0,
            (_, true) if i % 20 < 10 => 4.0,
            (_, true) => 6.0,
            _ => 20.0 + 0.05 * noise(),
        };
        let steer = if t < 10.0 { 0.0 } else { 0.02 } + 1e-4 * noise();
        let mut r = speed * steer / 2.78 + 1e-3 * noise();
        if i % 997 == 500 {
            r = 0.0;
        }
        run.t.push(t);
        run.speed.push(speed);
        run.steer.push(steer);
        run.yaw_rate.push(r);
        if let Some(ay) = run.ay.as_mut() {
            ay.push(speed * r + 0.02 * noise());
        }
    }
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
