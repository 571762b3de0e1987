//! The least-squares problem of one stage and the exact Jacobian of its
//! residuals `F_model − F_test` with
//! respect to its fitted coefficients: one evaluation of the stage's channel
//! per row in forward-mode dual numbers ([`MagicFormula::channel_of`] with
//! the coefficients as `num-dual`'s `DualSVec64<N>`, nothing allocated), `N`
//! the smallest of a few fixed sizes that holds the stage's parameters, the
//! unused directions padded with zeros; a stage with more parameters than
//! the largest size is done in blocks of columns. Finite differences (the
//! default of [`crate::optim::local::Residuals::jacobian`], `n` residual
//! evaluations) stay selectable ([`Derivatives`]), for comparison.

use super::{MfRow, Stage};
use crate::optim::local::{inward_jacobian, Residuals};
use crate::tyre::mf::{Held, MagicFormula, MfChannel, MfCoefficientsOf, MfPoint};
use nalgebra::{DMatrix, U1};
use num_dual::DualSVec64;
use rayon::prelude::*;
use serde::Serialize;

/// How a stage's Jacobian is computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Derivatives {
    /// Exact, by forward-mode dual numbers (one evaluation per row).
    #[default]
    Exact,
    /// Forward differences (relative step 1e-7, into the box at an upper
    /// bound: `n` residual evaluations per Jacobian).
    Differences,
}

/// The most directions one pass carries; more parameters take more passes.
/// A pass evaluates the whole formula's plain part (its arctangents, sines
/// and cosines) once whatever its width, so a stage of 26 or 27 free
/// coefficients in one pass of 28 spends a quarter of what four passes of
/// eight did on them; each direction's derivative is the same arithmetic
/// at any width (the Jacobian is the same to the bit).
const WIDEST: usize = 28;

/// Rows from which an evaluation over them is split between threads.
pub(super) const PARALLEL_ROWS: usize = 2048;

impl Stage {
    /// The output channel this stage fits.
    pub fn channel(self) -> MfChannel {
        match self {
            Stage::PureFx | Stage::CombinedFx => MfChannel::Fx,
            Stage::PureFy | Stage::CombinedFy => MfChannel::Fy,
            Stage::PureMz | Stage::CombinedMz => MfChannel::Mz,
            Stage::Mx => MfChannel::Mx,
            Stage::My => MfChannel::My,
        }
    }
}

/// The least-squares problem of one stage: the residuals `F_model − F_test`
/// of its channel over its rows as functions of its free coefficients
/// `names` (the rest of `base` held).
pub(super) struct StageProblem<'a> {
    pub(super) base: MagicFormula,
    pub(super) stage: Stage,
    pub(super) names: Vec<&'static str>,
    pub(super) rows: Vec<&'a MfRow>,
    pub(super) derivatives: Derivatives,
    /// The rows prepared with the parts the free coefficients do not
    /// enter (exact derivatives only).
    points: Vec<MfPoint>,
}

impl<'a> StageProblem<'a> {
    pub(super) fn new(
        base: MagicFormula,
        stage: Stage,
        names: Vec<&'static str>,
        rows: Vec<&'a MfRow>,
        derivatives: Derivatives,
    ) -> Self {
        let points = match derivatives {
            Derivatives::Exact => {
                let plain = base.coefficients.lift::<f64>();
                let held = Held::except(&names);
                rows.iter()
                    .map(|r| base.prepare_point(&plain, held, &r.input()))
                    .collect()
            }
            Derivatives::Differences => Vec::new(),
        };
        Self {
            base,
            stage,
            names,
            rows,
            derivatives,
            points,
        }
    }

    /// σ of the stage's channel at `p`, % (`sqrt(Σe²/ΣF²)`, as the
    /// stage's line gives it).
    pub(super) fn sigma_percent(&self, p: &[f64]) -> f64 {
        let mut e = vec![0.0; self.rows.len()];
        self.residuals(p, &mut e);
        let e2: f64 = e.iter().map(|x| x * x).sum();
        let y2: f64 = self
            .rows
            .iter()
            .map(|r| self.stage.measured(r).powi(2))
            .sum();
        100.0 * (e2 / y2).sqrt()
    }

    pub(super) fn tyre(&self, p: &[f64]) -> MagicFormula {
        let mut t = self.base.clone();
        for (k, v) in self.names.iter().zip(p) {
            t.coefficients.set(k, *v);
        }
        t
    }

    /// The coefficients at `p` in scalar `T` (plain numbers).
    fn coefficients(&self, p: &[f64]) -> MfCoefficientsOf<f64> {
        let mut c = self.base.coefficients.lift::<f64>();
        for (k, v) in self.names.iter().zip(p) {
            c.set(k, *v);
        }
        c
    }

