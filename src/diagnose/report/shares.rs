//! Each measured channel's share of the combined held-out error `J²`,
//! before the verdict (the base model) and with it, from one computation:
//! a channel's part of `J²` is `Σe²/s²`, the sum of its held-out squared
//! residuals (`n·rms²`) over the square of the scale the fits divide its
//! residuals by (its noise floor, the unit of `J`,
//! [`crate::diagnose::model::channels::ChannelErrors::combined`]), and its
//! share that part over the sum of all channels' parts. The sums are the
//! held-out errors the verdict reads (`J` before and after), so the
//! shares add up to the `J²` the report prints.
//!
//! A channel's steady offset (its runs' mean residual of one sign,
//! [`crate::diagnose::report::values::SteadyOffset`]) is a second number of
//! the same row: its part of `J²` is `n·mean²/s²` (at most the channel's
//! whole part), so the shares "with the offsets aside" are the same rows
//! less those parts, not a second sum. Whether a channel decides every fit
//! is judged with the offsets aside (an offset is one number a sensor bias
//! fits: [`crate::diagnose::report::summary::dominant`]). Shares in
//! percent.

use crate::diagnose::model::channels::{Channel, ChannelErrors};
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
    /// Its share of the base model's held-out `J²`, % (its steady offset
    /// counted).
    pub before_percent: f64,
    /// The part of the base model's held-out `J²` its steady offset
    /// carries, % of the whole `J²` (`null`: no steady offset).
    pub offset_percent: Option<f64>,
    /// Its share of the base model's held-out `J²` with every channel's
    /// steady offset set aside, %: `(before − offset)` over `100 − Σ
    /// offset` (equal to `before_percent` where no channel has one).
    pub before_offsets_aside_percent: f64,
    /// Its share of the held-out `J²` with the verdict's effects, % (`null`:
    /// no verdict).
    pub after_percent: Option<f64>,
}

/// One channel's row of the shares: its held-out samples, the sum of
/// their squared residuals and its scale (the unit of `J`), and its
/// steady offset's mean residual (None: no steady offset).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ErrorRow {
    pub(crate) channel: Channel,
    pub(crate) samples: usize,
    pub(crate) sum_sq: f64,
    pub(crate) scale: f64,
    pub(crate) offset_mean: Option<f64>,
}

impl ErrorRow {
    /// The channel's part of `J²` (times the samples of all channels).
    fn part(&self) -> f64 {
        self.sum_sq / (self.scale * self.scale)
    }

    /// The part of it its steady offset carries: `n·mean²/s²`, at most
    /// the whole part.
    fn offset_part(&self) -> Option<f64> {
        let m = self.offset_mean?;
        Some((self.samples as f64 * m * m / (self.scale * self.scale)).min(self.part()))
    }
}

/// The rows of every measured channel of held-out errors `e` at the fits'
/// `scales`, with each channel's steady offset mean from `offsets`.
pub(crate) fn error_rows(
    e: &ChannelErrors,
    scales: &[f64; 3],
    offsets: &[(Channel, f64)],
) -> Vec<ErrorRow> {
    Channel::ALL
        .into_iter()
        .filter(|c| e.count[c.index()] > 0 && scales[c.index()] > 0.0)
        .map(|c| ErrorRow {
            channel: c,
            samples: e.count[c.index()],
            sum_sq: e.sum_sq[c.index()],
            scale: scales[c.index()],
            offset_mean: offsets.iter().find(|o| o.0 == c).map(|o| o.1),
        })
        .collect()
}

/// The shares of every channel of the base model's rows `before` and,
/// with a verdict, of its rows `after` (the same channels and scales; no
/// offsets set aside there). Empty where the base's error is zero (or not
/// a number) or no channel is measured.
pub(crate) fn channel_shares(before: &[ErrorRow], after: Option<&[ErrorRow]>) -> Vec<ChannelShare> {
    let parts: Vec<f64> = before.iter().map(ErrorRow::part).collect();
    let total: f64 = parts.iter().sum();
    if total.is_nan() || total <= 0.0 {
        return Vec::new();
    }
    let offsets: Vec<Option<f64>> = before.iter().map(ErrorRow::offset_part).collect();
    let aside_total = total - offsets.iter().flatten().sum::<f64>();
    let after_total: Option<f64> = after
        .map(|a| a.iter().map(ErrorRow::part).sum::<f64>())
        .filter(|t| *t > 0.0);
    before
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let own = parts[i] - offsets[i].unwrap_or(0.0);
            ChannelShare {
                channel: r.channel,
                before_percent: 100.0 * parts[i] / total,
                offset_percent: offsets[i].map(|o| 100.0 * o / total),
                // Every part an offset: nothing left to share.
                before_offsets_aside_percent: if aside_total > 0.0 {
                    100.0 * own / aside_total
                } else {
                    0.0
                },
                after_percent: after_total.and_then(|t| {
                    let a = after?.iter().find(|a| a.channel == r.channel)?;
                    Some(100.0 * a.part() / t)
                }),
            }
        })
        .collect()
}

