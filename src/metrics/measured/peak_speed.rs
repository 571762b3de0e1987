//! The speeds a measured step's overshoot compares: at the yaw-rate peak
//! and over the steady window. The overshoot is the peak over the steady
//! value; where the speed changes between them, so does the steady yaw
//! rate the peak would settle to (`u·δ/l` for a neutral car), and a step
//! braked from 20 to 2 m/s read a 102 % overshoot that was the speed's
//! change, called a lightly damped response
//! ([`super::super::applicability::speed_explains`]). Units: m/s, s.

use super::super::{MetricSettings, StepMetrics};
use crate::measured::MeasuredRun;

/// The speed at the yaw-rate peak (the sample nearest it) and the mean
/// speed over the steady window of `piece` measured as `m` with `s`
/// (m/s); None without a peak.
pub(super) fn at_peak_and_steady(
    piece: &MeasuredRun,
    m: &StepMetrics,
    s: &MetricSettings,
) -> Option<(f64, f64)> {
    let at = m.time_zero + m.yaw_rate_peak_time?;
    let t = &piece.t;
    let nearest = (0..t.len()).min_by(|&i, &j| (t[i] - at).abs().total_cmp(&(t[j] - at).abs()))?;
    let from = t.last()? - s.steady_window;
    let steady: Vec<f64> = (0..t.len())
        .filter(|&i| t[i] >= from)
        .map(|i| piece.speed[i])
        .collect();
    let mean = steady.iter().sum::<f64>() / steady.len() as f64;
    Some((piece.speed[nearest], mean)).filter(|(p, u)| p.is_finite() && u.is_finite())
}
