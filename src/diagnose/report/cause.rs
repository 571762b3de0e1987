//! Where a verdict's warning on a channel ([`ChannelLeft`],
//! [`ChannelWorsened`]) says its gap has another cause, what the
//! diagnosis already holds about that channel elsewhere in its report
//! ([`ChannelCause`]), carried into the warning as typed values once the
//! notes and the gap's findings are made: a file whose sideslip moves
//! against the base model's (the note on the inputs), one run carrying
//! most of the gap the effects leave (the held-out table's runs), the base
//! model's steady offset in the channel (the gap's finding); and where a
//! gap the effects leave is carried by one channel (the gap's shares),
//! which, and the run (or two) holding most of that gap over all
//! channels ([`super::runs_left`]), with its yaw-rate scale where its road
//! reads one apart from the other runs' ([`ScaleApart`]). Without them
//! "another cause (a model-form error …, or this channel's sensor)" points
//! nowhere while the report's top names the run (round 38: one run's
//! `beta` negated, its note at −0.88, the warning silent on it).
//!
//! Units: RMS values and floors in the channel's unit; shares in percent.

use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::outcome::RunsCarrying;
use crate::diagnose::report::outcome::{
    CarriedBy, ChannelCause, ChannelLeft, ChannelWorsened, GapFinding, Note, Verdict,
    VerdictWarning,
};
use crate::diagnose::report::shares::{ChannelShare, CARRIES_SHARE};
use crate::diagnose::report::summary::DOMINANT_SHARE;
use crate::diagnose::report::{GapReport, Part, Shrinkage};
use crate::measured::road::{RoadGeometry, ScaleApart};

/// Fills the causes of the channel warnings of an explained `verdict`
/// from the diagnosis's `notes` and its `gap` (its findings and held-out
/// table), and the channel that carries what a gap it leaves holds (the
/// gap's shares); the runs holding a gap left named with their yaw-rate
/// scale where their `roads` read one apart.
pub(crate) fn point(
    verdict: &mut Verdict,
    notes: &[Note],
    gap: &GapReport,
    roads: &[RoadGeometry],
) {
    if let Verdict::OutsideLibrary(o) = verdict {
        // The verdict's gap is the base model's: its parts' `after` are
        // its `before` (no effects).
        o.bearing = beta_against(notes);
        let runs = super::runs_left::runs_carrying(&gap.parts, &gap.noise, o.noise_level);
        o.runs_carrying = with_scales(runs, roads);
        return;
    }
    let Verdict::Explained(e) = verdict else {
        return;
    };
    let mut named: Vec<Channel> = Vec::new();
    for w in &mut e.warnings {
        match w {
            VerdictWarning::ChannelLeft(ChannelLeft {
                channel, causes, ..
            })
            | VerdictWarning::ChannelWorsened(ChannelWorsened {
                channel, causes, ..
            }) => {
                *causes = causes_of(*channel, notes, &gap.findings, &gap.parts);
                with_run_scales(causes, roads);
                if !causes.is_empty() {
                    named.push(*channel);
                }
            }
            _ => {}
        }
    }
    for w in &mut e.warnings {
        if let VerdictWarning::GapRemains {
            carried_by,
            runs_carrying,
            noise_level,
            ..
        } = w
        {
            let runs = super::runs_left::runs_carrying(&gap.parts, &gap.noise, *noise_level);
            *runs_carrying = with_scales(runs, roads);
            *carried_by = carrying(&gap.channel_shares).map(|(channel, share_percent)| {
                let causes_named = named.contains(&channel);
                // A channel no warning names: what the report holds about
                // it said here (round 39: one run's yaw offset carried the
                // rest, "ay carries 75 %" pointed nowhere).
                let mut causes = match causes_named {
                    true => Vec::new(),
                    false => causes_of(channel, notes, &gap.findings, &gap.parts),
                };
                with_run_scales(&mut causes, roads);
                let noise_floor = gap
                    .parts
                    .iter()
                    .find(|p| p.channel == channel && p.part == Part::All)
                    .map_or(f64::NAN, |p| p.noise_floor);
                CarriedBy {
                    channel,
                    share_percent,
                    causes_named,
                    causes,
                    noise_floor,
                }
            });
        }
    }
}

/// `runs` with the yaw-rate scale apart of each run named in it, from its
/// road in `roads` (the same run names: each replayed piece's).
fn with_scales(runs: Option<RunsCarrying>, roads: &[RoadGeometry]) -> Option<RunsCarrying> {
    let mut runs = runs?;
    let scale_of =
        |run: &str| -> Option<ScaleApart> { roads.iter().find(|g| g.run == run)?.scale_apart };
    for s in runs.carried_by.iter_mut().chain(runs.largest.iter_mut()) {
        s.scale_apart = scale_of(&s.run);
    }
    Some(runs)
}

