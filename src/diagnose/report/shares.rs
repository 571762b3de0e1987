//! Each measured channel's share of the combined held-out error `J²`,
//! before the verdict (the base model) and with it: `n_c·(rms_c/s_c)²`
//! over `Σ n_c·(rms_c/s_c)²`, the channel's samples, held-out RMS and the
//! scale the fits divide its residuals by (its noise floor, the unit of
//! `J`, [`crate::diagnose::model::channels::ChannelErrors::combined`]).
//! Unlike [`crate::diagnose::report::summary::dominant`], a channel's
//! steady offset is counted here: this is the error each fit minimises,
//! as it is. Whether a channel decides every fit is `dominant`'s to say,
//! with the offset aside (one number a sensor bias fits), so the line
//! here gives the shares without that judgement. Shares in percent.

use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::{ChannelNoise, Part, Shrinkage};
use serde::Serialize;

/// A channel carrying more than this share of `J²` has its shares said
/// (the same two thirds as
/// [`crate::diagnose::report::summary::DOMINANT_SHARE`]).
pub const CARRIES_SHARE: f64 = 2.0 / 3.0;

/// One channel's share of the combined held-out error.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChannelShare {
    /// The channel.
    pub channel: Channel,
    /// Its share of the base model's held-out `J²`, %.
    pub before_percent: f64,
    /// Its share of the held-out `J²` with the verdict's effects, % (`null`:
    /// no verdict).
    pub after_percent: Option<f64>,
}

/// The shares of every measured channel, from the all-samples rows of
/// `parts` and the scales of `noise`; `verdict`: the rows' `after` is a
/// verdict's (without one it equals `before` and is not a share to give).
/// Empty where the error is zero or no channel is measured.
pub fn channel_shares(
    parts: &[Shrinkage],
    noise: &[ChannelNoise],
    verdict: bool,
) -> Vec<ChannelShare> {
    let rows: Vec<(&Shrinkage, f64)> = parts
        .iter()
        .filter(|s| s.part == Part::All && s.samples > 0)
        .filter_map(|s| {
            let scale = noise.iter().find(|n| n.channel == s.channel)?.scale;
            (scale > 0.0).then_some((s, scale))
        })
        .collect();
    let weight = |rms: f64, s: &Shrinkage, scale: f64| s.samples as f64 * (rms / scale).powi(2);
    let before: Vec<f64> = rows.iter().map(|(s, k)| weight(s.before, s, *k)).collect();
    let after: Vec<f64> = rows.iter().map(|(s, k)| weight(s.after, s, *k)).collect();
    let (tb, ta) = (before.iter().sum::<f64>(), after.iter().sum::<f64>());
    // A zero (or NaN) total leaves no share to give.
    if tb.is_nan() || tb <= 0.0 {
        return Vec::new();
    }
    rows.iter()
        .enumerate()
        .map(|(i, (s, _))| ChannelShare {
            channel: s.channel,
            before_percent: 100.0 * before[i] / tb,
            after_percent: (verdict && ta > 0.0).then(|| 100.0 * after[i] / ta),
        })
        .collect()
}

/// The line that says one channel carries more than [`CARRIES_SHARE`] of
/// the combined error, before the verdict or with it, naming it and its
/// share beside the others' (None: no channel does, or only one channel is
/// measured).
pub fn carries_line(shares: &[ChannelShare]) -> Option<String> {
    if shares.len() < 2 {
        return None;
    }
    let before: Vec<(Channel, f64)> = shares
        .iter()
        .map(|s| (s.channel, s.before_percent))
        .collect();
    let after: Option<Vec<(Channel, f64)>> = shares
        .iter()
        .map(|s| s.after_percent.map(|p| (s.channel, p)))
        .collect();
    let carries = |v: &[(Channel, f64)]| v.iter().any(|p| p.1 > 100.0 * CARRIES_SHARE);
    if !carries(&before) && !after.as_deref().is_some_and(carries) {
        return None;
    }
    let mut said = format!(
        "combined error by channel (each channel's held-out samples over its noise floor, its steady offset counted: whether a channel decides every fit is judged with its offset aside): {}",
        phase(&before, "the base model's")
    );
    if let Some(a) = &after {
        said.push_str(&format!("; {}", phase(a, "the verdict's")));
    }
    Some(said)
}

