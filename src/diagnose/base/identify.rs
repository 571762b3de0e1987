//! The base model identified from the runs when a campaign has no tyre
//! data: per axle a simplified Magic Formula (Li, Jia & Zhao,
//! `Fy = D·μ·Fz·sin(C·atan(B·α))`, C = 1.3) of cornering coefficient
//! `k = B·C·D` (cornering stiffness per unit load, 1/rad), and one peak
//! friction `D` shared by the axles.
//!
//! **Parameterised by physical limits.** The fit works on shares,
//! `s = k/(k + k_ref)` and `t = D/(D + D_ref)`, each in (0, 1): a share's
//! ends are limits of the quantity, not numbers picked for a search. `s → 0`
//! is an axle that makes no cornering force, `s → 1` a rigid axle that
//! never slips, `t → 0` a road without grip, `t → 1` a tyre that never
//! saturates. The fit's box stops just short of them
//! ([`crate::diagnose::model::axles::AXLE_BOUNDS`]:
//! k from 0.4 to 4,000 1/rad, D from 0.11 to 9); an optimum there is named
//! with what it means and which way the data pull ([`AxleLimit`]). A rigid
//! axle, one without force, a road without grip, or an axle whose force
//! peaks before 2° of slip (a stiff axle on little friction, acting like a
//! sign function of its slip) is no tyre: the base is then *degenerate* and
//! the diagnosis gives no model-form verdict from it.
//! A friction that never saturates only says that the runs stay in the
//! linear range: D is then not identified, which is reported, not refused.
//!
//! **Starts from the data.** The cost surface has long valleys (a stiff
//! rear trades against a soft front) and the no-effect basin of a banked
//! run is far from the banked one's, so a start is not a guess: the
//! runs are replayed over a grid of front and rear coefficients (5 to 380
//! 1/rad, geometric) at a friction that does not saturate, the best grid
//! points of distinct basins are polished by Levenberg–Marquardt
//! ([`identify_axles`]) against the prior as stated, and the fit starts
//! from the polish best against the prior tempered by the runs' own
//! evidence ([`best_tempered`]): the untempered best may be a basin far
//! outside the prior that the tempered polish would only refine. A
//! candidate effect is refitted jointly with the axles from a grid at its
//! own values
//! ([`axle_grid`]), so that an effect such as the measured bank is not
//! judged in the basin of the model without it.
//!
//! Units: SI, rad; k in 1/rad (N of lateral force per N of load per rad of
//! slip), D dimensionless.

use crate::diagnose::base::no_tyre::early_peaks;
pub use crate::diagnose::base::no_tyre::{Axle, AxleLimit, NoTyre, AXLE_NAMES, PEAK_SLIP_MIN};
use crate::diagnose::base::prior::PriorReport;
use crate::diagnose::fit::problem::Problem;
use crate::diagnose::fit::FIT_TOLERANCE;
#[cfg(test)]
pub(crate) use crate::diagnose::model::axles::axle_tyres;
pub use crate::diagnose::model::axles::{coefficient, friction, shares, SHAPE};
use crate::diagnose::model::axles::{D_REF, K_REF};
use crate::diagnose::model::Augmented;
use crate::optim::bounded::{BoundedLm, Jacobians};
use crate::optim::local::Residuals;
use rayon::prelude::*;
use serde::Serialize;

/// Shares of the start grid's coefficients: k = 5, 13, 30, 80, 380 1/rad.
const GRID: [f64; 5] = [0.2, 0.4, 0.6, 0.8, 0.95];
/// Friction share of the start grid: D = 4, far from saturating.
const GRID_FRICTION: f64 = 0.8;
/// Grid points polished when identifying the base (distinct basins).
const BASE_STARTS: usize = 3;

/// One axle characteristic as identified, in physical units.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AxleValue {
    /// Name.
    pub name: &'static str,
    /// Unit.
    pub unit: &'static str,
    /// Value.
    pub value: f64,
    /// Standard error (NaN, written as `null`, where the data do not pin it).
    #[serde(serialize_with = "crate::report::finite_or_null")]
    pub std_error: f64,
    /// The limit it stands on, if any.
    pub limit: Option<AxleLimit>,
    /// Whether it was held at its prior's value (the peak friction of runs
    /// that never approach the limit, [`crate::diagnose::base::prior`]).
    pub held: bool,
}