    /// The exact Jacobian at `p`: the columns in passes of at most
    /// [`WIDEST`] directions.
    fn exact_jacobian(&self, p: &[f64]) -> DMatrix<f64> {
        let (m, n) = (self.rows.len(), p.len());
        let mut j = DMatrix::zeros(m, n);
        let plain = self.coefficients(p);
        let mut start = 0;
        while start < n {
            let width = (n - start).min(WIDEST);
            let b = match width {
                0..=4 => self.columns::<4>(&plain, start, width),
                5..=8 => self.columns::<8>(&plain, start, width),
                9..=16 => self.columns::<16>(&plain, start, width),
                _ => self.columns::<WIDEST>(&plain, start, width),
            };
            j.columns_mut(start, width).copy_from(&b);
            start += width;
        }
        j
    }

    /// Columns `start..start + width` (`width ≤ N`) in one dual pass.
    fn columns<const N: usize>(
        &self,
        plain: &MfCoefficientsOf<f64>,
        start: usize,
        width: usize,
    ) -> DMatrix<f64> {
        let mut c: Box<MfCoefficientsOf<DualSVec64<N>>> = Box::new(self.base.coefficients.lift());
        for (k, name) in self.names.iter().enumerate() {
            let v = DualSVec64::from_re(plain.get(name).unwrap_or(0.0));
            let v = if (start..start + width).contains(&k) {
                v.derivative(k - start)
            } else {
                v
            };
            c.set(name, v);
        }
        let channel = self.stage.channel();
        let mut buf = vec![0.0; self.rows.len() * width];
        let row = |(out, q): (&mut [f64], &MfPoint)| {
            let g = self.base.channel_at(&c, q, channel);
            let eps = g.eps.unwrap_generic(nalgebra::Const::<N>, U1);
            out.copy_from_slice(&eps.as_slice()[..width]);
        };
        if self.rows.len() >= PARALLEL_ROWS {
            buf.par_chunks_mut(width)
                .zip(self.points.par_iter())
                .for_each(row);
        } else {
            buf.chunks_mut(width).zip(self.points.iter()).for_each(row);
        }
        DMatrix::from_row_slice(self.rows.len(), width, &buf)
    }
}

/// No bounds on `n` parameters.
pub(super) fn unbounded(n: usize) -> Vec<(f64, f64)> {
    vec![(f64::NEG_INFINITY, f64::INFINITY); n]
}

