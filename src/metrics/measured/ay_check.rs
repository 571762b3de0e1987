//! The check of a measured run's `ay` against its yaw rate: at a steady
//! state `ay = u·r` (ISO 8855, `β̇ = 0`), so over a step the steady change
//! of `ay` must match the speed times the steady change of the yaw rate (a
//! bank's constant `g·sin θ` cancels over the step). A dead accelerometer
//! logging noise, a gain in g, a channel of another axis fail it; the ay
//! metrics are then left out, not read from it.
//!
//! The speed is the steady window's own (its mean over the samples the
//! yaw rate's steady value is read from): `ay = u·r` holds sample by
//! sample, so the steady `ay` goes with the steady window's `u`. The
//! piece's median speed was used before, and a step braked from 25 to
//! 10 m/s, whose steady `ay` (0.724 m/s²) is its steady window's
//! 11.3 m/s × 0.0633 rad/s to 2 %, was checked at 18.8 m/s and its
//! accelerometer called wrong.
//!
//! Both changes are read from samples the logger measured: the initial
//! window's samples before the step (its time zero), and the
//! steady window's, none of them masked by the cleaning (a masked sample is
//! filled from its neighbours, and a masked initial window from the first
//! sample after the step: a 10 Hz log's correct 1.40 m/s² step of `ay`
//! read 0.652 m/s² and was called a sensor fault). Where a window holds
//! fewer than [`AY_CHECK_SAMPLES`] such samples (a coarse log, a short
//! window) the check is said not to be made, not failed.
//! Units: SI, rad, s.

use super::super::{MetricSettings, StepMetrics};
use crate::measured::MeasuredRun;

/// The share of `u·Δr` by which a steady `Δay` may differ from it before
/// the accelerometer is said to disagree with the gyro: at a steady state
/// `ay = u·r`, over a step the bank's constant cancels; what else moves it
/// is the body's roll, which tilts an accelerometer fixed to the body into
/// `g·sin φ` (an SUV's 7°/g roll gradient adds 12 % of ay), and a speed
/// read a few percent off; 30 % is a sensor fault (a gain of 1.4, a gain
/// in g, a dead accelerometer logging noise, a channel of another axis),
/// not a car.
pub const AY_DISAGREES: f64 = 0.3;

/// The metrics a run without a usable `ay` leaves out, as the warnings
/// name them.
pub(crate) const AY_METRICS: &str = "ay response time, steady ay, E_ay and Er";

/// The smallest `|u·Δr|` the check judges, m/s²: below it an
/// accelerometer's noise and offset drift are of its size.
pub const AY_CHECKED_FROM: f64 = 0.5;

/// The fewest measured samples each window must hold for the check: one
/// sample is one reading, with all its noise, and none is no reading.
pub const AY_CHECK_SAMPLES: usize = 2;

/// What the check reads from a piece: the means' changes and the samples
/// they stand on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct AyBasis {
    /// The steady change of `ay`, m/s².
    ay: f64,
    /// The steady change of the yaw rate, rad/s.
    yaw_rate: f64,
    /// The mean speed over the steady window, m/s.
    speed: f64,
    /// The initial window's measured samples before the step.
    before: usize,
    /// The steady window's measured samples.
    after: usize,
    /// The initial window read, s: its start and its end or the step's
    /// time zero, the earlier.
    before_span: (f64, f64),
    /// The steady window, s.
    after_span: (f64, f64),
}

/// The check's verdict.
#[derive(Debug, Clone, PartialEq)]
pub enum AyCheck {
    /// `ay` agrees with `u·r`, or is too small to judge, or is missing.
    Agrees,
    /// It disagrees: the warning, and the ay metrics are left out.
    Disagrees(String),
    /// Too few measured samples to compare: the warning, and the ay
    /// metrics are kept.
    Unchecked(String),
}

/// The mean of `x` over the samples `i` of `keep`, and their count.
fn mean_over(x: &[f64], keep: &[usize]) -> (f64, usize) {
    let n = keep.len();
    let sum: f64 = keep.iter().map(|&i| x[i]).sum();
    (sum / n.max(1) as f64, n)
}

