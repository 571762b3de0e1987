//! `study`: cornering stiffness against handling (Wang & Liang), or one
//! shard of its simulations (`handling merge` finishes it).

use anyhow::Result;
use clap::Args;
use handling::jobs::shard::Shard;
use std::path::PathBuf;

/// `handling study`'s arguments.
#[derive(Args)]
pub struct StudyArgs {
    /// Study file (TOML).
    study: PathBuf,
    /// Output folder (default: out/<study name>).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Simulate only shard K of N (combinations with index mod N = K − 1)
    /// and write shard-K-of-N.json; `handling merge` writes the outputs.
    #[arg(long, value_name = "K/N", value_parser = super::equilibria::parse_shard)]
    shard: Option<Shard>,
}

/// `handling study`.
pub fn study(a: StudyArgs) -> Result<()> {
    if let Some(shard) = a.shard {
        let r = handling::jobs::study::run_shard(&a.study, shard, a.out.as_deref())?;
        super::print(&r.summary());
        return Ok(());
    }
    let r = handling::jobs::study::run(&a.study, a.out.as_deref())?;
    r.write()?;
    super::print(&r.summary());
    say!("wrote {}", r.out_dir.display());
    Ok(())
}
