//! Step-steer metrics of GB/T 6323-2014 (GB/T 6323.2-94 in Wang & Liang) and
//! ISO 7401:2011, and Guo Konghui's total variances (Wang & Liang).
//!
//! From a record of steer δ(t), yaw rate r(t), lateral acceleration ay(t) and
//! optionally sideslip β(t):
//! - each signal's initial value is its mean over the first `pre_window`
//!   seconds, its steady value its mean over the last `steady_window` seconds;
//!   x̂ = (x − x₀)/(x_ss − x₀) is the normalised response;
//! - time zero t₀ is where δ̂ first reaches 0.5 (50 % of the steer input);
//! - response time: t₀ to the first time x̂ = 0.9 after the steer's onset
//!   (negative where the response leads the steer's half-way point, as a
//!   crawl's lateral acceleration does); peak response time: t₀ to
//!   the peak of r̂, the highest sample of its first stretch after the 90 %
//!   crossing that exceeds the steady state by more than the noise allows, by more than
//!   the low-pass alone lifts the steer step (`ρ`, the filtered steer's
//!   overshoot beyond the raw steer's: its ringing, which a yaw rate that
//!   follows the steer has too) and by at least `min_overshoot` (`1 +
//!   max(5·σ̂, 2·s_ss, ρ, min_overshoot)`, 1 % by default:
//!   a flatter maximum is one no test resolves, see [`DEFAULT_MIN_OVERSHOOT`];
//!   s_ss the scatter of r̂ in the steady window and σ̂ its noise:
//!   the robust deviation of the raw samples' differences over the record,
//!   `MAD(Δx)/(0.6745·√2)` — the few differences of the step itself do not
//!   move a median — times the filter's noise gain `√Σh²`); without one
//!   there is no overshoot (peak time none,
//!   overshoot none, TB none); overshoot = (r̂_peak − 1)·100 %;
//! - steady-state yaw-rate gain (r_ss − r₀)/(δ_ss − δ₀), 1/s; steady sideslip
//!   β_ss − β₀, rad; TB = peak response time × steady sideslip in s·deg
//!   (GB/T's unit);
//! - total variance `E_x = ∫ (δ̂ − x̂)² dt` (trapezoid) over a fixed window
//!   from the steer onset (δ̂ first at 5 %; `variance_window`, default 4 s,
//!   clipped to the record), so that noise before the step and after the
//!   response has settled does not add with the record's length; a pure
//!   delay d gives E = d and a first-order lag τ gives E = τ/2;
//!   `Er = e1·E_r + e2·E_ay`.
//!
//! Measured records are filtered first when `filter_hz` is set (`handling
//! metrics` sets 10 Hz): a second-order Butterworth low-pass run forward and
//! backward (zero phase, so no crossing moves; fourth-order magnitude),
//! designed by the bilinear transform at the record's median sample
//! interval. Simulated records are not filtered.
//!
//! Crossings are interpolated linearly between samples. A record that can be
//! evaluated at any time (a simulation's dense output) is measured by
//! [`continuous`] instead: integrals by quadrature, events as roots. Signs: any step
//! direction; the normalisation makes left and right steps give equal metrics.
//! A sampled record is measured step by step in `held.rs`.

pub use crate::error::MetricsError;
use serde::{Deserialize, Serialize};
use settling::{sideslip_scale, SETTLED_SPREAD};
pub use settling::{
    AxlesGrip, AyLimit, AyLimitSource, Ceiling, ChannelSettling, Settling,
    FALSE_ALARM as SETTLING_FALSE_ALARM, JUDGED_NOISES,
};

pub mod applicability;
pub(crate) mod continuous;
mod crossing_spread;
mod divergence;
mod filter;
mod held;
pub mod marks;
mod variance;
pub(crate) use filter::{below_filter_limit, zero_phase_low_pass};
pub(crate) use held::{step_metrics, step_metrics_held};

