//! What a study says of a target the map never reaches: the range the
//! map's handling responses span for that metric, in its SI unit, and —
//! for the sideslip, in rad inside — whether the target reads as degrees
//! (β_ss −0.5 given for −0.5°, "not reached on the map" with no hint).

use crate::study::inverse::Map;
use crate::study::Metric;

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
/// the map's range, and a degrees hint where the sideslip target, read as
/// degrees, falls inside it.
pub(super) fn beyond_the_map(map: &Map, metric: Metric, target: f64) -> String {
    let Some((lo, hi)) = span(map, metric) else {
        return format!(": no map point has a {metric} (none is a handling response)");
    };
    let u = unit(metric);
    let g = |v: f64| crate::format::significant(v, 4);
    let range = format!(": on the map {metric} spans {} to {} {u}", g(lo), g(hi));
    let rad = target.to_radians();
    match metric {
        Metric::BetaSteady if (lo..=hi).contains(&rad) => format!(
            "{range}; {target} read as degrees is {} rad, within it: the target is in rad",
            g(rad)
        ),
        _ => range,
    }
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
