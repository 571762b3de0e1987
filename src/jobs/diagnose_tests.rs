//! The diagnosis job's terminal and figures: the gap map's panels and
//! the reduction columns.

use super::*;
use crate::diagnose::effects::EffectKind;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::pipeline::PartAxis;

/// Two parts of every channel on every axis, each with two runs' shares:
/// the gap map these tests draw.
fn gap_points() -> Vec<GapPoint> {
    let mut points = Vec::new();
    for ch in Channel::ALL {
        for axis in PartAxis::ALL {
            for (x, b, a) in [(1.0, 5.0, 1.0), (2.0, 4.0, 1.5)] {
                points.push(GapPoint {
                    channel: ch,
                    axis,
                    x,
                    before: b,
                    after: a,
                    runs: vec![(x - 0.75, b + 0.5), (x + 0.25, b - 0.5)],
                });
            }
        }
    }
    points
}

/// Nine channel-and-axis charts become three print-sized panels: a
/// panel per axis holding every channel, labels about 10 pt on a
/// 170 mm text width, each channel's series named with its quantity.
#[test]
fn the_gap_map_is_three_panels_legible_in_print() {
    let points = gap_points();
    let fig = gap_figure(&[EffectKind::SensorDelay], &points, false);
    assert_eq!((fig.panels.len(), fig.columns), (3, 1));
    assert!(
        fig.printed_label_points() >= 9.5,
        "{}",
        fig.printed_label_points()
    );
    let time = &fig.panels[0];
    assert_eq!(time.title, "Held-out gap by time window");
    let labels: Vec<&str> = time
        .series
        .iter()
        .map(|s| s.label.as_str())
        .filter(|l| !l.is_empty())
        .collect();
    assert_eq!(
        labels,
        [
            "yaw rate r, base model",
            "yaw rate r, with sensor_delay",
            "yaw rate r, each run, base model",
            "lateral acceleration a_y, base model",
            "lateral acceleration a_y, with sensor_delay",
            "lateral acceleration a_y, each run, base model",
            "sideslip β, base model",
            "sideslip β, with sensor_delay",
            "sideslip β, each run, base model",
            "3 × noise floor"
        ]
    );
    // Over every part and run: the first run 0.75 before the first
    // part, half a unit of margin.
    assert_eq!(time.axes().x, (-0.25, 2.75));
    // The windows are points, not a line; the bands a joined profile; each
    // run's share a small dot, keyed apart from the verdict's discs, drawn
    // over its channel's pools at its own level.
    for (panel, joined) in fig.panels.iter().zip([false, true, true]) {
        let pooled = panel.series.iter().filter(|s| s.marker.is_some());
        for s in pooled {
            let points = matches!(s.style, Style::Points(_));
            assert_eq!(points, !joined, "{}: {:?}", panel.title, s.style);
        }
        let runs = &panel.series[2];
        assert_eq!(
            (runs.label.as_str(), runs.style, runs.marker),
            ("yaw rate r, each run, base model", Style::Points(2), None)
        );
        assert_eq!(
            (runs.x.clone(), runs.y.clone()),
            (vec![0.25, 1.25, 1.25, 2.25], vec![5.5, 4.5, 4.5, 3.5])
        );
    }
    assert_eq!(quantity(Channel::YawRate), "yaw rate r, rad/s");
    assert_eq!(quantity(Channel::Ay), "lateral acceleration a_y, m/s²");
    assert_eq!(quantity(Channel::Beta), "sideslip β, rad");
}

/// Without a verdict the map shows the base model alone, names no report
/// channel in a label, and says where a run without ay is banded by u·r.
#[test]
fn the_gap_map_without_a_verdict_is_the_base_model_alone() {
    let points = gap_points();
    let fig = gap_figure(&[EffectKind::SensorDelay], &points, false);
    // Without a verdict: the base model alone, and no report name
    // (yaw_rate, ay, beta) in a label.
    let base = gap_figure(&[], &points, true);
    assert_eq!(base.panels[1].series.len(), 7);
    // Runs without ay are banded by u·r: the axis says so.
    assert_eq!(
        base.panels[1].x_label,
        "|a_y| (u·r where a run has no a_y), m/s²: each band at its samples' mean (dots: each run's)"
    );
    assert_eq!(
        fig.panels[1].x_label,
        "|a_y|, m/s²: each band at its samples' mean (dots: each run's)"
    );
    for s in &base.panels[1].series {
        for ch in Channel::ALL {
            assert!(!s.label.contains(ch.name()), "{}", s.label);
        }
    }
}

/// A reduction that rounds to zero from below is no "-0.0 %".
#[test]
fn a_reduction_that_rounds_to_zero_has_no_sign() {
    let cells = reduction_cells([Reduction::Percent(-0.04), Reduction::Percent(-0.01)]);
    assert_eq!(cells, "      0.0 %      0.0 %");
    let cells = reduction_cells([Reduction::Percent(-1.25), Reduction::Percent(12.34)]);
    assert_eq!(cells, "     -1.2 %     12.3 %");
}
