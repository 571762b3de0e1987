//! Where the gap lies, in tables and words: the base model's gap on each
//! run, held-out errors pooled per channel, window and regime before and
//! after the verdict's effects, and the findings of the report (worded in
//! [`super::words`]).
//! Units: each channel's own (rad/s, m/s², rad).

use crate::diagnose::model::channels::reduction;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::model::replay::Prepared;
use crate::diagnose::model::scale::FloorCounting;
use crate::diagnose::model::{Augmented, Observed};
use crate::diagnose::report::gap::{channel_gap, regime_acceleration, run_gap, PartGap, Record};
use crate::diagnose::report::outcome::{above_noise, CombinedGap, GapFinding, OffInRight};
use crate::diagnose::report::parts::LEAST_PART_SAMPLES;
use crate::diagnose::report::shares::ChannelShare;
use crate::diagnose::report::values::SteadyOffset;
use crate::diagnose::report::{Part, RunGap, RunPart, Shrinkage};
use crate::manoeuvre::interpolate;
use crate::measured::MeasuredRun;

/// The base model's gap on one run, at the run's own samples (the base
/// model has no sensor effects: its history is what the sensors read),
/// each channel against its `trusted` noise floor, counted in the bias test
/// as `counting` says.
pub(crate) fn base_run_gap(
    base: &Augmented,
    run: &MeasuredRun,
    step: f64,
    (trusted, counting): (&[f64; 3], &[FloorCounting; 3]),
) -> RunGap {
    let p = Prepared::new(run, step, f64::INFINITY);
    let history = p.replay(base);
    let idx = crate::diagnose::report::gap::scored_samples(run);
    let pick = |v: &[f64]| -> Vec<f64> { idx.iter().map(|&i| v[i]).collect() };
    let t = pick(&run.t);
    let yaw_rate: Vec<f64> = t
        .iter()
        .map(|&t| interpolate(&history.t, &history.yaw_rate, t))
        .collect();
    let channels = run_gap(run, &history, trusted, counting);
    // The bands are judged against the yaw rate's noise floor, as its gap is.
    let floor = channels
        .iter()
        .find(|c| c.channel == Channel::YawRate)
        .map_or(0.0, |c| c.noise_floor);
    let bands = crate::diagnose::report::gap::band_gaps_above(
        &t,
        &pick(&run.steer),
        &pick(&run.yaw_rate),
        &yaw_rate,
        floor,
    );
    RunGap {
        run: run.path.display().to_string(),
        channels,
        bands: bands.found,
        bands_without_steer: bands.without_steer,
    }
}

/// The high-frequency scatter of each channel a run measures (None where
/// it does not) and its RMS, on its scored samples, as the run's gap
/// estimates its noise floor ([`channel_gap`]): known before any model.
pub(crate) fn run_scatter(run: &MeasuredRun) -> [Option<(f64, f64)>; 3] {
    let idx = crate::diagnose::report::gap::scored_samples(run);
    let pick = |v: &[f64]| -> Vec<f64> { idx.iter().map(|&i| v[i]).collect() };
    let (t, steer) = (pick(&run.t), pick(&run.steer));
    let pre = &crate::diagnose::report::parts::window_samples(&t, &steer)[0].1;
    Channel::ALL.map(|c| {
        c.of(run).map(|v| {
            let v = pick(v);
            let rms = (v.iter().map(|x| x * x).sum::<f64>() / v.len().max(1) as f64).sqrt();
            (crate::diagnose::report::parts::scatter(pre, &v), rms)
        })
    })
}

