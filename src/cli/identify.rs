//! `identify`: fit a tyre model to rig data.

use anyhow::{anyhow, Context, Result};
use handling::identify::data::Point;
use handling::identify::grouping::{group, Grouping, SlipAxis, Variable};
use handling::identify::mf_staged::{self, StartScheme};
use handling::identify::{fit_channel, Channel, FitSettings, LocalMethod};
use handling::io::rig::read_rig;
use handling::io::tir::TirDocument;
use handling::report::plot::{Figure, Panel, Series, Style};
use handling::report::{refuse_overwrite, write_bytes, write_json};
use handling::tyre::mf::MfVersion;
use handling::tyre::{Pac89, Tyre};
use std::path::{Path, PathBuf};

/// The start tyre of a model for data whose median load is `fz`.
fn start(model: &str, fz: f64) -> Result<Tyre> {
    handling::identify::start_tyre(model, fz).map_err(|e| anyhow!(e))
}

/// Options of `identify`.
pub struct Options<'a> {
    pub data: &'a Path,
    pub model: &'a str,
    pub seed: u64,
    pub out: Option<&'a Path>,
    pub pressure: Option<f64>,
    pub camber: Option<f64>,
    pub local: &'a str,
    pub alpha_bin_deg: f64,
    pub kappa_bin: f64,
    pub start: StartArg,
    pub template: Option<&'a Path>,
    pub max_iterations: usize,
}

/// `--start` of the Magic Formula identification.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum StartArg {
    /// Estimates from the data, then MINPACK's Levenberg–Marquardt.
    Data,
    /// Wei et al. (2010): every parameter 1, μ = 0.1, β = 5.
    Paper,
    /// The `--template` file's values, then MINPACK's Levenberg–Marquardt.
    Template,
}

