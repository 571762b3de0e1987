//! Sensor offsets from a log's standstills and straights, measured on the
//! raw runs before the cleaning ([`super::clean`]) excludes the slow
//! samples.
//!
//! **Why.** A body-fixed accelerometer reads the specific force, so on a
//! road banked by θ (`FORMATS.md`: positive with the left edge higher) its
//! lateral channel reads `a_y = u·r + v̇ + g·sin θ + b_ay` (ISO 8855; the
//! same sign as the model's: the accelerometer, the tyres' force over the
//! mass, reads `g·sin θ` more than the path's acceleration), and a gyro
//! reads `r + b_r`. Parked, `u = r = v̇ = 0`: the means are the offsets
//! `b_r` and `b_ay + g·sin θ` (the static bias estimation of inertial
//! sensors, and the zero-velocity and zero-angular-rate updates of a
//! navigation filter while stationary: Groves 2013, *Principles of GNSS,
//! Inertial, and Multisensor Integrated Navigation Systems*). Driving
//! straight at a steady speed, `r ≈ 0`, `v̇ ≈ 0` and a road vehicle's
//! lateral velocity is nearly zero (the non-holonomic constraint of land
//! vehicles' inertial navigation, Dissanayake et al. 2001; Groves 2013),
//! so the means of yaw rate, `a_y − g·sin θ` and sideslip are their
//! offsets too. Sideslip is undefined at a standstill (no velocity) and is
//! measured on straights only.
//!
//! **Standstills.** The speed's centred running median over
//! [`MEDIAN_WINDOW`] below [`STANDSTILL_SPEED`]; [`STANDSTILL_TRIM`] cut
//! from each end (the body still rocks on its springs after a stop, and
//! the car creeps before it drives off); at least [`STANDSTILL_SECONDS`]
//! left.
//!
//! **Straights.** On the same running medians, every sample: speed at
//! least [`STRAIGHT_SPEED`]; yaw rate within [`STRAIGHT_YAW_RATE`] of the
//! standstills' pooled yaw-rate offset (0 without one: a gyro offset larger
//! than the band would hide the straights); the path's lateral
//! acceleration `u·(r − r₀)` within [`STRAIGHT_LATERAL`]; `|ay|` (less a
//! logged bank's `g·sin θ`) within [`STRAIGHT_AY`], so that the straights
//! are straight by a channel a yaw rate in the wrong unit does not move
//! (a steady turn read with a yaw rate 57× too small passed the yaw
//! tests); steer within
//! [`STRAIGHT_STEER`] of the run's straight-line steer (the median steer
//! of its samples that pass the speed, yaw and `ay` tests, which carries the
//! steer sensor's own offset); `|ax|` within [`STRAIGHT_AX`] (without an
//! `ax` column, the running median's slope across one window). Stretches that pass, cut by [`STRAIGHT_TRIM`] at each end (the
//! corner's exit and the next one's entry) and at least
//! [`STRAIGHT_SECONDS`] long, are candidates; a candidate whose yaw rate's
//! running median has a standard deviation above
//! [`STRAIGHT_YAW_VARIATION`] (weaving) or whose speed changes by more than
//! [`STRAIGHT_SPEED_VARIATION`] of its mean is refused, and listed with the
//! reason. So is a candidate whose raw steer or yaw rate swings: the
//! running medians hide a swing as fast as their window (a 1 Hz slalom's
//! 1 s medians are near 0), so the raw samples' RMS about the straight-line
//! steer and about the yaw reference, with the channel's white noise
//! (estimated from successive differences) taken out in quadrature, must
//! stay within the same [`STRAIGHT_STEER`] and [`STRAIGHT_YAW_RATE`].
//!
//! **Means.** Per span and channel: masked samples and glitches (beyond
//! five robust deviations of the span's median) left out, the mean of the
//! rest, its standard error from the effective sample count of
//! autocorrelated samples, the samples; for `ay` with a `bank` column,
//! `g·sin(bank)` removed sample by sample (`stats.rs` has the rules). Per
//! channel and kind the spans are pooled (a random-effects mean: weights
//! `1/(s² + τ²)`, DerSimonian & Laird 1986) and tested for agreement: spans that disagree are a
//! drifting offset (temperature, a sensor knocked on its mount), reported
//! as such. The straights' offset is compared with the standstills': they
//! agree within [`AGREEMENT_SIGMAS`] standard errors of the difference.
//!
//! **Limits.** A straight's means also hold what the criteria let through:
//! a crosswind or a road's crown (a sideslip and a lateral force with no
//! yaw: 2 % of crown reads 0.2 m/s² in `a_y`), an unlogged bank, the path's
//! residual curvature (within [`STRAIGHT_LATERAL`]) and, on `a_y`, the body
//! roll of a car leaning on its springs. A standstill's means hold the
//! accelerometer's tilt on an unlogged slope and the body's static roll (a
//! parked car on a bank leans a little on its springs), and the gyro's
//! mean the Earth's rate (up to 7.3e-5 rad/s, below automotive gyros'
//! resolution). Straights and standstills that differ say so; which is
//! right the report cannot tell.
//!
//! Units: SI, rad, times in s. Layout: this file holds the criteria and
//! [`calibrate`]; `spans.rs` finds the spans, `stats.rs` measures and pools
//! them, `bank.rs` checks a logged bank against the standstills' `a_y`
//! (as logged, not acting, reversed), `report.rs` holds the report and its
//! lines, `roll.rs` levels `a_y` by a logged body roll (its own offset
//! from the standstills), `sensor.rs` says a straights' `a_y` offset beyond
//! an accelerometer's bias.

