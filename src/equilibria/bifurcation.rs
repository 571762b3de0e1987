//! Bifurcations along a one-parameter line of conditions (steer, friction or
//! speed varying, the others fixed).
//!
//! - Fold (saddle-node): between two neighbouring conditions the number of
//!   equilibria changes. The interval is bisected recursively with the exact
//!   solver's count to 1e-12 of its width, which separates several events in
//!   one interval; a change by two is a fold (a change by one is a root
//!   crossing the scan limit |αr| = 85°, where both axles slide, and is not a
//!   bifurcation). The two equilibria that merge are the closest neighbours
//!   in rear slip angle on the side that has them.
//!   The claim is checked: the pair must be one saddle and one node/focus
//!   (the eigenvalue count changes across the fold), and the augmented
//!   residual — max(|β̇|, |ṙ|) and det J relative to |J|² at the merge point —
//!   must be tiny. Two equilibria that merely approach each other never
//!   change the count and are not called a fold.
//! - Hopf: an equilibrium continued between neighbouring conditions whose
//!   leading eigenvalue's real part (the Jacobian trace's sign in (β, r))
//!   changes sign while det J > 0; bisected with Newton continuation to
//!   zero and checked the same way. With a tyre lag the eigenvalues are the
//!   full state's ([`super::lagged`]), so a Hopf point the lag brings is
//!   found too. Where the count changes in the same interval (a fold), the
//!   branches that persist across it (mutual nearest neighbours) are
//!   tested the same way.
//! - Zero eigenvalue: an equilibrium continued between neighbouring
//!   conditions whose det J changes sign with no change in the count (the
//!   straight-running car past its critical speed, where on linear tyres
//!   the one equilibrium stays at (0, 0) and goes from node to saddle);
//!   bisected with Newton continuation to det J = 0 and checked the same
//!   way. Along speed this is the critical speed.

use super::exact;
use super::lagged;
use super::stability::{self, Kind};
use super::{distance, polish, residual, Condition, Equilibrium};
use crate::vehicle::VehicleModel;
use serde::{Deserialize, Serialize};

/// The swept parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Axis {
    /// Steer δ.
    Steer,
    /// Friction μ.
    Friction,
    /// Speed u.
    Speed,
}

impl Axis {
    /// Name used in files.
    pub fn name(self) -> &'static str {
        match self {
            Axis::Steer => "steer",
            Axis::Friction => "friction",
            Axis::Speed => "speed",
        }
    }
    /// The parameter's value at a condition.
    pub fn get(self, c: &Condition) -> f64 {
        match self {
            Axis::Steer => c.steer,
            Axis::Friction => c.friction,
            Axis::Speed => c.speed,
        }
    }
    /// A condition with the parameter set.
    pub fn with(self, c: &Condition, v: f64) -> Condition {
        let mut c = *c;
        match self {
            Axis::Steer => c.steer = v,
            Axis::Friction => c.friction = v,
            Axis::Speed => c.speed = v,
        }
        c
    }
}

/// Kind of bifurcation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum BifurcationKind {
    /// Saddle-node: two equilibria meet.
    Fold,
    /// Three equilibria meet (a node, a saddle and a node): the degenerate
    /// case of axles with identical normalised characteristics, where
    /// equilibria with αf = αr exist.
    Pitchfork,
    /// Hopf.
    Hopf,
    /// A real eigenvalue of a continued equilibrium crosses zero with no
    /// change in the count of equilibria (det J changes sign on the
    /// branch): along speed, the straight-running car's critical speed,
    /// √(−l/K) on linear tyres (Genta 1997; Milliken & Milliken 1995).
    ZeroEigenvalue,
}

impl BifurcationKind {
    /// Name used in files and legends.
    pub fn name(self) -> &'static str {
        match self {
            BifurcationKind::Fold => "fold",
            BifurcationKind::Pitchfork => "pitchfork",
            BifurcationKind::Hopf => "hopf",
            BifurcationKind::ZeroEigenvalue => "zero-eigenvalue",
        }
    }
}

