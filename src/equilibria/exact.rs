//! Exact reference solver for the steering equilibria, independent of chance.
//!
//! At an equilibrium ay = u·r (plus g·sin θ on a banked road), and the force
//! and moment balances fix both axle forces by the yaw rate:
//! `Fyr = m·u·r·a/l`, `Fyf·cos δ = m·u·r·b/l`
//! (cos δ = 1 in the small-angle form). Parameterised by the rear slip angle
//! αr, the rear balance gives r (directly without load transfer; with it, the
//! loads depend on ay = u·r, so r solves the nested scalar equation
//! `m·u·a·r/l = Fyr(αr, loads(u·r))` by secant iteration with a Brent
//! fallback), the kinematics then give β and αf, and every equilibrium is a
//! root of the one scalar function
//! `h(αr) = Fyf(αf, loads(u·r))·cos δ − m·u·r·b/l`.
//! Its roots over |αr| < 85° are found completely by a sign scan (500 cells),
//! Brent's method on every sign change, and a golden-section search at every
//! local minimum of |h| for pairs of roots inside one cell (and double roots,
//! exactly at a fold). Where h vanishes identically over an interval (tyres
//! whose sliding force does not fall with slip, both axles sliding) the
//! interval is reported as a continuum of equilibria, not as roots. The
//! road's friction is the condition's, scaled by the model's effects
//! ([`crate::vehicle::Effects::friction_scale`], 1 unless a program sets
//! it), as the right-hand side scales it.

use super::{describe, Condition, Equilibrium};
use crate::tyre::{SlipState, TyreModel};
use crate::vehicle::{Kinematics, VehicleModel, MIN_SPEED};
use std::cell::Cell;

/// Largest |αr| scanned, rad (85°).
const ALPHA_MAX: f64 = 85.0 * std::f64::consts::PI / 180.0;

/// Scan cells.
const CELLS: usize = 500;

/// Width of one scan cell in rear slip angle, rad: a continuum's true ends lie
/// within one cell of the scanned ones.
pub(crate) const CELL: f64 = 2.0 * ALPHA_MAX / CELLS as f64;

/// Brent's method for a root of `f` in [a, b] with f(a)·f(b) ≤ 0.
pub(crate) fn brent(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64, tol: f64) -> f64 {
    let (mut fa, mut fb) = (f(a), f(b));
    if fa == 0.0 {
        return a;
    }
    if fb == 0.0 {
        return b;
    }
    if fa.abs() < fb.abs() {
        std::mem::swap(&mut a, &mut b);
        std::mem::swap(&mut fa, &mut fb);
    }
    let (mut c, mut fc) = (a, fa);
    let mut mflag = true;
    let mut d = 0.0;
    for _ in 0..200 {
        if fb == 0.0 || (b - a).abs() <= tol {
            return b;
        }
        let mut s = if fa != fc && fb != fc {
            a * fb * fc / ((fa - fb) * (fa - fc))
                + b * fa * fc / ((fb - fa) * (fb - fc))
                + c * fa * fb / ((fc - fa) * (fc - fb))
        } else {
            b - fb * (b - a) / (fb - fa)
        };
        let lo = (3.0 * a + b) / 4.0;
        let between = (s > lo.min(b)) && (s < lo.max(b));
        if !between
            || (mflag && (s - b).abs() >= (b - c).abs() / 2.0)
            || (!mflag && (s - b).abs() >= (c - d).abs() / 2.0)
            || (mflag && (b - c).abs() < tol)
            || (!mflag && (c - d).abs() < tol)
        {
            s = 0.5 * (a + b);
            mflag = true;
        } else {
            mflag = false;
        }
        let fs = f(s);
        d = c;
        c = b;
        fc = fb;
        if fa * fs < 0.0 {
            b = s;
            fb = fs;
        } else {
            a = s;
            fa = fs;
        }
        if fa.abs() < fb.abs() {
            std::mem::swap(&mut a, &mut b);
            std::mem::swap(&mut fa, &mut fb);
        }
    }
    b
}

