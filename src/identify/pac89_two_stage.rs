//! The two-stage PAC89 identification of Zhang et al. (2021).
//!
//! Stage 1, per test condition: the six coefficients B, C, D, E, Sh, Sv of
//! `Y = D·sin(C·atan(B·x − E·(B·x − atan(B·x)))) + Sv`, `x = α[deg] + Sh`,
//! by PSO + Levenberg–Marquardt. Stage 2: the Adams coefficients a0..a13 from
//! the stage-1 results across conditions (Fz in kN, γ in degrees):
//! `C = a0`, `D = a1·Fz² + a2·Fz`, `E = a6·Fz + a7`,
//! `Sh = a8·γ + a9·Fz + a10`, `Sv = a11·Fz·γ + a12·Fz + a13` — linear in
//! their coefficients, so solved together by least squares — and
//! `BCD = a3·sin(2·atan(Fz/a4))·(1 − a5·|γ|)` fitted separately (PSO + LM).
//! With one camber level the camber terms a5, a8, a11 are held at the
//! start tyre's values, as the direct swarm fit holds them (Zhang et al.
//! hold them at zero; two values for one hold, chosen by `--local`, wrote
//! a camber thrust of 225 N or of 0 at 4 kN and 2.9°), and the other
//! terms fitted to what they leave. An optional final
//! joint polish fits a0..a13 to all the raw data from the stage-2 values.

use super::data::{Condition, RigPoint};
use super::{sigma, FitSettings};
use crate::error::FitError;
use crate::optim::local::{levenberg_marquardt, Residuals};
use crate::optim::Pso;
use crate::tyre::pac89::{CurveCoefficients, Pac89, Pac89Form};
use crate::tyre::Tyre;
use nalgebra::{DMatrix, DVector};
use rayon::prelude::*;
use serde::Serialize;

/// Stage-1 result of one condition.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Stage1 {
    /// Load, kN.
    pub fz_kn: f64,
    /// Camber, degrees.
    pub camber_deg: f64,
    /// B, C, D, E, Sh, Sv (degrees and N).
    pub coefficients: [f64; 6],
    /// σ of this condition's fit, %.
    pub sigma_percent: f64,
}

/// The two-stage outcome.
#[derive(Debug, Clone, Serialize)]
pub struct TwoStage {
    /// Stage 1 per condition.
    pub stage1: Vec<Stage1>,
    /// Mean stage-1 σ, %.
    pub stage1_mean_sigma: f64,
    /// Stage-2 σ per condition (raw data, a0..a13), %.
    pub stage2_sigma: Vec<f64>,
    /// Mean stage-2 σ, %.
    pub stage2_mean_sigma: f64,
    /// Stage-2 coefficients a0..a13.
    pub stage2: [f64; 14],
    /// After the joint polish on all raw data: σ per condition, %.
    pub polished_sigma: Vec<f64>,
    /// Mean after the polish, %.
    pub polished_mean_sigma: f64,
    /// Polished coefficients a0..a13.
    pub polished: [f64; 14],
}

/// One condition's cornering points.
struct Curve<'a>(&'a [RigPoint]);

impl Residuals for Curve<'_> {
    fn count(&self) -> usize {
        self.0.len()
    }
    fn residuals(&self, p: &[f64], out: &mut [f64]) {
        let c = CurveCoefficients {
            b: p[0],
            c: p[1],
            d: p[2],
            e: p[3],
            sh: p[4],
            sv: p[5],
        };
        for (o, q) in out.iter_mut().zip(self.0) {
            *o = c.eval(q.slip().to_degrees()) - q.fy();
        }
    }
}

struct Bcd<'a>(&'a [(f64, f64, f64)]);

impl Residuals for Bcd<'_> {
    fn count(&self) -> usize {
        self.0.len()
    }
    fn residuals(&self, p: &[f64], out: &mut [f64]) {
        for (o, (fz, g, bcd)) in out.iter_mut().zip(self.0) {
            *o = p[0] * (2.0 * (fz / p[1]).atan()).sin() * (1.0 - p[2] * g.abs()) - bcd;
        }
    }
}

/// PSO + LM on a small problem.
fn fit(problem: &dyn Residuals, bounds: &[(f64, f64)], pso: &Pso) -> Vec<f64> {
    let r = pso.minimize(|p| problem.cost(p), bounds);
    let l = levenberg_marquardt(problem, &r.best);
    if l.cost.is_finite() && l.cost <= r.value {
        l.params
    } else {
        r.best
    }
}

