//! Sample statistics the crate's checks share: the centred sums of a pair of
//! series, their Pearson correlation and the least-squares slope of one on
//! the other; the least-squares parabola through a window of samples (a
//! smoothed derivative's, a curvature's). Dimensionless; a series' units
//! cancel in the correlation.
//!
//! Sums, not the correlation alone, are what is kept: runs judged one by one
//! pool by adding their sums (each centred on its own means, so an offset
//! between runs is no correlation), which a mean of correlations would
//! weight wrongly.

/// The centred sums of products of two series `x` and `y` over `n` pairs,
/// each centred on its own mean.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct CentredSums {
    /// Pairs summed.
    pub n: usize,
    /// Σ (x − x̄)(y − ȳ).
    pub xy: f64,
    /// Σ (x − x̄)².
    pub xx: f64,
    /// Σ (y − ȳ)².
    pub yy: f64,
}

impl CentredSums {
    /// The sums of the pairs `(x[i], y[i])` (the shorter length counts).
    pub fn of(x: &[f64], y: &[f64]) -> Self {
        let n = x.len().min(y.len());
        let (x, y) = (&x[..n], &y[..n]);
        let (mx, my) = (mean(x), mean(y));
        let mut s = CentredSums {
            n,
            ..Self::default()
        };
        for (p, q) in x.iter().zip(y) {
            let (p, q) = (p - mx, q - my);
            s.xy += p * q;
            s.xx += p * p;
            s.yy += q * q;
        }
        s
    }

    /// The sums of both sets of pairs together, each kept centred on its
    /// own means (the within-set sums of a pooled correlation).
    pub fn pooled(self, other: Self) -> Self {
        CentredSums {
            n: self.n + other.n,
            xy: self.xy + other.xy,
            xx: self.xx + other.xx,
            yy: self.yy + other.yy,
        }
    }

    /// Pearson's correlation, `None` where either series is constant (or
    /// there are no pairs).
    pub fn correlation(&self) -> Option<f64> {
        (self.xx > 0.0 && self.yy > 0.0).then(|| self.xy / (self.xx * self.yy).sqrt())
    }

    /// The centred RMS of `x` (its swing about its mean).
    pub fn x_rms(&self) -> f64 {
        (self.xx / self.n.max(1) as f64).sqrt()
    }

    /// The least-squares slope of `y` on `x` (a line with an intercept):
    /// `Σ(x − x̄)(y − ȳ) / Σ(x − x̄)²`; not finite where `x` is constant.
    pub fn slope(&self) -> f64 {
        self.xy / self.xx
    }
}

/// The mean of `v` (0 for no values): the centre [`CentredSums`] sums about.
pub fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len().max(1) as f64
}

/// The least-squares parabola `y ≈ c0 + c1·x + c2·x²` through the pairs
/// `(x, y)`: its coefficients and how many pairs it went through, from the
/// normal equations (sums of `x^k` and of `y·x^k`); None where they are
/// singular (fewer than three distinct `x`). Callers centre `x` on the
/// point they read and scale it by their window's span, which keeps the
/// sums of `x⁴` conditioned.
pub fn least_squares_parabola(
    points: impl IntoIterator<Item = (f64, f64)>,
) -> Option<([f64; 3], usize)> {
    let mut p = [0.0; 5];
    let mut q = [0.0; 3];
    let mut n = 0;
    for (x, y) in points {
        let mut xk = 1.0;
        for (j, pj) in p.iter_mut().enumerate() {
            *pj += xk;
            if j < 3 {
                q[j] += xk * y;
            }
            xk *= x;
        }
        n += 1;
    }
    let a = [[p[0], p[1], p[2]], [p[1], p[2], p[3]], [p[2], p[3], p[4]]];
    solve3(a, q).map(|c| (c, n))
}

/// The solution of the 3×3 system `a·x = b` by Cramer's rule, None when
/// `a` is singular against its largest entry.
fn solve3(a: [[f64; 3]; 3], b: [f64; 3]) -> Option<[f64; 3]> {
    let det = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(a);
    let scale = a.iter().flatten().fold(0.0_f64, |s, x| s.max(x.abs()));
    if !d.is_finite() || d.abs() <= 1e-12 * scale.powi(3) {
        return None;
    }
    let mut x = [0.0; 3];
    for (j, xj) in x.iter_mut().enumerate() {
        let mut m = a;
        for i in 0..3 {
            m[i][j] = b[i];
        }
        *xj = det(m) / d;
    }
    Some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_parabola_is_recovered_exactly_and_two_distinct_abscissae_fix_none() {
        // y = 0.3 − 1.2·x + 2.5·x² at uneven x in [−1, 1].
        let x = [-1.0, -0.55, -0.1, 0.2, 0.65, 1.0];
        let pts = x.map(|x| (x, 0.3 - 1.2 * x + 2.5 * x * x));
        let (c, n) = least_squares_parabola(pts).unwrap();
        assert_eq!(n, 6);
        for (got, want) in c.iter().zip([0.3, -1.2, 2.5]) {
            assert!((got - want).abs() < 1e-13, "{c:?}");
        }
        assert_eq!(
            least_squares_parabola([(0.0, 1.0), (1.0, 2.0), (1.0, 3.0)]),
            None
        );
    }

    #[test]
    fn a_line_correlates_fully_and_its_mirror_against() {
        let x = [1.0, 2.0, 4.0, 7.0];
        let up: Vec<f64> = x.iter().map(|v| 3.0 * v - 2.0).collect();
        let down: Vec<f64> = x.iter().map(|v| -0.5 * v + 9.0).collect();
        assert!((CentredSums::of(&x, &up).correlation().unwrap() - 1.0).abs() < 1e-15);
        assert!((CentredSums::of(&x, &down).correlation().unwrap() + 1.0).abs() < 1e-15);
    }

    #[test]
    fn a_known_correlation_and_swing_by_hand() {
        // x̄ = 2, ȳ = 3: Σxy = (−1)(−1) + 0·1 + 1·0 = 1, Σxx = 2, Σyy = 2.
        let s = CentredSums::of(&[1.0, 2.0, 3.0], &[2.0, 4.0, 3.0]);
        assert_eq!((s.n, s.xy, s.xx, s.yy), (3, 1.0, 2.0, 2.0));
        assert!((s.correlation().unwrap() - 0.5).abs() < 1e-15);
        assert!((s.x_rms() - (2.0_f64 / 3.0).sqrt()).abs() < 1e-15);
    }

    #[test]
    fn a_constant_series_has_no_correlation() {
        assert_eq!(
            CentredSums::of(&[1.0, 1.0, 1.0], &[0.0, 1.0, 2.0]).correlation(),
            None
        );
        assert_eq!(CentredSums::default().correlation(), None);
    }

    #[test]
    fn pooling_keeps_each_set_on_its_own_means() {
        // Two runs moving together but offset from each other by 100: the
        // pooled within-run correlation is 1, whereas the offset alone would
        // dominate one concatenated correlation.
        let a = CentredSums::of(&[0.0, 1.0, 2.0], &[0.0, 1.0, 2.0]);
        let b = CentredSums::of(&[100.0, 101.0, 102.0], &[-100.0, -99.0, -98.0]);
        let p = a.pooled(b);
        assert_eq!(p.n, 6);
        assert!((p.correlation().unwrap() - 1.0).abs() < 1e-15);
    }
}
