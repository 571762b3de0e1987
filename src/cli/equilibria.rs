//! `equilibria`: sweep the steering equilibria and write CSV, JSON and PNGs.

use anyhow::Result;
use clap::Args;
use handling::jobs::equilibria;
use std::path::PathBuf;

/// `handling equilibria`'s arguments.
#[derive(Args)]
pub struct EquilibriaArgs {
    /// Sweep file (TOML).
    sweep: PathBuf,
    /// Output folder (default: out/<sweep name>).
    #[arg(long)]
    out: Option<PathBuf>,
}

/// `handling equilibria`.
pub fn equilibria(a: EquilibriaArgs) -> Result<()> {
    let r = equilibria::run(&a.sweep, a.out.as_deref())?;
    super::print(&r.summary());
    r.write()?;
    println!("wrote {}", r.out_dir.display());
    Ok(())
}
