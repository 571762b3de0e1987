//! Where a diagnosis spends its time: wall and CPU time, and the seconds
//! and evaluations of the run set by phase ([`handling::diagnose::timing`]),
//! of the 8-run proving-ground campaign the `diagnose` bench times (a
//! sensor delay withheld, PAC89 fitted to its rig data, the full library)
//! or of a campaign file.
//!
//! `RAYON_NUM_THREADS=1 cargo run --release --example diagnose_phases
//! [campaign.toml] [--no-screening] [--exact]`
//!
//! `--exact` takes every fit's Jacobian exact (`[diagnose] derivatives =
//! "exact"`) instead of the default forward differences.
//!
//! On one thread the phases' seconds are their CPU time and add up to the
//! wall time; on more they overlap (see the module's documentation). The
//! CPU time of the process and the load average (Linux, from `/proc`) are
//! printed beside them: the machine may be shared.

use handling::diagnose::effects::{joined, EffectKind};
use handling::diagnose::timing::Timing;
use handling::diagnose::{diagnose_timed, Campaign, DiagnoseSettings};
use handling::proving_ground::{generate, truth_values, Noise, SynthSpec};
use std::path::Path;

fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "unknown".into())
}

/// The 8-run campaign of `benches/diagnose.rs`.
fn campaign_8_runs() -> Campaign {
    let spec = SynthSpec {
        effects: vec![(
            EffectKind::SensorDelay,
            truth_values(EffectKind::SensorDelay),
        )],
        seed: 1,
        noise: Noise::default(),
        programme: Default::default(),
    };
    generate(&spec).campaign(EffectKind::ALL.to_vec(), DiagnoseSettings::default())
}

fn print(t: &Timing) {
    let cpu = t.cpu_seconds;
    // On a shared machine the phases' seconds are wall time, stretched
    // alike by the other processes: their shares of the process's CPU time
    // stand for their CPU time.
    println!("| phase | s | share % | ≈ CPU s | evaluations |");
    println!("|---|---|---|---|---|");
    let total: f64 = t.phases.iter().map(|p| p.seconds).sum();
    let share = |s: f64| s / total.max(1e-12);
    for p in &t.phases {
        println!(
            "| {} | {:.2} | {:.1} | {} | {} |",
            p.phase.name(),
            p.seconds,
            100.0 * share(p.seconds),
            cpu.map_or("—".into(), |c| format!("{:.2}", c * share(p.seconds))),
            p.evaluations
        );
    }
    let evaluations: usize = t.phases.iter().map(|p| p.evaluations).sum();
    println!(
        "| all | {total:.2} | 100.0 | {} | {evaluations} |",
        cpu.map_or("—".into(), |c| format!("{c:.2}"))
    );
    println!();
    println!(
        "wall {:.2} s, CPU {} s, threads {}, load average {} (1, 5, 15 min)",
        t.wall_seconds,
        cpu.map_or("unknown".into(), |c| format!("{c:.2}")),
        rayon::current_num_threads(),
        load_average()
    );
    println!(
        "candidates fitted on all runs {}, cross-validated {}",
        t.candidates_fitted, t.candidates_cross_validated
    );
}

fn main() -> anyhow::Result<()> {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let screening = !args.iter().any(|a| a == "--no-screening");
    let exact = args.iter().any(|a| a == "--exact");
    args.retain(|a| a != "--no-screening" && a != "--exact");
    let mut c = match args.first() {
        Some(path) => handling::io::campaign::load_campaign(Path::new(path))?,
        None => campaign_8_runs(),
    };
    c.settings.screening = screening;
    if exact {
        c.settings.derivatives = handling::optim::local::Derivatives::Exact;
    }
    println!(
        "{}: {} runs, screening {screening}, derivatives {:?}\n",
        c.name,
        c.runs.len(),
        c.settings.derivatives
    );
    let (d, t) = diagnose_timed(&c)?;
    print(&t);
    let screened: Vec<&str> = d.screened.iter().map(|s| s.effect.as_str()).collect();
    println!("screened: {}", screened.join(", "));
    println!("verdict: {}", joined(d.verdict.effects(), "+"));
    for r in &d.ranking {
        println!(
            "  {:<28} held out {:>6.1} %  in sample {:>6.1} %",
            r.effect, r.reduction_percent, r.insample_reduction_percent
        );
    }
    Ok(())
}