/// The lowest low-pass cut-off the metrics take, Hz (exclusive): below it
/// the filter is slower than the response ([`crate::error::Limit::FilterCutoff`]).
pub const MIN_FILTER_HZ: f64 = 1.0;
pub(crate) mod beta_sign;
pub(crate) mod initial;
pub mod measured;
mod moving_steer;
mod noise;
mod peak;
mod pulse;
mod settling;
mod steady_inside;
mod steer_lead;
pub(crate) use noise::HeldEvery;
use noise::{noise_deviation, noise_gain};
pub(crate) use steer_lead::said as steer_lead_said;
pub mod simulated;
mod step_shape;
mod variance_said;
mod yaw_per_neutral;

pub use continuous::{step_metrics_continuous, ContinuousRecord, Sample};
pub use marks::{Mark, MarkedMetric, Marks};
pub use peak::{DRAWS as PEAK_DRAWS, SEED as PEAK_SEED};
pub use simulated::{simulated_step_metrics, DenseRecord};

/// Settings of the metric computation. The fields are public for struct
/// literals; [`MetricSettings::validate`] is the check every entry runs
/// before it measures (the scenario and study readers on the `[metrics]`
/// table, [`crate::jobs::metrics::run`] on its argument), so no job measures
/// with a window that is not positive or a filter that is not a frequency.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MetricSettings {
    /// Window at the start over which initial values are averaged, s.
    #[serde(default = "default_pre")]
    pub pre_window: f64,
    /// Window at the end over which steady values are averaged, s.
    #[serde(default = "default_steady")]
    pub steady_window: f64,
    /// Weight of the yaw-rate total variance in Er.
    #[serde(default = "one")]
    pub e1: f64,
    /// Weight of the lateral-acceleration total variance in Er.
    #[serde(default = "one")]
    pub e2: f64,
    /// Length of the total-variance window from the steer onset, s.
    #[serde(default = "default_variance_window")]
    pub variance_window: f64,
    /// Cut-off of the zero-phase low-pass applied to every channel first,
    /// Hz (none: unfiltered, as for simulated records).
    #[serde(default)]
    pub filter_hz: Option<f64>,
    /// The least yaw-rate overshoot that is a peak, % of the step: below it
    /// the run has no peak time and no TB (see [`DEFAULT_MIN_OVERSHOOT`]).
    #[serde(default = "default_min_overshoot")]
    pub min_overshoot: f64,
}

/// Cut-off of the low-pass `handling metrics` applies to measured runs, Hz:
/// far above a car's yaw bandwidth (1–3 Hz), so a 16 % overshoot loses under
/// 0.01 point, and it halves white noise sampled at 100 Hz.
pub const MEASURED_FILTER_HZ: f64 = 10.0;
/// A peak must exceed the steady state by this many noise deviations.
const PEAK_NOISE: f64 = 5.0;
/// How many noise deviations r̂ must fall below the peak's level before the
/// overshoot's stretch ends ([`peak::peak_index`]'s `dip`, capped at the
/// threshold so that it never reaches below the steady state): one noise
/// dip cut a 16.9 % overshoot (2 % noise, 40 Hz) to 10.5 % at 0.305 s,
/// where the noise-free curve was still rising. Noise-free, no dip.
const PEAK_DIP_NOISE: f64 = 3.0;
/// The least overshoot that counts as a GB/T 6323 peak by default, %. Below
/// it the maximum is flat and within what a test resolves: a simulation
/// would report a peak time (and a TB) that the same run with a noise of
/// 0.07 % of the step does not show (a noisy copy of the bundled UniTire
/// step), so simulated and measured metrics of one car would disagree on
/// whether it has a peak at all. The bundled PAC89 and UniTire steps overshoot by 0.05 % and 0.12 %.
/// The value is this project's reading, not the standard's: set
/// `min_overshoot = 0` to take any maximum above the steady state.
pub const DEFAULT_MIN_OVERSHOOT: f64 = 1.0;

/// The largest least overshoot a setting may ask, % of the step: a
/// threshold beyond takes no maximum of a car's step response as an
/// overshoot, and says nothing.
pub const MAX_MIN_OVERSHOOT: f64 = 100.0;

fn default_min_overshoot() -> f64 {
    DEFAULT_MIN_OVERSHOOT
}

fn default_variance_window() -> f64 {
    4.0
}

