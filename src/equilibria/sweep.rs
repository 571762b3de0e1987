//! Sweeps of the equilibrium problem over steer, friction and speed: every
//! point solved by the exact reference and by the PSO search, the two
//! cross-checked, and bifurcations located along each swept axis.
//!
//! Lines of constant friction and speed are solved in parallel (rayon); along
//! a line the PSO search is seeded with the previous point's equilibria, so a
//! sweep is deterministic for a given seed whatever the thread count.

use super::bifurcation::{self, Axis, Bifurcation};
use super::pso::{self, PsoSearch};
use super::{distance, exact, Condition, Equilibrium, FoundBy, SearchBox};
use crate::vehicle::VehicleModel;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The swept values (SI units, rad and m/s).
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    /// Steer angles, rad.
    pub steer: Vec<f64>,
    /// Friction scales.
    pub friction: Vec<f64>,
    /// Speeds, m/s.
    pub speed: Vec<f64>,
}

impl Grid {
    /// Number of conditions.
    pub fn len(&self) -> usize {
        self.steer.len() * self.friction.len() * self.speed.len()
    }
    /// True when a list is empty.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// Axes with more than one value.
    pub(crate) fn varying(&self) -> Vec<Axis> {
        [
            (Axis::Steer, &self.steer),
            (Axis::Friction, &self.friction),
            (Axis::Speed, &self.speed),
        ]
        .into_iter()
        .filter(|(_, v)| v.len() > 1)
        .map(|(a, _)| a)
        .collect()
    }
    /// Values of an axis.
    pub fn values(&self, axis: Axis) -> &[f64] {
        match axis {
            Axis::Steer => &self.steer,
            Axis::Friction => &self.friction,
            Axis::Speed => &self.speed,
        }
    }
    /// Index of a point: steer fastest.
    pub fn index(&self, i_steer: usize, i_friction: usize, i_speed: usize) -> usize {
        (i_speed * self.friction.len() + i_friction) * self.steer.len() + i_steer
    }
}

/// One equilibrium in a sweep's output.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Found {
    /// The equilibrium (the exact solver's where both found it).
    pub equilibrium: Equilibrium,
    /// Which solver found it.
    pub found_by: FoundBy,
    /// Whether it lies in the search box.
    pub in_box: bool,
}

/// The result at one condition.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PointResult {
    /// The condition.
    pub condition: Condition,
    /// Every isolated equilibrium the exact solver found (anywhere).
    pub exact: Vec<Equilibrium>,
    /// Continua of equilibria (curves, not points), if any.
    pub continua: Vec<exact::Continuum>,
    /// Exact and PSO equilibria merged.
    pub found: Vec<Found>,
    /// Whether PSO and exact agree in the box: same count, same points.
    pub agree: bool,
    /// Fitness evaluations of the PSO search.
    pub pso_evaluations: usize,
    /// Sum of the indices of the equilibria the swarm found in the box.
    #[serde(default)]
    pub index_sum: i32,
    /// Winding number of the field around the box (None: not asked, or
    /// the field vanishes on the box's edge).
    #[serde(default)]
    pub winding: Option<i32>,
}

/// The swarm's completeness certificate at one condition (Poincaré–Hopf:
/// the indices of the equilibria found add up to the winding number).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Certificate {
    /// The index sum equals the winding number.
    Holds,
    /// The index sum differs from the winding number: the swarm missed
    /// an equilibrium (or found one that is none).
    FallsShort,
    /// No winding number: the field nearly vanishes on the box's edge.
    Undefined,
    /// `certify = false`: no winding number taken.
    NotAsked,
}

impl PointResult {
    /// The certificate at this condition; `certify`: whether the search
    /// took the winding number.
    pub fn certificate(&self, certify: bool) -> Certificate {
        match (certify, self.winding) {
            (false, _) => Certificate::NotAsked,
            (true, None) => Certificate::Undefined,
            (true, Some(w)) if w == self.index_sum => Certificate::Holds,
            (true, Some(_)) => Certificate::FallsShort,
        }
    }
}

/// A whole sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepResult {
    /// The grid.
    pub grid: Grid,
    /// Per point, steer fastest.
    pub points: Vec<PointResult>,
    /// Bifurcations along every varying axis.
    pub bifurcations: Vec<Bifurcation>,
}

impl SweepResult {
    /// Points where PSO and the exact solver agree.
    pub fn agreeing(&self) -> usize {
        self.points.iter().filter(|p| p.agree).count()
    }
}

/// Scaled distance under which a PSO equilibrium is the exact one.
const SAME_POINT: f64 = 1e-6;