/// The yaw-rate scale apart of each run carrying a channel's gap in
/// `causes`, from its road in `roads`.
fn with_run_scales(causes: &mut [ChannelCause], roads: &[RoadGeometry]) {
    for c in causes {
        if let ChannelCause::RunCarries {
            run, scale_apart, ..
        } = c
        {
            *scale_apart = roads
                .iter()
                .find(|g| g.run == *run)
                .and_then(|g| g.scale_apart);
        }
    }
}

/// The channel carrying more than [`CARRIES_SHARE`] of the held-out `J²`
/// with the verdict's effects, and its share (%), where more than one
/// channel is measured.
fn carrying(shares: &[ChannelShare]) -> Option<(Channel, f64)> {
    if shares.len() < 2 {
        return None;
    }
    shares
        .iter()
        .filter_map(|s| Some((s.channel, s.after_percent?)))
        .find(|(_, p)| *p > 100.0 * CARRIES_SHARE)
}

/// What the report holds about `channel`: the files whose β moves against
/// the model's (β only), the run carrying most of its gap left, its
/// steady offset; in that order.
pub(crate) fn causes_of(
    channel: Channel,
    notes: &[Note],
    findings: &[GapFinding],
    parts: &[Shrinkage],
) -> Vec<ChannelCause> {
    let mut out: Vec<ChannelCause> = Vec::new();
    if channel == Channel::Beta {
        out.extend(beta_against(notes));
    }
    let all = parts
        .iter()
        .find(|p| p.channel == channel && p.part == Part::All);
    out.extend(all.and_then(run_carrying));
    out.extend(findings.iter().find_map(|f| match f {
        GapFinding::Channel {
            channel: c,
            offset: Some(o),
            ..
        } if *c == channel => Some(ChannelCause::SteadyOffset(*o)),
        _ => None,
    }));
    out
}

/// The files whose β moves against the model's, from the `notes`.
fn beta_against(notes: &[Note]) -> Vec<ChannelCause> {
    notes
        .iter()
        .filter_map(|n| match n {
            Note::BetaAgainstInFile {
                file, correlation, ..
            } => Some(ChannelCause::BetaAgainst {
                file: file.clone(),
                correlation: *correlation,
            }),
            _ => None,
        })
        .collect()
}

