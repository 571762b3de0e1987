//! `simulate` and `metrics`.

use anyhow::Result;
use clap::Args;
use handling::jobs::{metrics, simulate};
use handling::metrics::MetricSettings;
use std::path::PathBuf;

/// `handling simulate`'s arguments.
#[derive(Args)]
pub struct SimulateArgs {
    /// Scenario file (TOML).
    scenario: PathBuf,
    /// Output folder (default: out/<scenario name>).
    #[arg(long)]
    out: Option<PathBuf>,
}

/// `handling simulate`.
pub fn simulate(a: SimulateArgs) -> Result<()> {
    let r = simulate::run(&a.scenario, a.out.as_deref())?;
    // Written before printed: a reader that stops early ends the process.
    r.write()?;
    super::print(&r.summary());
    say!("wrote {}", r.out_dir.display());
    Ok(())
}

/// `handling metrics`'s arguments.
#[derive(Args)]
pub struct MetricsArgs {
    /// The run file.
    run: PathBuf,
    /// Print JSON instead of a table.
    #[arg(long)]
    json: bool,
    /// Initial-value window, s.
    #[arg(long, default_value_t = 0.5, allow_negative_numbers = true, value_parser = window)]
    pre_window: f64,
    /// Steady-value window, s.
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true, value_parser = window)]
    steady_window: f64,
    /// Lowest speed kept, m/s: standstills and crawling are excluded.
    #[arg(long, default_value_t = 5.0, allow_negative_numbers = true, value_parser = min_speed)]
    min_speed: f64,
    /// Cut-off of the zero-phase low-pass applied to the run first, Hz
    /// (0: unfiltered).
    #[arg(long, default_value_t = handling::metrics::MEASURED_FILTER_HZ, allow_negative_numbers = true, value_parser = cut_off)]
    filter_hz: f64,
    /// Total-variance window from the steer onset, s.
    #[arg(long, default_value_t = 4.0, allow_negative_numbers = true, value_parser = window)]
    variance_window: f64,
    /// The least yaw-rate overshoot that counts as a peak, % of the step
    /// (0: any maximum above the noise).
    #[arg(long, default_value_t = handling::metrics::DEFAULT_MIN_OVERSHOOT, allow_negative_numbers = true, value_parser = percent)]
    min_overshoot: f64,
    /// A column the run gives in degrees (deg/s for `yaw_rate`), converted
    /// to radians: `steer`, `yaw_rate`, `beta` or `roll`, the angle
    /// columns the metrics read (repeatable, or several after a comma).
    #[arg(long, value_parser = angle_column, value_delimiter = ',')]
    degrees: Vec<handling::io::AngleColumn>,
}

/// An angle column `metrics` reads: refused at its option, with those it
/// reads (a run's `bank` it does not); a run column that is no angle
/// (`speed`) said as such, not answered with the nearest angle's name.
fn angle_column(text: &str) -> Result<handling::io::AngleColumn, String> {
    use handling::io::AngleColumn;
    let known = AngleColumn::read_by_metrics_names();
    AngleColumn::from_name(text.trim())
        .filter(|c| AngleColumn::READ_BY_METRICS.contains(c))
        .ok_or_else(|| match AngleColumn::not_an_angle(text.trim()) {
            // A column that exists and is no angle is no slip of one's name.
            Some(why) => format!(
                "{why}; the angle columns `metrics` reads in degrees are {}",
                known.join(", ")
            ),
            None => format!(
                "not an angle column `metrics` reads{}: one of {}",
                handling::format::did_you_mean(text, &known),
                known.join(", ")
            ),
        })
}

/// A metrics window, s: refused at its option, with the value given, when
/// it is not a positive finite number of seconds (the library refuses it
/// too, but by its key in a scenario's `[metrics]`, not by the option).
fn window(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        Ok(_) => Err("a window is a positive, finite number of seconds".into()),
        Err(_) => Err("not a number (a window is in seconds)".into()),
    }
}

/// The lowest speed kept, m/s: any number, whose range the library checks
/// by its key, in the words of a campaign's `min_speed` (this parser
/// refused 500 in a form of its own, "the lowest speed kept is a speed of
/// 0 to 150 m/s", fresh-eyes round 39); a text that is no number refused
/// here.
fn min_speed(text: &str) -> Result<f64, String> {
    text.trim().parse::<f64>().map_err(|_| {
        format!(
            "not a number (the lowest speed kept is in m/s, 0 to {})",
            handling::error::MAX_MIN_SPEED
        )
    })
}

/// The least overshoot of a peak, %: any number, whose range the library
/// checks by its key (one range said by the option and by a scenario's
/// `[metrics]`: this parser refused -1 as "at least 0 %" while the library
/// refused 1e308 as "[0, 100]"); a text that is no number refused here.
fn percent(text: &str) -> Result<f64, String> {
    text.trim().parse::<f64>().map_err(|_| {
        format!(
            "not a number (the least overshoot is in % of the step, 0 to {})",
            handling::metrics::MAX_MIN_OVERSHOOT
        )
    })
}

/// The low-pass cut-off, Hz: refused at its option when it is neither 0
/// (unfiltered) nor a positive finite frequency (the library refuses it by
/// its key).
fn cut_off(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v >= 0.0 => Ok(v),
        Ok(_) => Err("a cut-off is a positive, finite frequency in Hz (0: unfiltered)".into()),
        Err(_) => Err("not a number (a cut-off is in Hz)".into()),
    }
}

/// A refused setting said at the option the user typed (`--filter-hz 1`),
/// where the library names it by its key (`filter_hz`, as a scenario's
/// `[metrics]` and Python's keyword do).
fn at_flag(e: handling::error::Error) -> anyhow::Error {
    const SETTINGS: [&str; 6] = [
        "filter_hz",
        "min_overshoot",
        "pre_window",
        "steady_window",
        "variance_window",
        "min_speed",
    ];
    match &e {
        handling::error::Error::Param(p) if SETTINGS.contains(&p.key.as_str()) => {
            anyhow::anyhow!("--{}: {e}", p.key.replace('_', "-"))
        }
        _ => e.into(),
    }
}

/// `handling metrics`: notes on stderr, the table or JSON on stdout.
pub fn metrics(a: MetricsArgs) -> Result<()> {
    let settings = MetricSettings {
        pre_window: a.pre_window,
        steady_window: a.steady_window,
        variance_window: a.variance_window,
        // 0 is "unfiltered"; anything else the library checks.
        filter_hz: (a.filter_hz != 0.0).then_some(a.filter_hz),
        min_overshoot: a.min_overshoot,
        ..MetricSettings::default()
    };
    let r =
        metrics::run_with_degrees(&a.run, &settings, a.min_speed, &a.degrees).map_err(at_flag)?;
    for line in r.notes() {
        eprintln!("{line}");
    }
    if a.json {
        say!("{}", serde_json::to_string_pretty(&r)?);
    } else {
        super::print(&r.table());
    }
    Ok(())
}
