//! The fitting of one stage's free parameters: the staged release by the
//! projected Levenberg–Marquardt within the physical bounds (`released_fit`),
//! the restart of a fit that ends on a bound with that parameter held
//! inside its box first (`profiled`), σ of a stage's channel, and why a
//! stage is skipped.

use super::hold_rounds::held_out;
use super::params::{Need, Stage, ANY};
use super::problem::StageProblem;
use super::MfRow;
use crate::error::{SkipReason, StageRows};
use crate::optim::bounded::BoundedLm;
use crate::optim::local::{LocalResult, Residuals};
use crate::tyre::mf::MagicFormula;

/// σ (%) and RMS of a stage's channel over rows.
pub(super) fn sigma(stage: Stage, t: &MagicFormula, rows: &[&MfRow]) -> (f64, f64, f64, f64) {
    let (mut e2, mut y2) = (0.0, 0.0);
    for r in rows {
        let e = stage.model(t, r) - stage.measured(r);
        e2 += e * e;
        y2 += stage.measured(r).powi(2);
    }
    (
        100.0 * (e2 / y2).sqrt(),
        (e2 / rows.len().max(1) as f64).sqrt(),
        e2,
        y2,
    )
}

/// Projected Levenberg–Marquardt within `bounds`, converged on a relative
/// cost decrease (or a step relative to the bounds' width) below 1e-12, or
/// when no damped step lowers the cost; at most `iterations` Jacobians.
pub(super) fn bounded(
    problem: &StageProblem,
    p0: &[f64],
    bounds: &[(f64, f64)],
    iterations: usize,
) -> LocalResult {
    BoundedLm {
        iterations,
        tolerance: 1e-12,
        ..BoundedLm::default()
    }
    .minimize(problem, p0, bounds)
}

