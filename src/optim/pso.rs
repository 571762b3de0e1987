//! Particle swarm optimisation (minimisation over a box).
//!
//! Update (Zhang & Li (2017) eq. 16–17): `v ← w·v + c1·r1·(p_best − x) + c2·r2·(g − x)`,
//! `x ← x + v`, velocities clamped to a fraction of the box width (Li, Jia & Zhao).
//! Inertia either decreases linearly,
//! `w_k = (k_max − k)/k_max·(w_max − w_min) + w_min` (Zhang & Li (2017)), or adapts
//! per particle, `w = w_min + (w_max − w_min)·
//! (f − f_min)/(f_avg − f_min)` for `f ≤ f_avg` and `w_max` otherwise
//! (Zhang et al. (2021)). Natural selection (Zhang et al. (2021)): after each iteration the worse
//! half of the swarm takes the positions and velocities of the better half,
//! keeping its own personal bests. Positions leaving the box are either
//! clamped or wrapped back by whole widths (Li, Jia & Zhao). The attractor `g` is
//! the global best or, with a ring topology, the best of each particle's
//! neighbourhood, which keeps sub-swarms on different minima (used to find
//! several equilibria in one run).
//!
//! Random numbers come from one ChaCha8 stream seeded by `seed` and are drawn
//! in a fixed order, so results do not depend on thread count; objective
//! evaluations may run in parallel (rayon).

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// Inertia schedule.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Inertia {
    /// Zhang & Li (2017): linear decrease from `w_max` to `w_min`.
    #[serde(alias = "linear_decreasing")]
    LinearDecreasing,
    /// Zhang et al. (2021): adaptive per particle from its fitness rank.
    Adaptive,
}

/// What happens to a particle that leaves the box.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Boundary {
    /// Put it on the bound and stop its motion in that coordinate.
    Clamp,
    /// Wrap it back by whole box widths (Li, Jia & Zhao).
    Wrap,
}

/// Which best attracts a particle.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Topology {
    /// The whole swarm's best.
    Global,
    /// The best of the particle and its `k` neighbours on each side of a ring.
    Ring(usize),
}

/// PSO settings.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Pso {
    /// Number of particles.
    pub particles: usize,
    /// Maximum iterations.
    pub iterations: usize,
    /// Cognitive coefficient c1.
    pub c1: f64,
    /// Social coefficient c2.
    pub c2: f64,
    /// Smallest inertia.
    pub w_min: f64,
    /// Largest inertia.
    pub w_max: f64,
    /// Inertia schedule.
    pub inertia: Inertia,
    /// Zhang et al.'s (2021) natural selection.
    pub natural_selection: bool,
    /// Box boundary handling.
    pub boundary: Boundary,
    /// Attractor topology.
    pub topology: Topology,
    /// Velocity limit as a fraction of each coordinate's box width.
    pub velocity_limit: f64,
    /// Stop as soon as the best value is at or below this.
    pub target: f64,
    /// Random seed.
    pub seed: u64,
    /// Evaluate the particles in parallel.
    pub parallel: bool,
    /// Stop early when the best value stops improving (default: never).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stall: Option<Stall>,
}

/// An early stop: the swarm ends when its best value has improved by less
/// than `tolerance` (relative) over the last `iterations` iterations. A
/// swarm that only feeds a local polish need not wait for its last
/// iterations once its best has settled in a basin.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Stall {
    /// Iterations without enough improvement.
    pub iterations: usize,
    /// Relative improvement that counts.
    pub tolerance: f64,
}

impl Default for Pso {
    fn default() -> Self {
        Self {
            particles: 40,
            iterations: 200,
            c1: 2.0,
            c2: 2.0,
            w_min: 0.4,
            w_max: 0.9,
            inertia: Inertia::LinearDecreasing,
            natural_selection: false,
            boundary: Boundary::Clamp,
            topology: Topology::Global,
            velocity_limit: 0.2,
            target: f64::NEG_INFINITY,
            seed: 0,
            parallel: false,
            stall: None,
        }
    }
}

