//! How a measured response moves inside its steady window, read where
//! the trend over the steady window and the one before it finds none: a
//! response that turns inside the window (an overshoot not decayed) has
//! not settled, whatever its spread. Shares of the step
//! (dimensionless); times in s.

use super::settling::{part_means, trend, Trend, TREND_PARTS};

/// How a steady window's response moves inside it, relative to the step:
/// read where the trend over two windows finds none (a record ending
/// 0.6 s after an instant step, read with a 0.3 s window, sat on its
/// overshoot's decay and read the yaw-rate gain 4.4 % high, its spread
/// 1.2 % of the step and its two windows holding the rise).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Inside {
    /// The largest distance of a part's mean from the window's mean,
    /// where the window holds an extremum of the response (a part's mean
    /// beyond both end parts'), beyond the noise; 0 elsewhere.
    pub(crate) peak: f64,
    /// The range of the parts' means, beyond the noise: how far the
    /// window's mean may be off its steady value where the response turns
    /// inside it (1.6 s record, 0.3 s window: 4.4 % for a gain 4.4 % high).
    pub(crate) range: f64,
}

/// The trend of the normalised response `x` over its steady window
/// (`window` s to the record's end `to`) and the one before it, and how
/// it moves inside the steady window
/// ([`Inside`]), `noise` the raw noise deviation relative to the step.
pub(super) fn steady_reading(
    t: &[f64],
    x: &[f64],
    window: f64,
    to: f64,
    noise: f64,
) -> (Option<Trend>, Inside) {
    let from = (to - 2.0 * window).max(t[0]);
    (
        trend(t, x, from, to, noise),
        inside(t, x, to - window, to, noise),
    )
}

/// How `x` moves inside [from, to] ([`Inside`]), from the means of
/// [`TREND_PARTS`] equal parts less three deviations of two parts'
/// difference; none where a part holds no sample.
fn inside(t: &[f64], x: &[f64], from: f64, to: f64, noise: f64) -> Inside {
    let Some((m, deviation)) = part_means(t, x, (from, to), noise) else {
        return Inside::default();
    };
    let sig = 3.0 * deviation;
    let (lo, hi) = m
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
    let ends = [m[0], m[TREND_PARTS - 1]];
    let turns = ends.iter().all(|e| hi > e + sig) || ends.iter().all(|e| lo < e - sig);
    let mean = m.iter().sum::<f64>() / TREND_PARTS as f64;
    let peak = m.iter().map(|v| (v - mean).abs()).fold(0.0, f64::max);
    Inside {
        peak: if turns { (peak - sig).max(0.0) } else { 0.0 },
        range: (hi - lo - sig).max(0.0),
    }
}
