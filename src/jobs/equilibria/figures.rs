//! PNG figures of equilibrium sweeps: branch diagrams (stable solid,
//! unstable dashed, folds marked), phase portraits (vector field,
//! trajectories with arrowheads in the direction of flow, equilibria, saddle separatrices, computed in
//! [`crate::equilibria::phase`]); the stability map over two swept
//! parameters is `super::map`'s. Angles are drawn in degrees, speeds in
//! km/h, for reading.

use super::slices::{axis_label, display, title_tail, Diagram};
use crate::equilibria::bifurcation::{Axis, Bifurcation, BifurcationKind};
use crate::equilibria::phase::{self, Manifold};
use crate::equilibria::sweep::SweepResult;
use crate::equilibria::{Condition, Equilibrium, Kind, SearchBox};
use crate::error::Error;
use crate::report::branches::{self, At};
use crate::report::plot::{Figure, Panel, Series, Style};
use crate::report::series::INK;
use crate::report::stability::{self, Class};
use crate::vehicle::VehicleModel;
use std::path::Path;

/// Palette index of the fold markers (grey, apart from the stability
/// colours).
pub(super) const FOLD: usize = 7;

pub(super) fn in_box(eqs: &[Equilibrium], bx: &SearchBox) -> Vec<Equilibrium> {
    eqs.iter()
        .copied()
        .filter(|e| bx.contains([e.beta, e.yaw_rate]))
        .collect()
}

/// Largest step, in box half-widths, between two equilibria of one branch
/// at neighbouring grid values.
const BRANCH_GAP: f64 = 0.35;
/// Largest distance, in box half-widths, from a fold to the last point of a
/// branch that ends there (branches move fast near a fold).
const FOLD_GAP: f64 = 0.8;

/// What a branch diagram draws along its line: the
/// equilibria in the box at each grid value, the links between
/// neighbouring values that make branches, and the branch ends joined to
/// the fold or pitchfork where they meet.
pub(super) struct Drawn<'a> {
    /// The swept parameter at each grid value of the line, SI.
    pub params: Vec<f64>,
    /// The equilibria in the box at each value.
    pub eqs: Vec<Vec<Equilibrium>>,
    /// (value i, index), (value i + 1, index) of one branch.
    pub links: Vec<(At, At)>,
    /// A branch end and the bifurcation it ends at.
    pub joins: Vec<(At, &'a Bifurcation)>,
}

