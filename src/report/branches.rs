//! Which points of a sweep belong to one branch, for drawing branches as
//! lines: the points at each value of the swept parameter form a column, and
//! points of neighbouring columns are linked by nearest-neighbour matching
//! in the (scaled) state, closest pairs first, each point linked at most
//! once to each side, never across a gap. The number of points may change
//! from one column to the next (a branch leaves the plotted box, or two
//! meet at a fold): the points left over end their branch. A fold's pair
//! is chosen first — the two points nearest to it on the side that has
//! them — and cut from the matching, so that the nearest-neighbour rule
//! cannot link one of them past the fold to another branch (a branch moves
//! fast near a fold: the partner it dies with may look closer to the
//! surviving branch's next point than that branch's own last point); and a
//! link never joins a saddle to a node or focus where no eigenvalue crosses
//! zero (det J keeps its sign along a branch between bifurcations).
//! Distances are in whatever
//! scaled units the caller gives the states in (the equilibria figures use
//! fractions of the search box).

/// A point: its column and its index in the column.
pub type At = (usize, usize);

fn distance(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The links between points of neighbouring columns: each (point in column
/// i, point in column i + 1), matched closest first, at most one link per
/// point and side, none longer than `gap`, none that `allowed` refuses
/// (given the interval i and the two points), and none from a point of
/// `cut` — (interval i, point) — across its interval.
pub fn link(
    columns: &[Vec<[f64; 2]>],
    gap: f64,
    cut: &[(usize, At)],
    allowed: &dyn Fn(usize, At, At) -> bool,
) -> Vec<(At, At)> {
    let mut links = Vec::new();
    for (i, w) in columns.windows(2).enumerate() {
        let is_cut = |p: At| cut.contains(&(i, p));
        let mut pairs: Vec<(f64, usize, usize)> = w[0]
            .iter()
            .enumerate()
            .flat_map(|(a, &p)| {
                w[1].iter()
                    .enumerate()
                    .map(move |(b, &q)| (distance(p, q), a, b))
            })
            .filter(|&(d, a, b)| {
                d <= gap && !is_cut((i, a)) && !is_cut((i + 1, b)) && allowed(i, (i, a), (i + 1, b))
            })
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

/// The points of column `col` that end at a bifurcation at `at` where
/// `meet` equilibria meet (2 at a fold, 3 at a pitchfork): the `meet`
/// nearest to `at` within `gap`; at a pitchfork the middle one (in the
/// first coordinate) continues through it and is left out.
pub fn meeting(
    columns: &[Vec<[f64; 2]>],
    col: usize,
    at: [f64; 2],
    meet: usize,
    gap: f64,
) -> Vec<At> {
    let Some(points) = columns.get(col) else {
        return Vec::new();
    };
    let mut near: Vec<(f64, usize)> = points
        .iter()
        .enumerate()
        .map(|(k, &p)| (distance(p, at), k))
        .filter(|(d, _)| *d <= gap)
        .collect();
    near.sort_by(|x, y| x.0.total_cmp(&y.0));
    near.truncate(meet);
    if meet == 3 && near.len() == 3 {
        near.sort_by(|x, y| points[x.1][0].total_cmp(&points[y.1][0]));
        near.remove(1);
    }
    near.into_iter().map(|(_, k)| (col, k)).collect()
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
        let mut links = link(&columns, 0.35, &[], &|_, _, _| true);
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
        // The fold between the first two columns joins the two nearest.
        let mut ends = meeting(&columns, 0, [-0.4, 0.8], 2, 0.5);
        ends.sort();
        assert_eq!(ends, [(0, 2), (0, 3)]);
        // The branch that entered the box joins nothing.
        assert!(links.iter().all(|l| l.1 != (2, 0)));
    }

    #[test]
    fn a_gap_breaks_a_branch_and_each_point_links_once() {
        // The nearest point is past the gap: no link.
        assert!(link(
            &[vec![[0.0, 0.0]], vec![[0.5, 0.0]]],
            0.35,
            &[],
            &|_, _, _| true
        )
        .is_empty());
        // Two points near one: the nearer is linked, the other ends.
        let links = link(
            &[vec![[0.0, 0.0], [0.1, 0.0]], vec![[0.08, 0.0]]],
            0.35,
            &[],
            &|_, _, _| true,
        );
        assert_eq!(links, [((0, 1), (1, 0))]);
        // A point cut at its interval is not linked across it.
        let cols = vec![vec![[0.0, 0.0]], vec![[0.01, 0.0]]];
        assert!(link(&cols, 0.35, &[(0, (0, 0))], &|_, _, _| true).is_empty());
    }

    #[test]
    fn a_fold_pair_is_cut_before_the_survivor_is_linked() {
        // Li, Jia & Zhao's sedan at δ = 0.04 → 0.06 rad (box units): the
        // node, the saddle and the unstable focus; then one stable focus.
        // The saddle is nearest to it, but the saddle dies with the
        // unstable focus at the fold (−0.53, 0.83): the node goes on.
        let columns = vec![
            vec![[-0.072, 0.578], [-0.447, 0.832], [-0.706, 0.819]],
            vec![[-0.265, 0.824]],
        ];
        let pair = meeting(&columns, 0, [-0.529, 0.829], 2, 0.8);
        assert_eq!(pair, [(0, 1), (0, 2)]);
        let cut: Vec<(usize, At)> = pair.iter().map(|&p| (0, p)).collect();
        assert_eq!(
            link(&columns, 0.35, &[], &|_, _, _| true),
            [((0, 1), (1, 0))]
        );
        assert_eq!(
            link(&columns, 0.35, &cut, &|_, _, _| true),
            [((0, 0), (1, 0))]
        );
        // Three meet at a pitchfork: the middle one goes through.
        let cols = vec![vec![[-0.1, 0.0], [0.0, 0.0], [0.1, 0.0]]];
        assert_eq!(meeting(&cols, 0, [0.0, 0.0], 3, 0.5), [(0, 0), (0, 2)]);
    }
}
