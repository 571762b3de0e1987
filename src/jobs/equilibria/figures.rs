//! PNG figures of equilibrium sweeps: branch diagrams (stable solid,
//! unstable dashed, folds marked), phase portraits (vector field,
//! trajectories, equilibria, saddle separatrices, computed in
//! [`crate::equilibria::phase`]) and stability maps over two swept
//! parameters. Angles are drawn in degrees, speeds in km/h, for reading.

use crate::equilibria::bifurcation::{Axis, Bifurcation};
use crate::equilibria::phase::{self, Manifold};
use crate::equilibria::sweep::{axis_lines, SweepResult};
use crate::equilibria::{Condition, Equilibrium, Kind, SearchBox};
use crate::error::Error;
use crate::report::plot::{Figure, Panel, Series, Style};
use crate::vehicle::VehicleModel;
use std::path::Path;

const STABLE: usize = 0;
const UNSTABLE: usize = 1;
const FOLD: usize = 7;

/// A parameter in display units and its label.
fn display(axis: Axis, v: f64) -> f64 {
    match axis {
        Axis::Steer => v.to_degrees(),
        Axis::Friction => v,
        Axis::Speed => v * 3.6,
    }
}

fn axis_label(axis: Axis) -> &'static str {
    match axis {
        Axis::Steer => "steer δ [deg]",
        Axis::Friction => "friction μ [-]",
        Axis::Speed => "speed u [km/h]",
    }
}

fn in_box(eqs: &[Equilibrium], bx: &SearchBox) -> Vec<Equilibrium> {
    eqs.iter()
        .copied()
        .filter(|e| bx.contains([e.beta, e.yaw_rate]))
        .collect()
}