/// A located bifurcation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Bifurcation {
    /// Fold or Hopf.
    pub kind: BifurcationKind,
    /// The swept parameter.
    pub axis: Axis,
    /// The condition at the bifurcation.
    pub at: Condition,
    /// Sideslip there, rad.
    pub beta: f64,
    /// Yaw rate there, rad/s.
    pub yaw_rate: f64,
    /// max(|β̇|, |ṙ|) at the point.
    pub residual: f64,
    /// det J/|J|² (fold) or 2·Re λ/|J| of the leading pair (Hopf; trace
    /// J/|J| without a tyre lag) at the point.
    pub criterion: f64,
    /// Kinds of the two equilibria that meet (fold) or of the branch before
    /// and after (Hopf).
    pub kinds: [Kind; 2],
    /// Whether every check passed.
    pub verified: bool,
}

fn jacobian_scale(j: &[[f64; 2]; 2]) -> f64 {
    j.iter()
        .flatten()
        .map(|v| v.abs())
        .fold(0.0, f64::max)
        .max(1e-300)
}

/// A narrow parameter interval across which the root count changes:
/// ((p, count), (p, count)).
type CountChange = ((f64, usize), (f64, usize));

/// Narrow intervals of the parameter across which the exact root count
/// changes, found by recursive bisection of [pa, pb] to `tol`: (p with count
/// n1, p with count n2).
fn count_changes(
    count: &dyn Fn(f64) -> usize,
    (pa, na): (f64, usize),
    (pb, nb): (f64, usize),
    tol: f64,
    out: &mut Vec<CountChange>,
) {
    if na == nb {
        return;
    }
    if (pb - pa).abs() <= tol {
        out.push(((pa, na), (pb, nb)));
        return;
    }
    let pm = 0.5 * (pa + pb);
    let nm = count(pm);
    count_changes(count, (pa, na), (pm, nm), tol, out);
    count_changes(count, (pm, nm), (pb, nb), tol, out);
}

/// The fold at a narrow interval where the count drops by two from `more`
/// (the parameter value with the extra pair); `far` is a value well inside
/// the side with the pair, where the pair's kinds are read (at `more` they are
/// within rounding of det J = 0 and their signs are noise).
fn fold_at(
    model: &VehicleModel,
    axis: Axis,
    base: &Condition,
    more: f64,
    far: f64,
) -> Option<Bifurcation> {
    let at = axis.with(base, more);
    let red = exact::Reduced::new(model, at);
    let (merge, third) = merging(&red)?;
    let p = red.at(merge);
    let x = [p.beta, p.yaw_rate];
    let f = residual(model, &at, x);
    let j = stability::jacobian(model, &at, x);
    let det = (j[0][0] * j[1][1] - j[0][1] * j[1][0]) / jacobian_scale(&j).powi(2);
    // The pair's kinds, a little way into the side that has it.
    let check = axis.with(base, more + 1e-3 * (far - more));
    let kinds = kinds_near(model, check, merge)?;
    let one_saddle = (kinds[0] == Kind::Saddle) != (kinds[1] == Kind::Saddle);
    // At the fold itself det J = 0: the eigenvalues are 0 and trace J, so
    // the saddle's partner is a node there, of the trace's sign, though a
    // hair into the side with the pair it may already be a focus (eq_eff:
    // eigenvalues 0 and 0.104 at the fold, a focus 1e-5 rad away, said
    // "saddle + unstable-focus, verified" against the book's "one saddle
    // and one node"). The words give the kinds at the fold.
    let kinds = match (third, one_saddle, model.options.effects.lagged()) {
        (None, true, false) => {
            let node = match j[0][0] + j[1][1] < 0.0 {
                true => Kind::StableNode,
                false => Kind::UnstableNode,
            };
            kinds.map(|k| if k == Kind::Saddle { k } else { node })
        }
        _ => kinds,
    };
    let res = f[0].abs().max(f[1].abs());
    Some(Bifurcation {
        kind: if third.is_some() {
            BifurcationKind::Pitchfork
        } else {
            BifurcationKind::Fold
        },
        axis,
        at,
        beta: x[0],
        yaw_rate: x[1],
        residual: res,
        criterion: det,
        kinds,
        verified: one_saddle && res <= 1e-8 && det.abs() <= 1e-3,
    })
}

