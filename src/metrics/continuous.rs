//! Step-steer metrics of a continuous record: the same GB/T 6323-2014 /
//! ISO 7401:2011 definitions and Guo Konghui's total variances as
//! [`super::step_metrics`], computed from signals that can be evaluated at any
//! time (the dense output of an error-controlled integration) instead of from
//! samples on a grid.
//!
//! - Window means and total variances are integrals, taken by 5-point
//!   Gauss–Legendre quadrature on every interval between the record's knots
//!   (integration step ends and input kinks, where the signals lose
//!   smoothness), so their error is the record's own, not a grid's.
//! - Events are roots, located to [`EVENT_TOLERANCE`] seconds by the
//!   Illinois variant of regula falsi after a scan that samples at least at
//!   every knot and every [`PROBE`] seconds: time zero (steer at 50 % of its
//!   step), the 5 % steer onset of the variance window, the 90 % crossings of
//!   yaw rate and lateral acceleration; the yaw-rate peak is the first zero
//!   of the yaw acceleration (a local maximum of the normalised yaw rate)
//!   after the normalised yaw rate first exceeds its threshold `1 +
//!   max(2·s_ss, 1e-9)` (s_ss the spread of the steady window; a simulated
//!   record has no noise), which is the first local maximum above it.
//!
//! Units: s, rad, rad/s, m/s² as in [`super::StepMetrics`].

use super::{MetricSettings, MetricsError, StepMetrics, MIN_STEP};

/// How finely events are located, s.
pub(crate) const EVENT_TOLERANCE: f64 = 1e-12;
/// Longest interval over which a crossing is looked for without sampling
/// the signal in between, s: the step response's fastest features (the
/// steer ramp, ≥ 0.05 s in practice, and the yaw mode, ~0.3 s period) are
/// far longer, so no crossing and recrossing can hide inside one.
pub(crate) const PROBE: f64 = 5e-3;

/// The signals of a step-steer record at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Sample {
    /// Front road-wheel steer, rad.
    pub steer: f64,
    /// Yaw rate, rad/s.
    pub yaw_rate: f64,
    /// Yaw acceleration, rad/s² (locates the yaw-rate peak).
    pub yaw_acceleration: f64,
    /// Lateral acceleration, m/s².
    pub ay: f64,
    /// Sideslip, rad.
    pub beta: f64,
}

/// A record whose signals can be evaluated at any time of its span.
pub trait ContinuousRecord {
    /// First and last time, s.
    fn span(&self) -> (f64, f64);
    /// Sorted times within the span (ends included) between which every
    /// signal is smooth.
    fn knots(&self) -> &[f64];
    /// The signals at `t`.
    fn sample(&mut self, t: f64) -> Sample;
}

/// Gauss–Legendre nodes on [−1, 1] and weights, 5 points (exact for
/// polynomials of degree 9).
const GL_X: [f64; 5] = [
    -0.906_179_845_938_664,
    -0.538_469_310_105_683,
    0.0,
    0.538_469_310_105_683,
    0.906_179_845_938_664,
];
const GL_W: [f64; 5] = [
    0.236_926_885_056_189,
    0.478_628_670_499_366,
    0.568_888_888_888_889,
    0.478_628_670_499_366,
    0.236_926_885_056_189,
];

/// ∫ f over [a, b], f vector-valued, Gauss–Legendre on every knot interval.
fn integrate<R: ContinuousRecord + ?Sized, const K: usize>(
    rec: &mut R,
    a: f64,
    b: f64,
    mut f: impl FnMut(f64, &Sample) -> [f64; K],
) -> [f64; K] {
    let mut sum = [0.0; K];
    if b <= a {
        return sum;
    }
    let start = rec.knots().partition_point(|k| *k <= a);
    let mut lo = a;
    let mut i = start;
    loop {
        let hi = rec.knots().get(i).copied().unwrap_or(b).min(b);
        if hi > lo {
            let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
            for (x, w) in GL_X.iter().zip(GL_W) {
                let t = mid + half * x;
                let s = rec.sample(t);
                let v = f(t, &s);
                for k in 0..K {
                    sum[k] += w * half * v[k];
                }
            }
        }
        if hi >= b {
            return sum;
        }
        lo = hi;
        i += 1;
    }
}

