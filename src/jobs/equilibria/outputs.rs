//! The files an `equilibria` run writes into its folder, so that an
//! earlier run's (a branch diagram of another swept axis, a phase portrait
//! beyond this sweep's count) are found and removed
//! ([`crate::report::stale`]).

use super::{EquilibriaReport, FILES};
use crate::report::stale::OwnSet;
use std::path::PathBuf;

/// `equilibria`'s outputs: its tables and summary, and its figures.
pub(super) const OWN: OwnSet = OwnSet {
    names: &[
        "equilibria.csv",
        "bifurcations.csv",
        "summary.json",
        "continua.csv",
        "stability_map.png",
    ],
    families: &[
        ("branches_", ".png"),
        ("branches_", ".csv"),
        ("phase_portrait_", ".png"),
    ],
};

impl EquilibriaReport {
    /// The files [`EquilibriaReport::write`] writes, as it names them.
    pub(super) fn outputs(&self) -> Vec<PathBuf> {
        let dir = &self.out_dir;
        let mut files: Vec<PathBuf> = FILES.iter().map(|f| dir.join(f)).collect();
        let sw = &self.sweep;
        if sw.report.plots {
            let v = sw.grid.varying();
            for &axis in &v {
                for d in super::slices::diagrams(&sw.grid, axis).0 {
                    files.push(dir.join(format!("{}.png", d.stem)));
                    files.push(dir.join(format!("{}.csv", d.stem)));
                }
            }
            if v.len() >= 2 {
                files.push(dir.join("stability_map.png"));
            }
            files.extend(
                (0..sw.portraits.len()).map(|k| dir.join(format!("phase_portrait_{k}.png"))),
            );
        }
        files
    }
}
