//! A campaign's `degrees = ["steer"]` under [runs] on runs whose steer is
//! in radians (`FORMATS.md`): read as degrees, their steer is 57.3× small
//! and their yaw rate far larger than a neutral car's for it (r·l/(u·δ)
//! above 5, the check the steer's unit is judged by, with the campaign's
//! wheelbase), while as logged it reads as a car's. Each run refused so by
//! itself asked whether `steer` was already in radians: N refusals for
//! one mistake in the campaign file (fresh-eyes round 49). They are one
//! refusal at that `degrees` entry, naming each run with the factor it
//! reads off by (its ratio as declared over its ratio as logged); where
//! other runs read right so, their files log the steer in degrees and a
//! campaign has no per-run unit: they are named to convert, as the yaw
//! rate's refusal at its entry names its own (`yaw_unit.rs`). ISO 8855
//! signs; SI, rad.

use super::run_checks::Judged;
use crate::error::{
    CampaignFileProblem, DeclaredRun, InputError, InputProblem, OtherRun, SteerDeclaredRuns,
};
use crate::io::AngleColumn;

/// The runs a declared `steer` reads 57× small (`small`, each with its
/// index in the campaign) as one refusal at that `degrees` entry
/// (`at_degrees`), filed in `refused` at the index of the first for the
/// order of refusals; the runs that read right so are those of `taken`
/// (in run order) `judged` by their held or swept steer, the others named
/// as `judged` says. Nothing where no run reads so.
pub(super) fn declared_refusal(
    (small, taken): (Vec<(usize, Box<DeclaredRun>)>, &[String]),
    (judged, refused): (&Judged, &mut Vec<(usize, InputError)>),
    at_degrees: &dyn Fn(AngleColumn, InputProblem) -> InputError,
    of: usize,
) {
    let Some(first) = small.iter().map(|(i, _)| *i).min() else {
        return;
    };
    let problem = SteerDeclaredRuns {
        runs: small.into_iter().map(|(_, d)| *d).collect(),
        of,
        right: read_right(taken, judged),
        others: judged
            .1
            .iter()
            .filter(|(_, k)| *k != OtherRun::Swept)
            .cloned()
            .collect(),
    };
    let problem = CampaignFileProblem::SteerDeclaredRuns(problem);
    let e = at_degrees(
        AngleColumn::Steer,
        InputProblem::Campaign(Box::new(problem)),
    );
    refused.push((first, e));
}

/// The runs of `taken` whose steer reads right against their yaw rate as
/// `judged`: held in radians, or swept; in run order.
fn read_right(taken: &[String], judged: &Judged) -> Vec<String> {
    let swept = |run: &String| {
        judged
            .1
            .iter()
            .any(|(r, k)| r == run && *k == OtherRun::Swept)
    };
    taken
        .iter()
        .filter(|run| judged.0.contains(run) || swept(run))
        .cloned()
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    #[test]
    fn the_runs_read_small_are_one_refusal_naming_those_that_read_right() {
        let small = |run: &str| {
            Box::new(DeclaredRun {
                run: run.into(),
                declared: 45.8,
                logged: 0.8,
            })
        };
        // Run order: a (small), b (held, right), c (swept, right), d
        // (refused for another reason), e (small), f (unjudged).
        let taken: Vec<String> = ["b", "c", "f"].map(String::from).to_vec();
        let judged: Judged = (
            vec!["b".into()],
            vec![
                ("c".into(), OtherRun::Swept),
                ("d".into(), OtherRun::Refused),
                ("f".into(), OtherRun::Unjudged),
            ],
        );
        let mut refused = vec![(
            3,
            InputError::problem(Path::new("d"), InputProblem::TooFewSamples),
        )];
        let at = |column: AngleColumn, problem| {
            assert_eq!(column, AngleColumn::Steer);
            InputError::problem(Path::new("c.toml"), problem)
        };
        let small = vec![(4, small("e")), (0, small("a"))];
        declared_refusal((small, &taken), (&judged, &mut refused), &at, 6);
        assert_eq!(refused.len(), 2);
        let (first, e) = &refused[1];
        assert_eq!(*first, 0);
        let InputError::Invalid { problem, .. } = e else {
            panic!("{e}")
        };
        let InputProblem::Campaign(c) = &**problem else {
            panic!("{e}")
        };
        let CampaignFileProblem::SteerDeclaredRuns(p) = &**c else {
            panic!("{e}")
        };
        let names: Vec<&str> = p.runs.iter().map(|r| r.run.as_str()).collect();
        assert_eq!(names, ["e", "a"]);
        assert_eq!(p.right, ["b", "c"]);
        let others: Vec<&str> = p.others.iter().map(|(r, _)| r.as_str()).collect();
        assert_eq!(others, ["d", "f"]);
        assert_eq!(p.of, 6);

        // No run read small: nothing filed.
        let mut refused = Vec::new();
        declared_refusal((Vec::new(), &taken), (&judged, &mut refused), &at, 6);
        assert!(refused.is_empty());
    }
}
