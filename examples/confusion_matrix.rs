//! The confusion matrix of the sim-to-real diagnosis on the virtual proving
//! ground: for every effect of the library (and no effect, and some pairs),
//! several noise seeds, generate a campaign with that effect, diagnose it
//! with the effect withheld from the base model, and tabulate what the
//! verdict names and how far the held-out gap shrinks.
//!
//! `cargo run --release --example confusion_matrix [seeds] [effect ... |
//! none] [--truth four-wheel] [--programme oval|road-course|slow-oval|
//! slow-oval-no-beta|slow-oval-estimated-beta|sedan-winding|racing-rear-steer]
//! [--glitches]`
//!
//! With `--programme oval` or `road-course` the runs are the logged racing
//! programmes of [`handling::proving_ground::Programme`] (25 Hz, `ax` and
//! `bank` channels, the oval's standstill left out by the cleaning): one
//! row for no effect and one for each effect of the library, including the
//! longitudinal and bank-profile ones. With `--programme slow-oval` (the
//! Putnam-like light racing car at 5–21 m/s on a 20° banked oval, no rig
//! data, sideslip and no ay, 20 s pieces) and its variants without `beta`
//! or with an estimated `beta` the rows are no effect, `bank_profile`,
//! `steer_path` and the two together. The analogues of real logs
//! (`sedan-winding`, `racing-rear-steer`) have what they reproduce built
//! into their car and logger: one row, no effect switched on, the verdict
//! on the analogue itself.
//!
//! With `--truth four-wheel` the car is the independent four-wheel model
//! with roll and its own tyre ([`handling::proving_ground::four_wheel`]): one
//! row for no effect and one for each effect that truth implements (its
//! own parameter values, in its own units, in the `fitted (truth)` column).
//!
//! With `--glitches` each campaign is diagnosed a second time from a copy of
//! its runs with logger glitches injected ([`handling::measured::clean::inject_glitches`]:
//! a zero read, a spike and a held value per response channel, a steer
//! spike) and cleaned as `diagnose` cleans a campaign read from files; the
//! row then also shows that copy's verdict and how many of the injected
//! glitches the cleaning listed.

use handling::diagnose::diagnose;
use handling::diagnose::effects::{joined, EffectKind};
use handling::diagnose::DiagnoseSettings;
use handling::measured::clean::{clean_runs, inject_glitches, CleanSettings};
use handling::proving_ground::{generate_with, Noise, Programme, SynthSpec, Truth};
use std::time::Instant;