fn default_pre() -> f64 {
    0.5
}
fn default_steady() -> f64 {
    1.0
}
fn one() -> f64 {
    1.0
}

impl MetricSettings {
    /// Checks every value: windows (s) and a cut-off (Hz) positive, weights
    /// finite and non-negative; the error names the key.
    pub fn validate(&self) -> Result<(), crate::error::ParamError> {
        use crate::error::ParamError;
        ParamError::positive("pre_window", self.pre_window)?;
        ParamError::positive("steady_window", self.steady_window)?;
        ParamError::positive("variance_window", self.variance_window)?;
        ParamError::non_negative("e1", self.e1)?;
        ParamError::non_negative("e2", self.e2)?;
        if self.e1 == 0.0 && self.e2 == 0.0 {
            // Said at the second weight: the one that left Er with none.
            let reason = crate::error::ParamReason::ErWeightsZero;
            return Err(ParamError::new("e2", self.e2, reason));
        }
        // One range for every value refused (negative, NaN, infinite or
        // above it), said by `metrics --min-overshoot` and a scenario's
        // `[metrics]` alike: "must not be negative" at -1 and "must lie in
        // [0, 100]" at 1e308 read as two different limits.
        let m = self.min_overshoot;
        if !(0.0..=MAX_MIN_OVERSHOOT).contains(&m) {
            let reason = crate::error::ParamReason::OutOfRange {
                lo: -f64::MIN_POSITIVE,
                hi: MAX_MIN_OVERSHOOT,
                why: crate::error::Limit::MinOvershoot,
            };
            return Err(ParamError::new("min_overshoot", m, reason));
        }
        if let Some(f) = self.filter_hz {
            ParamError::finite("filter_hz", f)?;
            if f <= MIN_FILTER_HZ {
                let reason = crate::error::ParamReason::OutOfRange {
                    lo: MIN_FILTER_HZ,
                    hi: f64::INFINITY,
                    why: crate::error::Limit::FilterCutoff,
                };
                return Err(ParamError::new("filter_hz", f, reason));
            }
        }
        Ok(())
    }
}

impl Default for MetricSettings {
    fn default() -> Self {
        Self {
            pre_window: default_pre(),
            steady_window: default_steady(),
            e1: 1.0,
            e2: 1.0,
            variance_window: default_variance_window(),
            filter_hz: None,
            min_overshoot: DEFAULT_MIN_OVERSHOOT,
        }
    }
}

