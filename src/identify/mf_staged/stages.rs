//! One stage's fit: its least-squares problem, the staged release of its
//! parameters by the projected Levenberg–Marquardt within the physical
//! bounds, the parameters the data do not determine held at a stated
//! value (`holds.rs`), and the standard errors and identifiability
//! warnings at the optimum (`uncertainty.rs`).

use super::holds::{held_reason, hold_undetermined, HoldReason, Holding, StageFit};
use super::paper_lm::paper_lm;
use super::params::{names_of, physical_bounds, Need, Stage, ANY};
use super::problem::{unbounded, Derivatives, StageProblem};
use super::start::{data_start, level_counts, template_value};
use super::uncertainty::{uncertainty, Uncertainty};
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

/// Why a combined `Fy` or `Mz` stage is not fitted whose rows with
/// longitudinal slip are all at α = 0 (pure braking and driving): there
/// `Gyκ·Fy0(0) + SVyκ` is all the stage sees, and a fit of its fifteen
/// coefficients to it wrote `RBY1` = 27386 from an `fy` of zeros. Those
/// rows pin `SVyκ` beside combined rows; without any they are no
/// combined-slip test.
fn only_pure_longitudinal(stage: Stage, rows: &[&MfRow]) -> Option<SkipReason> {
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
fn no_slip_angle(stage: Stage, rows: &[&MfRow]) -> Option<SkipReason> {
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

/// The base tyre with the free parameters at their start values, and
/// those values.
fn start_values(
    stage: Stage,
    run: &StageRun,
    tyre: &MagicFormula,
    free: &[(&'static str, Need)],
    rows: &[&MfRow],
) -> (MagicFormula, Vec<f64>) {
    let mut base = tyre.clone();
    let starts: Vec<f64> = match run.start {
        StartScheme::Paper => vec![1.0; free.len()],
        StartScheme::Template => free
            .iter()
            .map(|(name, _)| base.coefficients.get(name).unwrap_or(0.0))
            .collect(),
        StartScheme::Data => {
            // The data's estimates, else the coefficient's version default
            // (0 but for PKY4 = 2): never the template's fitted values.
            let defaults = MfCoefficients::default();
            // Kyα's law is estimated at the PKY4 the fit starts from: at a
            // template's (MFeval's 3.27) with PKY4 then started at 2, PKY1
            // started a curve no data had (σ 2.364 % against 1.755 % from
            // the other templates on the Hoosier file).
            let mut at_start = base.clone();
            if names_of(free).contains(&"PKY4") {
                at_start.coefficients.PKY4 = defaults.PKY4;
            }
            let est = data_start(stage, &at_start, rows);
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
        if !names_of(free).contains(&name)
            && run.holding.given(name).is_none()
            && base.coefficients.get(name) == Some(0.0)
        {
            base.coefficients.set(name, v);
        }
    }
    (base, starts)
}

/// How the stages are run: the start scheme, the iteration cap, the
/// derivatives, the values the user gives and the template.
pub(super) struct StageRun<'a> {
    pub(super) start: StartScheme,
    pub(super) max_iterations: usize,
    pub(super) derivatives: Derivatives,
    pub(super) holding: &'a Holding,
    pub(super) template: Option<&'a MagicFormula>,
}

impl StageRun<'_> {
    /// The iteration cap of the paper's scheme: at least
    /// [`PAPER_ITERATIONS`].
    fn paper_cap(&self) -> usize {
        self.max_iterations.max(PAPER_ITERATIONS)
    }
}

/// Fits one stage on its rows, updating `tyre`, and reports it.
pub(super) fn run_stage(
    stage: Stage,
    tyre: &mut MagicFormula,
    rows: &[&MfRow],
    run: &StageRun,
) -> StageReport {
    let t0 = Instant::now();
    let table = stage.parameters();
    let have = level_counts(rows);
    let free = free_parameters(table, have, run);
    if let Some(why) = only_pure_longitudinal(stage, rows).or_else(|| no_slip_angle(stage, rows)) {
        return StageReport::skipped(stage, why);
    }
    if rows.len() <= free.len() + 5 {
        return StageReport::skipped(stage, skip_reason(stage, rows.len(), free.len()));
    }
    let (base, starts) = start_values(stage, run, tyre, &free, rows);
    let names: Vec<&'static str> = free.iter().map(|(k, _)| *k).collect();
    let problem = StageProblem::new(
        base.clone(),
        stage,
        names.clone(),
        rows.to_vec(),
        run.derivatives,
    );
    let (sigma_start, ..) = sigma(stage, &base, rows);
    let bounds = start_bounds(run.start, &names, &starts);
    let result = match run.start {
        StartScheme::Paper => paper_lm(&problem, &starts, 1.0, run.paper_cap()),
        StartScheme::Data | StartScheme::Template => {
            released_fit(&problem, &free, &starts, &bounds, run.max_iterations)
        }
    };
    let mut evaluations = result.evaluations;
    let mut fit = StageFit {
        problem,
        needs: free.iter().map(|f| f.1).collect(),
        p: result.params,
        bounds,
        starts,
    };
    let held = held_undetermined(&mut fit, run, &mut evaluations);
    *tyre = fit.problem.tyre(&fit.p);
    let (sigma_end, rms, ..) = sigma(stage, tyre, rows);
    let u = uncertainty(&fit.problem, &fit.p);
    // Stopped on its cap at a point a Gauss–Newton step would barely
    // improve (after its holds), the stage is at its optimum for the
    // report (`Uncertainty::at_optimum`); the strict test per iteration
    // is the optimiser's, not the data's.
    let converged = result.converged || (run.start != StartScheme::Paper && u.at_optimum());
    let parameters = stage_parameters(table, tyre, (&fit, &held, &u), run, have);
    StageReport {
        stage,
        skipped: None,
        points: rows.len(),
        levels: have,
        sigma_start_percent: sigma_start,
        sigma_percent: sigma_end,
        paper_sigma_percent: stage.paper_sigma_percent(),
        rms,
        condition_number: u.condition,
        converged: Some(converged),
        evaluations: evaluations * fit.problem.count(),
        seconds: t0.elapsed().as_secs_f64(),
        warnings: u
            .near_singular
            .into_iter()
            .chain(not_converged(converged, run))
            .chain(paper_unheld(run.start, &parameters))
            .collect(),
        parameters,
        error_spread: None,
    }
}

/// The parameters of the stage's `table` the stage fits: those the data's
/// levels (`have`) determine and the user does not give.
fn free_parameters(
    table: &[(&'static str, Need)],
    have: [usize; 3],
    run: &StageRun,
) -> Vec<(&'static str, Need)> {
    table
        .iter()
        .copied()
        .filter(|(name, need)| {
            held_reason(name, *need, have).is_none() && run.holding.given(name).is_none()
        })
        .collect()
}

/// The bounds of the parameters `names` starting at `starts`: none for
/// the paper's scheme, the physical ones otherwise.
fn start_bounds(start: StartScheme, names: &[&'static str], starts: &[f64]) -> Vec<(f64, f64)> {
    match start {
        StartScheme::Paper => unbounded(names.len()),
        StartScheme::Data | StartScheme::Template => names
            .iter()
            .zip(starts)
            .map(|(k, v)| physical_bounds(k, *v))
            .collect(),
    }
}

/// The parameters of `fit` the data do not determine, held at their
/// stated values and the rest refitted (`holds.rs`; none for the paper's
/// scheme), the evaluations counted into `evaluations`.
fn held_undetermined(
    fit: &mut StageFit,
    run: &StageRun,
    evaluations: &mut usize,
) -> Vec<(&'static str, f64, HoldReason)> {
    // Judged even where the stage stopped on its cap: a fit crawling
    // along a direction the data barely see (PKY1 against PKY4) does not
    // converge because of it, and the holds are its remedy; the stage's
    // warning says the judgement is taken where it stopped.
    match run.start {
        StartScheme::Paper => Vec::new(),
        StartScheme::Data | StartScheme::Template => {
            let stated = |name: &str| {
                let template = run.template.and_then(|t| template_value(t, name));
                run.holding.stated(name, template)
            };
            let refit =
                |problem: &StageProblem, needs: &[Need], starts: &[f64], bounds: &[(f64, f64)]| {
                    let free: Vec<(&'static str, Need)> = problem
                        .names
                        .iter()
                        .copied()
                        .zip(needs.iter().copied())
                        .collect();
                    released_fit(problem, &free, starts, bounds, run.max_iterations)
                };
            hold_undetermined(fit, &stated, &refit, run.max_iterations, evaluations)
        }
    }
}

/// The report of each parameter of the stage's `table` in the fitted
/// `tyre`: fitted (with its start, standard error `u` and any warning)
/// or held, and why (`held` by the data, given, or for want of levels).
fn stage_parameters(
    table: &[(&'static str, Need)],
    tyre: &MagicFormula,
    (fit, held, u): (&StageFit, &[(&'static str, f64, HoldReason)], &Uncertainty),
    run: &StageRun,
    have: [usize; 3],
) -> Vec<StageParameter> {
    table
        .iter()
        .map(|(name, need)| {
            let value = tyre.coefficients.get(name).unwrap_or(0.0);
            let fitted = fit.problem.names.iter().position(|k| k == name);
            let because = held
                .iter()
                .find(|h| h.0 == *name)
                .map(|h| h.2.clone())
                // The user's value, even where the levels would hold it too.
                .or_else(|| run.holding.given(name).map(|_| HoldReason::Given))
                .or_else(|| held_reason(name, *need, have));
            let on_bound = fitted.and_then(|k| at_bound(fit.p[k], fit.bounds[k]));
            StageParameter {
                name,
                on_bound,
                value,
                start: fitted.map_or(value, |k| fit.starts[k]),
                free: fitted.is_some(),
                std_error: fitted.and_then(|k| u.std_error[k]),
                held: if fitted.is_some() { None } else { because },
                // On its bound, the standard error means nothing: said
                // first, as the swarm fits say it.
                warning: on_bound
                    .zip(fitted)
                    .map(|(_, k)| bound_warning(fit.bounds[k]))
                    .or_else(|| fitted.and_then(|k| u.warning(k, value))),
            }
        })
        .collect()
}

/// The bound of `(lo, hi)` that `v` ends on (within 1e-6 of the box's
/// width, or of the bound's size for a box open on one side), if any.
fn at_bound(v: f64, (lo, hi): (f64, f64)) -> Option<f64> {
    let width = if (hi - lo).is_finite() { hi - lo } else { 0.0 };
    let near = |b: f64| b.is_finite() && (v - b).abs() <= 1e-6 * width.max(b.abs()).max(1e-9);
    [lo, hi].into_iter().find(|b| near(*b))
}

/// The warning of a parameter on a bound of `(lo, hi)`.
fn bound_warning((lo, hi): (f64, f64)) -> String {
    format!(
        "on its physical bound ({} to {}): the fit would take it beyond; the value is the bound, not a fit",
        crate::format::exact(lo),
        crate::format::exact(hi)
    )
}

/// Iterations per step the paper's scheme runs at least: from every
/// parameter at 1 its LM takes hundreds of steps to reach the data.
pub(super) const PAPER_ITERATIONS: usize = 500;

/// The warning of a stage fitted by the paper's scheme (`start`) that
/// leaves parameters the data do not determine where its unbounded LM
/// stopped (`PKY1` = −415.8 ± 25503 on a cornering file): the scheme
/// holds nothing, as the paper does not, so the values are written as
/// they stand and the file's force beyond the data rests on them.
fn paper_unheld(start: StartScheme, parameters: &[StageParameter]) -> Option<String> {
    let unheld: Vec<String> = parameters
        .iter()
        .filter(|p| p.free && p.warning.is_some())
        .map(|p| format!("{} = {}", p.name, crate::format::rounded(p.value, 4)))
        .collect();
    (start == StartScheme::Paper && !unheld.is_empty()).then(|| {
        format!(
            "the paper's scheme (--start paper) holds nothing: {} of its parameters, which these data do not determine ({}), are written where its unbounded Levenberg–Marquardt left them, not at a stated value; do not rely on this stage's channel beyond the points; --start data (the default) holds such parameters at the template's or Pacejka's (2012) book values and says so",
            unheld.len(),
            unheld.join(", ")
        )
    })
}

/// The warning of a stage whose Levenberg–Marquardt stopped before its
/// convergence test (its iteration cap), `None` when it converged.
fn not_converged(converged: bool, run: &StageRun) -> Option<String> {
    // The paper's scheme runs at least 500 iterations per step whatever
    // `--max-iterations` (150 by default) says below that: said, as a cap
    // of 500 beside a default of 150 read as a misprint.
    let (cap, why) = match run.start {
        StartScheme::Paper if run.max_iterations < PAPER_ITERATIONS => (
            PAPER_ITERATIONS,
            format!(
                "the paper's scheme (--start paper) runs at least {PAPER_ITERATIONS} per step, above --max-iterations' {}; a larger --max-iterations raises the cap",
                run.max_iterations
            ),
        ),
        _ => (run.max_iterations, "--max-iterations sets the cap".to_string()),
    };
    let judged = match run.start {
        StartScheme::Paper => "",
        StartScheme::Data | StartScheme::Template => {
            "; its standard errors, and what they call not identifiable and hold, are taken \
             where it stopped, not at an optimum: with more iterations they may differ"
        }
    };
    (!converged).then(|| {
        format!(
            "not converged: Levenberg–Marquardt stopped at its cap of {cap} iterations per step \
             before its convergence test (its cost still falling by more than 1e-12 of itself \
             per iteration): the values are where it stopped ({why}){judged}"
        )
    })
}
