//! `diagnose` (the sim-to-real gap of a campaign) and `synth` (the virtual
//! proving ground that writes campaigns with known effects).

use anyhow::{anyhow, bail, Context, Result};
use handling::diagnose::diagnosis::{observed_channel, Diagnosis, Shrinkage};
use handling::diagnose::effects::EffectKind;
use handling::diagnose::fit::Channel;
use handling::diagnose::synth::{generate_with, Noise, SynthSpec, Truth};
use handling::diagnose::{diagnose as run_diagnosis, diagnosis::work_units};
use handling::io::campaign::load_campaign;
use handling::report::plot::{Figure, Panel, Series, Style};
use handling::report::progress::Progress;
use handling::report::{refuse_overwrite, write_columns, write_json};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// `handling diagnose`.
pub fn diagnose(path: &Path, out: Option<&Path>) -> Result<()> {
    let campaign = load_campaign(path)?;
    let out = out.map_or_else(
        || PathBuf::from("out").join(&campaign.name),
        Path::to_path_buf,
    );
    let files = ["diagnosis.json", "gap_map.png", "overlays.png"].map(|f| out.join(f));
    for f in &files {
        refuse_overwrite(f, &campaign.inputs)?;
    }
    println!(
        "{}: {} runs, {} candidate effects, seed {}",
        campaign.name,
        campaign.runs.len(),
        campaign.effects.len(),
        campaign.settings.seed
    );
    for n in &campaign.notes {
        println!("  note: {n}");
    }
    for line in campaign.cleaning.summary(5) {
        println!("  cleaning: {line}");
    }
    let t0 = Instant::now();
    let d = {
        let progress = Progress::start("diagnose", work_units(&campaign));
        run_diagnosis(&campaign, Some(progress.counter())).map_err(|e| anyhow!(e))?
    };
    let seconds = t0.elapsed().as_secs_f64();
    std::fs::create_dir_all(&out).with_context(|| format!("{}: cannot create", out.display()))?;
    write_json(&files[0], &d)?;
    gap_map(&d).save(&files[1])?;
    overlays(&d).save(&files[2])?;
    report(&d);
    println!(
        "diagnosed in {seconds:.1} s; wrote {}, {}, {}",
        files[0].display(),
        files[1].display(),
        files[2].display()
    );
    Ok(())
}

/// The short human report.
fn report(d: &Diagnosis) {
    println!("base model: {}", d.base.tyres);
    for line in d.base.rig_grouping.iter().flat_map(|g| g.lines()) {
        println!("  rig data: {line}");
    }
    println!("where the gap lies:");
    for s in &d.gap.summary {
        println!("  {s}");
    }
    println!(
        "candidates on held-out runs ({} folds; J before {:.3}, noise level {:.3}):",
        d.folds, d.gap.heldout_error, d.gap.noise_level
    );
    println!(
        "  {:<28} {:>8} {:>11} {:>10} {:>12}  parameters",
        "effect", "J after", "held out", "in sample", "ΔBIC"
    );
    for r in d.ranking.iter().chain(d.combinations.iter()) {
        let p: Vec<String> = r
            .parameters
            .iter()
            .map(|p| {
                if p.std_error.is_finite() {
                    format!(
                        "{} = {:.4} ± {:.2e} {}",
                        p.name, p.value, p.std_error, p.unit
                    )
                } else {
                    // No standard error: the runs cannot see it (a channel
                    // they lack, a parameter pinned by another).
                    format!(
                        "{} = {:.4} {} (no standard error: not identifiable from these runs)",
                        p.name, p.value, p.unit
                    )
                }
            })
            .collect();
        println!(
            "  {:<28} {:>8.3} {:>9.1} % {:>8.1} % {:>12.0}  {}",
            r.effect,
            r.heldout_error_after,
            r.reduction_percent,
            r.insample_reduction_percent,
            r.delta_bic,
            p.join(", ")
        );
        if let Some(w) = &r.warning {
            println!("  {:<28} warning: {w}", "");
        }
    }
    println!("verdict: {}", d.verdict.statement);
    for c in &d.confounded {
        println!(
            "confounded: {} — separate them with {}",
            c.effects.join(", "),
            c.separating_test
        );
    }
    if !d.verdict.effects.is_empty() {
        println!("held-out before → after (all samples):");
        for s in d.shrinkage.iter().filter(|s| s.part == "all") {
            println!(
                "  {:<9} {:.4} → {:.4} (noise floor {:.4}): {:.0} % of the gap above noise removed",
                s.channel, s.before, s.after, s.noise_floor, s.reduction_percent
            );
        }
    }
}

