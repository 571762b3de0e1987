//! Which runs hold what a verdict's effects leave above noise
//! ([`RunsCarrying`]), by the held-out error's own measure: the combined
//! error `J² = Σ_r Σ_c n_rc·rms_rc²/s_c² / N` (every run's samples of every
//! channel over the channel's scale, [`crate::diagnose::model::channels::ChannelErrors::combined`])
//! less the noise level's `J_n²` is the gap above noise `G²` whose share
//! the verdict says it leaves; it splits over the runs exactly, a run's
//! part `Σ_c n_rc·(rms_rc²/s_c² − J_n²)`. Without it a gap left that no
//! channel carries was "a further cause (an effect outside the library,
//! or the base model's own form)" while one run with its steer ×1.25 held
//! most of it (round 39).
//!
//! Units: RMS values and scales in each channel's unit, `J`
//! dimensionless, shares in percent.

use crate::diagnose::report::outcome::{RunShare, RunsCarrying};
use crate::diagnose::report::summary::DOMINANT_SHARE;
use crate::diagnose::report::{ChannelNoise, Part, Shrinkage};

/// Two runs are said together only of this many runs or more: of two or
/// three, two runs holding most is no run singled out.
const PAIR_OF_AT_LEAST: usize = 4;

/// One run's sums over the channels: `Σ n·rms²/s²` and `Σ n`.
struct RunSum {
    run: String,
    weighted: f64,
    samples: usize,
}