mod bank;
mod report;
pub mod roll;
mod sensor;
mod spans;
pub(crate) mod stats;
#[cfg(test)]
mod tests;

pub use bank::{BankCheck, BankSeen, PLAUSIBLE_AY_OFFSET};
pub use report::{
    Agreement, BankedStraights, CalibrationReport, CalibrationSpan, ChannelCalibration,
    ChannelMean, Criteria, Offset, Pooled, RejectedStraight, Rejection, SpanKind,
};
pub use sensor::MEMS_AY_BIAS;

use super::clean::RunChannel;
use super::MeasuredRun;
use crate::constants::G;
use stats::{mean_estimate, pool};

/// Width of the centred running medians every criterion is applied to, s.
pub const MEDIAN_WINDOW: f64 = 1.0;
/// Standstill: speed below this, m/s (stricter than the cleaning's 0.5 m/s:
/// creeping at 0.5 m/s on a 5 m radius turns at 0.1 rad/s).
pub const STANDSTILL_SPEED: f64 = 0.2;
/// Cut from each end of a standstill, s.
pub const STANDSTILL_TRIM: f64 = 1.0;
/// Shortest standstill after the cut, s.
pub const STANDSTILL_SECONDS: f64 = 3.0;
/// Straight: lowest speed, m/s (the diagnosis's default lowest speed).
pub const STRAIGHT_SPEED: f64 = 5.0;
/// Straight: largest yaw rate from the reference, rad/s (a radius of 1 km
/// at 10 m/s).
pub const STRAIGHT_YAW_RATE: f64 = 0.01;
/// Straight: largest lateral acceleration of the path, m/s² (0.02 g).
pub const STRAIGHT_LATERAL: f64 = 0.2;
/// Straight: largest |ay| (less a logged bank's `g·sin θ`), m/s²: the
/// accelerometer is a witness the yaw rate's unit does not move, and an
/// offset beyond [`PLAUSIBLE_AY_OFFSET`] is no mounted sensor's (a steady
/// 2 m/s² turn whose yaw rate was read 57× too small was taken for a
/// straight).
pub const STRAIGHT_AY: f64 = PLAUSIBLE_AY_OFFSET;
/// Straight: largest steer from the straight-line steer, rad (0.3°, about
/// 5° at a steering wheel over a 16:1 ratio).
pub const STRAIGHT_STEER: f64 = 0.005;
/// Straight: largest |ax| (or |du/dt| without `ax`), m/s².
pub const STRAIGHT_AX: f64 = 0.5;
/// Straight: largest standard deviation of the yaw rate's running median,
/// rad/s (a driver's corrections on a straight: ±0.006 rad/s in a racing
/// car's pit lane at 9 m/s, a standard deviation of 0.0032).
pub const STRAIGHT_YAW_VARIATION: f64 = 0.004;
/// Straight: largest speed change, share of its mean.
pub const STRAIGHT_SPEED_VARIATION: f64 = 0.1;
/// Cut from each end of a straight, s.
pub const STRAIGHT_TRIM: f64 = 0.5;
/// Shortest straight after the cut, s.
pub const STRAIGHT_SECONDS: f64 = 3.0;
/// Standard errors within which straights and standstills agree.
pub const AGREEMENT_SIGMAS: f64 = 3.0;
/// Straight: largest |logged bank| (the span's mean) on which its sideslip
/// is taken for an offset, rad (0.5°). Driving straight on a bank θ the
/// tyres hold the car up the slope with a lateral force `m·g·sin θ`, so
/// the car crabs: `β ≈ −sin θ/k_r` at the rear axle's cornering
/// coefficient `k_r` (per unit load; 20 1/rad and 10° give 0.0087 rad,
/// the size of a sensor offset). At 0.5° and the road tyres' lowest 8
/// 1/rad that is 0.0011 rad, about a sideslip sensor's noise.
pub const STRAIGHT_BETA_BANK: f64 = 0.008727;

