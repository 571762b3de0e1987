//! Which runs hold what a verdict leaves above noise ([`RunsCarrying`]),
//! in the words of its warning: the run (or two) and its share of the gap
//! above noise, or that it is spread over the runs, so that the user
//! knows whether one file is to look at. Shares in percent of `J² − J_n²`
//! (the held-out error's own measure, split over the runs' samples); `J`
//! dimensionless.

use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::outcome::{OutsideLibrary, RunShare, RunsCarrying};

/// One run and its share: `a.csv 58 % (its own held-out error 3.120)`,
/// and its yaw rate's scale where its road reads one the other runs do not
/// share (a gyro's scale error holds the gap its run leaves).
fn one(s: &RunShare) -> String {
    let scale = s.scale_apart.map_or(String::new(), |a| {
        format!("; {}", crate::measured::road::scale_in_run(&a))
    });
    format!(
        "{} {:.0} % (its own held-out error {:.3}{scale})",
        s.run, s.share_percent, s.heldout_error
    )
}

/// The run or two that hold most of it, named with their shares.
pub(super) fn held_by(r: &RunsCarrying) -> String {
    let each: Vec<String> = r.carried_by.iter().map(one).collect();
    let (who, verb) = match r.carried_by.len() {
        1 => ("one run", "holds"),
        _ => ("two runs", "hold"),
    };
    format!(
        "{who} {verb} most of it ({} of J² − J_n² over the {} runs' samples): {}",
        "more than two thirds",
        r.runs,
        each.join(" and ")
    )
}

/// `r` without the yaw-rate scales `said` already names (a run carrying
/// the channel's gap said with its scale is not said with it again).
pub(super) fn without_scales_said(r: &RunsCarrying, said: &str) -> RunsCarrying {
    let mut r = r.clone();
    for s in r.carried_by.iter_mut() {
        if let Some(a) = s.scale_apart {
            if said.contains(&crate::measured::road::scale_in_run(&a)) {
                s.scale_apart = None;
            }
        }
    }
    r
}

/// Where a further cause held by one run or two lies: in their data
/// first, else an effect outside the library or the base model's form.
pub(super) fn look_first(r: &RunsCarrying) -> &'static str {
    match r.carried_by.len() {
        1 => "the cause lies in that run's data or conditions, or in an effect outside the library or the base model's own form that it alone shows",
        _ => "the cause lies in those runs' data or conditions, or in an effect outside the library or the base model's own form that they alone show",
    }
}

/// No one or two runs hold most of it: spread, the largest part said.
pub(super) fn spread(r: &RunsCarrying) -> String {
    let largest = r
        .largest
        .as_ref()
        .map_or(String::new(), |s| format!("; the largest, {}", one(s)));
    format!(
        "it is spread over the runs, not one file: {} of {} runs lie above the noise level, and no one or two of them hold more than two thirds of J² − J_n²{largest}",
        r.above_noise, r.runs
    )
}

/// What an outside-the-library verdict `o` has beside it that bears on
/// it, in one clause after its sentence: the notes' files whose sideslip
/// moves against the base model's ([`OutsideLibrary::bearing`]), and the
/// run (or two) holding most of the gap or that it is spread over the
/// runs ([`OutsideLibrary::runs_carrying`]). Empty: nothing held. An
/// explained verdict's warnings say the same (round 39: a file whose beta
/// moved against the model was named there, not here).
pub(super) fn outside_bearing(o: &OutsideLibrary) -> String {
    let mut said: Vec<String> = Vec::new();
    if let Some(p) = super::causes::pointed(&o.bearing, Channel::Beta, f64::NAN) {
        said.push(format!("the notes bear on it: {p}"));
    }
    match &o.runs_carrying {
        Some(r) if !r.carried_by.is_empty() => said.push(held_by(r)),
        Some(r) => said.push(spread(r)),
        None => {}
    }
    match said.is_empty() {
        true => String::new(),
        false => format!("; {}", said.join("; ")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn share(run: &str, share_percent: f64, heldout_error: f64) -> RunShare {
        RunShare {
            run: run.into(),
            share_percent,
            heldout_error,
            scale_apart: None,
        }
    }

    /// One run, two runs and none, each in its words.
    #[test]
    fn the_runs_holding_what_is_left_are_said() {
        let r = RunsCarrying {
            carried_by: vec![share("runs/b.csv", 71.4, 3.1)],
            above_noise: 5,
            runs: 8,
            largest: None,
        };
        assert_eq!(
            held_by(&r),
            "one run holds most of it (more than two thirds of J² − J_n² over the 8 runs' samples): runs/b.csv 71 % (its own held-out error 3.100)"
        );
        let two = RunsCarrying {
            carried_by: vec![share("a.csv", 40.0, 2.0), share("b.csv", 35.0, 1.9)],
            ..r.clone()
        };
        assert!(
            held_by(&two).starts_with("two runs hold most of it"),
            "{}",
            held_by(&two)
        );
        assert!(held_by(&two).ends_with("a.csv 40 % (its own held-out error 2.000) and b.csv 35 % (its own held-out error 1.900)"));
        let spread_over = RunsCarrying {
            carried_by: Vec::new(),
            largest: Some(share("c.csv", 24.0, 1.8)),
            ..r
        };
        assert_eq!(
            spread(&spread_over),
            "it is spread over the runs, not one file: 5 of 8 runs lie above the noise level, and no one or two of them hold more than two thirds of J² − J_n²; the largest, c.csv 24 % (its own held-out error 1.800)"
        );
    }

    /// An outside-the-library verdict names the note's file and the run
    /// holding the gap after its sentence; nothing held, nothing said.
    #[test]
    fn an_outside_verdict_names_what_bears_on_it() {
        use crate::diagnose::report::outcome::ChannelCause;
        let mut o = OutsideLibrary {
            heldout_error: 1.985,
            noise_level: 0.946,
            refused: None,
            threshold_percent: 30.0,
            tyre_class: None,
            narrowed: None,
            bearing: Vec::new(),
            runs_carrying: None,
        };
        assert_eq!(outside_bearing(&o), "");
        o.bearing = vec![ChannelCause::BetaAgainst {
            file: "runs/sweep.csv".into(),
            correlation: -0.81,
        }];
        o.runs_carrying = Some(RunsCarrying {
            carried_by: vec![share("runs/sweep.csv", 80.0, 3.0)],
            above_noise: 2,
            runs: 8,
            largest: None,
        });
        assert_eq!(
            outside_bearing(&o),
            "; the notes bear on it: runs/sweep.csv's beta moves against the base model's (correlation -0.81, the note above); one run holds most of it (more than two thirds of J² − J_n² over the 8 runs' samples): runs/sweep.csv 80 % (its own held-out error 3.000)"
        );
    }
}
