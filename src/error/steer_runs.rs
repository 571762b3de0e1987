//! A campaign some of whose runs log the steer in degrees (or as a
//! steering-wheel angle) and some in radians: the run's own refusal
//! suggested `degrees = ["steer"]` under [runs], which converts every
//! run's steer and would break the runs logged right. It names the runs
//! that read so, says how many do not, and what to do with each kind;
//! every other run is accounted for by name (a swept steer judged by its
//! lagged yaw rate, a steer neither held nor swept, a run refused before
//! its steer was judged): "1 of the 8 runs … 6 runs do not" once left the
//! eighth unsaid.

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
    /// The runs whose held steer, judged against their yaw rate, reads
    /// in radians.
    pub radians: usize,
    /// The campaign's other runs (their files), each with what its steer
    /// was judged by.
    pub others: Vec<(String, OtherRun)>,
}

/// `n` runs named `subject` ("the other 7 runs", "6") whose held steer,
/// judged against their yaw rate, reads in radians.
fn held_in_radians(subject: &str, n: usize) -> String {
    let (verb, whose, should) = match n {
        1 => ("reads", "its", "it"),
        _ => ("read", "their", "they"),
    };
    format!("{subject} {verb} in radians by {whose} held steer against {whose} yaw rate, as {should} should")
}

/// A run of a campaign neither in degrees nor judged in radians on a held
/// steer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OtherRun {
    /// Its swept steer, judged against its lagged yaw rate, reads in
    /// radians.
    Swept,
    /// Its steer is neither held nor swept: its unit was not judged.
    Unjudged,
    /// Refused for another reason before its steer was judged.
    Refused,
}

impl SteerInDegreesRuns {
    /// Every other run of the campaign in one clause, counted once ("the
    /// other 7 runs: 6 read in radians by their held steer …; sweep.csv
    /// reads …"), then what to do: a fix in the files of the runs in
    /// degrees (when all runs are, the run's own refusal advises
    /// `degrees`). "1 run does not (their steer …)" and a second count
    /// after it read as two tallies of one campaign.
    fn advice(&self) -> String {
        let one = self.runs.len() == 1;
        let rest = self.radians + self.others.len();
        let fix = format!(
            "`degrees = [\"steer\"]` under [runs] would convert every run's steer, those in radians too (a campaign has no per-run unit): convert the steer of {} to radians in {} (× π/180 = 0.0174533 from degrees), or leave {} out of the campaign",
            if one { "this run" } else { "these runs" },
            if one { "its file" } else { "their files" },
            if one { "it" } else { "them" },
        );
        if rest == 0 {
            return fix;
        }
        let other = match rest {
            1 => "the other run".to_string(),
            n => format!("the other {n} runs"),
        };
        // Every other run held and in radians: said of them all at once.
        if self.others.is_empty() {
            return format!("{}. {fix}", held_in_radians(&other, rest));
        }
        let held =
            (self.radians > 0).then(|| held_in_radians(&self.radians.to_string(), self.radians));
        let said: Vec<String> = held.into_iter().chain(self.others()).collect();
        format!("{other}: {}. {fix}", said.join("; "))
    }

    /// The other runs by name, by what their steer was judged by.
    fn others(&self) -> Vec<String> {
        let group = |kind: OtherRun, one: &str, many: &str| {
            let names: Vec<&str> = self
                .others
                .iter()
                .filter(|(_, k)| *k == kind)
                .map(|(n, _)| n.as_str())
                .collect();
            let verb = if names.len() == 1 { one } else { many };
            (!names.is_empty()).then(|| format!("{} {verb}", names.join(", ")))
        };
        [
            group(
                OtherRun::Swept,
                "reads in radians by its swept steer against the lagged yaw rate",
                "read in radians by their swept steer against the lagged yaw rate",
            ),
            group(
                OtherRun::Unjudged,
                "holds no held or swept steer to judge its unit by",
                "hold no held or swept steer to judge their unit by",
            ),
            group(
                OtherRun::Refused,
                "was refused for another reason before its steer was judged",
                "were refused for other reasons before their steer was judged",
            ),
        ]
        .into_iter()
        .flatten()
        .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_run_of_the_campaign_is_accounted_for() {
        let e = SteerInDegreesRuns {
            runs: vec![("step.csv".into(), 0.0175)],
            of: 8,
            radians: 6,
            others: vec![("sweep.csv".into(), OtherRun::Swept)],
        };
        let s = e.to_string();
        assert!(s.contains("in 1 of the 8 runs: step.csv"), "{s}");
        assert!(
            s.contains("? the other 7 runs: 6 read in radians by their held steer against their yaw rate, as they should; sweep.csv reads in radians by its swept steer against the lagged yaw rate. `degrees"),
            "{s}"
        );
        let none = SteerInDegreesRuns {
            others: Vec::new(),
            radians: 7,
            ..e
        };
        assert!(none
            .to_string()
            .ends_with("or leave it out of the campaign"));
    }
}
