//! `simulate` and `metrics`.

use anyhow::{Context, Result};
use handling::io::{load_scenario, read_run};
use handling::manoeuvre::Manoeuvre;
use handling::metrics::{MetricSettings, StepMetrics};
use handling::report::plot::{Figure, Panel, Series, Style};
use handling::report::{refuse_overwrite, write_columns, write_json};
use handling::sim::{Method, TimeHistory};
use serde::Serialize;
use std::path::{Path, PathBuf};

#[derive(Serialize)]
struct MetricsReport<'a> {
    scenario: &'a str,
    units: &'static str,
    #[serde(flatten)]
    metrics: &'a StepMetrics,
    /// Intervals with a wheel off the ground (simulated runs only).
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    lift_offs: &'a [handling::sim::LiftOff],
}

const UNITS: &str = "SI and rad; times in s; yaw_rate_gain in 1/s; yaw_rate_overshoot in %; \
                     tb in s·deg (GB/T 6323); total variances and er in s";

fn print_metrics(m: &StepMetrics) {
    let opt =
        |v: Option<f64>, scale: f64| v.map_or("—".to_string(), |x| format!("{:.4}", x * scale));
    println!(
        "  steer step               {:>10.4} deg",
        m.steer_step.to_degrees()
    );
    println!(
        "  yaw-rate response time   {:>10.4} s",
        m.yaw_rate_response_time
    );
    println!(
        "  yaw-rate peak time       {:>10} s",
        opt(m.yaw_rate_peak_time, 1.0)
    );
    println!(
        "  yaw-rate overshoot       {:>10.2} %",
        m.yaw_rate_overshoot
    );
    println!(
        "  ay response time         {:>10} s",
        opt(m.ay_response_time, 1.0)
    );
    println!("  yaw-rate gain            {:>10.4} 1/s", m.yaw_rate_gain);
    println!(
        "  steady ay                {:>10} m/s²",
        opt(m.ay_steady, 1.0)
    );
    println!(
        "  steady sideslip          {:>10} deg",
        opt(m.beta_steady, 180.0 / std::f64::consts::PI)
    );
    println!("  TB                       {:>10} s·deg", opt(m.tb, 1.0));
    println!(
        "  E_r (yaw rate)           {:>10.4} s",
        m.yaw_rate_total_variance
    );
    println!(
        "  E_ay                     {:>10} s",
        opt(m.ay_total_variance, 1.0)
    );
    println!("  Er                       {:>10} s", opt(m.er, 1.0));
    if let Some(f) = m.filter_hz {
        println!(
            "  filtered: zero-phase 2nd-order Butterworth low-pass at {f} Hz; yaw-rate noise {:.2} % of the step",
            100.0 * m.yaw_rate_noise
        );
    }
    if m.yaw_rate_peak_time.is_none() {
        println!("  no overshoot: no yaw-rate maximum stands above the steady state by more than the noise");
    }
    if !m.settled {
        println!("  warning: the response has not settled in the steady window");
    }
}

fn history_figure(
    name: &str,
    h: &TimeHistory,
    measured: Option<&handling::io::MeasuredRun>,
) -> Figure {
    let deg = |v: &[f64]| v.iter().map(|x| x.to_degrees()).collect::<Vec<_>>();
    let mut panels = vec![
        Panel {
            title: format!("{name}: front road-wheel steer"),
            x_label: "t [s]".into(),
            y_label: "δ [deg]".into(),
            series: vec![Series::line("", &h.t, &deg(&h.steer), 0)],
            ..Panel::default()
        },
        Panel {
            title: "yaw rate".into(),
            x_label: "t [s]".into(),
            y_label: "r [deg/s]".into(),
            series: vec![Series::line("model", &h.t, &deg(&h.yaw_rate), 0)],
            ..Panel::default()
        },
        Panel {
            title: "lateral acceleration".into(),
            x_label: "t [s]".into(),
            y_label: "ay [m/s²]".into(),
            series: vec![Series::line("model", &h.t, &h.ay, 0)],
            ..Panel::default()
        },
        Panel {
            title: "sideslip".into(),
            x_label: "t [s]".into(),
            y_label: "β [deg]".into(),
            series: vec![Series::line("model", &h.t, &deg(&h.beta), 0)],
            ..Panel::default()
        },
    ];
    if let Some(run) = measured {
        let add = |p: &mut Panel, y: &[f64]| {
            p.series
                .push(Series::line("measured", &run.t, y, 1).styled(Style::Dashed));
        };
        add(&mut panels[1], &deg(&run.yaw_rate));
        if let Some(ay) = &run.ay {
            add(&mut panels[2], ay);
        }
        if let Some(b) = &run.beta {
            add(&mut panels[3], &deg(b));
        }
    }
    Figure::stack(panels)
}

