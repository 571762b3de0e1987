//! A campaign's runs whose yaw rate is in another unit than the others'
//! (rad/s, `FORMATS.md`): a campaign has one unit per channel (`[runs]
//! degrees` converts every run), so the advice a run read alone gets is
//! wrong for it.
//! - A run refused for a yaw rate in deg/s among runs whose yaw rate reads
//!   in rad/s (judged against their steer by a neutral car's r = u·δ/l,
//!   the check the steer's unit is judged by) is advised to convert its
//!   own file (÷ 57.2958), not to declare `degrees = ["yaw_rate"]`, which
//!   would make the others' 57× small.
//! - Runs whose yaw rate `degrees = ["yaw_rate"]` makes 57× small against
//!   their steer are refused at that entry, which is what to mend, naming
//!   the runs that read right so (in deg/s in their files); their own
//!   refusal asked whether `steer` was in degrees (round 48).

use super::run_checks::{Judged, SteerInDegrees};
use crate::error::{
    CampaignFileProblem, InputError, InputProblem, OtherRun, RunsInRadians, UnitSlip, YawAdvice,
    YawDeclaredRuns,
};
use crate::io::AngleColumn;

/// The advice of a refusal's yaw rate in deg/s, where it is one.
fn yaw_advice(e: &mut InputError) -> Option<&mut YawAdvice> {
    let InputError::Invalid { problem, .. } = e else {
        return None;
    };
    match problem.as_mut() {
        InputProblem::UnitSlip(
            UnitSlip::YawRate { by, .. } | UnitSlip::YawRateInDegPerS { by, .. },
        ) => Some(by),
        _ => None,
    }
}

/// The runs of `judged` whose yaw rate reads right against their steer:
/// held, or swept (against the lagged yaw rate); not those `refused` after
/// their steer was judged (a yaw rate 57× large among them).
fn read_right(judged: &Judged, refused: &[(usize, InputError)]) -> Vec<String> {
    let swept = judged.1.iter().filter(|(_, k)| *k == OtherRun::Swept);
    let swept = swept.map(|(run, _)| run);
    let taken = |run: &&String| {
        !refused
            .iter()
            .any(|(_, e)| e.path().display().to_string() == **run)
    };
    judged
        .0
        .iter()
        .chain(swept)
        .filter(taken)
        .cloned()
        .collect()
}

/// The refusals (`refused`) of runs whose yaw rate is in deg/s advised to
/// convert their own files where other runs of the `of` read in rad/s
/// (`judged`) and `degrees` does not declare the yaw rate (read alone,
/// each advises declaring it).
pub(super) fn own_file_advice(
    refused: &mut [(usize, InputError)],
    judged: &Judged,
    degrees: &[AngleColumn],
    of: usize,
) {
    let radians = read_right(judged, refused).len();
    if radians == 0 || degrees.contains(&AngleColumn::YawRate) {
        return;
    }
    let in_degrees = refused
        .iter_mut()
        .filter_map(|(_, e)| yaw_advice(e))
        .filter(|by| matches!(by, YawAdvice::Declare(_)))
        .count();
    let own = YawAdvice::OwnFile(RunsInRadians {
        in_degrees,
        radians,
        of,
    });
    for (_, e) in refused.iter_mut() {
        if let Some(by @ YawAdvice::Declare(_)) = yaw_advice(e) {
            *by = own;
        }
    }
}

/// A refused run's yaw rate 57× too small against its `ay`
/// ([`UnitSlip::YawRateTooSmall`] on its turning samples,
/// [`UnitSlip::YawScale`] on its steady half-seconds): its file and
/// ay/(speed·yaw_rate).
fn too_small_by_ay(e: &InputError) -> Option<(String, f64)> {
    let InputError::Invalid { path, problem, .. } = e else {
        return None;
    };
    let ratio = match problem.as_ref() {
        InputProblem::UnitSlip(UnitSlip::YawRateTooSmall { median, .. }) => *median,
        InputProblem::UnitSlip(UnitSlip::YawScale(y)) if y.in_degrees => 1.0 / y.share,
        _ => return None,
    };
    Some((path.display().to_string(), ratio))
}

/// Where `degrees` declares the yaw rate, the runs whose steer reads far
/// larger than their yaw rate (`in_degrees`) and those `refused` for a
/// yaw rate too small against their `ay` as one refusal at that entry,
/// filed in `refused` (at the index of the first run, for the order of
/// refusals), naming the runs that read right so (`judged`, not
/// `refused`); else `in_degrees` returned as it is.
pub(super) fn declared_refusal(
    in_degrees: Vec<(usize, Box<SteerInDegrees>)>,
    (judged, refused): (&Judged, &mut Vec<(usize, InputError)>),
    (degrees, at_degrees): (
        &[AngleColumn],
        &dyn Fn(AngleColumn, InputProblem) -> InputError,
    ),
    of: usize,
) -> Vec<(usize, Box<SteerInDegrees>)> {
    if !degrees.contains(&AngleColumn::YawRate) {
        return in_degrees;
    }
    let right = read_right(judged, refused);
    let (small, kept): (Vec<_>, Vec<_>) = std::mem::take(refused)
        .into_iter()
        .partition(|(_, e)| too_small_by_ay(e).is_some());
    *refused = kept;
    let indices = in_degrees
        .iter()
        .map(|(i, _)| *i)
        .chain(small.iter().map(|(i, _)| *i));
    let Some(first) = indices.min() else {
        return in_degrees;
    };
    let by_ay: Vec<(String, f64)> = small
        .iter()
        .filter_map(|(_, e)| too_small_by_ay(e))
        .collect();
    let runs = in_degrees
        .into_iter()
        .map(|(_, d)| (d.run, d.median))
        .collect();
    let folded = |run: &String| by_ay.iter().any(|(r, _)| r == run);
    let others = judged
        .1
        .iter()
        .filter(|(run, k)| *k != OtherRun::Swept && !folded(run));
    let problem = YawDeclaredRuns {
        runs,
        by_ay: by_ay.clone(),
        of,
        right,
        others: others.cloned().collect(),
    };
    let problem = CampaignFileProblem::YawDeclaredRuns(problem);
    let e = at_degrees(
        AngleColumn::YawRate,
        InputProblem::Campaign(Box::new(problem)),
    );
    refused.push((first, e));
    Vec::new()
}
