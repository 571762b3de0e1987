//! `diagnose`'s gap map (`gap_map.png`, and on the page): held-out RMS over
//! the noise floor against the time window, the |ay| level and the speed
//! band, with the base model and with the verdict's effects. Units: each
//! channel's RMS in noise floors (dimensionless); time in s, |ay| in m/s²,
//! speed in m/s.

use crate::diagnose::effects::{joined, EffectKind};
use crate::diagnose::model::channels::Channel;
use crate::diagnose::pipeline::{Diagnosis, PartAxis};
use crate::diagnose::report::GapFinding;
use crate::report::plot::{Figure, Marker, Panel, Series, Shape, Style};
/// The gap map: held-out RMS over the noise floor against the time window,
/// the |ay| level and the speed band, with the base model and with the
/// verdict's effects ([`gap_figure`]), each part at its samples' mean
/// level and each run's share of it at the run's own.
pub(super) fn gap_map(d: &Diagnosis) -> Figure {
    let without_ay = d
        .gap
        .findings
        .iter()
        .any(|f| matches!(f, GapFinding::WithoutAy { .. }));
    let points: Vec<GapPoint> = d
        .shrinkage
        .iter()
        .filter_map(|s| {
            let (axis, x) = (s.part.axis()?, s.mean_level?);
            let nf = s.noise_floor;
            let runs = s
                .runs
                .iter()
                .filter_map(|r| Some((r.mean_level?, r.before / nf)))
                .collect();
            (nf > 0.0).then_some(GapPoint {
                channel: s.channel,
                axis,
                x,
                before: s.before / nf,
                after: s.after / nf,
                runs,
            })
        })
        .collect();
    gap_figure(d.verdict.effects(), &points, without_ay)
}

/// One point of the gap map: a channel's held-out RMS over its noise floor
/// in one part of the data, before and after the verdict's effects, and
/// each run's share of it with the base model.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct GapPoint {
    pub(super) channel: Channel,
    pub(super) axis: PartAxis,
    /// The part's samples' mean level on its axis (s, m/s² or m/s).
    pub(super) x: f64,
    pub(super) before: f64,
    pub(super) after: f64,
    /// Each run's (mean level, base model's RMS over the noise floor) in
    /// the part.
    pub(super) runs: Vec<(f64, f64)>,
}

/// Width of the gap map, px: printed at a report's text width (170 mm) its
/// labels are ~10 pt ([`Figure::printed_label_points`]).
const GAP_MAP_WIDTH: u32 = 640;

/// One channel's series on one axis of the gap map: the parts pooled with
/// the base model (dotted, rings) and with the verdict's `effects` (solid,
/// discs), then each run's share with the base model (small dots, keyed
/// apart from the verdict's discs). `pts` sorted by level.
fn channel_series(
    ch: Channel,
    colour: usize,
    pts: &[&GapPoint],
    effects: &[EffectKind],
) -> Vec<Series> {
    let axis = pts[0].axis;
    let x: Vec<f64> = pts.iter().map(|p| p.x).collect();
    let before: Vec<f64> = pts.iter().map(|p| p.before).collect();
    let after: Vec<f64> = pts.iter().map(|p| p.after).collect();
    let (run_x, run_y): (Vec<f64>, Vec<f64>) =
        pts.iter().flat_map(|p| p.runs.iter().copied()).unzip();
    let name = symbol(ch);
    // The time windows are four pools of unequal, open-ended
    // spans: a line between them would draw a time history that
    // is not there, so they are points; the |ay| and speed bands
    // are a profile over a continuous level, joined.
    let (base_style, after_style) = match axis {
        PartAxis::Time => (Style::Points(4), Style::Points(4)),
        PartAxis::Ay | PartAxis::Speed => (Style::Dotted, Style::Line),
    };
    let mut out = vec![
        Series::line(&format!("{name}, base model"), &x, &before, colour)
            .styled(base_style)
            .marked(Marker {
                shape: Shape::Ring,
                size: 4,
            }),
    ];
    if !effects.is_empty() {
        out.push(
            Series::line(
                &format!("{name}, with {}", joined(effects, " + ")),
                &x,
                &after,
                colour,
            )
            .styled(after_style)
            .marked(Marker {
                shape: Shape::Disc,
                size: 4,
            }),
        );
    }
    // Over the pooled marks: a run whose level is the pool's shows as a
    // dot inside its ring. Keyed, so that a run's small dot is not read as
    // the verdict's disc.
    out.push(
        Series::line(
            &format!("{name}, each run, base model"),
            &run_x,
            &run_y,
            colour,
        )
        .styled(Style::Points(2)),
    );
    out
}