/// `handling identify`.
pub fn identify(o: &Options) -> Result<()> {
    match o.model {
        "mf61" => return identify_mf(o, MfVersion::Mf61),
        "mf62" => return identify_mf(o, MfVersion::Mf62),
        _ => {}
    }
    let mut settings = FitSettings::new(o.seed);
    settings.local = match o.local {
        "lm" => LocalMethod::LevenbergMarquardt,
        "gn" => LocalMethod::GaussNewton,
        "none" => LocalMethod::None,
        l => return Err(anyhow!("unknown local method `{l}`: lm, gn or none")),
    };
    // The model name is checked before the data are read.
    start(o.model, 1.0)?;
    let data = read_rig(o.data)?;
    if !data.has_lateral() && start(o.model, 1.0)?.longitudinal_names().is_empty() {
        return Err(anyhow!(
            "{}: no lateral data (columns `alpha` and `fy`), and the {} model has no longitudinal force",
            o.data.display(),
            o.model
        ));
    }
    let grouping = Grouping {
        pressure: o.pressure,
        camber: o.camber,
        alpha_bin: o.alpha_bin_deg.to_radians(),
        kappa_bin: o.kappa_bin,
        ..Grouping::default()
    };
    let long_view = data.longitudinal_view();
    let grouped = if data.has_lateral() {
        group(o.data, &data, &grouping, SlipAxis::Angle)?
    } else {
        let view = long_view.as_ref().expect("checked above");
        group(o.data, view, &grouping, SlipAxis::Ratio)?
    };
    let conditions = grouped.conditions;
    if conditions.is_empty() {
        return Err(anyhow!(
            "{}: no test condition found in the data ({})",
            o.data.display(),
            grouped.report.lines().join("; ")
        ));
    }
    let mut loads: Vec<f64> = conditions.iter().map(|c| c.fz).collect();
    loads.sort_by(f64::total_cmp);
    let tyre0 = start(o.model, loads[loads.len() / 2])?;
    let out = output_path(o, "toml");
    let report_path = out.with_extension("report.json");
    let png_path = out.with_extension("png");
    for f in [&out, &report_path, &png_path] {
        refuse_overwrite(f, &[o.data.to_path_buf()])?;
    }
    println!(
        "{}: {} conditions; model {}, seed {}",
        o.data.display(),
        conditions.len(),
        o.model,
        o.seed
    );
    for line in grouped.report.lines() {
        println!("  {line}");
    }
    // The models fitted here have no pressure terms: several pressures
    // pooled into one parameter set blur their differences into the fit.
    let pressures = grouped
        .report
        .levels
        .iter()
        .find(|l| l.variable == Variable::Pressure)
        .map_or(0, |l| l.levels.len());
    if o.pressure.is_none() && pressures > 1 {
        eprintln!(
            "warning: {} pressures pooled into one {} fit, which has no pressure terms: select one with --pressure",
            pressures, o.model
        );
    }
    let first = if data.has_lateral() {
        Channel::LateralForce
    } else {
        Channel::LongitudinalForce
    };
    let mut fit = fit_channel(&tyre0, first, &conditions, &settings)
        .map_err(|e| anyhow!("{}: {e}", o.data.display()))?;
    // PAC89: Zhang et al.'s (2021) two-stage identification as well; both are reported
    // and the better of the two is written.
    let two_stage = if o.model == "pac89" && first == Channel::LateralForce {
        let r = handling::identify::pac89_two_stage::identify(&conditions, &settings)
            .map_err(|e| anyhow!("{}: {e}", o.data.display()))?;
        println!(
            "  two-stage (Zhang et al. 2021): stage 1 mean σ {:.3} %, stage 2 mean σ {:.3} %, after the joint polish {:.3} %",
            r.stage1_mean_sigma, r.stage2_mean_sigma, r.polished_mean_sigma
        );
        Some(r)
    } else {
        None
    };
    println!(
        "  σ {:.3} % (PSO alone {:.3} %), RMS {:.1} N, {} evaluations, {:.2} s",
        fit.sigma_percent, fit.sigma_pso_percent, fit.rms, fit.evaluations, fit.seconds
    );
    for c in &fit.curves {
        println!(
            "    Fz {:>7.0} N, camber {:>5.2}°, pressure {}: {:>4} points, σ {:.3} %, RMS {:.1} N",
            c.fz,
            c.camber.to_degrees(),
            c.pressure
                .map_or("—".into(), |p| format!("{:.0} kPa", p / 1000.0)),
            c.points,
            c.sigma_percent,
            c.rms
        );
    }
    for p in fit.parameters.iter().filter(|p| p.warning.is_some()) {
        println!(
            "  warning: {} = {:.6}: {}",
            p.name,
            p.value,
            p.warning.as_deref().unwrap_or("")
        );
    }
    let header = format!(
        "# Identified by `handling identify {} --model {} --seed {}`: sigma {:.3} %.\n",
        o.data.display(),
        o.model,
        o.seed,
        fit.sigma_percent
    );
    let mut report = serde_json::to_value(&fit)?;
    if let Some(r) = &two_stage {
        report["two_stage"] = serde_json::to_value(r)?;
        let all: Vec<handling::identify::data::Point> = conditions
            .iter()
            .flat_map(|c| c.points.iter().copied())
            .collect();
        let t = Tyre::Pac89(Pac89 {
            a: r.polished,
            b: None,
            c: None,
            ..Pac89::adams_example()
        });
        let (s, _) = handling::identify::sigma(&t, &all);
        report["two_stage"]["polished_overall_sigma_percent"] = serde_json::json!(s);
        if s < fit.sigma_percent {
            println!(
                "  writing the two-stage result (σ {s:.3} % < direct {:.3} %)",
                fit.sigma_percent
            );
            report["written"] = serde_json::json!("two-stage");
            fit.tyre = Tyre::Pac89(Pac89 {
                a: r.polished,
                b: None,
                c: None,
                ..Pac89::adams_example()
            });
        } else {
            report["written"] = serde_json::json!("direct");
        }
    }
    // The aligning moment, where the data have it and the model has one,
    // with the lateral parameters just fitted held.
    let mut fitted_mz = false;
    if first == Channel::LateralForce && data.mz.is_some() && !fit.tyre.aligning_names().is_empty()
    {
        let mz = fit_channel(&fit.tyre, Channel::AligningMoment, &conditions, &settings)
            .map_err(|e| anyhow!("{}: aligning moment: {e}", o.data.display()))?;
        println!(
            "  aligning moment: σ {:.3} % (PSO alone {:.3} %), RMS {:.2} N·m, {:.2} s",
            mz.sigma_percent, mz.sigma_pso_percent, mz.rms, mz.seconds
        );
        for p in mz.parameters.iter().filter(|p| p.warning.is_some()) {
            println!(
                "  warning: {} = {:.6}: {}",
                p.name,
                p.value,
                p.warning.as_deref().unwrap_or("")
            );
        }
        report["aligning"] = serde_json::to_value(&mz)?;
        fit.tyre = mz.tyre;
        fitted_mz = true;
    }
    // The longitudinal force, where the data have it and the model has one.
    let mut fitted_fx = first == Channel::LongitudinalForce;
    let mut long_conditions = Vec::new();
    let mut long_report = None;
    if let (Some(view), true, Channel::LateralForce) =
        (&long_view, !fit.tyre.longitudinal_names().is_empty(), first)
    {
        // The same pressure and camber selection as the lateral data.
        let g = group(o.data, view, &grouping, SlipAxis::Ratio)?;
        for line in g.report.lines() {
            println!("  longitudinal: {line}");
        }
        long_conditions = g.conditions;
        long_report = Some(g.report);
        let fx = fit_channel(
            &fit.tyre,
            Channel::LongitudinalForce,
            &long_conditions,
            &settings,
        )
        .map_err(|e| anyhow!("{}: longitudinal force: {e}", o.data.display()))?;
        println!(
            "  longitudinal force: σ {:.3} % (PSO alone {:.3} %), RMS {:.1} N, {:.2} s",
            fx.sigma_percent, fx.sigma_pso_percent, fx.rms, fx.seconds
        );
        report["longitudinal"] = serde_json::to_value(&fx)?;
        fit.tyre = fx.tyre;
        fitted_fx = true;
    }
    report["data"] = serde_json::json!(o.data.display().to_string());
    report["grouping"] = serde_json::to_value(&grouped.report)?;
    if let Some(r) = &long_report {
        report["longitudinal_grouping"] = serde_json::to_value(r)?;
    }
    let text = toml::to_string(&fit.tyre).context("serialising the fitted tyre")?;
    write_bytes(&out, format!("{header}{text}").as_bytes())?;
    write_json(&report_path, &report)?;
    // Measured points against fitted curves, one panel per camber.
    let mut cambers: Vec<f64> = conditions.iter().map(|c| c.camber).collect();
    cambers.sort_by(f64::total_cmp);
    cambers.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
    let mut channels = Vec::new();
    if first == Channel::LateralForce {
        channels.push(Channel::LateralForce);
    }
    if fitted_mz {
        channels.push(Channel::AligningMoment);
    }
    if fitted_fx {
        channels.push(Channel::LongitudinalForce);
    }
    let cond_of = |ch: Channel| -> &[handling::identify::data::Condition] {
        if ch == Channel::LongitudinalForce && first == Channel::LateralForce {
            &long_conditions
        } else {
            &conditions
        }
    };
    let panels = channels
        .iter()
        .flat_map(|&ch| cambers.iter().map(move |&g| (ch, g)))
        .map(|(ch, g)| {
            let slip = |v: f64| {
                if ch == Channel::LongitudinalForce {
                    100.0 * v
                } else {
                    v.to_degrees()
                }
            };
            let mut series = Vec::new();
            for (k, c) in cond_of(ch)
                .iter()
                .filter(|c| (c.camber - g).abs() < 1e-3)
                .enumerate()
            {
                let (x, y): (Vec<f64>, Vec<f64>) = c
                    .points
                    .iter()
                    .map(|q| (slip(q.slip()), ch.measured(q)))
                    .filter(|p| p.1.is_finite())
                    .unzip();
                series.push(Series::line("", &x, &y, k).styled(Style::Points(2)));
                let amax = c.points.iter().map(|q| q.slip().abs()).fold(0.0, f64::max);
                let speed = c.points.first().map_or(10.0, |q| q.speed);
                let xs: Vec<f64> = (0..=200)
                    .map(|i| -amax + 2.0 * amax * i as f64 / 200.0)
                    .collect();
                let ys: Vec<f64> = xs
                    .iter()
                    .map(|a| {
                        let axis = match ch {
                            Channel::LongitudinalForce => SlipAxis::Ratio,
                            _ => SlipAxis::Angle,
                        };
                        let q = Point::unmeasured(axis, *a, c.fz, c.camber, speed);
                        ch.model(&fit.tyre, &q)
                    })
                    .collect();
                let xd: Vec<f64> = xs.iter().map(|a| slip(*a)).collect();
                series.push(Series::line(&format!("{:.0} N", c.fz), &xd, &ys, k));
            }
            Panel {
                title: format!(
                    "{} fit, camber {:.2}°: points measured, lines fitted",
                    o.model,
                    g.to_degrees()
                ),
                x_label: if ch == Channel::LongitudinalForce {
                    "slip ratio [%]".into()
                } else {
                    "slip angle [deg]".into()
                },
                y_label: match ch {
                    Channel::LateralForce => "Fy [N]".into(),
                    Channel::AligningMoment => "Mz [N·m]".into(),
                    Channel::LongitudinalForce => "Fx [N]".into(),
                },
                series,
                ..Panel::default()
            }
        })
        .collect();
    Figure::stack(panels).save(&png_path)?;
    println!(
        "wrote {}, {} and {}",
        out.display(),
        report_path.display(),
        png_path.display()
    );
    Ok(())
}

