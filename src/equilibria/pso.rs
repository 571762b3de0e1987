//! Li, Jia & Zhao's PSO search for steering equilibria, made complete.
//!
//! Fitness over the box of (β, r), positions wrapped back by whole widths and
//! velocities clamped (Li, Jia & Zhao). Two fitness functions:
//! - `residual`: Li, Jia & Zhao's `f1² + f2²` of the scaled right-hand side;
//! - `newton-step` (default): the length of the Newton step `‖J⁻¹·f‖`
//!   (scaled, forward-difference Jacobian), which near any simple root equals
//!   the distance to it. Li, Jia & Zhao's fitness is tiny over the wide regions
//!   where both axles saturate and steep around the straight-running
//!   equilibrium, so a swarm settles on the saddles and misses the stable node
//!   (measured in the tests); the Newton step makes every basin look alike.
//!
//! Each round runs a ring-topology swarm (sub-swarms settle on different
//! equilibria), polishes the distinct personal bests below `candidate`
//! fitness by Newton to machine precision, and keeps the new equilibria in the
//! box. From every new equilibrium it also polishes points along both
//! eigenvectors of its Jacobian: near a fold the partner equilibrium lies
//! there, closer than the swarm can resolve. Later rounds deflate the fitness at every equilibrium found,
//! `F(x)·Π(1 + ρ²/‖x − x_i‖²)`, so the swarm is pushed away from them; the
//! search stops after a round that finds nothing new.

use super::{
    describe, distance, polish_fast, residual_at_equilibrium_loads, Condition, Equilibrium,
    SearchBox,
};
use crate::optim::{Boundary, Pso, PsoResult, Topology};
use crate::vehicle::VehicleModel;
use serde::{Deserialize, Serialize};

/// PSO fitness.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Fitness {
    /// Li, Jia & Zhao: f1² + f2².
    Residual,
    /// Length of the Newton step.
    #[serde(alias = "newton_step")]
    NewtonStep,
}

/// Settings of the PSO equilibrium search.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PsoSearch {
    /// Particles per round.
    pub particles: usize,
    /// Iterations per round.
    pub iterations: usize,
    /// Most rounds (the search also stops after a round with nothing new).
    pub rounds: usize,
    /// Fewest rounds.
    pub min_rounds: usize,
    /// Fitness below which a personal best is polished by Newton.
    pub candidate: f64,
    /// Deflation radius ρ (scaled units).
    pub deflation_radius: f64,
    /// Random seed (round k uses seed + k).
    pub seed: u64,
    /// Fitness function.
    pub fitness: Fitness,
    /// Keep searching until the index sum matches the winding number.
    pub certify: bool,
}

impl Default for PsoSearch {
    fn default() -> Self {
        Self {
            particles: 16,
            iterations: 30,
            rounds: 8,
            min_rounds: 2,
            candidate: 0.5,
            deflation_radius: 0.1,
            seed: 1,
            fitness: Fitness::NewtonStep,
            certify: true,
        }
    }
}

/// Statistics of a search.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct SearchStats {
    /// Rounds run.
    pub rounds: usize,
    /// Fitness evaluations (PSO and Newton).
    pub evaluations: usize,
    /// Winding number of the vector field around the box (None when an
    /// equilibrium sits on the boundary).
    pub winding: Option<i32>,
    /// Sum of the indices (sign det J) of the equilibria found.
    pub index_sum: i32,
}