/// The branches of the line of diagram `d` ([`Drawn`]). The equilibria
/// that meet at a fold (two) or pitchfork (the outer two of three) are
/// chosen first, on the side of it that has them (more equilibria in all),
/// and kept out of the matching across its interval ([`branches::link`]);
/// a saddle is linked to a node or focus only across an interval that
/// holds a zero eigenvalue or pitchfork.
pub(super) fn drawn<'a>(res: &'a SweepResult, d: &Diagram, bx: &SearchBox) -> Drawn<'a> {
    let (axis, line) = (d.axis, &d.line);
    let params: Vec<f64> = line
        .iter()
        .map(|&i| axis.get(&res.points[i].condition))
        .collect();
    let eqs: Vec<Vec<Equilibrium>> = line
        .iter()
        .map(|&i| in_box(&res.points[i].exact, bx))
        .collect();
    let scaled = |e: &Equilibrium| [e.beta / bx.beta_max, e.yaw_rate / bx.yaw_rate_max];
    let columns: Vec<Vec<[f64; 2]>> = eqs.iter().map(|c| c.iter().map(scaled).collect()).collect();
    let (mut cut, mut joins, mut turning) = (Vec::new(), Vec::new(), Vec::new());
    for f in folds_on_line(res, axis, line) {
        let p = axis.get(&f.at);
        let Some(i) = params
            .windows(2)
            .position(|w| w[0].min(w[1]) <= p && p <= w[0].max(w[1]))
        else {
            continue;
        };
        let meet = match f.kind {
            BifurcationKind::Fold => 2,
            BifurcationKind::Pitchfork => 3,
            BifurcationKind::ZeroEigenvalue => {
                turning.push(i);
                continue;
            }
            BifurcationKind::Hopf => continue,
        };
        if meet == 3 {
            turning.push(i);
        }
        let at = [f.beta / bx.beta_max, f.yaw_rate / bx.yaw_rate_max];
        let (na, nb) = (
            res.points[line[i]].exact.len(),
            res.points[line[i + 1]].exact.len(),
        );
        let near = |c: usize| {
            columns[c]
                .iter()
                .map(|&q| (q[0] - at[0]).hypot(q[1] - at[1]))
                .fold(f64::INFINITY, f64::min)
        };
        let side = match na.cmp(&nb) {
            std::cmp::Ordering::Greater => i,
            std::cmp::Ordering::Less => i + 1,
            std::cmp::Ordering::Equal if near(i) <= near(i + 1) => i,
            std::cmp::Ordering::Equal => i + 1,
        };
        for end in branches::meeting(&columns, side, at, meet, FOLD_GAP) {
            cut.push((i, end));
            joins.push((end, f));
        }
    }
    let saddle = |(c, k): At| eqs[c][k].stability.kind == Kind::Saddle;
    let allowed = |i: usize, a: At, b: At| saddle(a) == saddle(b) || turning.contains(&i);
    let links = branches::link(&columns, BRANCH_GAP, &cut, &allowed);
    Drawn {
        params,
        eqs,
        links,
        joins,
    }
}

/// The segments [`branch_diagram`] draws for diagram `dg`, as rows of
/// its `.csv` (SI: rad, rad/s, m/s): a link between
/// equilibria of one branch at neighbouring grid values, or a branch end
/// joined to the fold or pitchfork where it ends (`to_kind` names it).
pub(super) fn branch_rows(res: &SweepResult, dg: &Diagram, bx: &SearchBox) -> Vec<Vec<String>> {
    let (axis, d) = (dg.axis, drawn(res, dg, bx));
    let point = |(c, k): At| {
        let e = &d.eqs[c][k];
        [d.params[c], e.beta, e.yaw_rate].map(|v| v.to_string())
    };
    let kind = |(c, k): At| d.eqs[c][k].stability.kind.name().to_string();
    let links = d.links.iter().map(|&(a, b)| {
        let mut row = point(a).to_vec();
        row.push(kind(a));
        row.extend(point(b));
        row.push(kind(b));
        row
    });
    let joins = d.joins.iter().map(|&(a, f)| {
        let mut row = point(a).to_vec();
        row.push(kind(a));
        row.extend([axis.get(&f.at), f.beta, f.yaw_rate].map(|v| v.to_string()));
        row.push(f.kind.name().to_string());
        row
    });
    links.chain(joins).collect()
}