/// Step-steer metrics. Times in s, angles in rad unless the name says deg.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct StepMetrics {
    /// Steer step δ_ss − δ₀, rad.
    pub steer_step: f64,
    /// Time zero (50 % of the steer input), s on the record's clock.
    pub time_zero: f64,
    /// Yaw-rate response time (t₀ to 90 % of steady state), s.
    pub yaw_rate_response_time: f64,
    /// Yaw-rate peak response time, s; `None` without a peak above steady state.
    pub yaw_rate_peak_time: Option<f64>,
    /// Yaw-rate overshoot, %; `None` without a peak: below
    /// the threshold the run resolves (a measured run's
    /// `yaw_rate_peak_threshold`), not a measured 0.
    pub yaw_rate_overshoot: Option<f64>,
    /// Lateral-acceleration response time, s (`None` for a run without
    /// `ay`, or one whose response time is below what the log resolves:
    /// then [`Self::ay_response_time_below`]).
    pub ay_response_time: Option<f64>,
    /// The bound the ay response time is below, s: one sample interval of
    /// a log whose steer steps within one interval and whose `ay` reaches
    /// 90 % at the first sample after the step (the crossing read is then
    /// where the samples fall, half an interval, not the response).
    /// `None` where the time is read.
    #[serde(default)]
    pub ay_response_time_below: Option<f64>,
    /// Steady-state yaw-rate gain r/δ, 1/s.
    pub yaw_rate_gain: f64,
    /// Steady-state yaw rate change, rad/s.
    pub yaw_rate_steady: f64,
    /// Steady-state lateral acceleration change, m/s² (`None` for a run without `ay`).
    pub ay_steady: Option<f64>,
    /// Steady-state sideslip change, rad (`None` without a β record).
    pub beta_steady: Option<f64>,
    /// TB = peak response time × |steady sideslip|, s·deg (GB/T 6323 unit).
    pub tb: Option<f64>,
    /// Yaw-rate total variance E_r, s.
    pub yaw_rate_total_variance: f64,
    /// Lateral-acceleration total variance E_ay, s (`None` for a run without `ay`).
    pub ay_total_variance: Option<f64>,
    /// Er = e1·E_r + e2·E_ay, s (`None` for a run without `ay`).
    pub er: Option<f64>,
    /// Whether yaw rate and ay are steady in the steady window (standard
    /// deviation below 2 % of the step); a channel not judged
    /// ([`Settling::NotJudged`]) does not unsettle it.
    pub settled: bool,
    /// The verdict on each channel's steady window.
    #[serde(default)]
    pub settling: ChannelSettling,
    /// Noise of the normalised yaw rate in the initial window (after the
    /// filter), as a share of the step.
    pub yaw_rate_noise: f64,
    /// Noise of the normalised lateral acceleration (after the filter), as
    /// a share of its step, as `yaw_rate_noise` is the yaw rate's: it adds
    /// to `E_ay` and through it to Er (`None` for a run without `ay`).
    #[serde(default)]
    pub ay_noise: Option<f64>,
    /// The overshoot a maximum needed to be a peak, % of the step: the
    /// largest of `min_overshoot`, five noise deviations, twice the
    /// steady scatter and [`Self::yaw_rate_filter_ringing`].
    #[serde(default)]
    pub yaw_rate_peak_threshold: f64,
    /// What the low-pass alone makes of the steer step, % of it: the
    /// filtered steer's overshoot beyond the raw steer's (0 unfiltered). A
    /// yaw-rate maximum within it is the filter's ringing, not a peak.
    #[serde(default)]
    pub yaw_rate_filter_ringing: f64,
    /// The low-pass applied, Hz (none: unfiltered).
    pub filter_hz: Option<f64>,
    /// How far the run's own noise moves the peak time: its standard
    /// deviation over noisy copies of the record that find it, s
    /// (`peak.rs`); `None` without a peak or without noise.
    #[serde(default)]
    pub yaw_rate_peak_time_spread: Option<f64>,
    /// The share of those copies that find the peak (within the peak
    /// time of it).
    #[serde(default)]
    pub yaw_rate_peak_found_share: Option<f64>,
    /// The share that find a maximum only farther from it: another
    /// maximum (the next one, a noise bump of the steady state), left out
    /// of the spread and said apart.
    #[serde(default)]
    pub yaw_rate_peak_stray_share: Option<f64>,
    /// How far the run's own noise moves the overshoot: its standard
    /// deviation over the same copies, percentage points of the step.
    #[serde(default)]
    pub yaw_rate_overshoot_spread: Option<f64>,
    /// How far the run's noise lifts the overshoot on average, percentage
    /// points of the step: the overshoot less its extrapolation to no
    /// noise over copies with a quarter, a half and all of the run's noise
    /// variance added again (SIMEX, `peak.rs`); the highest of a noisy curve lies above
    /// the curve's. `None` without a peak or without noise.
    #[serde(default)]
    pub yaw_rate_overshoot_noise_bias: Option<f64>,
    /// How far the run's own noise moves the yaw-rate response time: its
    /// standard deviation over the peak's noisy copies (`crossing_spread.rs`),
    /// s; `None` without noise (a simulation) or where most copies do not
    /// cross.
    #[serde(default)]
    pub yaw_rate_response_time_spread: Option<f64>,
    /// The same for the lateral acceleration's response time, s.
    #[serde(default)]
    pub ay_response_time_spread: Option<f64>,
    /// How far the noise of the initial and steady means moves the
    /// yaw-rate gain: its relative standard deviation (share of the gain).
    #[serde(default)]
    pub yaw_rate_gain_spread: Option<f64>,
    /// The yaw rate's largest value lies where the log does not measure it
    /// (samples masked and filled, a clipped flat top): peak time,
    /// overshoot and TB withheld, not below the threshold.
    #[serde(default)]
    pub yaw_rate_peak_unmeasured: bool,
    /// How long before the steer leaves its initial band the yaw rate
    /// leaves its own, s (`steer_lead.rs`): a car's yaw rate never moves
    /// first, so the steer was logged that much late against it, and the
    /// response times and total variances are read against a misaligned
    /// steer. `None` where the yaw rate moves after the steer (or the noise
    /// cannot tell).
    #[serde(default)]
    pub steer_logged_late: Option<f64>,
    /// The yaw rate still moves in its steady window (not settled, or
    /// drifting towards a steady value): its response time, peak time and
    /// overshoot are read against the mean of a moving window, and no
    /// maximum standing out is no bound on the overshoot (the steady value
    /// it would stand above is not in the record).
    #[serde(default)]
    pub yaw_rate_window_moving: bool,
    /// The lateral acceleration still moves in its steady window, as
    /// `yaw_rate_window_moving` says of the yaw rate: its response time is
    /// read against the mean of a moving window.
    #[serde(default)]
    pub ay_window_moving: bool,
    /// The sideslip still moves in its steady window, as
    /// `yaw_rate_window_moving` says of the yaw rate: its steady value is
    /// the mean of a moving window.
    #[serde(default)]
    pub beta_window_moving: bool,
    /// The length of the total-variance window where the record ends
    /// before `variance_window` from the steer onset does, s: E_r, E_ay and
    /// Er integrate over this much, not the window set. `None` where the
    /// whole window is in the record.
    #[serde(default)]
    pub total_variance_window_cut: Option<f64>,
}

