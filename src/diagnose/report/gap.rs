//! Where simulation and measurement disagree, for one replayed run.
//!
//! Per channel (yaw rate, and lateral acceleration and sideslip where
//! measured): the residual e = simulated − measured at the measurement times
//! (the simulation linearly interpolated), its RMS, bias and largest value;
//! the Sprague–Geers split (Sprague & Geers 2004, simulated m against
//! measured c): magnitude error `M = sqrt(∫m²/∫c²) − 1`, phase error
//! `P = acos(∫mc/sqrt(∫m²·∫c²))/π`, comprehensive `C = sqrt(M² + P²)`; the
//! residual's lag-1 autocorrelation (near 0: white, measurement-like; near 1:
//! a slow, model-like error) and its largest correlation with the steer input
//! over lags 0–1 s (a residual that follows the input points to a dynamic
//! error: a lag, a stiffness, a gain). The residual is also split by time
//! window (before the input, the first 0.5 s after it starts, 0.5–2 s, the
//! rest; only for a run whose steer holds its initial value for
//! [`crate::diagnose::report::parts::STEADY_BEFORE_INPUT`] before the
//! input, not a piece of a lap) and by regime (lateral-acceleration level,
//! speed band).
//!
//! The noise floor of each channel is its standard deviation in the
//! pre-input window (the steer not yet moved) when that window has at least
//! ten samples, else the first-difference estimate `std(Δx)/√2` (an upper
//! bound for smooth signals). A gap is significant when the RMS residual
//! exceeds three noise floors (and 1e-6 of the signal, for noise-free data),
//! so "no significant gap" is a possible answer. That whole-run test alone
//! is `significant`, the one `diagnose`'s verdicts read; beside it
//! ([`scan`]) the sliding window that carries the most evidence of a gap,
//! the bias against its standard error and the time shift between the
//! simulated and the measured channel, which the words and
//! `gap_found` add.
//! Units: SI, rad; times in s.

use crate::diagnose::model::channels::Channel;
use crate::diagnose::model::replay::UNMEASURED_START;
use crate::diagnose::model::scale::FloorCounting;
use crate::diagnose::report::outcome::above_noise;
use crate::diagnose::report::parts::{
    regime_samples, scatter_by, timed_from_an_input, window_samples, Levels, Part, Scatter,
};
use crate::manoeuvre::interpolate;
use serde::Serialize;

mod bands;
mod drift;
mod said;
mod scan;
mod shift;
#[cfg(test)]
pub use bands::band_gaps;
pub use bands::{band_gaps_above, BandGap, BAND_SNR};
use said::{verdict, Found, Said};
pub use scan::scored_from;
pub use scan::WindowGap;

/// The residual over a part of the run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PartGap {
    /// The window or regime (serialised as its label).
    pub name: Part,
    /// Samples in it.
    pub samples: usize,
    /// Its samples' mean level on its axis: time after the input starts
    /// (s), |ay| (m/s²) or speed (m/s), where the gap map draws it
    /// ([`Levels::mean`]; `null` for all samples).
    pub mean_level: Option<f64>,
    /// RMS residual.
    pub rms: f64,
    /// Mean residual (simulated − measured).
    pub bias: f64,
}