/// The run of a channel's all-samples row `row` that carries more than
/// [`DOMINANT_SHARE`] of its held-out gap above noise with the verdict's
/// effects (each run's samples times `after² − floor²`, the part of its
/// mean square above the noise), where there are two runs or more and a
/// gap above noise to share.
fn run_carrying(row: &Shrinkage) -> Option<ChannelCause> {
    let floor2 = row.noise_floor * row.noise_floor;
    let above = |r: &crate::diagnose::report::RunPart| {
        r.samples as f64 * (r.after * r.after - floor2).max(0.0)
    };
    let total: f64 = row.runs.iter().map(above).sum();
    if row.runs.len() < 2 || total <= 0.0 || !total.is_finite() {
        return None;
    }
    let top = row
        .runs
        .iter()
        .max_by(|a, b| above(a).total_cmp(&above(b)))?;
    let share = above(top) / total;
    (share > DOMINANT_SHARE).then(|| ChannelCause::RunCarries {
        run: top.run.clone(),
        share_percent: 100.0 * share,
        rms: top.after,
        scale_apart: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::report::values::SteadyOffset;
    use crate::diagnose::report::RunPart;

    fn run(name: &str, samples: usize, after: f64) -> RunPart {
        RunPart {
            run: name.into(),
            samples,
            mean_level: None,
            before: after,
            after,
            bias_after: 0.0,
        }
    }

    fn row(channel: Channel, runs: Vec<RunPart>) -> Shrinkage {
        Shrinkage {
            channel,
            part: Part::All,
            samples: runs.iter().map(|r| r.samples).sum(),
            before: 0.01,
            after: 0.01,
            noise_floor: 0.002,
            reduction_percent: 0.0,
            mean_level: None,
            runs,
        }
    }

    /// The share is of the mean square above the noise, weighted by the
    /// samples: 0.0102 rad over 600 samples against 0.0030 over 7 × 600
    /// carries 600·(1.0404e-4 − 4e-6) / (that + 7·600·(9e-6 − 4e-6)) =
    /// 0.060024 / (0.060024 + 0.021) = 74.1 %, beyond two thirds; the same
    /// run at 0.0080 carries 0.036 / 0.057 = 63.2 %, not.
    #[test]
    fn a_run_carrying_more_than_two_thirds_of_the_gap_left_is_named() {
        let runs = |x: f64| {
            let mut v: Vec<RunPart> = (0..7)
                .map(|k| run(&format!("r{k}.csv"), 600, 0.003))
                .collect();
            v.insert(3, run("b.csv", 600, x));
            v
        };
        let Some(ChannelCause::RunCarries {
            run: named,
            share_percent,
            rms,
            scale_apart,
        }) = run_carrying(&row(Channel::Beta, runs(0.0102)))
        else {
            panic!("no run named")
        };
        assert_eq!((named.as_str(), rms), ("b.csv", 0.0102));
        // Its road's scale is added where the roads are known (`point`).
        assert_eq!(scale_apart, None);
        let expected = 100.0 * 0.060024 / (0.060024 + 0.021);
        assert!((share_percent - expected).abs() < 1e-6, "{share_percent}");
        assert_eq!(run_carrying(&row(Channel::Beta, runs(0.0080))), None);
        // One run is no share, nothing above noise nothing to share.
        let one = row(Channel::Beta, vec![run("a.csv", 600, 0.02)]);
        assert_eq!(run_carrying(&one), None);
        let quiet = row(Channel::Beta, vec![run("a.csv", 600, 0.001); 3]);
        assert_eq!(run_carrying(&quiet), None);
    }

    /// The β-sign note names its file for the β channel only; the steady
    /// offset of the channel's finding comes after the run; other
    /// channels' findings and notes are not this channel's.
    #[test]
    fn the_causes_are_the_channels_own_in_order() {
        let note = Note::BetaAgainstInFile {
            file: "runs/b.csv".into(),
            correlation: -0.88,
            samples: 601,
        };
        let offset = SteadyOffset {
            mean: -0.004,
            same_sign: 8,
            runs: 8,
            floors: 2.0,
            share: 0.6,
            std_error: 0.0,
        };
        let finding = |channel| GapFinding::Channel {
            channel,
            rms: 0.01,
            noise_floor: 0.002,
            significant_runs: 0,
            significant_in: Vec::new(),
            within_in: Vec::new(),
            runs: 8,
            wrong: Vec::new(),
            right: Vec::new(),
            off_in_right: Vec::new(),
            offset: Some(offset),
            combined: None,
        };
        let mut runs: Vec<RunPart> = (0..7).map(|k| run(&format!("r{k}"), 600, 0.003)).collect();
        runs.push(run("runs/b.csv", 600, 0.0102));
        let parts = [row(Channel::Beta, runs)];
        let notes = [note];
        let beta = causes_of(Channel::Beta, &notes, &[finding(Channel::Beta)], &parts);
        assert_eq!(beta.len(), 3, "{beta:?}");
        assert_eq!(
            beta[0],
            ChannelCause::BetaAgainst {
                file: "runs/b.csv".into(),
                correlation: -0.88
            }
        );
        assert!(matches!(&beta[1], ChannelCause::RunCarries { run, .. } if run == "runs/b.csv"));
        assert_eq!(beta[2], ChannelCause::SteadyOffset(offset));
        let yaw = causes_of(Channel::YawRate, &notes, &[finding(Channel::Beta)], &parts);
        assert!(yaw.is_empty(), "{yaw:?}");
    }

    /// The sweep with its β negated (round 38): β carried 82 % of the
    /// verdict's J², and the gap it left was "a further cause (an effect
    /// outside the library, or the base model's own form)". The channel
    /// above two thirds after is named; none at or below it, none without
    /// a verdict's shares, none of one channel alone.
    #[test]
    fn the_channel_carrying_what_the_verdict_leaves_is_found() {
        let share = |channel, after: Option<f64>| ChannelShare {
            channel,
            before_percent: 33.0,
            offset_percent: None,
            before_offsets_aside_percent: 33.0,
            after_percent: after,
        };
        let shares = |beta: Option<f64>| {
            let rest = beta.map(|b| (100.0 - b) / 2.0);
            vec![
                share(Channel::YawRate, rest),
                share(Channel::Ay, rest),
                share(Channel::Beta, beta),
            ]
        };
        assert_eq!(carrying(&shares(Some(82.0))), Some((Channel::Beta, 82.0)));
        assert_eq!(carrying(&shares(Some(100.0 * CARRIES_SHARE))), None);
        assert_eq!(carrying(&shares(None)), None);
        assert_eq!(carrying(&[share(Channel::YawRate, Some(100.0))]), None);
    }
}