/// The criteria, as the report states them.
pub const CRITERIA: Criteria = Criteria {
    median_window: MEDIAN_WINDOW,
    standstill_speed: STANDSTILL_SPEED,
    standstill_trim: STANDSTILL_TRIM,
    standstill_seconds: STANDSTILL_SECONDS,
    straight_speed: STRAIGHT_SPEED,
    straight_yaw_rate: STRAIGHT_YAW_RATE,
    straight_lateral: STRAIGHT_LATERAL,
    straight_ay: STRAIGHT_AY,
    straight_steer: STRAIGHT_STEER,
    straight_ax: STRAIGHT_AX,
    straight_yaw_variation: STRAIGHT_YAW_VARIATION,
    straight_speed_variation: STRAIGHT_SPEED_VARIATION,
    straight_trim: STRAIGHT_TRIM,
    straight_seconds: STRAIGHT_SECONDS,
    straight_beta_bank: STRAIGHT_BETA_BANK,
    outlier_mads: stats::OUTLIER_MADS,
    agreement_quantile: stats::AGREEMENT_QUANTILE,
    agreement_sigmas: AGREEMENT_SIGMAS,
};

/// The response channels, in report order.
const CHANNELS: [RunChannel; 3] = [RunChannel::YawRate, RunChannel::Ay, RunChannel::Beta];

/// A channel's unit.
fn unit(channel: RunChannel) -> &'static str {
    match channel {
        RunChannel::YawRate => "rad/s",
        RunChannel::Ay => "m/s²",
        RunChannel::T => "s",
        RunChannel::Speed => "m/s",
        RunChannel::Steer | RunChannel::Beta => "rad",
    }
}

/// The values of a response channel of `run`.
fn values(run: &MeasuredRun, channel: RunChannel) -> Option<&Vec<f64>> {
    match channel {
        RunChannel::YawRate => Some(&run.yaw_rate),
        RunChannel::Ay => run.ay.as_ref(),
        RunChannel::Beta => run.beta.as_ref(),
        _ => None,
    }
}

/// The sensor offsets the standstills and straights of `runs` show. The
/// runs are taken as read (raw: before any cleaning).
pub fn calibrate(runs: &[MeasuredRun]) -> CalibrationReport {
    let c = CRITERIA;
    let mut spans: Vec<(usize, CalibrationSpan)> = Vec::new();
    for (k, run) in runs.iter().enumerate() {
        for (lo, hi) in spans::standstills(run, &c) {
            spans.push((k, measure(run, lo, hi, SpanKind::Standstill)));
        }
    }
    let standing: Vec<&CalibrationSpan> = spans.iter().map(|(_, s)| s).collect();
    let yaw_reference =
        pooled(&standing, SpanKind::Standstill, RunChannel::YawRate).map_or(0.0, |p| p.mean);
    let mut rejected = Vec::new();
    for (k, run) in runs.iter().enumerate() {
        let (found, refused) = spans::straights(run, yaw_reference, &c);
        for (lo, hi) in found {
            spans.push((k, measure(run, lo, hi, SpanKind::Straight)));
        }
        rejected.extend(refused);
    }
    spans.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.t_start.total_cmp(&b.1.t_start)));
    let spans: Vec<CalibrationSpan> = spans.into_iter().map(|(_, s)| s).collect();
    let all: Vec<&CalibrationSpan> = spans.iter().collect();
    let channels = CHANNELS
        .into_iter()
        .filter_map(|ch| channel_calibration(&all, ch))
        .collect();
    CalibrationReport {
        criteria: c,
        yaw_reference,
        spans,
        rejected,
        channels,
    }
}

/// The response channels' means over `[lo, hi)` of `run`.
fn measure(run: &MeasuredRun, lo: usize, hi: usize, kind: SpanKind) -> CalibrationSpan {
    let live: Vec<usize> = (lo..hi)
        .filter(|i| run.masked.binary_search(i).is_err())
        .collect();
    let mut channels = Vec::new();
    let mut held = Vec::new();
    let beta_bank = match (&run.bank, &run.beta, kind) {
        (Some(b), Some(_), SpanKind::Straight) if !live.is_empty() => {
            let mean = live.iter().map(|&i| b[i]).sum::<f64>() / live.len() as f64;
            (mean.abs() > STRAIGHT_BETA_BANK).then_some(mean)
        }
        _ => None,
    };
    for ch in CHANNELS {
        // No velocity, no sideslip.
        if ch == RunChannel::Beta && kind == SpanKind::Standstill {
            continue;
        }
        // On a logged bank the car crabs: its sideslip is no offset.
        if ch == RunChannel::Beta && beta_bank.is_some() {
            continue;
        }
        let Some(x) = values(run, ch) else { continue };
        let bank: Option<Vec<f64>> = match (ch, &run.bank) {
            (RunChannel::Ay, Some(b)) => Some(live.iter().map(|&i| G * b[i].sin()).collect()),
            _ => None,
        };
        let v: Vec<f64> = match &bank {
            Some(g) => live.iter().zip(g).map(|(&i, g)| x[i] - g).collect(),
            None => live.iter().map(|&i| x[i]).collect(),
        };
        let bank_term = bank.map(|g| g.iter().sum::<f64>() / g.len().max(1) as f64);
        match mean_estimate(&v) {
            Some(e) => channels.push(ChannelMean::new(ch, e, bank_term)),
            None if !v.is_empty() => held.push(ch),
            None => {}
        }
    }
    let mut steer = run.steer[lo..hi].to_vec();
    CalibrationSpan {
        run: run.path.display().to_string(),
        kind,
        t_start: run.t[lo],
        t_end: run.t[hi - 1],
        speed: run.speed[lo..hi].iter().sum::<f64>() / (hi - lo) as f64,
        steer: crate::measured::clean::median(&mut steer),
        channels,
        held,
        beta_bank,
    }
}

