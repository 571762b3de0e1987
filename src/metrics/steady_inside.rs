//! How a response (measured, or a simulation's by [`of_means`] on its
//! exact parts' means) moves inside its steady window, read where
//! the trend over the steady window and the one before it finds none: a
//! response that turns inside the window (an overshoot not decayed) has
//! not settled, whatever its spread. Shares of the step
//! (dimensionless); times in s.

use super::settling::{part_means, trend, Inside, Trend, TREND_PARTS};

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
    match part_means(t, x, (from, to), noise) {
        Some((m, deviation)) => of_means(&m, deviation),
        None => Inside::default(),
    }
}

/// How a window whose [`TREND_PARTS`] equal parts have the means `m`
/// moves inside it ([`Inside`]), less three deviations `deviation` of two
/// parts' difference (0 for a noise-free record, whose means are exact):
/// the one reading of a measured and of a simulated record.
pub(super) fn of_means(m: &[f64; TREND_PARTS], deviation: f64) -> Inside {
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
