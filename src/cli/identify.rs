//! `identify`: fit a tyre model to rig data.

use anyhow::Result;
use clap::Args;
use handling::jobs::identify::{self, FitOption, IdentifyModel, Options, Polish, StartArg};
use std::path::PathBuf;

/// `handling identify`'s arguments.
#[derive(Args)]
pub struct IdentifyArgs {
    /// Rig data file.
    data: PathBuf,
    /// The tyre model: one with a swarm fit, or mf61 / mf62 (the Magic
    /// Formula by Wei et al. (2010)'s staged Levenberg–Marquardt; writes a
    /// .tir).
    #[arg(long, value_parser = super::named::<IdentifyModel>(IdentifyModel::names))]
    model: IdentifyModel,
    /// Random seed of the swarm (a whole number of 0 or more; default 1).
    #[arg(long, allow_hyphen_values = true, value_parser = super::whole_number)]
    seed: Option<u64>,
    /// Tyre file to write (default: out/<data>_<model>.toml).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Keep only the load level holding this value, N (default: all; an
    /// error when no level lies near it): a model without load terms, such
    /// as `linear`, fits one.
    #[arg(long, allow_hyphen_values = true)]
    load: Option<f64>,
    /// Keep only the pressure level holding this value, Pa (an error when
    /// the file has no pressure column or no level near it).
    #[arg(long, allow_hyphen_values = true)]
    pressure: Option<f64>,
    /// Keep only the camber level holding this value, rad (default: all;
    /// an error when the file has no camber column or no level near it).
    #[arg(long, allow_hyphen_values = true)]
    camber: Option<f64>,
    /// Local polish: lm (the default), gn (Zhang & Li's (2017) modified
    /// Gauss-Newton) or none.
    #[arg(long, value_parser = super::named::<Polish>(|| Polish::ALL.map(Polish::as_str).to_vec()))]
    local: Option<Polish>,
    /// Slip-angle bin for thinning, degrees (0: no thinning): the
    /// samples of one condition in one bin are averaged; a lone sample is
    /// kept as it is.
    #[arg(long, default_value_t = 0.25, allow_hyphen_values = true)]
    bin_deg: f64,
    /// Slip-ratio bin for thinning longitudinal data (0: no thinning;
    /// default 0.0025).
    #[arg(long, allow_hyphen_values = true)]
    bin_kappa: Option<f64>,
    /// mf61/mf62: where the parameters start — `template` (the template's values), `data` (estimates from
    /// the data, then MINPACK's LM) or `paper` (all 1, Wei et al.'s LM
    /// with μ = 0.1, β = 5); default `data`.
    #[arg(long, value_parser = super::named::<StartArg>(|| StartArg::ALL.map(StartArg::as_str).to_vec()))]
    start: Option<StartArg>,
    /// mf61/mf62: a .tir whose constants (FNOMIN, UNLOADED_RADIUS,
    /// NOMPRES, side) and unfitted coefficients are kept, and whose
    /// layout the written file follows.
    #[arg(long)]
    template: Option<PathBuf>,
    /// mf61/mf62: Levenberg–Marquardt iterations per step at most
    /// (`--start paper` runs at least 500, the paper's scheme; default
    /// 150).
    #[arg(long, value_parser = super::count)]
    max_iterations: Option<usize>,
    /// Hold a parameter at a value, NAME=VALUE (repeatable): for mf61/mf62
    /// a .tir coefficient in the file's SI units in every stage, e.g.
    /// --hold PKY4=2 (without it, a parameter the data do not determine is
    /// held at the template's value or Pacejka's (2012) book default, and
    /// said so); for the other models one of the parameters of the tyre
    /// file it writes, in its units, e.g. --hold a1=-22.1 for pac89
    /// (PAC89's two-stage identification is then not run), or --hold
    /// pneumatic_trail=0.03 for linear (held there, not fitted to mz).
    #[arg(long)]
    hold: Vec<String>,
}

/// The options given that only some fits read, in the order of
/// `identify --help` (`identify/taken.rs` says which fit reads which).
fn given(a: &IdentifyArgs) -> Vec<FitOption> {
    [
        (FitOption::Seed, a.seed.is_some()),
        (FitOption::Load, a.load.is_some()),
        (FitOption::Pressure, a.pressure.is_some()),
        (FitOption::Camber, a.camber.is_some()),
        (FitOption::Local, a.local.is_some()),
        (FitOption::BinKappa, a.bin_kappa.is_some()),
        (FitOption::Start, a.start.is_some()),
        (FitOption::Template, a.template.is_some()),
        (FitOption::MaxIterations, a.max_iterations.is_some()),
    ]
    .into_iter()
    .filter(|(_, given)| *given)
    .map(|(o, _)| o)
    .collect()
}

/// `handling identify`.
pub fn identify(a: IdentifyArgs) -> Result<()> {
    identify::check_given(a.model, &given(&a))?;
    // Read with the model known: its error's example is one of its names.
    let hold = (a.hold.iter())
        .map(|s| identify::parse_hold(s, a.model))
        .collect::<Result<Vec<_>, _>>()?;
    let r = identify::run(&Options {
        data: a.data,
        model: a.model,
        seed: a.seed.unwrap_or(1),
        out: a.out,
        load: a.load,
        pressure: a.pressure,
        camber: a.camber,
        local: a.local.unwrap_or(Polish::Lm),
        alpha_bin_deg: a.bin_deg,
        kappa_bin: a.bin_kappa.unwrap_or(0.0025),
        start: a.start.unwrap_or(StartArg::Data),
        template: a.template,
        max_iterations: a.max_iterations,
        hold: hold.clone(),
    })
    .map_err(|e| named_hold(e, &hold))?;
    for w in r.warnings() {
        eprintln!("warning: {w}");
    }
    r.write()?;
    super::print(&r.summary());
    say!("{}", r.wrote());
    Ok(())
}

/// A refused option said as the user gave it: the library's error names
/// the parameter or option as Python's keyword does (`a1`, `bin_deg`), the
/// command line the flag too (`--hold a1=1e308`, `--bin-deg -1`). A value
/// is written in its shortest form (`1e308`, not 309 digits).
fn named_hold(e: handling::error::Error, hold: &[(String, f64)]) -> anyhow::Error {
    let handling::error::Error::Param(p) = &e else {
        return e.into();
    };
    if let Some((name, v)) = hold.iter().find(|(name, _)| *name == p.key) {
        return anyhow::anyhow!("--hold {name}={}: {e}", handling::error::Num(*v));
    }
    match OPTIONS.iter().find(|k| **k == p.key) {
        Some(k) => anyhow::anyhow!("--{}: {e}", k.replace('_', "-")),
        None => e.into(),
    }
}

/// The options `Options::validate` names by their Python keyword.
const OPTIONS: [&str; 6] = [
    "bin_deg",
    "bin_kappa",
    "load",
    "pressure",
    "camber",
    "max_iterations",
];
