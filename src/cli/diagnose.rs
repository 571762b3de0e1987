//! `diagnose` (the sim-to-real gap of a campaign) and `synth` (the virtual
//! proving ground that writes campaigns with known effects).

use anyhow::Result;
use clap::Args;
use handling::diagnose::synth::Truth;
use handling::jobs::diagnose;
use handling::jobs::synth::{self, truth_named, EffectName};
use std::path::PathBuf;
use std::str::FromStr;

/// `handling diagnose`'s arguments.
#[derive(Args)]
pub struct DiagnoseArgs {
    /// Campaign file or folder.
    campaign: PathBuf,
    /// Output folder (default: out/<campaign name>).
    #[arg(long)]
    out: Option<PathBuf>,
}

/// `handling diagnose`.
pub fn diagnose(a: DiagnoseArgs) -> Result<()> {
    let r = diagnose::run(&a.campaign, a.out.as_deref())?;
    r.write()?;
    super::print(&r.summary());
    let f = r.outputs();
    println!(
        "diagnosed in {:.1} s; wrote {}, {}, {}",
        r.seconds,
        f[0].display(),
        f[1].display(),
        f[2].display()
    );
    Ok(())
}

/// `handling synth`'s arguments.
#[derive(Args)]
pub struct SynthArgs {
    /// Effects to switch on, comma-separated (`none` for none).
    #[arg(long, value_delimiter = ',', default_value = "none", value_parser = EffectName::from_str)]
    effects: Vec<EffectName>,
    /// Noise seed.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// The model that plays the car: `augmented` (the diagnosis's own
    /// model) or `four-wheel` (an independent four-wheel model with roll
    /// and its own tyre).
    #[arg(long, default_value = "augmented", value_parser = truth_named)]
    truth: Truth,
    /// Campaign folder to create.
    #[arg(long)]
    out: PathBuf,
}

/// `handling synth`: writes a campaign folder generated with the effects.
pub fn synth(a: SynthArgs) -> Result<()> {
    let r = synth::run(&a.effects, a.seed, a.truth, &a.out)?;
    r.write()?;
    println!("{}", r.wrote());
    Ok(())
}
