//! The global stage of a fit: what hands the Levenberg–Marquardt polish
//! ([`super::fit`]) a start in the optimum's basin. Along one to three
//! parameters it is a deterministic grid of cell centres over their box
//! ([`grid`]: 9, 5 × 5 or 3 × 3 × 3 replays of the runs, where a swarm
//! spends 40 to 130); along more it is the crate's particle swarm ([`swarm`]: PSO over
//! the box of each parameter, one particle at the start, stopped once its
//! best has settled). Either evaluates the start too, so a fit is never
//! worse than the model it starts from; the parameters outside the range
//! searched (the axle characteristics of a candidate; a set's members but
//! the one it adds, and the roll dynamics its members fitted) keep their
//! values in the start.
//! Units are the parameters' own; the cost is the problem's scaled
//! ½·Σ e².

use crate::diagnose::fit::problem::Problem;
use crate::diagnose::fit::GlobalSearch;
use crate::diagnose::model::Augmented;
use crate::optim::local::Residuals;
use crate::optim::pso::Pso;
use std::ops::Range;

/// Cells per parameter of the grid stage, by the number of parameters
/// searched (one, two, three); a wider search keeps the swarm. Nine cells
/// put a centre within 1/18 of the box of any optimum, five per axis
/// within 1/10, three within 1/6; the polish needs no more than a start in
/// the optimum's basin. That this is enough for the library's effects,
/// whose costs are smooth in their parameters, is what the confusion
/// matrices check: with the grid they give the swarm's verdicts, held-out
/// errors and fitted values. Along three (a sensor's three offsets,
/// combined slip's shape) the swarm spent 40 to 100 replays per fit, the
/// 27 cells of the grid stopped early wherever their runs show them above
/// the best; on the Putnam log the same verdict and every reported figure
/// to its printed digit, each such fit's in-sample error within 0.01 % of
/// the swarm's.
pub const GRID_CELLS: [usize; 3] = [9, 5, 3];

/// The global stage of a fit over the parameters in `searched` (the rest
/// kept at their values in `start`): a grid ([`grid`]) along one or two
/// parameters, the swarm ([`swarm`]) along more; its best point (never
/// worse than `start`) and how it searched.
// The diagnosis's fits take [`global_best`] (the cost too); this stays for
// callers that need only the point.
#[cfg_attr(not(test), allow(dead_code))]
pub fn global_search<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    start: &[f64],
    pso: &Pso,
    searched: Range<usize>,
) -> (Vec<f64>, GlobalSearch) {
    let (p, _, global) = global_best(problem, start, pso, searched);
    (p, global)
}

/// [`global_search`] with the cost of its best point where it replayed it
/// (None: nothing searched, `start` clamped), that point's replays kept by
/// the problem ([`Residuals::keep_last`]): the polish starts there without
/// replaying it again.
pub fn global_best<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    start: &[f64],
    pso: &Pso,
    searched: Range<usize>,
) -> (Vec<f64>, Option<f64>, GlobalSearch) {
    let searched = searched.start.min(problem.bounds.len())..searched.end.min(problem.bounds.len());
    match searched.len() {
        0 => (problem.clamp(start), None, GlobalSearch::None),
        n @ 1..=3 => {
            let per_parameter = GRID_CELLS[n - 1];
            let (p, cost, points) = grid(problem, start, searched, per_parameter);
            let global = GlobalSearch::Grid {
                per_parameter,
                points,
            };
            (p, Some(cost), global)
        }
        _ => {
            let (p, cost, evaluations) = swarm(problem, start, pso, searched);
            (p, Some(cost), GlobalSearch::Swarm { evaluations })
        }
    }
}

