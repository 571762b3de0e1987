//! Which branch diagrams a sweep draws, and their names. A branch diagram
//! is drawn along one swept axis with the others held; a sweep of two or
//! three axes has one line along that axis per value (or pair of values)
//! of the others, and draws one diagram per line, named by the values it
//! holds (`branches_steer_speed_60kmh.png`): a 2-D sweep drew the first
//! speed only, where none of its bifurcations were. Past [`MAX_DIAGRAMS`]
//! lines the diagrams are drawn at evenly spread lines, the first and the
//! last among them, and the terminal says so. Values are named in the
//! figures' units: steer in degrees, speed in km/h, friction as a scale.

use crate::equilibria::bifurcation::Axis;
use crate::equilibria::sweep::{axis_lines, Grid};
use crate::equilibria::Condition;
use crate::format::{carried, plural};

/// The most branch diagrams drawn along one axis: beyond it a folder of
/// figures is no longer read one by one.
pub(super) const MAX_DIAGRAMS: usize = 20;

/// A parameter in display units: degrees, the friction scale, km/h.
pub(super) fn display(axis: Axis, v: f64) -> f64 {
    match axis {
        Axis::Steer => v.to_degrees(),
        Axis::Friction => v,
        Axis::Speed => v * 3.6,
    }
}

/// An axis's label on a figure, with its display unit.
pub(super) fn axis_label(axis: Axis) -> &'static str {
    match axis {
        Axis::Steer => "steer δ [deg]",
        Axis::Friction => "friction μ [-]",
        Axis::Speed => "speed u [km/h]",
    }
}

/// An axis's display unit in words and in a file name.
fn unit(axis: Axis) -> (&'static str, &'static str) {
    match axis {
        Axis::Steer => (" deg", "deg"),
        Axis::Friction => ("", ""),
        Axis::Speed => (" km/h", "kmh"),
    }
}

/// The value of `axis` at `c` in words, in display units: "speed 60 km/h".
pub(super) fn held_words(axis: Axis, c: &Condition) -> String {
    let v = carried(display(axis, axis.get(c)), 6);
    format!("{} {v}{}", axis.name(), unit(axis).0)
}

/// One branch diagram: the line it draws and what it holds.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Diagram {
    /// The axis along which it is drawn.
    pub axis: Axis,
    /// The grid indices of its line, in order along `axis`.
    pub line: Vec<usize>,
    /// Its files' name without extension: `branches_<axis>`, with the held
    /// values of the other swept axes where there are any.
    pub stem: String,
    /// The held values of the other swept axes in words ("speed 60
    /// km/h"); empty for a one-axis sweep.
    pub held: String,
}

/// The condition of grid index `i` (steer fastest).
fn condition(grid: &Grid, i: usize) -> Condition {
    let (ns, nf) = (grid.steer.len(), grid.friction.len());
    Condition {
        steer: grid.steer[i % ns],
        friction: grid.friction[(i / ns) % nf],
        speed: grid.speed[i / (ns * nf)],
    }
}

/// The other swept axes than `axis`.
fn others(grid: &Grid, axis: Axis) -> Vec<Axis> {
    grid.varying().into_iter().filter(|&a| a != axis).collect()
}

/// The diagrams drawn along `axis` and the number of lines along it: one
/// per line, or [`MAX_DIAGRAMS`] evenly spread from the first line to the
/// last.
pub(super) fn diagrams(grid: &Grid, axis: Axis) -> (Vec<Diagram>, usize) {
    let lines = axis_lines(grid, axis);
    let n = lines.len();
    let chosen: Vec<usize> = if n <= MAX_DIAGRAMS {
        (0..n).collect()
    } else {
        let last = (n - 1) as f64;
        let k = (MAX_DIAGRAMS - 1) as f64;
        (0..MAX_DIAGRAMS)
            .map(|j| (j as f64 * last / k).round() as usize)
            .collect()
    };
    let others = others(grid, axis);
    let mut out: Vec<Diagram> = chosen
        .into_iter()
        .map(|l| {
            let c = condition(grid, lines[l][0]);
            let value = |a: Axis| carried(display(a, a.get(&c)), 6);
            let stem: String = std::iter::once(format!("branches_{}", axis.name()))
                .chain(
                    others
                        .iter()
                        .map(|&a| format!("{}_{}{}", a.name(), value(a), unit(a).1)),
                )
                .collect::<Vec<_>>()
                .join("_");
            let held: Vec<String> = others.iter().map(|&a| held_words(a, &c)).collect();
            Diagram {
                axis,
                line: lines[l].clone(),
                stem,
                held: held.join(", "),
            }
        })
        .collect();
    // Values that six digits do not tell apart keep their line's number.
    for k in 0..out.len() {
        if out.iter().filter(|d| d.stem == out[k].stem).count() > 1 {
            out[k].stem = format!("{}_line{}", out[k].stem, k + 1);
        }
    }
    (out, n)
}

