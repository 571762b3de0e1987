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
    /// MFeval's useMode for a Magic Formula tyre: hundreds 1 = limit checks
    /// on, 2 = off; tens 1 = α* off, 2 = on; units 1 = no turn slip (turn
    /// slip is not modelled). Default 121.
    #[arg(long, value_name = "NNN")]
    mode: Option<u32>,
}

/// `handling tyre-eval`.
pub fn tyre_eval(a: TyreEvalArgs) -> Result<()> {
    let r = tyre_eval::run(&a.tyre, &a.points, &a.out, a.mode)?;
    for w in r.warnings() {
        eprintln!("warning: {w}");
    }
    r.write()?;
    for line in r.measured_lines() {
        say!("{line}");
    }
    say!("{}", r.wrote());
    Ok(())
}