/// The staged release of a stage's parameters, each step within the
/// physical bounds and stopped by tolerance: the terms without conditions
/// (from three curvature starts, E = 0, −1, 0.5: a curvature started on
/// the wrong side of a kink — E is clipped at 1 — or of a flat trail curve
/// can stall LM in a local minimum), then with the load terms, then all
/// (camber and pressure terms too). The result counts the residual
/// evaluations of every step and start.
pub(super) fn released_fit(
    problem: &StageProblem,
    free: &[(&'static str, Need)],
    starts: &[f64],
    bounds: &[(f64, f64)],
    iterations: usize,
) -> LocalResult {
    let mut evaluations = 0;
    let mut converged = true;
    let mut p: Vec<f64> = starts
        .iter()
        .zip(bounds)
        .map(|(v, (lo, hi))| v.clamp(*lo, *hi))
        .collect();
    let steps: [&dyn Fn(Need) -> bool; 3] = [
        &|n: Need| n == ANY,
        &|n: Need| n.cambers == 1 && n.pressures == 1,
        &|_| true,
    ];
    let mut last = None;
    for (s, takes) in steps.iter().enumerate() {
        let idx: Vec<usize> = (0..free.len()).filter(|&i| takes(free[i].1)).collect();
        if idx.is_empty() || (s > 0 && last == Some(idx.len())) {
            continue;
        }
        last = Some(idx.len());
        let sub = StageProblem::new(
            problem.tyre(&p),
            problem.stage,
            idx.iter().map(|&i| problem.names[i]).collect(),
            problem.rows.clone(),
            problem.derivatives,
        );
        let b: Vec<(f64, f64)> = idx.iter().map(|&i| bounds[i]).collect();
        let q0: Vec<f64> = idx.iter().map(|&i| p[i]).collect();
        let curvature = sub
            .names
            .iter()
            .position(|k| matches!(*k, "PEX1" | "PEY1" | "QEZ1" | "REX1" | "REY1"));
        let e0s: &[f64] = match (s, curvature) {
            (0, Some(_)) => &[0.0, -1.0, 0.5],
            _ => &[f64::NAN],
        };
        let mut best = (sub.cost(&q0), q0.clone(), true);
        for &e0 in e0s {
            let mut q = q0.clone();
            if let (Some(k), false) = (curvature, e0.is_nan()) {
                q[k] = e0;
            }
            let r = bounded(&sub, &q, &b, iterations);
            evaluations += r.evaluations;
            if r.cost.is_finite() && r.cost < best.0 {
                best = (r.cost, r.params, r.converged);
            }
        }
        converged &= best.2;
        for (k, &i) in idx.iter().enumerate() {
            p[i] = best.1[k];
        }
    }
    let cost = problem.cost(&p);
    LocalResult {
        cost,
        params: p,
        evaluations,
        converged,
    }
}

/// Why a stage with `rows` rows and `free` parameters is not fitted.
pub(super) fn skip_reason(stage: Stage, rows: usize, free: usize) -> SkipReason {
    if rows > 0 {
        return SkipReason::TooFewRows { rows, free };
    }
    SkipReason::NoRows(match stage {
        Stage::PureFx => StageRows::PureLongitudinal,
        Stage::PureFy => StageRows::PureLateral,
        Stage::PureMz => StageRows::PureLateralMz,
        Stage::CombinedFx => StageRows::CombinedFx,
        Stage::CombinedFy => StageRows::LongitudinalSlipFy,
        Stage::CombinedMz => StageRows::LongitudinalSlipMz,
        Stage::Mx => StageRows::Mx,
        Stage::My => StageRows::My,
    })
}

/// Why a combined `Fy` or `Mz` stage is not fitted whose rows with
/// longitudinal slip are all at α = 0 (pure braking and driving): there
/// `Gyκ·Fy0(0) + SVyκ` is all the stage sees, and a fit of its fifteen
/// coefficients to it wrote `RBY1` = 27386 from an `fy` of zeros. Those
/// rows pin `SVyκ` beside combined rows; without any they are no
/// combined-slip test.
pub(super) fn only_pure_longitudinal(stage: Stage, rows: &[&MfRow]) -> Option<SkipReason> {
    let column = match stage {
        Stage::CombinedFy => "fy",
        Stage::CombinedMz => "mz",
        _ => return None,
    };
    let combined = rows.iter().any(|r| r.alpha.abs() > super::PURE_TOL);
    (!rows.is_empty() && !combined).then_some(SkipReason::NoRows(StageRows::OnlyPureLongitudinal {
        column,
    }))
}

/// Why a pure `Fy` or `Mz` stage is not fitted whose rows are all at
/// α = 0 (a braking or driving sweep with `fy` and `mz` logged): a stage
/// fitted there wrote a lateral block from its rows' offsets alone
/// (σ 4.7 % "fitted" on 36 rows of a longitudinal-only rig file, and a
/// car that steered on it), where `--model pac89` says there is no
/// lateral slip to fit.
pub(super) fn no_slip_angle(stage: Stage, rows: &[&MfRow]) -> Option<SkipReason> {
    let column = match stage {
        Stage::PureFy => "fy",
        Stage::PureMz => "mz",
        _ => return None,
    };
    let flat = rows.iter().all(|r| r.alpha.abs() <= super::PURE_TOL);
    (!rows.is_empty() && flat).then_some(SkipReason::NoRows(StageRows::NoSlipAngle {
        column,
        rows: rows.len(),
    }))
}

/// The bound of `(lo, hi)` that `v` ends on (within 1e-6 of the box's
/// width, or of the bound's size for a box open on one side), if any.
pub(super) fn at_bound(v: f64, (lo, hi): (f64, f64)) -> Option<f64> {
    let width = if (hi - lo).is_finite() { hi - lo } else { 0.0 };
    let near = |b: f64| b.is_finite() && (v - b).abs() <= 1e-6 * width.max(b.abs()).max(1e-9);
    [lo, hi].into_iter().find(|b| near(*b))
}

/// Values a parameter that ended on its bound is held at before it is
/// released again: its `stated` one, and for a curvature (`E`, whose box
/// is −50 to 1) −1 too, the other side of the ridge at E ≈ 0 that a fit
/// started there climbs to the bound 1 over (combined Fx of noise-free
/// MF 6.1 data: σ 0.82 % at `REX1` = 0, 0.70 % at 1, 0.19 % at −1, 0 at
/// the generating −1.39).
fn held_values(name: &str, stated: f64) -> Vec<f64> {
    let curvature = matches!(name, "PEX1" | "PEY1" | "QEZ1" | "REX1" | "REY1");
    let mut values = vec![stated];
    if curvature && stated != -1.0 {
        values.push(-1.0);
    }
    values
}

/// The fit of `problem` from `end` (a fit whose `k`-th parameter ended on
/// its bound) with that parameter first held at each of [`held_values`]
/// and the rest refitted, then all released from there: the best, with
/// the value held and the point it was released from, or `None` where
/// none is finite. `evaluations` counts every fit's.
pub(super) fn profiled(
    problem: &StageProblem,
    end: &[f64],
    k: usize,
    (bounds, stated): (&[(f64, f64)], f64),
    iterations: usize,
) -> Option<(LocalResult, f64, Vec<f64>)> {
    let mut best: Option<(LocalResult, f64, Vec<f64>)> = None;
    let mut evaluations = 0;
    let (lo, hi) = bounds[k];
    for value in held_values(problem.names[k], stated) {
        let value = value.clamp(lo, hi);
        let sub = held_out(problem, end, k, value);
        let (mut rest, mut b) = (end.to_vec(), bounds.to_vec());
        rest.remove(k);
        b.remove(k);
        let held = bounded(&sub, &rest, &b, iterations);
        let mut from = held.params;
        from.insert(k, value);
        let r = bounded(problem, &from, bounds, iterations);
        evaluations += held.evaluations + r.evaluations;
        if r.cost.is_finite() && best.as_ref().is_none_or(|b| r.cost < b.0.cost) {
            best = Some((r, value, from));
        }
    }
    best.map(|(r, v, from)| {
        let r = LocalResult { evaluations, ..r };
        (r, v, from)
    })
}
