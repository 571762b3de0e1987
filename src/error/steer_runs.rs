//! A campaign some of whose runs log the steer in degrees (or as a
//! steering-wheel angle) and some in radians: the run's own refusal
//! suggested `degrees = ["steer"]` under [runs], which converts every
//! run's steer and would break the runs logged right. It names the runs
//! that read so, says how many do not, and what to do with each kind;
//! every other run is accounted for by name (a swept steer judged by its
//! lagged yaw rate, a steer neither held nor swept, a run refused for
//! another reason): "1 of the 8 runs … 6 runs do not" once left the
//! eighth unsaid. Only runs taken are counted as reading in radians: a
//! run refused after its steer was judged (another sign convention) is
//! named as refused (round 49). Runs whose yaw rate a `degrees =
//! ["yaw_rate"]` makes 57× small are refused at that entry instead
//! ([`YawDeclaredRuns`]); runs whose steer `degrees = ["steer"]` makes 57×
//! small likewise ([`super::SteerDeclaredRuns`]).

use crate::format::readable;

/// Runs whose yaw rate is far smaller than a neutral car's for their
/// steer (a steer in degrees or a steering-wheel angle), of a campaign.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("the yaw rate is far smaller than a neutral car's for the steer in {}: {}: is `steer` in degrees (57×) or a steering-wheel angle (divide by the steering ratio)? {}", format!("{} of the {} runs", self.runs.len(), self.of), runs_said(&self.runs), self.advice())]
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
    /// Refused for another reason (before its steer was judged, or by
    /// what judging it found: a sign, a ratio no car gives): not taken,
    /// so never counted among the runs that read in radians.
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
        let said: Vec<String> = held.into_iter().chain(others_said(&self.others)).collect();
        format!("{other}: {}. {fix}", said.join("; "))
    }
}

/// Runs by name, grouped by what their steer was judged by ([`OtherRun`]).
pub(super) fn others_said(others: &[(String, OtherRun)]) -> Vec<String> {
    let group = |kind: OtherRun, one: &str, many: &str| {
        let names: Vec<&str> = others
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
            "was refused for another reason",
            "were refused for other reasons",
        ),
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// The runs of a campaign that `degrees = ["yaw_rate"]` under [runs]
/// reads 57× small: their yaw rate, in rad/s as `FORMATS.md` asks, read
/// as deg/s is far smaller than a neutral car's for their steer. Refused
/// at that `degrees` entry, which is what to mend: the runs' own refusal
/// asked whether `steer` was in degrees (round 48). The runs that read
/// right so log the yaw rate in deg/s, and are named to convert in their
/// files (a campaign has no per-run unit).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("`degrees` under [runs] declares `yaw_rate` in deg/s for every run, and so read the yaw rate is far too small in {} of the {} runs: {}, as a yaw rate in rad/s read as deg/s is 57× smaller: {} in rad/s, as FORMATS.md asks. {}", self.runs.len() + self.by_ay.len(), self.of, self.said(), if self.runs.len() + self.by_ay.len() == 1 { "that run logs it" } else { "those runs log it" }, self.advice())]
pub struct YawDeclaredRuns {
    /// Each run that reads so (its file) and its median r·l/(u·δ).
    pub runs: Vec<(String, f64)>,
    /// Each run whose yaw rate reads far smaller than `ay` over its speed
    /// (its file) and its ay/(speed·yaw_rate).
    pub by_ay: Vec<(String, f64)>,
    /// The campaign's run files.
    pub of: usize,
    /// The runs whose yaw rate, converted, reads right against their
    /// steer (held or swept): in deg/s in their files.
    pub right: Vec<String>,
    /// The campaign's other runs, their steer not judged ([`OtherRun`]).
    pub others: Vec<(String, OtherRun)>,
}

/// Runs with their median r·l/(u·δ), as both refusals list them.
fn runs_said(runs: &[(String, f64)]) -> String {
    runs.iter()
        .map(|(run, m)| {
            format!(
                "{run} ({}× smaller, median r·l/(u·δ) = {})",
                readable(1.0 / m, 2),
                readable(*m, 3)
            )
        })
        .collect::<Vec<_>>()
        .join(", ")
}

impl YawDeclaredRuns {
    /// The runs that read so, by what judged them: their steer, their `ay`.
    fn said(&self) -> String {
        let steer = (!self.runs.is_empty()).then(|| {
            format!(
                "far smaller than a neutral car's for the steer in {}",
                runs_said(&self.runs)
            )
        });
        let ay = (!self.by_ay.is_empty()).then(|| {
            let each: Vec<String> = self
                .by_ay
                .iter()
                .map(|(run, m)| format!("{run} (ay/(speed·yaw_rate) = {})", readable(*m, 3)))
                .collect();
            format!(
                "far smaller than `ay` over the speed, where a car's lateral acceleration is about speed × yaw_rate, in {}",
                each.join(", ")
            )
        });
        [steer, ay]
            .into_iter()
            .flatten()
            .collect::<Vec<_>>()
            .join("; ")
    }

    /// What to do: leave `yaw_rate` out of `degrees`; the runs that read
    /// right only so converted in their files; the runs not judged named.
    fn advice(&self) -> String {
        let out = "take \"yaw_rate\" out of `degrees` under [runs]";
        let unjudged = others_said(&self.others);
        let unjudged = match unjudged.is_empty() {
            true => String::new(),
            false => format!(" ({})", unjudged.join("; ")),
        };
        match self.right.len() {
            0 => format!("{out}{unjudged}"),
            n => format!(
                "{} {} right so, by {} steer against {} yaw rate: {} {} in deg/s, and a campaign has no per-run unit: {out} and convert the yaw rate of {} to rad/s in {} (÷ 57.2958){unjudged}",
                self.right.join(", "),
                if n == 1 { "reads" } else { "read" },
                if n == 1 { "its" } else { "their" },
                if n == 1 { "its" } else { "their" },
                if n == 1 { "it" } else { "they" },
                if n == 1 { "logs it" } else { "log it" },
                self.right.join(", "),
                if n == 1 { "its file" } else { "their files" },
            ),
        }
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
