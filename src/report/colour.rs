//! Colour for values on maps: a perceptually ordered blue → green → yellow
//! map ([`colormap`], after the viridis stops) and the scale that places a
//! value on it ([`ColourScale`]): linear, logarithmic for positive values
//! spanning decades, or by quantile where a few extreme cells would leave
//! the rest of the map one colour. Non-finite values have no position: the
//! figure draws them as cells without a value. And how far apart two
//! colours look ([`delta_e76`]): the CIE 1976 colour difference ΔE*ab, the
//! Euclidean distance in CIE L*a*b* (CIE 15:2004) of sRGB colours
//! (IEC 61966-2-1, D65 white); about 2.3 is a just noticeable difference
//! (Sharma 2003), and series a reader must tell apart at a glance stand
//! more than 15 apart.

use plotters::style::RGBColor;

/// CIE L*a*b* of an sRGB colour (D65 white): L* from 0 (black) to 100
/// (white).
pub fn lab(c: RGBColor) -> [f64; 3] {
    // sRGB's gamma undone (IEC 61966-2-1), then its primaries to XYZ.
    let linear = |v: u8| {
        let v = f64::from(v) / 255.0;
        match v > 0.04045 {
            true => ((v + 0.055) / 1.055).powf(2.4),
            false => v / 12.92,
        }
    };
    let (r, g, b) = (linear(c.0), linear(c.1), linear(c.2));
    let x = 0.4124 * r + 0.3576 * g + 0.1805 * b;
    let y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    let z = 0.0193 * r + 0.1192 * g + 0.9505 * b;
    // The cube root, linear near black (CIE 15:2004, δ = 6/29).
    const D: f64 = 6.0 / 29.0;
    let f = |t: f64| match t > D.powi(3) {
        true => t.cbrt(),
        false => t / (3.0 * D * D) + 4.0 / 29.0,
    };
    let (fx, fy, fz) = (f(x / 0.95047), f(y), f(z / 1.08883));
    [116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)]
}

/// The CIE 1976 colour difference ΔE*ab of two sRGB colours.
pub fn delta_e76(a: RGBColor, b: RGBColor) -> f64 {
    let (p, q) = (lab(a), lab(b));
    p.iter()
        .zip(q)
        .map(|(u, v)| (u - v).powi(2))
        .sum::<f64>()
        .sqrt()
}

/// A blue → green → yellow colour map (viridis-like) for t in [0, 1].
pub fn colormap(t: f64) -> RGBColor {
    const STOPS: [(f64, f64, f64); 5] = [
        (68.0, 1.0, 84.0),
        (59.0, 82.0, 139.0),
        (33.0, 145.0, 140.0),
        (94.0, 201.0, 98.0),
        (253.0, 231.0, 37.0),
    ];
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let x = t * (STOPS.len() - 1) as f64;
    let i = (x.floor() as usize).min(STOPS.len() - 2);
    let w = x - i as f64;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    let mix = |p: f64, q: f64| (p + w * (q - p)).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// How values are spread over the colour map.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScaleKind {
    /// Evenly in value.
    Linear,
    /// Evenly in log10 of the value (positive values over more than a
    /// decade and a half).
    Log,
    /// By rank: each colour band holds the same number of cells.
    Quantile,
}

impl ScaleKind {
    /// The name printed on the colour bar.
    pub fn name(self) -> &'static str {
        match self {
            ScaleKind::Linear => "linear scale",
            ScaleKind::Log => "log scale",
            ScaleKind::Quantile => "quantile scale",
        }
    }
}

/// The map from values to positions t ∈ [0, 1] on the colour map.
#[derive(Debug, Clone, PartialEq)]
pub struct ColourScale {
    /// The quantity and its unit, for the colour bar.
    pub label: String,
    /// How values are spread.
    pub kind: ScaleKind,
    /// Finite values, sorted (the quantile scale's ranks; the ends give
    /// the range of the others).
    sorted: Vec<f64>,
}

impl ColourScale {
    /// The scale for `values`: logarithmic when they are all positive and
    /// span more than a factor 30; by quantile when the median sits in the
    /// outer sixth of the range (a skew that leaves most cells one colour);
    /// linear otherwise.
    pub fn fit(values: &[f64], label: &str) -> Self {
        let mut sorted: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
        sorted.sort_by(f64::total_cmp);
        let kind = match (sorted.first(), sorted.last()) {
            (Some(&lo), Some(&hi)) if lo > 0.0 && hi / lo > 30.0 => ScaleKind::Log,
            (Some(&lo), Some(&hi)) if hi > lo => {
                let median = sorted[sorted.len() / 2];
                let m = (median - lo) / (hi - lo);
                if !(1.0 / 6.0..=5.0 / 6.0).contains(&m) {
                    ScaleKind::Quantile
                } else {
                    ScaleKind::Linear
                }
            }
            _ => ScaleKind::Linear,
        };
        Self::with_kind(values, label, kind)
    }

    /// A scale of the given kind (log falls back to linear unless every
    /// finite value is positive).
    pub fn with_kind(values: &[f64], label: &str, kind: ScaleKind) -> Self {
        let mut sorted: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
        sorted.sort_by(f64::total_cmp);
        let kind = if kind == ScaleKind::Log && sorted.first().is_some_and(|&v| v <= 0.0) {
            ScaleKind::Linear
        } else {
            kind
        };
        Self {
            label: label.to_string(),
            kind,
            sorted,
        }
    }