/// The axle characteristics identified from the runs, and how well the
/// runs pin them.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AxleIdentification {
    /// Front and rear cornering coefficient (1/rad) and peak friction.
    pub parameters: Vec<AxleValue>,
    /// The most correlated pair of the three, and its correlation
    /// (None where the covariance is singular).
    pub largest_correlation: Option<(String, String, f64)>,
    /// Grid points polished (several starts).
    pub starts: usize,
    /// Why the base is no tyre (a rigid axle, one without force, no grip,
    /// an early peak); empty for a tyre.
    pub no_tyre: Vec<NoTyre>,
    /// The prior the axles were fitted against, and where they lie on it
    /// (the base's identification; None for a candidate's axles).
    pub prior: Option<PriorReport>,
}

impl AxleIdentification {
    /// The identification of shares `p` with standard errors `se` (of the
    /// shares) and the Jacobian's covariance `cov` (of the shares).
    pub fn new(p: &[f64], se: &[f64], cov: Option<&nalgebra::DMatrix<f64>>, starts: usize) -> Self {
        // Standard errors through the derivative of each share's map.
        let d_k = |s: f64| K_REF / ((1.0 - s) * (1.0 - s));
        let d_d = |t: f64| D_REF / ((1.0 - t) * (1.0 - t));
        let parameters: Vec<AxleValue> = (0..3)
            .map(|i| AxleValue {
                name: AXLE_NAMES[i],
                unit: if i < 2 { "1/rad" } else { "-" },
                value: if i < 2 {
                    coefficient(p[i])
                } else {
                    friction(p[i])
                },
                std_error: se[i] * if i < 2 { d_k(p[i]) } else { d_d(p[i]) },
                limit: AxleLimit::of(i, p),
                held: false,
            })
            .collect();
        let largest_correlation = cov.and_then(|c| {
            let mut best: Option<(String, String, f64)> = None;
            for i in 0..3 {
                for j in i + 1..3 {
                    let rho = c[(i, j)] / (c[(i, i)] * c[(j, j)]).sqrt();
                    if rho.is_finite() && best.as_ref().is_none_or(|b| rho.abs() > b.2.abs()) {
                        best = Some((AXLE_NAMES[i].into(), AXLE_NAMES[j].into(), rho));
                    }
                }
            }
            best
        });
        let mut no_tyre: Vec<NoTyre> = parameters
            .iter()
            .filter_map(|v| {
                v.limit
                    .filter(|l| l.degenerate())
                    .map(|limit| NoTyre::Limit {
                        parameter: v.name,
                        limit,
                    })
            })
            .collect();
        no_tyre.extend(early_peaks(p));
        Self {
            parameters,
            largest_correlation,
            starts,
            no_tyre,
            prior: None,
        }
    }

    /// The same identification fitted against `prior`: a peak friction the
    /// rule held is named so, without a standard error (it was not
    /// fitted).
    pub fn with_prior(mut self, prior: PriorReport) -> Self {
        self.no_tyre.extend(prior.far_outside());
        if !prior.friction_rule.free {
            let d = &mut self.parameters[2];
            d.held = true;
            d.std_error = f64::NAN;
            d.limit = None;
        }
        self.prior = Some(prior);
        self
    }

    /// Whether the axles are no tyre.
    pub fn degenerate(&self) -> bool {
        !self.no_tyre.is_empty()
    }
}

/// The grid of axle shares (front, rear) at the grid friction, each
/// followed by `tail` (a candidate's effect values), ordered by cost:
/// `(cost, vector)`. The grid points run in parallel.
pub fn axle_grid<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    tail: &[f64],
) -> Vec<(f64, Vec<f64>)> {
    // A held friction is where the grid starts too: a grid at another
    // would be judged against its hold.
    let friction_share = problem.grid_friction(GRID_FRICTION);
    let points: Vec<Vec<f64>> = GRID
        .iter()
        .flat_map(|&f| GRID.iter().map(move |&r| (f, r)))
        .map(|(f, r)| {
            let mut p = vec![f, r, friction_share];
            p.extend_from_slice(tail);
            p
        })
        .collect();
    let mut scored: Vec<(f64, Vec<f64>)> = points
        .into_par_iter()
        .map(|p| (problem.cost(&p), p))
        .collect();
    scored.sort_by(|a, b| a.0.total_cmp(&b.0));
    scored
}

