//! How a channel moves over a stretch of samples: the statistics a logger
//! hold (a stuck value) is judged against in `glitches.rs` — its zero
//! differences, mean first and second differences — and the chance of
//! such a hold — and whether the channel moves there by more than its
//! resolution ([`beyond_resolution`]). Units: the channel's own.

/// How a channel moves over a stretch of samples, the statistics a hold
/// is judged against: zero differences, differences, Σ|Δx|, Σ|Δ²x| and
/// second differences, samples already found glitched skipped.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Moves {
    zeros: usize,
    count: usize,
    d1: f64,
    d2: f64,
    count2: usize,
}

impl Moves {
    /// Over the differences of samples `from..to`.
    pub(super) fn over(x: &[f64], flagged: &[bool], from: usize, to: usize) -> Self {
        let mut m = Self::default();
        for k in from + 1..to {
            if flagged[k] || flagged[k - 1] {
                continue;
            }
            let d = x[k] - x[k - 1];
            m.zeros += usize::from(d == 0.0);
            m.count += 1;
            m.d1 += d.abs();
            if k >= from + 2 && !flagged[k - 2] {
                m.d2 += (d - (x[k - 1] - x[k - 2])).abs();
                m.count2 += 1;
            }
        }
        m
    }

    /// Both stretches together.
    pub(super) fn and(self, o: Self) -> Self {
        Self {
            zeros: self.zeros + o.zeros,
            count: self.count + o.count,
            d1: self.d1 + o.d1,
            d2: self.d2 + o.d2,
            count2: self.count2 + o.count2,
        }
    }

    /// Moving on most samples: fewer than half the differences zero.
    pub(super) fn moving(&self) -> bool {
        self.count >= 3 && 2 * self.zeros < self.count
    }

    /// The mean |Δx|.
    pub(super) fn m1(&self) -> f64 {
        self.d1 / self.count.max(1) as f64
    }

    /// Second differences at least half the first: noise, not a smooth
    /// noise-free signal.
    pub(super) fn rough(&self) -> bool {
        self.d2 / self.count2.max(1) as f64 >= 0.5 * self.m1()
    }

    /// How many holds of `len` samples chance would give a channel of `n`
    /// samples moving so: `n·p₀^(len−1)`, `p₀` the share of zero
    /// differences.
    pub(super) fn chance(&self, n: usize, len: usize) -> f64 {
        let p0 = self.zeros as f64 / self.count.max(1) as f64;
        (n as f64) * p0.powi(len as i32 - 1)
    }
}

/// Share of the differences beside a hold that must exceed the channel's
/// resolution step for the hold to be a stuck sensor's.
const BEYOND_RESOLUTION_SHARE: f64 = 0.5;

/// Whether `x` moves over samples `from..to` (glitched ones skipped) by
/// more than its resolution on at least [`BEYOND_RESOLUTION_SHARE`] of
/// the differences — by more than 1.5 times the smallest non-zero
/// difference there (the step of its last written digit or of its
/// quantisation) — or holds on fewer than [`HOLDING_SHARE`] of them. A channel with noise or motion of several steps does;
/// a settled noise-free response creeping by its last digit (a
/// simulation written to 9 significant digits) or a quantised channel
/// dithering by one count does not, and holds values by nature.
pub(super) fn beyond_resolution(x: &[f64], flagged: &[bool], from: usize, to: usize) -> bool {
    let d: Vec<f64> = (from + 1..to)
        .filter(|&k| !flagged[k] && !flagged[k - 1])
        .map(|k| (x[k] - x[k - 1]).abs())
        .collect();
    let step = d
        .iter()
        .copied()
        .filter(|v| *v > 0.0)
        .fold(f64::INFINITY, f64::min);
    if !step.is_finite() {
        return false;
    }
    // At its resolution: holding or moving by about one step, and holding
    // on a tenth of the samples at least (a channel moving steadily, a
    // sweep's, changes on every sample by alike amounts, all near the
    // smallest, and is no settled one).
    let zeros = d.iter().filter(|&&v| v == 0.0).count();
    let within = d.iter().filter(|&&v| v <= 1.5 * step).count();
    let at_resolution = zeros as f64 >= HOLDING_SHARE * d.len() as f64
        && within as f64 > (1.0 - BEYOND_RESOLUTION_SHARE) * d.len() as f64;
    !at_resolution
}

/// Least share of zero differences beside a hold for the channel to be
/// at its resolution there.
const HOLDING_SHARE: f64 = 0.1;
