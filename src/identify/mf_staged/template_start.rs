//! A second start from the template's values for a stage of the data
//! start (`--start data`, the default, with a `--template`) that ends
//! near-singular. The data's estimates start each stage in no basin in
//! particular; where the stage stops with a Jacobian of condition number
//! past 1e8 it may sit in a local minimum whose standard errors, taken
//! from that linearisation, then misjudge what the data allow. On
//! noise-free data made by `tyre-eval` from `car205_60R19.tir`, the Mx
//! stage from the data's estimates stopped at σ 0.002 % (condition number
//! 4.7e11) with `QSX9` held 25 standard errors from the template's value
//! that generated the data; from the template's values it reached
//! 1e-16 N·m at them. Both are fitted and the lower cost kept, and said.
//! Only then: a stage that ends well conditioned keeps its one start (the
//! template scheme is `--start template`).

use super::params::Need;
use super::problem::StageProblem;
use super::release::released_fit;
use super::start::template_value;
use super::uncertainty::uncertainty;
use super::StartScheme;
use crate::optim::local::LocalResult;
use crate::tyre::mf::MagicFormula;

/// The better of `first` (the stage's fit from the data's estimates) and
/// a fit of `problem` from the template's values within `bounds`, where
/// `first` ends near-singular (module notes), for a stage of `start` with
/// `template` and an iteration cap of `iterations`: the result, the
/// starts of the fit kept (`None`: the first's) and what was said.
pub(super) fn from_template(
    problem: &StageProblem,
    free: &[(&'static str, Need)],
    first: LocalResult,
    bounds: &[(f64, f64)],
    (start, template, iterations): (StartScheme, Option<&MagicFormula>, usize),
) -> (LocalResult, Option<Vec<f64>>, Option<String>) {
    let Some(t) = template.filter(|_| start == StartScheme::Data) else {
        return (first, None, None);
    };
    let u = uncertainty(problem, &first.params);
    if u.near_singular.is_none() {
        return (first, None, None);
    }
    let condition = u.condition;
    let starts: Vec<f64> = problem
        .names
        .iter()
        .zip(bounds)
        .zip(&first.params)
        .map(|((n, (lo, hi)), p)| {
            template_value(t, n).map_or(*p, |v| v.clamp(lo.min(*hi), hi.max(*lo)))
        })
        .collect();
    let second = released_fit(problem, free, &starts, bounds, iterations);
    let sigma_of = |p: &[f64]| problem.sigma_percent(p);
    let (was, now) = (sigma_of(&first.params), sigma_of(&second.params));
    let better = second.cost.is_finite() && second.cost < first.cost;
    let said = format!(
        "a second start: the fit from the data's estimates ended near-singular (condition number {}, σ {was:.3} %), where a local minimum would misjudge what the data allow; fitted again from the template's values, it reached σ {now:.3} %: {}",
        crate::format::readable(condition, 3),
        if better { "kept" } else { "no better, the first kept" }
    );
    let evaluations = first.evaluations + second.evaluations;
    match better {
        true => (
            LocalResult {
                evaluations,
                ..second
            },
            Some(starts),
            Some(said),
        ),
        false => (
            LocalResult {
                evaluations,
                ..first
            },
            None,
            Some(said),
        ),
    }
}
