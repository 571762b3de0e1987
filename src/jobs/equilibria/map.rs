//! The stability map of a sweep over two or more axes
//! (`stability_map.png`): a cell per point of the first two swept axes
//! (the third at its first value), coloured by the set of equilibria in
//! the search box there — how many are stable, saddles and unstable —
//! with the bifurcations located along the axes as grey discs.
//!
//! The set, not only whether a stable one exists: the compact sedan's
//! steer × speed sweep has a stable equilibrium at every point, with one
//! saddle on one side of its pitchfork curve and two on the other; a map
//! keyed to "stable beside saddles" was one colour everywhere and did not
//! show the pitchfork it marked. Each set present gets its own colour
//! (stable alone in blues, stable beside saddles or unstable ones in
//! orange, green, purple…, none stable in reds), the legend and the
//! terminal name each with its count of points, and a map of one set says
//! so. Angles in degrees, speeds in km/h, as the other figures.

use super::figures::{in_box, FOLD};
use super::slices::{axis_label, display, held_words};
use crate::equilibria::bifurcation::{Axis, Bifurcation};
use crate::equilibria::sweep::SweepResult;
use crate::equilibria::{Condition, Equilibrium, SearchBox};
use crate::error::Error;
use crate::report::plot::{Figure, Panel, Series, Style};
use crate::report::series::OLIVE;
use crate::report::stability::Class;
use std::collections::BTreeMap;
use std::path::Path;

/// The equilibria in the box at a point of the map, counted by class: the
/// point's colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(super) struct MapSet {
    /// Stable nodes and foci.
    pub stable: usize,
    /// Saddles.
    pub saddles: usize,
    /// Unstable nodes and foci, and degenerate points.
    pub unstable: usize,
}

impl MapSet {
    /// The set of equilibria `e`.
    fn of(e: &[Equilibrium]) -> Self {
        let count = |c: Class| e.iter().filter(|q| q.stability.kind.class() == c).count();
        Self {
            stable: e.iter().filter(|q| q.stability.kind.is_stable()).count(),
            saddles: count(Class::Saddle),
            unstable: count(Class::Unstable),
        }
    }

    /// In words: "1 stable + 2 saddles", "no equilibrium in the box".
    pub fn words(self) -> String {
        let parts: Vec<String> = [
            (self.stable, "stable", "stable"),
            (self.saddles, "saddle", "saddles"),
            (self.unstable, "unstable", "unstable"),
        ]
        .iter()
        .filter(|(n, ..)| *n > 0)
        .map(|&(n, one, many)| format!("{n} {}", if n == 1 { one } else { many }))
        .collect();
        match parts.is_empty() {
            true => "no equilibrium in the box".into(),
            false => parts.join(" + "),
        }
    }

    /// Its order in the key: sets with a stable equilibrium first (fewest
    /// others first), then those without one, then none at all.
    fn rank(self) -> (u8, Self) {
        let group = match (self.stable, self.saddles + self.unstable) {
            (0, 0) => 3,
            (0, _) => 2,
            (_, 0) => 0,
            _ => 1,
        };
        (group, self)
    }
}

/// The palette indices of each group of sets, in the order the sets of a
/// group take them: stable alone in blues, stable beside others in
/// colours apart from them, none stable in reds; no equilibrium grey.
fn colours(group: u8) -> &'static [usize] {
    match group {
        0 => &[0, 6, 8],
        1 => &[3, 2, 4, 9, OLIVE],
        2 => &[1, 5],
        _ => &[7],
    }
}

/// The map's cells: each set present, in the key's order, with its colour
/// and the points (display units) that have it.
pub(super) type Cells = Vec<(MapSet, usize, Vec<(f64, f64)>)>;

/// The points of the map over `ax` × `ay` (the other axis at its value in
/// the first point), by set of equilibria in the box `bx`.
pub(super) fn cells(res: &SweepResult, ax: Axis, ay: Axis, bx: &SearchBox) -> Cells {
    let first = res.points[0].condition;
    let mut by: BTreeMap<(u8, MapSet), Vec<(f64, f64)>> = BTreeMap::new();
    for p in res
        .points
        .iter()
        .filter(|p| on_map(&p.condition, &first, ax, ay))
    {
        let set = MapSet::of(&in_box(&p.exact, bx));
        by.entry(set.rank()).or_default().push((
            display(ax, ax.get(&p.condition)),
            display(ay, ay.get(&p.condition)),
        ));
    }
    let mut taken: BTreeMap<u8, usize> = BTreeMap::new();
    by.into_iter()
        .map(|((group, set), pts)| {
            let k = taken.entry(group).or_default();
            let palette = colours(group);
            let colour = palette[*k % palette.len()];
            *k += 1;
            (set, colour, pts)
        })
        .collect()
}