/// The outcome of a PSO run.
#[derive(Debug, Clone, PartialEq)]
pub struct PsoResult {
    /// Best position found.
    pub best: Vec<f64>,
    /// Objective at `best`.
    pub value: f64,
    /// Iterations run.
    pub iterations: usize,
    /// Objective evaluations made.
    pub evaluations: usize,
    /// Every particle's personal best (position, value).
    pub personal_bests: Vec<(Vec<f64>, f64)>,
    /// Best value after each iteration.
    pub history: Vec<f64>,
}

/// Objective value with NaN treated as the worst possible.
fn sane(v: f64) -> f64 {
    if v.is_nan() {
        f64::INFINITY
    } else {
        v
    }
}

impl Pso {
    /// Minimises `f` over the box `bounds` (lower, upper per coordinate).
    pub(crate) fn minimize<F>(&self, f: F, bounds: &[(f64, f64)]) -> PsoResult
    where
        F: Fn(&[f64]) -> f64 + Sync,
    {
        self.minimize_from(f, bounds, &[])
    }

    /// As [`Pso::minimize`], with some particles started at given positions
    /// (e.g. a previous solution); the rest start uniformly in the box.
    pub(crate) fn minimize_from<F>(
        &self,
        f: F,
        bounds: &[(f64, f64)],
        starts: &[Vec<f64>],
    ) -> PsoResult
    where
        F: Fn(&[f64]) -> f64 + Sync,
    {
        self.minimize_bounded_from(|x, _| f(x), bounds, starts)
    }

    /// As [`Pso::minimize_from`], for an objective `f(x, bound)` that may
    /// return infinity instead of its value where that value is at or
    /// above `bound` (the particle's personal best): the swarm then moves
    /// exactly as with the values, and a costly objective can stop early.
    /// Only the linearly decreasing inertia without natural selection reads
    /// nothing else of the values; the other schedules get no bound.
    pub(crate) fn minimize_bounded_from<F>(
        &self,
        f: F,
        bounds: &[(f64, f64)],
        starts: &[Vec<f64>],
    ) -> PsoResult
    where
        F: Fn(&[f64], f64) -> f64 + Sync,
    {
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        let mut swarm = Swarm::new(self, bounds, starts, &mut rng);
        let bounded = self.inertia == Inertia::LinearDecreasing && !self.natural_selection;
        // The bound of particle i: its personal best (none before it has one).
        let eval = |x: &[f64], pval: &[f64], out: &mut Vec<f64>| {
            let d = bounds.len();
            let bound = |i: usize| match pval.get(i) {
                Some(&b) if bounded => b,
                _ => f64::INFINITY,
            };
            if self.parallel {
                x.par_chunks(d)
                    .enumerate()
                    .map(|(i, p)| sane(f(p, bound(i))))
                    .collect_into_vec(out);
            } else {
                out.clear();
                out.extend(x.chunks(d).enumerate().map(|(i, p)| sane(f(p, bound(i)))));
            }
        };
        eval(&swarm.x, &[], &mut swarm.fx);
        swarm.pbest = swarm.x.clone();
        swarm.pval = swarm.fx.clone();
        let mut evaluations = swarm.n;
        let mut history = Vec::with_capacity(self.iterations);
        let mut iterations = 0;
        for k in 0..self.iterations {
            let g = swarm.best();
            history.push(swarm.pval[g]);
            if swarm.pval[g] <= self.target || self.stalled(&history) {
                break;
            }
            iterations = k + 1;
            swarm.attract(self.topology, g);
            swarm.step(self, k, bounds, &mut rng);
            eval(&swarm.x, &swarm.pval, &mut swarm.fx);
            evaluations += swarm.n;
            swarm.remember_bests();
            if self.natural_selection {
                swarm.select();
            }
        }
        swarm.result(history, iterations, evaluations)
    }

