//! Gaussian radial-basis-function network, as Wang & Liang trains it (MATLAB's
//! `newrbe`): one neuron per training input, `φ(x) = exp(−(b·‖x − c‖)²)` with
//! `b = √(ln 2)/spread` (a neuron's output is 0.5 at a distance of `spread`),
//! and a linear output layer with bias fitted to the training outputs. The
//! output layer is solved by SVD least squares, so a badly conditioned design
//! (a spread large against the spacing of the inputs) still gives an answer;
//! the condition number is reported.

use nalgebra::{DMatrix, DVector};

/// A trained network from scalar inputs to vector outputs.
#[derive(Debug, Clone, PartialEq)]
pub struct Rbf {
    centres: Vec<f64>,
    b: f64,
    /// Output weights: one row per output, one column per neuron plus bias.
    weights: DMatrix<f64>,
    /// 2-norm condition number of the design matrix.
    pub condition: f64,
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
                .solve(&rhs, 1e-12 * smax)
                .expect("SVD was computed with U and V");
            weights.set_row(k, &w.transpose());
        }
        Self {
            centres: x.to_vec(),
            b,
            weights,
            condition: smax / smin,
        }
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

    #[test]
    fn neuron_output_is_half_at_one_spread() {
        let net = Rbf::train(&[0.0, 10.0], &[vec![1.0], vec![0.0]], 2.0);
        assert!((((-(net.b * 2.0).powi(2)).exp()) - 0.5).abs() < 1e-15);
    }
}
