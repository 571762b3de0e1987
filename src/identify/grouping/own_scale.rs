//! Splitting one gap-separated group of a grouping variable's sorted
//! samples (load, camber, pressure) into levels on its own scale: a
//! histogram of [`OWN_SCALE_BINS`] bins across the group, cut at density
//! valleys that separate levels, and only at those (the method is
//! described in [`super`]). Units: the variable's own (N, rad, Pa).
//!
//! What a rig produces decides the rule. A load-controlled rig scatters
//! about each level by a fraction of the load plus a floor (the Hoosier
//! TTC file: robust deviation 47 N at 534 N, 71 N at 2751 N): one level of
//! ~100 samples with 1 % noise at 6000 N spreads over ±150 N, and its tail
//! bins hold a sample or two, so an empty bin among them is no boundary
//! (rig_n3 of round 40 read its 6000 N level as 5899, 6007 and 6112 N). A
//! cut must be a dip below a tenth of the smaller of the highest bins on
//! its two sides, at least the resolution wide (no gap between a quantised
//! channel's steps), with a mode's share of the group each side, and the
//! medians of the parts on its two sides at least [`SEPARATED`] of their
//! within-level deviations apart (a cut inside one Gaussian leaves parts
//! about 2–3 deviations apart). The samples of a valley then join the
//! level within whose scatter they lie ([`TAIL`] deviations): a level
//! keeps its tails, and only samples far from both levels (a ramp between
//! them) are transitions.

use std::ops::Range;

/// Bins across a group (or a part the separation-wide bins found) when
/// its valleys are looked for on its own scale.
const OWN_SCALE_BINS: usize = 32;
/// Share of a group's samples each side of a valley must hold for the
/// valley to split it on its own scale.
const OWN_SCALE_MODE: f64 = 0.05;
/// A bin is in a valley when it holds less than this share of the smaller
/// of the highest bins on its two sides (or fewer than 1 % of the group):
/// two Gaussian levels 7.5 deviations apart dip to 0.2 % of their peaks
/// between them, while a load wandering sinusoidally about one level
/// (the ramp test in `levels.rs`) dips to 18 % at its middle, 32 bins
/// across it.
const DIP: f64 = 0.1;
/// Within-level deviations between the medians of the two sides of a
/// valley for it to separate two levels: two rig loads 10 % apart with
/// 1 % noise lie 10 deviations apart, the parts of one Gaussian cut at a
/// chance dip 2–3.
const SEPARATED: f64 = 4.0;
/// Within-level deviations from a level's median inside which a valley's
/// sample belongs to the level: a Gaussian's sample lies beyond on the
/// valley's side with probability 3·10⁻⁵, while a ramp's sample farther
/// from a level than its scatter reaches is no sample at its load (a
/// condition is fitted at its level's nominal load).
const TAIL: f64 = 4.0;

/// The median of `sorted` (the mean of its two middle values for an
/// even count).
pub(super) fn median(sorted: &[f64]) -> f64 {
    let n = sorted.len();
    if n % 2 == 1 {
        sorted[n / 2]
    } else {
        0.5 * (sorted[n / 2 - 1] + sorted[n / 2])
    }
}

/// Robust deviation (1.4826·MAD) of sorted values about their median; 0
/// for none.
fn deviation(sorted: &[f64]) -> f64 {
    if sorted.is_empty() {
        return 0.0;
    }
    let m = median(sorted);
    let mut dev: Vec<f64> = sorted.iter().map(|v| (v - m).abs()).collect();
    dev.sort_by(f64::total_cmp);
    1.4826 * median(&dev)
}

/// A group's histogram on its own scale.
struct Histogram<'a> {
    group: &'a [f64],
    lo: f64,
    width: f64,
    counts: [usize; OWN_SCALE_BINS],
}

