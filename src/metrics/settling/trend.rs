//! Where a steady window's trend heads: the means of equal parts of the
//! steady window and the one before it, carried on as a geometric
//! approach where they slow, or by a window's change where they do not.
//! Shares of the step (dimensionless); times in s.

/// Where a steady window's trend heads, relative to the step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::metrics) struct Trend {
    /// How far beyond the window's mean the trend heads (a share of the
    /// step, ≥ 0).
    pub heads: f64,
    /// Whether it slows across the window.
    pub converging: bool,
    /// Whether it rises (on the step's scale: its limit above the
    /// window's mean).
    pub rising: bool,
}

/// The trend of the normalised response `x` (steady value 1 over the
/// steady window) at times `t`, over [`TREND_PARTS`] equal parts of the
/// span from `from` (a steady window before the steady window) to `to`
/// (the record's end), `noise` the raw noise deviation relative to the
/// step ([`trend_of_parts`]).
pub(in crate::metrics) fn trend(
    t: &[f64],
    x: &[f64],
    from: f64,
    to: f64,
    noise: f64,
) -> Option<Trend> {
    let (means, deviation) = part_means(t, x, (from, to), noise)?;
    trend_of_parts(means, deviation)
}

/// The means of `x` over [`TREND_PARTS`] equal parts of [from, to] (times
/// `t`), with the deviation of two parts' difference for a raw noise
/// deviation `noise`; none where a part holds no sample.
pub(in crate::metrics) fn part_means(
    t: &[f64],
    x: &[f64],
    (from, to): (f64, f64),
    noise: f64,
) -> Option<([f64; TREND_PARTS], f64)> {
    let part = (to - from) / TREND_PARTS as f64;
    let mut sums = [(0.0, 0usize); TREND_PARTS];
    for (ti, xi) in t.iter().zip(x) {
        if *ti >= from && *ti <= to {
            let k = (((ti - from) / part) as usize).min(TREND_PARTS - 1);
            sums[k].0 += xi;
            sums[k].1 += 1;
        }
    }
    if sums.iter().any(|s| s.1 == 0) {
        return None;
    }
    // A part's mean is uncertain by σ/√n; two parts' difference by √2 as much.
    let fewest = sums.iter().map(|s| s.1).min().unwrap_or(1) as f64;
    Some((
        sums.map(|(s, n)| s / n as f64),
        noise * (2.0 / fewest).sqrt(),
    ))
}

/// The parts a trend is read over: sixths of the steady window and of the
/// window before it.
pub(in crate::metrics) const TREND_PARTS: usize = 12;

/// The most a trend's slope may keep, across the two windows it is read
/// over, and still be read as slowing: a slope that falls by less than a
/// third there (thirds' ratio q above 0.935, a time constant over about
/// five windows) is a drift the record cannot tell from a ramp, and a
/// geometric limit extrapolated from it (d₂·q/(1 − q), fifteen thirds'
/// changes and more) is no steady value the record bounds. A logged ramp's
/// ratio read 0.9999 through the zero-phase filter's ends and was called
/// settling.
const SLOWED_BY: f64 = 2.0 / 3.0;

/// Where the trend of a normalised response (steady value 1 over its
/// steady window) heads, from the means of [`TREND_PARTS`] equal parts
/// spanning the steady window and the window before it; `deviation` is
/// the uncertainty of the difference of two parts' means (0 for a
/// noise-free simulation, where a change below 10⁻⁶ of the step is
/// rounding).
///
/// A trend is one only where every part moves the same way, each by more
/// than three deviations, over both windows: a ringing response turns back
/// within them (the spread's to judge), and noise turns a flat one back
/// and forth. The steady window's thirds' means m₁, m₂, m₃ of a geometric
/// approach x = L − c·qᵗ form a geometric sequence whose limit is
/// L = m₃ + d₂·q/(1 − q), with d₁ = m₂ − m₁, d₂ = m₃ − m₂, q = d₂/d₁ < 1; a
/// trend that does not slow (q ≥ 1, or q⁶ above [`SLOWED_BY`]) heads at
/// least a window's change beyond its last third.
pub(in crate::metrics) fn trend_of_parts(
    parts: [f64; TREND_PARTS],
    deviation: f64,
) -> Option<Trend> {
    let significant = (3.0 * deviation).max(1e-6);
    let rising = parts[1] > parts[0];
    let moves = parts.windows(2).map(|w| w[1] - w[0]);
    if moves
        .into_iter()
        .any(|d| (d > 0.0) != rising || d.abs() < significant)
    {
        return None;
    }
    let last = &parts[TREND_PARTS / 2..];
    let [m1, m2, m3] = [0, 2, 4].map(|k| 0.5 * (last[k] + last[k + 1]));
    let (d1, d2) = (m2 - m1, m3 - m2);
    if d2.abs() >= d1.abs() || (d2 / d1).powi(TREND_PARTS as i32 / 2) > SLOWED_BY {
        return Some(Trend {
            heads: (m3 - 1.0).abs() + (m3 - m1).abs(),
            converging: false,
            rising,
        });
    }
    let q = d2 / d1;
    Some(Trend {
        heads: (m3 + d2 * q / (1.0 - q) - 1.0).abs(),
        converging: true,
        rising,
    })
}

/// How a steady window's response moves inside it, relative to the step:
/// read where the trend over two windows finds none (a record ending
/// 0.6 s after an instant step, read with a 0.3 s window, sat on its
/// overshoot's decay and read the yaw-rate gain 4.4 % high, its spread
/// 1.2 % of the step and its two windows holding the rise).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(in crate::metrics) struct Inside {
    /// The largest distance of a part's mean from the window's mean,
    /// where the window holds an extremum of the response (a part's mean
    /// beyond both end parts'), beyond the noise; 0 elsewhere.
    pub(in crate::metrics) peak: f64,
    /// The range of the parts' means, beyond the noise: how far the
    /// window's mean may be off its steady value where the response turns
    /// inside it (1.6 s record, 0.3 s window: 4.4 % for a gain 4.4 % high).
    pub(in crate::metrics) range: f64,
}
