//! The study's figures: heat maps of six metrics over the (k1, k2) map with
//! the Er curves on the Er map (`maps.png`), and Er against front stiffness
//! along Wang & Liang's pairs (`rbf.png`). Stiffness in the file's unit.

use crate::report::plot::{Figure, Panel, Series, Style};
use crate::study::inverse::Map;
use crate::study::{Metric, Sample, StiffnessUnit};

/// The metrics mapped, with their axis labels.
const MAPPED: [(Metric, &str); 6] = [
    (Metric::Er, "Er [s]"),
    (Metric::YawRateTotalVariance, "E_r [s]"),
    (Metric::AyTotalVariance, "E_ay [s]"),
    (Metric::YawRateResponseTime, "yaw-rate response time [s]"),
    (Metric::YawRateOvershoot, "yaw-rate overshoot [%]"),
    (Metric::Tb, "TB [s·deg]"),
];

/// Heat maps of the mapped metrics; `curves` (target Er, points in the
/// stiffness unit) are drawn on the Er map.
pub(super) fn heat_maps(map: &Map, unit: StiffnessUnit, curves: &[(f64, &[[f64; 2]])]) -> Figure {
    let k = unit.to_si();
    let step = |v: &[f64]| {
        v.windows(2)
            .map(|w| (w[1] - w[0]) / k)
            .fold(f64::INFINITY, f64::min)
    };
    let (dx, dy) = (step(&map.front), step(&map.rear));
    let mut panels = Vec::new();
    for (metric, label) in MAPPED {
        let (mut x, mut y, mut v) = (Vec::new(), Vec::new(), Vec::new());
        for (i, kf) in map.front.iter().enumerate() {
            for (j, kr) in map.rear.iter().enumerate() {
                x.push(kf / k);
                y.push(kr / k);
                v.push(map.value(metric, i, j));
            }
        }
        let finite: Vec<f64> = v.iter().copied().filter(|a| a.is_finite()).collect();
        let lo = finite.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let mut heat = Series::line("", &x, &y, 0).styled(Style::Heat(dx, dy, lo, hi));
        heat.values = Some(v);
        let mut series = vec![heat];
        if metric == Metric::Er {
            for (target, c) in curves {
                let (cx, cy): (Vec<f64>, Vec<f64>) = c.iter().map(|p| (p[0], p[1])).unzip();
                series.push(
                    Series::line(&format!("Er = {target}"), &cx, &cy, 1).styled(Style::Points(2)),
                );
            }
        }
        panels.push(Panel {
            title: format!("{label}: {lo:.4} (dark) … {hi:.4} (yellow)"),
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

/// Er against front stiffness along the pairs, one line per rear − front
/// offset.
pub(super) fn rbf_pairs(pairs: &[Sample], unit: StiffnessUnit) -> Figure {
    let k = unit.to_si();
    let mut offsets: Vec<f64> = pairs
        .iter()
        .map(|s| ((s.k_rear - s.k_front) / k).round())
        .collect();
    offsets.dedup();
    let series = offsets
        .iter()
        .enumerate()
        .map(|(c, off)| {
            let (x, y): (Vec<f64>, Vec<f64>) = pairs
                .iter()
                .filter(|s| ((s.k_rear - s.k_front) / k).round() == *off)
                .map(|s| (s.k_front / k, Metric::Er.of_sample(s)))
                .unzip();
            Series::line(&format!("k2 = k1 + {off} {unit}"), &x, &y, c)
        })
        .collect();
    Figure::stack(vec![Panel {
        title: "Wang & Liang pairs: Er against front stiffness".into(),
        x_label: format!("front k1 [{unit}]"),
        y_label: "Er [s]".into(),
        series,
        ..Panel::default()
    }])
}
