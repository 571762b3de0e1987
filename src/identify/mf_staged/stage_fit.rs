//! One stage's fit of its free parameters from their start values, before
//! its holds: the paper's own Levenberg–Marquardt for `--start paper`;
//! else the staged release within the physical bounds, continued past the
//! default cap where short of its optimum, fitted again from a template's
//! values where one is given (`template_start.rs`), and fitted again off
//! a physical bound a parameter ends on.

use super::holds::Holding;
use super::paper_lm::paper_lm;
use super::params::Need;
use super::problem::Derivatives;
use super::problem::StageProblem;
use super::release::bounded;
use super::release::{at_bound, profiled, released_fit};
use super::start::template_value;
use super::template_start::SecondStart;
use super::uncertainty::uncertainty;
use super::StartScheme;
use crate::optim::local::LocalResult;
use crate::tyre::mf::MagicFormula;

/// A stage's fit: the result, the starts of the fit kept, the second
/// start from the template's values (`template_start.rs`) and the words
/// of a refit off a physical bound.
pub(super) struct Fitted {
    pub(super) result: LocalResult,
    pub(super) starts: Vec<f64>,
    pub(super) second: Option<SecondStart>,
    pub(super) off_bound: Option<String>,
}

/// The stage's fit of `problem` from `starts` by its scheme, the starts
/// of the fit kept, and what a second start found: from the template's
/// values where a template is given (`template_start.rs`), and off a
/// physical bound (`off_bound`).
pub(super) fn stage_fit(
    problem: &StageProblem,
    free: &[(&'static str, Need)],
    starts: Vec<f64>,
    bounds: &[(f64, f64)],
    run: &StageRun,
) -> Fitted {
    if run.start == StartScheme::Paper {
        let result = paper_lm(problem, &starts, 1.0, run.paper_cap());
        return Fitted {
            result,
            starts,
            second: None,
            off_bound: None,
        };
    }
    let first = released_fit(problem, free, &starts, bounds, run.max_iterations);
    let first = continued(problem, first, bounds, run);
    // With a template, its values are tried too (`template_start.rs`).
    let with = (run.start, run.template, run.max_iterations);
    let (first, from, second) =
        super::template_start::from_template(problem, free, first, bounds, with);
    let from_template = from.is_some();
    let (first, starts) = (
        continued(problem, first, bounds, run),
        from.unwrap_or(starts),
    );
    let (result, starts, off_bound) =
        off_bound(problem, (first, starts), bounds, run, from_template);
    Fitted {
        result,
        starts,
        second,
        off_bound,
    }
}

/// The fit `first` (from `starts`; from the template's values where
/// `from_template`), fitted again where it ends with a parameter on its
/// physical bound: that parameter held inside its box first (at its
/// stated value, and a curvature at −1 too), then released (`profiled`):
/// on noise-free MF 6.1 data the combined-Fx fit from the data's
/// estimates stopped with `REX1` on its bound 1 at σ 0.70 %, where the
/// generating tyre's `REX1` is −1.39 and σ 0. The better cost is kept,
/// and said.
fn off_bound(
    problem: &StageProblem,
    (first, starts): (LocalResult, Vec<f64>),
    bounds: &[(f64, f64)],
    run: &StageRun,
    from_template: bool,
) -> (LocalResult, Vec<f64>, Option<String>) {
    let Some(k) = (0..starts.len()).find(|&k| at_bound(first.params[k], bounds[k]).is_some())
    else {
        return (first, starts, None);
    };
    let name = problem.names[k];
    let template = run.template.and_then(|t| template_value(t, name));
    let stated = run.holding.stated(name, template).0;
    let Some((second, held, from)) = profiled(
        problem,
        &first.params,
        k,
        (bounds, stated),
        run.max_iterations,
    ) else {
        return (first, starts, None);
    };
    let second = continued(problem, second, bounds, run);
    let evaluations = first.evaluations + second.evaluations;
    let sigma_of = |p: &[f64]| problem.sigma_percent(p);
    let (was, now) = (sigma_of(&first.params), sigma_of(&second.params));
    let better = second.cost < first.cost;
    let said = format!(
        "a second start: the fit from the {} ended with {name} on its physical bound (σ {was:.3} %); \
         refitted with {name} held at {} and then released, it reached σ {now:.3} %: {}",
        if run.start == StartScheme::Data && !from_template { "data's estimates" } else { "template's values" },
        crate::format::exact(held),
        if better { "kept" } else { "no better, the first kept" }
    );
    match better {
        true => (
            LocalResult {
                evaluations,
                ..second
            },
            from,
            Some(said),
        ),
        false => (
            LocalResult {
                evaluations,
                ..first
            },
            starts,
            Some(said),
        ),
    }
}

/// How the stages are run: the start scheme, the iteration cap, the
/// derivatives, the values the user gives and the template.
pub(super) struct StageRun<'a> {
    pub(super) start: StartScheme,
    pub(super) max_iterations: usize,
    pub(super) cap_given: bool,
    pub(super) derivatives: Derivatives,
    pub(super) holding: &'a Holding,
    pub(super) template: Option<&'a MagicFormula>,
}

impl StageRun<'_> {
    /// The iteration cap of the paper's scheme: at least
    /// [`PAPER_ITERATIONS`].
    pub(super) fn paper_cap(&self) -> usize {
        self.max_iterations.max(PAPER_ITERATIONS)
    }
}

/// Iterations per free parameter a stage's last step may take where it
/// stops on `--max-iterations` short of its optimum: the Hoosier file's
/// pure Fy (26 free) stopped on the default 150 at every run, and
/// converged with 1000 at the same σ.
pub(super) const ITERATIONS_PER_FREE: usize = 50;

/// The last step's cap of a stage of `free` parameters: at least
/// `--max-iterations`, and [`ITERATIONS_PER_FREE`] for each.
pub(super) fn continued_cap(free: usize, run: &StageRun) -> usize {
    (ITERATIONS_PER_FREE * free).max(run.max_iterations)
}

/// The fit `r`, continued from where it stopped on the default cap up to
/// [`continued_cap`] where it is short of its optimum (not converged, and
/// a Gauss–Newton step would still lower the cost by more than the data
/// tell apart: `Uncertainty::at_optimum`). A cap the user gives is
/// honoured: the stage stops there and says so.
pub(super) fn continued(
    problem: &StageProblem,
    r: LocalResult,
    bounds: &[(f64, f64)],
    run: &StageRun,
) -> LocalResult {
    let cap = continued_cap(r.params.len(), run);
    if run.cap_given
        || r.converged
        || cap <= run.max_iterations
        || uncertainty(problem, &r.params).at_optimum()
    {
        return r;
    }
    let more = bounded(problem, &r.params, bounds, cap - run.max_iterations);
    // A continuation that ends worse, or at no number, is dropped.
    if more.cost.is_nan() || more.cost > r.cost {
        return r;
    }
    LocalResult {
        evaluations: r.evaluations + more.evaluations,
        ..more
    }
}

/// Iterations per step the paper's scheme runs at least: from every
/// parameter at 1 its LM takes hundreds of steps to reach the data.
pub(super) const PAPER_ITERATIONS: usize = 500;