/// Smallest steer step that counts as a step, rad (0.01°).
pub(crate) const MIN_STEP: f64 = 1.745e-4;

impl StepMetrics {
    /// No overshoot can be told from this run: no maximum stands above its
    /// peak threshold, and that threshold (the noise and the steady
    /// window's scatter, doubled) lies beyond
    /// [`applicability::SPIN_OVERSHOOT`] — a maximum would have to be more
    /// than twice the steady value to be seen, so "no overshoot below it"
    /// says nothing (a spinning car's yaw rate scattered by 310 % of its
    /// step and read "< 619 %").
    pub fn overshoot_unresolved(&self) -> bool {
        self.yaw_rate_overshoot.is_none()
            && !self.yaw_rate_peak_unmeasured
            && self.yaw_rate_peak_threshold > applicability::SPIN_OVERSHOOT
    }

    /// The warning of a response that has not settled in the steady window
    /// (`settled` false), for the report's `warnings`: in the typed report,
    /// so that `--json`, `metrics.json` and the terminal say the same.
    /// Names the channels that have not settled, each with its spread.
    pub fn settling_warning(&self) -> Option<String> {
        match self.settled {
            true => self.settling.approaching_warning(self.yaw_rate_gain),
            false => self.settling.not_settled_warning(self.yaw_rate_gain).or_else(|| {
                Some(format!(
                    "the response has not settled in the steady window (it spreads by more than {} % of its step beyond its noise)",
                    crate::error::Num(100.0 * SETTLED_SPREAD)
                ))
            }),
        }
    }

    /// The yaw-rate noise as the terminal says it, % of the step: two
    /// decimals, or two significant digits below 0.1 % (a noise-free
    /// run's 0.0042 % read `0.00 %`); none measured said so, not `0.00 %`
    /// (the median difference of neighbouring samples is 0 when at least
    /// half of them repeat, as a noise-free simulated record's do).
    pub fn yaw_rate_noise_text(&self) -> String {
        if self.yaw_rate_noise == 0.0 {
            "0 % of the step (none measured: at least half of its successive samples are equal)"
                .into()
        } else {
            let v = crate::format::decimals_or_digits(100.0 * self.yaw_rate_noise, 2, 2);
            format!("{v} % of the step")
        }
    }
}

fn window_mean(t: &[f64], x: &[f64], from: f64, to: f64) -> (f64, f64) {
    let (mut s, mut s2, mut n) = (0.0, 0.0, 0usize);
    for (ti, xi) in t.iter().zip(x) {
        if *ti >= from && *ti <= to {
            s += xi;
            s2 += xi * xi;
            n += 1;
        }
    }
    let m = s / n.max(1) as f64;
    (m, (s2 / n.max(1) as f64 - m * m).max(0.0).sqrt())
}

