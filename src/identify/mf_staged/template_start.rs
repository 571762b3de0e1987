//! A second start from the template's values for a stage of the data
//! start (`--start data`, the default, with a `--template`). The data's
//! estimates start each stage in no basin in particular, and a user who
//! gave a template must not get a worse fit than the template's own start
//! without being told. Each such stage is fitted again from the
//! template's values (clamped into the physical box) unless the data
//! start's fit already reproduces its rows to float precision
//! ([`REPRODUCED_SIGMA_PERCENT`]), and the lower cost kept:
//! - where the data start ends near-singular (a Jacobian of condition
//!   number past 1e8) it may sit in a local minimum whose standard errors,
//!   taken from that linearisation, then misjudge what the data allow. On
//!   noise-free data made by `tyre-eval` from `car205_60R19.tir`, the Mx
//!   stage from the data's estimates stopped at σ 0.002 % (condition
//!   number 4.7e11) with `QSX9` held 25 standard errors from the
//!   template's value that generated the data; from the template's values
//!   it reached 1e-16 N·m at them. Said whichever start is kept.
//! - elsewhere, the stage may stop well conditioned in a local minimum
//!   and say nothing: on the noise-free forces `tyre-eval` gives of the
//!   public `MagicFormula61_Paramerters.tir` over the book's grid, with
//!   that file as template, pure Mz stopped at σ 15.803 % and pure Fy at
//!   0.455 % from the data's estimates; from the template's values both
//!   reach σ 0.000 %. (Round 38 saw pure Mz at 0.142 % on
//!   `car205_60R19.tir`'s forces; on this code its data start reaches
//!   σ 0.000 % there.) The template's fit is kept where its cost is lower
//!   by more than the data tell apart (half a residual variance of the
//!   data start's fit, the holds' tie rule, `holds.rs`), and then said,
//!   with the σ of both starts; where it is not, the data start is kept
//!   and only the report's `second_start` says what the template's
//!   reached.
//!
//! Cost: one more released fit per stage fitted with a template.

use super::params::Need;
use super::problem::StageProblem;
use super::release::released_fit;
use super::start::template_value;
use super::uncertainty::uncertainty;
use super::StartScheme;
use crate::optim::local::LocalResult;
use crate::tyre::mf::MagicFormula;
use serde::Serialize;
use std::fmt;

/// A data start's σ below this (%) reproduces its rows to float precision:
/// no second start can lower it by anything the data tell apart.
pub const REPRODUCED_SIGMA_PERCENT: f64 = 1e-9;

/// Why a stage was fitted again from the template's values.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "reason", rename_all = "kebab-case")]
pub enum SecondStartWhy {
    /// The data start ended near-singular.
    NearSingular {
        /// The condition number of its column-scaled Jacobian there.
        condition_number: f64,
    },
    /// A template was given and the data start did not reproduce the
    /// rows: every such stage is fitted from the template's values too.
    TemplateGiven,
}

/// A stage's second start from the template's values: why, the σ (%) of
/// the stage's rows that each start's fit reached, and the start kept.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SecondStart {
    /// Why the stage was fitted again.
    pub why: SecondStartWhy,
    /// σ of the fit from the data's estimates, %.
    pub sigma_data_percent: f64,
    /// σ of the fit from the template's values, %.
    pub sigma_template_percent: f64,
    /// The start whose fit is kept (`data` or `template`).
    pub kept: StartScheme,
}

impl SecondStart {
    /// Whether the terminal says it: a near-singular data start always,
    /// a template start otherwise where it is kept.
    pub fn said(&self) -> bool {
        matches!(self.why, SecondStartWhy::NearSingular { .. })
            || self.kept == StartScheme::Template
    }
}

impl fmt::Display for SecondStart {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (was, now) = (self.sigma_data_percent, self.sigma_template_percent);
        let kept = self.kept == StartScheme::Template;
        match self.why {
            SecondStartWhy::NearSingular {
                condition_number: condition,
            } => write!(
                f,
                "a second start: the fit from the data's estimates ended near-singular (condition number {}, σ {was:.3} %), where a local minimum would misjudge what the data allow; fitted again from the template's values, it reached σ {now:.3} %: {}",
                crate::format::readable(condition, 3),
                if kept { "kept" } else { "no better, the first kept" }
            ),
            SecondStartWhy::TemplateGiven if kept => write!(
                f,
                "a second start: fitted again from the template's values, the stage reached σ {now:.3} % where the fit from the data's estimates had stopped at σ {was:.3} %: the template's start kept"
            ),
            SecondStartWhy::TemplateGiven => write!(
                f,
                "a second start: fitted again from the template's values, the stage reached σ {now:.3} %, no lower than the σ {was:.3} % from the data's estimates by what the data tell apart: the first kept"
            ),
        }
    }
}

/// The better of `first` (the stage's fit from the data's estimates) and
/// a fit of `problem` from the template's values within `bounds` (module
/// notes), for a stage of `start` with `template` and an iteration cap
/// of `iterations`: the result, the starts of the fit kept (`None`: the
/// first's) and the second start, if one was fitted.
pub(super) fn from_template(
    problem: &StageProblem,
    free: &[(&'static str, Need)],
    first: LocalResult,
    bounds: &[(f64, f64)],
    (start, template, iterations): (StartScheme, Option<&MagicFormula>, usize),
) -> (LocalResult, Option<Vec<f64>>, Option<SecondStart>) {
    let Some(t) = template.filter(|_| start == StartScheme::Data) else {
        return (first, None, None);
    };
    let sigma_of = |p: &[f64]| problem.sigma_percent(p);
    let was = sigma_of(&first.params);
    if was.is_nan() || was < REPRODUCED_SIGMA_PERCENT {
        return (first, None, None);
    }
    let u = uncertainty(problem, &first.params);
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
    let now = sigma_of(&second.params);
    let (why, better) = match u.near_singular {
        Some(_) => (
            SecondStartWhy::NearSingular {
                condition_number: u.condition,
            },
            second.cost.is_finite() && second.cost < first.cost,
        ),
        // Lower by more than half a residual variance (`u.s2`, of Σe²;
        // the costs are ½·Σe²): what the data tell apart.
        None => (
            SecondStartWhy::TemplateGiven,
            second.cost.is_finite() && 2.0 * (first.cost - second.cost) > 0.5 * u.s2,
        ),
    };
    let kept = if better {
        StartScheme::Template
    } else {
        StartScheme::Data
    };
    let said = SecondStart {
        why,
        sigma_data_percent: was,
        sigma_template_percent: now,
        kept,
    };
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