/// β and r of the equilibria against the swept parameter, along the first
/// line of `axis`.
pub fn branch_diagram(
    res: &SweepResult,
    axis: Axis,
    bx: &SearchBox,
    path: &Path,
) -> Result<(), Error> {
    let line = &axis_lines(&res.grid, axis)[0];
    let mut beta = Panel {
        title: format!("steering equilibria: sideslip against {}", axis.name()),
        x_label: axis_label(axis).into(),
        y_label: "β_e [deg]".into(),
        ..Panel::default()
    };
    let mut yaw = Panel {
        title: format!("yaw rate against {}", axis.name()),
        x_label: axis_label(axis).into(),
        y_label: "r_e [deg/s]".into(),
        ..Panel::default()
    };
    for w in line.windows(2) {
        let (a, b) = (&res.points[w[0]], &res.points[w[1]]);
        let (ea, eb) = (in_box(&a.exact, bx), in_box(&b.exact, bx));
        if ea.len() != eb.len() {
            continue;
        }
        let (pa, pb) = (
            display(axis, axis.get(&a.condition)),
            display(axis, axis.get(&b.condition)),
        );
        for (x, y) in ea.iter().zip(&eb) {
            let stable = x.stability.kind.is_stable() && y.stability.kind.is_stable();
            let (style, color) = if stable {
                (Style::Line, STABLE)
            } else {
                (Style::Dashed, UNSTABLE)
            };
            let seg =
                |v0: f64, v1: f64| Series::line("", &[pa, pb], &[v0, v1], color).styled(style);
            beta.series
                .push(seg(x.beta.to_degrees(), y.beta.to_degrees()));
            yaw.series
                .push(seg(x.yaw_rate.to_degrees(), y.yaw_rate.to_degrees()));
        }
    }
    for &i in line {
        let p = &res.points[i];
        for e in in_box(&p.exact, bx) {
            let c = if e.stability.kind.is_stable() {
                STABLE
            } else {
                UNSTABLE
            };
            let x = [display(axis, axis.get(&p.condition))];
            beta.series
                .push(Series::line("", &x, &[e.beta.to_degrees()], c).styled(Style::Points(3)));
            yaw.series
                .push(Series::line("", &x, &[e.yaw_rate.to_degrees()], c).styled(Style::Points(3)));
        }
    }
    let first = &res.points[line[0]].condition;
    let on_line = |b: &&Bifurcation| {
        b.axis == axis
            && [Axis::Steer, Axis::Friction, Axis::Speed]
                .iter()
                .all(|&o| o == axis || (o.get(&b.at) - o.get(first)).abs() < 1e-12)
    };
    let folds: Vec<&Bifurcation> = res.bifurcations.iter().filter(on_line).collect();
    let fx: Vec<f64> = folds
        .iter()
        .map(|b| display(axis, axis.get(&b.at)))
        .collect();
    if !folds.is_empty() {
        let l = folds[0].kind.name();
        beta.series.push(
            Series::line(
                l,
                &fx,
                &folds
                    .iter()
                    .map(|b| b.beta.to_degrees())
                    .collect::<Vec<_>>(),
                FOLD,
            )
            .styled(Style::Points(7)),
        );
        yaw.series.push(
            Series::line(
                l,
                &fx,
                &folds
                    .iter()
                    .map(|b| b.yaw_rate.to_degrees())
                    .collect::<Vec<_>>(),
                FOLD,
            )
            .styled(Style::Points(7)),
        );
    }
    for p in [&mut beta, &mut yaw] {
        p.series.push(Series::line("stable", &[], &[], STABLE));
        p.series
            .push(Series::line("unstable", &[], &[], UNSTABLE).styled(Style::Dashed));
    }
    Figure::stack(vec![beta, yaw]).save(path)
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
    // Trajectories from a grid of starts.
    let m = 7;
    for i in 0..m {
        for k in 0..m {
            let x0 = phase::grid_point(bx, m, i, k);
            let (tx, ty) = in_degrees(&phase::trajectory(model, c, bx, x0, 0.01, 600));
            series.push(Series::line("", &tx, &ty, 0));
        }
    }
    series.extend(separatrices(model, c, bx, eqs));
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

/// The vector field as unit arrows in box-scaled units on a 21 × 21 grid.
fn vector_field(model: &VehicleModel, c: &Condition, bx: &SearchBox) -> Series {
    let arrows: Vec<[f64; 2]> = phase::vector_field(model, c, bx, 21)
        .into_iter()
        .flatten()
        .collect();
    let (ax, ay) = in_degrees(&arrows);
    Series::line("", &ax, &ay, 7).styled(Style::Segments)
}

/// The stable and unstable manifolds of every saddle, the first saddle's
/// labelled.
fn separatrices(
    model: &VehicleModel,
    c: &Condition,
    bx: &SearchBox,
    eqs: &[Equilibrium],
) -> Vec<Series> {
    let mut series = Vec::new();
    for (k, branches) in phase::separatrices(model, c, bx, eqs).iter().enumerate() {
        for b in branches {
            let (color, name) = match b.manifold {
                Manifold::Stable => (1, "stable manifold (separatrix)"),
                Manifold::Unstable => (3, "unstable manifold"),
            };
            let label = if k == 0 && b.side < 0.0 { name } else { "" };
            let (tx, ty) = in_degrees(&b.points);
            series.push(Series::line(label, &tx, &ty, color));
        }
    }
    series
}

/// The equilibria in the box, marked by kind: stable, saddle, other unstable.
fn equilibrium_markers(eqs: &[Equilibrium], bx: &SearchBox) -> Vec<Series> {
    // Which kinds a marker shows, its label and its colour.
    type Marker = (fn(Kind) -> bool, &'static str, usize);
    let kinds: [Marker; 3] = [
        (|k| k.is_stable(), "stable equilibrium", 2),
        (|k| k == Kind::Saddle, "saddle", 1),
        (
            |k| !k.is_stable() && k != Kind::Saddle,
            "unstable equilibrium",
            4,
        ),
    ];
    kinds
        .into_iter()
        .filter_map(|(kind_ok, label, color)| {
            let pts: Vec<[f64; 2]> = eqs
                .iter()
                .filter(|e| kind_ok(e.stability.kind) && bx.contains([e.beta, e.yaw_rate]))
                .map(|e| [e.beta, e.yaw_rate])
                .collect();
            (!pts.is_empty()).then(|| {
                let (px, py) = in_degrees(&pts);
                Series::line(label, &px, &py, color).styled(Style::Points(7))
            })
        })
        .collect()
}

/// Stability map over two swept axes (the third at its first value).
pub fn stability_map(
    res: &SweepResult,
    ax: Axis,
    ay: Axis,
    bx: &SearchBox,
    path: &Path,
) -> Result<(), Error> {
    let cats: [(&str, usize); 4] = [
        ("no equilibrium in the box", 7),
        ("stable only", 2),
        ("stable and saddles", 0),
        ("no stable equilibrium", 1),
    ];
    let mut pts: Vec<Vec<(f64, f64)>> = vec![Vec::new(); 4];
    let first = res.points[0].condition;
    let others: Vec<Axis> = [Axis::Steer, Axis::Friction, Axis::Speed]
        .into_iter()
        .filter(|a| *a != ax && *a != ay)
        .collect();
    for p in &res.points {
        if others
            .iter()
            .any(|o| (o.get(&p.condition) - o.get(&first)).abs() > 1e-12)
        {
            continue;
        }
        let e = in_box(&p.exact, bx);
        let stable = e.iter().filter(|q| q.stability.kind.is_stable()).count();
        let saddles = e
            .iter()
            .filter(|q| q.stability.kind == Kind::Saddle)
            .count();
        let cat = match (e.len(), stable, saddles) {
            (0, _, _) => 0,
            (_, s, 0) if s > 0 => 1,
            (_, s, _) if s > 0 => 2,
            _ => 3,
        };
        pts[cat].push((
            display(ax, ax.get(&p.condition)),
            display(ay, ay.get(&p.condition)),
        ));
    }
    let step = |a: Axis| {
        let v = res.grid.values(a);
        v.windows(2)
            .map(|w| display(a, w[1]) - display(a, w[0]))
            .fold(f64::INFINITY, f64::min)
    };
    let (dx, dy) = (step(ax), step(ay));
    let series = cats
        .iter()
        .zip(&pts)
        .filter(|(_, p)| !p.is_empty())
        .map(|((label, color), p)| {
            let (x, y): (Vec<f64>, Vec<f64>) = p.iter().copied().unzip();
            Series::line(label, &x, &y, *color).styled(Style::Cells(dx, dy))
        })
        .collect();
    let panel = Panel {
        title: "stability map (equilibria in the search box)".into(),
        x_label: axis_label(ax).into(),
        y_label: axis_label(ay).into(),
        series,
        ..Panel::default()
    };
    Figure {
        panels: vec![panel],
        columns: 1,
        width: 900,
        row_height: 700,
    }
    .save(path)
}
