//! Which points of a sweep belong to one branch, for drawing branches as
//! lines: the points at each value of the swept parameter form a column, and
//! points of neighbouring columns are linked by nearest-neighbour matching
//! in the (scaled) state, closest pairs first, each point linked at most
//! once to each side, never across a gap. The number of points may change
//! from one column to the next (a branch leaves the plotted box, or two
//! meet at a fold): the points left over end their branch, and a fold is
//! joined to the two branch ends nearest to it. Distances are in whatever
//! scaled units the caller gives the states in (the equilibria figures use
//! fractions of the search box).

/// A point: its column and its index in the column.
pub type At = (usize, usize);

fn distance(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The links between points of neighbouring columns: each (point in column
/// i, point in column i + 1), matched closest first, at most one link per
/// point and side, none longer than `gap`.
pub fn link(columns: &[Vec<[f64; 2]>], gap: f64) -> Vec<(At, At)> {
    let mut links = Vec::new();
    for (i, w) in columns.windows(2).enumerate() {
        let mut pairs: Vec<(f64, usize, usize)> = w[0]
            .iter()
            .enumerate()
            .flat_map(|(a, &p)| {
                w[1].iter()
                    .enumerate()
                    .map(move |(b, &q)| (distance(p, q), a, b))
            })
            .filter(|(d, _, _)| *d <= gap)
            .collect();
        pairs.sort_by(|x, y| x.0.total_cmp(&y.0));
        let (mut left, mut right) = (vec![false; w[0].len()], vec![false; w[1].len()]);
        for (_, a, b) in pairs {
            if !left[a] && !right[b] {
                left[a] = true;
                right[b] = true;
                links.push(((i, a), (i + 1, b)));
            }
        }
    }
    links
}

/// The branch ends a fold at `at`, located between columns `i` and `i + 1`,
/// joins: of the points of column `i` with no link forward and those of
/// column `i + 1` with no link back, the two nearest to `at` within `gap`
/// (the saddle and the node that meet there).
pub fn fold_ends(
    columns: &[Vec<[f64; 2]>],
    links: &[(At, At)],
    i: usize,
    at: [f64; 2],
    gap: f64,
) -> Vec<At> {
    let mut ends: Vec<(f64, At)> = Vec::new();
    for col in [i, i + 1] {
        let Some(points) = columns.get(col) else {
            continue;
        };
        for (k, &p) in points.iter().enumerate() {
            // Linked across the fold already: forward from column i, back
            // from column i + 1.
            let across = links
                .iter()
                .any(|l| (l.0 .0 == i) && (l.0 == (col, k) || l.1 == (col, k)));
            let d = distance(p, at);
            if !across && d <= gap {
                ends.push((d, (col, k)));
            }
        }
    }
    ends.sort_by(|x, y| x.0.total_cmp(&y.0));
    ends.into_iter().take(2).map(|e| e.1).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_of_one_branch_are_linked_when_the_count_changes() {
        // Four points, then two, then three: two branches meet at a fold
        // between the first two columns, a third enters the box at the last.
        let columns = vec![
            vec![[0.05, 0.3], [0.45, -0.8], [-0.2, 0.85], [-0.55, 0.9]],
            vec![[0.04, 0.35], [0.4, -0.65]],
            vec![[0.9, -0.5], [0.38, -0.55], [0.02, 0.4]],
        ];
        let mut links = link(&columns, 0.35);
        links.sort();
        assert_eq!(
            links,
            [
                ((0, 0), (1, 0)),
                ((0, 1), (1, 1)),
                ((1, 0), (2, 2)),
                ((1, 1), (2, 1)),
            ]
        );
        // The fold between the first two columns joins the two ends left.
        let mut ends = fold_ends(&columns, &links, 0, [-0.4, 0.8], 0.5);
        ends.sort();
        assert_eq!(ends, [(0, 2), (0, 3)]);
        // The branch that entered the box joins nothing.
        assert!(links.iter().all(|l| l.1 != (2, 0)));
    }

    #[test]
    fn a_gap_breaks_a_branch_and_each_point_links_once() {
        // The nearest point is past the gap: no link.
        assert!(link(&[vec![[0.0, 0.0]], vec![[0.5, 0.0]]], 0.35).is_empty());
        // Two points near one: the nearer is linked, the other ends.
        let links = link(&[vec![[0.0, 0.0], [0.1, 0.0]], vec![[0.08, 0.0]]], 0.35);
        assert_eq!(links, [((0, 1), (1, 0))]);
        // A fold never takes an end already linked across it.
        let cols = vec![vec![[0.0, 0.0]], vec![[0.01, 0.0]]];
        let l = link(&cols, 0.35);
        assert!(fold_ends(&cols, &l, 0, [0.0, 0.0], 0.5).is_empty());
    }
}
