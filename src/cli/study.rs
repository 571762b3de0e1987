//! `study`: cornering stiffness against handling (Wang & Liang).

use anyhow::Result;
use clap::Args;
use std::path::PathBuf;

/// `handling study`'s arguments.
#[derive(Args)]
pub struct StudyArgs {
    /// Study file (TOML).
    study: PathBuf,
    /// Output folder (default: out/<study name>).
    #[arg(long)]
    out: Option<PathBuf>,
}

/// `handling study`.
pub fn study(a: StudyArgs) -> Result<()> {
    let r = handling::jobs::study::run(&a.study, a.out.as_deref())?;
    super::print(&r.summary());
    r.write()?;
    println!("wrote {}", r.out_dir.display());
    Ok(())
}