/// The first time in [after, end] at which `g ≥ 0`, located to
/// [`EVENT_TOLERANCE`]; `after` itself when g ≥ 0 there.
fn first_reach<R: ContinuousRecord + ?Sized>(
    rec: &mut R,
    after: f64,
    mut g: impl FnMut(&Sample) -> f64,
) -> Option<f64> {
    let (_, end) = rec.span();
    let mut ta = after;
    let mut ga = g(&rec.sample(ta));
    if ga >= 0.0 {
        return Some(ta);
    }
    let mut i = rec.knots().partition_point(|k| *k <= after);
    while ta < end {
        let knot = rec.knots().get(i).copied().unwrap_or(end);
        let tb = knot.min(ta + PROBE).min(end);
        if tb >= knot {
            i += 1;
        }
        let gb = g(&rec.sample(tb));
        if gb >= 0.0 {
            return Some(illinois(rec, &mut g, (ta, ga), (tb, gb)));
        }
        (ta, ga) = (tb, gb);
    }
    None
}

/// Root of g in [a, b] with g(a) < 0 ≤ g(b): the Illinois variant of regula
/// falsi (superlinear, never leaves the bracket), stopped when the bracket is
/// below [`EVENT_TOLERANCE`]; returns the first time at which g ≥ 0 within it.
fn illinois<R: ContinuousRecord + ?Sized>(
    rec: &mut R,
    g: &mut impl FnMut(&Sample) -> f64,
    (mut a, mut ga): (f64, f64),
    (mut b, mut gb): (f64, f64),
) -> f64 {
    let mut side = 0;
    for _ in 0..200 {
        if b - a <= EVENT_TOLERANCE {
            break;
        }
        let mut t = (a * gb - b * ga) / (gb - ga);
        if !(t > a && t < b) {
            t = 0.5 * (a + b);
        }
        let gt = g(&rec.sample(t));
        if gt >= 0.0 {
            (b, gb) = (t, gt);
            if side == 1 {
                ga *= 0.5;
            }
            side = 1;
        } else {
            (a, ga) = (t, gt);
            if side == -1 {
                gb *= 0.5;
            }
            side = -1;
        }
        if gt == 0.0 {
            return t;
        }
    }
    b
}

/// Step-steer metrics of a continuous record (unfiltered: a simulation).
pub fn step_metrics_continuous<R: ContinuousRecord + ?Sized>(
    rec: &mut R,
    s: &MetricSettings,
) -> Result<StepMetrics, MetricsError> {
    let st = Steps::of(rec, s)?;
    let t_last = st.t_last;
    let dn = |x: &Sample| (x.steer - st.d0) / st.d_step;
    let rn = |x: &Sample| (x.yaw_rate - st.r0) / st.r_step;
    let an = |x: &Sample| (x.ay - st.a0) / st.a_step;
    let t0 = first_reach(rec, st.t_first, |x| dn(x) - 0.5).ok_or(MetricsError::NoHalfStep)?;
    let (settling, r_spread) = steady_settling(rec, s, &st, t0);
    // One rule, the sampled metrics' too: `simulate` and `metrics` of
    // one history flag and mark alike.
    let [yaw_moving, ay_moving, beta_moving] = settling.windows_moving();
    // From the steer's onset, not t₀: a response may lead the steer's
    // half-way point ([`super`]).
    let onset = first_reach(rec, st.t_first, |x| dn(x) - 0.05).unwrap_or(t0);
    let tr =
        first_reach(rec, onset, |x| rn(x) - 0.9).ok_or(MetricsError::NoCrossing("yaw rate"))?;
    let ta = first_reach(rec, onset, |x| an(x) - 0.9)
        .ok_or(MetricsError::NoCrossing("lateral acceleration"))?;
    // The peak: the first local maximum of the normalised yaw rate above the
    // threshold is the first zero of its derivative after it first exceeds
    // the threshold; a maximum at the record's end is not one.
    let threshold = (2.0 * r_spread).max(s.min_overshoot / 100.0).max(1e-9);
    let level = 1.0 + threshold;
    let peak = first_reach(rec, tr, |x| rn(x) - level).and_then(|above| {
        let tp = first_reach(rec, above, |x| -x.yaw_acceleration / st.r_step)?;
        (tp < t_last).then(|| (tp, rn(&rec.sample(tp))))
    });
    let peak_time = peak.map(|(tp, _)| tp - t0);
    let beta_steady = st.bs - st.b0;
    let tb = peak_time.map(|tp| tp * beta_steady.abs().to_degrees());
    let to = (onset + s.variance_window).min(t_last);
    let [e_r, e_ay] = integrate(rec, onset, to, |_, x| {
        let d = dn(x);
        [(d - rn(x)).powi(2), (d - an(x)).powi(2)]
    });
    Ok(StepMetrics {
        steer_step: st.d_step,
        time_zero: t0,
        yaw_rate_response_time: tr - t0,
        yaw_rate_peak_time: peak_time,
        yaw_rate_overshoot: peak.map(|(_, v)| (v - 1.0) * 100.0),
        ay_response_time: Some(ta - t0),
        ay_response_time_below: None,
        yaw_rate_gain: st.r_step / st.d_step,
        yaw_rate_steady: st.r_step,
        ay_steady: Some(st.a_step),
        beta_steady: Some(beta_steady),
        tb,
        yaw_rate_total_variance: e_r,
        ay_total_variance: Some(e_ay),
        er: Some(s.e1 * e_r + s.e2 * e_ay),
        settled: settling.settled(),
        settling,
        yaw_rate_noise: 0.0,
        ay_noise: Some(0.0),
        yaw_rate_peak_threshold: threshold * 100.0,
        // Unfiltered: no ringing of a filter.
        yaw_rate_filter_ringing: 0.0,
        filter_hz: None,
        yaw_rate_peak_time_spread: None,
        yaw_rate_peak_found_share: None,
        yaw_rate_peak_stray_share: None,
        yaw_rate_overshoot_spread: None,
        yaw_rate_overshoot_noise_bias: None,
        yaw_rate_response_time_spread: None,
        ay_response_time_spread: None,
        yaw_rate_gain_spread: None,
        yaw_rate_peak_unmeasured: false,
        steer_logged_late: None,
        yaw_rate_window_moving: yaw_moving,
        ay_window_moving: ay_moving,
        beta_window_moving: beta_moving,
        total_variance_window_cut: (onset + s.variance_window > t_last).then_some(to - onset),
    })
}