/// Where the closest pair of simple roots (rear slip angles) of `red`
/// merges, and a third root as near the pair as the pair is wide, if any:
/// then three meet, a pitchfork, not a fold (None: no pair).
fn merging(red: &exact::Reduced) -> Option<(f64, Option<f64>)> {
    // Simple roots only: the pair is two simple roots a hair before the fold,
    // as the bisection counted them.
    let roots = red.simple_roots();
    let (i, _) = roots
        .windows(2)
        .enumerate()
        .min_by(|(_, x), (_, y)| (x[1] - x[0]).abs().total_cmp(&(y[1] - y[0]).abs()))?;
    let (a0, a1) = (roots[i], roots[i + 1]);
    // A third equilibrium as close to the pair as the pair is wide (both
    // scale as the square root of the distance to the event) means three
    // meet: a pitchfork, not a fold.
    let (gap, mid) = (a1 - a0, 0.5 * (a0 + a1));
    let third = [i.checked_sub(1), Some(i + 2)]
        .into_iter()
        .flatten()
        .filter_map(|k| roots.get(k).copied())
        .find(|r| (r - mid).abs() < 10.0 * gap);
    // The merge point: for a pitchfork, the middle one of the three (the
    // branch that continues through it: on straight running at δ = 0 it is
    // (0, 0) exactly, where the outer two are √ of the distance away);
    // for a fold, the extremum of h between the pair's rear slip angles (h
    // has a double root there at the fold itself).
    let merge = match third {
        Some(t) => {
            let mut three = [a0, a1, t];
            three.sort_by(f64::total_cmp);
            three[1]
        }
        None => merge_point(red, a0, a1),
    };
    Some((merge, third))
}

/// The kinds of the two equilibria of condition `check` nearest the rear
/// slip angle `merge` (None: fewer than two there).
fn kinds_near(model: &VehicleModel, check: Condition, merge: f64) -> Option<[Kind; 2]> {
    let red_c = exact::Reduced::new(model, check);
    let mut near = red_c.simple_roots();
    near.sort_by(|x, y| (x - merge).abs().total_cmp(&(y - merge).abs()));
    let kind_at = |ar: f64| {
        let q = red_c.at(ar);
        lagged::classify(model, &check, [q.beta, q.yaw_rate]).kind
    };
    match near.as_slice() {
        [x, y, ..] => Some([kind_at(*x), kind_at(*y)]),
        _ => None,
    }
}

