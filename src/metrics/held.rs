//! Step-steer metrics of one sampled record (the definitions of the parent
//! module: GB/T 6323-2014, ISO 7401:2011, Guo Konghui's total variances
//! after Wang & Liang), in steps: the record's shape checked, the stated
//! low-pass, the channels normalised, the crossings (time zero, onset,
//! the 90 % response times), the yaw-rate peak against its noise, and the
//! settling verdicts and total variances. A channel held between updates
//! and interpolated (`HeldEvery`) has its noise read on the updates.
//!
//! Units: s, rad, rad/s, m/s² as in [`super::StepMetrics`].

use super::filter::{below_filter_limit, zero_phase_low_pass};
use super::noise::{correlation_sum, held_noise_scale, noise_deviation, noise_gain, HeldEvery};
use super::settling::ringing::{lift, ringing};
use super::settling::{sideslip_scale, verdict, with_ringing, ChannelSettling, NoiseNull};
use super::variance::total_variance;
use super::{
    crossing_spread, divergence, filter_ringing, first_crossing, initial, normalise, peak, pulse,
    steer_lead, MetricSettings, Normalised, StepMetrics, MIN_STEP, PEAK_DIP_NOISE, PEAK_NOISE,
};
use crate::error::MetricsError;

/// Step-steer metrics of one record.
pub(crate) fn step_metrics(
    t: &[f64],
    steer: &[f64],
    yaw_rate: &[f64],
    ay: Option<&[f64]>,
    beta: Option<&[f64]>,
    s: &MetricSettings,
) -> Result<StepMetrics, MetricsError> {
    step_metrics_held(t, steer, yaw_rate, ay, beta, s, HeldEvery::default())
}

/// Step-steer metrics of one record whose channels `held` were held
/// between updates and interpolated (their noise read on the updates).
pub(crate) fn step_metrics_held(
    t: &[f64],
    steer: &[f64],
    yaw_rate: &[f64],
    ay: Option<&[f64]>,
    beta: Option<&[f64]>,
    s: &MetricSettings,
    every: HeldEvery,
) -> Result<StepMetrics, MetricsError> {
    check_record(t, steer, yaw_rate, ay, beta, s)?;
    let low_pass = LowPass::of(t, s, every);
    let c = Channels::read(t, (steer, yaw_rate, ay), s, every, &low_pass)?;
    let times = Crossings::of(t, &c, yaw_rate, every.yaw_rate)?;
    let peak = Peak::of(t, steer, &c, &times, s, &low_pass);
    let beta_n = beta.map(|raw| {
        let b = low_pass.apply(raw);
        normalise(
            t,
            (raw, &b, low_pass.scale(every.beta)),
            c.pre_end,
            s,
            "sideslip",
        )
        .ok()
    });
    let mut m = metrics_of(t, &c, &times, &peak, beta_n, s, &low_pass);
    // On the raw channels: a zero-phase low-pass spreads the steer's sharp
    // start ahead of it more than the yaw rate's gradual one, and cut an
    // 80 ms lead to 62 ms.
    let raw = |x: &[f64], f: &[f64], n: &Normalised| -> Vec<f64> {
        (0..t.len())
            .map(|i| n.values[i] + (x[i] - f[i]) / n.steady)
            .collect()
    };
    m.steer_logged_late = steer_lead::yaw_rate_leads(
        t,
        (
            &raw(steer, &c.steer_f, &c.d),
            &raw(yaw_rate, &c.yaw_rate_f, &c.r),
        ),
        (c.d.noise, c.r.noise),
        (times.t0, times.tr),
        low_pass.dt,
    );
    Ok(m)
}

/// The record refused where its channels' lengths differ, it has fewer
/// than 10 samples, or it is no longer than the initial and steady
/// windows together.
fn check_record(
    t: &[f64],
    steer: &[f64],
    yaw_rate: &[f64],
    ay: Option<&[f64]>,
    beta: Option<&[f64]>,
    s: &MetricSettings,
) -> Result<(), MetricsError> {
    let n = t.len();
    if n < 10
        || steer.len() != n
        || yaw_rate.len() != n
        || ay.is_some_and(|a| a.len() != n)
        || beta.is_some_and(|b| b.len() != n)
    {
        let mut lengths = vec![
            ("t", n),
            ("steer", steer.len()),
            ("yaw_rate", yaw_rate.len()),
        ];
        lengths.extend(ay.map(|a| ("ay", a.len())));
        lengths.extend(beta.map(|b| ("beta", b.len())));
        return Err(MetricsError::Shape { lengths });
    }
    let span = t[n - 1] - t[0];
    if span <= s.pre_window + s.steady_window {
        return Err(MetricsError::TooShort {
            span,
            pre_window: s.pre_window,
            steady_window: s.steady_window,
        });
    }
    Ok(())
}