/// The steady offsets of `channels` in words, and the pronoun that takes
/// them up: "ay's steady offset", "it"; "the steady offsets of ay and
/// beta", "them".
pub fn offsets_named(channels: &[Channel]) -> (String, &'static str) {
    match channels {
        [c] => (format!("{}'s steady offset", c.name()), "it"),
        _ => {
            let names: Vec<&str> = channels.iter().map(|c| c.name()).collect();
            (
                format!("the steady offsets of {}", names.join(" and ")),
                "them",
            )
        }
    }
}

/// The line that says one channel carries more than [`CARRIES_SHARE`] of
/// the combined error, before the verdict (offsets counted or aside) or
/// with it, naming it and its share beside the others' (None: no channel
/// does, or only one channel is measured). Where a channel has a steady
/// offset the base's shares are said with the offsets aside, the shares
/// with them counted in the same clause.
pub fn carries_line(shares: &[ChannelShare]) -> Option<String> {
    if shares.len() < 2 {
        return None;
    }
    let of = |f: fn(&ChannelShare) -> f64| -> Vec<(Channel, f64)> {
        shares.iter().map(|s| (s.channel, f(s))).collect()
    };
    let (before, aside) = (
        of(|s| s.before_percent),
        of(|s| s.before_offsets_aside_percent),
    );
    let after: Option<Vec<(Channel, f64)>> = shares
        .iter()
        .map(|s| s.after_percent.map(|p| (s.channel, p)))
        .collect();
    let carries = |v: &[(Channel, f64)]| v.iter().any(|p| p.1 > 100.0 * CARRIES_SHARE);
    if !carries(&before) && !carries(&aside) && !after.as_deref().is_some_and(carries) {
        return None;
    }
    let offsets: Vec<Channel> = shares
        .iter()
        .filter(|s| s.offset_percent.is_some())
        .map(|s| s.channel)
        .collect();
    let base = if offsets.is_empty() {
        phase(&before, "the base model's")
    } else {
        let (named, pronoun) = offsets_named(&offsets);
        format!(
            "{}, with {named} aside ({} with {pronoun})",
            phase(&aside, "the base model's"),
            list(&before)
        )
    };
    let mut said = format!(
        "combined error by channel (each channel's held-out samples over its noise floor): {base}"
    );
    if let Some(a) = &after {
        said.push_str(&format!("; {}", phase(a, "the verdict's")));
    }
    Some(said)
}

/// Channels and their shares, largest first: "ay 60 %, yaw_rate 38 %".
fn list(v: &[(Channel, f64)]) -> String {
    let mut v = v.to_vec();
    v.sort_by(|a, b| b.1.total_cmp(&a.1));
    v.iter()
        .map(|(c, p)| format!("{} {p:.0} %", c.name()))
        .collect::<Vec<_>>()
        .join(", ")
}