/// The reduced problem at one condition.
pub struct Reduced<'a> {
    model: &'a VehicleModel,
    c: Condition,
    u: f64,
    /// The last rear-axle solve's yaw rate and the slope of its residual:
    /// the scan and the root finders call [`Reduced::at`] at neighbouring
    /// rear slip angles, so the next solve starts there (two or three
    /// evaluations of the rear axle instead of five or six). The answer is
    /// the unique root to the same tolerance wherever it starts.
    last: Cell<Option<(f64, f64)>>,
    /// The rear slip angles and yaw rates of the last two solves: the next
    /// solve starts from their linear extrapolation (second-order accurate
    /// along the evenly spaced scan).
    history: Cell<[(f64, f64); 2]>,
    /// The rear half of the scan, when a line of steers shares it.
    rear: Option<&'a RearScan>,
}

/// The rear half of a scan: the yaw rate that balances the rear axle at
/// every scanned rear slip angle, and the rear solve's state after it. It
/// depends on the speed and friction (and the model), not on the steer, so
/// a line of conditions that differ only in steer solves it once
/// ([`solve_with_continua_along`]); the state is carried over too, so every
/// later solve starts where it would have and the answers are the same to
/// the bit.
#[derive(Debug, Clone, PartialEq)]
pub struct RearScan {
    friction: f64,
    speed: f64,
    yaw_rates: Vec<f64>,
    last: Option<(f64, f64)>,
    history: [(f64, f64); 2],
}

/// What the reduced problem gives at one rear slip angle.
#[derive(Debug, Clone, Copy)]
pub struct Point {
    /// h(αr), N.
    pub h: f64,
    /// Sideslip, rad.
    pub beta: f64,
    /// Yaw rate, rad/s.
    pub yaw_rate: f64,
}

impl<'a> Reduced<'a> {
    /// The reduced problem of `model` at `c`.
    pub fn new(model: &'a VehicleModel, c: Condition) -> Self {
        Self {
            model,
            c,
            u: c.speed.max(MIN_SPEED),
            last: Cell::new(None),
            history: Cell::new([(f64::NAN, f64::NAN); 2]),
            rear: None,
        }
    }

    /// The rear half of this condition's scan, solved from a fresh start
    /// (as [`Reduced::scan`] does without one).
    fn rear_scan(&self) -> RearScan {
        let yaw_rates = Self::scan_angles().map(|x| self.yaw_rate(x)).collect();
        RearScan {
            friction: self.c.friction,
            speed: self.c.speed,
            yaw_rates,
            last: self.last.get(),
            history: self.history.get(),
        }
    }

    /// The road's friction as the model's effects scale it.
    fn mu(&self) -> f64 {
        self.model.options.effects.friction_scale * self.c.friction
    }

    fn scan_angles() -> impl Iterator<Item = f64> {
        (0..=CELLS).map(|i| -ALPHA_MAX + 2.0 * ALPHA_MAX * i as f64 / CELLS as f64)
    }

    fn axle(&self, front: bool, alpha: f64, ay: f64) -> f64 {
        let fz = self.model.wheel_loads_at(ay, self.u);
        let (tyre, l, r) = if front {
            (&self.model.front, fz[0], fz[1])
        } else {
            (&self.model.rear, fz[2], fz[3])
        };
        let s = |fz| SlipState {
            alpha,
            kappa: 0.0,
            fz,
            camber: 0.0,
            mu_scale: self.mu(),
            speed: self.u,
        };
        tyre.lateral_force(&s(l)) + tyre.lateral_force(&s(r))
    }

