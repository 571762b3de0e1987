//! Diagnosis speed (the target: a campaign of 8 runs diagnosed
//! against the full library in at most 10 s on 2 cores): the synthetic proving-ground
//! campaign (8 runs, 66 s of data at 100 Hz, a sensor delay withheld, PAC89
//! fitted to its rig data) against all 14 effects, and the cost of one
//! replay of its 8 runs, which every fit evaluation pays. And one replay of
//! the Putnam racing log (`replay_racing_log_460s_stiff_axles`: 460 s in 23
//! pieces, with the stiff racing axles its diagnosis fits, each piece by the
//! method it is stable under): what each evaluation of that diagnosis costs;
//! and its whole diagnosis against the full library
//! (`putnam_460s_full_library`, the axles identified from the runs). Both
//! skipped, with a line saying so, when the log (outside the repository) is
//! missing.
//!
//! `campaign_8_runs_full_library_exact_jacobian` is the 8-run campaign with
//! `[diagnose] derivatives = "exact"`: the cost of exact Jacobians beside
//! the default differences.
//!
//! `RAYON_NUM_THREADS=2 cargo bench --bench diagnose`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use handling::diagnose::diagnose;
use handling::diagnose::effects::EffectKind;
use handling::diagnose::{Augmented, DiagnoseSettings, Prepared};
use handling::optim::local::Derivatives;
use handling::proving_ground::{generate, truth_values, Noise, Programme, SynthSpec};
use handling::tyre::{MagicSimple, Pac89, Tyre};
use handling::vehicle::VehicleModel;
use std::time::Duration;

fn diagnosis(c: &mut Criterion) {
    let spec = SynthSpec {
        effects: vec![(
            EffectKind::SensorDelay,
            truth_values(EffectKind::SensorDelay),
        )],
        seed: 1,
        noise: Noise::default(),
        programme: Default::default(),
    };
    let s = generate(&spec);
    let campaign = s.campaign(EffectKind::ALL.to_vec(), DiagnoseSettings::default());

    let runs: Vec<Prepared> = s
        .runs
        .iter()
        .map(|r| Prepared::new(r, 0.01, 25.0))
        .collect();
    let t = Tyre::Pac89(Pac89::adams_example());
    let model = Augmented::new(VehicleModel::new(s.vehicle.clone(), t.clone(), t), 1.0);
    let mut g = c.benchmark_group("diagnose");
    g.bench_function("replay_8_runs_66s_pac89", |b| {
        b.iter(|| {
            for r in &runs {
                black_box(r.errors(black_box(&model)));
            }
        })
    });
    g.sample_size(10);
    g.measurement_time(Duration::from_secs(200));
    g.bench_function("campaign_8_runs_full_library", |b| {
        b.iter(|| diagnose(black_box(&campaign), None).unwrap())
    });
    // The same with every fit's Jacobian exact (one replay in dual numbers
    // instead of one plain replay per parameter), back to back.
    let mut exact = campaign.clone();
    exact.settings.derivatives = Derivatives::Exact;
    g.bench_function("campaign_8_runs_full_library_exact_jacobian", |b| {
        b.iter(|| diagnose(black_box(&exact), None).unwrap())
    });
    g.finish();
}

fn racing_log(c: &mut Criterion) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("campaigns/putnam.toml");
    let campaign = match handling::io::campaign::load_campaign(&path) {
        Ok(c) => c,
        Err(e) => {
            eprintln!(
                "diagnose/replay_racing_log_460s_stiff_axles and diagnose/putnam_460s_full_library skipped: {e}"
            );
            return;
        }
    };
    let runs = Prepared::campaign_runs(&campaign);
    let axle = |b: f64| Tyre::MagicSimple(MagicSimple { b, c: 1.3, d: 3.5 });
    let mut model = Augmented::new(
        VehicleModel::new(campaign.vehicle.clone(), axle(9.27), axle(80.0)),
        campaign.friction,
    );
    model.effects_mut().roll = campaign.roll;
    let mut g = c.benchmark_group("diagnose");
    g.sample_size(10);
    g.bench_function("replay_racing_log_460s_stiff_axles", |b| {
        b.iter(|| {
            for r in &runs {
                black_box(r.errors(black_box(&model)));
            }
        })
    });
    g.measurement_time(Duration::from_secs(900));
    g.bench_function("putnam_460s_full_library", |b| {
        b.iter(|| diagnose(black_box(&campaign), None).unwrap())
    });
    g.finish();
}

/// The slow-oval programme (the regime of a real autonomous racing car's
/// oval log): 600 s in three runs at 25 Hz, cut into 20 s pieces and
/// replayed at 20 ms, no rig data (the base identifies its axles from the
/// runs, from its grid of starts), the bank withheld, against the full
/// library: the real-log target of at most 60 s on 2 cores.
fn slow_oval(c: &mut Criterion) {
    let spec = SynthSpec {
        effects: vec![(
            EffectKind::BankProfile,
            truth_values(EffectKind::BankProfile),
        )],
        seed: 1,
        noise: Noise::default(),
        programme: Programme::SlowOval,
    };
    let campaign = generate(&spec).campaign(EffectKind::ALL.to_vec(), DiagnoseSettings::default());
    let mut g = c.benchmark_group("diagnose");
    g.sample_size(10);
    g.measurement_time(Duration::from_secs(600));
    g.bench_function("slow_oval_600s_log_full_library", |b| {
        b.iter(|| diagnose(black_box(&campaign), None).unwrap())
    });
    g.finish();
}

criterion_group!(benches, diagnosis, racing_log, slow_oval);
criterion_main!(benches);