/// The gap of one channel.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChannelGap {
    /// The channel.
    pub channel: Channel,
    /// Its unit.
    pub unit: &'static str,
    /// Noise floor (standard deviation of the measurement noise).
    pub noise_floor: f64,
    /// How the noise floor was estimated.
    pub noise_source: NoiseSource,
    /// RMS residual.
    pub rms: f64,
    /// Mean residual.
    pub bias: f64,
    /// Largest |residual|.
    pub max_abs: f64,
    /// Sprague–Geers magnitude error (`null` when the measured channel
    /// holds no signal: all zero).
    #[serde(serialize_with = "crate::report::finite_or_null")]
    pub magnitude_error: f64,
    /// Sprague–Geers phase error (0 … 1; `null` as above).
    #[serde(serialize_with = "crate::report::finite_or_null")]
    pub phase_error: f64,
    /// Sprague–Geers comprehensive error (`null` as above).
    #[serde(serialize_with = "crate::report::finite_or_null")]
    pub comprehensive_error: f64,
    /// Lag-1 autocorrelation of the residual (`null` for a constant one).
    #[serde(serialize_with = "crate::report::finite_or_null")]
    pub lag1_autocorrelation: f64,
    /// Largest |correlation| of the residual with the steer over lags 0–1 s
    /// (how much the residual looks like the steer input: not a time shift).
    pub input_correlation: f64,
    /// The lag of that largest correlation, s: the steer that earlier
    /// resembles the residual most.
    pub input_correlation_lag: f64,
    /// How much later the measurement runs than the simulation, s
    /// (`measured(t) ≈ simulated(t − time_shift)`; negative: it leads);
    /// `null` where the two correlate below 0.9 at every shift within 1 s,
    /// or the shift is within 4 of its standard errors (`shift.rs`).
    pub time_shift: Option<f64>,
    /// The sliding window of [`scan::WINDOW`] s with the most evidence of a gap
    /// (`null` on a run shorter than one window).
    pub worst_window: Option<WindowGap>,
    /// Standard error of the bias (the residual's autocorrelation counted).
    pub bias_standard_error: f64,
    /// How the floor counts in that standard error: `white`, a draw a
    /// sample, or `slow`, one for the run (an estimator's floor).
    pub bias_counting: FloorCounting,
    /// The bias beyond [`scan::bias_threshold`] standard errors.
    pub bias_significant: bool,
    /// By time window.
    pub windows: Vec<PartGap>,
    /// By regime.
    pub regimes: Vec<PartGap>,
    /// RMS above three noise floors (the whole run; what `diagnose`'s
    /// verdicts read).
    pub significant: bool,
    /// A gap by any test: the whole run's RMS, a window's, or the bias.
    pub gap_found: bool,
    /// The finding in words.
    pub verdict: String,
}

/// How a channel's noise floor was estimated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum NoiseSource {
    /// The standard deviation over the window before the input (at least
    /// ten samples).
    #[serde(rename = "standard deviation before the input")]
    BeforeInput,
    /// `1.4826·MAD(Δ²x)/√6` over the whole record: the window before the
    /// input holds motion.
    #[serde(rename = "robust second differences (the window before the input holds motion)")]
    SecondDifferences,
    /// `1.4826·MAD(Δ²x)/√6` over the whole record: no window before the
    /// input.
    #[serde(rename = "robust second differences (no window before the input)")]
    NoWindow,
    /// `std(Δx)/√2` over the whole record: an upper bound for a smooth
    /// signal (too few samples for the second differences, or a channel
    /// whose second differences are mostly zero).
    #[serde(rename = "first differences (an upper bound)")]
    FirstDifferences,
    /// The uncertainty the diagnosis trusts the channel to (stated, or its
    /// scatter over the runs at least a sensor's floor).
    #[serde(rename = "the channel's trusted uncertainty")]
    Trusted,
}

fn trapezoid(t: &[f64], f: impl Fn(usize) -> f64) -> f64 {
    (1..t.len())
        .map(|i| 0.5 * (f(i - 1) + f(i)) * (t[i] - t[i - 1]))
        .sum()
}

/// Sprague–Geers (M, P, C) of `m` (simulated) against `c` (measured).
pub fn sprague_geers(t: &[f64], m: &[f64], c: &[f64]) -> (f64, f64, f64) {
    let mm = trapezoid(t, |i| m[i] * m[i]);
    let cc = trapezoid(t, |i| c[i] * c[i]);
    let mc = trapezoid(t, |i| m[i] * c[i]);
    if mm <= 0.0 || cc <= 0.0 {
        return (f64::NAN, f64::NAN, f64::NAN);
    }
    let mag = (mm / cc).sqrt() - 1.0;
    let phase = (mc / (mm * cc).sqrt()).clamp(-1.0, 1.0).acos() / std::f64::consts::PI;
    (mag, phase, mag.hypot(phase))
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len().max(1) as f64
}