impl Residuals for StageProblem<'_> {
    fn count(&self) -> usize {
        self.rows.len()
    }
    /// With exact derivatives, the residuals of the same evaluation as the
    /// Jacobian (the prepared points; equal to the fast path to rounding);
    /// with differences, those of [`MagicFormula::evaluate`].
    fn residuals(&self, p: &[f64], out: &mut [f64]) {
        let (stage, channel) = (self.stage, self.stage.channel());
        let mut run = |f: &(dyn Fn(usize) -> f64 + Sync)| {
            let g = |(i, o): (usize, &mut f64)| *o = f(i) - stage.measured(self.rows[i]);
            // Parallel only where the rows are many enough to pay for it.
            if self.rows.len() >= PARALLEL_ROWS {
                out.par_iter_mut().enumerate().for_each(g);
            } else {
                out.iter_mut().enumerate().for_each(g);
            }
        };
        match self.derivatives {
            Derivatives::Exact => {
                let c = self.coefficients(p);
                run(&|i| self.base.channel_at(&c, &self.points[i], channel));
            }
            Derivatives::Differences => {
                let t = self.tyre(p);
                run(&|i| stage.model(&t, self.rows[i]));
            }
        }
    }
    fn jacobian(&self, p: &[f64], r0: &[f64], bounds: &[(f64, f64)]) -> DMatrix<f64> {
        match self.derivatives {
            Derivatives::Exact => self.exact_jacobian(p),
            Derivatives::Differences => inward_jacobian(self, p, r0, bounds),
        }
    }
    fn jacobian_evaluations(&self, n: usize) -> usize {
        match self.derivatives {
            Derivatives::Exact => 0,
            Derivatives::Differences => n,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::tir::load_tir;
    use std::path::Path;

    fn fixture(name: &str) -> MagicFormula {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/tir");
        load_tir(&dir.join(name)).unwrap()
    }

    /// Rows over loads, slips, cambers and pressures (channel values are
    /// not needed: the Jacobian is the model's).
    fn grid() -> Vec<MfRow> {
        let mut rows = Vec::new();
        for (i, fz) in [1800.0, 4200.0, 6500.0].into_iter().enumerate() {
            for kappa in [0.0, -0.12, 0.04, 0.3] {
                for alpha in [0.0, 0.02, -0.09, 0.25] {
                    for camber in [0.0, 0.03, -0.06] {
                        let pressure = [1.8e5, 2.2e5, 2.6e5][(i + rows.len()) % 3];
                        rows.push(MfRow {
                            fz,
                            kappa,
                            alpha,
                            camber,
                            speed: 16.7,
                            pressure: Some(pressure),
                            fx: 0.0,
                            fy: 0.0,
                            mz: 0.0,
                            mx: 0.0,
                            my: 0.0,
                        });
                    }
                }
            }
        }
        rows
    }

    fn channel_at(t: &MagicFormula, r: &MfRow, ch: MfChannel) -> f64 {
        let o = t.evaluate(&r.input());
        match ch {
            MfChannel::Fx => o.fx,
            MfChannel::Fy => o.fy,
            MfChannel::Mz => o.mz,
            MfChannel::Mx => o.mx,
            MfChannel::My => o.my,
        }
    }

    /// Fourth-order central differences of the fast path `evaluate`:
    /// `(−f(p+2h) + 8f(p+h) − 8f(p−h) + f(p−2h))/(12h)`.
    fn differences(t: &MagicFormula, name: &str, r: &MfRow, ch: MfChannel) -> (f64, f64) {
        let p = t.coefficients.get(name).unwrap();
        let h = 1e-3 * p.abs().max(0.1);
        let at = |d: f64| {
            let mut u = t.clone();
            u.coefficients.set(name, p + d);
            channel_at(&u, r, ch)
        };
        let d = (-at(2.0 * h) + 8.0 * at(h) - 8.0 * at(-h) + at(-2.0 * h)) / (12.0 * h);
        (d, h)
    }

    /// Every stage's Jacobian (all its coefficients, in passes of up to 8
    /// directions, the last padded) equals fourth-order central
    /// differences of the fast path to 1e-6 relative, on the public MF 6.1
    /// and 6.2 files (right-side: mirrored) over loads, both slips, camber
    /// and pressure. The step, 1e-3 of the coefficient (at least 1e-4),
    /// leaves the differences a truncation error ≈ 1e-12 and a rounding
    /// error ≈ 1e-16·S/h (S the channel's largest magnitude over the grid):
    /// where the derivative itself is below 1e-9·S/h, ~0 (a camber term at
    /// zero camber, a shift's effect at a peak), the comparison is absolute,
    /// to 1e-15·S/h — ten times that rounding, far below any derivative
    /// that matters. Most entries are above the floor (checked).
    #[test]
    fn exact_jacobians_equal_fourth_order_differences() {
        for file in [
            "MagicFormula61_Parameters.tir",
            "MagicFormula62_Parameters.tir",
        ] {
            let t = fixture(file);
            let rows = grid();
            let refs: Vec<&MfRow> = rows.iter().collect();
            for stage in Stage::ALL {
                let names: Vec<&'static str> = stage.parameters().iter().map(|(k, _)| *k).collect();
                let ch = stage.channel();
                let values: Vec<f64> = names
                    .iter()
                    .map(|k| t.coefficients.get(k).unwrap())
                    .collect();
                let problem = StageProblem::new(
                    t.clone(),
                    stage,
                    names.clone(),
                    refs.clone(),
                    Derivatives::Exact,
                );
                let j = problem.exact_jacobian(&values);
                let scale = rows
                    .iter()
                    .map(|r| channel_at(&t, r, ch).abs())
                    .fold(0.0, f64::max);
                let (mut relative, mut all) = (0, 0);
                for (k, name) in names.iter().enumerate() {
                    for (i, r) in rows.iter().enumerate() {
                        let (d, h) = differences(&t, name, r, ch);
                        let (e, floor) = (j[(i, k)], 1e-9 * scale / h);
                        assert!(
                            (e - d).abs() <= 1e-6 * e.abs().max(floor),
                            "{file} {stage:?} ∂/∂{name} at {r:?}: exact {e}, differences {d}"
                        );
                        all += 1;
                        relative += usize::from(e.abs() > floor);
                    }
                }
                // Most entries are compared relatively, not on the floor.
                assert!(2 * relative > all, "{file} {stage:?}: {relative} of {all}");
            }
        }
    }

    /// With exact derivatives the residuals are the generic channel's at
    /// the prepared points: the fast path's to rounding.
    #[test]
    fn the_prepared_residuals_equal_the_fast_paths() {
        let t = fixture("MagicFormula61_Parameters.tir");
        let mut rows = grid();
        for (i, r) in rows.iter_mut().enumerate() {
            r.mz = 10.0 * (i as f64).sin();
        }
        let refs: Vec<&MfRow> = rows.iter().collect();
        for stage in Stage::ALL {
            let names: Vec<&'static str> = stage.parameters().iter().map(|(k, _)| *k).collect();
            let p: Vec<f64> = names
                .iter()
                .map(|k| 1.01 * t.coefficients.get(k).unwrap())
                .collect();
            let [a, b] = [Derivatives::Exact, Derivatives::Differences].map(|d| {
                let mut out = vec![0.0; rows.len()];
                StageProblem::new(t.clone(), stage, names.clone(), refs.clone(), d)
                    .residuals(&p, &mut out);
                out
            });
            let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for (x, y) in a.iter().zip(&b) {
                assert!((x - y).abs() <= 1e-12 * scale, "{stage:?}: {x} vs {y}");
            }
        }
    }
}
