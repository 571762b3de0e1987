//! `tyre-eval`: forces and moments of a tyre file at the points of a CSV.

use anyhow::Result;
use clap::Args;
use handling::jobs::tyre_eval;
use std::path::PathBuf;

/// `handling tyre-eval`'s arguments.
#[derive(Args)]
pub struct TyreEvalArgs {
    /// Tyre file.
    tyre: PathBuf,
    /// Points file (CSV).
    points: PathBuf,
    /// Output CSV.
    #[arg(long)]
    out: PathBuf,
}

/// `handling tyre-eval`.
pub fn tyre_eval(a: TyreEvalArgs) -> Result<()> {
    let r = tyre_eval::run(&a.tyre, &a.points, &a.out)?;
    r.write()?;
    println!("{}", r.wrote());
    Ok(())
}