/// Correlation of `a[i]` with `b[i − lag]`: the gap scan's Pearson
/// correlation at that lag, 0 where it has none (an overlap under three
/// samples, or a constant series).
fn correlation(a: &[f64], b: &[f64], lag: usize) -> f64 {
    let rho = scan::lagged_correlation(a, b, lag as isize);
    if rho.is_nan() {
        0.0
    } else {
        rho
    }
}

fn part(name: Part, idx: &[usize], e: &[f64], levels: &Levels) -> PartGap {
    let v: Vec<f64> = idx.iter().map(|&i| e[i]).collect();
    PartGap {
        name,
        samples: v.len(),
        mean_level: levels.mean(name, idx),
        rms: (v.iter().map(|x| x * x).sum::<f64>() / v.len().max(1) as f64).sqrt(),
        bias: mean(&v),
    }
}

/// What a run shares between its channels: sample times, the steer input,
/// and the lateral acceleration (measured, or u·r) and speed that define the
/// regimes.
#[derive(Debug, Clone, Copy)]
pub struct Record<'a> {
    /// When the replay starts, s (`t[0]`, or before it where the opening
    /// stretch is not scored): the scan's windows start one window in.
    pub start: f64,
    /// Sample times, s.
    pub t: &'a [f64],
    /// Steer, rad.
    pub steer: &'a [f64],
    /// Lateral acceleration for the regimes, m/s².
    pub ay: &'a [f64],
    /// Speed, m/s.
    pub speed: &'a [f64],
}

/// The gap of one channel of a record, against its own scatter.
pub fn channel_gap(
    channel: Channel,
    rec: &Record,
    measured: &[f64],
    simulated: &[f64],
) -> ChannelGap {
    trusted_channel_gap(
        channel,
        rec,
        measured,
        simulated,
        None,
        FloorCounting::White,
    )
}

/// The gap of one channel of a record against the noise floor `trusted`
/// (the campaign's trusted uncertainty; its own scatter where None or 0),
/// counted in the bias and window tests as `counting` says (white for its
/// own scatter: the trust's countings are white wherever its floor is 0).
pub fn trusted_channel_gap(
    channel: Channel,
    rec: &Record,
    measured: &[f64],
    simulated: &[f64],
    trusted: Option<f64>,
    counting: FloorCounting,
) -> ChannelGap {
    let (t, steer) = (rec.t, rec.steer);
    let n = t.len();
    let e: Vec<f64> = (0..n).map(|i| simulated[i] - measured[i]).collect();
    let unit = channel.unit();
    let win = window_samples(t, steer);
    let (noise_floor, noise_source) = floor_of(trusted, &win[0].1, measured);
    let rms = (e.iter().map(|x| x * x).sum::<f64>() / n.max(1) as f64).sqrt();
    let (magnitude_error, phase_error, comprehensive_error) = sprague_geers(t, simulated, measured);
    let dt = (t[n - 1] - t[0]) / (n - 1).max(1) as f64;
    let (lag, rho) = steer_correlation(&e, steer, dt);
    let pre_samples = win[0].1.len();
    let (windows, regimes) = parts_of(rec, win, &e);
    // Noise-free data (a simulation replayed) have a zero floor: a residual
    // below 1e-6 of the signal is numerical, not a gap.
    let signal = (measured.iter().map(|x| x * x).sum::<f64>() / n.max(1) as f64).sqrt();
    let resolved = rms > 1e-6 * signal;
    let significant = above_noise(rms, noise_floor) && resolved;
    let (window, bias, tau) = scanned(rec, &e, (noise_floor, counting), pre_samples, resolved);
    let time_shift = scan::time_shift(dt, measured, simulated)
        .filter(|&s| shift::resolved(dt, measured, simulated, s, tau));
    let found = Found {
        whole: significant,
        window: window.as_ref().filter(|w| w.significant),
        bias,
    };
    let verdict = verdict(&Said {
        unit,
        rms,
        noise_floor,
        e: &e,
        measured,
        windows: &windows,
        regimes: &regimes,
        sg: (magnitude_error, phase_error),
        steer: (rho, lag as f64 * dt),
        found: &found,
        worst: window.as_ref(),
        time_shift,
        dt,
    });
    let gap_found = found.any();
    ChannelGap {
        channel,
        unit,
        noise_floor,
        noise_source,
        rms,
        bias: mean(&e),
        max_abs: e.iter().map(|x| x.abs()).fold(0.0, f64::max),
        magnitude_error,
        phase_error,
        comprehensive_error,
        lag1_autocorrelation: correlation(&e, &e, 1),
        input_correlation: rho,
        input_correlation_lag: lag as f64 * dt,
        time_shift,
        bias_standard_error: bias.standard_error,
        bias_counting: bias.counting,
        bias_significant: bias.significant,
        worst_window: window,
        windows,
        regimes,
        significant,
        gap_found,
        verdict,
    }
}

