//! How far each measured channel is trusted ([`channel_scale`]): the
//! uncertainty that scales its residuals in every fit and serves as its
//! noise floor in the gap above noise.
//!
//! A channel's weight in a fit is `1/s²`. Estimated from the channel's
//! high-frequency scatter alone (the standard deviation before the first
//! input, or the robust second differences where that window holds motion,
//! else the robust second differences: [`crate::diagnose::report::parts`]),
//! a *smooth* channel — a
//! state estimator's sideslip, a filtered yaw rate — looks ten times more
//! precise than a gyro and drowns the other channels, though its real
//! error (the estimator's lag, drift and model) is at low frequency where
//! the scatter does not see it. So the uncertainty is, in order:
//! 1. the one the user states for the channel (`[channels]`);
//! 2. for a channel whose scatter is below its line ([`smooth_line`]) — for
//!    a sideslip [`SMOOTH_SHARE`] of its sensor type's floor (no slip sensor
//!    is that quiet, so the channel is an estimator's output); for a yaw
//!    rate or ay, measured by a gyro and an accelerometer, not estimated,
//!    [`QUIET_SENSOR_SHARE`] of it (quieter than any sensor: noise-free or
//!    smoothed data) — the floor of an estimated output ([`ESTIMATED`]);
//! 3. else the scatter, at least the sensor type's floor ([`SENSOR_FLOOR`]).
//!
//! The scale of the fits is that uncertainty, at least 2 % of the
//! channel's RMS signal (so that a very quiet channel on a loud signal
//! does not drown the others).
//!
//! The floors: a vehicle-dynamics MEMS gyro and accelerometer resolve
//! about 0.1 °/s and 0.02 m/s² in a car's vibration; an optical or
//! GNSS/INS slip-angle sensor is specified to about ±0.1–0.2° (Kistler
//! Correvit S-Motion and OxTS RT data sheets), 0.0017 rad at 1σ; a
//! sideslip *estimated* from an inertial unit and a model is good to about
//! 0.3° (0.005 rad), an estimated yaw rate to 0.3 °/s, an estimated ay to
//! 0.1 m/s² (Chindamo, Lenzo & Gadola 2018, the review of sideslip
//! estimators). Units: the channel's (rad/s, m/s², rad).

use crate::diagnose::campaign::StatedUncertainty;
use crate::diagnose::model::channels::Channel;
use crate::measured::MeasuredRun;
use serde::Serialize;

/// The floor of a sensor of each channel's type (yaw rate rad/s, ay m/s²,
/// beta rad): no measurement of that type is trusted better.
pub const SENSOR_FLOOR: [f64; 3] = [0.0017, 0.02, 0.0017];

/// A channel whose scatter is below this share of its sensor floor is a
/// filtered or estimated output, not a sensor's.
pub const SMOOTH_SHARE: f64 = 0.5;

/// A yaw rate or ay (a gyro's, an accelerometer's: measured, not the
/// output of an estimator) whose scatter is below this share of its sensor
/// floor is smoother than any sensor: noise-free or smoothed data. Between
/// it and the floor it is a quiet sensor (a fibre-optic gyro scatters
/// about 0.0002 rad/s at 100 Hz, 0.12 of the floor; a gyro of 0.0005 rad/s
/// read as an estimated output was trusted to 0.005 rad/s, and a 20 %
/// cornering-stiffness error, 17 of its noise levels, read as no gap).
pub const QUIET_SENSOR_SHARE: f64 = 0.05;

/// The share of its sensor type's floor below which channel `c`'s scatter
/// reads as an estimated output: [`SMOOTH_SHARE`] for a sideslip (usually
/// an estimator's), [`QUIET_SENSOR_SHARE`] for a yaw rate or ay.
pub fn smooth_line(c: Channel) -> f64 {
    match c {
        Channel::Beta => SMOOTH_SHARE,
        Channel::YawRate | Channel::Ay => QUIET_SENSOR_SHARE,
    }
}

/// The uncertainty of an estimated (smooth) output of each channel.
pub const ESTIMATED: [f64; 3] = [0.005, 0.1, 0.005];

/// The share of a channel's RMS signal below which no scale goes.
pub const SIGNAL_SHARE: f64 = 0.02;