    /// The smallest and largest finite value, if any.
    pub fn range(&self) -> Option<(f64, f64)> {
        Some((*self.sorted.first()?, *self.sorted.last()?))
    }

    /// Where `v` sits on the colour map; None for a value that is not a
    /// number (a cell without a value).
    pub fn position(&self, v: f64) -> Option<f64> {
        let (lo, hi) = self.range()?;
        if !v.is_finite() {
            return None;
        }
        if hi <= lo {
            return Some(0.5);
        }
        let t = match self.kind {
            ScaleKind::Linear => (v - lo) / (hi - lo),
            ScaleKind::Log => (v / lo).ln() / (hi / lo).ln(),
            ScaleKind::Quantile => {
                let below = self.sorted.partition_point(|&s| s < v);
                let upto = self.sorted.partition_point(|&s| s <= v);
                // Mid-rank of the value, so ties share one colour.
                0.5 * (below + upto.saturating_sub(1)) as f64 / (self.sorted.len() - 1) as f64
            }
        };
        Some(t.clamp(0.0, 1.0))
    }

    /// The value at position `t` (the inverse of [`Self::position`]), for the
    /// colour bar's tick labels.
    pub fn value_at(&self, t: f64) -> Option<f64> {
        let (lo, hi) = self.range()?;
        let t = t.clamp(0.0, 1.0);
        Some(match self.kind {
            ScaleKind::Linear => lo + t * (hi - lo),
            ScaleKind::Log => lo * (hi / lo).powf(t),
            ScaleKind::Quantile => {
                let x = t * (self.sorted.len() - 1) as f64;
                let i = (x.floor() as usize).min(self.sorted.len() - 1);
                let j = (i + 1).min(self.sorted.len() - 1);
                let w = x - i as f64;
                self.sorted[i] + w * (self.sorted[j] - self.sorted[i])
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scale_follows_the_spread_of_the_values() {
        let even: Vec<f64> = (0..=10).map(f64::from).collect();
        assert_eq!(ColourScale::fit(&even, "x").kind, ScaleKind::Linear);
        let decades: Vec<f64> = (0..=4).map(|k| 10f64.powi(k)).collect();
        let log = ColourScale::fit(&decades, "x");
        assert_eq!(log.kind, ScaleKind::Log);
        // Each decade one quarter of the map.
        for (k, v) in decades.iter().enumerate() {
            assert!((log.position(*v).unwrap() - k as f64 / 4.0).abs() < 1e-12);
            assert!((log.value_at(k as f64 / 4.0).unwrap() / v - 1.0).abs() < 1e-12);
        }
        // One outlier among many alike (and a negative, so not log).
        let mut skewed = vec![-1.0, 0.0, 0.1, 0.2, 0.3, 0.4];
        skewed.push(100.0);
        let q = ColourScale::fit(&skewed, "x");
        assert_eq!(q.kind, ScaleKind::Quantile);
        // Ranks spread evenly: the third of seven sits at 2/6.
        assert!((q.position(0.1).unwrap() - 2.0 / 6.0).abs() < 1e-12);
        assert!((q.value_at(2.0 / 6.0).unwrap() - 0.1).abs() < 1e-12);
    }

    /// White is L* 100 and grey-free, black 0; sRGB red's published
    /// L*a*b* (53.24, 80.09, 67.20; Lindbloom's calculator, D65) within
    /// the matrix's rounding; the distance is symmetric and white to
    /// black is 100.
    #[test]
    fn lab_and_delta_e_match_published_values() {
        let close = |p: [f64; 3], q: [f64; 3]| p.iter().zip(q).all(|(u, v)| (u - v).abs() < 0.05);
        assert!(close(lab(RGBColor(255, 255, 255)), [100.0, 0.0, 0.0]));
        assert!(close(lab(RGBColor(0, 0, 0)), [0.0, 0.0, 0.0]));
        let red = lab(RGBColor(255, 0, 0));
        assert!(close(red, [53.24, 80.09, 67.20]), "{red:?}");
        let (w, k) = (RGBColor(255, 255, 255), RGBColor(0, 0, 0));
        assert!((delta_e76(w, k) - 100.0).abs() < 1e-3);
        let (a, b) = (RGBColor(31, 119, 180), RGBColor(160, 196, 222));
        assert_eq!(delta_e76(a, b), delta_e76(b, a));
    }

    #[test]
    fn a_cell_without_a_value_has_no_colour() {
        let s = ColourScale::fit(&[1.0, f64::NAN, 2.0], "x");
        assert_eq!(s.range(), Some((1.0, 2.0)));
        assert_eq!(s.position(f64::NAN), None);
        assert_eq!(s.position(1.0), Some(0.0));
        assert_eq!(s.position(2.0), Some(1.0));
        assert_eq!(ColourScale::fit(&[f64::NAN], "x").position(1.0), None);
        // Log refused for values that are not all positive.
        assert_eq!(
            ColourScale::with_kind(&[0.0, 1.0], "x", ScaleKind::Log).kind,
            ScaleKind::Linear
        );
    }
}
