//! Where the cells of a map lie: each cell centred on its grid node and
//! reaching halfway to its neighbours, the outer cells as far out again
//! (half their step beyond the outer node), so that the edge cells are as
//! wide as the inner ones; and the plotted range of a panel, which for a
//! map is exactly the outer cells' edges (no margin that would clip them).

use super::series::{Series, Style};

/// The edges of the cells centred on `nodes` along one axis: the sorted
/// distinct nodes, each with its cell's (low, high) edge. A lone node gets
/// a cell `fallback` wide.
pub fn edges(nodes: &[f64], fallback: f64) -> Vec<(f64, f64, f64)> {
    let mut n: Vec<f64> = nodes.iter().copied().filter(|v| v.is_finite()).collect();
    n.sort_by(f64::total_cmp);
    n.dedup();
    (0..n.len())
        .map(|i| {
            let below = if i > 0 { n[i] - n[i - 1] } else { f64::NAN };
            let above = if i + 1 < n.len() {
                n[i + 1] - n[i]
            } else {
                f64::NAN
            };
            // The outer half-cell mirrors the inner one.
            let lo = if below.is_finite() { below } else { above };
            let hi = if above.is_finite() { above } else { below };
            let (lo, hi) = if lo.is_finite() {
                (lo, hi)
            } else {
                (fallback, fallback)
            };
            (n[i], n[i] - 0.5 * lo, n[i] + 0.5 * hi)
        })
        .collect()
}

/// The (low, high) edge of the cell of `v` among `edges` (from [`edges`]).
pub fn cell_of(edges: &[(f64, f64, f64)], v: f64, fallback: f64) -> (f64, f64) {
    match edges.binary_search_by(|e| e.0.total_cmp(&v)) {
        Ok(i) => (edges[i].1, edges[i].2),
        Err(_) => (v - 0.5 * fallback, v + 0.5 * fallback),
    }
}

/// The rectangles ((x0, y0), (x1, y1)) of the cells of a `Cells` or `Heat`
/// series, in the order of its points; none for another style.
pub fn rectangles(s: &Series) -> Vec<[(f64, f64); 2]> {
    let (dx, dy) = match s.style {
        Style::Cells(dx, dy) | Style::Heat(dx, dy) => (dx, dy),
        _ => return Vec::new(),
    };
    let (ex, ey) = (edges(&s.x, dx), edges(&s.y, dy));
    s.x.iter()
        .zip(&s.y)
        .map(|(&x, &y)| {
            let (x0, x1) = cell_of(&ex, x, dx);
            let (y0, y1) = cell_of(&ey, y, dy);
            [(x0, y0), (x1, y1)]
        })
        .collect()
}

/// Finite min/max with a margin of 5 %; a flat range is widened.
pub fn padded(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let pad = if hi > lo {
        0.05 * (hi - lo)
    } else {
        lo.abs().max(1.0) * 0.05
    };
    (lo - pad, hi + pad)
}

/// The default (x, y) ranges of a panel's series: for a panel with a map,
/// the map's outer cell edges (widened only to take in points beyond
/// them); otherwise the data's, with a margin.
pub fn ranges(series: &[Series]) -> ((f64, f64), (f64, f64)) {
    let cells: Vec<[(f64, f64); 2]> = series.iter().flat_map(rectangles).collect();
    if cells.is_empty() {
        return (
            padded(series.iter().flat_map(|s| s.x.iter().copied())),
            padded(series.iter().flat_map(|s| s.y.iter().copied())),
        );
    }
    let span = |axis: usize| {
        let corners = cells.iter().map(|c| {
            if axis == 0 {
                (c[0].0, c[1].0)
            } else {
                (c[0].1, c[1].1)
            }
        });
        let others = series
            .iter()
            .filter(|s| rectangles(s).is_empty())
            .flat_map(|s| if axis == 0 { &s.x } else { &s.y }.iter().map(|&v| (v, v)));
        corners
            .chain(others)
            .filter(|(a, b)| a.is_finite() && b.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), (a, b)| {
                (lo.min(a), hi.max(b))
            })
    };
    (span(0), span(1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edge_cells_are_as_wide_as_inner_ones_and_fill_the_panel() {
        let e = edges(&[2.0, 0.0, 1.0, 3.0, 1.0], 9.0);
        assert_eq!(
            e,
            [
                (0.0, -0.5, 0.5),
                (1.0, 0.5, 1.5),
                (2.0, 1.5, 2.5),
                (3.0, 2.5, 3.5)
            ]
        );
        assert_eq!(edges(&[4.0], 2.0), [(4.0, 3.0, 5.0)]);
        // A 5 × 3 map over nodes 0..4 × 10, 20, 30: the panel is the cells'
        // outer edges, so the edge cells are drawn whole.
        let (mut x, mut y) = (Vec::new(), Vec::new());
        for i in 0..5 {
            for j in 1..=3 {
                x.push(f64::from(i));
                y.push(f64::from(10 * j));
            }
        }
        let heat = Series::heat(&x, &y, vec![1.0; 15], (1.0, 10.0), "v");
        let curve = Series::line("curve", &[1.0, 2.0], &[15.0, 25.0], 1);
        assert_eq!(ranges(&[heat.clone(), curve]), ((-0.5, 4.5), (5.0, 35.0)));
        let r = rectangles(&heat);
        let width = |c: &[(f64, f64); 2]| (c[1].0 - c[0].0, c[1].1 - c[0].1);
        assert!(r.iter().all(|c| width(c) == (1.0, 10.0)), "{r:?}");
        // A point beyond the map widens the range to take it in.
        let far = Series::line("far", &[6.0], &[20.0], 1);
        assert_eq!(ranges(&[heat, far]).0, (-0.5, 6.0));
        // Without a map: the data's range with a margin, as before.
        let line = Series::line("l", &[0.0, 10.0], &[0.0, 1.0], 0);
        assert_eq!(ranges(&[line]).0, (-0.5, 10.5));
    }
}