/// The gap map for print: a panel per axis (time window, |ay| level, speed
/// band), one column, the three channels in each (the ratio to the noise
/// floor is one scale for all), a colour per channel — the base model
/// dotted with rings, with the verdict's effects solid with discs, each
/// part at its samples' mean level, and each run's share as a dot at its
/// own — and 3 × the noise floor dashed. `without_ay`: some run has
/// no `ay`, its |ay| levels are u·r's, and the axis says so.
pub(super) fn gap_figure(effects: &[EffectKind], points: &[GapPoint], without_ay: bool) -> Figure {
    let mut panels = Vec::new();
    for axis in PartAxis::ALL {
        let mut series = Vec::new();
        let (mut x0, mut x1) = (f64::INFINITY, f64::NEG_INFINITY);
        for (ch, colour) in Channel::ALL.into_iter().zip([0, 3, 2]) {
            let mut pts: Vec<&GapPoint> = points
                .iter()
                .filter(|p| p.channel == ch && p.axis == axis)
                .collect();
            if pts.is_empty() {
                continue;
            }
            pts.sort_by(|a, b| a.x.total_cmp(&b.x));
            for p in &pts {
                for x in std::iter::once(p.x).chain(p.runs.iter().map(|r| r.0)) {
                    (x0, x1) = (x0.min(x - 0.5), x1.max(x + 0.5));
                }
            }
            series.extend(channel_series(ch, colour, &pts, effects));
        }
        if series.is_empty() {
            continue;
        }
        series
            .push(Series::line("3 × noise floor", &[x0, x1], &[3.0, 3.0], 7).styled(Style::Dashed));
        let (x_label, title) = match axis {
            PartAxis::Time => (
                "time after the input starts, s: each window at its samples' mean (dots: each run's)",
                "by time window",
            ),
            // A run without `ay` is banded by u·r (`regime_acceleration`).
            PartAxis::Ay if without_ay => (
                "|a_y| (u·r where a run has no a_y), m/s²: each band at its samples' mean (dots: each run's)",
                "by |a_y| level",
            ),
            PartAxis::Ay => (
                "|a_y|, m/s²: each band at its samples' mean (dots: each run's)",
                "by |a_y| level",
            ),
            PartAxis::Speed => (
                "speed, m/s: each band at its samples' mean (dots: each run's)",
                "by speed",
            ),
        };
        panels.push(Panel {
            title: format!("Held-out gap {title}"),
            x_label: x_label.into(),
            y_label: "RMS / noise floor".into(),
            series,
            x_range: Some((x0, x1)),
            y_range: None,
        });
    }
    Figure {
        panels,
        columns: 1,
        width: GAP_MAP_WIDTH,
        // Room for the key's ten entries, each run's among them.
        row_height: 400,
    }
}

/// A channel as a figure names it: the quantity, its symbol and its unit.
pub(super) fn quantity(ch: Channel) -> String {
    format!("{}, {}", symbol(ch), ch.unit())
}

/// A channel's name and symbol: `yaw rate r`.
fn symbol(ch: Channel) -> &'static str {
    match ch {
        Channel::YawRate => "yaw rate r",
        Channel::Ay => "lateral acceleration a_y",
        Channel::Beta => "sideslip β",
    }
}
