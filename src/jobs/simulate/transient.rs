//! A step steer's `response.png` over its transient: where the run is far
//! longer than the response takes to settle (a 600 s step drew its whole
//! response in one pixel column), the time axis is limited to the step's
//! transient, from before the step to a few settling times after it, and
//! the first panel's title says what part of the run is shown.

use crate::report::plot::Figure;
use crate::sim::TimeHistory;

/// The band about its final value within which a response has settled, as
/// a share of its change (the 2 % of a settling time).
const SETTLED: f64 = 0.02;

/// Settling times shown after the step; as many before it as one.
const SHOWN_AFTER: f64 = 3.0;

/// The least time shown for the settling, s: a response settled within a
/// few samples still shows its rise.
const MIN_SETTLING: f64 = 0.5;

/// The share of the run beyond which the window is not taken: a run no
/// more than twice its transient draws it legibly whole.
const WHOLE_RUN: f64 = 0.5;

/// The part of the run `h` a figure shows for a step at `step` (s): the
/// window (from, to) and when the response settled, s; `None` where the
/// whole run is legible (or the response never settles).
pub(super) fn transient_window(h: &TimeHistory, step: f64) -> Option<(f64, f64, f64)> {
    let (first, last) = (*h.t.first()?, *h.t.last()?);
    let at_step =
        h.t.partition_point(|&t| t < step)
            .min(h.len().checked_sub(1)?);
    let settles = [&h.yaw_rate, &h.ay, &h.beta]
        .into_iter()
        .filter_map(|x| {
            let (initial, end) = (x[at_step], *x.last()?);
            let band = SETTLED * (end - initial).abs();
            (band > 0.0).then(|| {
                x.iter()
                    .rposition(|v| (v - end).abs() > band)
                    .map_or(first, |i| h.t[(i + 1).min(h.len() - 1)])
            })
        })
        .fold(step, f64::max);
    let settling = (settles - step).max(MIN_SETTLING);
    let (from, to) = ((step - settling).max(first), step + SHOWN_AFTER * settling);
    (to - from < WHOLE_RUN * (last - first)).then_some((from, to, settles))
}

/// Limits every panel of `fig` (drawn from `h`) to the transient of the
/// step at `step` (s), where [`transient_window`] takes one: each series
/// cut to it (so that the points a long record is thinned to fall in it),
/// and the run's length said in the first panel's title.
pub(super) fn focus(fig: &mut Figure, h: &TimeHistory, step: f64) {
    let Some((from, to, settles)) = transient_window(h, step) else {
        return;
    };
    for panel in &mut fig.panels {
        panel.x_range = Some((from, to));
        for s in &mut panel.series {
            let keep: Vec<usize> = (0..s.x.len())
                .filter(|&i| (from..=to).contains(&s.x[i]))
                .collect();
            s.y = keep.iter().map(|&i| s.y[i]).collect();
            s.x = keep.iter().map(|&i| s.x[i]).collect();
        }
    }
    let length = h.t[h.len() - 1] - h.t[0];
    if let Some(p) = fig.panels.first_mut() {
        p.title = format!(
            "{}: t = {}–{} s of the {} s run (settled within 2 % by {} s)",
            p.title,
            crate::format::rounded(from, 3),
            crate::format::rounded(to, 3),
            crate::format::rounded(length, 3),
            crate::format::rounded(settles, 3)
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    /// A 600 s run of a step at 1 s whose response settles in about 1.2 s
    /// (rows every 0.01 s): yaw rate, ay and sideslip rising as
    /// `1 − e^(−(t−1)/0.3)`.
    fn long_step() -> TimeHistory {
        let t: Vec<f64> = (0..=60_000).map(|i| 0.01 * f64::from(i)).collect();
        let rise = |t: &f64| match *t > 1.0 {
            true => 1.0 - (-(t - 1.0) / 0.3).exp(),
            false => 0.0,
        };
        let shape: Vec<f64> = t.iter().map(rise).collect();
        TimeHistory {
            steer: t
                .iter()
                .map(|t| 0.0175 * (10.0 * (t - 1.0)).clamp(0.0, 1.0))
                .collect(),
            speed: vec![22.0; t.len()],
            yaw_rate: shape.iter().map(|s| 0.065 * s).collect(),
            ay: shape.iter().map(|s| 1.43 * s).collect(),
            beta: shape.iter().map(|s| -0.01 * s).collect(),
            t,
            ..TimeHistory::default()
        }
    }

    /// The (x, y) points, px, of every polyline of an SVG with more than
    /// `min` points (the data's lines, not the axes').
    fn polylines(svg: &str, min: usize) -> Vec<Vec<(f64, f64)>> {
        svg.split("<polyline ")
            .skip(1)
            .filter_map(|e| {
                let points = e.split("points=\"").nth(1)?.split('"').next()?;
                let p: Vec<(f64, f64)> = points
                    .split_whitespace()
                    .filter_map(|xy| {
                        let (x, y) = xy.split_once(',')?;
                        Some((x.parse().ok()?, y.parse().ok()?))
                    })
                    .collect();
                (p.len() > min).then_some(p)
            })
            .collect()
    }

    /// The yaw rate's transient (from the first point off its initial
    /// height to the last point outside 2 % of its change from its final
    /// one) spans a fifth or more of its line's width: in the whole 600 s
    /// run it spanned 0.2 % of it, a pixel or two.
    #[test]
    fn a_long_step_runs_figure_shows_its_transient_across_the_axis() {
        let h = long_step();
        let mut fig = super::super::history_figure("long", &h, None);
        focus(&mut fig, &h, 1.0);
        let svg = fig.svg(Path::new("response.svg")).unwrap();
        let lines = polylines(&svg, 50);
        assert_eq!(lines.len(), 4, "steer, yaw rate, ay, sideslip");
        let r = &lines[1];
        let (y0, y1) = (r[0].1, r[r.len() - 1].1);
        let band = 0.02 * (y1 - y0).abs();
        let onset = r.iter().find(|p| (p.1 - y0).abs() > band).unwrap().0;
        let settled = r.iter().rev().find(|p| (p.1 - y1).abs() > band).unwrap().0;
        let width = r[r.len() - 1].0 - r[0].0;
        let share = (settled - onset) / width;
        assert!(share > 0.2, "the transient spans {share} of the axis");
        assert!(
            svg.contains("t = 0–4.54 s of the 600 s run (settled within 2 % by 2.18 s)"),
            "the title says the part of the run shown: {}",
            svg.split("<text")
                .filter(|t| t.contains("run"))
                .collect::<Vec<_>>()
                .join("\n")
        );
    }

    /// A run twice its transient or shorter is drawn whole.
    #[test]
    fn a_run_close_to_its_transient_is_drawn_whole() {
        let mut h = long_step();
        let n = 601;
        for x in [
            &mut h.t,
            &mut h.steer,
            &mut h.speed,
            &mut h.yaw_rate,
            &mut h.ay,
            &mut h.beta,
        ] {
            x.truncate(n);
        }
        assert_eq!(transient_window(&h, 1.0), None);
        assert!(transient_window(&long_step(), 1.0).is_some());
    }
}