/// The first of [`axle_grid`]'s points in its order (the lowest cost,
/// the earlier grid point where two tie), with its cost, for a caller that
/// needs only that: the same point and cost for a fraction of the
/// replays. The points are replayed one after another from the grid point
/// nearest `near` (the front and rear shares a start has) outwards, each
/// only until its runs show it is not below the best so far
/// ([`Residuals::cost_below`], which decides as the whole cost would; a
/// point that ties is replayed whole): most of the grid lies far from the
/// basin and is dropped after a run or two. The best's replays are kept
/// ([`Residuals::keep_last`]). None for an empty grid.
pub fn axle_grid_best<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
    tail: &[f64],
    near: &[f64],
) -> Option<(f64, Vec<f64>)> {
    let friction_share = problem.grid_friction(GRID_FRICTION);
    let index = |x: f64| {
        GRID.iter()
            .enumerate()
            .min_by(|a, b| (a.1 - x).abs().total_cmp(&(b.1 - x).abs()))
            .map_or(0, |(k, _)| k) as i64
    };
    let centre = [near.first(), near.get(1)].map(|x| x.map_or(0, |&x| index(x)));
    let n = GRID.len();
    // (front, rear) grid indices in axle_grid's order, nearest the centre
    // first (that order among equals).
    let mut cells: Vec<(usize, usize)> = (0..n).flat_map(|f| (0..n).map(move |r| (f, r))).collect();
    cells.sort_by_key(|&(f, r)| (f as i64 - centre[0]).abs() + (r as i64 - centre[1]).abs());
    let mut best: Option<(f64, usize, Vec<f64>)> = None;
    for (f, r) in cells {
        let mut p = vec![GRID[f], GRID[r], friction_share];
        p.extend_from_slice(tail);
        let order = f * n + r;
        // A best of zero cost would stop a tie at its first run: replayed
        // whole then.
        let c = match &best {
            Some((b, _, _)) if *b > 0.0 => problem.cost_below(&p, *b),
            _ => problem.cost(&p),
        };
        let lower = best
            .as_ref()
            .is_none_or(|(b, k, _)| c.total_cmp(b).then_with(|| order.cmp(k)).is_lt());
        if lower {
            problem.keep_last();
            best = Some((c, order, p));
        }
    }
    best.map(|(c, _, p)| (c, p))
}

/// Grid points of distinct basins: the best, then the next best that are
/// not a grid neighbour of one already taken, up to `n`.
fn distinct(scored: &[(f64, Vec<f64>)], n: usize) -> Vec<Vec<f64>> {
    let index = |x: f64| GRID.iter().position(|&g| g == x).unwrap_or(0) as i64;
    let mut taken: Vec<Vec<f64>> = Vec::new();
    for (c, p) in scored {
        if !c.is_finite() || taken.len() >= n {
            continue;
        }
        let near = taken.iter().any(|q| {
            (index(q[0]) - index(p[0])).abs() <= 1 && (index(q[1]) - index(p[1])).abs() <= 1
        });
        if !near {
            taken.push(p.clone());
        }
    }
    taken
}

/// The grid's distinct basins polished by Levenberg–Marquardt under
/// `problem` (its prior as it stands: untempered when the base is first
/// identified), each as `(cost, shares)` lowest cost first, and the number
/// of starts. Every basin is kept, not only the best: the prior is
/// tempered after this polish ([`best_tempered`]), and a basin the
/// untempered prior let the runs pull far off it may then lose to one
/// inside it.
pub fn identify_axles<F: Fn(&[f64]) -> Augmented + Sync>(
    problem: &Problem<F>,
) -> (Vec<(f64, Vec<f64>)>, usize) {
    let grid = axle_grid(problem, &[]);
    let starts = distinct(&grid, BASE_STARTS);
    let mut polished: Vec<(f64, Vec<f64>)> = starts
        .par_iter()
        .map(|p| {
            let lm = BoundedLm {
                iterations: 30,
                tolerance: FIT_TOLERANCE,
                jacobians: Jacobians::Secant,
            }
            .minimize(problem, p, &problem.bounds);
            (lm.cost, lm.params)
        })
        .collect();
    polished.sort_by(|a, b| a.0.total_cmp(&b.0));
    if polished.is_empty() {
        polished.push((f64::NAN, shares(20.0, 20.0, 1.0).to_vec()));
    }
    (polished, starts.len())
}

