//! The study's figures: heat maps of every metric of `study.csv` over the
//! (k1, k2) map, each with its colour bar, with each inverse target's curve
//! on the map of its metric (`maps.png`), and what Wang & Liang's RBF
//! network learnt from their pairs (`rbf.png`). Stiffness in the file's
//! unit; each metric in its `study.csv` unit (SI: s, %, 1/s, rad, s·deg).

use super::RbfReport;
use crate::report::plot::{Figure, Marker, Panel, Series, Shape, Style};
use crate::study::inverse::Map;
use crate::study::{Metric, Sample, StiffnessUnit};

/// The title and the unit of a metric's map (every metric of `study.csv`
/// has one, in its columns' order: a target's curve is drawn on the map of
/// its metric, whichever it is).
fn mapped(metric: Metric) -> (&'static str, &'static str, &'static str) {
    match metric {
        Metric::Er => ("Er", "s", ""),
        Metric::YawRateTotalVariance => ("E_r", "s", ""),
        Metric::AyTotalVariance => ("E_ay", "s", ""),
        Metric::YawRateResponseTime => ("yaw-rate response time", "s", ""),
        Metric::YawRatePeakTime => ("yaw-rate peak time", "s", " (grey: no peak)"),
        Metric::YawRateOvershoot => (
            "yaw-rate overshoot",
            "%",
            " (grey: below the peak threshold)",
        ),
        Metric::AyResponseTime => ("ay response time", "s", ""),
        Metric::YawRateGain => ("yaw-rate gain", "1/s", ""),
        Metric::BetaSteady => ("steady sideslip beta", "rad", ""),
        Metric::Tb => ("TB", "s·deg", ""),
    }
}

/// A target's curve through the map: its metric, its value and its points
/// (k1, k2) in the stiffness unit.
pub(super) struct Curve<'a> {
    pub metric: Metric,
    pub target: f64,
    pub points: &'a [[f64; 2]],
}

/// Heat maps of every metric of `study.csv`; each of `curves` is drawn on
/// the map of its metric.
pub(super) fn heat_maps(map: &Map, unit: StiffnessUnit, curves: &[Curve]) -> Figure {
    let k = unit.to_si();
    let step = |v: &[f64]| {
        v.windows(2)
            .map(|w| (w[1] - w[0]) / k)
            .fold(f64::INFINITY, f64::min)
    };
    let (dx, dy) = (step(&map.front), step(&map.rear));
    let mut panels = Vec::new();
    for metric in Metric::ALL {
        let (name, metric_unit, note) = mapped(metric);
        let label = format!("{name} [{metric_unit}]{note}");
        let (mut x, mut y, mut v) = (Vec::new(), Vec::new(), Vec::new());
        for (i, kf) in map.front.iter().enumerate() {
            for (j, kr) in map.rear.iter().enumerate() {
                x.push(kf / k);
                y.push(kr / k);
                // An overshoot below the peak threshold is no value (grey),
                // not a measured 0 (the darkest cell).
                v.push(map.measured(metric, i, j));
            }
        }
        // The scale follows the values (log over decades, quantile where a
        // few cells are extreme); cells without a value (TB's, the peak
        // time's and the overshoot's without a peak) stay grey.
        let mut series = vec![Series::heat(&x, &y, v, (dx, dy), &label)];
        for (n, c) in curves
            .iter()
            .enumerate()
            .filter(|(_, c)| c.metric == metric)
        {
            let (cx, cy): (Vec<f64>, Vec<f64>) = c.points.iter().map(|p| (p[0], p[1])).unzip();
            // One colour per target, none of them the map's.
            // Rings, white inside, read on dark and light cells alike.
            series.push(
                Series::line(
                    &format!("{name} = {} {metric_unit}", c.target),
                    &cx,
                    &cy,
                    [1, 3, 6, 5][n % 4],
                )
                .styled(Style::Points(4))
                .marked(Marker {
                    shape: Shape::Ring,
                    size: 4,
                }),
            );
        }
        panels.push(Panel {
            title: label,
            x_label: format!("front k1 [{unit}]"),
            y_label: format!("rear k2 [{unit}]"),
            series,
            ..Panel::default()
        });
    }
    Figure {
        panels,
        columns: 2,
        width: 1400,
        row_height: 520,
    }
}

/// What Wang & Liang's network learnt: front and rear stiffness against Er,
/// the simulated pairs as points, the network's answer as a line and its
/// answers to the held-out pairs' Er as crosses beside their true values.
pub(super) fn rbf_pairs(pairs: &[Sample], rbf: &RbfReport, unit: StiffnessUnit) -> Figure {
    let k = unit.to_si();
    let er: Vec<f64> = pairs.iter().map(|s| Metric::Er.of_sample(s)).collect();
    let column = |i: usize| -> Vec<f64> { rbf.prediction.iter().map(|p| p[i]).collect() };
    let curve_er = column(0);
    let panel = |axle: &str, stiffness: Vec<f64>, predicted: Vec<f64>, held: Vec<(f64, f64)>| {
        let (hx, hy): (Vec<f64>, Vec<f64>) = held.into_iter().unzip();
        Panel {
            title: format!("{axle} stiffness against Er: simulated pairs and the RBF network"),
            x_label: "Er [s]".into(),
            y_label: format!("{axle} k [{unit}]"),
            series: vec![
                Series::line("simulated pairs", &er, &stiffness, 0).styled(Style::Points(3)),
                Series::line("RBF network", &curve_er, &predicted, 1),
                Series::line("held-out pairs, predicted", &hx, &hy, 3).styled(Style::Points(5)),
            ],
            ..Panel::default()
        }
    };
    let held = |f: fn(&super::Validation) -> f64| -> Vec<(f64, f64)> {
        rbf.validation.iter().map(|v| (v.er_target, f(v))).collect()
    };
    Figure::stack(vec![
        panel(
            "front",
            pairs.iter().map(|s| s.k_front / k).collect(),
            column(1),
            held(|v| v.k_front_predicted),
        ),
        panel(
            "rear",
            pairs.iter().map(|s| s.k_rear / k).collect(),
            column(2),
            held(|v| v.k_rear_predicted),
        ),
    ])
}
