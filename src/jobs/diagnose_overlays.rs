//! `diagnose`'s overlays: the held-out replays of the runs with the largest
//! base gap over their measured samples, drawn as `overlays.png` (and on
//! the page) and written as `overlays.csv`, one set of traces for both.
//!
//! The model lines start where the gap scan's scored span starts
//! ([`scored_from`], one window into each replay): before it a replay
//! follows from the initial state it estimates from noisy samples (a step's
//! ay starting at −0.4 m/s² where the measurement reads 0; a banked piece's
//! "with bank_profile" line jumping from 0 to −3.3 m/s²), a transient of
//! the replay that the scan leaves out, so the figure leaves it out too.
//! The measured dots are drawn over the whole run (over its scored samples
//! where its opening stretch is not scored: a run without a sideslip).

use crate::diagnose::effects::joined;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::pipeline::{observed_channel, Diagnosis};
use crate::diagnose::report::gap::scored_from;
use crate::error::Error;
use crate::report::plot::{Figure, Panel, Series, Style, MEASURED_DOTS};
use crate::report::write_csv;
use std::path::Path;

/// Runs drawn: the three with the largest base gap.
const RUNS_DRAWN: usize = 3;

/// One drawn trace of an overlay panel.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Trace {
    /// Its label in the key (`measured`, `base model`, `with …`).
    pub(super) label: String,
    /// Times, s.
    pub(super) t: Vec<f64>,
    /// Values, in the channel's unit.
    pub(super) y: Vec<f64>,
    /// How it is drawn.
    pub(super) style: Style,
    /// Its colour in the palette.
    pub(super) colour: usize,
}

/// One panel of the overlays: a run's channel and its traces.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct OverlayPanel {
    /// The run's file name (with its piece, `#2`).
    pub(super) run: String,
    /// The channel.
    pub(super) channel: Channel,
    /// Measured dots first, then the models' lines.
    pub(super) traces: Vec<Trace>,
}

/// The panels of the three runs with the largest base gap: each measured
/// channel (sideslip left out beside two others, for room).
pub(super) fn overlay_panels(d: &Diagnosis) -> Vec<OverlayPanel> {
    let label = format!("with {}", joined(d.verdict.effects(), " + "));
    let mut panels = Vec::new();
    for o in d.overlays.iter().take(RUNS_DRAWN) {
        let run = Path::new(&o.run)
            .file_name()
            .map_or(o.run.clone(), |s| s.to_string_lossy().into_owned());
        for (ch, m) in &o.measured {
            if *ch == Channel::Beta && o.measured.len() > 2 {
                continue;
            }
            let after = (!d.verdict.effects().is_empty())
                .then(|| (label.as_str(), observed_channel(&o.after, *ch)));
            panels.push(OverlayPanel {
                run: run.clone(),
                channel: *ch,
                traces: overlay_traces(o.start, &o.t, m, observed_channel(&o.base, *ch), after),
            });
        }
    }
    panels
}

/// The overlays' caption: what each trace is, the verdict's line only
/// where the verdict has effects (a verdict of no significant gap was
/// captioned "with the verdict's effects (solid)" over no solid line),
/// and why the model lines start later than the dots.
pub(super) fn overlay_caption(d: &Diagnosis) -> String {
    let after = if d.verdict.effects().is_empty() {
        "; no solid line: the verdict names no effect"
    } else {
        ", with the verdict's effects (solid)"
    };
    format!(
        "Held-out replays of the runs with the largest base-model gap: measured (grey points), \
         base model (dashed){after}. The model lines start {} s into each replay: before, a replay \
         settles from the initial state it estimates from noisy samples, a transient the gap scan \
         does not score either.",
        crate::format::exact(scored_from(0.0))
    )
}

/// The overlay figure's time axis, with where the model lines start.
fn time_label() -> String {
    format!(
        "t, s (models from {} s into the replay: its settling is not scored)",
        crate::format::exact(scored_from(0.0))
    )
}

