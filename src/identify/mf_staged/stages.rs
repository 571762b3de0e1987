//! One stage's fit: its least-squares problem, the staged release of its
//! parameters by the projected Levenberg–Marquardt within the physical
//! bounds, and the standard errors and identifiability warnings at the
//! optimum.

use super::paper_lm::paper_lm;
use super::params::{held_reason, names_of, physical_bounds, Need, Stage, ANY};
use super::problem::{unbounded, Derivatives, StageProblem};
use super::start::{data_start, level_counts};
use super::{MfRow, StageParameter, StageReport, StartScheme};
use crate::error::{SkipReason, StageRows};
use crate::optim::bounded::BoundedLm;
use crate::optim::local::{LocalResult, Residuals};
use crate::tyre::mf::{MagicFormula, MfCoefficients};
use std::time::Instant;

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
fn bounded(
    problem: &StageProblem,
    p0: &[f64],
    bounds: &[(f64, f64)],
    iterations: usize,
) -> LocalResult {
    BoundedLm {
        iterations,
        tolerance: 1e-12,
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
fn released_fit(
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
fn skip_reason(stage: Stage, rows: usize, free: usize) -> SkipReason {
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

/// The base tyre with the free parameters at their start values, and
/// those values.
fn start_values(
    stage: Stage,
    start: StartScheme,
    tyre: &MagicFormula,
    free: &[(&'static str, Need)],
    rows: &[&MfRow],
) -> (MagicFormula, Vec<f64>) {
    let mut base = tyre.clone();
    let starts: Vec<f64> = match start {
        StartScheme::Paper => vec![1.0; free.len()],
        StartScheme::Template => free
            .iter()
            .map(|(name, _)| base.coefficients.get(name).unwrap_or(0.0))
            .collect(),
        StartScheme::Data => {
            // The data's estimates, else the coefficient's version default
            // (0 but for PKY4 = 2): never the template's fitted values.
            let est = data_start(stage, &base, rows);
            let defaults = MfCoefficients::default();
            free.iter()
                .map(|(name, _)| {
                    est.iter()
                        .find(|(k, _)| k == name)
                        .map_or(defaults.get(name).unwrap_or(0.0), |e| e.1)
                })
                .collect()
        }
    };
    for ((name, _), v) in free.iter().zip(&starts) {
        base.coefficients.set(name, *v);
    }
    // A held coefficient still at 0 that the formula cannot live with at 0
    // (`PKY2` divides the load) takes the data's estimate.
    for (name, v) in data_start(stage, &base, rows) {
        if !names_of(free).contains(&name) && base.coefficients.get(name) == Some(0.0) {
            base.coefficients.set(name, v);
        }
    }
    (base, starts)
}

/// The stage's parameters with their standard errors `s²·(JᵀJ)⁻¹` on the
/// column-scaled Jacobian at the optimum `p` (SVD, pseudo-inverse), the
/// condition number, and the warnings (not identifiable, near-singular).
fn standard_errors(
    problem: &StageProblem,
    p: &[f64],
    names: &[&'static str],
    starts: &[f64],
    table: &[(&'static str, Need)],
    have: [usize; 3],
    tyre: &MagicFormula,
) -> (Vec<StageParameter>, f64, Vec<String>) {
    // Standard errors on the column-scaled Jacobian.
    let mut res = vec![0.0; problem.count()];
    problem.residuals(p, &mut res);
    let j = problem.jacobian(p, &res, &unbounded(p.len()));
    let (m, nf) = (problem.count(), p.len());
    let s2 = res.iter().map(|e| e * e).sum::<f64>() / (m - nf).max(1) as f64;
    let norms: Vec<f64> = (0..nf).map(|k| j.column(k).norm()).collect();
    let mut js = j.clone();
    for (k, nk) in norms.iter().enumerate() {
        if *nk > 0.0 {
            js.column_mut(k).scale_mut(1.0 / nk);
        }
    }
    // The measured channel's norm over the rows: the scale of a
    // parameter's effect (see `identifiability_warning`).
    let y_norm = problem
        .rows
        .iter()
        .map(|r| problem.stage.measured(r).powi(2))
        .sum::<f64>()
        .sqrt()
        .max(f64::MIN_POSITIVE);
    let svd = js.clone().svd(false, true);
    let sv = &svd.singular_values;
    let (smax, smin) = (sv.max(), sv.min());
    let cond = if smin > 0.0 {
        smax / smin
    } else {
        f64::INFINITY
    };
    let jtj = js.transpose() * &js;
    let cov = jtj.pseudo_inverse(1e-14).ok();
    let mut warnings = Vec::new();
    if cond > 1e8 {
        // The weakest direction: the right singular vector of the smallest
        // singular value names the parameters that trade off.
        let mut weak = String::new();
        if let Some(vt) = &svd.v_t {
            let kmin = (0..sv.len())
                .min_by(|a, b| sv[*a].total_cmp(&sv[*b]))
                .unwrap_or(0);
            let row = vt.row(kmin);
            let mut w: Vec<(usize, f64)> = row.iter().map(|v| v.abs()).enumerate().collect();
            w.sort_by(|a, b| b.1.total_cmp(&a.1));
            weak = w
                .iter()
                .take(3)
                .filter(|x| x.1 > 0.2)
                .map(|x| names[x.0])
                .collect::<Vec<_>>()
                .join(", ");
        }
        warnings.push(format!(
            "near-singular Jacobian (condition number {cond:.2e}): the data barely separate {weak}"
        ));
    }
    let parameters = table
        .iter()
        .map(|(name, need)| {
            let value = tyre.coefficients.get(name).unwrap_or(0.0);
            match names.iter().position(|k| k == name) {
                Some(k) => {
                    let se = cov.as_ref().and_then(|c| {
                        (norms[k] > 0.0).then(|| (s2 * c[(k, k)]).max(0.0).sqrt() / norms[k])
                    });
                    let warning = match se {
                        None => Some("no sensitivity: the data do not move it".into()),
                        Some(s) => identifiability_warning(value, s, s * norms[k] / y_norm),
                    };
                    StageParameter {
                        name,
                        value,
                        start: starts[k],
                        free: true,
                        std_error: se,
                        held_because: None,
                        warning,
                    }
                }
                None => StageParameter {
                    name,
                    value,
                    start: value,
                    free: false,
                    std_error: None,
                    held_because: held_reason(*need, have),
                    warning: None,
                },
            }
        })
        .collect();
    (parameters, cond, warnings)
}

/// One standard error, alone, moving the stage's channel by less than this
/// fraction of its RMS is an uncertainty too small to matter.
pub(super) const EFFECT_FLOOR: f64 = 0.01;

/// The identifiability warning of a fitted parameter, or `None`.
///
/// The rule: a parameter is *not identifiable* when its standard error `se`
/// reaches its magnitude **and** one standard error of it, alone, moves
/// the stage's channel by at least [`EFFECT_FLOOR`] (1 %) of its RMS
/// (`effect = se·‖∂F/∂p‖/‖F‖`, over the stage's rows). The magnitude alone
/// is no scale for a parameter whose true value is zero (`SSZ*` of a file
/// without them: estimate 1e-7, standard error 1e-6, and the data pin the
/// moment to 1e-5 of its RMS): that parameter is identified, as zero. The
/// effect is the parameter's natural scale taken from the data: the change
/// of it that matters is the one that moves the fitted curve. It is large
/// where the data trade the parameter against others (a large variance
/// inflation: `RVY1` against `RVY4` where `cos(atan(RVY4·α))` is in its
/// 1/α regime) or barely see it, which is what the warning is for.
pub(super) fn identifiability_warning(value: f64, se: f64, effect: f64) -> Option<String> {
    if !se.is_finite() {
        return Some("not identifiable from these data (no finite standard error)".into());
    }
    (se >= value.abs() && effect >= EFFECT_FLOOR).then(|| {
        format!(
            "not identifiable from these data (standard error {se:.3e} ≥ |value|; one standard error moves the fit by {:.1} % of the channel's RMS)",
            100.0 * effect
        )
    })
}

/// Fits one stage on its rows, updating `tyre`, and reports it.
pub(super) fn run_stage(
    stage: Stage,
    tyre: &mut MagicFormula,
    rows: &[&MfRow],
    start: StartScheme,
    max_iterations: usize,
    derivatives: Derivatives,
) -> StageReport {
    let t0 = Instant::now();
    let table = stage.parameters();
    let have = level_counts(rows);
    let free: Vec<(&'static str, Need)> = table
        .iter()
        .copied()
        .filter(|(_, need)| held_reason(*need, have).is_none())
        .collect();
    if rows.len() <= free.len() + 5 {
        return StageReport::skipped(stage, skip_reason(stage, rows.len(), free.len()));
    }
    let (base, starts) = start_values(stage, start, tyre, &free, rows);
    let names: Vec<&'static str> = free.iter().map(|(k, _)| *k).collect();
    let problem = StageProblem::new(
        base.clone(),
        stage,
        names.clone(),
        rows.to_vec(),
        derivatives,
    );
    let (sigma_start, ..) = sigma(stage, &base, rows);
    let result = match start {
        StartScheme::Paper => paper_lm(&problem, &starts, 1.0, max_iterations.max(500)),
        StartScheme::Data | StartScheme::Template => {
            let bounds: Vec<(f64, f64)> = names
                .iter()
                .zip(&starts)
                .map(|(k, v)| physical_bounds(k, *v))
                .collect();
            released_fit(&problem, &free, &starts, &bounds, max_iterations)
        }
    };
    let evaluations = result.evaluations;
    let p = result.params.clone();
    *tyre = problem.tyre(&p);
    let (sigma_end, rms, ..) = sigma(stage, tyre, rows);
    let (parameters, cond, warnings) =
        standard_errors(&problem, &p, &names, &starts, table, have, tyre);
    StageReport {
        stage,
        skipped: None,
        points: rows.len(),
        levels: have,
        sigma_start_percent: sigma_start,
        sigma_percent: sigma_end,
        paper_sigma_percent: stage.paper_sigma_percent(),
        rms,
        condition_number: cond,
        converged: result.converged,
        evaluations: evaluations * problem.count(),
        seconds: t0.elapsed().as_secs_f64(),
        parameters,
        warnings,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A zero parameter pinned by the data is identified (as zero); one
    /// whose uncertainty spans its value and moves the fit is not; a
    /// well-determined large one is identified.
    #[test]
    fn a_parameter_identified_as_zero_is_not_flagged() {
        // SSZ1 of a file without it: 1e-7 ± 1e-6, moving Mz by 3e-5 of its RMS.
        assert_eq!(identifiability_warning(1e-7, 1e-6, 3e-5), None);
        // RVY4 in its 1/α regime: 72 ± 163, one SE moves Fy by 4 %.
        let w = identifiability_warning(72.0, 163.0, 0.04).unwrap();
        assert!(w.contains("moves the fit by 4.0 %"), "{w}");
        // Just below the effect floor, and a value larger than its SE.
        assert_eq!(identifiability_warning(0.0, 1.0, 0.0099), None);
        assert_eq!(identifiability_warning(-2.0, 1.9, 0.5), None);
        assert!(identifiability_warning(1.0, 1.0, EFFECT_FLOOR).is_some());
        assert!(identifiability_warning(1.0, f64::INFINITY, 0.0).is_some());
    }
}