/// The offset of `channel` pooled over the spans of `kind`; None without
/// any.
fn pooled(spans: &[&CalibrationSpan], kind: SpanKind, channel: RunChannel) -> Option<Pooled> {
    let of: Vec<(&CalibrationSpan, &ChannelMean)> = spans
        .iter()
        .filter(|s| s.kind == kind)
        .filter_map(|s| {
            s.channels
                .iter()
                .find(|m| m.channel == channel)
                .map(|m| (*s, m))
        })
        .collect();
    if of.is_empty() {
        return None;
    }
    let means: Vec<(f64, f64)> = of.iter().map(|(_, m)| (m.mean, m.std_error)).collect();
    let p = pool(&means);
    let (least, greatest) = means
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &(m, _)| (a.min(m), b.max(m)));
    Some(Pooled {
        spans: of.len(),
        seconds: of.iter().map(|(s, _)| s.seconds()).sum(),
        samples: of.iter().map(|(_, m)| m.samples).sum(),
        mean: p.mean,
        std_error: p.std_error,
        chi2: p.chi2,
        between_spans: p.between,
        dof: p.dof,
        consistent: p.agree,
        least,
        greatest,
    })
}

/// The standstills' `channel` (with a logged bank removed, pooled to
/// `corrected`) read against that bank (`bank.rs`); None where no bank was
/// removed.
fn bank_check(
    spans: &[&CalibrationSpan],
    channel: RunChannel,
    corrected: f64,
) -> Option<BankCheck> {
    let read: Vec<(f64, f64)> = spans
        .iter()
        .filter(|s| s.kind == SpanKind::Standstill)
        .flat_map(|s| &s.channels)
        .filter(|m| m.channel == channel)
        .map(|m| m.bank_term.map(|b| (m.mean + b, m.std_error)))
        .collect::<Option<_>>()?;
    // Pooled with the same weights as the corrected means, so the
    // difference is the pooled bank term.
    let read = pool(&read).mean;
    Some(BankCheck::judge(read, read - corrected))
}

/// One channel over the standstills and the straights; None when neither
/// measures it.
fn channel_calibration(
    spans: &[&CalibrationSpan],
    channel: RunChannel,
) -> Option<ChannelCalibration> {
    let standstill = pooled(spans, SpanKind::Standstill, channel);
    let straight = pooled(spans, SpanKind::Straight, channel);
    let banked = (channel == RunChannel::Beta)
        .then(|| BankedStraights::of(spans))
        .flatten();
    if standstill.is_none() && straight.is_none() && banked.is_none() {
        return None;
    }
    let agreement = standstill.zip(straight).map(|(a, b)| {
        let difference = b.mean - a.mean;
        let std_error = a.std_error.hypot(b.std_error);
        Agreement {
            difference,
            std_error,
            agree: difference.abs() <= AGREEMENT_SIGMAS * std_error,
        }
    });
    let bank_removed = spans.iter().any(|s| {
        s.channels
            .iter()
            .any(|m| m.channel == channel && m.bank_term.is_some())
    });
    let bank = standstill.and_then(|p| bank_check(spans, channel, p.mean));
    // Without a bank column the standstills' ay holds g·sin θ of the
    // ground they stood on: beyond a mounted sensor's offset, that is it.
    let unlogged_bank = channel == RunChannel::Ay
        && !bank_removed
        && standstill.is_some_and(|p| p.mean.abs() > PLAUSIBLE_AY_OFFSET);
    Some(ChannelCalibration {
        channel,
        unit: unit(channel),
        bank_removed,
        bank,
        unlogged_bank,
        offset: Offset::of(
            standstill.as_ref(),
            straight.as_ref(),
            bank.as_ref(),
            unlogged_bank,
        ),
        standstill,
        straight,
        agreement,
        banked_straights: banked,
    })
}