/// The grid stage: the cost at the centres of `cells` equal cells along
/// each parameter in `searched` (the product of them) and at
/// `start`; the lowest of them, its cost and the replays made (a point
/// is replayed only until it is known not to be lower than the best so
/// far, [`Residuals::cost_below`]).
///
/// The cells are replayed nearest the start's cell first ([`visit_order`]):
/// most candidates are not the answer, their optimum lies next to the
/// effect off where their search starts, and once a low best is known the
/// cells beyond it stop after their first runs. The point returned is the
/// one an index-order scan returns whatever the order: the lowest cost,
/// among equal costs the start, then the cell of lowest index (a stopped
/// replay is certainly above the best, so every comparison that decides
/// is one of full costs).
fn grid<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    start: &[f64],
    searched: Range<usize>,
    cells: usize,
) -> (Vec<f64>, f64, usize) {
    let p0 = problem.clamp(start);
    // The best so far: its cost, its cell's index (None: the start) and
    // its point.
    let mut best: (f64, Option<usize>, Vec<f64>) = (problem.cost(&p0), None, p0.clone());
    problem.keep_last();
    let ranges = &problem.bounds[searched.clone()];
    let order = visit_order(&p0[searched.clone()], ranges, cells);
    let total = order.len();
    let mut q = p0.clone();
    for index in order {
        let mut rest = index;
        for (slot, (lo, hi)) in q[searched.clone()].iter_mut().zip(ranges) {
            *slot = lo + ((rest % cells) as f64 + 0.5) * (hi - lo) / cells as f64;
            rest /= cells;
        }
        // Only a point below the best counts: with a best that is not a
        // number, any finite one (no bound then).
        let c = problem.cost_below(&q, best.0);
        // A replay that fails (a cost not finite) is no candidate start;
        // an equal cost wins only over a cell of higher index.
        let tie = c == best.0 && best.1.is_some_and(|b| index < b);
        if c.is_finite() && (best.0.is_nan() || c < best.0 || tie) {
            best = (c, Some(index), q.clone());
            problem.keep_last();
        }
    }
    (best.2, best.0, total + 1)
}

/// The grid's cell indices (the first parameter's cell the fastest
/// digit, `cells` per parameter of `ranges`) ordered by their distance,
/// in cells summed over the parameters, from the cell that holds `p0`,
/// index order among equals.
fn visit_order(p0: &[f64], ranges: &[(f64, f64)], cells: usize) -> Vec<usize> {
    let home: Vec<usize> = p0
        .iter()
        .zip(ranges)
        .map(|(x, (lo, hi))| {
            let at = (x - lo) / (hi - lo) * cells as f64;
            // A point box (hi = lo) or a value that is not a number sits
            // in the first cell.
            if at.is_finite() {
                (at.max(0.0) as usize).min(cells - 1)
            } else {
                0
            }
        })
        .collect();
    let distance = |index: usize| {
        let mut rest = index;
        home.iter()
            .map(|&h| {
                let k = rest % cells;
                rest /= cells;
                k.abs_diff(h)
            })
            .sum::<usize>()
    };
    let mut order: Vec<usize> = (0..cells.pow(ranges.len() as u32)).collect();
    order.sort_by_key(|&index| (distance(index), index));
    order
}