/// The check's basis on the cleaned `piece` (its `masked` samples not yet
/// filled) measured as `m` with `s`; None without `ay`.
pub(crate) fn ay_basis(
    piece: &MeasuredRun,
    m: &StepMetrics,
    s: &MetricSettings,
) -> Option<AyBasis> {
    let ay = piece.ay.as_deref()?;
    let t = &piece.t;
    let (first, last) = (*t.first()?, *t.last()?);
    let mut masked = vec![false; t.len()];
    for &i in &piece.masked {
        masked[i] = true;
    }
    // Before the step: ahead of the steer's half-way point, time zero
    // (the metrics check the steer held over the initial window, to its
    // noise; a first sample's noise is no onset).
    let onset = m.time_zero;
    let window_end = crate::metrics::initial::initial_end(t, &piece.steer, s);
    let before: Vec<usize> = (0..t.len())
        .filter(|&i| !masked[i] && t[i] <= window_end && t[i] < onset)
        .collect();
    let from = last - s.steady_window;
    let after: Vec<usize> = (0..t.len())
        .filter(|&i| !masked[i] && t[i] >= from)
        .collect();
    let change = |x: &[f64]| mean_over(x, &after).0 - mean_over(x, &before).0;
    // The speed is an input, repaired by the cleaning, not masked: every
    // sample of the window reads it.
    let steady: Vec<usize> = (0..t.len()).filter(|&i| t[i] >= from).collect();
    Some(AyBasis {
        ay: change(ay),
        yaw_rate: change(&piece.yaw_rate),
        speed: mean_over(&piece.speed, &steady).0,
        before: before.len(),
        after: after.len(),
        before_span: (first, window_end.min(onset)),
        after_span: (from, last),
    })
}

/// The verdict on the basis `b` of piece `piece`, at the steady window's
/// speed.
pub(crate) fn ay_check(b: &AyBasis, piece: &str) -> AyCheck {
    let u = b.speed;
    let expected = u * b.yaw_rate;
    let few = b.before < AY_CHECK_SAMPLES || b.after < AY_CHECK_SAMPLES;
    if !expected.is_finite() || expected.abs() < AY_CHECKED_FROM {
        return AyCheck::Agrees;
    }
    if few {
        return AyCheck::Unchecked(format!(
            "{piece}: `ay` is not checked against the speed times the yaw rate (at a steady state ay = u·r): the check reads samples the logger measured (none the cleaning masked), and the initial window holds {} before the step ({}–{} s) and the steady window {} ({}–{} s), fewer than {AY_CHECK_SAMPLES} in one of them; the ay metrics are given unchecked: log faster or widen the window (--pre-window, --steady-window) to check them",
            b.before,
            crate::format::fixed(b.before_span.0, 2),
            crate::format::fixed(b.before_span.1, 2),
            b.after,
            crate::format::fixed(b.after_span.0, 2),
            crate::format::fixed(b.after_span.1, 2),
        ));
    }
    if (b.ay - expected).abs() <= AY_DISAGREES * expected.abs() {
        return AyCheck::Agrees;
    }
    AyCheck::Disagrees(format!(
        "{piece}: the steady change of `ay` ({} m/s²) disagrees with the speed times that of the yaw rate ({} m/s × {} rad/s = {} m/s²) by more than {} % (u is the speed over the steady window, where the steady values are read): at a steady state ay = u·r, so the accelerometer or the gyro is wrong (a dead accelerometer logging noise, a gain, unit or sign, another axis); the ay metrics ({AY_METRICS}) are left out (null in --json), not read from it",
        crate::format::readable(b.ay, 3),
        crate::format::readable(u, 3),
        crate::format::readable(b.yaw_rate, 3),
        crate::format::readable(expected, 3),
        crate::format::fixed(100.0 * AY_DISAGREES, 0)
    ))
}