/// Where a channel's uncertainty comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ScaleSource {
    /// Stated by the user (`[channels]`).
    Stated,
    /// Its high-frequency scatter.
    Scatter,
    /// Its sensor type's floor, above its scatter.
    SensorFloor,
    /// Smoother than any sensor of its type: an estimated output's floor.
    Estimated,
}

/// How the part of a channel's floor above its own scatter counts in the
/// standard error of a run's mean residual (the gap's bias test).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FloorCounting {
    /// White noise: a new draw every sample, counted over all of them.
    White,
    /// A slow error (an estimator's drift, a misalignment): one draw for
    /// the whole run, counted once.
    Slow,
}

/// The lag-1 correlation of a white record's first differences, −½
/// (`Δxᵢ = wᵢ − wᵢ₋₁`); a random walk's, an estimator's integrated output,
/// is 0 and a smooth signal's near 1. Above this line a record's
/// high-frequency part is not a white sensor's: it is smoothed.
pub const WHITE_DIFFERENCES: f64 = -0.25;

/// The lag-1 correlation of the first differences of `x`, read robustly
/// from the scatter of its first and second differences (`1.4826·MAD`):
/// `ρ₁ = 1 − var(Δ²x)/(2·var(Δx))`. −½ for white noise, 0 for a random
/// walk; the medians ignore the minority of samples where the signal
/// itself moves fast (Hampel 1974). 1 (smooth) for a record whose
/// differences are mostly zero; NaN on fewer than four samples.
pub fn difference_correlation(x: &[f64]) -> f64 {
    if x.len() < 4 {
        return f64::NAN;
    }
    let mad = |mut d: Vec<f64>| {
        let median = crate::measured::clean::midpoint_median;
        let m = median(&mut d);
        let mut dev: Vec<f64> = d.iter().map(|v| (v - m).abs()).collect();
        1.4826 * median(&mut dev)
    };
    let first = mad(x.windows(2).map(|w| w[1] - w[0]).collect());
    let second = mad(x.windows(3).map(|w| w[2] - 2.0 * w[1] + w[0]).collect());
    if first <= 0.0 {
        return 1.0;
    }
    1.0 - 0.5 * (second / first).powi(2)
}

/// What channel `c`'s floor (from `source`, its high-frequency `scatter`
/// and the median lag-1 correlation of its first differences,
/// `differences` ([`difference_correlation`]), beside it) stands for, and
/// so how the gap's bias and window tests count it:
/// - a floor read from the scatter, or a gyro's or accelerometer's sensor
///   floor, is the sensor's noise: white;
/// - a yaw rate or `ay` smoother than any sensor is a gyro's or an
///   accelerometer's record smoothed or noise-free (they are measured, not
///   estimated: [`QUIET_SENSOR_SHARE`]); its floor is the white noise the
///   smoothing took away, and a low-pass leaves the standard error of a
///   white noise's mean as it was: white. Their slow error, an offset, is
///   the very bias the test looks for;
/// - a sideslip that reads as an estimator's output (its scatter below
///   [`SMOOTH_SHARE`] of the slip sensor's floor) and is trusted to an
///   estimated output's assumed uncertainty, *and smooth* (its
///   differences correlated above [`WHITE_DIFFERENCES`]): its record shows
///   nothing of that uncertainty, which is the estimator's lag, drift and
///   misalignment, at low frequency: slow. A run's mean inside it is not
///   evidence of a bias (Chindamo, Lenzo & Gadola 2018: estimators' errors
///   are offsets and drifts over a manoeuvre, not sample-to-sample scatter);
/// - the same sideslip trusted to an uncertainty the user stated: slow,
///   smooth or not. The statement says what the record cannot: an error
///   beyond the channel's scatter, which a scatter below any slip sensor's
///   does not hold;
/// - an unstated sideslip whose high-frequency scatter is white
///   (differences correlated near −½, as a sensor's noise; Putnam's log
///   reads −0.45), however quiet, or one read as a sensor's (stated or
///   not): white. The tool cannot tell such a record from a quiet slip
///   sensor's, and a sensor's floor is its noise.
pub fn floor_counting(
    c: Channel,
    source: ScaleSource,
    scatter: f64,
    differences: f64,
) -> FloorCounting {
    // NaN (too few samples) is not white: read as an estimator's.
    let smooth = differences.is_nan() || differences >= WHITE_DIFFERENCES;
    match (c, source) {
        (Channel::YawRate | Channel::Ay, _) => FloorCounting::White,
        (Channel::Beta, ScaleSource::Scatter | ScaleSource::SensorFloor) => FloorCounting::White,
        (Channel::Beta, ScaleSource::Estimated) if smooth => FloorCounting::Slow,
        (Channel::Beta, ScaleSource::Stated) if reads_as_estimated(c, scatter) => {
            FloorCounting::Slow
        }
        (Channel::Beta, ScaleSource::Estimated | ScaleSource::Stated) => FloorCounting::White,
    }
}