/// One model's shares in words: the channel that carries more than
/// [`CARRIES_SHARE`] named first, with what it means.
fn phase(v: &[(Channel, f64)], whose: &str) -> String {
    let mut v = v.to_vec();
    v.sort_by(|a, b| b.1.total_cmp(&a.1));
    let list = |v: &[(Channel, f64)]| {
        v.iter()
            .map(|(c, p)| format!("{} {p:.0} %", c.name()))
            .collect::<Vec<_>>()
            .join(", ")
    };
    match v.split_first() {
        Some(((c, p), rest)) if *p > 100.0 * CARRIES_SHARE => format!(
            "{} {p:.0} % of {whose} J² ({}), more than two thirds",
            c.name(),
            list(rest)
        ),
        _ => format!("no channel above two thirds of {whose} J² ({})", list(&v)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::report::ScaleSource;

    fn row(channel: Channel, samples: usize, before: f64, after: f64) -> Shrinkage {
        Shrinkage {
            channel,
            part: Part::All,
            samples,
            before,
            after,
            noise_floor: 1.0,
            reduction_percent: 0.0,
            mean_level: None,
            runs: Vec::new(),
        }
    }

    fn noise(channel: Channel, scale: f64) -> ChannelNoise {
        ChannelNoise {
            channel,
            unit: channel.unit(),
            noise_floor: scale,
            scale,
            source: ScaleSource::Stated,
            scatter: scale,
            runs: 1,
            other_side: 0,
            stated_excess: None,
        }
    }

    /// The sedan's noise floors: ay at 12.8, beta 3.2, yaw rate 2.4 floors
    /// on equal samples give ay 12.8²/(12.8² + 3.2² + 2.4²) = 91.1 %.
    #[test]
    fn shares_are_each_channels_part_of_j_squared() {
        let parts = [
            row(Channel::YawRate, 100, 2.4 * 0.002, 1.2 * 0.002),
            row(Channel::Ay, 100, 12.8 * 0.05, 1.2 * 0.05),
            row(Channel::Beta, 100, 3.2 * 0.005, 0.0),
        ];
        let noise = [
            noise(Channel::YawRate, 0.002),
            noise(Channel::Ay, 0.05),
            noise(Channel::Beta, 0.005),
        ];
        let s = channel_shares(&parts, &noise, true);
        let total = 12.8f64.powi(2) + 3.2f64.powi(2) + 2.4f64.powi(2);
        assert!((s[1].before_percent - 100.0 * 12.8f64.powi(2) / total).abs() < 1e-9);
        assert!((s[1].before_percent - 91.1).abs() < 0.05);
        // After: yaw rate and ay at 1.2 floors each, beta 0: half each.
        assert!((s[0].after_percent.unwrap() - 50.0).abs() < 1e-9);
        let sum: f64 = s.iter().map(|x| x.before_percent).sum();
        assert!((sum - 100.0).abs() < 1e-9);
        let line = carries_line(&s).unwrap();
        assert!(line.contains("ay 91 % of the base model's J²"), "{line}");
        assert!(
            line.contains("no channel above two thirds of the verdict's J²"),
            "{line}"
        );
        // Without a verdict no after share, and samples weigh: ten times
        // the yaw-rate samples at 2.4 floors outweigh ay's.
        let parts = [
            row(Channel::YawRate, 1000, 2.4 * 0.002, 0.0),
            row(Channel::Ay, 10, 2.4 * 0.05, 0.0),
        ];
        let s = channel_shares(&parts, &noise, false);
        assert_eq!(s[0].after_percent, None);
        assert!((s[0].before_percent - 100.0 * 1000.0 / 1010.0).abs() < 1e-9);
        assert!(carries_line(&s).unwrap().contains("yaw_rate 99 %"));
        // Balanced channels: no line.
        let parts = [
            row(Channel::YawRate, 10, 0.002, 0.0),
            row(Channel::Ay, 10, 0.05, 0.0),
        ];
        assert_eq!(carries_line(&channel_shares(&parts, &noise, false)), None);
    }
}
