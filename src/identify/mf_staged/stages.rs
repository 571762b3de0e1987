//! One stage's fit: its least-squares problem, the staged release of its
//! parameters by the projected Levenberg–Marquardt within the physical
//! bounds, the parameters the data do not determine held at a stated
//! value (`holds.rs`), and the standard errors and identifiability
//! warnings at the optimum (`uncertainty.rs`).

use super::curvature_clip::at_clip;
use super::determination::determination;
use super::hold_rounds::{hold_undetermined, HoldOutcome, StageFit};
use super::holds::{held_reason, HoldReason};
use super::params::{names_of, physical_bounds, Need, Stage};
use super::problem::{unbounded, StageProblem};
use super::release::{
    at_bound, no_slip_angle, only_pure_longitudinal, released_fit, sigma, skip_reason,
};
use super::stage_fit::{continued_cap, StageRun, ITERATIONS_PER_FREE, PAPER_ITERATIONS};
use super::start::{data_start, level_counts, template_value};
use super::template_start::SecondStart;
use super::uncertainty::{uncertainty, Uncertainty};
use super::{MfRow, StageParameter, StageReport, StartScheme};
use crate::optim::local::Residuals;
use crate::tyre::mf::{MagicFormula, MfCoefficients};
use std::time::Instant;

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
    let super::stage_fit::Fitted {
        result,
        starts,
        second,
        off_bound,
    } = super::stage_fit::stage_fit(&problem, &free, starts, &bounds, run);
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
    super::conventional_signs(&mut tyre.coefficients);
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
        sigma_own_percent: Some(sigma_end),
        sigma_moved_by: Vec::new(),
        paper_sigma_percent: stage.paper_sigma_percent(),
        rms,
        condition_number: u.condition,
        converged: Some(converged),
        evaluations: evaluations * fit.problem.count(),
        seconds: t0.elapsed().as_secs_f64(),
        warnings: u
            .near_singular
            .into_iter()
            .chain(second.filter(SecondStart::said).map(|s| s.to_string()))
            .chain(off_bound)
            .chain(not_converged(converged, run, free.len()))
            .chain(paper_unheld(run.start, &parameters))
            .collect(),
        parameters,
        error_spread: None,
        second_start: second,
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
fn held_undetermined(fit: &mut StageFit, run: &StageRun, evaluations: &mut usize) -> HoldOutcome {
    // Judged even where the stage stopped on its cap: a fit crawling
    // along a direction the data barely see (PKY1 against PKY4) does not
    // converge because of it, and the holds are its remedy; the stage's
    // warning says the judgement is taken where it stopped.
    let stated = |name: &str| {
        let template = run.template.and_then(|t| template_value(t, name));
        run.holding.stated(name, template)
    };
    match run.start {
        StartScheme::Paper => HoldOutcome {
            held: hold_insensitive(fit, &stated),
            refused: Vec::new(),
        },
        StartScheme::Data | StartScheme::Template => {
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

/// The parameters of the paper's scheme's `fit` the data do not move at
/// all (a zero column of the Jacobian: `RVY4` at 6.7e-233, where
/// `cos(atan(RVY4·α))` is flat in it), each held at its `stated` value
/// where that leaves the stage's cost as it is (within 1e-9 of itself):
/// a value the optimiser left there is no fit, and one of −233 decades
/// reads as a misprint in the written file. The scheme holds nothing
/// else, as the paper does not; one whose stated value would move the
/// fit stays free, with its warning.
fn hold_insensitive(
    fit: &mut StageFit,
    stated: &dyn Fn(&str) -> (f64, super::holds::HoldSource),
) -> Vec<(&'static str, f64, HoldReason)> {
    let mut held = Vec::new();
    let cost = |problem: &StageProblem, p: &[f64]| {
        let mut r = vec![0.0; problem.count()];
        problem.residuals(p, &mut r);
        r.iter().map(|e| e * e).sum::<f64>()
    };
    let mut k = 0;
    while k < fit.p.len() && fit.p.len() > 1 {
        let u = uncertainty(&fit.problem, &fit.p);
        let name = fit.problem.names[k];
        let (value, source) = stated(name);
        let before = cost(&fit.problem, &fit.p);
        let without = super::hold_rounds::held_out(&fit.problem, &fit.p, k, value);
        let mut rest = fit.p.clone();
        rest.remove(k);
        let same = |problem: &StageProblem, p: &[f64]| cost(problem, p) <= before * (1.0 + 1e-9);
        // Not moved because its curvature factor sits at its clip at 1
        // over the rows: held there by the bound, not for want of data.
        let clip = u.std_error[k]
            .is_none()
            .then(|| at_clip(&fit.problem, &fit.p, k))
            .flatten();
        if let Some(clip) = clip {
            let fitted = fit.p[k];
            let reason = HoldReason::AtCurvatureClip { fitted, clip };
            fit.hold_out(k, fitted);
            held.push((name, fitted, reason));
            continue;
        }
        if u.std_error[k].is_some() || !same(&without, &rest) {
            // Where its stated value moves the fit, a value of no size
            // (`RVY4` = 6.7e-233) is written as the 0 it is to the fit.
            let mut zero = fit.p.clone();
            zero[k] = 0.0;
            if u.std_error[k].is_none() && fit.p[k].abs() < 1e-12 && same(&fit.problem, &zero) {
                fit.p = zero;
            }
            k += 1;
            continue;
        }
        held.push((
            name,
            value,
            HoldReason::NotIdentifiable {
                fitted: fit.p[k],
                std_error: None,
                effect_percent: 0.0,
                source,
                stated: value,
                held_at: value,
                standard_errors_away: None,
                at_bound: None,
                sigma_held_free: None,
                hold_order: None,
            },
        ));
        fit.hold_out(k, value);
    }
    held
}

/// The report of each parameter of the stage's `table` in the fitted
/// `tyre`: fitted (with its start, standard error `u`, any warning and
/// any hold refused) or held, and why (`holds` by the data, given, or
/// for want of levels).
fn stage_parameters(
    table: &[(&'static str, Need)],
    tyre: &MagicFormula,
    (fit, holds, u): (&StageFit, &HoldOutcome, &Uncertainty),
    run: &StageRun,
    have: [usize; 3],
) -> Vec<StageParameter> {
    table
        .iter()
        .map(|(name, need)| {
            let value = tyre.coefficients.get(name).unwrap_or(0.0);
            let fitted = fit.problem.names.iter().position(|k| k == name);
            let because = holds
                .held
                .iter()
                .find(|h| h.0 == *name)
                .map(|h| h.2.clone())
                // The user's value, even where the levels would hold it too.
                .or_else(|| run.holding.given(name).map(|_| HoldReason::Given))
                .or_else(|| held_reason(name, *need, have));
            let on_bound = fitted.and_then(|k| at_bound(fit.p[k], fit.bounds[k]));
            // Free after its hold was refused: what was tried, and what it
            // cost (`hold_refusal.rs`).
            let hold_refused = fitted.and_then(|_| {
                let r = holds.refused.iter().find(|r| r.0 == *name);
                r.map(|r| r.1.clone())
            });
            let determination =
                fitted.map(|k| determination(fit, u, (k, value), hold_refused.as_ref()));
            let std_error = fitted.and_then(|k| u.std_error[k]);
            let beyond = determination.as_ref().and_then(|d| d.said(std_error));
            StageParameter {
                name,
                on_bound,
                value,
                start: fitted.map_or(value, |k| fit.starts[k]),
                free: fitted.is_some(),
                std_error,
                held: if fitted.is_some() { None } else { because },
                determination,
                // On its bound, the standard error means nothing: said
                // first, as the swarm fits say it; fixed beyond its
                // linearisation, neither does it, and it is not called
                // not identifiable (`determination.rs`).
                warning: on_bound
                    .zip(fitted)
                    .map(|(_, k)| bound_warning(fit.bounds[k]))
                    .or(beyond)
                    .or_else(|| fitted.and_then(|k| u.warning(k, value))),
                hold_refused,
            }
        })
        .collect()
}

/// The warning of a parameter on a bound of `(lo, hi)`.
fn bound_warning((lo, hi): (f64, f64)) -> String {
    format!(
        "on its physical bound ({} to {}): the fit would take it beyond; the value is the bound, not a fit",
        crate::format::exact(lo),
        crate::format::exact(hi)
    )
}

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
    // What the data do not move at all is held even here, and what its
    // curvature's clip at 1 holds (`hold_insensitive`).
    let inert = parameters
        .iter()
        .any(|p| matches!(p.held, Some(HoldReason::NotIdentifiable { .. })));
    let clipped = parameters
        .iter()
        .any(|p| matches!(p.held, Some(HoldReason::AtCurvatureClip { .. })));
    (start == StartScheme::Paper && !unheld.is_empty()).then(|| {
        format!(
            "the paper's scheme (--start paper) holds no parameter for want of data: {} of its parameters, which these data do not determine ({}), are written where its unbounded Levenberg–Marquardt left them, not at a stated value{}; do not rely on this stage's channel beyond the points; --start data (the default) holds such parameters at the template's or Pacejka's (2012) book values and says so",
            unheld.len(),
            unheld.join(", "),
            match (inert, clipped) {
                (true, false) => " (only what the data do not move at all, where its stated value leaves the fit as it is, is held, as said below)",
                (true, true) => " (only what the data do not move at all, where its stated value leaves the fit as it is, and what a curvature's clip at 1 holds, is held, as said below)",
                (false, true) => " (only what a curvature's clip at 1 holds is held, as said below)",
                (false, false) => "",
            }
        )
    })
}

/// The warning of a stage whose Levenberg–Marquardt stopped before its
/// convergence test (its iteration cap), `None` when it converged.
fn not_converged(converged: bool, run: &StageRun, free: usize) -> Option<String> {
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
    let last = continued_cap(free, run);
    let more = match run.start {
        StartScheme::Data | StartScheme::Template if !run.cap_given && last > cap => format!(
            ", and continued on its last step to {last} ({ITERATIONS_PER_FREE} per free parameter), short of it still"
        ),
        _ => String::new(),
    };
    (!converged).then(|| {
        format!(
            "not converged: Levenberg–Marquardt stopped at its cap of {cap} iterations per step \
             before its convergence test (its cost still falling by more than 1e-12 of itself \
             per iteration){more}: the values are where it stopped ({why}){judged}"
        )
    })
}
