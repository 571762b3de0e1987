//! `study.csv`: one row per combination, every metric a column. A cell with
//! no value is empty — never `NaN`, which half the readers of a CSV take for
//! a number — and the row's `response` and `note` say why: a response that
//! is no handling response ([`crate::study::Response`]) has every metric empty, a handling
//! response without a yaw-rate peak has no peak time, no overshoot (it is
//! below the peak threshold, the column `yaw_rate_peak_threshold`: not a
//! measured 0) and no TB.

use super::numbers::csv_number;
use crate::error::Error;
use crate::metrics::StepMetrics;
use crate::report::write_csv;
use crate::study::{Metric, Sample, SideslipEnd, StiffnessUnit, METRICS};
use serde::Serialize;
use std::path::Path;

/// `summary.json`: the size and time of the study.
#[derive(Debug, Clone, Serialize)]
pub struct StudySummary {
    /// Combinations simulated (map and RBF pairs).
    pub combinations: usize,
    /// Wall time of the simulations, s (printed, not written: a run merged
    /// from shards writes the unsharded run's outputs byte for byte).
    #[serde(skip)]
    pub seconds: f64,
    /// Study name.
    pub study: String,
    /// Stiffness unit of the reports.
    pub unit: StiffnessUnit,
    /// Combinations whose response has no steady state.
    pub without_steady_state: usize,
    /// Combinations on tyres with no friction limit that oversteer past
    /// their critical speed √(−l/K): unstable, no handling response (their
    /// metrics are left out).
    pub unstable: usize,
    /// The lowest critical speed of the unstable ones, m/s.
    pub lowest_critical_speed: Option<f64>,
    /// Combinations whose sideslip passes 10° on tyres with no
    /// friction limit (below their critical speed): far outside a linear
    /// tyre's range, no handling response (their metrics are left out).
    pub large_sideslip: usize,
    /// Of those, the ones whose sideslip is still moving at the end of the
    /// run (no steady value; the others' is steady).
    pub large_sideslip_still_moving: usize,
    /// Combinations whose sideslip passes 10° on tyres with a
    /// friction limit: sliding, no handling
    /// response (their metrics are left out).
    pub sliding: usize,
    /// Of those, the ones whose sideslip is still moving at the end of the
    /// run (no steady value; the others' is steady).
    pub sliding_still_moving: usize,
    /// Combinations (not sliding) whose response has not settled by the
    /// end of the step: no handling response (their metrics are left out).
    pub not_settled: usize,
    /// Combinations still converging at the end of the step (a slow
    /// response): kept in the maps as handling responses, flagged in
    /// study.csv's `note`.
    pub still_settling: usize,
    /// The largest sideslip at the end of the run of the sliding ones, rad
    /// (printed).
    #[serde(skip)]
    pub largest_sideslip: Option<f64>,
}

/// Writes `samples` to `path`, stiffness in `unit` and in N/rad.
pub(super) fn write(path: &Path, samples: &[Sample], unit: StiffnessUnit) -> Result<(), Error> {
    let k = unit.to_si();
    let name = unit.as_str().replace('/', "_per_");
    let (kf, kr) = (format!("k_front_{name}"), format!("k_rear_{name}"));
    let mut header = vec![kf.as_str(), kr.as_str(), "k_front", "k_rear"];
    header.extend(METRICS);
    header.extend(["yaw_rate_peak_threshold", "response", "note"]);
    let rows = samples.iter().map(|x| {
        let response = x.response();
        let note = match (response.note(), x.handling_metrics()) {
            // A response still settling keeps its empty cells' reason.
            (Some(n), Some(m)) if !empty_cells(&m).is_empty() => {
                format!("{n}; {}", empty_cells(&m))
            }
            (Some(n), _) => n,
            (None, Some(m)) => empty_cells(&m),
            (None, None) => String::new(),
        };
        let threshold = x
            .handling_metrics()
            .map_or(f64::NAN, |m| m.yaw_rate_peak_threshold);
        [x.k_front / k, x.k_rear / k, x.k_front, x.k_rear]
            .into_iter()
            .chain(Metric::ALL.iter().map(|m| m.measured_of_sample(x)))
            .chain([threshold])
            .map(cell)
            .chain([response.word().to_string(), note])
    });
    write_csv(path, &header, rows)
}

/// A number's cell: empty where it has none.
fn cell(v: f64) -> String {
    if v.is_finite() {
        csv_number(v)
    } else {
        String::new()
    }
}

/// Why a handling response's empty cells are empty: the metrics it lacks
/// and the reason (no yaw-rate peak above the steady value, no lateral
/// acceleration, no sideslip). Empty when it has every metric.
fn empty_cells(m: &StepMetrics) -> String {
    let empty: Vec<&str> = Metric::ALL
        .iter()
        .filter(|metric| metric.measured(m).is_none())
        .map(|metric| metric.name())
        .collect();
    if empty.is_empty() {
        return String::new();
    }
    let mut why = Vec::new();
    if m.overshoot_unresolved() {
        why.push(format!(
            "no overshoot measured: a yaw-rate maximum would have to stand {} % above the steady value to be told from its scatter, beyond a spin's 100 %",
            crate::format::rounded(m.yaw_rate_peak_threshold, 3)
        ));
    } else if m.yaw_rate_peak_time.is_none() {
        why.push(format!(
            "no yaw-rate maximum stands more than {} % above the steady value (the peak threshold, yaw_rate_peak_threshold): an overshoot below it, not a measured 0",
            crate::format::rounded(m.yaw_rate_peak_threshold, 3)
        ));
    }
    if m.ay_steady.is_none() {
        why.push("no lateral acceleration".into());
    }
    if m.beta_steady.is_none() {
        why.push("no sideslip".into());
    }
    format!("{} empty: {}", empty.join(", "), why.join("; "))
}