    /// Whether the best value (`history`, one entry per iteration) has
    /// improved by less than the [`Stall`] tolerance over its window.
    fn stalled(&self, history: &[f64]) -> bool {
        let Some(s) = self.stall else {
            return false;
        };
        let k = history.len();
        if s.iterations == 0 || k <= s.iterations {
            return false;
        }
        let (then, now) = (history[k - 1 - s.iterations], history[k - 1]);
        then.is_finite() && then - now <= s.tolerance * then.abs()
    }

    /// The inertia weight of a particle of value `fx` in iteration `k`,
    /// given the swarm's finite minimum and mean values.
    fn inertia_of(&self, k: usize, fx: f64, f_min: f64, f_avg: f64) -> f64 {
        match self.inertia {
            Inertia::LinearDecreasing => {
                (self.iterations - k) as f64 / self.iterations as f64 * (self.w_max - self.w_min)
                    + self.w_min
            }
            Inertia::Adaptive => {
                if fx <= f_avg && f_avg > f_min {
                    self.w_min + (self.w_max - self.w_min) * (fx - f_min) / (f_avg - f_min)
                } else if fx <= f_avg {
                    self.w_min
                } else {
                    self.w_max
                }
            }
        }
    }
}

/// The state of a swarm of `n` particles in `d` dimensions, row-major
/// (particle i's coordinates at `i·d..(i + 1)·d`).
struct Swarm {
    n: usize,
    d: usize,
    width: Vec<f64>,
    vmax: Vec<f64>,
    x: Vec<f64>,
    v: Vec<f64>,
    fx: Vec<f64>,
    pbest: Vec<f64>,
    pval: Vec<f64>,
    /// The particle whose personal best attracts each particle.
    attract: Vec<usize>,
    order: Vec<usize>,
}

impl Swarm {
    /// Positions (the given starts first, clamped into the box; the rest
    /// uniform) and velocities, drawn particle by particle, coordinate by
    /// coordinate, position before velocity.
    fn new(pso: &Pso, bounds: &[(f64, f64)], starts: &[Vec<f64>], rng: &mut ChaCha8Rng) -> Self {
        let n = pso.particles.max(2);
        let d = bounds.len();
        let width: Vec<f64> = bounds.iter().map(|(lo, hi)| hi - lo).collect();
        let vmax: Vec<f64> = width.iter().map(|w| w * pso.velocity_limit).collect();
        let mut x = vec![0.0; n * d];
        let mut v = vec![0.0; n * d];
        for i in 0..n {
            for j in 0..d {
                x[i * d + j] = match starts.get(i) {
                    Some(s) => s[j].clamp(bounds[j].0, bounds[j].1),
                    None => bounds[j].0 + rng.random::<f64>() * width[j],
                };
                v[i * d + j] = (2.0 * rng.random::<f64>() - 1.0) * vmax[j];
            }
        }
        Self {
            n,
            d,
            width,
            vmax,
            x,
            v,
            fx: Vec::with_capacity(n),
            pbest: Vec::new(),
            pval: Vec::new(),
            attract: vec![0; n],
            order: (0..n).collect(),
        }
    }

    /// The particle with the lowest personal best (the first of equals).
    fn best(&self) -> usize {
        let p = &self.pval;
        (0..self.n).fold(0, |b, i| if p[i] < p[b] { i } else { b })
    }

    /// Each particle's attractor: the global best `g`, or the best of its
    /// ring neighbourhood.
    fn attract(&mut self, topology: Topology, g: usize) {
        let (n, pval) = (self.n, &self.pval);
        for (i, a) in self.attract.iter_mut().enumerate() {
            *a = match topology {
                Topology::Global => g,
                Topology::Ring(r) => {
                    let mut best = i;
                    for o in 1..=r.min(n / 2) {
                        for nb in [(i + o) % n, (i + n - o) % n] {
                            if pval[nb] < pval[best] {
                                best = nb;
                            }
                        }
                    }
                    best
                }
            };
        }
    }