    /// Yaw rate that balances the rear axle at slip angle `ar`: the tyres
    /// carry `m·(u·r + g·sin θ)` (the bank's pull included), the rear its
    /// a/l share.
    fn yaw_rate(&self, ar: f64) -> f64 {
        let v = &self.model.vehicle;
        let k = v.mass * self.u * v.a / v.wheelbase();
        let gb = self.model.bank_acceleration();
        let bank = v.mass * v.a / v.wheelbase() * gb;
        if !self.model.options.load_transfer {
            return (self.axle(false, ar, gb) - bank) / k;
        }
        let g = |r: f64| k * r + bank - self.axle(false, ar, self.u * r + gb);
        let converged = |r: f64, gr: f64| gr.abs() <= 1e-13 * k * (1e-3 + r.abs());
        // Secant from the last solve's answer and slope, or from the
        // no-transfer answer with g' ≈ k; g is increasing (the axle force
        // grows with load more slowly than m·u·a/l), so the root is unique.
        // Brent over a bracket that must contain the root (the axle force
        // cannot exceed the whole vehicle weight times the peak friction)
        // takes over if the secant does not converge.
        let (mut x0, slope) = match self.last.get() {
            Some((r_last, slope)) => {
                let [(a1, r1), (a0, r0)] = self.history.get();
                // Extrapolate only from close neighbours (the scan's order),
                // never far out.
                let near = (ar - a1).abs() <= 2.0 * (a1 - a0).abs() && a1 != a0;
                let pred = r1 + (r1 - r0) / (a1 - a0) * (ar - a1);
                (
                    if near && pred.is_finite() {
                        pred
                    } else {
                        r_last
                    },
                    slope,
                )
            }
            None => ((self.axle(false, ar, gb) - bank) / k, k),
        };
        let remember = |r: f64| {
            let [h1, _] = self.history.get();
            self.history.set([(ar, r), h1]);
        };
        let mut g0 = g(x0);
        if g0 == 0.0 || converged(x0, g0) {
            remember(x0);
            return x0;
        }
        let mut x1 = x0 - g0 / slope;
        for _ in 0..30 {
            let g1 = g(x1);
            let s = (g1 - g0) / (x1 - x0);
            if converged(x1, g1) {
                if s.is_finite() && s > 0.0 {
                    self.last.set(Some((x1, s)));
                }
                remember(x1);
                return x1;
            }
            if !s.is_finite() || s <= 0.0 {
                break;
            }
            (x0, g0) = (x1, g1);
            x1 -= g1 / s;
        }
        self.last.set(None);
        let fmax = 3.0 * self.mu().max(1.0) * v.mass * crate::constants::G;
        let bound = 2.0 * fmax / k;
        brent(g, -bound, bound, 1e-15 * bound)
    }

    /// The reduced function and the state at rear slip angle `ar`.
    pub fn at(&self, ar: f64) -> Point {
        self.point(ar, self.yaw_rate(ar))
    }

    /// [`Reduced::at`] with the rear axle's yaw rate `r` given.
    fn point(&self, ar: f64, r: f64) -> Point {
        let v = &self.model.vehicle;
        let u = self.u;
        let (beta, af, proj) = match self.model.options.kinematics {
            Kinematics::Exact => {
                let vy = v.b * r - u * ar.tan();
                (
                    (vy / u).atan(),
                    self.c.steer - ((vy + v.a * r) / u).atan(),
                    self.c.steer.cos(),
                )
            }
            Kinematics::SmallAngle => {
                let beta = v.b * r / u - ar;
                (beta, self.c.steer - beta - v.a * r / u, 1.0)
            }
        };
        let ay = u * r + self.model.bank_acceleration();
        let need = v.mass * ay * v.b / v.wheelbase();
        Point {
            h: self.axle(true, af, ay) * proj - need,
            beta,
            yaw_rate: r,
        }
    }

    /// Every root of h over |αr| < 85°, ascending in αr, double roots (a
    /// tangency within rounding, exactly at a fold) included.
    pub fn roots(&self) -> Vec<f64> {
        self.roots_with(true)
    }

    /// The simple roots only: the count that changes by exactly two across a
    /// fold (a double root counted once would split the change in two).
    pub(crate) fn simple_roots(&self) -> Vec<f64> {
        self.roots_with(false)
    }

    /// The scan: rear slip angles and h at them.
    fn scan(&self) -> (Vec<f64>, Vec<f64>) {
        let a: Vec<f64> = Self::scan_angles().collect();
        let h: Vec<f64> = match self.rear {
            Some(rear) => {
                let h = a
                    .iter()
                    .zip(&rear.yaw_rates)
                    .map(|(&x, &r)| self.point(x, r).h)
                    .collect();
                self.last.set(rear.last);
                self.history.set(rear.history);
                h
            }
            None => a.iter().map(|&x| self.at(x).h).collect(),
        };
        (a, h)
    }