/// How the runs of the all-samples rows of `parts` (the verdict's held-out
/// RMS `after`) hold the gap above the noise level `noise_level`, each
/// channel over its fits' scale in `noise`. None with fewer than two runs,
/// a channel without its scale, or no part above noise to split.
pub(crate) fn runs_carrying(
    parts: &[Shrinkage],
    noise: &[ChannelNoise],
    noise_level: f64,
) -> Option<RunsCarrying> {
    let mut sums: Vec<RunSum> = Vec::new();
    for row in parts.iter().filter(|p| p.part == Part::All) {
        let scale = noise.iter().find(|n| n.channel == row.channel)?.scale;
        if scale.is_nan() || scale <= 0.0 {
            return None;
        }
        for r in &row.runs {
            let w = r.samples as f64 * (r.after / scale).powi(2);
            match sums.iter_mut().find(|s| s.run == r.run) {
                Some(s) => {
                    s.weighted += w;
                    s.samples += r.samples;
                }
                None => sums.push(RunSum {
                    run: r.run.clone(),
                    weighted: w,
                    samples: r.samples,
                }),
            };
        }
    }
    let jn2 = noise_level * noise_level;
    // A run below the noise level holds none of the gap above it.
    let part = |s: &RunSum| (s.weighted - s.samples as f64 * jn2).max(0.0);
    let total: f64 = sums.iter().map(part).sum();
    if sums.len() < 2 || !total.is_finite() || total <= 0.0 {
        return None;
    }
    let mut shares: Vec<RunShare> = sums
        .iter()
        .map(|s| RunShare {
            run: s.run.clone(),
            share_percent: 100.0 * part(s) / total,
            heldout_error: (s.weighted / s.samples.max(1) as f64).sqrt(),
            scale_apart: None,
        })
        .collect();
    shares.sort_by(|a, b| b.share_percent.total_cmp(&a.share_percent));
    let most = 100.0 * DOMINANT_SHARE;
    let taken = if shares[0].share_percent > most {
        1
    } else if shares.len() >= PAIR_OF_AT_LEAST
        && shares[0].share_percent + shares[1].share_percent > most
    {
        2
    } else {
        0
    };
    let above_noise = sums.iter().filter(|s| part(s) > 0.0).count();
    let largest = (taken == 0).then(|| shares[0].clone());
    shares.truncate(taken);
    Some(RunsCarrying {
        carried_by: shares,
        above_noise,
        runs: sums.len(),
        largest,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::model::channels::Channel;
    use crate::diagnose::model::scale::ScaleSource;
    use crate::diagnose::report::RunPart;

    fn noise(channel: Channel, scale: f64) -> ChannelNoise {
        ChannelNoise {
            channel,
            unit: channel.unit(),
            noise_floor: scale,
            scale,
            source: ScaleSource::Scatter,
            scatter: scale,
            runs: 4,
            other_side: 0,
            stated_excess: None,
        }
    }

    fn row(channel: Channel, part: Part, runs: &[(&str, usize, f64)]) -> Shrinkage {
        Shrinkage {
            channel,
            part,
            samples: runs.iter().map(|r| r.1).sum(),
            before: 0.0,
            after: 0.0,
            noise_floor: 0.0,
            reduction_percent: 0.0,
            mean_level: None,
            runs: runs
                .iter()
                .map(|&(run, samples, after)| RunPart {
                    run: run.into(),
                    samples,
                    mean_level: None,
                    before: after,
                    after,
                    bias_after: 0.0,
                })
                .collect(),
        }
    }

    /// Two channels, four runs of 100 samples per channel, scales 0.002
    /// rad/s and 0.05 m/s², noise level 1: run `a` at 3 floors in both
    /// channels has the part 100·(9 − 1)·2 = 1600, `b`, `c` at 1.5 floors
    /// 100·(2.25 − 1)·2 = 250 each, `d` at 0.5 floors none. `a` holds
    /// 1600/2100 = 76.19 %, beyond two thirds, and is named alone with its
    /// own J = 3; a window row is no part of the split.
    #[test]
    fn the_run_holding_most_of_the_gap_left_is_named_in_closed_form() {
        let runs = |s: f64| {
            [
                ("a", 100, 3.0 * s),
                ("b", 100, 1.5 * s),
                ("c", 100, 1.5 * s),
                ("d", 100, 0.5 * s),
            ]
        };
        let parts = [
            row(Channel::YawRate, Part::All, &runs(0.002)),
            row(Channel::Ay, Part::All, &runs(0.05)),
            row(
                Channel::Ay,
                Part::Window(crate::diagnose::report::parts::Window::BeforeInput),
                &[("b", 50, 1.0)],
            ),
        ];
        let n = [noise(Channel::YawRate, 0.002), noise(Channel::Ay, 0.05)];
        let r = runs_carrying(&parts, &n, 1.0).unwrap();
        assert_eq!(r.carried_by.len(), 1, "{r:?}");
        assert_eq!(r.carried_by[0].run, "a");
        assert!((r.carried_by[0].share_percent - 100.0 * 1600.0 / 2100.0).abs() < 1e-9);
        assert!((r.carried_by[0].heldout_error - 3.0).abs() < 1e-12);
        assert_eq!((r.above_noise, r.runs, r.largest), (3, 4, None));
        // The shares sum to the whole: N·(J² − J_n²) over the runs above.
        // At noise level 1.4 (J_n² = 1.96) `b` and `c` hold 100·0.29·2 = 58
        // each against `a`'s 100·7.04·2 = 1408: 1408/1524 = 92.39 %.
        let r = runs_carrying(&parts, &n, 1.4).unwrap();
        assert!((r.carried_by[0].share_percent - 100.0 * 1408.0 / 1524.0).abs() < 1e-9);
    }

    /// Two runs at 3 floors and two at 1.5: each of the two holds 800/1850
    /// = 43.2 %, together 86.5 %: both named; of three runs a pair is not.
    /// Four runs alike: spread, the largest said, every run above noise.
    #[test]
    fn two_runs_together_or_none_spread_over_the_runs() {
        let n = [noise(Channel::YawRate, 0.002)];
        let of = |runs: &[(&str, usize, f64)]| {
            runs_carrying(&[row(Channel::YawRate, Part::All, runs)], &n, 1.0).unwrap()
        };
        let r = of(&[
            ("a", 100, 0.006),
            ("b", 100, 0.006),
            ("c", 100, 0.003),
            ("d", 100, 0.003),
        ]);
        let named: Vec<&str> = r.carried_by.iter().map(|s| s.run.as_str()).collect();
        assert_eq!(named, ["a", "b"]);
        assert!((r.carried_by[1].share_percent - 100.0 * 800.0 / 1850.0).abs() < 1e-9);
        let r = of(&[("a", 100, 0.006), ("b", 100, 0.006), ("c", 100, 0.003)]);
        assert!(r.carried_by.is_empty(), "{r:?}");
        let r = of(&[
            ("a", 100, 0.006),
            ("b", 100, 0.006),
            ("c", 100, 0.006),
            ("d", 100, 0.006),
        ]);
        assert!(r.carried_by.is_empty(), "{r:?}");
        assert_eq!(r.above_noise, 4);
        assert!((r.largest.unwrap().share_percent - 25.0).abs() < 1e-9);
        // Nothing above noise, one run, a channel without its scale: none.
        assert_eq!(
            runs_carrying(
                &[row(
                    Channel::YawRate,
                    Part::All,
                    &[("a", 10, 0.001), ("b", 10, 0.001)]
                )],
                &n,
                1.0
            ),
            None
        );
        assert_eq!(
            runs_carrying(
                &[row(Channel::YawRate, Part::All, &[("a", 10, 0.01)])],
                &n,
                1.0
            ),
            None
        );
        assert_eq!(
            runs_carrying(
                &[row(
                    Channel::Beta,
                    Part::All,
                    &[("a", 10, 0.01), ("b", 10, 0.1)]
                )],
                &n,
                1.0
            ),
            None
        );
    }
}