/// Position of a part on its axis: window → time after the input starts,
/// regime → band centre. None for `all`.
fn part_axis(part: &str) -> Option<(usize, f64)> {
    let window = [
        ("before the input", -0.5),
        ("first 0.5 s", 0.25),
        ("0.5–2 s", 1.25),
        ("later", 3.0),
    ];
    if let Some((_, x)) = window.iter().find(|(n, _)| part.starts_with(n)) {
        return Some((0, *x));
    }
    let band = |s: &str| -> Option<f64> {
        let (lo, hi) = s.split_once('–')?;
        let lo: f64 = lo.trim().parse().ok()?;
        let hi: f64 = hi.split_whitespace().next()?.parse().ok()?;
        Some(if hi.is_finite() {
            0.5 * (lo + hi)
        } else {
            lo + 1.0
        })
    };
    if let Some(rest) = part.strip_prefix("|ay| ") {
        return band(rest).map(|x| (1, x));
    }
    part.strip_prefix("speed ").and_then(band).map(|x| (2, x))
}

/// The gap map: held-out RMS over the noise floor per channel against the
/// time window, the lateral-acceleration level and the speed band, with the
/// base model and with the verdict's effects.
fn gap_map(d: &Diagnosis) -> Figure {
    let mut panels = Vec::new();
    let axes = [
        "time after the input starts (window centre), s",
        "|ay| band centre, m/s²",
        "speed band centre, m/s",
    ];
    let titles = [
        "by time window",
        "by lateral-acceleration level",
        "by speed",
    ];
    for ch in Channel::ALL {
        let rows: Vec<&Shrinkage> = d
            .shrinkage
            .iter()
            .filter(|s| s.channel == ch.name())
            .collect();
        if rows.is_empty() {
            continue;
        }
        for axis in 0..3 {
            let mut pts: Vec<(f64, f64, f64)> = rows
                .iter()
                .filter_map(|s| {
                    let (a, x) = part_axis(&s.part)?;
                    (a == axis && s.noise_floor > 0.0)
                        .then(|| (x, s.before / s.noise_floor, s.after / s.noise_floor))
                })
                .collect();
            pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            if pts.is_empty() {
                continue;
            }
            let x: Vec<f64> = pts.iter().map(|p| p.0).collect();
            let before: Vec<f64> = pts.iter().map(|p| p.1).collect();
            let after: Vec<f64> = pts.iter().map(|p| p.2).collect();
            let mut series = vec![
                Series::line("base model", &x, &before, 1),
                Series::line("", &x, &before, 1).styled(Style::Points(4)),
            ];
            if !d.verdict.effects.is_empty() {
                series.push(Series::line(
                    &format!("with {}", d.verdict.effects.join(" + ")),
                    &x,
                    &after,
                    2,
                ));
                series.push(Series::line("", &x, &after, 2).styled(Style::Points(4)));
            }
            let (x0, x1) = (x[0] - 0.5, x[x.len() - 1] + 0.5);
            series.push(
                Series::line("3 × noise floor", &[x0, x1], &[3.0, 3.0], 7).styled(Style::Dashed),
            );
            panels.push(Panel {
                title: format!("{} {}: held-out RMS / noise floor", ch.name(), titles[axis]),
                x_label: axes[axis].into(),
                y_label: "RMS / noise floor".into(),
                series,
                x_range: Some((x0, x1)),
                y_range: None,
            });
        }
    }
    Figure {
        panels,
        columns: 3,
        width: 1500,
        row_height: 300,
    }
}