/// The data's cost of `polished` basins, each `(cost, shares)` with its
/// cost under `problem`'s prior: the cost less the prior's rows, as
/// `(data cost, shares)`.
pub fn data_costs<F: Fn(&[f64]) -> Augmented + Sync>(
    polished: &[(f64, Vec<f64>)],
    problem: &Problem<F>,
) -> Vec<(f64, Vec<f64>)> {
    polished
        .iter()
        .map(|(c, p)| (c - problem.prior_cost(p), p.clone()))
        .collect()
}

/// Of basins of data cost `data` (`(data cost, shares)`, [`data_costs`]),
/// the one lowest under `tempered`'s prior: its data cost plus the
/// tempered prior's rows, no replay needed. The basins were polished
/// against the untempered prior, which counts every residual as an
/// independent sample: thousands of them outweigh it at a small gain in
/// fit, and the best basin there may lie far outside the prior (the slow
/// oval's, [`crate::diagnose::base`]) where the tempered prior charges
/// more than the runs gain. A basin of no finite cost is passed over; the
/// first of `data` when none is finite, None for none.
pub fn best_tempered<F: Fn(&[f64]) -> Augmented + Sync>(
    data: &[(f64, Vec<f64>)],
    tempered: &Problem<F>,
) -> Option<Vec<f64>> {
    data.iter()
        .map(|(c, p)| (c + tempered.prior_cost(p), p))
        .filter(|(c, _)| c.is_finite())
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, p)| p.clone())
        .or_else(|| data.first().map(|(_, p)| p.clone()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::base::no_tyre::peak_slip;
    use crate::diagnose::model::axles::AXLE_BOUNDS;
    use crate::tyre::Tyre;

    #[test]
    fn shares_map_to_coefficients_and_back_and_the_box_is_where_the_doc_says() {
        let p = shares(12.0, 30.0, 1.4);
        assert!((coefficient(p[0]) - 12.0).abs() < 1e-12);
        assert!((coefficient(p[1]) - 30.0).abs() < 1e-12);
        assert!((friction(p[2]) - 1.4).abs() < 1e-12);
        // The box's ends in physical units, as the module doc and the
        // limits' meanings state them.
        assert!((coefficient(AXLE_BOUNDS[0].0) - 0.408).abs() < 1e-3);
        assert!((coefficient(AXLE_BOUNDS[0].1) - 3980.0).abs() < 1.0);
        assert!((friction(AXLE_BOUNDS[2].0) - 0.111).abs() < 1e-3);
        assert!((friction(AXLE_BOUNDS[2].1) - 9.0).abs() < 1e-9);
        // The tyres' slope per unit load is the coefficient.
        let (f, r) = axle_tyres(&p);
        for (t, k) in [(f, 12.0), (r, 30.0)] {
            let Tyre::MagicSimple(m) = t else { panic!() };
            assert!((m.b * m.c * m.d - k).abs() < 1e-9);
        }
    }

    #[test]
    fn a_limit_is_named_for_what_it_means_and_only_the_linear_one_is_harmless() {
        let (lo, hi) = AXLE_BOUNDS[1];
        assert_eq!(AxleLimit::of(1, &[0.5, hi, 0.5]), Some(AxleLimit::Rigid));
        assert_eq!(AxleLimit::of(0, &[lo, 0.5, 0.5]), Some(AxleLimit::NoForce));
        assert_eq!(AxleLimit::of(2, &[0.5, 0.5, 0.9]), Some(AxleLimit::Linear));
        assert_eq!(AxleLimit::of(2, &[0.5, 0.5, 0.1]), Some(AxleLimit::NoGrip));
        assert_eq!(AxleLimit::of(0, &[0.5, 0.5, 0.5]), None);
        // A rigid rear (which also peaks within a fraction of a degree).
        let id = AxleIdentification::new(&[0.5, hi, 0.9], &[0.01; 3], None, 3);
        assert_eq!(
            id.no_tyre[0],
            NoTyre::Limit {
                parameter: "rear cornering coefficient",
                limit: AxleLimit::Rigid
            }
        );
        assert!(matches!(
            id.no_tyre[1..],
            [NoTyre::EarlyPeak {
                axle: Axle::Rear,
                ..
            }]
        ));
        // A friction that never saturates is on a limit and still a tyre.
        let linear = AxleIdentification::new(&[0.5, 0.6, 0.9], &[0.01; 3], None, 3);
        assert!(!linear.degenerate());
        assert_eq!(linear.parameters[2].limit, Some(AxleLimit::Linear));
    }

    /// Runs of a car whose axles are the simplified Magic Formula of
    /// shares `truth`: sine steers at three speeds, 25 Hz, yaw rate and ay.
    fn runs_of(truth: &[f64]) -> Vec<crate::diagnose::model::replay::Prepared> {
        use crate::vehicle::{Vehicle, VehicleModel};
        let (f, r) = axle_tyres(truth);
        let car = Augmented::new(VehicleModel::new(Vehicle::compact_sedan(), f, r), 1.0);
        crate::diagnose::model::replay::tests::sine_runs(&car)
    }

    #[test]
    fn the_grid_and_its_polish_recover_known_axles_from_far_off_the_grid() {
        use crate::vehicle::{Vehicle, VehicleModel};
        // Front 9, rear 24 1/rad (between grid nodes), a friction the
        // runs reach (0.9: the sines peak near 5 m/s²).
        let truth = shares(9.0, 24.0, 0.9);
        let runs = runs_of(&truth);
        let problem = Problem::new(
            |p: &[f64]| {
                let (f, r) = axle_tyres(p);
                Augmented::new(VehicleModel::new(Vehicle::compact_sedan(), f, r), 1.0)
            },
            runs.iter().collect(),
            [2e-4, 5e-3, 1.0],
            AXLE_BOUNDS.to_vec(),
        );
        let (polished, starts) = identify_axles(&problem);
        assert_eq!(starts, BASE_STARTS);
        let start = polished[0].1.clone();
        // The diagnosis polishes the best start to convergence.
        let p = crate::diagnose::fit::fit(
            &problem,
            &start,
            None,
            crate::diagnose::fit::Polish::LevenbergMarquardt,
        )
        .params;
        for (i, want) in [9.0, 24.0].into_iter().enumerate() {
            let k = coefficient(p[i]);
            // Measured 0.3 %: the replay sees the steer interpolated
            // linearly between 25 Hz samples (up to 0.5 % low at the sine
            // peaks), the truth the sine itself.
            assert!(
                (k / want - 1.0).abs() < 1e-2,
                "axle {i}: {k} against {want}"
            );
        }
        // Measured 1.1 %, the same interpolation at the peaks.
        assert!(
            (friction(p[2]) / 0.9 - 1.0).abs() < 2e-2,
            "{}",
            friction(p[2])
        );
    }

    #[test]
    fn the_start_is_the_basin_best_under_the_tempered_prior_not_the_untempered() {
        use crate::diagnose::base::prior::{rows, FrictionRule};
        use crate::diagnose::campaign::prior::{AxlePrior, TyreClass};
        use crate::vehicle::{Vehicle, VehicleModel};
        // The slow oval's two basins (session 108): 22 / 22 1/rad inside
        // the road prior (8–35), 138 / 190 1/rad 5.6 and 6.5 σ outside it,
        // the friction held. Data costs (½Σr², no replay made) such that
        // the untempered prior (rows of weight 1, ½(5.6² + 6.5²) ≈ 36.6
        // for the stiff basin) lets the stiff one win by its lower data
        // cost, and the slow oval's tempering (×139) does not.
        let prior = AxlePrior::of(TyreClass::Road);
        let rule = FrictionRule::new(&prior, 1.3);
        let held = rule.value;
        let (soft, stiff) = (shares(22.0, 22.0, held), shares(138.0, 190.0, held));
        let runs = runs_of(&soft);
        let problem = |weight: f64| {
            Problem::new(
                |p: &[f64]| {
                    let (f, r) = axle_tyres(p);
                    Augmented::new(VehicleModel::new(Vehicle::compact_sedan(), f, r), 1.0)
                },
                runs.iter().collect(),
                [2e-4, 5e-3, 1.0],
                AXLE_BOUNDS.to_vec(),
            )
            .with_prior(Some(rows(&prior, &rule, 0).tempered(weight)))
        };
        let untempered = problem(1.0);
        let z = |k: f64| AxlePrior::z(prior.cornering, k);
        let stiff_rows = 0.5 * (z(138.0).powi(2) + z(190.0).powi(2));
        assert!((untempered.prior_cost(&stiff) - stiff_rows).abs() < 1e-6 * stiff_rows);
        // Polished costs under the untempered prior (data + rows): the
        // data cost back is each basin's own.
        let soft_rows = untempered.prior_cost(&soft);
        let polished = vec![
            (960.0 + stiff_rows, stiff.to_vec()),
            (1000.0 + soft_rows, soft.to_vec()),
        ];
        let data = data_costs(&polished, &untempered);
        assert!((data[0].0 - 960.0).abs() < 1e-9, "{data:?}");
        assert!((data[1].0 - 1000.0).abs() < 1e-9, "{data:?}");
        // Untempered, the stiff basin is the best: 40 less of data cost
        // against its 36.6 of rows (the soft one's 0.5).
        assert!(soft_rows < 1.0, "{soft_rows}");
        assert_eq!(best_tempered(&data, &untempered), Some(stiff.to_vec()));
        // Tempered ×139, its rows cost 139² times more: the soft basin.
        assert_eq!(best_tempered(&data, &problem(139.1)), Some(soft.to_vec()));
        // A basin of no finite cost is passed over.
        let broken = vec![(f64::NAN, stiff.to_vec()), (1000.0, soft.to_vec())];
        assert_eq!(best_tempered(&broken, &untempered), Some(soft.to_vec()));
        assert_eq!(best_tempered(&[], &untempered), None);
    }

    #[test]
    fn an_axle_that_peaks_before_two_degrees_is_no_tyre() {
        // Putnam's base: rear 284 1/rad at D 1.0 peaks at 0.69°.
        let id = AxleIdentification::new(&shares(43.1, 283.8, 1.0), &[0.01; 3], None, 3);
        let [NoTyre::EarlyPeak {
            axle: Axle::Rear,
            peak_slip: slip,
            coefficient_over_friction,
        }] = id.no_tyre[..]
        else {
            panic!(
                "a rear peaking at 0.69° is no tyre, the front is: {:?}",
                id.no_tyre
            );
        };
        assert!((slip.to_degrees() - 0.69).abs() < 0.005, "{slip}");
        assert!((coefficient_over_friction - 283.8).abs() < 1e-6);
        // The same stiffness far from saturating (D 9) is a tyre.
        let linear = AxleIdentification::new(&shares(43.1, 283.8, 9.0), &[0.01; 3], None, 3);
        assert!(!linear.degenerate());
        // The peak is where the axle's force is largest.
        let (f, _) = axle_tyres(&shares(20.0, 20.0, 1.0));
        let Tyre::MagicSimple(m) = f else { panic!() };
        let force = |a: f64| (m.c * (m.b * a).atan()).sin();
        let a = peak_slip(20.0, 1.0);
        assert!(
            force(a) > force(a * 0.999) && force(a) > force(a * 1.001),
            "{a}"
        );
    }

    #[test]
    fn distinct_starts_skip_grid_neighbours() {
        let pt = |f: f64, r: f64, c: f64| (c, vec![f, r, GRID_FRICTION]);
        let scored = vec![
            pt(0.4, 0.4, 1.0),
            pt(0.6, 0.4, 1.1),
            pt(0.95, 0.2, 1.2),
            pt(0.2, 0.95, f64::NAN),
            pt(0.2, 0.8, 1.3),
        ];
        let d = distinct(&scored, 3);
        assert_eq!(d.len(), 3);
        assert_eq!(d[0][..2], [0.4, 0.4]);
        assert_eq!(d[1][..2], [0.95, 0.2]);
        assert_eq!(d[2][..2], [0.2, 0.8]);
    }
}
