//! The measured response channels the diagnosis compares a replay with:
//! yaw rate (rad/s), lateral acceleration from the accelerometer (m/s²) and
//! sideslip at the centre of gravity (rad), ISO 8855 signs (left positive).
//! A run carries the yaw rate always, the other two when logged. Per
//! channel, the squared errors of a replay pool over runs into an RMS, and
//! the channels into one error scaled by each channel's noise scale.

use crate::measured::MeasuredRun;
use serde::Serialize;

/// A measured channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Channel {
    /// Yaw rate, rad/s.
    YawRate,
    /// Lateral acceleration (accelerometer), m/s².
    Ay,
    /// Sideslip, rad.
    Beta,
}

impl Channel {
    /// All channels.
    pub const ALL: [Channel; 3] = [Channel::YawRate, Channel::Ay, Channel::Beta];
    /// Name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Channel::YawRate => "yaw_rate",
            Channel::Ay => "ay",
            Channel::Beta => "beta",
        }
    }
    /// Unit.
    pub fn unit(self) -> &'static str {
        match self {
            Channel::YawRate => "rad/s",
            Channel::Ay => "m/s²",
            Channel::Beta => "rad",
        }
    }
    /// Index in per-channel arrays.
    pub fn index(self) -> usize {
        self as usize
    }
    /// The channel of a run, if measured.
    pub fn of(self, run: &MeasuredRun) -> Option<&[f64]> {
        match self {
            Channel::YawRate => Some(&run.yaw_rate),
            Channel::Ay => run.ay.as_deref(),
            Channel::Beta => run.beta.as_deref(),
        }
    }
}

/// Squared residuals and counts per channel, to be pooled over runs.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ChannelErrors {
    /// Σ e² per channel (units²).
    pub sum_sq: [f64; 3],
    /// Samples per channel.
    pub count: [usize; 3],
}

impl ChannelErrors {
    /// Adds another run's errors.
    pub fn add(&mut self, o: &ChannelErrors) {
        for c in 0..3 {
            self.sum_sq[c] += o.sum_sq[c];
            self.count[c] += o.count[c];
        }
    }
    /// RMS of a channel (None when not measured).
    pub fn rms(&self, c: Channel) -> Option<f64> {
        let i = c.index();
        (self.count[i] > 0).then(|| (self.sum_sq[i] / self.count[i] as f64).sqrt())
    }
    /// The combined error `J = sqrt(Σ_c n_c·(rms_c/s_c)² / Σ n_c)`.
    pub fn combined(&self, scales: &[f64; 3]) -> f64 {
        let n: usize = self.count.iter().sum();
        let s: f64 = (0..3)
            .map(|c| self.sum_sq[c] / (scales[c] * scales[c]))
            .sum();
        (s / n.max(1) as f64).sqrt()
    }
}

/// The gap above noise `G = sqrt(J² − J_n²)` of a combined error `j` over
/// the noise alone's `jn` (0 within noise).
pub(crate) fn gap_above(j: f64, jn: f64) -> f64 {
    (j * j - jn * jn).max(0.0).sqrt()
}

/// The share (%) of the gap above noise of `before` that `after` removes,
/// `100·(1 − G_after/G_before)` (0 without a gap before).
pub(crate) fn reduction(before: f64, after: f64, jn: f64) -> f64 {
    let g0 = gap_above(before, jn);
    if g0 <= 0.0 {
        0.0
    } else {
        100.0 * (1.0 - gap_above(after, jn) / g0)
    }
}