    /// Iteration `k`'s move: new velocities (two draws per coordinate) and
    /// positions, kept in the box by the pso's boundary rule.
    fn step(&mut self, pso: &Pso, k: usize, bounds: &[(f64, f64)], rng: &mut ChaCha8Rng) {
        let (f_min, f_avg) = {
            let finite = self.fx.iter().copied().filter(|v| v.is_finite());
            let (min, sum, count) = finite.fold((f64::INFINITY, 0.0, 0usize), |(m, s, c), v| {
                (m.min(v), s + v, c + 1)
            });
            (min, sum / count.max(1) as f64)
        };
        let d = self.d;
        for i in 0..self.n {
            let w = pso.inertia_of(k, self.fx[i], f_min, f_avg);
            let a = self.attract[i];
            for (j, &(lo, hi)) in bounds.iter().enumerate() {
                let idx = i * d + j;
                let r1: f64 = rng.random();
                let r2: f64 = rng.random();
                let mut vel = w * self.v[idx]
                    + pso.c1 * r1 * (self.pbest[idx] - self.x[idx])
                    + pso.c2 * r2 * (self.pbest[a * d + j] - self.x[idx]);
                vel = vel.clamp(-self.vmax[j], self.vmax[j]);
                let mut pos = self.x[idx] + vel;
                if pos < lo || pos > hi {
                    match pso.boundary {
                        Boundary::Clamp => {
                            pos = pos.clamp(lo, hi);
                            vel = 0.0;
                        }
                        Boundary::Wrap => pos = lo + (pos - lo).rem_euclid(self.width[j]),
                    }
                }
                self.v[idx] = vel;
                self.x[idx] = pos;
            }
        }
    }

    /// Personal bests updated from the latest values.
    fn remember_bests(&mut self) {
        let d = self.d;
        for i in 0..self.n {
            if self.fx[i] < self.pval[i] {
                self.pval[i] = self.fx[i];
                self.pbest[i * d..(i + 1) * d].copy_from_slice(&self.x[i * d..(i + 1) * d]);
            }
        }
    }

    /// Zhang et al.'s (2021) natural selection: the worse half takes the
    /// positions and velocities of the better half (personal bests kept).
    fn select(&mut self) {
        let (n, d, fx) = (self.n, self.d, &mut self.fx);
        self.order.sort_by(|&p, &q| fx[p].total_cmp(&fx[q]));
        for r in 0..n / 2 {
            let (good, bad) = (self.order[r], self.order[n - 1 - r]);
            if fx[bad] > fx[good] {
                let (gs, bs) = (good * d, bad * d);
                for j in 0..d {
                    self.x[bs + j] = self.x[gs + j];
                    self.v[bs + j] = self.v[gs + j];
                }
                fx[bad] = fx[good];
            }
        }
    }