/// Whether `c` lies on the map over `ax` × `ay`: the third axis at its
/// value in `first`.
fn on_map(c: &Condition, first: &Condition, ax: Axis, ay: Axis) -> bool {
    [Axis::Steer, Axis::Friction, Axis::Speed]
        .into_iter()
        .filter(|&o| o != ax && o != ay)
        .all(|o| (o.get(c) - o.get(first)).abs() < 1e-12)
}

/// The terminal's words on the map's colours, after what it shows: each
/// set with its count of points, or that every point has the same one.
pub(super) fn colour_words(res: &SweepResult, bx: &SearchBox) -> String {
    let v = res.grid.varying();
    if v.len() < 2 || res.points.is_empty() {
        return String::new();
    }
    let cells = cells(res, v[0], v[1], bx);
    match &cells[..] {
        [(set, ..)] => format!(
            "; one colour: every point of it has the same equilibria in the box, {}",
            set.words()
        ),
        _ => {
            let sets: Vec<String> = cells
                .iter()
                .map(|(set, _, pts)| format!("{} ({})", set.words(), pts.len()))
                .collect();
            format!(
                "; coloured by the equilibria in the box at each point (points): {}",
                sets.join(", ")
            )
        }
    }
}

/// The bifurcations located along either axis of a stability map over
/// `axes` (the third, if any, at its value in `first`), as grey discs:
/// where a map's set of equilibria changes, or a Hopf point where it does
/// not.
fn map_bifurcations(res: &SweepResult, axes: (Axis, Axis), first: &Condition) -> Option<Series> {
    let (ax, ay) = axes;
    let on: Vec<&Bifurcation> = res
        .bifurcations
        .iter()
        .filter(|b| (b.axis == ax || b.axis == ay) && on_map(&b.at, first, ax, ay))
        .collect();
    (!on.is_empty()).then(|| {
        let x: Vec<f64> = on.iter().map(|b| display(ax, ax.get(&b.at))).collect();
        let y: Vec<f64> = on.iter().map(|b| display(ay, ay.get(&b.at))).collect();
        Series::line("bifurcations located", &x, &y, FOLD).styled(Style::Points(7))
    })
}

/// Stability map over two swept axes (the third at its first value), the
/// bifurcations along them marked.
pub fn stability_map(
    res: &SweepResult,
    ax: Axis,
    ay: Axis,
    bx: &SearchBox,
    path: &Path,
) -> Result<(), Error> {
    let step = |a: Axis| {
        let v = res.grid.values(a);
        v.windows(2)
            .map(|w| display(a, w[1]) - display(a, w[0]))
            .fold(f64::INFINITY, f64::min)
    };
    let (dx, dy) = (step(ax), step(ay));
    let mut series: Vec<Series> = cells(res, ax, ay, bx)
        .into_iter()
        .map(|(set, colour, p)| {
            let (x, y): (Vec<f64>, Vec<f64>) = p.iter().copied().unzip();
            let label = format!("{} ({})", set.words(), p.len());
            Series::line(&label, &x, &y, colour).styled(Style::Cells(dx, dy))
        })
        .collect();
    let first = res.points[0].condition;
    series.extend(map_bifurcations(res, (ax, ay), &first));
    let others = [Axis::Steer, Axis::Friction, Axis::Speed]
        .into_iter()
        .filter(|a| *a != ax && *a != ay);
    let panel = Panel {
        title: format!(
            "stability map: equilibria in the search box (points){}",
            others
                .map(|o| format!(", at {}", held_words(o, &first)))
                .collect::<String>()
        ),
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

#[cfg(test)]
mod tests {
    use super::*;

    fn set(stable: usize, saddles: usize, unstable: usize) -> MapSet {
        MapSet {
            stable,
            saddles,
            unstable,
        }
    }

    /// Sets are said by their counts, ordered stable-alone first and none
    /// last, and two sets beside a stable one take different colours (the
    /// sedan's 1 + 1 and 1 + 2 saddles were one colour).
    #[test]
    fn each_set_of_equilibria_is_said_and_coloured_apart() {
        assert_eq!(set(1, 2, 0).words(), "1 stable + 2 saddles");
        assert_eq!(set(0, 1, 1).words(), "1 saddle + 1 unstable");
        assert_eq!(set(0, 0, 0).words(), "no equilibrium in the box");
        let mut sets = [
            set(0, 0, 0),
            set(1, 2, 0),
            set(0, 1, 0),
            set(1, 1, 0),
            set(1, 0, 0),
        ];
        sets.sort_by_key(|s| s.rank());
        assert_eq!(
            sets,
            [
                set(1, 0, 0),
                set(1, 1, 0),
                set(1, 2, 0),
                set(0, 1, 0),
                set(0, 0, 0)
            ]
        );
        let all: Vec<usize> = (0..4).flat_map(|g| colours(g).to_vec()).collect();
        let mut unique = all.clone();
        unique.sort_unstable();
        unique.dedup();
        assert_eq!(unique.len(), all.len(), "{all:?}");
    }
}
