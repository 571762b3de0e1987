//! Step-steer metrics of GB/T 6323-2014 (GB/T 6323.2-94 in seed 004) and
//! ISO 7401:2011, and Guo Konghui's total variances (seed 004).
//!
//! From a record of steer δ(t), yaw rate r(t), lateral acceleration ay(t) and
//! optionally sideslip β(t):
//! - each signal's initial value is its mean over the first `pre_window`
//!   seconds, its steady value its mean over the last `steady_window` seconds;
//!   x̂ = (x − x₀)/(x_ss − x₀) is the normalised response;
//! - time zero t₀ is where δ̂ first reaches 0.5 (50 % of the steer input);
//! - response time: t₀ to the first time x̂ = 0.9; peak response time: t₀ to
//!   the maximum of r̂; overshoot = (max r̂ − 1)·100 %;
//! - steady-state yaw-rate gain (r_ss − r₀)/(δ_ss − δ₀), 1/s; steady sideslip
//!   β_ss − β₀, rad; TB = peak response time × steady sideslip in s·deg
//!   (GB/T's unit);
//! - total variance `E_x = ∫ (δ̂ − x̂)² dt` over the record (trapezoid), so a
//!   pure delay d gives E = d and a first-order lag τ gives E = τ/2;
//!   `Er = e1·E_r + e2·E_ay`.
//!
//! Crossings are interpolated linearly between samples. Signs: any step
//! direction; the normalisation makes left and right steps give equal metrics.

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// Settings of the metric computation.
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

impl Default for MetricSettings {
    fn default() -> Self {
        Self {
            pre_window: default_pre(),
            steady_window: default_steady(),
            e1: 1.0,
            e2: 1.0,
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
    /// Yaw-rate overshoot, % (0 without a peak).
    pub yaw_rate_overshoot: f64,
    /// Lateral-acceleration response time, s.
    pub ay_response_time: f64,
    /// Steady-state yaw-rate gain r/δ, 1/s.
    pub yaw_rate_gain: f64,
    /// Steady-state yaw rate change, rad/s.
    pub yaw_rate_steady: f64,
    /// Steady-state lateral acceleration change, m/s².
    pub ay_steady: f64,
    /// Steady-state sideslip change, rad (`None` without a β record).
    pub beta_steady: Option<f64>,
    /// TB = peak response time × |steady sideslip|, s·deg (GB/T 6323 unit).
    pub tb: Option<f64>,
    /// Yaw-rate total variance E_r, s.
    pub yaw_rate_total_variance: f64,
    /// Lateral-acceleration total variance E_ay, s.
    pub ay_total_variance: f64,
    /// Er = e1·E_r + e2·E_ay, s.
    pub er: f64,
    /// Whether yaw rate and ay are steady in the steady window (standard
    /// deviation below 2 % of the step).
    pub settled: bool,
}

/// Why the metrics could not be computed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MetricsError {
    /// Channels of different lengths or too few samples.
    #[error("a step-steer record needs at least 10 samples with equal-length channels")]
    Shape,
    /// The record is too short for the windows.
    #[error("the record ({0:.3} s) is shorter than the initial and steady windows together")]
    TooShort(f64),
    /// No steer step in the record.
    #[error(
        "no steer step: the steer changes by {0:.3e} rad between the initial and steady windows"
    )]
    NoStep(f64),
    /// A response does not change.
    #[error("the {0} does not change between the initial and steady windows")]
    NoResponse(&'static str),
    /// A response never reaches 90 % of its steady value.
    #[error("the {0} never reaches 90 % of its steady-state value")]
    NoCrossing(&'static str),
}

/// Smallest steer step that counts as a step, rad (0.01°).
const MIN_STEP: f64 = 1.745e-4;

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
}

