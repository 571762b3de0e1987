//! A campaign whose `degrees = ["steer"]` under [runs] reads runs logged
//! in radians (as `FORMATS.md` asks) 57.3× small: their yaw rate is then
//! far larger than a neutral car's for the steer (r·l/(u·δ) above 5, where
//! a car gives 0.2–1.5). Each such run's own refusal asked whether `steer`
//! was already in radians, one refusal per run for one mistake in the
//! campaign file (fresh-eyes round 49); it is one refusal at that entry,
//! naming the runs with the factor each reads off by (its ratio as
//! declared over its ratio as logged: 57.3 where only the unit differs).
//! Runs that read right so log the steer in degrees: a campaign has no
//! per-run unit, so they are named to convert in their files, as the yaw
//! rate's [`super::YawDeclaredRuns`] names its own.

use super::steer_runs::{others_said, OtherRun};
use crate::format::readable;

/// The runs of a campaign whose steer `degrees = ["steer"]` reads 57×
/// small, refused at that entry.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("`degrees` under [runs] declares `steer` in degrees for every run, and so read the steer is far too small in {} of the {} runs, the yaw rate far larger than a neutral car's for it: {}: as logged, {} as a car's, in radians as FORMATS.md asks. {}", self.runs.len(), self.of, runs_said(&self.runs), if self.runs.len() == 1 { "that run reads" } else { "those runs read" }, self.advice())]
pub struct SteerDeclaredRuns {
    /// Each run that reads so (its file) and its median r·l/(u·δ) with
    /// the steer as declared and as logged.
    pub runs: Vec<DeclaredRun>,
    /// The campaign's run files.
    pub of: usize,
    /// The runs taken whose steer, converted, reads right against their
    /// yaw rate (held or swept): in degrees in their files.
    pub right: Vec<String>,
    /// The campaign's other runs, their steer not judged or refused for
    /// another reason ([`OtherRun`]).
    pub others: Vec<(String, OtherRun)>,
}

/// A run whose steer as declared in degrees reads far too small.
#[derive(Debug, Clone, PartialEq)]
pub struct DeclaredRun {
    /// The run's file, as said.
    pub run: String,
    /// Its median r·l/(u·δ), the steer read in degrees as declared.
    pub declared: f64,
    /// Its median r·l/(u·δ), the steer read as logged (radians).
    pub logged: f64,
}

impl DeclaredRun {
    /// The factor the declaration makes the steer small by: the ratio as
    /// declared over the ratio as logged (180/π = 57.3 on the same
    /// samples).
    pub fn factor(&self) -> f64 {
        self.declared / self.logged
    }
}

/// Each run with its factor and both ratios.
fn runs_said(runs: &[DeclaredRun]) -> String {
    runs.iter()
        .map(|r| {
            format!(
                "{} ({}× too small: median r·l/(u·δ) = {} so, {} as logged)",
                r.run,
                readable(r.factor(), 3),
                readable(r.declared, 3),
                readable(r.logged, 3)
            )
        })
        .collect::<Vec<_>>()
        .join(", ")
}

impl SteerDeclaredRuns {
    /// What to do: leave `steer` out of `degrees`; the runs that read right
    /// only so converted in their files; the runs not judged named.
    fn advice(&self) -> String {
        let out = "take \"steer\" out of `degrees` under [runs]";
        let others = others_said(&self.others);
        let others = match others.is_empty() {
            true => String::new(),
            false => format!(" ({})", others.join("; ")),
        };
        let one = self.right.len() == 1;
        let (reads, its, it, logs, file) = match one {
            true => ("reads", "its", "it", "logs", "its file"),
            false => ("read", "their", "they", "log", "their files"),
        };
        match self.right.is_empty() {
            true => format!("{out}{others}"),
            false => format!(
                "{right} {reads} right so, by {its} steer against {its} yaw rate: {it} {logs} the steer in degrees, and a campaign has no per-run unit: {out} and convert the steer of {right} to radians in {file} (× π/180 = 0.0174533){others}",
                right = self.right.join(", "),
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(name: &str) -> DeclaredRun {
        DeclaredRun {
            run: name.into(),
            declared: 0.8 * 180.0 / std::f64::consts::PI,
            logged: 0.8,
        }
    }

    #[test]
    fn the_runs_are_named_with_their_factor_and_the_fix_is_said_once() {
        let e = SteerDeclaredRuns {
            runs: vec![run("a.csv"), run("b.csv")],
            of: 4,
            right: vec!["c.csv".into()],
            others: vec![("d.csv".into(), OtherRun::Refused)],
        };
        let s = e.to_string();
        assert!(
            s.contains("far too small in 2 of the 4 runs, the yaw rate far larger than a neutral car's for it: a.csv (57.3× too small: median r·l/(u·δ) = 45.8 so, 0.800 as logged), b.csv ("),
            "{s}"
        );
        assert!(
            s.contains("those runs read as a car's, in radians as FORMATS.md asks. c.csv reads right so, by its steer against its yaw rate: it logs the steer in degrees, and a campaign has no per-run unit: take \"steer\" out of `degrees` under [runs] and convert the steer of c.csv to radians in its file (× π/180 = 0.0174533) (d.csv was refused for another reason)"),
            "{s}"
        );
        // Every run read small: the entry alone is to go.
        let all = SteerDeclaredRuns {
            runs: vec![run("a.csv")],
            of: 1,
            right: Vec::new(),
            others: Vec::new(),
        };
        assert!(
            all.to_string().ends_with(
                "as logged, that run reads as a car's, in radians as FORMATS.md asks. take \"steer\" out of `degrees` under [runs]"
            ),
            "{all}"
        );
    }
}