/// One run's held-out RMS before and after in every part of channel `ch`
/// (all samples, its time windows, its regimes), with their samples and
/// mean levels: `measured` against the base model's `before` and the
/// verdict's `after`, at the record's times.
fn run_parts(
    run: &str,
    rec: &Record,
    ch: Channel,
    measured: &[f64],
    [before, after]: [&[f64]; 2],
) -> Vec<(Part, RunPart)> {
    let gb = channel_gap(ch, rec, measured, before);
    let ga = channel_gap(ch, rec, measured, after);
    let all = |g: &crate::diagnose::report::gap::ChannelGap| PartGap {
        name: Part::All,
        samples: measured.len(),
        mean_level: None,
        rms: g.rms,
        bias: g.bias,
    };
    let (all_b, all_a) = (all(&gb), all(&ga));
    let pb = std::iter::once(&all_b)
        .chain(gb.windows.iter())
        .chain(gb.regimes.iter());
    let pa = std::iter::once(&all_a)
        .chain(ga.windows.iter())
        .chain(ga.regimes.iter());
    pb.zip(pa)
        .map(|(b, a)| {
            let share = RunPart {
                run: run.to_string(),
                samples: b.samples,
                mean_level: b.mean_level,
                before: b.rms,
                after: a.rms,
                bias_after: a.bias,
            };
            (b.name, share)
        })
        .collect()
}

/// A part's runs pooled: the RMS over all their samples, and their mean
/// level, each run weighted by its samples.
fn pooled(channel: Channel, part: Part, runs: Vec<RunPart>, noise_floor: f64) -> Shrinkage {
    let samples: usize = runs.iter().map(|r| r.samples).sum();
    let n = samples as f64;
    let mean_square = |f: fn(&RunPart) -> f64| {
        runs.iter()
            .map(|r| f(r) * f(r) * r.samples as f64)
            .sum::<f64>()
            / n
    };
    let (before, after) = (
        mean_square(|r| r.before).sqrt(),
        mean_square(|r| r.after).sqrt(),
    );
    // None for all samples: no run has a level there.
    let mean_level = runs
        .iter()
        .map(|r| r.mean_level.map(|l| l * r.samples as f64))
        .sum::<Option<f64>>()
        .map(|sum| sum / n);
    Shrinkage {
        channel,
        part,
        samples,
        before,
        after,
        noise_floor,
        reduction_percent: reduction(before, after, noise_floor),
        mean_level,
        runs,
    }
}

/// Held-out RMS before/after pooled over runs per channel, window and
/// regime, each part with its runs' shares ([`RunPart`]).
pub(crate) fn parts_table(
    runs: &[MeasuredRun],
    prepared: &[Prepared],
    before: &[Observed],
    after: &[Observed],
    floors: &[f64; 3],
) -> Vec<Shrinkage> {
    // (channel, part) → each run's share.
    let mut acc: Vec<(Channel, Part, Vec<RunPart>)> = Vec::new();
    for (i, p) in prepared.iter().enumerate() {
        let run = &runs[i];
        let at = |v: &[f64]| -> Vec<f64> {
            p.times.iter().map(|&t| interpolate(&run.t, v, t)).collect()
        };
        let steer = at(&run.steer);
        let speed = at(&run.speed);
        let ay = at(&regime_acceleration(run));
        let rec = Record {
            start: p.start_time(),
            t: &p.times,
            steer: &steer,
            ay: &ay,
            speed: &speed,
        };
        for (ch, m) in &p.measured {
            let models = [before, after].map(|o| observed_channel(&o[i], *ch));
            for (part, share) in run_parts(&p.name, &rec, *ch, m, models) {
                match acc.iter_mut().find(|x| x.0 == *ch && x.1 == part) {
                    Some(x) => x.2.push(share),
                    None => acc.push((*ch, part, vec![share])),
                }
            }
        }
    }
    // Pooled in the order the runs showed them: listed in the parts' own.
    acc.sort_by(|a, b| {
        let (ka, kb) = (a.1.order(), b.1.order());
        a.0.index()
            .cmp(&b.0.index())
            .then(ka.0.cmp(&kb.0))
            .then(ka.1.total_cmp(&kb.1))
    });
    acc.into_iter()
        .filter(|x| x.2.iter().any(|r| r.samples > 0))
        .map(|(ch, part, shares)| pooled(ch, part, shares, floors[ch.index()]))
        .collect()
}