/// The stated low-pass, when one is asked for and the sampling allows it
/// (below 0.4 of the sampling rate), at the record's median interval.
struct LowPass {
    dt: f64,
    hz: Option<f64>,
    /// How the channels were held between updates.
    every: HeldEvery,
}

impl LowPass {
    fn of(t: &[f64], s: &MetricSettings, every: HeldEvery) -> Self {
        let dt = crate::measured::clean::median_interval(t);
        let hz = s
            .filter_hz
            .filter(|f| *f > 0.0 && below_filter_limit(*f, dt));
        LowPass { dt, hz, every }
    }

    /// `x` filtered (as it is without a filter).
    fn apply(&self, x: &[f64]) -> Vec<f64> {
        match self.hz {
            Some(f) => zero_phase_low_pass(x, self.dt, f),
            None => x.to_vec(),
        }
    }

    /// The filter's white-noise gain `√Σh²` (1 without one).
    fn gain(&self) -> f64 {
        self.hz.map_or(1.0, |f| noise_gain(self.dt, f))
    }

    /// The noise scale of a channel held `every` samples.
    fn scale(&self, every: usize) -> f64 {
        held_noise_scale(every, self.dt, self.hz)
    }

    /// The null distribution of a channel held `every` samples whose
    /// noise was read on `read_on` samples: its noise, white at the
    /// updates, correlated by the hold over `every` samples and by the
    /// low-pass run at the updates' interval ([`correlation_sum`]).
    fn null(&self, every: usize, read_on: usize) -> NoiseNull {
        let k = every.max(1);
        let at = k as f64 * self.dt;
        let filtered = self
            .hz
            .filter(|f| below_filter_limit(*f, at))
            .map_or(1.0, |f| correlation_sum(at, f));
        NoiseNull {
            per_dof: k as f64 * filtered,
            read_on: read_on / k,
        }
    }
}

/// The steer, yaw rate and lateral acceleration normalised, with the
/// filtered signals the crossings and the peak read.
struct Channels {
    steer_f: Vec<f64>,
    yaw_rate_f: Vec<f64>,
    /// The end of the initial window ([`initial::initial_end`]).
    pre_end: f64,
    d: Normalised,
    r: Normalised,
    a: Option<Normalised>,
}

impl Channels {
    /// The channels normalised; a steer without a step (or below
    /// [`MIN_STEP`]) refused as [`pulse::no_step`] says it.
    fn read(
        t: &[f64],
        (steer, yaw_rate, ay): (&[f64], &[f64], Option<&[f64]>),
        s: &MetricSettings,
        every: HeldEvery,
        low_pass: &LowPass,
    ) -> Result<Self, MetricsError> {
        let (steer_f, yaw_rate_f) = (low_pass.apply(steer), low_pass.apply(yaw_rate));
        let ay_f = ay.map(|a| low_pass.apply(a));
        let no_step = || pulse::no_step(t, steer, &steer_f, s);
        let pre_end = initial::initial_end(t, steer, s);
        let scale = |k: usize| low_pass.scale(k);
        let d = normalise(
            t,
            (steer, &steer_f, scale(every.steer)),
            pre_end,
            s,
            "steer",
        )
        .map_err(|_| no_step())?;
        if d.steady.abs() < MIN_STEP {
            return Err(no_step());
        }
        let r = normalise(
            t,
            (yaw_rate, &yaw_rate_f, scale(every.yaw_rate)),
            pre_end,
            s,
            "yaw rate",
        )?;
        let a = match (ay, ay_f.as_deref()) {
            (Some(raw), Some(f)) => Some(normalise(
                t,
                (raw, f, scale(every.ay)),
                pre_end,
                s,
                "lateral acceleration",
            )?),
            _ => None,
        };
        Ok(Channels {
            steer_f,
            yaw_rate_f,
            pre_end,
            d,
            r,
            a,
        })
    }
}

/// The record's times: time zero `t0` (steer at 50 %), the steer's onset
/// (5 %), the yaw rate's and the lateral acceleration's 90 % crossings.
struct Crossings {
    t0: f64,
    onset: f64,
    tr: f64,
    ta: Option<f64>,
}

