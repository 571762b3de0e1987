//! Gaussian radial-basis-function network, as Wang & Liang trains it (MATLAB's
//! `newrbe`): one neuron per training input, `φ(x) = exp(−(b·‖x − c‖)²)` with
//! `b = √(ln 2)/spread` (a neuron's output is 0.5 at a distance of `spread`),
//! and a linear output layer with bias fitted to the training outputs. The
//! output layer is solved by SVD least squares, so a badly conditioned design
//! (a spread large against the spacing of the inputs) still gives an answer;
//! the condition number is reported. The solve drops the directions whose
//! singular value is below [`RCOND`] of the largest: past a condition
//! number of `1/RCOND` it keeps fewer directions than there are pairs, and
//! the network is then a least-squares fit through them, not the
//! interpolant `newrbe` builds (`kept` says how many it kept).

use nalgebra::{DMatrix, DVector};

/// The singular values the solve keeps, relative to the largest: below it a
/// direction of the design is rounding (double precision carries about 16
/// digits, so at 1e-12 a direction's weight would carry 4 at best).
pub(crate) const RCOND: f64 = 1e-12;

/// A trained network from scalar inputs to vector outputs.
#[derive(Debug, Clone, PartialEq)]
pub struct Rbf {
    centres: Vec<f64>,
    b: f64,
    /// Output weights: one row per output, one column per neuron plus bias.
    weights: DMatrix<f64>,
    /// 2-norm condition number of the design matrix.
    pub condition: f64,
    /// The directions (singular values) the solve kept: those above
    /// [`RCOND`] of the largest; fewer than the centres makes the network a
    /// regression, not an interpolant.
    pub kept: usize,
}

impl Rbf {
    /// The smallest and largest input it was trained on: outside them its
    /// answer is an extrapolation of Gaussians that fade to the bias.
    pub(crate) fn trained_range(&self) -> (f64, f64) {
        self.centres
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &c| {
                (lo.min(c), hi.max(c))
            })
    }

    /// Trains on inputs `x` and outputs `y` (one vector per input).
    pub(crate) fn train(x: &[f64], y: &[Vec<f64>], spread: f64) -> Self {
        let n = x.len();
        let b = (2f64.ln()).sqrt() / spread;
        let phi = |u: f64, c: f64| (-(b * (u - c)).powi(2)).exp();
        let design = DMatrix::from_fn(n, n + 1, |i, j| if j < n { phi(x[i], x[j]) } else { 1.0 });
        let svd = design.clone().svd(true, true);
        let s = &svd.singular_values;
        let (smax, smin) = (
            s.max(),
            s.iter()
                .copied()
                .filter(|v| *v > 0.0)
                .fold(f64::INFINITY, f64::min),
        );
        let m = y[0].len();
        let mut weights = DMatrix::zeros(m, n + 1);
        for k in 0..m {
            let rhs = DVector::from_iterator(n, y.iter().map(|v| v[k]));
            let w = svd
                .solve(&rhs, RCOND * smax)
                .expect("SVD was computed with U and V");
            weights.set_row(k, &w.transpose());
        }
        Self {
            centres: x.to_vec(),
            b,
            weights,
            condition: smax / smin,
            kept: s.iter().filter(|v| **v > RCOND * smax).count(),
        }
    }

    /// The largest spread, to 1 %, at which a network on inputs `x` keeps
    /// every direction (its condition number below `1/RCOND`): the spread
    /// from which down it interpolates its pairs; None where even a spread
    /// of a millionth of the inputs' range does not (inputs repeated).
    pub(crate) fn interpolating_spread(x: &[f64]) -> Option<f64> {
        let full = |spread: f64| {
            let y: Vec<Vec<f64>> = x.iter().map(|_| vec![0.0]).collect();
            Self::train(x, &y, spread).kept == x.len()
        };
        let (lo, hi) = x.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, &v| {
            (a.0.min(v), a.1.max(v))
        });
        let range = hi - lo;
        let (mut a, mut b) = (1e-6 * range, 1e3 * range);
        if range.is_nan() || range <= 0.0 || !full(a) {
            return None;
        }
        if full(b) {
            return Some(b);
        }
        // The condition number grows with the spread: bisect its log.
        while b / a > 1.01 {
            let m = (a * b).sqrt();
            if full(m) {
                a = m;
            } else {
                b = m;
            }
        }
        Some(a)
    }

    /// The network's output at `x`.
    pub(crate) fn predict(&self, x: f64) -> Vec<f64> {
        let n = self.centres.len();
        let mut h = DVector::zeros(n + 1);
        for (i, c) in self.centres.iter().enumerate() {
            h[i] = (-(self.b * (x - c)).powi(2)).exp();
        }
        h[n] = 1.0;
        (&self.weights * h).iter().copied().collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_its_training_points_when_well_conditioned() {
        let x: Vec<f64> = (0..20).map(|i| i as f64 * 0.1).collect();
        let y: Vec<Vec<f64>> = x.iter().map(|v| vec![v.sin(), v * v]).collect();
        let net = Rbf::train(&x, &y, 0.15);
        assert!(net.condition < 1e8, "{}", net.condition);
        for (xi, yi) in x.iter().zip(&y) {
            let p = net.predict(*xi);
            assert!(
                (p[0] - yi[0]).abs() < 1e-8 && (p[1] - yi[1]).abs() < 1e-8,
                "{p:?} vs {yi:?}"
            );
        }
        // Between the centres it interpolates smoothly.
        let p = net.predict(0.55);
        assert!((p[0] - 0.55f64.sin()).abs() < 1e-3, "{p:?}");
    }

    /// Wang & Liang's spread of 2 s on Er values 0.01 s apart is numerically
    /// singular: the solve keeps fewer directions than pairs and misses
    /// them; at the spread `interpolating_spread` finds it keeps every one
    /// and passes through its pairs, and at twice that it no longer does.
    #[test]
    fn a_spread_far_beyond_the_spacing_regresses_and_the_one_found_interpolates() {
        let x: Vec<f64> = (0..9).map(|i| 0.10 + 0.012 * f64::from(i)).collect();
        let y: Vec<Vec<f64>> = x.iter().map(|v| vec![(40.0 * v).sin()]).collect();
        let wide = Rbf::train(&x, &y, 2.0);
        assert!(wide.condition > 1.0 / RCOND, "{}", wide.condition);
        assert!(wide.kept < x.len(), "{}", wide.kept);
        let s = Rbf::interpolating_spread(&x).unwrap();
        assert!(s < 2.0 && s > 0.001, "{s}");
        let net = Rbf::train(&x, &y, s);
        assert_eq!(net.kept, x.len());
        assert!(net.condition <= 1.0 / RCOND, "{}", net.condition);
        for (xi, yi) in x.iter().zip(&y) {
            assert!((net.predict(*xi)[0] - yi[0]).abs() < 1e-6);
        }
        assert!(Rbf::train(&x, &y, 1.03 * s).kept < x.len());
        assert_eq!(Rbf::interpolating_spread(&[0.1, 0.1]), None);
    }

    #[test]
    fn neuron_output_is_half_at_one_spread() {
        let net = Rbf::train(&[0.0, 10.0], &[vec![1.0], vec![0.0]], 2.0);
        assert!((((-(net.b * 2.0).powi(2)).exp()) - 0.5).abs() < 1e-15);
    }
}