/// Channel `ch`'s finding ([`gap_summary`]): where its held-out RMS is
/// above three noise floors and where within, the runs it is significant
/// in and its steady offset; None where no part covers all its samples.
fn channel_finding(
    ch: Channel,
    runs: &[RunGap],
    parts: &[Shrinkage],
    combined: Option<&CombinedGap>,
) -> Option<GapFinding> {
    let rows: Vec<&Shrinkage> = parts.iter().filter(|p| p.channel == ch).collect();
    let all = rows.iter().find(|p| p.part == Part::All)?;
    let nf = all.noise_floor;
    let split = rows
        .iter()
        .filter(|p| p.part != Part::All && p.samples >= LEAST_PART_SAMPLES);
    let wrong: Vec<(Part, f64)> = split
        .clone()
        .filter(|p| above_noise(p.before, nf))
        .map(|p| (p.part, p.before))
        .collect();
    let right: Vec<&&Shrinkage> = split.filter(|p| !above_noise(p.before, nf)).collect();
    let off_in_right = right.iter().flat_map(|p| off_in(p)).collect();
    let right: Vec<Part> = right.iter().map(|p| p.part).collect();
    let of = |significant: bool| -> Vec<(String, f64)> {
        runs.iter()
            .filter_map(|r| {
                let c = r
                    .channels
                    .iter()
                    .find(|c| c.channel == ch && c.significant == significant)?;
                Some((r.run.clone(), c.rms))
            })
            .collect()
    };
    let (significant_in, within_in) = (of(true), of(false));
    // Counted of the runs that measure the channel: a run without a beta
    // column is neither significant nor within noise in beta.
    let measuring = significant_in.len() + within_in.len();
    Some(GapFinding::Channel {
        channel: ch,
        rms: all.before,
        noise_floor: nf,
        significant_runs: significant_in.len(),
        significant_in,
        within_in,
        runs: measuring,
        wrong,
        right,
        off_in_right,
        offset: SteadyOffset::of(
            &runs
                .iter()
                .flat_map(|r| r.channels.iter().filter(|c| c.channel == ch))
                .map(|c| c.bias)
                .collect::<Vec<_>>(),
            nf,
            all.before,
        ),
        combined: combined.cloned(),
    })
}

/// The runs of a part `p` above three of its noise floors in it (at least
/// [`LEAST_PART_SAMPLES`], the parts' own rule), largest first: a part the pooled RMS
/// calls right is not right for them.
fn off_in(p: &Shrinkage) -> Vec<OffInRight> {
    let mut off: Vec<OffInRight> = p
        .runs
        .iter()
        .filter(|r| r.samples >= LEAST_PART_SAMPLES && above_noise(r.before, p.noise_floor))
        .map(|r| OffInRight {
            part: p.part,
            run: r.run.clone(),
            rms: r.before,
        })
        .collect();
    off.sort_by(|a, b| b.rms.total_cmp(&a.rms));
    off
}

/// The gap's findings (the report words them): overall, per channel where
/// it is largest and where the model is right (parts of at least ten
/// samples, against three noise floors), and the frequency bands of a run
/// whose yaw-rate response is off by more than 1 dB or 10°.
pub(crate) fn gap_summary(
    runs: &[RunGap],
    parts: &[Shrinkage],
    significant: bool,
    j0: f64,
    jn: f64,
) -> Vec<GapFinding> {
    let mut out = vec![GapFinding::Overall {
        significant,
        heldout_error: j0,
        noise_level: jn,
    }];
    // Where a significant combined gap lies: the channels significant
    // alone by the per-channel table's rule, so that a channel's line and
    // the table call the same channels significant.
    let combined = significant.then(|| CombinedGap {
        heldout_error: j0,
        noise_level: jn,
        significant_alone: parts
            .iter()
            .filter(|p| p.part == Part::All && above_noise(p.before, p.noise_floor))
            .map(|p| p.channel)
            .collect(),
    });
    out.extend(
        Channel::ALL
            .into_iter()
            .filter_map(|ch| channel_finding(ch, runs, parts, combined.as_ref())),
    );
    for r in runs {
        for b in &r.bands {
            if b.gain_error_db.abs() > 1.0 || b.phase_error_deg.abs() > 10.0 {
                out.push(GapFinding::Band {
                    run: r.run.clone(),
                    f_low: b.f_low,
                    f_high: b.f_high,
                    gain_error_db: b.gain_error_db,
                    phase_error_deg: b.phase_error_deg,
                });
            }
        }
    }
    // Bands left unsaid are counted, not dropped without a word.
    let quiet: Vec<usize> = runs.iter().map(|r| r.bands_without_steer).collect();
    let bands: usize = quiet.iter().sum();
    if bands > 0 {
        out.push(GapFinding::BandsWithoutSteer {
            bands,
            runs: quiet.iter().filter(|&&b| b > 0).count(),
        });
    }
    out
}