/// The title's tail of a diagram: ", at speed 60 km/h (2 of 4)"; empty
/// for a one-axis sweep.
pub(super) fn title_tail(d: &Diagram, k: usize, lines: usize) -> String {
    match d.held.is_empty() {
        true => String::new(),
        false => format!(", at {} ({} of {lines})", d.held, k + 1),
    }
}

/// The terminal's lines on the figures of a sweep of two or more axes:
/// which files hold the branch diagrams along each axis, and what the
/// stability map shows, its `colours` in words after it
/// (`super::map::colour_words`). Nothing for a one-axis sweep (its one
/// diagram is `branches_<axis>.png`).
pub(super) fn figure_lines(grid: &Grid, colours: &str) -> Vec<String> {
    let varying = grid.varying();
    if varying.len() < 2 {
        return Vec::new();
    }
    let mut out = Vec::new();
    for &axis in &varying {
        let (ds, n) = diagrams(grid, axis);
        let names: Vec<&str> = others(grid, axis).iter().map(|a| a.name()).collect();
        let per = match names.len() {
            1 => names[0].to_string(),
            _ => format!("({}) pair", names.join(", ")),
        };
        let (first, last) = (&ds[0].stem, &ds[ds.len() - 1].stem);
        let which = match ds.len() == n {
            true => format!("one per {per} ({})", plural(n, "figure", "figures")),
            false => format!(
                "at {} of the {n} {per}s, evenly spread from the first to the last (the others are not drawn)",
                ds.len()
            ),
        };
        out.push(format!(
            "  branch diagrams along {}, {which}: {first}.png … {last}.png, each with its .csv",
            axis.name()
        ));
    }
    out.push(format!("  stability_map.png: {}{colours}", map_words(grid)));
    out
}

/// What the stability map shows: its two axes, the third held at its
/// first value where it varies too.
pub(super) fn map_words(grid: &Grid) -> String {
    let v = grid.varying();
    let mut words = format!(
        "{} × {}, every swept value, bifurcations along them marked",
        v[0].name(),
        v[1].name()
    );
    if let Some(&third) = v.get(2) {
        let c = condition(grid, 0);
        words.push_str(&format!(
            "; at {} (the first of {})",
            held_words(third, &c),
            grid.values(third).len()
        ));
    }
    words
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(steer: usize, speed: usize) -> Grid {
        Grid {
            steer: (0..steer).map(|k| 0.02 * k as f64).collect(),
            friction: vec![0.8],
            speed: (1..=speed).map(|k| 30.0 * k as f64 / 3.6).collect(),
        }
    }

    /// A two-axis sweep draws one diagram per value of the other axis,
    /// named by it (round 27: only the first speed was drawn); a one-axis
    /// sweep's one diagram keeps its plain name.
    #[test]
    fn a_two_axis_sweep_draws_a_diagram_per_value_of_the_other_axis() {
        let g = grid(11, 4);
        let (ds, n) = diagrams(&g, Axis::Steer);
        assert_eq!(n, 4);
        let stems: Vec<&str> = ds.iter().map(|d| d.stem.as_str()).collect();
        assert_eq!(
            stems,
            [
                "branches_steer_speed_30kmh",
                "branches_steer_speed_60kmh",
                "branches_steer_speed_90kmh",
                "branches_steer_speed_120kmh"
            ]
        );
        assert_eq!(title_tail(&ds[1], 1, n), ", at speed 60 km/h (2 of 4)");
        let (along_speed, n) = diagrams(&g, Axis::Speed);
        assert_eq!(n, 11);
        assert_eq!(along_speed[1].stem, "branches_speed_steer_1.14592deg");
        for (d, s) in along_speed.iter().zip(&g.steer) {
            assert_eq!(condition(&g, d.line[0]).steer, *s);
        }
        let (one, n) = diagrams(&grid(11, 1), Axis::Steer);
        assert_eq!(
            (one.len(), n, one[0].stem.as_str()),
            (1, 1, "branches_steer")
        );
        assert_eq!(title_tail(&one[0], 0, 1), "");
    }

    /// Past the cap the diagrams are spread from the first line to the
    /// last, and the terminal says how many of how many.
    #[test]
    fn past_the_cap_the_diagrams_are_spread_and_said() {
        let g = grid(3, 41);
        let (ds, n) = diagrams(&g, Axis::Steer);
        assert_eq!((ds.len(), n), (MAX_DIAGRAMS, 41));
        assert_eq!(ds[0].line, axis_lines(&g, Axis::Steer)[0]);
        assert_eq!(ds[MAX_DIAGRAMS - 1].line, axis_lines(&g, Axis::Steer)[40]);
        let lines = figure_lines(&g, "");
        assert!(
            lines[0].contains("at 20 of the 41 speeds, evenly spread"),
            "{lines:?}"
        );
        assert!(lines[1].contains("one per steer (3 figures)"), "{lines:?}");
    }
}