    /// Which scan samples lie in a continuum of equilibria: runs of at least
    /// three consecutive samples where h vanishes to 1e-9 of the weight. With
    /// a tyre whose sliding force does not fall with slip (the classic brush
    /// model) and both axles sliding, the forces no longer depend on the slip
    /// angles and a whole curve of states is in equilibrium.
    fn flat(&self, h: &[f64]) -> Vec<bool> {
        let tol = 1e-9 * self.model.vehicle.mass * crate::constants::G;
        let small: Vec<bool> = h.iter().map(|v| v.abs() <= tol).collect();
        let mut flat = vec![false; h.len()];
        let mut i = 0;
        while i < h.len() {
            if !small[i] {
                i += 1;
                continue;
            }
            let mut j = i;
            while j < h.len() && small[j] {
                j += 1;
            }
            if j - i >= 3 {
                flat[i..j].iter_mut().for_each(|f| *f = true);
            }
            i = j;
        }
        flat
    }

    /// Intervals of rear slip angle (rad) that are continua of equilibria.
    pub fn continua(&self) -> Vec<(f64, f64)> {
        let (a, h) = self.scan();
        Self::continua_of(&a, &self.flat(&h))
    }

    fn continua_of(a: &[f64], flat: &[bool]) -> Vec<(f64, f64)> {
        let mut out = Vec::new();
        let mut i = 0;
        while i < a.len() {
            if flat[i] {
                let j = (i..a.len()).take_while(|&k| flat[k]).last().unwrap_or(i);
                out.push((a[i], a[j]));
                i = j + 1;
            } else {
                i += 1;
            }
        }
        out
    }

    /// Every root (double roots included) and every continuum, from one scan.
    pub(crate) fn analyse(&self) -> (Vec<f64>, Vec<(f64, f64)>) {
        let (a, h) = self.scan();
        let flat = self.flat(&h);
        (
            self.roots_of(&a, &h, &flat, true),
            Self::continua_of(&a, &flat),
        )
    }

    fn roots_with(&self, doubles: bool) -> Vec<f64> {
        let (a, h) = self.scan();
        let flat = self.flat(&h);
        self.roots_of(&a, &h, &flat, doubles)
    }

    fn roots_of(&self, a: &[f64], h: &[f64], flat: &[bool], doubles: bool) -> Vec<f64> {
        let n = CELLS;
        let f = |x: f64| self.at(x).h;
        let tol = 1e-15;
        let mut roots = Vec::new();
        for i in 0..n {
            if flat[i] || flat[i + 1] {
                continue;
            }
            if h[i] == 0.0 {
                roots.push(a[i]);
            } else if h[i] * h[i + 1] < 0.0 {
                roots.push(brent(f, a[i], a[i + 1], tol));
            }
        }
        // Pairs of roots inside one cell, and double roots: at each interior
        // local minimum of |h| without a sign change nearby, minimise s·h
        // (s = sign of h there) over the two neighbouring cells.
        for i in 1..n {
            if flat[i - 1] || flat[i] || flat[i + 1] {
                continue;
            }
            let (p, q, r) = (h[i - 1], h[i], h[i + 1]);
            if q == 0.0
                || !(q.abs() <= p.abs() && q.abs() <= r.abs())
                || p * q <= 0.0
                || q * r <= 0.0
            {
                continue;
            }
            let s = q.signum();
            let xm = least(f, s, a[i - 1], a[i + 1]);
            let hm = f(xm);
            let scale = self.model.vehicle.mass * crate::constants::G;
            if s * hm < 0.0 {
                roots.push(brent(f, a[i - 1], xm, tol));
                roots.push(brent(f, xm, a[i + 1], tol));
            } else if doubles && hm.abs() <= 1e-12 * scale {
                roots.push(xm);
            }
        }
        self.roots_beside_zero_samples(a, h, flat, &mut roots);
        roots.sort_by(f64::total_cmp);
        roots.dedup_by(|x, y| (*x - *y).abs() < 1e-12);
        roots
    }