/// A channel of an observation.
pub fn observed_channel(o: &Observed, c: Channel) -> &[f64] {
    match c {
        Channel::YawRate => &o.yaw_rate,
        Channel::Ay => &o.ay,
        Channel::Beta => &o.beta,
    }
}

/// Each channel's steady offset in `findings` ([`GapFinding::Channel`]'s
/// `offset`): its mean residual, the second number of its row of the
/// shares ([`crate::diagnose::report::shares::error_rows`]).
pub(crate) fn steady_offsets(findings: &[GapFinding]) -> Vec<(Channel, f64)> {
    findings
        .iter()
        .filter_map(|f| match f {
            GapFinding::Channel {
                channel,
                offset: Some(o),
                ..
            } => Some((*channel, o.mean)),
            _ => None,
        })
        .collect()
}

/// The channel whose share of the base model's held-out error `J²`
/// exceeds [`DOMINANT_SHARE`], when more than one channel is measured,
/// with each channel's steady offset set aside: read of the shares
/// ([`ChannelShare::before_offsets_aside_percent`]), so that the report
/// gives one share per channel. An offset is one number a sensor bias
/// fits, not the floor the channel is trusted to, so a channel whose share
/// is its offset does not decide every fit (a logger's ay offset of
/// +0.6 m/s² carried 84 % of a sedan's error, 98 % of it the offset).
pub(crate) fn dominant(shares: &[ChannelShare]) -> Option<GapFinding> {
    if shares.len() < 2 {
        return None;
    }
    let less_offsets: Vec<Channel> = shares
        .iter()
        .filter(|s| s.offset_percent.is_some())
        .map(|s| s.channel)
        .collect();
    shares
        .iter()
        .find(|s| s.before_offsets_aside_percent > 100.0 * DOMINANT_SHARE)
        .map(|s| GapFinding::Dominant {
            channel: s.channel,
            share_percent: s.before_offsets_aside_percent,
            with_offsets_percent: s.before_percent,
            less_offsets,
        })
}

/// A channel carrying more than this share of the base's combined error
/// (its steady offset set aside) decides every fit: the report names it.
pub const DOMINANT_SHARE: f64 = 2.0 / 3.0;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::report::parts::Window;

    fn run(name: &str, samples: usize, before: f64) -> RunPart {
        RunPart {
            run: name.into(),
            samples,
            mean_level: None,
            before,
            after: before,
            bias_after: 0.0,
        }
    }

    /// Round 39: one run's yaw rate +0.02 rad/s sat 6.5 floors off before
    /// its input while the part, pooled, was within three. The runs above
    /// three floors of a part (ten samples or more) are found, largest
    /// first; at three floors exactly, or on nine samples, not.
    #[test]
    fn the_runs_off_in_a_part_are_found_largest_first() {
        let part = Part::Window(Window::BeforeInput);
        let p = Shrinkage {
            channel: Channel::YawRate,
            part,
            samples: 500,
            before: 0.005,
            after: 0.005,
            noise_floor: 0.003,
            reduction_percent: 0.0,
            mean_level: None,
            runs: vec![
                run("a.csv", 100, 0.0100),
                run("b.csv", 100, 0.0195),
                run("c.csv", 100, 0.0090),
                run("d.csv", 9, 0.0500),
                run("e.csv", 191, 0.0020),
            ],
        };
        let off = off_in(&p);
        let named: Vec<(&str, f64)> = off.iter().map(|o| (o.run.as_str(), o.rms)).collect();
        assert_eq!(named, [("b.csv", 0.0195), ("a.csv", 0.0100)]);
        assert!(off.iter().all(|o| o.part == part));
    }
}