/// The terminal's line on the combinations that are no handling response,
/// where there are any.
pub(super) fn not_handling_line(s: &StudySummary) -> Option<String> {
    let total = s.unstable + s.sliding + s.large_sideslip + s.not_settled + s.without_steady_state;
    if total == 0 {
        return None;
    }
    let mut kinds = Vec::new();
    if s.unstable > 0 {
        let lowest = s
            .lowest_critical_speed
            .map_or_else(String::new, |u| format!(", the lowest {u:.2} m/s"));
        let (are, they, speed) = match s.unstable {
            1 => ("1 is", "it oversteers", "its critical speed"),
            _ => ("", "they oversteer", "their critical speed"),
        };
        let count = if are.is_empty() {
            format!("{} are", s.unstable)
        } else {
            are.to_string()
        };
        kinds.push(format!(
            "{count} unstable: {they} (K < 0) past {speed} sqrt(-l/K){lowest}, on tyres with no friction limit, so the response diverges"
        ));
    }
    if s.sliding > 0 {
        let most = s
            .largest_sideslip
            .map_or_else(String::new, |b| format!("{:.1}°", b.to_degrees()));
        kinds.push(format!(
            "{} {} ({})",
            s.sliding,
            verb(s.sliding, "slides", "slide"),
            beyond_ten(s.sliding, s.sliding_still_moving, &most)
        ));
    }
    if s.large_sideslip > 0 {
        kinds.push(format!(
            "{} {} a sideslip beyond 10° by the end of the step on tyres with no friction limit (far outside a linear tyre's range{})",
            s.large_sideslip,
            verb(s.large_sideslip, "reaches", "reach"),
            still_moving(s.large_sideslip, s.large_sideslip_still_moving)
        ));
    }
    if s.not_settled > 0 {
        kinds.push(format!(
            "{} {} by the end of the step (slower than the step is long, or diverging from a steady turn: a longer step tells them apart)",
            s.not_settled,
            verb(s.not_settled, "does not settle", "do not settle")
        ));
    }
    if s.without_steady_state > 0 {
        kinds.push(format!(
            "{} {} no steady state",
            s.without_steady_state,
            verb(s.without_steady_state, "has", "have")
        ));
    }
    Some(format!(
        "  {total} of {} {} no handling response: {}; {} metrics are left out of the maps, the network and the inverse (empty in study.csv, `response` says why)",
        s.combinations,
        verb(total, "combinations is", "combinations are"),
        kinds.join(", "),
        verb(total, "its", "their")
    ))
}

/// `n` sideslips beyond 10°, the largest `most` (empty: not said), of
/// which `moving` are still moving at the end of the run, in the words of
/// `study.csv`'s notes ([`SideslipEnd`]): a sideslip still moving is never
/// called steady.
fn beyond_ten(n: usize, moving: usize, most: &str) -> String {
    let still = SideslipEnd::STILL_MOVING;
    let up_to = |tail: &str| match most.is_empty() {
        true => format!("sideslip beyond 10°{tail}"),
        false => format!("sideslip beyond 10°, up to {most}{tail}"),
    };
    match (moving, n - moving) {
        (0, _) => format!("steady {}", up_to("")),
        (_, 0) => up_to(&format!(" at the end of the run, {still}")),
        (m, steady) => up_to(&format!(
            " at the end of the run: {steady} steady, {m} {still}"
        )),
    }
}

/// Of `n` sideslips beyond 10°, the `moving` still moving at the end of
/// the run, said where there are any, in the notes' words.
fn still_moving(n: usize, moving: usize) -> String {
    let still = SideslipEnd::STILL_MOVING;
    match (moving, n - moving) {
        (0, _) => String::new(),
        (_, 0) => format!("; at the end of the run, {still}"),
        (m, steady) => format!("; at the end of the run: {steady} steady, {m} {still}"),
    }
}

/// `one` for a count of 1, else `many`: "1 does not settle", "2 do not".
fn verb(n: usize, one: &'static str, many: &'static str) -> &'static str {
    if n == 1 {
        one
    } else {
        many
    }
}

/// The terminal's line on the combinations still converging at the end
/// of the step, where there are any: kept, but their steady values are a
/// little short of where a longer step would take them.
pub(super) fn still_settling_line(s: &StudySummary) -> Option<String> {
    (s.still_settling > 0).then(|| {
        format!(
            "  still settling at the end of the step: {} of {} combinations (slow, converging responses; kept in the maps, their steady values a little short: study.csv's `note` says how far; a longer step settles them)",
            s.still_settling, s.combinations
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cell_without_a_value_is_empty_not_nan() {
        assert_eq!(cell(f64::NAN), "");
        assert_eq!(cell(f64::INFINITY), "");
        assert_eq!(cell(700.0), "700");
    }

    #[test]
    fn the_line_counts_each_kind() {
        let s = StudySummary {
            combinations: 47,
            seconds: 1.0,
            study: "s".into(),
            unit: StiffnessUnit::NPerDeg,
            without_steady_state: 0,
            unstable: 0,
            lowest_critical_speed: None,
            sliding: 6,
            sliding_still_moving: 4,
            large_sideslip: 0,
            large_sideslip_still_moving: 0,
            not_settled: 1,
            still_settling: 0,
            largest_sideslip: Some(-1.0),
        };
        let line = not_handling_line(&s).unwrap();
        assert!(line.starts_with("  7 of 47 combinations are no handling response: 6 slide (sideslip beyond 10°, up to -57.3° at the end of the run: 2 steady, 4 still moving (no steady value)), 1 does not settle"), "{line}");
    }
}