/// The means of steer, yaw rate, lateral acceleration and sideslip over
/// `(a, b)`.
fn window_means<R: ContinuousRecord + ?Sized>(rec: &mut R, (a, b): (f64, f64)) -> [f64; 4] {
    integrate(rec, a, b, |_, x| [x.steer, x.yaw_rate, x.ay, x.beta]).map(|v| v / (b - a))
}

/// The record's span, its channels' initial values (means over the
/// initial window) and steady values (over the steady window), and the
/// steps between them.
struct Steps {
    t_first: f64,
    t_last: f64,
    d0: f64,
    r0: f64,
    a0: f64,
    b0: f64,
    rs: f64,
    as_: f64,
    bs: f64,
    d_step: f64,
    r_step: f64,
    a_step: f64,
}

impl Steps {
    /// The steps of `rec`; a record no longer than the two windows, a
    /// steer without a step (below [`MIN_STEP`]) or a response without
    /// one refused.
    fn of<R: ContinuousRecord + ?Sized>(
        rec: &mut R,
        s: &MetricSettings,
    ) -> Result<Self, MetricsError> {
        let (t_first, t_last) = rec.span();
        let span = t_last - t_first;
        if span <= s.pre_window + s.steady_window {
            return Err(MetricsError::TooShort {
                span,
                pre_window: s.pre_window,
                steady_window: s.steady_window,
            });
        }
        let pre = (t_first, t_first + s.pre_window);
        let steady = (t_last - s.steady_window, t_last);
        let [d0, r0, a0, b0] = window_means(rec, pre);
        let [ds, rs, as_, bs] = window_means(rec, steady);
        let (d_step, r_step, a_step) = (ds - d0, rs - r0, as_ - a0);
        if d_step == 0.0 || !d_step.is_finite() || d_step.abs() < MIN_STEP {
            return Err(MetricsError::NoStep {
                initial: d0,
                steady: ds,
                min: MIN_STEP,
                pre_window: s.pre_window,
            });
        }
        for (step, name) in [(r_step, "yaw rate"), (a_step, "lateral acceleration")] {
            if step == 0.0 || !step.is_finite() {
                return Err(MetricsError::NoResponse(name));
            }
        }
        Ok(Steps {
            t_first,
            t_last,
            d0,
            r0,
            a0,
            b0,
            rs,
            as_,
            bs,
            d_step,
            r_step,
            a_step,
        })
    }
}