/// How far a channel is trusted.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ChannelScale {
    /// The uncertainty (one standard deviation): the noise floor of the
    /// gap above noise.
    pub uncertainty: f64,
    /// The residual scale of the fits: the uncertainty, at least
    /// [`SIGNAL_SHARE`] of the RMS signal.
    pub scale: f64,
    /// Where the uncertainty comes from.
    pub source: ScaleSource,
    /// The high-frequency scatter measured.
    pub scatter: f64,
}

/// How far, as a factor either side, a channel's scatter may lie from the
/// line between a sensor and an estimated output ([`smooth_line`] of the
/// sensor floor) and still be read as near it. The scatter is a sample
/// statistic: a sideslip with white noise of 0.0005 rad reads 0.00045
/// (0.26: an estimated output, trusted to 0.005 rad), the same with
/// 0.0009 rad reads 0.00092 (0.54: a sensor, trusted to 0.0017 rad).
/// Scatter alone cannot tell a quiet sensor from a smooth estimator, so
/// between half and twice the line the report says the reading is near
/// it and asks for the channel's uncertainty.
pub const NEAR_THE_LINE: f64 = 2.0;

/// Which side of the line between a sensor and an estimated output a
/// scatter of channel `c` falls: true for an estimated output's (below
/// its [`smooth_line`] share of its sensor floor, or not a number).
pub fn reads_as_estimated(c: Channel, scatter: f64) -> bool {
    scatter.is_nan() || scatter < smooth_line(c) * SENSOR_FLOOR[c.index()]
}

/// The scatter of channel `c` as a share of its sensor type's floor, where
/// an unstated channel's trust hangs on a reading near the line between a
/// sensor and an estimated output: its scatter within [`NEAR_THE_LINE`] of
/// it, or `other_side` runs of the campaign reading the other way alone.
/// `None` where the trust is stated or clear.
pub fn near_the_line(
    c: Channel,
    source: ScaleSource,
    scatter: f64,
    other_side: usize,
) -> Option<f64> {
    if source == ScaleSource::Stated || !scatter.is_finite() {
        return None;
    }
    let share = scatter / SENSOR_FLOOR[c.index()];
    let line = smooth_line(c);
    let near = share > line / NEAR_THE_LINE && share < line * NEAR_THE_LINE;
    (near || other_side > 0).then_some(share)
}

/// The uncertainty the user `stated` for channel `c`, if any.
pub fn stated_of(c: Channel, stated: &StatedUncertainty) -> Option<f64> {
    match c {
        Channel::YawRate => stated.yaw_rate,
        Channel::Ay => stated.ay,
        Channel::Beta => stated.beta,
    }
}

/// How many times the uncertainty of an estimated output of its channel
/// ([`ESTIMATED`]) a stated uncertainty may be before, beyond the
/// channel's whole signal too, it is refused ([`beyond_signal`]).
pub const ESTIMATED_REACH: f64 = 10.0;

/// A stated uncertainty (channel `c`) at least the channel's RMS `signal`
/// on the runs and [`ESTIMATED_REACH`] times what even an estimated output
/// of its kind is good to: no sensor or estimator is that poor, so it is a
/// slip (a unit, a digit), refused where it is read. Either alone is not:
/// a light car's sideslip (RMS 0.0033 rad on the slow oval) is smaller
/// than an estimator's 0.005 rad and still carries what it measures. False
/// without a signal.
pub fn beyond_signal(c: Channel, stated: f64, signal: f64) -> bool {
    signal > 0.0 && stated >= signal && stated > ESTIMATED_REACH * ESTIMATED[c.index()]
}

/// How many times a channel's high-frequency scatter may exceed its
/// stated uncertainty before the statement is noted as contradicted: a
/// channel scattering more from sample to sample than it is trusted to
/// would be weighted past what its own record shows (and dominate every
/// fit). A scatter within three times is the noise of the estimate itself
/// on short runs.
pub const SCATTER_EXCESS: f64 = 3.0;