/// The scan's window and bias tests of the residual `e` of `rec` against
/// its floor (value, counting), with the noise's autocorrelation time
/// (samples) the time shift reads; `pre_samples` before the input.
fn scanned(
    rec: &Record,
    e: &[f64],
    (noise_floor, counting): (f64, FloorCounting),
    pre_samples: usize,
    resolved: bool,
) -> (Option<WindowGap>, scan::BiasTest, f64) {
    let t = rec.t;
    // The noise's autocorrelation from the residual's fast part: its slow
    // part is the model's error or the replay's start, not noise.
    let tau = scan::noise_time(t, e);
    // The floor's own sample count: the window before the input it is the
    // scatter of, else the whole run (its second differences); a stated
    // floor is known better, and counted so, conservatively.
    let floor_samples = if pre_samples >= 10 {
        pre_samples
    } else {
        t.len()
    };
    let from = scored_from(rec.start);
    let floor = (noise_floor, counting);
    let window = scan::worst_window(t, from, e, floor, tau, floor_samples, resolved);
    let bias = scan::bias_test(t, e, noise_floor, counting, resolved);
    (window, bias, tau)
}

/// The error `e` in the record's time windows and its regimes. A run with
/// no input to time from (a piece of a lap) is split by regime only: its
/// "first 0.5 s of the input" would be a time picked by a steering
/// correction.
fn parts_of(rec: &Record, win: Vec<(Part, Vec<usize>)>, e: &[f64]) -> (Vec<PartGap>, Vec<PartGap>) {
    let timed = timed_from_an_input(rec.t, rec.steer);
    let levels = Levels::new(rec.t, rec.steer, rec.ay, rec.speed);
    let windows = win
        .into_iter()
        .filter(|w| timed && !w.1.is_empty())
        .map(|(name, idx)| part(name, &idx, e, &levels))
        .collect();
    let regimes = regime_samples(rec.ay, rec.speed)
        .into_iter()
        .map(|(name, idx)| part(name, &idx, e, &levels))
        .collect();
    (windows, regimes)
}

/// The noise floor and where it comes from: the campaign's trusted
/// uncertainty where it has one (a run's own scatter is a state
/// estimator's smoothness or a hand-driven run's unquiet start, not what
/// the channel can be trusted to), else the scatter of `measured` before
/// the input (`before`, its samples) or of its differences.
fn floor_of(trusted: Option<f64>, before: &[usize], measured: &[f64]) -> (f64, NoiseSource) {
    match trusted {
        Some(f) if f > 0.0 => (f, NoiseSource::Trusted),
        _ => match scatter_by(before, measured) {
            (s, Scatter::BeforeInput) => (s, NoiseSource::BeforeInput),
            (s, Scatter::SecondDifferences) => (s, NoiseSource::SecondDifferences),
            (s, Scatter::NoWindow) => (s, NoiseSource::NoWindow),
            (s, Scatter::FirstDifferences) => (s, NoiseSource::FirstDifferences),
        },
    }
}