impl<'a> Histogram<'a> {
    fn new(group: &'a [f64]) -> Self {
        let lo = group[0];
        let width = (group[group.len() - 1] - lo) / OWN_SCALE_BINS as f64;
        let mut h = Self {
            group,
            lo,
            width,
            counts: [0; OWN_SCALE_BINS],
        };
        for &v in group {
            h.counts[h.bin(v)] += 1;
        }
        h
    }
    fn bin(&self, v: f64) -> usize {
        (((v - self.lo) / self.width) as usize).min(OWN_SCALE_BINS - 1)
    }
    /// Index of the first sample in bin `b` or above.
    fn start(&self, b: usize) -> usize {
        self.group.partition_point(|&v| self.bin(v) < b)
    }
    /// The samples in bins `from..to`.
    fn samples(&self, from: usize, to: usize) -> &'a [f64] {
        &self.group[self.start(from)..self.start(to)]
    }
    /// Which bins from `since` on are low: below [`DIP`] of the smaller of
    /// the highest bins on their two sides, or below the 1 % (at least 3
    /// samples) that makes a bin dense.
    fn low(&self, since: usize) -> [bool; OWN_SCALE_BINS] {
        let keep = (self.group.len() / 100).max(3) as f64;
        let mut low = [false; OWN_SCALE_BINS];
        for (k, is_low) in low.iter_mut().enumerate().skip(since) {
            let left = self.counts[since..=k].iter().max().copied().unwrap_or(0);
            let right = self.counts[k..].iter().max().copied().unwrap_or(0);
            let floor = keep.max(DIP * left.min(right) as f64);
            *is_low = (self.counts[k] as f64) < floor;
        }
        low
    }
}

/// Splits `group` (sorted) into levels on its own scale (see the module
/// doc); `noise` (the variable's noise read from consecutive samples) is
/// the floor of a level's deviation, so that a few samples in a sliver of
/// bins do not read as a level of no scatter. Returns the levels as index
/// ranges of `group`; samples between them are transitions.
pub(super) fn split_own_scale(group: &[f64], resolution: f64, noise: f64) -> Vec<Range<usize>> {
    let n = group.len();
    if n < 2 * OWN_SCALE_BINS || group[n - 1] <= group[0] {
        let whole = 0..n;
        return vec![whole];
    }
    let h = Histogram::new(group);
    let mut cores = Vec::new();
    let mut since = 0;
    while let Some((a, b)) = valley(&h, since, resolution, noise) {
        cores.push(h.start(since)..h.start(a));
        since = b + 1;
    }
    cores.push(h.start(since)..n);
    widen(group, cores, noise)
}

/// The first valley from bin `since` on that separates two levels, as its
/// first and last bin.
fn valley(h: &Histogram, since: usize, resolution: f64, noise: f64) -> Option<(usize, usize)> {
    let low = h.low(since);
    let least = (OWN_SCALE_MODE * h.group.len() as f64).ceil() as usize;
    let mut k = since + 1;
    while k < OWN_SCALE_BINS {
        if !low[k] || low[k - 1] {
            k += 1;
            continue;
        }
        let a = k;
        while k < OWN_SCALE_BINS && low[k] {
            k += 1;
        }
        // A run of low bins to the group's end is its tail.
        if k == OWN_SCALE_BINS {
            return None;
        }
        let b = k - 1;
        let wide = (b + 1 - a) as f64 * h.width >= resolution;
        let before: usize = h.counts[since..a].iter().sum();
        let after: usize = h.counts[b + 1..].iter().sum();
        if !wide || before < least || after < least {
            continue;
        }
        // The level after the valley: its dense bins up to the next low one.
        let end = (b + 1..OWN_SCALE_BINS)
            .find(|&j| low[j])
            .unwrap_or(OWN_SCALE_BINS);
        let (left, right) = (h.samples(since, a), h.samples(b + 1, end));
        let scale = deviation(left).max(deviation(right)).max(noise);
        if median(right) - median(left) >= SEPARATED * scale {
            return Some((a, b));
        }
    }
    None
}

/// The levels grown from their cores over the valleys between them: a
/// valley's sample joins the nearer level (in its deviations) within
/// [`TAIL`] of them; farther from both, it is a transition.
fn widen(group: &[f64], mut parts: Vec<Range<usize>>, noise: f64) -> Vec<Range<usize>> {
    // Each level's median and deviation, of its core.
    let scales: Vec<(f64, f64)> = parts
        .iter()
        .map(|r| {
            let s = &group[r.clone()];
            (median(s), deviation(s).max(noise).max(f64::MIN_POSITIVE))
        })
        .collect();
    for i in 1..parts.len() {
        let ((ml, sl), (mr, sr)) = (scales[i - 1], scales[i]);
        let gap = parts[i - 1].end..parts[i].start;
        let z = |v: f64| ((v - ml) / sl, (mr - v) / sr);
        let valley = &group[gap.clone()];
        let left = valley.partition_point(|&v| {
            let (zl, zr) = z(v);
            zl <= TAIL && zl <= zr
        });
        let right = valley.partition_point(|&v| {
            let (zl, zr) = z(v);
            !(zr <= TAIL && zr < zl)
        });
        parts[i - 1].end = gap.start + left;
        parts[i].start = gap.start + right.max(left);
    }
    parts
}
