//! `equilibria`: sweep the steering equilibria and write CSV, JSON and PNGs,
//! or one shard of the sweep; `merge`: the outputs of a sharded run (a
//! sweep, a study or a batch of diagnoses).

use anyhow::Result;
use clap::Args;
use handling::jobs::equilibria;
use handling::jobs::shard::{shard_job, Shard, ShardJob};
use std::path::PathBuf;

/// `handling equilibria`'s arguments.
#[derive(Args)]
pub struct EquilibriaArgs {
    /// Sweep file (TOML).
    sweep: PathBuf,
    /// Output folder (default: out/<sweep name>).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Solve only shard K of N (lines of the grid with index mod N = K − 1)
    /// and write shard-K-of-N.json; `handling merge` writes the outputs.
    #[arg(long, value_name = "K/N", value_parser = parse_shard)]
    shard: Option<Shard>,
}

/// `handling merge`'s arguments.
#[derive(Args)]
pub struct MergeArgs {
    /// The shard files of one run (shard-K-of-N.json, every K once).
    #[arg(required = true)]
    shards: Vec<PathBuf>,
    /// Output folder (default: the unsharded run's).
    #[arg(long)]
    out: Option<PathBuf>,
}

pub(super) fn parse_shard(s: &str) -> Result<Shard, String> {
    s.parse().map_err(|e: handling::error::Error| e.to_string())
}

/// `handling equilibria`.
pub fn equilibria(a: EquilibriaArgs) -> Result<()> {
    if let Some(shard) = a.shard {
        let r = equilibria::run_shard(&a.sweep, shard, a.out.as_deref())?;
        super::print(&r.summary());
        return Ok(());
    }
    let r = equilibria::run(&a.sweep, a.out.as_deref())?;
    r.write()?;
    super::print(&r.summary());
    say!("wrote {}", r.out_dir.display());
    Ok(())
}

/// `handling merge`.
pub fn merge(a: MergeArgs) -> Result<()> {
    match shard_job(&a.shards[0])? {
        ShardJob::Equilibria => {
            let r = equilibria::merge(&a.shards, a.out.as_deref())?;
            r.write()?;
            super::print(&r.summary());
            say!("wrote {}", r.out_dir.display());
        }
        ShardJob::Study => {
            let r = handling::jobs::study::merge(&a.shards, a.out.as_deref())?;
            r.write()?;
            super::print(&r.summary());
            say!("wrote {}", r.out_dir.display());
        }
        ShardJob::Diagnose => {
            let r = handling::jobs::fleet::merge(&a.shards, a.out.as_deref())?;
            super::print(&r.summary());
            let [csv, json, html] = r.outputs();
            say!(
                "wrote {}, {}, {}",
                csv.display(),
                json.display(),
                html.display()
            );
            // As `diagnose --batch` ends: a merge that diagnosed nothing
            // does not end as a success.
            if let Some(e) = r.all_failed(&r.out_dir) {
                return Err(e.into());
            }
        }
    }
    Ok(())
}