/// The lag (samples, up to 1 s and half the run) at which the error `e`
/// correlates most with the steer, and that correlation.
fn steer_correlation(e: &[f64], steer: &[f64], dt: f64) -> (usize, f64) {
    let max_lag = ((1.0 / dt).round() as usize).min(e.len() / 2);
    (0..=max_lag)
        .map(|l| (l, correlation(e, steer, l)))
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        .unwrap_or((0, 0.0))
}

/// The lateral acceleration that defines a run's regimes: measured, or u·r
/// when the run has no accelerometer.
pub fn regime_acceleration(run: &crate::measured::MeasuredRun) -> Vec<f64> {
    match &run.ay {
        Some(ay) => ay.clone(),
        None => run
            .yaw_rate
            .iter()
            .zip(&run.speed)
            .map(|(r, u)| r * u)
            .collect(),
    }
}

/// The samples of a run that are scored: all but the masked ones (logger
/// glitches in a response channel), and without a sideslip channel not
/// those of the replay's first [`UNMEASURED_START`] s, as the diagnosis's
/// residuals leave them out (`Prepared::new`).
pub fn scored_samples(run: &crate::measured::MeasuredRun) -> Vec<usize> {
    let mut keep = vec![true; run.t.len()];
    for &i in &run.masked {
        keep[i] = false;
    }
    let from = match run.beta {
        Some(_) => f64::NEG_INFINITY,
        None => replay_start(run) + UNMEASURED_START - 1e-9,
    };
    let scored: Vec<usize> = (0..run.t.len())
        .filter(|&i| keep[i] && run.t[i] >= from)
        .collect();
    if scored.is_empty() {
        (0..run.t.len()).filter(|&i| keep[i]).collect()
    } else {
        scored
    }
}

/// When a run's replay starts, s: its first unmasked sample.
fn replay_start(run: &crate::measured::MeasuredRun) -> f64 {
    let first = (0..run.t.len())
        .find(|i| run.masked.binary_search(i).is_err())
        .unwrap_or(0);
    run.t.get(first).copied().unwrap_or(0.0)
}

/// The gap of every measured channel of a replayed run, on its unmasked
/// samples, each against its `trusted` noise floor (by channel index; 0:
/// the run's own scatter), counted in the bias test as `counting` says.
pub fn run_gap(
    run: &crate::measured::MeasuredRun,
    sim: &crate::sim::TimeHistory,
    trusted: &[f64; 3],
    counting: &[FloorCounting; 3],
) -> Vec<ChannelGap> {
    let idx = scored_samples(run);
    let pick = |v: &[f64]| -> Vec<f64> { idx.iter().map(|&i| v[i]).collect() };
    let t = pick(&run.t);
    let at = |ys: &[f64]| -> Vec<f64> { t.iter().map(|&x| interpolate(&sim.t, ys, x)).collect() };
    let ay_regime = pick(&regime_acceleration(run));
    let (steer, speed) = (pick(&run.steer), pick(&run.speed));
    let rec = Record {
        start: replay_start(run),
        t: &t,
        steer: &steer,
        ay: &ay_regime,
        speed: &speed,
    };
    let gap = |c: Channel, m: &[f64], s: &[f64]| {
        let i = c.index();
        trusted_channel_gap(c, &rec, &pick(m), &at(s), Some(trusted[i]), counting[i])
    };
    let mut out = vec![gap(Channel::YawRate, &run.yaw_rate, &sim.yaw_rate)];
    if let Some(ay) = &run.ay {
        out.push(gap(Channel::Ay, ay, &sim.ay));
    }
    if let Some(beta) = &run.beta {
        out.push(gap(Channel::Beta, beta, &sim.beta));
    }
    out
}

#[cfg(test)]
mod tests;