    /// The outcome, the final best appended to `history` when new.
    fn result(self, mut history: Vec<f64>, iterations: usize, evaluations: usize) -> PsoResult {
        let (g, d) = (self.best(), self.d);
        if history.last() != Some(&self.pval[g]) {
            history.push(self.pval[g]);
        }
        PsoResult {
            best: self.pbest[g * d..(g + 1) * d].to_vec(),
            value: self.pval[g],
            iterations,
            evaluations,
            personal_bests: (0..self.n)
                .map(|i| (self.pbest[i * d..(i + 1) * d].to_vec(), self.pval[i]))
                .collect(),
            history,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rosenbrock(x: &[f64]) -> f64 {
        x.windows(2)
            .map(|w| 100.0 * (w[1] - w[0] * w[0]).powi(2) + (1.0 - w[0]).powi(2))
            .sum()
    }

    fn rastrigin(x: &[f64]) -> f64 {
        10.0 * x.len() as f64
            + x.iter()
                .map(|v| v * v - 10.0 * (std::f64::consts::TAU * v).cos())
                .sum::<f64>()
    }

    #[test]
    fn finds_the_rosenbrock_valley_minimum() {
        for (inertia, ns) in [
            (Inertia::LinearDecreasing, false),
            (Inertia::Adaptive, true),
        ] {
            for seed in 0..3 {
                let pso = Pso {
                    particles: 60,
                    iterations: 1500,
                    inertia,
                    natural_selection: ns,
                    seed,
                    ..Pso::default()
                };
                let r = pso.minimize(rosenbrock, &[(-2.0, 2.0); 2]);
                assert!(r.value < 1e-6, "{inertia:?} seed {seed}: {}", r.value);
                assert!(
                    (r.best[0] - 1.0).abs() < 1e-2 && (r.best[1] - 1.0).abs() < 2e-2,
                    "{:?}",
                    r.best
                );
            }
        }
    }

    #[test]
    fn escapes_the_local_minima_of_rastrigin() {
        // 3-D Rastrigin has ~10³ local minima in the box; the global one is 0.
        let mut hits = 0;
        for seed in 0..5 {
            let pso = Pso {
                particles: 80,
                iterations: 600,
                inertia: Inertia::Adaptive,
                natural_selection: true,
                seed,
                ..Pso::default()
            };
            let r = pso.minimize(rastrigin, &[(-5.12, 5.12); 3]);
            if r.value < 1e-6 {
                hits += 1;
            }
        }
        assert!(hits >= 4, "global minimum found in {hits}/5 runs");
    }

    #[test]
    fn same_seed_same_answer_regardless_of_threads() {
        let base = Pso {
            seed: 42,
            iterations: 100,
            ..Pso::default()
        };
        let a = base.minimize(rosenbrock, &[(-2.0, 2.0); 3]);
        let b = Pso {
            parallel: true,
            ..base
        }
        .minimize(rosenbrock, &[(-2.0, 2.0); 3]);
        assert_eq!(a.best, b.best);
        assert_eq!(a.history, b.history);
        let c = Pso { seed: 43, ..base }.minimize(rosenbrock, &[(-2.0, 2.0); 3]);
        assert_ne!(a.best, c.best);
    }

    #[test]
    fn wrapped_positions_stay_in_the_box() {
        let pso = Pso {
            boundary: Boundary::Wrap,
            velocity_limit: 0.9,
            iterations: 50,
            ..Pso::default()
        };
        // Minimum outside the box on the right: wrapping must keep every
        // personal best inside anyway.
        let r = pso.minimize(|x| (x[0] - 5.0).powi(2), &[(0.0, 1.0)]);
        for (p, _) in &r.personal_bests {
            assert!((0.0..=1.0).contains(&p[0]));
        }
        assert!(r.best[0] > 0.99, "{:?}", r.best);
    }

    #[test]
    fn ring_topology_keeps_several_minima() {
        // Two equal minima at ±1: a ring swarm keeps particles at both.
        let pso = Pso {
            particles: 40,
            iterations: 300,
            topology: Topology::Ring(1),
            seed: 7,
            ..Pso::default()
        };
        let r = pso.minimize(|x| (x[0] * x[0] - 1.0).powi(2), &[(-2.0, 2.0)]);
        let near = |c: f64| {
            r.personal_bests
                .iter()
                .filter(|(p, v)| (p[0] - c).abs() < 1e-2 && *v < 1e-6)
                .count()
        };
        assert!(
            near(1.0) > 0 && near(-1.0) > 0,
            "{} {}",
            near(1.0),
            near(-1.0)
        );
    }

    #[test]
    fn stops_at_the_target() {
        let pso = Pso {
            target: 1e-3,
            iterations: 10_000,
            ..Pso::default()
        };
        let r = pso.minimize(|x| x[0] * x[0], &[(-1.0, 1.0)]);
        assert!(r.value <= 1e-3 && r.iterations < 10_000);
    }
}
