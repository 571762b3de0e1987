//! A campaign some of whose runs log the steer in degrees (or as a
//! steering-wheel angle) and some in radians: the run's own refusal
//! suggested `degrees = ["steer"]` under [runs], which converts every
//! run's steer and would break the runs logged right. It names the runs
//! that read so, says how many do not, and what to do with each kind.

use crate::format::readable;

/// Runs whose yaw rate is far smaller than a neutral car's for their
/// steer (a steer in degrees or a steering-wheel angle), of a campaign.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("the yaw rate is far smaller than a neutral car's for the steer in {}: {}: is `steer` in degrees (57×) or a steering-wheel angle (divide by the steering ratio)? {}", format!("{} of the {} runs", self.runs.len(), self.of), self.runs.iter().map(|(run, m)| format!("{run} ({}× smaller, median r·l/(u·δ) = {})", readable(1.0 / m, 2), readable(*m, 3))).collect::<Vec<_>>().join(", "), self.advice())]
pub struct SteerInDegreesRuns {
    /// Each run that reads so (its file) and its median r·l/(u·δ).
    pub runs: Vec<(String, f64)>,
    /// The campaign's run files.
    pub of: usize,
    /// The runs whose steer, judged against their yaw rate, reads in
    /// radians (others were refused before, or hold no steer to judge).
    pub radians: usize,
}

impl SteerInDegreesRuns {
    /// What to do: a fix in the files of the runs in degrees (when all
    /// runs are, the run's own refusal advises `degrees`).
    fn advice(&self) -> String {
        format!(
            "{} not (their steer, judged against their yaw rate, is in radians, as it should be), and `degrees = [\"steer\"]` under [runs] would convert every run's steer, theirs too (a campaign has no per-run unit): convert the steer of {} to radians in {} (× π/180 = 0.0174533 from degrees), or leave {} out of the campaign",
            crate::format::plural(self.radians, "run does", "runs do"),
            if self.runs.len() == 1 { "this run" } else { "these runs" },
            if self.runs.len() == 1 { "its file" } else { "their files" },
            if self.runs.len() == 1 { "it" } else { "them" },
        )
    }
}