/// Each channel's settling verdict from its spread in the steady window
/// and where its trend heads, with the yaw rate's spread (normalised by
/// its step), which sets the peak's threshold.
fn steady_settling<R: ContinuousRecord + ?Sized>(
    rec: &mut R,
    s: &MetricSettings,
    st: &Steps,
    t0: f64,
) -> (super::ChannelSettling, f64) {
    let (t_first, t_last) = (st.t_first, st.t_last);
    let (rs, as_, bs, b0) = (st.rs, st.as_, st.bs, st.b0);
    // Spreads of the normalised responses in the steady window, about the
    // mean (a second pass: E[x²] − m² would cancel to rounding).
    let [vr, va, vb] = integrate(rec, t_last - s.steady_window, t_last, |_, x| {
        [
            (x.yaw_rate - rs).powi(2),
            (x.ay - as_).powi(2),
            (x.beta - bs).powi(2),
        ]
    });
    // The means over sixths of the steady window and of the window before
    // it (within the record), each channel's normalised by its step, for
    // where its trend heads.
    let from = (t_last - 2.0 * s.steady_window).max(t_first);
    let w = (t_last - from) / super::settling::TREND_PARTS as f64;
    let parts: [[f64; 4]; super::settling::TREND_PARTS] = std::array::from_fn(|k| {
        let a = from + k as f64 * w;
        window_means(rec, (a, a + w))
    });
    let trend = |i: usize, x0: f64, step: f64| {
        super::settling::trend_of_parts(parts.map(|m| (m[i] - x0) / step), 0.0)
    };
    let b_scale = super::sideslip_scale(bs - b0, st.d_step);
    let b_trend = trend(3, b0, bs - b0).map(|tr| super::settling::Trend {
        heads: tr.heads * ((bs - b0) / b_scale).abs(),
        ..tr
    });
    let r_spread = (vr / s.steady_window).sqrt() / st.r_step.abs();
    let a_spread = (va / s.steady_window).sqrt() / st.a_step.abs();
    let b_spread = (vb / s.steady_window).sqrt() / b_scale;
    let [r_ring, a_ring, b_ring] = ringings(rec, st, t0, t_last - s.steady_window);
    let [r_in, a_in, b_in] = insides(rec, st, s.steady_window, b_scale);
    let b_to = ((bs - b0) / b_scale).abs();
    let with = super::settling::with_ringing;
    let settling = super::ChannelSettling {
        yaw_rate: with(
            super::Settling::of_spread(r_spread, trend(1, st.r0, st.r_step), r_in),
            r_ring,
            1.0,
            0.0,
        ),
        ay: Some(with(
            super::Settling::of_spread(a_spread, trend(2, st.a0, st.a_step), a_in),
            a_ring,
            1.0,
            0.0,
        )),
        beta: Some(with(
            super::Settling::of_spread(b_spread, b_trend, b_in),
            b_ring,
            b_to,
            0.0,
        )),
    };
    (settling, r_spread)
}

/// How each channel (yaw rate, lateral acceleration, sideslip, each
/// normalised by its step, the sideslip by `b_scale`) moves inside the
/// steady window of length `window` ([`super::settling::Inside`]): the
/// means of its equal parts, exact in a record without noise, read as a
/// measured record's are ([`super::steady_inside::of_means`]), so that
/// `simulate` and `metrics` on its history judge one window alike.
fn insides<R: ContinuousRecord + ?Sized>(
    rec: &mut R,
    st: &Steps,
    window: f64,
    b_scale: f64,
) -> [super::settling::Inside; 3] {
    const N: usize = super::settling::TREND_PARTS;
    let part = window / N as f64;
    let from = st.t_last - window;
    let m: [[f64; 4]; N] = std::array::from_fn(|k| {
        let a = from + k as f64 * part;
        window_means(rec, (a, (a + part).min(st.t_last)))
    });
    let of = |i: usize, x0: f64, step: f64| {
        super::steady_inside::of_means(&m.map(|p| (p[i] - x0) / step), 0.0)
    };
    [
        of(1, st.r0, st.r_step),
        of(2, st.a0, st.a_step),
        of(3, st.b0, b_scale),
    ]
}

/// Each channel's decaying oscillation (yaw rate, lateral acceleration,
/// sideslip, each normalised by its own step) from time zero `t0` on,
/// judged at the steady window starting at `window`
/// ([`super::settling::ringing`]), read on samples every [`PROBE`]
/// seconds: the record has no noise, and a swing of a period of a second
/// or more is resolved far finer than its extrema are judged.
fn ringings<R: ContinuousRecord + ?Sized>(
    rec: &mut R,
    st: &Steps,
    t0: f64,
    window: f64,
) -> [Option<super::settling::ringing::Ringing>; 3] {
    let n = ((st.t_last - t0) / PROBE).ceil().max(1.0) as usize;
    let t: Vec<f64> = (0..=n)
        .map(|i| (t0 + i as f64 * PROBE).min(st.t_last))
        .collect();
    let mut x = [Vec::new(), Vec::new(), Vec::new()];
    for &ti in &t {
        let v = rec.sample(ti);
        x[0].push((v.yaw_rate - st.r0) / st.r_step);
        x[1].push((v.ay - st.a0) / st.a_step);
        x[2].push((v.beta - st.b0) / (st.bs - st.b0));
    }
    x.map(|x| super::settling::ringing::ringing(&t, &x, t0, window, 0.0))
}