/// First time after `after` at which `y` reaches `level`, interpolated.
fn first_crossing(t: &[f64], y: &[f64], level: f64, after: f64) -> Option<f64> {
    for i in 1..t.len() {
        if t[i] < after || y[i] < level {
            continue;
        }
        if y[i - 1] >= level || t[i - 1] < after {
            return Some(t[i]);
        }
        let w = (level - y[i - 1]) / (y[i] - y[i - 1]);
        return Some(t[i - 1] + w * (t[i] - t[i - 1]));
    }
    None
}

struct Normalised {
    values: Vec<f64>,
    steady: f64,
    spread: f64,
    /// White-noise deviation of the raw normalised signal.
    noise: f64,
    /// The same read from second differences, which the signal's own
    /// slope does not enter ([`settling::ringing::still_noise`]): what
    /// lifts a swing's extrema, where the slope is nil.
    still_noise: f64,
    /// Samples in the shorter of the initial and steady windows.
    samples: usize,
    /// Samples in the steady window.
    steady_samples: usize,
    /// Where the steady window's trend heads ([`settling::trend`]).
    trend: Option<settling::Trend>,
    /// How it moves inside the steady window ([`settling::Inside`]).
    inside: settling::Inside,
}

/// `x` (raw: `raw`) normalised from its mean over the initial window,
/// ending at `pre_end` ([`initial::initial_end`]), to its mean over the
/// steady window; its noise read on `raw` times `scale` (a held channel's,
/// [`noise::held_noise_scale`]).
fn normalise(
    t: &[f64],
    (raw, x, scale): (&[f64], &[f64], f64),
    pre_end: f64,
    s: &MetricSettings,
    name: &'static str,
) -> Result<Normalised, MetricsError> {
    let (t_first, t_last) = (t[0], t[t.len() - 1]);
    let (x0, _) = window_mean(t, x, t_first, pre_end);
    let sd0 = scale * noise_deviation(raw);
    let (xs, sd) = window_mean(t, x, t_last - s.steady_window, t_last);
    let step = xs - x0;
    let in_window = |from: f64, to: f64| t.iter().filter(|&&v| v >= from && v <= to).count();
    let steady_samples = in_window(t_last - s.steady_window, t_last);
    let samples = in_window(t_first, pre_end).min(steady_samples);
    if step == 0.0 || !step.is_finite() {
        return Err(MetricsError::NoResponse(name));
    }
    let values: Vec<f64> = x.iter().map(|v| (v - x0) / step).collect();
    let noise = sd0 / step.abs();
    let still_noise = scale * settling::ringing::still_noise(raw) / step.abs();
    let (trend, inside) = steady_inside::steady_reading(t, &values, s.steady_window, t_last, noise);
    Ok(Normalised {
        values,
        steady: step,
        spread: sd / step.abs(),
        noise,
        still_noise,
        samples,
        steady_samples,
        trend,
        inside,
    })
}

/// What the low-pass alone makes of the steer step, as a share of it: the
/// filtered steer's (`filtered`, normalised as `d`) highest value from
/// `from` on above the raw steer's (`raw`) there. A zero-phase Butterworth
/// rings at a ramp's ends (a 10 Hz one lifts a 0.08 s ramp's end by about
/// 1.2 %), and a yaw rate that follows the steer (a crawl's geometry)
/// rings alike: a maximum within this is the filter's, not the car's. A
/// driver's own overshoot of the steer is in both, and no part of it; 0
/// unfiltered.
fn filter_ringing(t: &[f64], raw: &[f64], filtered: &[f64], d: &Normalised, from: f64) -> f64 {
    let (mut most_filtered, mut most_raw) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
    for i in (0..t.len()).filter(|&i| t[i] >= from) {
        most_filtered = most_filtered.max(d.values[i]);
        most_raw = most_raw.max(d.values[i] + (raw[i] - filtered[i]) / d.steady);
    }
    (most_filtered - most_raw).max(0.0)
}

#[cfg(test)]
mod tests;