/// One overlay panel's traces: the measured dots first, then the base
/// model dashed and the model with the verdict's effects (its label and
/// trace) solid over them, as the tyre fits draw a model over its data
/// (drawn last, the dots hid the lines wherever they agree). The models
/// are drawn from the scored span's start ([`scored_from`]) on.
pub(super) fn overlay_traces(
    start: f64,
    t: &[f64],
    measured: &[f64],
    base: &[f64],
    after: Option<(&str, &[f64])>,
) -> Vec<Trace> {
    // From the replay's start: a run without a sideslip has its
    // residuals (its `t`) start where the scored span does already.
    let from = t.partition_point(|&x| x < scored_from(start));
    let trace = |label: &str, y: &[f64], from: usize, style, colour| Trace {
        label: label.into(),
        t: t[from.min(t.len())..].to_vec(),
        y: y[from.min(y.len())..].to_vec(),
        style,
        colour,
    };
    let mut traces = vec![
        trace("measured", measured, 0, MEASURED_DOTS, 7),
        trace("base model", base, from, Style::Dashed, 1),
    ];
    if let Some((label, y)) = after {
        traces.push(trace(label, y, from, Style::Line, 2));
    }
    traces
}

/// The figure of `panels`, titled with the run and the quantity
/// (`quantity` names a channel with its unit).
pub(super) fn overlay_figure(panels: &[OverlayPanel], quantity: fn(Channel) -> String) -> Figure {
    let panels = panels
        .iter()
        .map(|p| Panel {
            title: format!("{}: {} (held out)", p.run, quantity(p.channel)),
            x_label: time_label(),
            y_label: quantity(p.channel),
            series: p
                .traces
                .iter()
                .map(|s| Series::line(&s.label, &s.t, &s.y, s.colour).styled(s.style))
                .collect(),
            x_range: None,
            y_range: None,
        })
        .collect();
    Figure {
        panels,
        columns: 2,
        width: 1400,
        row_height: 280,
    }
}

/// The header of `overlays.csv`.
const HEADER: [&str; 5] = ["run", "channel", "series", "t", "value"];

/// Writes `panels` to `path` as CSV, a line per drawn sample: the run, the
/// channel (`yaw_rate`, `ay`, `beta`), the trace's label, t in s and the
/// value in the channel's SI unit.
pub(super) fn write_overlays_csv(path: &Path, panels: &[OverlayPanel]) -> Result<(), Error> {
    let rows = panels.iter().flat_map(|p| {
        p.traces.iter().flat_map(move |s| {
            s.t.iter().zip(&s.y).map(move |(t, y)| {
                [
                    p.run.clone(),
                    p.channel.name().to_string(),
                    s.label.clone(),
                    t.to_string(),
                    y.to_string(),
                ]
            })
        })
    });
    write_csv(path, &HEADER, rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An overlay's measured samples are dots drawn first, under the base
    /// model's dashed line and the verdict's solid one; the models from
    /// one window in (the scan's scored span), the dots over the whole run.
    #[test]
    fn overlay_model_lines_are_drawn_over_the_measured_dots_from_the_scored_span() {
        let t: Vec<f64> = (0..20).map(|i| 3.0 + 0.04 * i as f64).collect();
        let m = vec![0.0; 20];
        let base: Vec<f64> = t.iter().map(|x| -0.4 * (-(x - 3.0) / 0.05).exp()).collect();
        let with = overlay_traces(t[0], &t, &m, &base, Some(("with x", &base)));
        let drawn: Vec<(&str, Style)> = with.iter().map(|s| (s.label.as_str(), s.style)).collect();
        assert_eq!(
            drawn,
            [
                ("measured", MEASURED_DOTS),
                ("base model", Style::Dashed),
                ("with x", Style::Line)
            ]
        );
        assert_eq!(with[0].t, t);
        // 3.5 s is the scan's first window: the model lines start at the
        // first sample there (3.52 s), past the start transient.
        assert_eq!(scored_from(3.0), 3.5);
        for s in &with[1..] {
            assert_eq!(s.t.len(), s.y.len());
            assert!((s.t[0] - 3.52).abs() < 1e-12, "{}: {}", s.label, s.t[0]);
            assert!(s.y[0].abs() < 1e-4, "{}", s.y[0]);
        }
        let without = overlay_traces(t[0], &t, &m, &base, None);
        assert_eq!(without.last().unwrap().style, Style::Dashed);
        assert_eq!(without.len(), 2);
    }
}