    /// Roots inside a cell that ends on a sample where h is exactly zero
    /// (straight running at δ = 0, where symmetry puts a root on the sample
    /// αr = 0): the sign scan misses them, as the product of the cell's
    /// ends is zero. Near a pitchfork two roots ±ε sit there, ε → 0; without
    /// them the count changes a scan cell away from the event, not at it.
    fn roots_beside_zero_samples(&self, a: &[f64], h: &[f64], flat: &[bool], roots: &mut Vec<f64>) {
        let f = |x: f64| self.at(x).h;
        for i in 0..CELLS {
            if flat[i] || flat[i + 1] || (h[i] == 0.0) == (h[i + 1] == 0.0) {
                continue;
            }
            let (zero, other) = if h[i] == 0.0 { (i, i + 1) } else { (i + 1, i) };
            // The extremum of h of the sign opposite to the non-zero end's:
            // a root lies between it and that end when h gets there.
            let s = h[other].signum();
            let xm = least(f, s, a[i], a[i + 1]);
            // An extremum within rounding of the zero sample is that
            // sample's own root.
            if s * f(xm) < 0.0 && (xm - a[zero]).abs() > 1e-12 {
                roots.push(brent(f, xm, a[other], 1e-15));
            }
        }
    }
}

/// Where `s·f` is least on `[lo, hi]`: 80 steps of a golden-section
/// search (the interval shrinks to rounding), the last bracket's middle.
fn least(f: impl Fn(f64) -> f64, s: f64, mut lo: f64, mut hi: f64) -> f64 {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..80 {
        let m1 = hi - g * (hi - lo);
        let m2 = lo + g * (hi - lo);
        if s * f(m1) < s * f(m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    0.5 * (lo + hi)
}

/// A continuum of equilibria: an interval of rear slip angle over which the
/// reduced function vanishes (both axles sliding at constant force).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Continuum {
    /// Rear slip angle interval, rad.
    pub alpha_rear: (f64, f64),
    /// Sideslip at its ends, rad.
    pub beta: (f64, f64),
    /// Yaw rate at its ends, rad/s.
    pub yaw_rate: (f64, f64),
}

/// The continua of equilibria at a condition (usually none).
pub fn continua(model: &VehicleModel, c: &Condition) -> Vec<Continuum> {
    solve_with_continua(model, c).1
}

/// All isolated equilibria at a condition (anywhere, not only in a box; see
/// [`continua`] for curves of them), in ascending rear slip angle. Each root
/// is polished by Newton on the full model so the residual is at machine
/// precision.
pub fn solve(model: &VehicleModel, c: &Condition) -> Vec<Equilibrium> {
    solve_with_continua(model, c).0
}

/// The isolated equilibria and the continua of a condition from one scan.
pub(crate) fn solve_with_continua(
    model: &VehicleModel,
    c: &Condition,
) -> (Vec<Equilibrium>, Vec<Continuum>) {
    solve_reduced(model, c, Reduced::new(model, *c))
}

/// [`solve_with_continua`] along a line of conditions: `rear` keeps the
/// rear half of the scan of the last condition, reused while the speed and
/// friction stay the same (the same answers, to the bit, at a fraction of
/// the rear axle's evaluations).
pub(crate) fn solve_with_continua_along(
    model: &VehicleModel,
    c: &Condition,
    rear: &mut Option<RearScan>,
) -> (Vec<Equilibrium>, Vec<Continuum>) {
    if !rear
        .as_ref()
        .is_some_and(|s| s.friction == c.friction && s.speed == c.speed)
    {
        *rear = Some(Reduced::new(model, *c).rear_scan());
    }
    let red = Reduced {
        rear: rear.as_ref(),
        ..Reduced::new(model, *c)
    };
    solve_reduced(model, c, red)
}

fn solve_reduced(
    model: &VehicleModel,
    c: &Condition,
    red: Reduced,
) -> (Vec<Equilibrium>, Vec<Continuum>) {
    let (roots, cont) = red.analyse();
    let equilibria = roots
        .into_iter()
        .map(|ar| {
            let p = red.at(ar);
            let x0 = [p.beta, p.yaw_rate];
            // Keep the polish only if it stayed at this root (near a fold,
            // Newton could jump to the partner root).
            let x = super::polish_fast(model, c, x0)
                .filter(|x| super::distance(*x, x0, [1.0, 1.0]) < 1e-6)
                .unwrap_or(x0);
            describe(model, c, x)
        })
        .collect();
    let continua = cont
        .into_iter()
        .map(|(lo, hi)| {
            let (p, q) = (red.at(lo), red.at(hi));
            Continuum {
                alpha_rear: (lo, hi),
                beta: (p.beta, q.beta),
                yaw_rate: (p.yaw_rate, q.yaw_rate),
            }
        })
        .collect();
    (equilibria, continua)
}