/// The extremum of h between two neighbouring roots `a0 < a1` (golden
/// section): where they merge at a fold.
fn merge_point(red: &exact::Reduced, a0: f64, a1: f64) -> f64 {
    let mid = 0.5 * (a0 + a1);
    let (mut lo, mut hi) = (a0, a1);
    let s = red.at(mid).h.signum();
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..100 {
        let m1 = hi - g * (hi - lo);
        let m2 = lo + g * (hi - lo);
        if s * red.at(m1).h < s * red.at(m2).h {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    0.5 * (lo + hi)
}

/// Folds between conditions `a` and `b` (which differ only in `axis`). A
/// change of the count by one is a root crossing the scan limit |αr| = 85°,
/// not a bifurcation, and is skipped; one interval may hold both.
fn folds(model: &VehicleModel, axis: Axis, a: &Condition, b: &Condition) -> Vec<Bifurcation> {
    let count = |p: f64| {
        exact::Reduced::new(model, axis.with(a, p))
            .simple_roots()
            .len()
    };
    let (pa, pb) = (axis.get(a), axis.get(b));
    let tol = 1e-12 * (pa - pb).abs().max(1e-12);
    let mut changes = Vec::new();
    count_changes(&count, (pa, count(pa)), (pb, count(pb)), tol, &mut changes);
    // Within rounding of a fold the pair's dip is below the noise of h, so
    // the count may step 1 → 2 → 3 over a few ulps: merge changes that lie
    // within 1e-8 of the interval of each other and judge the net change.
    changes.sort_by(|x, y| x.0 .0.total_cmp(&y.0 .0));
    let mut merged: Vec<CountChange> = Vec::new();
    for ch in changes {
        match merged.last_mut() {
            Some(last) if (ch.0 .0 - last.1 .0).abs() <= 1e-8 * (pa - pb).abs() => last.1 = ch.1,
            _ => merged.push(ch),
        }
    }
    merged
        .into_iter()
        .filter_map(|((p1, n1), (p2, n2))| match (n1, n2) {
            _ if n1 == n2 + 2 => fold_at(
                model,
                axis,
                a,
                p1,
                if count(pa) >= count(pb) { pa } else { pb },
            ),
            _ if n2 == n1 + 2 => fold_at(
                model,
                axis,
                a,
                p2,
                if count(pa) >= count(pb) { pa } else { pb },
            ),
            _ => None,
        })
        .collect()
}

/// A point of a continued branch: (parameter, (β, r)).
type BranchPoint = (f64, [f64; 2]);

/// The branch from `ea` at `a` to `eb` at `b` bisected in the parameter,
/// each midpoint's equilibrium found by Newton from the mean of the
/// bracket's, until the bracket is 1e-12 of its width: where `quantity` of
/// the equilibrium's stability (with a tyre lag, the full state's) changes
/// sign. The bracket's ends, (parameter, state) on `ea`'s side and on
/// `eb`'s; `None` when Newton loses the branch.
fn bisect_sign(
    model: &VehicleModel,
    axis: Axis,
    (a, ea): (&Condition, &Equilibrium),
    (b, eb): (&Condition, &Equilibrium),
    quantity: impl Fn(&stability::Stability) -> f64,
) -> Option<(BranchPoint, BranchPoint)> {
    let (mut pa, mut pb) = (axis.get(a), axis.get(b));
    let (mut xa, mut xb) = ([ea.beta, ea.yaw_rate], [eb.beta, eb.yaw_rate]);
    let qa = quantity(&ea.stability);
    let tol = 1e-12 * (pa - pb).abs().max(1e-12);
    while (pa - pb).abs() > tol {
        let pm = 0.5 * (pa + pb);
        let x0 = [0.5 * (xa[0] + xb[0]), 0.5 * (xa[1] + xb[1])];
        let cm = axis.with(a, pm);
        let xm = polish(model, &cm, x0)?;
        if quantity(&lagged::classify(model, &cm, xm)) * qa > 0.0 {
            (pa, xa) = (pm, xm);
        } else {
            (pb, xb) = (pm, xm);
        }
    }
    Some(((pa, xa), (pb, xb)))
}

/// Locates a Hopf point on the branch from `ea` at `a` to `eb` at `b`.
fn hopf(
    model: &VehicleModel,
    axis: Axis,
    a: &Condition,
    ea: &Equilibrium,
    b: &Condition,
    eb: &Equilibrium,
) -> Option<Bifurcation> {
    // The leading eigenvalue's real part: its sign is the trace's for the
    // (β, r) Jacobian at det J > 0, and it is what crosses zero at a Hopf
    // point of the full state with a tyre lag.
    let ((pa, xa), _) = bisect_sign(model, axis, (a, ea), (b, eb), |s| s.eigenvalues[0].0)?;
    let at = axis.with(a, pa);
    let f = residual(model, &at, xa);
    let (s, scale) = if model.options.effects.lagged() {
        let j = lagged::jacobian(model, &at, xa);
        let scale = j.iter().flatten().fold(1e-300, |m: f64, v| m.max(v.abs()));
        (lagged::from_jacobian(j), scale)
    } else {
        let j = stability::jacobian(model, &at, xa);
        (stability::from_jacobian(j), jacobian_scale(&j))
    };
    // Twice the leading pair's real part: the trace of the (β, r) Jacobian
    // at a complex pair.
    let crit = 2.0 * s.eigenvalues[0].0 / scale;
    let res = f[0].abs().max(f[1].abs());
    Some(Bifurcation {
        kind: BifurcationKind::Hopf,
        axis,
        at,
        beta: xa[0],
        yaw_rate: xa[1],
        residual: res,
        criterion: crit,
        kinds: [ea.stability.kind, eb.stability.kind],
        verified: s.determinant > 0.0 && res <= 1e-8 && crit.abs() <= 1e-6,
    })
}

/// Locates where det J of the branch from `ea` at `a` to `eb` at `b`
/// crosses zero (a real eigenvalue through zero; the count unchanged).
fn zero_eigenvalue(
    model: &VehicleModel,
    axis: Axis,
    a: &Condition,
    ea: &Equilibrium,
    b: &Condition,
    eb: &Equilibrium,
) -> Option<Bifurcation> {
    let ((pa, xa), (pb, _)) = bisect_sign(model, axis, (a, ea), (b, eb), |s| s.determinant)?;
    let p = 0.5 * (pa + pb);
    let at = axis.with(a, p);
    let x = polish(model, &at, xa).unwrap_or(xa);
    let f = residual(model, &at, x);
    let j = stability::jacobian(model, &at, x);
    let det = (j[0][0] * j[1][1] - j[0][1] * j[1][0]) / jacobian_scale(&j).powi(2);
    let res = f[0].abs().max(f[1].abs());
    Some(Bifurcation {
        kind: BifurcationKind::ZeroEigenvalue,
        axis,
        at,
        beta: x[0],
        yaw_rate: x[1],
        residual: res,
        criterion: det,
        kinds: [ea.stability.kind, eb.stability.kind],
        verified: res <= 1e-8 && det.abs() <= 1e-6,
    })
}

/// Whether the leading eigenvalue's real part changes sign between two
/// points of one branch with det J > 0 on both (no real eigenvalue
/// through zero between them).
fn hopf_between(x: &Equilibrium, y: &Equilibrium) -> bool {
    let (sx, sy) = (x.stability, y.stability);
    sx.determinant > 0.0 && sy.determinant > 0.0 && sx.eigenvalues[0].0 * sy.eigenvalues[0].0 < 0.0
}

/// The branches that persist across an interval where the count changes:
/// pairs, one equilibrium from each side, each the other's nearest and
/// within 0.1 rad and 0.1 rad/s of it. The pair that appears or vanishes
/// at a fold has no partner on the other side, or a partner nearer to its
/// twin, so it is left out.
fn persisting<'a>(
    ea: &'a [Equilibrium],
    eb: &'a [Equilibrium],
) -> Vec<(&'a Equilibrium, &'a Equilibrium)> {
    let d = |x: &Equilibrium, y: &Equilibrium| {
        distance([x.beta, x.yaw_rate], [y.beta, y.yaw_rate], [0.1, 0.1])
    };
    let nearest = |x: &Equilibrium, among: &'a [Equilibrium]| {
        among.iter().min_by(|p, q| d(x, p).total_cmp(&d(x, q)))
    };
    ea.iter()
        .filter_map(|x| {
            let y = nearest(x, eb)?;
            let back = nearest(y, ea)?;
            (std::ptr::eq(back, x) && d(x, y) < 1.0).then_some((x, y))
        })
        .collect()
}