/// β and r of the equilibria against the swept parameter, along the line
/// of diagram `dg` (`k` of `lines` along its axis): equilibria of one branch joined (nearest neighbours in
/// the box-scaled plane, [`branches::link`]), each segment and point in the
/// style of its stability ([`Class`]), folds joined to the branch ends that
/// meet there; along speed, the closed-form `critical` speed (m/s) where
/// it falls on the line ([`mark_critical_speed`]).
pub(super) fn branch_diagram(
    res: &SweepResult,
    (dg, k, lines): (&Diagram, usize, usize),
    bx: &SearchBox,
    critical: Option<f64>,
    path: &Path,
) -> Result<(), Error> {
    let (axis, line) = (dg.axis, &dg.line);
    let (mut beta, mut yaw) = branch_panels(axis, &title_tail(dg, k, lines));
    let d = drawn(res, dg, bx);
    let params: Vec<f64> = d.params.iter().map(|&p| display(axis, p)).collect();
    let eqs = &d.eqs;
    let class = |(c, k): At| eqs[c][k].stability.kind.class();
    let mut present = Vec::new();
    let mut segment = |class: Class, x: [f64; 2], b: [f64; 2], r: [f64; 2]| {
        present.push(class);
        beta.series.push(stability::branch(class, &x, &b));
        yaw.series.push(stability::branch(class, &x, &r));
    };
    let state = |(c, k): At| {
        let e = &eqs[c][k];
        (params[c], e.beta.to_degrees(), e.yaw_rate.to_degrees())
    };
    for &(a, b) in &d.links {
        let ((xa, ba, ra), (xb, bb, rb)) = (state(a), state(b));
        segment(class(a).weaker(class(b)), [xa, xb], [ba, bb], [ra, rb]);
    }
    let folds = folds_on_line(res, axis, line);
    for &(end, f) in &d.joins {
        let p = display(axis, axis.get(&f.at));
        let (x, b, r) = state(end);
        let (fb, fr) = (f.beta.to_degrees(), f.yaw_rate.to_degrees());
        segment(class(end), [x, p], [b, fb], [r, fr]);
    }
    for cl in Class::ALL {
        let mut pts = Vec::new();
        for (c, col) in eqs.iter().enumerate() {
            for (k, _) in col.iter().enumerate().filter(|(k, _)| class((c, *k)) == cl) {
                pts.push(state((c, k)));
            }
        }
        if pts.is_empty() {
            continue;
        }
        present.push(cl);
        let x: Vec<f64> = pts.iter().map(|p| p.0).collect();
        let b: Vec<f64> = pts.iter().map(|p| p.1).collect();
        let r: Vec<f64> = pts.iter().map(|p| p.2).collect();
        beta.series.push(stability::equilibria(cl, &x, &b, 4));
        yaw.series.push(stability::equilibria(cl, &x, &r, 4));
    }
    mark_folds(&mut beta, &mut yaw, &folds, axis);
    if axis == Axis::Speed {
        mark_critical_speed([&mut beta, &mut yaw], critical, &params);
    }
    for cl in Class::ALL.into_iter().filter(|c| present.contains(c)) {
        beta.series.push(stability::key(cl));
        yaw.series.push(stability::key(cl));
    }
    Figure::stack(vec![beta, yaw]).save(path)
}

/// The branch diagram's two panels, sideslip over yaw rate, titled with
/// the swept parameter and the values `held` of the others.
fn branch_panels(axis: Axis, held: &str) -> (Panel, Panel) {
    let beta = Panel {
        title: format!(
            "steering equilibria: sideslip against {}{held}",
            axis.name()
        ),
        x_label: axis_label(axis).into(),
        y_label: "β_e [deg]".into(),
        ..Panel::default()
    };
    let yaw = Panel {
        title: format!("yaw rate against {}", axis.name()),
        x_label: axis_label(axis).into(),
        y_label: "r_e [deg/s]".into(),
        ..Panel::default()
    };
    (beta, yaw)
}

/// The bifurcations `folds` of the line as points on both panels, named
/// by the first one's kind.
fn mark_folds(beta: &mut Panel, yaw: &mut Panel, folds: &[&Bifurcation], axis: Axis) {
    if let Some(first) = folds.first() {
        let fx: Vec<f64> = folds
            .iter()
            .map(|b| display(axis, axis.get(&b.at)))
            .collect();
        let deg = |f: fn(&Bifurcation) -> f64| -> Vec<f64> {
            folds.iter().map(|b| f(b).to_degrees()).collect()
        };
        let l = first.kind.name();
        beta.series
            .push(Series::line(l, &fx, &deg(|b| b.beta), FOLD).styled(Style::Points(7)));
        yaw.series
            .push(Series::line(l, &fx, &deg(|b| b.yaw_rate), FOLD).styled(Style::Points(7)));
    }
}