/// How many times what a channel shows of itself ([`own_uncertainty`]) a
/// stated uncertainty may be before the report says so: a floor that high
/// makes a gap the data would show insignificant by the statement alone
/// (a steady yaw-rate gain 1.8 dB off read "no significant gap" beside a
/// yaw-rate uncertainty stated 16 times the gyro's scatter). The user may
/// state it (an estimator's error is at low frequency, where no scatter
/// sees it); the report says it.
pub const STATED_EXCESS: f64 = 10.0;

/// What channel `c` shows of its own uncertainty: its high-frequency
/// `scatter` where that reads as a sensor's, an estimated output's
/// uncertainty ([`ESTIMATED`]) where it reads as an estimated output (a
/// smooth channel's scatter says nothing of its error).
pub fn own_uncertainty(c: Channel, scatter: f64) -> f64 {
    if reads_as_estimated(c, scatter) {
        ESTIMATED[c.index()]
    } else {
        scatter
    }
}

/// A stated uncertainty more than [`STATED_EXCESS`] times what its channel
/// shows of itself.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StatedExcess {
    /// The channel.
    pub channel: Channel,
    /// The uncertainty stated under `[channels]`, the channel's unit.
    pub stated: f64,
    /// What the channel shows ([`own_uncertainty`]), the channel's unit.
    pub own: f64,
    /// Whether `own` is an estimated output's uncertainty (the channel is
    /// smoother than any sensor), not its scatter.
    pub estimated: bool,
    /// `stated / own`.
    pub times: f64,
}

/// The excess of an uncertainty `stated` for channel `c` (of `source`)
/// over what its `scatter` shows, where beyond [`STATED_EXCESS`]; None for
/// an unstated channel or one without a scatter.
pub fn stated_excess(
    c: Channel,
    source: ScaleSource,
    stated: f64,
    scatter: f64,
) -> Option<StatedExcess> {
    if source != ScaleSource::Stated || !scatter.is_finite() {
        return None;
    }
    let own = own_uncertainty(c, scatter);
    let times = stated / own;
    (own > 0.0 && times > STATED_EXCESS).then_some(StatedExcess {
        channel: c,
        stated,
        own,
        estimated: reads_as_estimated(c, scatter),
        times,
    })
}

/// The uncertainty and scale of channel `c` (module doc) from what the
/// user `stated`, its measured `scatter` and its RMS `signal`.
pub fn channel_scale(
    c: Channel,
    stated: &StatedUncertainty,
    scatter: f64,
    signal: f64,
) -> ChannelScale {
    let i = c.index();
    let (uncertainty, source) = match stated_of(c, stated) {
        Some(s) => (s, ScaleSource::Stated),
        // A scatter that is not a number (no samples) is no sensor's either.
        None if reads_as_estimated(c, scatter) => (ESTIMATED[i], ScaleSource::Estimated),
        None if scatter >= SENSOR_FLOOR[i] => (scatter, ScaleSource::Scatter),
        None => (SENSOR_FLOOR[i], ScaleSource::SensorFloor),
    };
    ChannelScale {
        uncertainty,
        scale: uncertainty.max(SIGNAL_SHARE * signal),
        source,
        scatter,
    }
}

