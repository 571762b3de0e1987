//! What a study says of a target the map never reaches: the range the
//! map's handling responses span for that metric, in its SI unit, and —
//! for the sideslip, in rad inside — whether the target reads as degrees
//! (β_ss −0.5 given for −0.5°, "not reached on the map" with no hint);
//! and what the map reaches ([`MapReach`]): its lowest and highest value
//! and where, and whether a target lies within them or is unreachable
//! within the map, with the nearest value it reaches and where (stiffness
//! in the study's unit).

use crate::study::inverse::Map;
use crate::study::{Metric, StiffnessUnit};
use serde::Serialize;

/// One map point's value of a metric, with its stiffness (the study's
/// unit, per tyre).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ReachPoint {
    /// The metric there, simulated (its unit: `study.csv`'s).
    pub value: f64,
    /// Front stiffness.
    pub k_front: f64,
    /// Rear stiffness.
    pub k_rear: f64,
}

/// Where a target lies against the values the map reaches.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TargetReach {
    /// Within the map's lowest and highest value.
    Within,
    /// Below the map's lowest: unreachable within the map.
    BelowMap,
    /// Above the map's highest: unreachable within the map.
    AboveMap,
}

/// What a map reaches of a metric over its handling responses: its lowest
/// and highest value and where, and where a target lies against them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MapReach {
    /// The lowest value on the map.
    pub lowest: ReachPoint,
    /// The highest value on the map.
    pub highest: ReachPoint,
    /// Where the target lies against them.
    pub target: TargetReach,
}

impl MapReach {
    /// What `map` reaches of `metric`, and where `target` lies against
    /// it; `None` where no map point has the metric (no handling
    /// response). Stiffness in `u`.
    pub(super) fn of(map: &Map, metric: Metric, target: f64, u: StiffnessUnit) -> Option<Self> {
        let k = u.to_si();
        let point = |(i, j): (usize, usize)| ReachPoint {
            value: map.value(metric, i, j),
            k_front: map.front[i] / k,
            k_rear: map.rear[j] / k,
        };
        let mut points = (0..map.front.len())
            .flat_map(|i| (0..map.rear.len()).map(move |j| (i, j)))
            .map(point)
            .filter(|p| p.value.is_finite());
        let first = points.next()?;
        let (lowest, highest) = points.fold((first, first), |(lo, hi), p| {
            (
                if p.value < lo.value { p } else { lo },
                if p.value > hi.value { p } else { hi },
            )
        });
        let target = match target {
            t if t < lowest.value => TargetReach::BelowMap,
            t if t > highest.value => TargetReach::AboveMap,
            _ => TargetReach::Within,
        };
        Some(Self {
            lowest,
            highest,
            target,
        })
    }

    /// The nearest value the map reaches to a target it does not reach.
    pub(super) fn nearest(&self) -> Option<ReachPoint> {
        match self.target {
            TargetReach::Within => None,
            TargetReach::BelowMap => Some(self.lowest),
            TargetReach::AboveMap => Some(self.highest),
        }
    }

    /// "the nearest it reaches is 0.5578 s, at (200, 220) N/deg" of
    /// `metric` in `u`; `None` within the map's values.
    pub(super) fn nearest_words(&self, metric: Metric, u: StiffnessUnit) -> Option<String> {
        let p = self.nearest()?;
        Some(format!(
            "the nearest it reaches is {} {}, at ({}, {}) {u}",
            crate::format::significant(p.value, 4),
            unit(metric),
            crate::format::rounded(p.k_front, 6),
            crate::format::rounded(p.k_rear, 6)
        ))
    }

    /// "; unreachable within the map: " and [`Self::nearest_words`];
    /// empty within the map's values.
    pub(super) fn unreachable_words(&self, metric: Metric, u: StiffnessUnit) -> String {
        self.nearest_words(metric, u).map_or(String::new(), |w| {
            format!("; unreachable within the map: {w}")
        })
    }
}

/// The SI unit the study reads a metric's target in (study.csv's).
pub(super) fn unit(metric: Metric) -> &'static str {
    match metric {
        Metric::Er
        | Metric::YawRateTotalVariance
        | Metric::AyTotalVariance
        | Metric::YawRateResponseTime
        | Metric::YawRatePeakTime
        | Metric::AyResponseTime => "s",
        Metric::YawRateOvershoot => "%",
        Metric::YawRateGain => "1/s",
        Metric::BetaSteady => "rad",
        Metric::Tb => "s·deg",
    }
}

/// The smallest and largest value of `metric` over the map's handling
/// responses; `None` where it has none.
pub(super) fn span(map: &Map, metric: Metric) -> Option<(f64, f64)> {
    let mut values = (0..map.front.len())
        .flat_map(|i| (0..map.rear.len()).map(move |j| (i, j)))
        .map(|(i, j)| map.value(metric, i, j))
        .filter(|v| v.is_finite())
        .peekable();
    values.peek()?;
    Some(
        values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        }),
    )
}

/// The words after "not reached on the map" for `target` of `metric`:
/// the map's range, the nearest value it reaches and where (stiffness in
/// `su`), and a degrees hint where the sideslip target, read as degrees,
/// falls inside it.
pub(super) fn beyond_the_map(map: &Map, metric: Metric, target: f64, su: StiffnessUnit) -> String {
    let Some((lo, hi)) = span(map, metric) else {
        return format!(": no map point has a {metric} (none is a handling response)");
    };
    let u = unit(metric);
    let g = |v: f64| crate::format::significant(v, 4);
    let range = format!(": on the map {metric} spans {} to {} {u}", g(lo), g(hi));
    let rad = target.to_radians();
    let hint = match metric {
        Metric::BetaSteady if (lo..=hi).contains(&rad) => format!(
            "; {target} read as degrees is {} rad, within it: the target is in rad",
            g(rad)
        ),
        _ => String::new(),
    };
    let nearest = MapReach::of(map, metric, target, su)
        .map_or(String::new(), |r| r.unreachable_words(metric, su));
    format!("{range}{hint}{nearest}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_metric_has_a_unit() {
        assert!(Metric::ALL.iter().all(|m| !unit(*m).is_empty()));
        assert_eq!(unit(Metric::BetaSteady), "rad");
    }
}