/// The tyre file to write: `--out`, else `out/<data stem>_<model>.<ext>`.
fn output_path(o: &Options, ext: &str) -> PathBuf {
    o.out.map_or_else(
        || {
            let stem = o
                .data
                .file_stem()
                .map_or("data".into(), |s| s.to_string_lossy().into_owned());
            PathBuf::from("out").join(format!("{stem}_{}.{ext}", o.model))
        },
        Path::to_path_buf,
    )
}

/// `handling identify --model mf61|mf62`: Wei et al. (2010)'s five stages;
/// writes the .tir and `<out>.report.json`.
fn identify_mf(o: &Options, version: MfVersion) -> Result<()> {
    let out = output_path(o, "tir");
    let report_path = out.with_extension("report.json");
    let mut inputs = vec![o.data.to_path_buf()];
    inputs.extend(o.template.map(Path::to_path_buf));
    for f in [&out, &report_path] {
        refuse_overwrite(f, &inputs)?;
    }
    let template = o.template.map(TirDocument::read).transpose()?;
    let template_tyre = template.as_ref().map(|d| d.magic_formula()).transpose()?;
    let data = read_rig(o.data)?;
    let default_speed = template_tyre
        .as_ref()
        .map_or(16.7, |t| t.coefficients.LONGVL);
    let prepared = mf_staged::prepare(o.data, &data, o.alpha_bin_deg.to_radians(), default_speed)?;
    let settings = mf_staged::Settings {
        version,
        start: match o.start {
            StartArg::Data => StartScheme::Data,
            StartArg::Paper => StartScheme::Paper,
            StartArg::Template if o.template.is_none() => {
                return Err(anyhow!("--start template needs --template <file.tir>"))
            }
            StartArg::Template => StartScheme::Template,
        },
        template: template_tyre,
        max_iterations: o.max_iterations,
    };
    println!(
        "{}: {} samples, {} rows; model {}, start {:?}",
        o.data.display(),
        prepared.account.samples,
        prepared.account.rows,
        o.model,
        o.start
    );
    if let Some(g) = &prepared.account.thinning {
        for line in g.lines() {
            println!("  {line}");
        }
    }
    let id = mf_staged::identify(&prepared.rows, &settings)
        .map_err(|e| anyhow!("{}: {e}", o.data.display()))?;
    for s in &id.report.stages {
        match &s.skipped {
            Some(why) => println!("  {:<12} skipped: {why}", s.stage.label()),
            None => println!(
                "  {:<12} {:>5} points, {} free: σ {:.3} % (start {:.2} %; Wei et al. 2010: {:.2} %), RMS {:.2}, {:.2} s",
                s.stage.label(),
                s.points,
                s.parameters.iter().filter(|p| p.free).count(),
                s.sigma_percent,
                s.sigma_start_percent,
                s.paper_sigma_percent,
                s.rms,
                s.seconds
            ),
        }
        for w in &s.warnings {
            println!("    warning: {w}");
        }
        for p in s.parameters.iter().filter(|p| p.warning.is_some()) {
            println!(
                "    warning: {} = {:.6}: {}",
                p.name,
                p.value,
                p.warning.as_deref().unwrap_or("")
            );
        }
    }
    if let Some(s) = id.report.sigma_fy_mz_percent {
        println!("  Fy and Mz together: σ {s:.3} %");
    }
    let text = handling::io::tir::tir_text(&id.tyre, template.as_ref())?;
    let read_back = handling::io::tir::read_tir_text("<written .tir>", &text)?;
    let back = mf_staged::round_trip_difference(&id.tyre, &read_back, &prepared.rows);
    if back > 1e-9 {
        return Err(anyhow!(
            "the written .tir does not reproduce the fitted forces (relative difference {back:.2e})"
        ));
    }
    let mut report = serde_json::to_value(&id.report)?;
    report["data"] = serde_json::json!(o.data.display().to_string());
    report["rows"] = serde_json::to_value(&prepared.account)?;
    report["round_trip_relative_difference"] = serde_json::json!(back);
    write_bytes(&out, text.as_bytes())?;
    write_json(&report_path, &report)?;
    println!(
        "identified in {:.2} s; wrote {} and {}",
        id.report.seconds,
        out.display(),
        report_path.display()
    );
    Ok(())
}