/// Winding number of (β̇, ṙ) around the boundary of `bx`, counter-clockwise:
/// by the Poincaré–Hopf index theorem it equals the sum of the indices of the
/// equilibria inside (+1 node or focus, −1 saddle), which certifies a search
/// independently of the exact solver (a missing saddle–node pair cancels and
/// goes unseen; a single missing equilibrium does not). `None` when the field
/// nearly vanishes on the boundary.
///
/// The field followed is [`residual_at_equilibrium_loads`] (loads at
/// ay = u·r, no load-transfer solve): it has the model's roots, and at each
/// its Jacobian's determinant is the model's times `1 − Y'(ay)/m` (the
/// first rows differ by that factor, the second rows by a multiple of the
/// first), positive wherever the load-transfer loop has its unique root
/// (`vehicle`), so every index, and therefore the winding number, is the
/// model's.
pub(crate) fn winding_number(model: &VehicleModel, c: &Condition, bx: &SearchBox) -> Option<i32> {
    let (b, r) = (bx.beta_max, bx.yaw_rate_max);
    let corners = [[-b, -r], [b, -r], [b, r], [-b, r], [-b, -r]];
    let scale = bx.scale();
    let angle = |x: [f64; 2]| {
        let f = residual_at_equilibrium_loads(model, c, x);
        let (u, v) = (f[0] / scale[0], f[1] / scale[1]);
        (u.hypot(v) > 1e-9).then(|| v.atan2(u))
    };
    let wrap = |d: f64| {
        (d + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI
    };
    let mut total = 0.0;
    for w in corners.windows(2) {
        let n = 48;
        let pt = |t: f64| {
            [
                w[0][0] + t * (w[1][0] - w[0][0]),
                w[0][1] + t * (w[1][1] - w[0][1]),
            ]
        };
        let mut prev = (0.0, angle(pt(0.0))?);
        for i in 1..=n {
            let t = i as f64 / n as f64;
            let a = angle(pt(t))?;
            // Refine a segment whose angle jumps by more than 45°, so the
            // unwrapped sum cannot skip a turn.
            let mut stack = vec![(prev, (t, a), 0)];
            while let Some(((t0, a0), (t1, a1), depth)) = stack.pop() {
                let d = wrap(a1 - a0);
                if d.abs() <= std::f64::consts::FRAC_PI_4 || depth >= 12 {
                    total += d;
                } else {
                    let tm = 0.5 * (t0 + t1);
                    let am = angle(pt(tm))?;
                    stack.push(((tm, am), (t1, a1), depth + 1));
                    stack.push(((t0, a0), (tm, am), depth + 1));
                }
            }
            prev = (t, a);
        }
    }
    Some((total / std::f64::consts::TAU).round() as i32)
}

/// Starting points around an equilibrium along both eigenvectors of its
/// Jacobian (scaled distances 0.003 to 0.1, both directions), when one
/// eigenvalue is small against the other (near a fold); none otherwise.
fn partner_probes(
    model: &VehicleModel,
    c: &Condition,
    x: [f64; 2],
    scale: [f64; 2],
) -> Vec<[f64; 2]> {
    let j = super::stability::jacobian(model, c, x);
    let s = super::stability::from_jacobian(j);
    // Far from a fold the partner is far too, where the swarm finds it; only
    // a soft direction (|λ_min| < 0.2·|λ_max|) hides one nearby.
    let (l0, l1) = (
        s.eigenvalues[0].0.hypot(s.eigenvalues[0].1),
        s.eigenvalues[1].0.hypot(s.eigenvalues[1].1),
    );
    if l0.min(l1) >= 0.2 * l0.max(l1) {
        return Vec::new();
    }
    let mut dirs = Vec::new();
    if s.eigenvalues[0].1 == 0.0 {
        for (lambda, _) in s.eigenvalues {
            // (J − λI)·v = 0: v from whichever row is better conditioned.
            let v = if j[0][1].abs() + (j[0][0] - lambda).abs()
                > j[1][0].abs() + (j[1][1] - lambda).abs()
            {
                [j[0][1], lambda - j[0][0]]
            } else {
                [lambda - j[1][1], j[1][0]]
            };
            let n = (v[0] / scale[0]).hypot(v[1] / scale[1]);
            if n > 0.0 && n.is_finite() {
                dirs.push([v[0] / n, v[1] / n]);
            }
        }
    } else {
        dirs.push([scale[0], 0.0]);
        dirs.push([0.0, scale[1]]);
    }
    let mut out = Vec::new();
    for d in dirs {
        for step in [0.003, 0.01, 0.03, 0.1] {
            for sign in [-1.0, 1.0] {
                out.push([x[0] + sign * step * d[0], x[1] + sign * step * d[1]]);
            }
        }
    }
    out
}

/// Finds the equilibria in `bx` by PSO + Newton with deflation; `starts` seed
/// some particles (e.g. the equilibria of a neighbouring condition).
pub fn search(
    model: &VehicleModel,
    c: &Condition,
    bx: &SearchBox,
    settings: &PsoSearch,
    starts: &[[f64; 2]],
) -> (Vec<Equilibrium>, SearchStats) {
    let scale = bx.scale();
    let inputs = c.inputs();
    let fitness = |x: &[f64]| swarm_fitness(model, &inputs, scale, settings.fitness, x);
    let mut found: Vec<[f64; 2]> = Vec::new();
    let mut stats = SearchStats {
        winding: if settings.certify {
            winding_number(model, c, bx)
        } else {
            None
        },
        ..SearchStats::default()
    };
    let index = |x: &[f64; 2]| {
        if super::stability::classify(model, c, *x).determinant >= 0.0 {
            1
        } else {
            -1
        }
    };
    let mut indices: Vec<i32> = Vec::new();
    for round in 0..settings.rounds {
        stats.rounds = round + 1;
        let r = fly_round(&fitness, scale, bx, settings, round, &found, starts);
        stats.evaluations += r.evaluations
            * match settings.fitness {
                Fitness::Residual => 1,
                Fitness::NewtonStep => 3,
            };
        let before = found.len();
        polish_candidates(
            model,
            c,
            bx,
            settings,
            r.personal_bests,
            &mut found,
            &mut stats,
        );
        probe_partners(model, c, bx, before, &mut found, &mut stats);
        let new = found.len() - before;
        // Each equilibrium's index once, when it is first found.
        indices.extend(found[indices.len()..].iter().map(index));
        stats.index_sum = indices.iter().sum();
        let certified = stats.winding.is_none_or(|w| w == stats.index_sum);
        if new == 0 && round + 1 >= settings.min_rounds && certified {
            break;
        }
    }
    let mut eqs: Vec<Equilibrium> = found.iter().map(|x| describe(model, c, *x)).collect();
    eqs.sort_by(|a, b| a.alpha_rear.total_cmp(&b.alpha_rear));
    (eqs, stats)
}

/// One round of the swarm: its fitness deflated away from the equilibria
/// `known` (scaled by the box, `scale`), more particles in each round past
/// the minimum, its own seed, `starts` seeding the first round only.
fn fly_round(
    fitness: &(impl Fn(&[f64]) -> f64 + Sync),
    scale: [f64; 2],
    bx: &SearchBox,
    settings: &PsoSearch,
    round: usize,
    known: &[[f64; 2]],
    starts: &[[f64; 2]],
) -> PsoResult {
    let rho2 = settings.deflation_radius.powi(2);
    // Deflation: near a known root the Newton step ≈ its distance d, so
    // d·(1 + ρ²/d²) ≥ 2ρ keeps the swarm away from it.
    let deflated = |x: &[f64]| {
        let m: f64 = known
            .iter()
            .map(|k| {
                // The squared scaled distance, without hypot's square root.
                let d2 = ((x[0] - k[0]) / scale[0]).powi(2) + ((x[1] - k[1]) / scale[1]).powi(2);
                1.0 + rho2 / d2.max(1e-300)
            })
            .product();
        fitness(x) * m
    };
    // Rounds past the minimum run only while new equilibria keep turning
    // up or the index certificate fails: each brings a larger swarm.
    let pso = Pso {
        particles: settings.particles * (1 + round.saturating_sub(settings.min_rounds)),
        iterations: settings.iterations,
        boundary: Boundary::Wrap,
        topology: Topology::Ring(1),
        velocity_limit: 0.25,
        seed: settings.seed.wrapping_add(round as u64),
        ..Pso::default()
    };
    let seeds: Vec<Vec<f64>> = if round == 0 {
        starts.iter().map(|s| s.to_vec()).collect()
    } else {
        Vec::new()
    };
    // The swarm flies over a box 10 % larger than the one reported, so an
    // equilibrium just inside the edge is not lost to wrapping.
    let wide = SearchBox {
        beta_max: 1.1 * bx.beta_max,
        yaw_rate_max: 1.1 * bx.yaw_rate_max,
    };
    pso.minimize_from(deflated, &wide.bounds(), &seeds)
}

/// The swarm's fitness at `x`: the residual scaled so that both components
/// are rates of order one over the box (β̇ relative to β_max, ṙ relative to
/// r_max per second), or the length of the Newton step in the same scale.
/// The residual takes the loads at the equilibrium's ay = u·r, with its
/// Jacobian in closed form for PAC89: the same roots as the model's, one
/// tyre-set evaluation per point instead of a load-transfer solve and two
/// differenced neighbours (the swarm only ranks points; every candidate is
/// polished on the model itself).
fn swarm_fitness(
    model: &VehicleModel,
    inputs: &crate::vehicle::Inputs,
    scale: [f64; 2],
    kind: Fitness,
    x: &[f64],
) -> f64 {
    let state = crate::vehicle::State {
        beta: x[0],
        yaw_rate: x[1],
    };
    let (f, j) = model.equilibrium_residual(&state, inputs);
    match kind {
        Fitness::Residual => (f[0] / scale[0]).powi(2) + (f[1] / scale[1]).powi(2),
        Fitness::NewtonStep => {
            let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
            let dx = [
                (j[1][1] * f[0] - j[0][1] * f[1]) / det,
                (-j[1][0] * f[0] + j[0][0] * f[1]) / det,
            ];
            let step = (dx[0] / scale[0]).hypot(dx[1] / scale[1]);
            // A singular Jacobian (a fold) gives an infinite step: rank it
            // below every finite one rather than as NaN.
            if step.is_finite() {
                step
            } else {
                1e3
            }
        }
    }
}

/// Polishes the swarm's personal bests, best first, that are good enough and
/// not next to one already tried; adds each new equilibrium in the box to
/// `found`.
fn polish_candidates(
    model: &VehicleModel,
    c: &Condition,
    bx: &SearchBox,
    settings: &PsoSearch,
    mut candidates: Vec<(Vec<f64>, f64)>,
    found: &mut Vec<[f64; 2]>,
    stats: &mut SearchStats,
) {
    let scale = bx.scale();
    let mut tried: Vec<[f64; 2]> = Vec::new();
    candidates.sort_by(|a, b| a.1.total_cmp(&b.1));
    for (p, v) in candidates {
        let x0 = [p[0], p[1]];
        if v > settings.candidate || tried.iter().any(|t| distance(*t, x0, scale) < 0.05) {
            continue;
        }
        tried.push(x0);
        stats.evaluations += 20;
        if let Some(x) = polish_fast(model, c, x0) {
            if bx.contains(x) && !found.iter().any(|k| distance(*k, x, scale) < 1e-7) {
                found.push(x);
            }
        }
    }
}

/// Near a fold the partner equilibrium lies close by along the Jacobian's
/// soft eigenvector, inside the deflation zone where the swarm rarely lands:
/// probes along both eigenvectors of every equilibrium from `found[first..]`
/// on, including those the probes themselves add.
fn probe_partners(
    model: &VehicleModel,
    c: &Condition,
    bx: &SearchBox,
    first: usize,
    found: &mut Vec<[f64; 2]>,
    stats: &mut SearchStats,
) {
    let scale = bx.scale();
    let mut k = first;
    while k < found.len() {
        for x0 in partner_probes(model, c, found[k], scale) {
            stats.evaluations += 20;
            if let Some(x) = polish_fast(model, c, x0) {
                if bx.contains(x) && !found.iter().any(|q| distance(*q, x, scale) < 1e-7) {
                    found.push(x);
                }
            }
        }
        k += 1;
    }
}