/// Measured, base and augmented held-out replays of the three runs with the
/// largest base-model gap.
fn overlays(d: &Diagnosis) -> Figure {
    let mut panels = Vec::new();
    for o in d.overlays.iter().take(3) {
        let name = Path::new(&o.run)
            .file_name()
            .map_or(o.run.clone(), |s| s.to_string_lossy().into_owned());
        for (ch, m) in &o.measured {
            if *ch == Channel::Beta && o.measured.len() > 2 {
                continue;
            }
            let mut series = vec![
                Series::line("measured", &o.t, m, 7).styled(Style::Points(1)),
                Series::line("base model", &o.t, observed_channel(&o.base, *ch), 1)
                    .styled(Style::Dashed),
            ];
            if !d.verdict.effects.is_empty() {
                series.push(Series::line(
                    &format!("with {}", d.verdict.effects.join(" + ")),
                    &o.t,
                    observed_channel(&o.after, *ch),
                    2,
                ));
            }
            panels.push(Panel {
                title: format!("{name}: {} (held out)", ch.name()),
                x_label: "t, s".into(),
                y_label: format!("{}, {}", ch.name(), ch.unit()),
                series,
                x_range: None,
                y_range: None,
            });
        }
    }
    Figure {
        panels,
        columns: 2,
        width: 1400,
        row_height: 280,
    }
}

/// `handling synth`: writes a campaign folder generated with `effects`.
pub fn synth(effects: &[String], seed: u64, truth: &str, out: &Path) -> Result<()> {
    let truth = Truth::from_name(truth).ok_or_else(|| {
        let all: Vec<&str> = Truth::ALL.iter().map(|t| t.name()).collect();
        anyhow!("unknown truth `{truth}`: one of {}", all.join(", "))
    })?;
    let kinds: Vec<EffectKind> = effects
        .iter()
        .filter(|e| e.as_str() != "none")
        .map(|e| {
            EffectKind::from_name(e)
                .filter(|k| truth.values(*k).is_some())
                .ok_or_else(|| {
                    let all: Vec<&str> = truth.effects().iter().map(|k| k.name()).collect();
                    anyhow!(
                        "unknown effect `{e}` for the {} truth: one of none, {}",
                        truth.name(),
                        all.join(", ")
                    )
                })
        })
        .collect::<Result<_>>()?;
    if out.exists() {
        bail!(
            "{}: exists; synth writes a new campaign folder and does not overwrite one",
            out.display()
        );
    }
    let spec = SynthSpec {
        effects: kinds
            .iter()
            .filter_map(|k| Some((*k, truth.values(*k)?)))
            .collect(),
        seed,
        noise: Noise::default(),
    };
    let s = generate_with(&spec, truth)?;
    // Written into a sibling temporary folder, renamed when complete: a
    // failed run leaves no half-written campaign.
    let parent = out
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    std::fs::create_dir_all(parent)
        .with_context(|| format!("{}: cannot create", parent.display()))?;
    let name = out
        .file_name()
        .map_or("campaign".into(), |n| n.to_string_lossy().into_owned());
    let tmp = parent.join(format!(".{name}.synth-{}", std::process::id()));
    let written = write_campaign(&s, &tmp);
    if let Err(e) = written {
        let _ = std::fs::remove_dir_all(&tmp);
        return Err(e);
    }
    std::fs::rename(&tmp, out).with_context(|| format!("{}: cannot create", out.display()))?;
    println!(
        "wrote {} ({} runs, rig data, {} truth with {}, noise seed {seed}); diagnose it with `handling diagnose {}`",
        out.display(),
        s.runs.len(),
        truth.name(),
        s.name(),
        out.display()
    );
    Ok(())
}

fn write_campaign(s: &handling::diagnose::synth::Synthetic, dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir.join("runs"))
        .with_context(|| format!("{}: cannot create", dir.display()))?;
    std::fs::write(dir.join("vehicle.toml"), s.vehicle_toml())?;
    let [fz, alpha, fy] = s.rig_columns();
    write_columns(
        &dir.join("tyre_rig.csv"),
        &[("fz", &fz), ("alpha", &alpha), ("fy", &fy)],
    )?;
    for r in &s.runs {
        let mut cols: Vec<(&str, &[f64])> = vec![
            ("t", &r.t),
            ("speed", &r.speed),
            ("steer", &r.steer),
            ("yaw_rate", &r.yaw_rate),
        ];
        if let Some(ay) = &r.ay {
            cols.push(("ay", ay));
        }
        if let Some(b) = &r.beta {
            cols.push(("beta", b));
        }
        write_columns(&dir.join("runs").join(&r.path), &cols)?;
    }
    Ok(())
}