/// The swarm search of a fit: PSO over the bounds of the parameters in
/// `searched` (the rest kept at their values in `start`; at least one is
/// searched, [`global_search`] sees to it), one particle at `start`; its
/// best point, its cost and the evaluations made (each replayed only until
/// it is known not to be below its particle's best,
/// [`Pso::minimize_bounded_from`]).
fn swarm<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    start: &[f64],
    pso: &Pso,
    searched: Range<usize>,
) -> (Vec<f64>, f64, usize) {
    let p0 = problem.clamp(start);
    let full = |q: &[f64]| {
        let mut p = p0.clone();
        p[searched.clone()].copy_from_slice(q);
        p
    };
    // The lowest cost so far, whose replays the problem keeps: the swarm's
    // best (unless an equal one came later, then only replayed again).
    let lowest = std::sync::Mutex::new(f64::INFINITY);
    let r = pso.minimize_bounded_from(
        |q, bound| {
            let c = problem.cost_below(&full(q), bound);
            let mut l = lowest.lock().unwrap_or_else(|e| e.into_inner());
            if c < *l {
                *l = c;
                problem.keep_last();
            }
            c
        },
        &problem.bounds[searched.clone()],
        &[p0[searched.clone()].to_vec()],
    );
    (full(&r.best), r.value, r.evaluations)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::fit::{fit, Polish};
    use crate::diagnose::model::replay::tests::sine_runs;
    use crate::diagnose::model::replay::Prepared;
    use crate::tyre::{MagicSimple, Tyre};
    use crate::vehicle::{Vehicle, VehicleModel};

    /// A car on simplified-Magic-Formula axles of stiffness factors
    /// `p[0]` (front), `p[1]` (rear) and peak friction `p[2]` (1.0 when
    /// not given).
    fn model(p: &[f64]) -> Augmented {
        let d = p.get(2).copied().unwrap_or(1.0);
        let tyre = |b: f64| Tyre::MagicSimple(MagicSimple { b, c: 1.3, d });
        Augmented::new(
            VehicleModel::new(Vehicle::compact_sedan(), tyre(p[0]), tyre(p[1])),
            1.0,
        )
    }

    /// Noise-free runs of the car with B = 9 front, 13 rear.
    fn runs() -> Vec<Prepared> {
        sine_runs(&model(&[9.0, 13.0]))
    }

    const SCALES: [f64; 3] = [2e-3, 5e-2, 1.0];

    /// The optimum of the replays (the 0.01 s replay step of the 1 ms
    /// simulation moves it a little off the truth): Levenberg–Marquardt
    /// from the truth.
    fn optimum(problem: &Problem<fn(&[f64]) -> Augmented>) -> Vec<f64> {
        let f = fit(problem, &[9.0, 13.0], None, Polish::LevenbergMarquardt);
        assert!(f.converged);
        assert!((f.params[0] - 9.0).abs() < 0.5 && (f.params[1] - 13.0).abs() < 0.5);
        f.params
    }

    /// The stiffness factors' box, and the peak friction's.
    const B: (f64, f64) = (2.0, 40.0);
    const D: (f64, f64) = (0.5, 1.5);

    fn problem<'a>(
        runs: &'a [Prepared],
        bounds: &[(f64, f64)],
    ) -> Problem<'a, fn(&[f64]) -> Augmented> {
        let build: fn(&[f64]) -> Augmented = model;
        Problem::new(build, runs.iter().collect(), SCALES, bounds.to_vec())
    }

    #[test]
    fn a_grid_starts_the_polish_in_the_basin_of_the_optimum() {
        let runs = runs();
        let problem = problem(&runs, &[B, B]);
        let best_fit = optimum(&problem);
        let start = [35.0, 35.0];
        let (best, _, points) = grid(&problem, &start, 0..2, 5);
        assert_eq!(points, 26);
        // The lowest of the 25 cell centres 2 + (i + ½)·7.6.
        let centre = |i: usize| 2.0 + (i as f64 + 0.5) * 7.6;
        let lowest = (0..25)
            .map(|k| problem.cost(&[centre(k % 5), centre(k / 5)]))
            .fold(f64::INFINITY, f64::min);
        assert!((problem.cost(&best) - lowest).abs() <= 1e-12 * lowest);
        assert!(lowest < problem.cost(&start));
        let f = fit(&problem, &best, None, Polish::LevenbergMarquardt);
        for k in 0..2 {
            assert!(
                (f.params[k] - best_fit[k]).abs() < 1e-4 * best_fit[k],
                "{:?} against {best_fit:?}",
                f.params
            );
        }
    }

    #[test]
    fn a_grid_never_returns_worse_than_its_start_and_keeps_the_held_values() {
        let runs = runs();
        let problem = problem(&runs, &[B, B]);
        // At the optimum no cell is better.
        let at = optimum(&problem);
        let (best, _, points) = grid(&problem, &at, 0..2, 9);
        assert_eq!((best, points), (at.clone(), 82));
        // The front held at the optimum's: the best of the rear's nine
        // cells is the centre nearest its optimum (2 + 2.5·38/9 = 12.56,
        // the third).
        let (best, _, points) = grid(&problem, &[at[0], 35.0], 1..2, 9);
        assert_eq!(points, 10);
        assert_eq!(best[0], at[0]);
        assert!(
            (best[1] - (2.0 + 2.5 * 38.0 / 9.0)).abs() < 1e-12,
            "{best:?}"
        );
    }

    /// The grid as it was before it visited nearest the start first:
    /// every cell in index order, each replayed whole, the lowest cost
    /// kept (the start among equals, then the first).
    fn index_order_grid(
        problem: &Problem<fn(&[f64]) -> Augmented>,
        start: &[f64],
        searched: Range<usize>,
        cells: usize,
    ) -> (Vec<f64>, f64) {
        let mut best = (problem.cost(start), start.to_vec());
        let mut q = start.to_vec();
        for index in 0..cells.pow(searched.len() as u32) {
            let mut rest = index;
            for k in searched.clone() {
                let (lo, hi) = problem.bounds[k];
                q[k] = lo + ((rest % cells) as f64 + 0.5) * (hi - lo) / cells as f64;
                rest /= cells;
            }
            let c = problem.cost(&q);
            if c.is_finite() && c < best.0 {
                best = (c, q.clone());
            }
        }
        (best.1, best.0)
    }

    #[test]
    fn the_grid_visits_nearest_the_start_first_and_returns_what_an_index_order_scan_returns() {
        let box3 = [(0.0, 3.0), (0.0, 3.0)];
        // From the centre cell: it, its four neighbours, the corners.
        assert_eq!(
            visit_order(&[1.5, 1.5], &box3, 3),
            [4, 1, 3, 5, 7, 0, 2, 6, 8]
        );
        // From a corner (and a value that is not a number: the first cell).
        let from_corner = [0, 1, 3, 2, 4, 6, 5, 7, 8];
        assert_eq!(visit_order(&[0.0, 0.0], &box3, 3), from_corner);
        assert_eq!(visit_order(&[f64::NAN, 0.0], &box3, 3), from_corner);
        assert_eq!(visit_order(&[3.0], &[(0.0, 3.0)], 3), [2, 1, 0]);
        let runs = runs();
        let two = problem(&runs, &[B, B]);
        let start = [21.0, 13.5];
        let (best, cost, points) = grid(&two, &start, 0..2, 5);
        assert_eq!(points, 26);
        assert_eq!((best, cost), index_order_grid(&two, &start, 0..2, 5));
        // A fourth parameter the model does not read: its cells tie to the
        // bit, and the cell of lowest index wins, as in index order,
        // though the start's (its last cell) is visited first.
        let four = problem(&runs, &[B, B, D, (0.0, 1.0)]);
        let start = [9.0, 13.0, 0.7, 0.95];
        let (best, cost, _) = grid(&four, &start, 2..4, 5);
        assert_eq!(best, [9.0, 13.0, 1.0, 0.1]);
        assert_eq!((best, cost), index_order_grid(&four, &start, 2..4, 5));
        // At a start as good as every cell, the start.
        let start = [9.0, 13.0, 1.0, 0.95];
        let (best, _, _) = grid(&four, &start, 3..4, 9);
        assert_eq!(best, start);
    }

    #[test]
    fn the_global_stage_is_a_grid_along_one_to_three_parameters_and_a_swarm_along_more() {
        let runs = runs();
        let two = problem(&runs, &[B, B]);
        let three = problem(&runs, &[B, B, D]);
        // A fourth parameter the model does not read: the swarm's width.
        let four = problem(&runs, &[B, B, D, (0.0, 1.0)]);
        let pso = Pso {
            particles: 6,
            iterations: 3,
            seed: 7,
            ..Pso::default()
        };
        let start = [20.0, 20.0, 1.0, 0.5];
        let stage = |p: &Problem<_>, held: usize| {
            global_search(p, &start[..p.bounds.len()], &pso, held..p.bounds.len()).1
        };
        assert_eq!(
            stage(&two, 0),
            GlobalSearch::Grid {
                per_parameter: 5,
                points: 26
            }
        );
        assert_eq!(
            stage(&two, 1),
            GlobalSearch::Grid {
                per_parameter: 9,
                points: 10
            }
        );
        assert_eq!(stage(&two, 2), GlobalSearch::None);
        assert_eq!(
            stage(&three, 0),
            GlobalSearch::Grid {
                per_parameter: 3,
                points: 28
            }
        );
        assert!(matches!(stage(&four, 0), GlobalSearch::Swarm { evaluations } if evaluations >= 6));
        assert!(matches!(
            stage(&three, 1),
            GlobalSearch::Grid { points: 26, .. }
        ));
        // A range that leaves a tail held (a set's roll dynamics) grids
        // the parameters inside it only, and keeps the tail's values.
        let (best, global) = global_search(&three, &[20.0, 20.0, 1.3], &pso, 0..1);
        assert_eq!(
            global,
            GlobalSearch::Grid {
                per_parameter: 9,
                points: 10
            }
        );
        assert_eq!(best[1..], [20.0, 1.3]);
    }
}
