//! Argument parsing and printing; all work is done by the library.

mod diagnose;
mod equilibria;
mod identify;
mod simulate;
mod study;
mod tyre_eval;

use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "handling",
    version,
    about = "Vehicle handling simulator: 2-DOF model with load transfer and nonlinear tyres"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Simulate a scenario; writes history.csv, metrics.json and response.png.
    Simulate {
        /// Scenario file (TOML).
        scenario: PathBuf,
        /// Output folder (default: out/<scenario name>).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Steering equilibria over a sweep: PSO and exact solver, stability,
    /// bifurcations; writes equilibria.csv, bifurcations.csv, summary.json, PNGs.
    Equilibria {
        /// Sweep file (TOML).
        sweep: PathBuf,
        /// Output folder (default: out/<sweep name>).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Cornering stiffness against handling (Wang & Liang): map, RBF, inverse;
    /// writes study.csv, maps.png, rbf.json, rbf.png, inverse.json, summary.json.
    Study {
        /// Study file (TOML).
        study: PathBuf,
        /// Output folder (default: out/<study name>).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Fit a tyre model's lateral force to rig data (CSV, FORMATS.md): PSO
    /// then Levenberg–Marquardt or modified Gauss–Newton; writes a tyre file,
    /// a JSON report and a PNG.
    Identify {
        /// Rig data file.
        data: PathBuf,
        /// gim, magic-simple, unitire, pac89, linear, or mf61 / mf62 (the
        /// Magic Formula by Wei et al. (2010)'s staged Levenberg–Marquardt;
        /// writes a .tir).
        #[arg(long)]
        model: String,
        /// Random seed of the swarm.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Tyre file to write (default: out/<data>_<model>.toml).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Keep only the pressure level holding this value, Pa (an error when
        /// the file has no pressure column or no level near it).
        #[arg(long)]
        pressure: Option<f64>,
        /// Keep only the camber level holding this value, rad (default: all;
        /// an error when the file has no camber column or no level near it).
        #[arg(long)]
        camber: Option<f64>,
        /// Local polish: lm, gn (Zhang & Li's (2017) modified Gauss-Newton) or none.
        #[arg(long, default_value = "lm")]
        local: String,
        /// Slip-angle bin for thinning, degrees (0: no thinning): the
        /// samples of one condition in one bin are averaged; a lone sample is
        /// kept as it is.
        #[arg(long, default_value_t = 0.25)]
        bin_deg: f64,
        /// Slip-ratio bin for thinning longitudinal data (0: no thinning).
        #[arg(long, default_value_t = 0.0025)]
        bin_kappa: f64,
        /// mf61/mf62: where the parameters start — `template` (the template's values), `data` (estimates from
        /// the data, then MINPACK's LM) or `paper` (all 1, Wei et al.'s LM
        /// with μ = 0.1, β = 5).
        #[arg(long, value_enum, default_value_t = identify::StartArg::Data)]
        start: identify::StartArg,
        /// mf61/mf62: a .tir whose constants (FNOMIN, UNLOADED_RADIUS,
        /// NOMPRES, side) and unfitted coefficients are kept, and whose
        /// layout the written file follows.
        #[arg(long)]
        template: Option<PathBuf>,
        /// mf61/mf62: Levenberg–Marquardt iterations per step.
        #[arg(long, default_value_t = handling::identify::mf_staged::LM_ITERATIONS)]
        max_iterations: usize,
    },
    /// The sim-to-real gap of a campaign (a TOML file or a folder with
    /// vehicle.toml, runs/*.csv and optionally tyre_rig.csv): where the base
    /// model is wrong, which candidate effect explains it, how far the
    /// held-out gap shrinks; writes diagnosis.json, gap_map.png, overlays.png.
    Diagnose {
        /// Campaign file or folder.
        campaign: PathBuf,
        /// Output folder (default: out/<campaign name>).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Virtual proving ground: writes a campaign folder measured on a truth
    /// model with the given effects on (noise, UniTire tyres; the diagnosis
    /// fits PAC89 to its rig data).
    Synth {
        /// Effects to switch on, comma-separated (`none` for none).
        #[arg(long, value_delimiter = ',', default_value = "none")]
        effects: Vec<String>,
        /// Noise seed.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// The model that plays the car: `augmented` (the diagnosis's own
        /// model) or `four-wheel` (an independent four-wheel model with roll
        /// and its own tyre).
        #[arg(long, default_value = "augmented")]
        truth: String,
        /// Campaign folder to create.
        #[arg(long)]
        out: PathBuf,
    },
    /// Forces and moments of a tyre file (.tir or .toml) at the points of a
    /// CSV with columns fz, kappa, alpha, camber, speed and optionally
    /// pressure (SI, rad, Pa); writes them with fx, fy, mz (and mx, my for
    /// the Magic Formula).
    TyreEval {
        /// Tyre file.
        tyre: PathBuf,
        /// Points file (CSV).
        points: PathBuf,
        /// Output CSV.
        #[arg(long)]
        out: PathBuf,
    },
    /// Step-steer metrics of a measured run (CSV, FORMATS.md).
    Metrics {
        /// The run file.
        run: PathBuf,
        /// Print JSON instead of a table.
        #[arg(long)]
        json: bool,
        /// Initial-value window, s.
        #[arg(long, default_value_t = 0.5)]
        pre_window: f64,
        /// Steady-value window, s.
        #[arg(long, default_value_t = 1.0)]
        steady_window: f64,
        /// Lowest speed kept, m/s: standstills and crawling are excluded.
        #[arg(long, default_value_t = 5.0)]
        min_speed: f64,
        /// Cut-off of the zero-phase low-pass applied to the run first, Hz
        /// (0: unfiltered).
        #[arg(long, default_value_t = handling::metrics::MEASURED_FILTER_HZ)]
        filter_hz: f64,
        /// Total-variance window from the steer onset, s.
        #[arg(long, default_value_t = 4.0)]
        variance_window: f64,
    },
}

/// Parses the arguments, runs the command, prints errors; exit code 1 on error.
pub fn run() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Simulate { scenario, out } => simulate::simulate(&scenario, out.as_deref()),
        Command::Equilibria { sweep, out } => equilibria::equilibria(&sweep, out.as_deref()),
        Command::Study { study, out } => study::study(&study, out.as_deref()),
        Command::Identify {
            data,
            model,
            seed,
            out,
            pressure,
            camber,
            local,
            bin_deg,
            bin_kappa,
            start,
            template,
            max_iterations,
        } => identify::identify(&identify::Options {
            data: &data,
            model: &model,
            seed,
            out: out.as_deref(),
            pressure,
            camber,
            local: &local,
            alpha_bin_deg: bin_deg,
            kappa_bin: bin_kappa,
            start,
            template: template.as_deref(),
            max_iterations,
        }),
        Command::Diagnose { campaign, out } => diagnose::diagnose(&campaign, out.as_deref()),
        Command::Synth {
            effects,
            seed,
            truth,
            out,
        } => diagnose::synth(&effects, seed, &truth, &out),
        Command::TyreEval { tyre, points, out } => tyre_eval::tyre_eval(&tyre, &points, &out),
        Command::Metrics {
            run,
            json,
            pre_window,
            steady_window,
            min_speed,
            filter_hz,
            variance_window,
        } => simulate::metrics(
            &run,
            json,
            handling::metrics::MetricSettings {
                pre_window,
                steady_window,
                variance_window,
                filter_hz: (filter_hz > 0.0).then_some(filter_hz),
                ..handling::metrics::MetricSettings::default()
            },
            min_speed,
        ),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}