impl Crossings {
    /// The crossings; a yaw rate (raw: `yaw_rate`, held `every` samples)
    /// growing exponentially once the steer is held refused.
    fn of(t: &[f64], c: &Channels, yaw_rate: &[f64], every: usize) -> Result<Self, MetricsError> {
        let d = &c.d;
        let t0 = first_crossing(t, &d.values, 0.5, t[0]).ok_or(MetricsError::NoHalfStep)?;
        // The 90 % crossings are looked for from the steer's onset, not from
        // time zero: at a crawl the lateral acceleration (through v̇) leads the
        // steer's half-way point, and a search from t₀ would find t₀ itself.
        let onset = first_crossing(t, &d.values, 0.05, t[0]).unwrap_or(t0);
        // A yaw rate growing exponentially once the steer is held: refused.
        let held = first_crossing(t, &d.values, 0.9, onset).unwrap_or(onset);
        let sd_r = every.max(1) as f64 * noise_deviation(yaw_rate);
        divergence::refuse(t, &c.yaw_rate_f, held, sd_r, c.r.steady)?;
        let tr = first_crossing(t, &c.r.values, 0.9, onset)
            .ok_or(MetricsError::NoCrossing("yaw rate"))?;
        let ta = match &c.a {
            Some(a) => Some(
                first_crossing(t, &a.values, 0.9, onset)
                    .ok_or(MetricsError::NoCrossing("lateral acceleration"))?,
            ),
            None => None,
        };
        Ok(Crossings { t0, onset, tr, ta })
    }
}

/// The yaw-rate peak: its index (none without one), its threshold over
/// the steady state, the filter's ringing and the spread of its reading.
struct Peak {
    at: Option<usize>,
    threshold: f64,
    ringing: f64,
    spread: Option<peak::PeakSpread>,
}

impl Peak {
    /// The first local maximum after the 90 % crossing that stands
    /// above the steady state by more than the noise allows, and by more
    /// than the low-pass alone makes of the steer step; a maximum at the
    /// record's end is not one.
    fn of(
        t: &[f64],
        steer: &[f64],
        c: &Channels,
        times: &Crossings,
        s: &MetricSettings,
        low_pass: &LowPass,
    ) -> Self {
        let r_noise = low_pass.gain() * c.r.noise;
        let ringing = filter_ringing(t, steer, &c.steer_f, &c.d, times.t0);
        let threshold = (PEAK_NOISE * r_noise)
            .max(2.0 * c.r.spread)
            .max(s.min_overshoot / 100.0)
            .max(ringing)
            .max(1e-9);
        // A dip of the noise alone does not end the overshoot (peak.rs).
        let level = (1.0 + threshold, (PEAK_DIP_NOISE * r_noise).min(threshold));
        let v = &c.r.values;
        let at = peak::peak_index(t, v, times.tr, level);
        let filtered = |x: &[f64]| low_pass.apply(x);
        // A copy's peak counts within the peak time of the reported one
        // (peak.rs: past twice it is another maximum).
        let spread = at.and_then(|i| {
            let window = (t[i], t[i] - times.t0);
            peak::peak_spread(t, v, (times.tr, level), c.r.noise, &filtered, window)
        });
        Peak {
            at,
            threshold,
            ringing,
            spread,
        }
    }
}