/// Palette index of the critical speed's line (purple, apart from the
/// stability colours and the folds' grey).
const CRITICAL: usize = 4;

/// The closed-form critical speed `critical` (m/s) of an oversteering car
/// as a dotted vertical line over the equilibria of both panels of a
/// branch diagram along speed (`speeds` in km/h), where it falls among
/// them: below it the linear car's trims are stable, above it saddles, and
/// near it their β and r grow without bound (the yaw-rate gain
/// u/(l + K·u²)), so that the branches leave the box there without a
/// bifurcation located in it.
fn mark_critical_speed(panels: [&mut Panel; 2], critical: Option<f64>, speeds: &[f64]) {
    let Some(c) = critical.map(|c| display(Axis::Speed, c)) else {
        return;
    };
    let (lo, hi) = speeds
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    if !(lo..=hi).contains(&c) {
        return;
    }
    for panel in panels {
        let ys = panel.series.iter().flat_map(|s| s.y.iter().copied());
        let (y0, y1) = ys
            .filter(|y| y.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            });
        if y0 <= y1 {
            let label = format!("critical speed {c:.1} km/h (closed form)");
            panel
                .series
                .push(Series::line(&label, &[c, c], &[y0, y1], CRITICAL).styled(Style::Dotted));
        }
    }
}

/// The bifurcations located along `line` (the other parameters at its
/// values).
fn folds_on_line<'a>(res: &'a SweepResult, axis: Axis, line: &[usize]) -> Vec<&'a Bifurcation> {
    let first = &res.points[line[0]].condition;
    let on_line = |b: &&Bifurcation| {
        b.axis == axis
            && [Axis::Steer, Axis::Friction, Axis::Speed]
                .iter()
                .all(|&o| o == axis || (o.get(&b.at) - o.get(first)).abs() < 1e-12)
    };
    res.bifurcations.iter().filter(on_line).collect()
}

/// β, r in degrees and deg/s, for drawing.
fn in_degrees(v: &[[f64; 2]]) -> (Vec<f64>, Vec<f64>) {
    v.iter()
        .map(|x| (x[0].to_degrees(), x[1].to_degrees()))
        .unzip()
}

/// Phase portrait at one condition.
pub fn phase_portrait(
    model: &VehicleModel,
    c: &Condition,
    search: &SearchBox,
    eqs: &[Equilibrium],
    path: &Path,
) -> Result<(), Error> {
    // Trajectories and separatrices leave the search box (which only bounds
    // where equilibria can be): draw twice its yaw-rate range.
    let bx = &SearchBox {
        beta_max: search.beta_max,
        yaw_rate_max: 2.0 * search.yaw_rate_max,
    };
    let mut series = vec![vector_field(model, c, bx)];
    // Trajectories from a grid of starts, each to a node or out of the box.
    let ends: Vec<[f64; 2]> = eqs.iter().map(|e| [e.beta, e.yaw_rate]).collect();
    let m = 7;
    let mut heads = Vec::new();
    for i in 0..m {
        for k in 0..m {
            let x0 = phase::grid_point(bx, m, i, k);
            let orbit = phase::orbit(model, c, bx, x0, 1.0, 0.01, &ends);
            let (tx, ty) = in_degrees(&orbit);
            let label = if i + k == 0 { "trajectories" } else { "" };
            series.push(Series::line(label, &tx, &ty, stability::TRAJECTORY));
            heads.extend(phase::arrowhead(&orbit, bx));
        }
    }
    series.push(arrowheads(&heads));
    series.extend(separatrices(model, c, bx, eqs));
    series.extend(searched(search));
    series.extend(equilibrium_markers(eqs, bx));
    let panel = Panel {
        title: format!(
            "phase portrait: δ = {:.2}°, μ = {:.2}, u = {:.1} km/h",
            c.steer.to_degrees(),
            c.friction,
            c.speed * 3.6
        ),
        x_label: "β [deg]".into(),
        y_label: "r [deg/s]".into(),
        series,
        x_range: Some((-bx.beta_max.to_degrees(), bx.beta_max.to_degrees())),
        y_range: Some((-bx.yaw_rate_max.to_degrees(), bx.yaw_rate_max.to_degrees())),
    };
    Figure {
        panels: vec![panel],
        columns: 1,
        width: 900,
        row_height: 800,
    }
    .save(path)
}