/// Linear least squares `A·x ≈ y` by SVD.
fn lstsq(rows: &[Vec<f64>], y: &[f64]) -> Vec<f64> {
    let a = DMatrix::from_fn(rows.len(), rows[0].len(), |i, j| rows[i][j]);
    let svd = a.svd(true, true);
    let tol = 1e-12 * svd.singular_values.max();
    svd.solve(&DVector::from_column_slice(y), tol).map_or_else(
        |_| vec![0.0; rows[0].len()],
        |x| x.iter().copied().collect(),
    )
}

fn tyre(a: [f64; 14]) -> Tyre {
    Tyre::Pac89(Pac89 {
        form: Pac89Form::AdamsPac89,
        a,
        b: None,
        c: None,
    })
}

/// Runs both stages (and the joint polish) on the conditions, the camber
/// terms held at `start`'s (a0..a13) where the conditions have one camber.
pub fn identify(
    conditions: &[Condition],
    settings: &FitSettings,
    start: &[f64; 14],
) -> Result<TwoStage, FitError> {
    if conditions.len() < 3 {
        return Err(FitError::TooFewConditions {
            method: "two-stage PAC89",
            needed: 3,
            have: conditions.len(),
        });
    }
    let pso = Pso {
        particles: 40,
        iterations: 200,
        parallel: false,
        ..settings.pso
    };
    let stage1 = stage1(conditions, &pso);
    let cambers = stage1
        .iter()
        .map(|s| s.camber_deg)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), g| {
            (a.min(g), b.max(g))
        });
    let with_camber = cambers.1 - cambers.0 > 0.1;
    let held = (!with_camber).then(|| LATERAL_CAMBER_TERMS.map(|i| start[i]));
    let a = stage2(&stage1, held, &pso);
    let per_condition = |t: &Tyre| {
        conditions
            .iter()
            .map(|c| sigma(t, &c.points).0)
            .collect::<Vec<f64>>()
    };
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let stage2_sigma = per_condition(&tyre(a));
    let polished = polish(a, conditions, with_camber);
    let polished_sigma = per_condition(&tyre(polished));
    Ok(TwoStage {
        stage1_mean_sigma: mean(&stage1.iter().map(|s| s.sigma_percent).collect::<Vec<_>>()),
        stage1,
        stage2_mean_sigma: mean(&stage2_sigma),
        stage2_sigma,
        stage2: a,
        polished_mean_sigma: mean(&polished_sigma),
        polished_sigma,
        polished,
    })
}

/// Stage 1: B, C, D, E, Sh, Sv of each condition's curve by PSO + LM (the
/// swarm's seed advanced by the condition's index). The conditions' fits
/// are independent (each its own seed, its own serial swarm), so they run
/// side by side and are collected in the conditions' order: the same
/// results as one after another.
fn stage1(conditions: &[Condition], pso: &Pso) -> Vec<Stage1> {
    conditions
        .par_iter()
        .enumerate()
        .map(|(k, c)| stage1_of(c, k, pso))
        .collect()
}

/// Stage 1 of condition `c`, the `k`-th.
fn stage1_of(c: &Condition, k: usize, pso: &Pso) -> Stage1 {
    let ymax = c
        .points
        .iter()
        .map(|q| q.fy().abs())
        .fold(0.0, f64::max)
        .max(1.0);
    let bounds = [
        (0.01, 3.0),
        (1.0, 2.0),
        (0.5 * ymax, 2.0 * ymax),
        (-5.0, 1.0),
        (-2.0, 2.0),
        (-0.2 * ymax, 0.2 * ymax),
    ];
    let p = fit(
        &Curve(&c.points),
        &bounds,
        &Pso {
            seed: pso.seed.wrapping_add(k as u64),
            ..*pso
        },
    );
    let coefficients = [p[0], p[1], p[2], p[3], p[4], p[5]];
    let cost = Curve(&c.points).cost(&p);
    let y2: f64 = c.points.iter().map(|q| q.fy() * q.fy()).sum();
    Stage1 {
        fz_kn: c.fz / 1000.0,
        camber_deg: c.camber.to_degrees(),
        coefficients,
        sigma_percent: 100.0 * (2.0 * cost / y2).sqrt(),
    }
}