/// Merges the exact and PSO equilibria of one condition. PSO points on a
/// continuum of equilibria (rear slip angle inside one of `continua`, with a
/// margin of one and a half scan cells, as its true ends lie within a cell of
/// the scanned ones) are points of that curve, not isolated equilibria, and
/// are left out.
pub(crate) fn cross_check(
    exact: &[Equilibrium],
    pso: &[Equilibrium],
    continua: &[exact::Continuum],
    bx: &SearchBox,
) -> (Vec<Found>, bool) {
    let scale = bx.scale();
    let margin = 1.5 * exact::CELL;
    let on_curve = |e: &Equilibrium| {
        continua.iter().any(|c| {
            e.alpha_rear >= c.alpha_rear.0 - margin && e.alpha_rear <= c.alpha_rear.1 + margin
        })
    };
    let pso: Vec<Equilibrium> = pso.iter().copied().filter(|e| !on_curve(e)).collect();
    let mut used = vec![false; pso.len()];
    let mut found = Vec::new();
    let mut agree = true;
    for e in exact {
        let in_box = bx.contains([e.beta, e.yaw_rate]);
        let m = pso.iter().enumerate().find(|(i, p)| {
            !used[*i] && distance([p.beta, p.yaw_rate], [e.beta, e.yaw_rate], scale) < SAME_POINT
        });
        let found_by = match m {
            Some((i, _)) => {
                used[i] = true;
                FoundBy::Both
            }
            None => {
                if in_box {
                    agree = false;
                }
                FoundBy::Exact
            }
        };
        found.push(Found {
            equilibrium: *e,
            found_by,
            in_box,
        });
    }
    for (i, p) in pso.iter().enumerate() {
        if !used[i] {
            agree = false;
            found.push(Found {
                equilibrium: *p,
                found_by: FoundBy::Pso,
                in_box: true,
            });
        }
    }
    (found, agree)
}

/// Solves every point of the grid; `progress` counts finished points.
pub fn run(
    model: &VehicleModel,
    grid: &Grid,
    bx: &SearchBox,
    search: &PsoSearch,
    with_bifurcations: bool,
    progress: &AtomicUsize,
) -> SweepResult {
    let all: Vec<usize> = (0..grid_lines(grid).len()).collect();
    let solved = solve_lines(model, grid, bx, search, &all, progress);
    assemble(model, grid, solved, with_bifurcations)
}

/// The lines of constant friction and speed, as (friction, speed) indices,
/// speed slowest: the unit of work of a sweep (a line's search is seeded
/// along it, so lines are independent of each other).
pub(crate) fn grid_lines(grid: &Grid) -> Vec<(usize, usize)> {
    (0..grid.speed.len())
        .flat_map(|s| (0..grid.friction.len()).map(move |f| (f, s)))
        .collect()
}

/// Solves the lines `which` (indices into [`grid_lines`]) in parallel, each
/// point by the exact solver and the PSO search seeded with the previous
/// point's equilibria; one vector of points per line, steer fastest. A line
/// gives the same points whatever other lines are solved with it.
pub fn solve_lines(
    model: &VehicleModel,
    grid: &Grid,
    bx: &SearchBox,
    search: &PsoSearch,
    which: &[usize],
    progress: &AtomicUsize,
) -> Vec<Vec<PointResult>> {
    let lines = grid_lines(grid);
    which
        .par_iter()
        .map(|&l| {
            let (i_f, i_s) = lines[l];
            let mut prev: Vec<[f64; 2]> = Vec::new();
            let mut rear = None;
            grid.steer
                .iter()
                .map(|&steer| {
                    let c = Condition {
                        steer,
                        friction: grid.friction[i_f],
                        speed: grid.speed[i_s],
                    };
                    let (ex, continua) = exact::solve_with_continua_along(model, &c, &mut rear);
                    let (ps, stats) = pso::search(model, &c, bx, search, &prev);
                    prev = ps.iter().map(|e| [e.beta, e.yaw_rate]).collect();
                    let (found, agree) = cross_check(&ex, &ps, &continua, bx);
                    progress.fetch_add(1, Ordering::Relaxed);
                    PointResult {
                        condition: c,
                        exact: ex,
                        continua,
                        found,
                        agree,
                        pso_evaluations: stats.evaluations,
                        index_sum: stats.index_sum,
                        winding: stats.winding,
                    }
                })
                .collect()
        })
        .collect()
}

/// The sweep from every line's points (in [`grid_lines`] order), with the
/// bifurcations along every varying axis located when asked.
pub(crate) fn assemble(
    model: &VehicleModel,
    grid: &Grid,
    solved: Vec<Vec<PointResult>>,
    with_bifurcations: bool,
) -> SweepResult {
    let points: Vec<PointResult> = solved.into_iter().flatten().collect();
    let mut bifurcations = Vec::new();
    if with_bifurcations {
        for axis in grid.varying() {
            bifurcations.extend(
                axis_lines(grid, axis)
                    .par_iter()
                    .flat_map(|line| {
                        let l: Vec<(Condition, Vec<Equilibrium>)> = line
                            .iter()
                            .map(|&i| (points[i].condition, points[i].exact.clone()))
                            .collect();
                        bifurcation::locate(model, axis, &l)
                    })
                    .collect::<Vec<_>>(),
            );
        }
    }
    SweepResult {
        grid: grid.clone(),
        points,
        bifurcations,
    }
}

/// Point indices of every line along `axis` (the other two fixed).
pub(crate) fn axis_lines(grid: &Grid, axis: Axis) -> Vec<Vec<usize>> {
    let (ns, nf, nu) = (grid.steer.len(), grid.friction.len(), grid.speed.len());
    let mut out = Vec::new();
    match axis {
        Axis::Steer => {
            for u in 0..nu {
                for f in 0..nf {
                    out.push((0..ns).map(|s| grid.index(s, f, u)).collect());
                }
            }
        }
        Axis::Friction => {
            for u in 0..nu {
                for s in 0..ns {
                    out.push((0..nf).map(|f| grid.index(s, f, u)).collect());
                }
            }
        }
        Axis::Speed => {
            for f in 0..nf {
                for s in 0..ns {
                    out.push((0..nu).map(|u| grid.index(s, f, u)).collect());
                }
            }
        }
    }
    out
}