/// `handling simulate`.
pub fn simulate(path: &Path, out: Option<&Path>) -> Result<()> {
    let sc = load_scenario(path)?;
    let out_dir = out.map_or_else(|| PathBuf::from("out").join(&sc.name), Path::to_path_buf);
    let sim = sc.integrator.simulate(&sc.model, &sc.manoeuvre, sc.initial);
    let h = &sim.history;
    let files = [
        out_dir.join("history.csv"),
        out_dir.join("metrics.json"),
        out_dir.join("response.png"),
        out_dir.join("gap.json"),
    ];
    for f in &files {
        refuse_overwrite(f, &sc.inputs)?;
    }
    let integration = match (sc.integrator.method, sim.stats()) {
        (Method::Dopri5(tol), Some(st)) => format!(
            "Dormand–Prince 5(4), rtol {:e}, atol {:e}: {} steps ({} rejected, {} evaluations, {} tyre-set evaluations), rows every {} s",
            tol.rtol, tol.atol, st.accepted, st.rejected, st.evaluations, h.load_evaluations, sc.integrator.step
        ),
        _ => format!("RK4, {} steps of {} s", h.len() - 1, sc.integrator.step),
    };
    println!(
        "{}: {integration}, tyres {} / {}, friction {}",
        sc.name,
        sc.model.front.model_name(),
        sc.model.rear.model_name(),
        sc.integrator.friction
    );
    // Everything is computed before the first file is written, so a failure
    // leaves no outputs behind.
    let metrics = match sc.manoeuvre {
        // From the dense output under Dormand–Prince (events located to
        // the tolerance), from the rows under RK4.
        Manoeuvre::StepSteer(_) => Some(
            sc.integrator
                .step_metrics(&sc.model, &sc.manoeuvre, &sim, &sc.metrics)
                .context("step-steer metrics")?,
        ),
        _ => None,
    };
    let lift_offs = h.lift_offs();
    write_columns(&files[0], &h.columns())?;
    if let Some(m) = &metrics {
        print_metrics(m);
        write_json(
            &files[1],
            &MetricsReport {
                scenario: &sc.name,
                units: UNITS,
                metrics: m,
                lift_offs: &lift_offs,
            },
        )?;
    }
    // The four loads always add up to the weight; a wheel at zero load has
    // lifted off, and the 2-DOF model then carries its axle on one wheel.
    for l in &lift_offs {
        println!(
            "  wheel lift-off: {:?} off the ground from {:.3} s to {:.3} s",
            l.wheel, l.start, l.end
        );
    }
    // A replayed measurement: where the model and the run disagree.
    if let Some(run) = &sc.measured {
        for line in sc.cleaning.iter().flat_map(|c| c.summary(5)) {
            println!("  cleaning: {line}");
        }
        let gap = handling::diagnose::gap::run_gap(run, h);
        for g in &gap {
            println!("  {}: {}", g.channel, g.verdict);
        }
        write_json(
            &files[3],
            &serde_json::json!({
                "run": run.path.display().to_string(),
                "channels": gap,
                "cleaning": sc.cleaning,
            }),
        )?;
    }
    history_figure(&sc.name, h, sc.measured.as_ref()).save(&files[2])?;
    println!("wrote {}", out_dir.display());
    Ok(())
}

/// `handling metrics`.
pub fn metrics(path: &Path, json: bool, settings: MetricSettings, min_speed: f64) -> Result<()> {
    let m =
        handling::metrics::measured::measured_step_metrics(read_run(path)?, min_speed, &settings)?;
    for line in m.cleaning.summary(usize::MAX) {
        eprintln!("cleaning: {line}");
    }
    eprintln!(
        "measured piece: {} ({:.2}–{:.2} s); steer 10–90 % rise {:.3} s",
        m.piece, m.t_start, m.t_end, m.steer_rise_time
    );
    for w in &m.warnings {
        eprintln!("warning: {w}");
    }
    let name = path.display().to_string();
    if json {
        println!(
            "{}",
            serde_json::to_string_pretty(&MeasuredMetricsReport {
                scenario: &name,
                units: UNITS,
                metrics: &m.metrics,
                piece: &m.piece,
                steer_rise_time: m.steer_rise_time,
                warnings: &m.warnings,
                cleaning: &m.cleaning,
            })?
        );
    } else {
        println!("{name}");
        print_metrics(&m.metrics);
    }
    Ok(())
}

/// `handling metrics --json`: the metrics, the piece measured and how the
/// run was cleaned.
#[derive(Serialize)]
struct MeasuredMetricsReport<'a> {
    scenario: &'a str,
    units: &'static str,
    #[serde(flatten)]
    metrics: &'a StepMetrics,
    piece: &'a str,
    steer_rise_time: f64,
    warnings: &'a [String],
    cleaning: &'a handling::measured::clean::CleaningReport,
}
