//! `design` (the next test to drive: manoeuvres that separate the
//! candidates a diagnosis confounds).

use anyhow::{anyhow, Result};
use clap::Args;
use handling::design::DesignRequest;
use handling::diagnose::effects::EffectKind;
use handling::jobs::design;
use handling::jobs::synth::EffectName;
use std::path::PathBuf;
use std::str::FromStr;

/// `handling design`'s arguments.
#[derive(Args)]
pub struct DesignArgs {
    /// The diagnosis folder (`handling diagnose --out`), with its
    /// diagnosis.json.
    diagnosis: PathBuf,
    /// The campaign (default: the one the diagnosis names).
    #[arg(long)]
    campaign: Option<PathBuf>,
    /// Candidates to separate, comma-separated, the reference first
    /// (default: each confounded set of the diagnosis); `a+b` names a
    /// combination.
    #[arg(long, value_delimiter = ',')]
    effects: Vec<String>,
    /// Share of the lateral acceleration the runs reached that a design may ask.
    #[arg(long, default_value_t = handling::design::family::DEFAULT_AY_SHARE)]
    ay_share: f64,
    /// Largest |du/dt| a design may ask, m/s² (the runs' own where larger).
    #[arg(long, default_value_t = handling::design::family::DEFAULT_AX)]
    max_ax: f64,
    /// Best manoeuvres kept, each written as a scenario file.
    #[arg(long, default_value_t = 3)]
    top: usize,
    /// Runs driven after the design (CSV): their measured separation.
    #[arg(long)]
    measured: Vec<PathBuf>,
    /// Output folder (default: <diagnosis>/design).
    #[arg(long)]
    out: Option<PathBuf>,
}

fn candidate(name: &str) -> Result<Vec<EffectKind>> {
    name.split('+')
        .map(|n| {
            EffectName::from_str(n.trim())?
                .0
                .ok_or_else(|| anyhow!("`none` is no candidate to separate"))
        })
        .collect()
}

/// `handling design`.
pub fn design(a: DesignArgs) -> Result<()> {
    let sets = if a.effects.is_empty() {
        None
    } else {
        let set = a
            .effects
            .iter()
            .map(|e| candidate(e))
            .collect::<Result<Vec<_>>>()?;
        Some(vec![set])
    };
    let request = DesignRequest {
        sets,
        ay_share: a.ay_share,
        ax: a.max_ax,
        top: a.top,
        also: Vec::new(),
    };
    let r = design::run(
        &a.diagnosis,
        a.campaign.as_deref(),
        &request,
        &a.measured,
        a.out.as_deref(),
    )?;
    r.write()?;
    super::print(&r.summary());
    Ok(())
}