/// Least squares of `y` over stage 1's conditions against the regressors
/// `row` gives each: one of [`stage2`]'s linear laws in load and camber,
/// written once.
fn fit_law(
    stage1: &[Stage1],
    row: impl Fn(&Stage1) -> Vec<f64>,
    y: impl Fn(&Stage1) -> f64,
) -> Vec<f64> {
    lstsq(
        &stage1.iter().map(row).collect::<Vec<_>>(),
        &stage1.iter().map(y).collect::<Vec<_>>(),
    )
}

/// The camber terms a5, a8, a11 in a0..a13.
const LATERAL_CAMBER_TERMS: [usize; 3] = [5, 8, 11];

/// Stage 2: the Adams coefficients a0..a13 from the stage-1 curves; the
/// camber terms fitted, or `held` at those values (a5, a8, a11) without
/// camber data, the other terms fitted to what they leave.
fn stage2(stage1: &[Stage1], held: Option<[f64; 3]>, pso: &Pso) -> [f64; 14] {
    let mut a = [0.0; 14];
    let coefficient = |k: usize| move |s: &Stage1| s.coefficients[k];
    // C = a0.
    a[0] = stage1.iter().map(|s| s.coefficients[1]).sum::<f64>() / stage1.len() as f64;
    // D = a1·Fz² + a2·Fz.
    let d = fit_law(stage1, |s| vec![s.fz_kn * s.fz_kn, s.fz_kn], coefficient(2));
    a[1] = d[0];
    a[2] = d[1];
    // E = a6·Fz + a7.
    let e = fit_law(stage1, |s| vec![s.fz_kn, 1.0], coefficient(3));
    a[6] = e[0];
    a[7] = e[1];
    // Sh = a8·γ + a9·Fz + a10, Sv = a11·Fz·γ + a12·Fz + a13.
    let [sh, sv] = offsets(stage1, held);
    a[8..11].copy_from_slice(&sh);
    a[11..14].copy_from_slice(&sv);
    // BCD = a3·sin(2·atan(Fz/a4))·(1 − a5·|γ|), separately.
    let bcd: Vec<(f64, f64, f64)> = stage1
        .iter()
        .map(|s| {
            (
                s.fz_kn,
                s.camber_deg,
                s.coefficients[0] * s.coefficients[1] * s.coefficients[2],
            )
        })
        .collect();
    let bmax = bcd.iter().map(|x| x.2.abs()).fold(0.0, f64::max);
    let a5_bounds = held.map_or((-0.2, 0.2), |h| (h[0], h[0]));
    let p = fit(
        &Bcd(&bcd),
        &[(0.5 * bmax, 10.0 * bmax), (0.2, 50.0), a5_bounds],
        pso,
    );
    a[3] = p[0];
    a[4] = p[1];
    a[5] = held.map_or(p[2], |h| h[0]);
    a
}

/// The offsets' laws `Sh = a8·γ + a9·Fz + a10` and
/// `Sv = a11·Fz·γ + a12·Fz + a13` from the stage-1 curves: (a8, a9, a10)
/// and (a11, a12, a13), the camber terms fitted or `held` (a5, a8, a11),
/// the rest fitted to the offsets less the held terms' share.
fn offsets(stage1: &[Stage1], held: Option<[f64; 3]>) -> [[f64; 3]; 2] {
    let law = |k: usize, camber: fn(&Stage1) -> f64, h: Option<f64>| -> [f64; 3] {
        match h {
            None => {
                let x = fit_law(
                    stage1,
                    |s| vec![camber(s), s.fz_kn, 1.0],
                    |s| s.coefficients[k],
                );
                [x[0], x[1], x[2]]
            }
            Some(h) => {
                let x = fit_law(
                    stage1,
                    |s| vec![s.fz_kn, 1.0],
                    |s| s.coefficients[k] - h * camber(s),
                );
                [h, x[0], x[1]]
            }
        }
    };
    [
        law(4, |s| s.camber_deg, held.map(|h| h[1])),
        law(5, |s| s.fz_kn * s.camber_deg, held.map(|h| h[2])),
    ]
}