/// One model's shares in words: the channel that carries more than
/// [`CARRIES_SHARE`] named first, with what it means.
fn phase(v: &[(Channel, f64)], whose: &str) -> String {
    let mut v = v.to_vec();
    v.sort_by(|a, b| b.1.total_cmp(&a.1));
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

    fn row(channel: Channel, samples: usize, rms: f64, scale: f64) -> ErrorRow {
        ErrorRow {
            channel,
            samples,
            sum_sq: samples as f64 * rms * rms,
            scale,
            offset_mean: None,
        }
    }

    /// The sedan's noise floors: ay at 12.8, beta 3.2, yaw rate 2.4 floors
    /// on equal samples give ay 12.8²/(12.8² + 3.2² + 2.4²) = 91.1 %.
    #[test]
    fn shares_are_each_channels_part_of_j_squared() {
        let before = [
            row(Channel::YawRate, 100, 2.4 * 0.002, 0.002),
            row(Channel::Ay, 100, 12.8 * 0.05, 0.05),
            row(Channel::Beta, 100, 3.2 * 0.005, 0.005),
        ];
        let after = [
            row(Channel::YawRate, 100, 1.2 * 0.002, 0.002),
            row(Channel::Ay, 100, 1.2 * 0.05, 0.05),
            row(Channel::Beta, 100, 0.0, 0.005),
        ];
        let s = channel_shares(&before, Some(&after));
        let total = 12.8f64.powi(2) + 3.2f64.powi(2) + 2.4f64.powi(2);
        assert!((s[1].before_percent - 100.0 * 12.8f64.powi(2) / total).abs() < 1e-9);
        assert!((s[1].before_percent - 91.1).abs() < 0.05);
        // No offset: aside is counted.
        assert_eq!(s[1].before_offsets_aside_percent, s[1].before_percent);
        assert_eq!(s[1].offset_percent, None);
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
        let before = [
            row(Channel::YawRate, 1000, 2.4 * 0.002, 0.002),
            row(Channel::Ay, 10, 2.4 * 0.05, 0.05),
        ];
        let s = channel_shares(&before, None);
        assert_eq!(s[0].after_percent, None);
        assert!((s[0].before_percent - 100.0 * 1000.0 / 1010.0).abs() < 1e-9);
        assert!(carries_line(&s).unwrap().contains("yaw_rate 99 %"));
        // Balanced channels: no line.
        let before = [
            row(Channel::YawRate, 10, 0.002, 0.002),
            row(Channel::Ay, 10, 0.05, 0.05),
        ];
        assert_eq!(carries_line(&channel_shares(&before, None)), None);
    }

    /// Two channels in closed form: the yaw rate's 400 samples at RMS
    /// 0.006 rad/s over its scale 0.002 (3 floors: part 400·9 = 3600), ay's
    /// 200 samples at RMS 0.5 m/s² over 0.05 (10 floors: part 200·100 =
    /// 20000) of which a steady offset of mean −0.35 m/s² carries
    /// 200·(0.35/0.05)² = 9800. Counted: ay 20000/23600 = 84.746 %, the
    /// yaw rate 15.254 %; the offset 9800/23600 = 41.525 % of `J²`; aside:
    /// the yaw rate 3600/13800 = 26.087 %, ay 10200/13800 = 73.913 %.
    #[test]
    fn a_steady_offset_is_a_second_number_of_the_same_rows() {
        let mut ay = row(Channel::Ay, 200, 0.5, 0.05);
        ay.offset_mean = Some(-0.35);
        let before = [row(Channel::YawRate, 400, 0.006, 0.002), ay];
        let s = channel_shares(&before, None);
        let close = |a: f64, b: f64| (a - b).abs() < 1e-9;
        assert!(close(s[1].before_percent, 100.0 * 20000.0 / 23600.0));
        assert!(close(s[0].before_percent, 100.0 * 3600.0 / 23600.0));
        assert!(close(
            s[1].offset_percent.unwrap(),
            100.0 * 9800.0 / 23600.0
        ));
        assert_eq!(s[0].offset_percent, None);
        assert!(close(
            s[0].before_offsets_aside_percent,
            100.0 * 3600.0 / 13800.0
        ));
        assert!(close(
            s[1].before_offsets_aside_percent,
            100.0 * 10200.0 / 13800.0
        ));
        // Derived from the same numbers: (before − offset)/(100 − Σ offset).
        let o = s[1].offset_percent.unwrap();
        assert!(close(
            s[1].before_offsets_aside_percent,
            100.0 * (s[1].before_percent - o) / (100.0 - o)
        ));
        // Both said in one clause.
        let line = carries_line(&s).unwrap();
        assert!(
            line.contains("ay 74 % of the base model's J² (yaw_rate 26 %), more than two thirds, with ay's steady offset aside (ay 85 %, yaw_rate 15 % with it)"),
            "{line}"
        );
        // An offset larger than the whole part carries the whole part.
        let mut ay = row(Channel::Ay, 200, 0.5, 0.05);
        ay.offset_mean = Some(0.9);
        let s = channel_shares(&[row(Channel::YawRate, 400, 0.006, 0.002), ay], None);
        assert!(close(s[1].offset_percent.unwrap(), s[1].before_percent));
        assert!(close(s[0].before_offsets_aside_percent, 100.0));
    }

    /// The rows of held-out errors: unmeasured channels left out, each
    /// measured one with its samples, sum and scale, its offset found.
    #[test]
    fn rows_are_read_from_the_held_out_errors() {
        let e = ChannelErrors {
            sum_sq: [0.1, 0.0, 0.3],
            count: [10, 0, 30],
        };
        let rows = error_rows(&e, &[0.002, 0.05, 0.005], &[(Channel::Beta, 0.01)]);
        assert_eq!(rows.len(), 2);
        assert_eq!((rows[0].channel, rows[0].samples), (Channel::YawRate, 10));
        assert_eq!(rows[0].offset_mean, None);
        assert_eq!((rows[1].channel, rows[1].sum_sq), (Channel::Beta, 0.3));
        assert_eq!((rows[1].scale, rows[1].offset_mean), (0.005, Some(0.01)));
    }
}