/// Each channel's RMS signal over every unmasked sample of every run (0
/// where no run measures it).
pub fn signal_rms(runs: &[MeasuredRun]) -> [f64; 3] {
    Channel::ALL.map(|ch| {
        let (mut s, mut n) = (0.0, 0usize);
        for r in runs {
            if let Some(v) = ch.of(r) {
                // A masked sample (a logger's spike of 9999) is no signal:
                // counted, it would set a scale that hides every gap.
                let kept = v
                    .iter()
                    .enumerate()
                    .filter(|(k, _)| r.masked.binary_search(k).is_err());
                s += kept.clone().map(|(_, x)| x * x).sum::<f64>();
                n += kept.count();
            }
        }
        if n == 0 {
            0.0
        } else {
            (s / n as f64).sqrt()
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const NONE: StatedUncertainty = StatedUncertainty {
        yaw_rate: None,
        ay: None,
        beta: None,
    };

    #[test]
    fn a_stated_uncertainty_wins_over_every_estimate() {
        let s = StatedUncertainty {
            beta: Some(0.004),
            ..NONE
        };
        let c = channel_scale(Channel::Beta, &s, 0.0001, 0.01);
        assert_eq!((c.uncertainty, c.source), (0.004, ScaleSource::Stated));
    }

    #[test]
    fn a_channel_smoother_than_half_its_sensor_floor_is_an_estimated_output() {
        // A state estimator's sideslip: 0.0002 rad of scatter.
        let c = channel_scale(Channel::Beta, &NONE, 0.0002, 0.02);
        assert_eq!((c.uncertainty, c.source), (0.005, ScaleSource::Estimated));
        // Noise-free data are no more precise than an estimate.
        let c = channel_scale(Channel::YawRate, &NONE, 0.0, 0.2);
        assert_eq!(c.source, ScaleSource::Estimated);
        let c = channel_scale(Channel::YawRate, &NONE, f64::NAN, 0.2);
        assert_eq!(c.source, ScaleSource::Estimated);
    }

    #[test]
    fn a_sensor_is_trusted_to_its_scatter_but_never_below_its_type_floor() {
        let c = channel_scale(Channel::YawRate, &NONE, 0.003, 0.05);
        assert_eq!((c.uncertainty, c.source), (0.003, ScaleSource::Scatter));
        let c = channel_scale(Channel::Ay, &NONE, 0.015, 1.0);
        assert_eq!((c.uncertainty, c.source), (0.02, ScaleSource::SensorFloor));
    }

    #[test]
    fn a_scatter_near_the_line_between_sensor_and_estimate_is_said_to_be() {
        let yaw = Channel::YawRate;
        // Putnam's yaw rate: 0.0010 rad/s over the log, 0.00072 over 60 s;
        // a quiet gyro of 0.0005 rad/s: all sensors, far from the yaw
        // rate's line (0.05 of the floor), trusted to the gyro floor.
        for s in [0.0010, 0.00072, 0.00047] {
            let c = channel_scale(yaw, &NONE, s, 0.1);
            assert_eq!(
                (c.uncertainty, c.source),
                (0.0017, ScaleSource::SensorFloor)
            );
            assert_eq!(near_the_line(yaw, c.source, s, 0), None);
        }
        // Smoother than any gyro: near the line at 0.00012 (0.07), an
        // estimated output at 0.00005 (0.03).
        assert!(near_the_line(yaw, ScaleSource::SensorFloor, 0.00012, 0).is_some());
        let c = channel_scale(yaw, &NONE, 0.00005, 0.1);
        assert_eq!(c.source, ScaleSource::Estimated);
        // A quieter sideslip read as an estimate, a noisier as a sensor:
        // both near the line (0.5 of the slip sensor's floor).
        let quiet = channel_scale(Channel::Beta, &NONE, 0.00045, 0.02);
        assert_eq!(quiet.source, ScaleSource::Estimated);
        assert!(near_the_line(Channel::Beta, ScaleSource::Estimated, 0.00045, 0).is_some());
        assert!(near_the_line(Channel::Beta, ScaleSource::SensorFloor, 0.00092, 0).is_some());
        // Clear readings: a gyro at its floor, an estimator's 0.0002 rad.
        assert_eq!(
            near_the_line(yaw, ScaleSource::SensorFloor, 0.0017, 0),
            None
        );
        assert_eq!(
            near_the_line(Channel::Beta, ScaleSource::Estimated, 0.0002, 0),
            None
        );
        // ... unless runs read alone fall on the other side.
        assert!(near_the_line(yaw, ScaleSource::SensorFloor, 0.0017, 2).is_some());
        // A stated uncertainty is the user's: never near any line.
        assert_eq!(near_the_line(yaw, ScaleSource::Stated, 0.0010, 5), None);
    }

    #[test]
    fn a_stated_uncertainty_far_above_the_channels_own_is_an_excess() {
        let yaw = Channel::YawRate;
        // A gyro scattering 0.0025 rad/s, stated 0.04: 16 times.
        let e = stated_excess(yaw, ScaleSource::Stated, 0.04, 0.0025).unwrap();
        assert!((e.times - 16.0).abs() < 1e-12 && !e.estimated, "{e:?}");
        // Ten times is within the rule; unstated is never an excess.
        assert_eq!(stated_excess(yaw, ScaleSource::Stated, 0.025, 0.0025), None);
        assert_eq!(stated_excess(yaw, ScaleSource::Scatter, 0.04, 0.0025), None);
        // An estimator's smooth sideslip (scatter 0.0002 rad) stated at
        // 0.005 rad, an estimate's uncertainty: no excess, though it is 25
        // times the scatter; 0.06 rad is 12 times an estimate's.
        assert_eq!(
            stated_excess(Channel::Beta, ScaleSource::Stated, 0.005, 0.0002),
            None
        );
        let e = stated_excess(Channel::Beta, ScaleSource::Stated, 0.06, 0.0002).unwrap();
        assert!(e.estimated && (e.times - 12.0).abs() < 1e-12, "{e:?}");
    }

    #[test]
    fn only_a_smooth_sideslip_read_as_an_estimator_s_output_has_a_slow_floor() {
        use FloorCounting::{Slow, White};
        let counted = |c, stated: StatedUncertainty, scatter, differences| {
            let s = channel_scale(c, &stated, scatter, 0.05);
            floor_counting(c, s.source, scatter, differences)
        };
        let beta = |v| StatedUncertainty {
            beta: Some(v),
            ..NONE
        };
        // A smooth sideslip (its differences a random walk's, 0): an
        // estimator's, assumed or stated.
        assert_eq!(counted(Channel::Beta, NONE, 0.0002, 0.0), Slow);
        assert_eq!(counted(Channel::Beta, beta(0.004), 0.0002, 0.0), Slow);
        assert_eq!(counted(Channel::Beta, NONE, 0.0002, f64::NAN), Slow);
        // As quiet, but white (−½), nothing stated: a sensor's noise
        // (Putnam's sideslip, 0.0007 rad, differences −0.45); with an
        // uncertainty stated, the user's word for an estimator's: slow.
        assert_eq!(counted(Channel::Beta, NONE, 0.0005, -0.5), White);
        assert_eq!(counted(Channel::Beta, NONE, 0.0007, -0.45), White);
        assert_eq!(counted(Channel::Beta, beta(0.005), 0.0007, -0.45), Slow);
        // A slip sensor, at its floor or beyond it, stated or not.
        assert_eq!(counted(Channel::Beta, NONE, 0.0012, 0.0), White);
        assert_eq!(counted(Channel::Beta, NONE, 0.003, -0.5), White);
        assert_eq!(counted(Channel::Beta, beta(0.004), 0.0012, 0.0), White);
        // A noise-free or smoothed gyro's or accelerometer's record: white.
        for c in [Channel::YawRate, Channel::Ay] {
            assert_eq!(counted(c, NONE, 0.0, 0.9), White);
            assert_eq!(counted(c, NONE, 0.01, -0.5), White);
        }
    }

    /// The closed forms: white noise's differences correlate −½, a random
    /// walk's 0 (an estimator's integrated output), on a slow signal (a
    /// 0.02 rad step over 0.3 s at 100 Hz) as without it; a first-order
    /// wander of 3 s reads as a random walk.
    #[test]
    fn a_white_record_s_differences_correlate_minus_a_half_and_a_smooth_one_s_zero() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
        let mut gauss = || crate::optim::stats::gauss(&mut rng);
        let n = 8000;
        let step = |i: usize| 0.02 * (1.0 - (-(i as f64 * 0.01 - 1.0).max(0.0) / 0.3).exp());
        let white: Vec<f64> = (0..n).map(|i| step(i) + 0.0005 * gauss()).collect();
        let rho = (-0.01_f64 / 3.0).exp();
        let mut x = 0.0;
        let wander: Vec<f64> = (0..n)
            .map(|i| {
                x = rho * x + 0.001 * (1.0 - rho * rho).sqrt() * gauss();
                step(i) + x
            })
            .collect();
        let w = difference_correlation(&white);
        let s = difference_correlation(&wander);
        assert!((w + 0.5).abs() < 0.05, "{w}");
        assert!(s.abs() < 0.1, "{s}");
        assert!(w < WHITE_DIFFERENCES && s > WHITE_DIFFERENCES);
        assert_eq!(difference_correlation(&[0.1; 50]), 1.0);
        assert!(difference_correlation(&[0.0, 1.0, 2.0]).is_nan());
    }

    #[test]
    fn the_scale_is_at_least_two_percent_of_the_signal() {
        let c = channel_scale(Channel::YawRate, &NONE, 0.003, 0.5);
        assert_eq!(c.uncertainty, 0.003);
        assert!((c.scale - 0.01).abs() < 1e-15);
    }
}