fn main() -> anyhow::Result<()> {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let glitches = args.iter().any(|a| a == "--glitches");
    args.retain(|a| a != "--glitches");
    let mut model = Truth::Augmented;
    if let Some(k) = args.iter().position(|a| a == "--truth") {
        let name = args.get(k + 1).cloned().unwrap_or_default();
        model = Truth::from_name(&name)
            .ok_or_else(|| anyhow::anyhow!("unknown truth `{name}`: augmented or four-wheel"))?;
        args.drain(k..(k + 2).min(args.len()));
    }
    let mut programme = Programme::Handling;
    if let Some(k) = args.iter().position(|a| a == "--programme") {
        let name = args.get(k + 1).cloned().unwrap_or_default();
        programme = name.parse()?;
        args.drain(k..(k + 2).min(args.len()));
    }
    let seeds: u64 = args.first().and_then(|s| s.parse().ok()).unwrap_or(3);
    let chosen: Vec<EffectKind> = args
        .iter()
        .skip(1)
        .filter_map(|n| EffectKind::from_name(n))
        .collect();
    let mut truths: Vec<Vec<EffectKind>> = vec![Vec::new()];
    if args.iter().skip(1).any(|a| a == "none") {
        // `none`: the no-effect row alone.
    } else if chosen.is_empty()
        && matches!(
            programme,
            Programme::SedanWinding | Programme::RacingRearSteer
        )
    {
        // The analogue alone: its failure is built in.
    } else if chosen.is_empty() && programme.slow_oval() {
        truths.push(vec![EffectKind::BankProfile]);
        truths.push(vec![EffectKind::SteerPath]);
        truths.push(vec![EffectKind::BankProfile, EffectKind::SteerPath]);
    } else if chosen.is_empty() && (model == Truth::FourWheel || programme.logged()) {
        truths.extend(model.effects(programme).into_iter().map(|e| vec![e]));
    } else if chosen.is_empty() {
        truths.extend(model.effects(programme).into_iter().map(|e| vec![e]));
        truths.push(vec![EffectKind::RelaxationLength, EffectKind::SensorBias]);
        truths.push(vec![
            EffectKind::CorneringStiffness,
            EffectKind::SensorDelay,
        ]);
        truths.push(vec![EffectKind::AeroLoad, EffectKind::YawInertia]);
        truths.push(vec![EffectKind::RelaxationLength, EffectKind::SensorDelay]);
    } else {
        truths = vec![chosen];
    }
    if model != Truth::Augmented {
        println!("truth model: {}\n", model.name());
    }
    if programme.logged() {
        println!("programme: {}\n", programme.name());
    }
    if glitches {
        println!("| truth | seed | verdict | confounded with | held-out J before → after (noise) | reduction % | fitted (truth) | s | verdict with glitches | glitches listed / injected |");
        println!("|---|---|---|---|---|---|---|---|---|---|");
    } else {
        println!("| truth | seed | verdict | confounded with | held-out J before → after (noise) | reduction % | fitted (truth) | s |");
        println!("|---|---|---|---|---|---|---|---|");
    }
    for truth in &truths {
        for seed in 1..=seeds {
            let spec = SynthSpec {
                effects: truth
                    .iter()
                    .filter_map(|e| Some((*e, model.values(programme, *e)?)))
                    .collect(),
                seed,
                noise: Noise::default(),
                programme,
            };
            let s = generate_with(&spec, model)?;
            let settings = DiagnoseSettings {
                seed,
                ..DiagnoseSettings::default()
            };
            let c = s.campaign(EffectKind::ALL.to_vec(), settings);
            let glitched = if glitches {
                let mut g = c.clone();
                let mut injected = 0;
                for (k, run) in g.runs.iter_mut().enumerate() {
                    injected += inject_glitches(run, 1000 * seed + k as u64).len();
                }
                let (runs, report) = clean_runs(g.runs, &CleanSettings::diagnosis(5.0));
                g.runs = runs;
                let listed = report.glitches.len();
                g.cleaning = report;
                let v = diagnose(&g, None)?.verdict.effects().to_vec();
                Some((
                    if v.is_empty() {
                        "—".into()
                    } else {
                        joined(&v, "+")
                    },
                    format!("{listed} / {injected}"),
                ))
            } else {
                None
            };
            let t0 = Instant::now();
            let d = diagnose(&c, None)?;
            let conf: Vec<String> = d
                .confounded
                .iter()
                .flat_map(|g| g.effects.iter().skip(1).map(|e| e.name().to_string()))
                .collect();
            let after = d
                .ranking
                .iter()
                .find(|r| r.effects == d.verdict.effects())
                .or(d
                    .combinations
                    .iter()
                    .find(|r| r.effects == d.verdict.effects()))
                .map_or(d.gap.heldout_error, |r| r.heldout_error_after);
            let truth_params: Vec<f64> = spec.effects.iter().flat_map(|(_, p)| p.clone()).collect();
            let fitted: Vec<String> = d
                .verdict
                .parameters()
                .iter()
                .map(|p| {
                    format!(
                        "{} {:.3}",
                        p.name.split('.').next_back().unwrap_or(""),
                        p.value
                    )
                })
                .collect();
            print!(
                "| {} | {seed} | {} | {} | {:.2} → {:.2} ({:.2}) | {:.0} | {} ({:?}) | {:.1} |",
                s.name(),
                if d.verdict.effects().is_empty() {
                    "—".into()
                } else {
                    joined(d.verdict.effects(), "+")
                },
                conf.join(", "),
                d.gap.heldout_error,
                after,
                d.gap.noise_level,
                d.ranking
                    .iter()
                    .chain(&d.combinations)
                    .find(|r| r.effects == d.verdict.effects())
                    .map_or(0.0, |r| r.reduction_percent),
                fitted.join(", "),
                truth_params,
                t0.elapsed().as_secs_f64()
            );
            match &glitched {
                Some((v, n)) => println!(" {v} | {n} |"),
                None => println!(),
            }
            for r in d.ranking.iter().take(4) {
                eprintln!(
                    "    {} J {:.3} red {:.0}% dBIC {:.0} {:?}",
                    r.effect,
                    r.heldout_error_after,
                    r.reduction_percent,
                    r.delta_bic,
                    r.parameters.iter().map(|p| p.value).collect::<Vec<_>>()
                );
            }
        }
    }
    Ok(())
}