/// Palette index of the arrowheads: the trajectories' hue, dark (in their
/// own light colour, one pixel wide, they could not be seen).
const ARROWHEAD: usize = 0;

/// The trajectories' arrowheads (direction of increasing time), two
/// segments each from the barbs to the tip.
fn arrowheads(heads: &[phase::Arrowhead]) -> Series {
    let points: Vec<[f64; 2]> = heads
        .iter()
        .flat_map(|a| [a.barbs[0], a.tip, a.barbs[1], a.tip])
        .collect();
    let (x, y) = in_degrees(&points);
    Series::line("", &x, &y, ARROWHEAD).styled(Style::Segments)
}

/// The search box's yaw-rate bounds as dashed lines across the portrait,
/// named once in the key: the portrait draws twice its range, and beyond
/// them no equilibrium was searched for.
fn searched(search: &SearchBox) -> [Series; 2] {
    let b = search.beta_max.to_degrees();
    let r = search.yaw_rate_max.to_degrees();
    let label = format!("equilibria searched within |r| ≤ {r:.1} deg/s");
    [r, -r].map(|y| {
        let label = if y > 0.0 { label.as_str() } else { "" };
        Series::line(label, &[-b, b], &[y, y], INK).styled(Style::Dashed)
    })
}

/// The vector field as unit arrows in box-scaled units on a 21 × 21 grid.
fn vector_field(model: &VehicleModel, c: &Condition, bx: &SearchBox) -> Series {
    let arrows: Vec<[f64; 2]> = phase::vector_field(model, c, bx, 21)
        .into_iter()
        .flatten()
        .collect();
    let (ax, ay) = in_degrees(&arrows);
    Series::line("", &ax, &ay, 7).styled(Style::Segments)
}

/// The stable and unstable manifolds of every saddle in colours of their
/// own, the separatrix (stable manifold) the bolder, each named once in the
/// key.
fn separatrices(
    model: &VehicleModel,
    c: &Condition,
    bx: &SearchBox,
    eqs: &[Equilibrium],
) -> Vec<Series> {
    let mut series = Vec::new();
    let mut named = [false; 2];
    for branches in phase::separatrices(model, c, bx, eqs) {
        for b in branches {
            let (k, color, name) = match b.manifold {
                Manifold::Stable => (
                    0,
                    stability::STABLE_MANIFOLD,
                    "stable manifold (separatrix)",
                ),
                Manifold::Unstable => (1, stability::UNSTABLE_MANIFOLD, "unstable manifold"),
            };
            let label = if named[k] { "" } else { name };
            named[k] = true;
            let (tx, ty) = in_degrees(&b.points);
            series.push(Series::line(label, &tx, &ty, color));
        }
    }
    series
}

/// The equilibria in the box, marked by their stability class as on the
/// branch diagrams, the classes present named in the key.
fn equilibrium_markers(eqs: &[Equilibrium], bx: &SearchBox) -> Vec<Series> {
    let mut series = Vec::new();
    for class in Class::ALL {
        let pts: Vec<[f64; 2]> = eqs
            .iter()
            .filter(|e| e.stability.kind.class() == class && bx.contains([e.beta, e.yaw_rate]))
            .map(|e| [e.beta, e.yaw_rate])
            .collect();
        if !pts.is_empty() {
            let (px, py) = in_degrees(&pts);
            series.push(stability::equilibria(class, &px, &py, 7));
            series.push(stability::key(class));
        }
    }
    series
}