/// Every fold, Hopf and zero-eigenvalue point along a line of conditions ordered by `axis`,
/// given the exact equilibria at each (all of them, not box-limited).
pub(crate) fn locate(
    model: &VehicleModel,
    axis: Axis,
    line: &[(Condition, Vec<Equilibrium>)],
) -> Vec<Bifurcation> {
    let mut out = Vec::new();
    for w in line.windows(2) {
        let ((ca, ea), (cb, eb)) = (&w[0], &w[1]);
        let (na, nb) = (ea.len(), eb.len());
        if na != nb {
            out.extend(folds(model, axis, ca, cb));
            // A Hopf point on a branch that persists across the fold's
            // interval (the soft-rear sedan's high-yaw branch turns stable
            // at 0.0226 rad of steer, in the interval of a fold at 0.0245).
            for (x, y) in persisting(ea, eb) {
                if hopf_between(x, y) {
                    out.extend(hopf(model, axis, ca, x, cb, y));
                }
            }
        } else {
            for (x, y) in ea.iter().zip(eb) {
                let close = distance([x.beta, x.yaw_rate], [y.beta, y.yaw_rate], [0.1, 0.1]) < 1.0;
                let (sx, sy) = (x.stability, y.stability);
                if close && sx.determinant * sy.determinant < 0.0 {
                    out.extend(zero_eigenvalue(model, axis, ca, x, cb, y));
                } else if close && hopf_between(x, y) {
                    out.extend(hopf(model, axis, ca, x, cb, y));
                }
            }
        }
    }
    out
}