/// The metrics of the channels `c` read at `times` with the yaw-rate
/// peak `peak`, the sideslip (normalised: `beta_n`, none where it could
/// not be) and the settling verdicts.
fn metrics_of(
    t: &[f64],
    c: &Channels,
    times: &Crossings,
    peak: &Peak,
    beta_n: Option<Option<Normalised>>,
    s: &MetricSettings,
    low_pass: &LowPass,
) -> StepMetrics {
    let (d, r, gain) = (&c.d, &c.r, low_pass.gain());
    let r_noise = gain * r.noise;
    let t0 = times.t0;
    let peak_time = peak.at.map(|i| t[i] - t0);
    let beta_steady = beta_n
        .as_ref()
        .map(|nb| nb.as_ref().map_or(0.0, |nb| nb.steady));
    // The sideslip's spread and noise on the scale of [`sideslip_scale`].
    let t_last = t[t.len() - 1];
    let from = (t0, t_last - s.steady_window);
    let settling = settling_of(t, from, c, beta_n.as_ref(), low_pass);
    let [yaw_moving, ay_moving, beta_moving] = settling.windows_moving();
    let tb = match (peak_time, beta_steady) {
        (Some(tp), Some(b)) => Some(tp * b.abs().to_degrees()),
        _ => None,
    };
    let window = (times.onset, times.onset + s.variance_window);
    let e_r = total_variance(t, &d.values, &r.values, window.0, window.1);
    let e_ay =
        c.a.as_ref()
            .map(|a| total_variance(t, &d.values, &a.values, window.0, window.1));
    let spreads = response_spreads(t, c, times, low_pass);
    StepMetrics {
        steer_step: d.steady,
        time_zero: t0,
        yaw_rate_response_time: times.tr - t0,
        yaw_rate_peak_time: peak_time,
        yaw_rate_overshoot: peak.at.map(|i| (r.values[i] - 1.0) * 100.0),
        ay_response_time: times.ta.map(|ta| ta - t0),
        ay_response_time_below: None,
        yaw_rate_gain: r.steady / d.steady,
        yaw_rate_steady: r.steady,
        ay_steady: c.a.as_ref().map(|a| a.steady),
        beta_steady,
        tb,
        yaw_rate_total_variance: e_r,
        ay_total_variance: e_ay,
        er: e_ay.map(|e_ay| s.e1 * e_r + s.e2 * e_ay),
        settled: settling.settled(),
        settling,
        yaw_rate_noise: r_noise,
        ay_noise: c.a.as_ref().map(|a| gain * a.noise),
        yaw_rate_peak_threshold: peak.threshold * 100.0,
        yaw_rate_filter_ringing: peak.ringing * 100.0,
        filter_hz: low_pass.hz,
        yaw_rate_peak_time_spread: peak.spread.map(|s| s.sd),
        yaw_rate_peak_found_share: peak.spread.map(|s| s.found),
        yaw_rate_peak_stray_share: peak.spread.map(|s| s.stray),
        yaw_rate_overshoot_spread: peak.spread.map(|s| 100.0 * s.overshoot_sd),
        yaw_rate_overshoot_noise_bias: peak.spread.and_then(|s| s.height_bias).map(|b| 100.0 * b),
        yaw_rate_response_time_spread: spreads[0],
        ay_response_time_spread: spreads[1],
        yaw_rate_gain_spread: crossing_spread::gain_spread(r, d),
        yaw_rate_peak_unmeasured: false,
        // Read on the raw record by `step_metrics_held`.
        steer_logged_late: None,
        // One rule, the continuous metrics' too.
        yaw_rate_window_moving: yaw_moving,
        ay_window_moving: ay_moving,
        beta_window_moving: beta_moving,
        total_variance_window_cut: (window.1 > t_last).then_some(t_last - window.0),
    }
}

/// The verdict on each channel of `c` (and the sideslip, `beta_n`) of a
/// record at times `t`, judged against its noise after `low_pass`, and
/// on whether it still swings at its steady window (`from`: time zero
/// and the window's start; [`ringing`]), its swing judged less the lift
/// its noise gives its extrema ([`lift`]: none of a record whose
/// neighbours differ by its own slope, as `simulate`'s history does).
fn settling_of(
    t: &[f64],
    (t0, window): (f64, f64),
    c: &Channels,
    beta_n: Option<&Option<Normalised>>,
    low_pass: &LowPass,
) -> ChannelSettling {
    let (every, gain, n) = (low_pass.every, low_pass.gain(), t.len());
    let judged = |x: &Normalised, to_scale: f64, held: usize| {
        let noise = gain * x.noise;
        let v = verdict(x, noise, to_scale, low_pass.null(held, n));
        let ring = ringing(t, &x.values, t0, window, noise);
        with_ringing(v, ring, to_scale, gain * lift(x.noise, x.still_noise, held))
    };
    ChannelSettling {
        yaw_rate: judged(&c.r, 1.0, every.yaw_rate),
        ay: c.a.as_ref().map(|a| judged(a, 1.0, every.ay)),
        beta: beta_n.and_then(|nb| nb.as_ref()).map(|nb| {
            let to_scale = nb.steady.abs() / sideslip_scale(nb.steady, c.d.steady);
            judged(nb, to_scale, every.beta)
        }),
    }
}

/// How far the run's noise moves the yaw rate's and the lateral
/// acceleration's 90 % crossings (`crossing_spread.rs`), s.
fn response_spreads(
    t: &[f64],
    c: &Channels,
    times: &Crossings,
    low_pass: &LowPass,
) -> [Option<f64>; 2] {
    let filtered = |x: &[f64]| low_pass.apply(x);
    let from = (times.onset, 0.9);
    [
        crossing_spread::crossing_spread(t, &c.r.values, from, (c.r.noise, c.r.samples), &filtered),
        c.a.as_ref().and_then(|a| {
            crossing_spread::crossing_spread(t, &a.values, from, (a.noise, a.samples), &filtered)
        }),
    ]
}