/// The joint polish of a0..a13 on every raw point from the stage-2 values
/// (camber terms held without camber data); the stage-2 values when the
/// polish does not lower the cost.
fn polish(a: [f64; 14], conditions: &[Condition], with_camber: bool) -> [f64; 14] {
    let start = tyre(a);
    let free = start.lateral_free(conditions.len(), if with_camber { 2 } else { 1 });
    let problem = super::FitProblem::new(&start, &free, conditions);
    let p0: Vec<f64> = a
        .iter()
        .zip(&free)
        .filter(|(_, f)| **f)
        .map(|(v, _)| *v)
        .collect();
    // Within the direct fit's box unless the data take a value past it, as
    // the direct fit's polish: stage 2's least squares are unbounded and
    // start the polish where `a0`, `a1`, `a2` trade off freely.
    let all_bounds = super::Channel::LateralForce.bounds(&start);
    let bounds: Vec<(f64, f64)> = problem.free.iter().map(|&i| all_bounds[i]).collect();
    let l = super::within_box(&problem, &p0, levenberg_marquardt(&problem, &p0), &bounds);
    let polished_tyre = if l.cost.is_finite() && l.cost <= problem.cost(&p0) {
        problem.tyre(&l.params).canonical()
    } else {
        start.clone()
    };
    match polished_tyre {
        Tyre::Pac89(p) => p.a,
        _ => unreachable!("a PAC89 tyre"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_stage_recovers_a_pac89_tyre() {
        let truth = Tyre::Pac89(Pac89::adams_example());
        let (data, noise) = super::super::data::identification_conditions(&truth, 0.01, 3);
        // The camber terms are unidentifiable at zero camber: held at the
        // start's, here zero, which the curves at zero camber do not see.
        let start = [0.0; 14];
        let r = identify(&data, &FitSettings::new(1), &start).unwrap();
        assert_eq!(LATERAL_CAMBER_TERMS.map(|i| r.polished[i]), [0.0; 3]);
        // Stage 1 fits each curve to the noise; stage 2 is an exact model
        // of the stage-1 laws, so it stays near the noise too.
        assert!(
            r.stage1_mean_sigma <= noise,
            "{} vs {noise}",
            r.stage1_mean_sigma
        );
        assert!(
            r.stage2_mean_sigma < 2.0 * noise,
            "{} vs {noise}",
            r.stage2_mean_sigma
        );
        assert!(
            r.polished_mean_sigma <= noise * 1.01,
            "{} vs {noise}",
            r.polished_mean_sigma
        );
        let t = match &truth {
            Tyre::Pac89(p) => p.a,
            _ => unreachable!(),
        };
        // D = a1·Fz² + a2·Fz reproduced within 1 % over the loads.
        for fz in [2.8, 5.7, 8.6] {
            let (dt, dp) = (
                t[1] * fz * fz + t[2] * fz,
                r.polished[1] * fz * fz + r.polished[2] * fz,
            );
            assert!((dp - dt).abs() < 0.01 * dt, "D({fz}) {dp} vs {dt}");
        }
    }
}

#[cfg(test)]
mod seed_style {
    use super::*;
    use crate::tyre::pac89::ADAMS_EXAMPLE_A;

    /// Zhang et al.'s (2021) residual levels on data like theirs: a tyre that
    /// is not a PAC89 (the bundled UniTire) at Zhang & Li's (2017) three
    /// loads with 1 % noise. Zhang et al. (2021) report stage-1 and stage-2
    /// means of 0.75 % and 1.70 %; here
    /// stage 1 stays below 1 % and stage 2, which imposes PAC89's load laws
    /// on the curves, stays below 1.8 % and above stage 1.
    #[test]
    fn two_stage_residuals_on_a_unitire_tyre_are_in_zhang_et_al_range() {
        let truth: Tyre = toml::from_str(include_str!("../../tyres/unitire.toml")).unwrap();
        let (data, _) = crate::identify::data::identification_conditions(&truth, 0.01, 4);
        let r = identify(&data, &FitSettings::new(1), &ADAMS_EXAMPLE_A).unwrap();
        assert!(r.stage1_mean_sigma < 1.0, "stage 1 {}", r.stage1_mean_sigma);
        assert!(r.stage2_mean_sigma < 1.8, "stage 2 {}", r.stage2_mean_sigma);
        assert!(r.stage2_mean_sigma >= r.stage1_mean_sigma);
        // One camber level: the camber terms are the start's, as the
        // direct fit holds them.
        let held = LATERAL_CAMBER_TERMS.map(|i| r.polished[i]);
        assert_eq!(held, LATERAL_CAMBER_TERMS.map(|i| ADAMS_EXAMPLE_A[i]));
    }
}