fn normalise(
    t: &[f64],
    x: &[f64],
    s: &MetricSettings,
    name: &'static str,
) -> Result<Normalised, MetricsError> {
    let (t_first, t_last) = (t[0], t[t.len() - 1]);
    let (x0, _) = window_mean(t, x, t_first, t_first + s.pre_window);
    let (xs, sd) = window_mean(t, x, t_last - s.steady_window, t_last);
    let step = xs - x0;
    if step == 0.0 || !step.is_finite() {
        return Err(MetricsError::NoResponse(name));
    }
    Ok(Normalised {
        values: x.iter().map(|v| (v - x0) / step).collect(),
        steady: step,
        spread: sd / step.abs(),
    })
}

fn total_variance(t: &[f64], a: &[f64], b: &[f64]) -> f64 {
    let mut e = 0.0;
    for i in 1..t.len() {
        let d0 = a[i - 1] - b[i - 1];
        let d1 = a[i] - b[i];
        e += 0.5 * (d0 * d0 + d1 * d1) * (t[i] - t[i - 1]);
    }
    e
}

/// Step-steer metrics of one record.
pub fn step_metrics(
    t: &[f64],
    steer: &[f64],
    yaw_rate: &[f64],
    ay: &[f64],
    beta: Option<&[f64]>,
    s: &MetricSettings,
) -> Result<StepMetrics, MetricsError> {
    let n = t.len();
    if n < 10
        || steer.len() != n
        || yaw_rate.len() != n
        || ay.len() != n
        || beta.is_some_and(|b| b.len() != n)
    {
        return Err(MetricsError::Shape);
    }
    let span = t[n - 1] - t[0];
    if span <= s.pre_window + s.steady_window {
        return Err(MetricsError::TooShort(span));
    }
    let d = normalise(t, steer, s, "steer").map_err(|_| MetricsError::NoStep(0.0))?;
    if d.steady.abs() < MIN_STEP {
        return Err(MetricsError::NoStep(d.steady));
    }
    let r = normalise(t, yaw_rate, s, "yaw rate")?;
    let a = normalise(t, ay, s, "lateral acceleration")?;
    let t0 = first_crossing(t, &d.values, 0.5, t[0]).ok_or(MetricsError::NoStep(d.steady))?;
    let tr = first_crossing(t, &r.values, 0.9, t0).ok_or(MetricsError::NoCrossing("yaw rate"))?;
    let ta = first_crossing(t, &a.values, 0.9, t0)
        .ok_or(MetricsError::NoCrossing("lateral acceleration"))?;
    let (mut i_peak, mut peak) = (0, f64::NEG_INFINITY);
    for (i, (ti, v)) in t.iter().zip(&r.values).enumerate() {
        if *ti >= t0 && *v > peak {
            peak = *v;
            i_peak = i;
        }
    }
    // A maximum that sits at the end of the record or within the steady
    // window's scatter is not a peak.
    let has_peak = peak > 1.0 + 2.0 * r.spread.max(1e-9) && i_peak + 1 < n;
    let peak_time = has_peak.then(|| t[i_peak] - t0);
    let beta_steady = beta.map(|b| normalise(t, b, s, "sideslip").map_or(0.0, |nb| nb.steady));
    let tb = match (peak_time, beta_steady) {
        (Some(tp), Some(b)) => Some(tp * b.abs().to_degrees()),
        _ => None,
    };
    let e_r = total_variance(t, &d.values, &r.values);
    let e_ay = total_variance(t, &d.values, &a.values);
    Ok(StepMetrics {
        steer_step: d.steady,
        time_zero: t0,
        yaw_rate_response_time: tr - t0,
        yaw_rate_peak_time: peak_time,
        yaw_rate_overshoot: if has_peak { (peak - 1.0) * 100.0 } else { 0.0 },
        ay_response_time: ta - t0,
        yaw_rate_gain: r.steady / d.steady,
        yaw_rate_steady: r.steady,
        ay_steady: a.steady,
        beta_steady,
        tb,
        yaw_rate_total_variance: e_r,
        ay_total_variance: e_ay,
        er: s.e1 * e_r + s.e2 * e_ay,
        settled: r.spread < 0.02 && a.spread < 0.02,
    })
}

#[cfg(test)]
mod tests;
