//! The marks a step metric carries where the record does not let it be
//! read as GB/T 6323 / ISO 7401 define it: against a level the response
//! drifts past without slowing (no steady state), against the mean of a
//! steady window the response still moves in, timed from a steer logged
//! late against the responses, or a response time at or below 0 (the 90 %
//! crossing before the steer reaches half its step: noise, or channels
//! out of step, never a lag), or over a total-variance window the record
//! ends inside. Every value read from a steady window's mean (the response
//! times, peak and overshoot, the gain, steady ay and sideslip, TB, and
//! the total variances, whose normalised responses divide by it) carries
//! its window's mark. One function decides them: the terminal's
//! table prints them after the values (`jobs/metrics/table.rs`) and
//! `metrics --json` carries them (`marks`), so that a reader of either
//! sees the same metrics qualified.

use super::{Settling, StepMetrics};
use serde::Serialize;
use std::collections::BTreeMap;

/// Why a metric is not read as the standards define it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Mark {
    /// Read against a level the channel drifts past without slowing.
    NoSteadyState,
    /// Read against the mean of a steady window the channel still moves in.
    MovingWindow,
    /// Timed from a steer logged late against the responses.
    SteerMisaligned,
    /// A response time at or below 0: the 90 % crossing comes before the
    /// steer reaches half its step.
    BeforeTheSteer,
    /// A total variance integrated over less than its window: the record
    /// ends first.
    WindowCut,
}

impl Mark {
    /// The mark as the table prints it after a value.
    pub fn text(self) -> &'static str {
        match self {
            Mark::NoSteadyState => "  (no steady state)",
            Mark::MovingWindow => "  (moving window)",
            Mark::SteerMisaligned => "  (steer misaligned)",
            Mark::BeforeTheSteer => "  (before the steer)",
            Mark::WindowCut => "  (window cut short)",
        }
    }
}

/// The metrics that can carry a mark, named as their JSON fields are.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MarkedMetric {
    /// `yaw_rate_response_time`.
    YawRateResponseTime,
    /// `yaw_rate_peak_time`.
    YawRatePeakTime,
    /// `yaw_rate_overshoot`.
    YawRateOvershoot,
    /// `ay_response_time`.
    AyResponseTime,
    /// `yaw_rate_gain`.
    YawRateGain,
    /// `ay_steady`.
    AySteady,
    /// `beta_steady`.
    BetaSteady,
    /// `tb`.
    Tb,
    /// `yaw_rate_total_variance`.
    YawRateTotalVariance,
    /// `ay_total_variance`.
    AyTotalVariance,
    /// `er`.
    Er,
}

/// Each marked metric's marks, in the order the table prints them.
pub type Marks = BTreeMap<MarkedMetric, Vec<Mark>>;

/// Whether a channel drifts without slowing through the steady window.
fn drifting(s: Option<Settling>) -> bool {
    matches!(
        s,
        Some(Settling::Drifting {
            converging: false,
            ..
        })
    )
}

impl StepMetrics {
    /// Whether the yaw rate and the lateral acceleration drift without
    /// slowing across the steady window: no steady state is in the record,
    /// and every metric defined against one measures a level the response
    /// passes on its way (the table's notes and [`Mark::NoSteadyState`]).
    pub fn drifting_channels(&self) -> (bool, bool) {
        (
            drifting(Some(self.settling.yaw_rate)),
            drifting(self.settling.ay),
        )
    }

    /// The marks of these metrics (metrics without one are left out).
    pub fn marks(&self) -> Marks {
        rows_of(self)
            .into_iter()
            .map(|(metric, flags)| {
                let on: Vec<Mark> = flags.into_iter().filter(|f| f.0).map(|f| f.1).collect();
                (metric, on)
            })
            .filter(|(_, on)| !on.is_empty())
            .collect()
    }
}

/// A markable metric with its candidate marks, each with whether it holds.
type Row = (MarkedMetric, Vec<(bool, Mark)>);

/// What the marks of `m` are decided on.
struct Flags {
    /// The yaw rate and the lateral acceleration drift without slowing.
    yaw: bool,
    ay: bool,
    /// The steer was logged late.
    late: bool,
    /// The yaw rate's, ay's and sideslip's windows still move.
    moving: bool,
    ay_window: bool,
    beta: bool,
    /// The total-variance window is cut short by the record's end.
    cut: bool,
}

impl Flags {
    fn of(m: &StepMetrics) -> Self {
        let (yaw, ay) = m.drifting_channels();
        Flags {
            yaw,
            ay,
            late: m.steer_logged_late.is_some(),
            moving: m.yaw_rate_window_moving && !yaw,
            ay_window: m.ay_window_moving && !ay,
            beta: m.beta_window_moving && m.beta_steady.is_some(),
            cut: m.total_variance_window_cut.is_some(),
        }
    }
}

/// Each markable metric of `m` with its candidate marks and whether each
/// holds: the times and the overshoot, then the steady values and the
/// total variances ([`value_rows`]).
fn rows_of(m: &StepMetrics) -> Vec<Row> {
    use Mark::{BeforeTheSteer, MovingWindow, NoSteadyState, SteerMisaligned};
    use MarkedMetric as M;
    let f = Flags::of(m);
    let ay_time = m.ay_response_time;
    let before = |t: Option<f64>| t.is_some_and(|t| t <= 0.0);
    let peak = m.yaw_rate_peak_time.is_some();
    let overshoot = m.yaw_rate_overshoot.is_some();
    let mut rows = vec![
        (
            M::YawRateResponseTime,
            vec![
                (f.yaw, NoSteadyState),
                (f.moving, MovingWindow),
                (f.late, SteerMisaligned),
                (before(Some(m.yaw_rate_response_time)), BeforeTheSteer),
            ],
        ),
        (M::YawRatePeakTime, vec![(f.moving && peak, MovingWindow)]),
        (
            M::YawRateOvershoot,
            vec![
                (f.yaw && overshoot, NoSteadyState),
                (f.moving && overshoot, MovingWindow),
            ],
        ),
        (
            M::AyResponseTime,
            vec![
                (f.ay && ay_time.is_some(), NoSteadyState),
                (f.ay_window && ay_time.is_some(), MovingWindow),
                (f.late, SteerMisaligned),
                (before(ay_time), BeforeTheSteer),
            ],
        ),
    ];
    rows.extend(value_rows(m, &f));
    rows
}

/// The steady values' and the total variances' rows of [`rows_of`]. A
/// total variance divides each response by its steady window's step, so
/// a window the response still moves in marks it as it marks the gain;
/// one the record ends inside marks it cut short.
fn value_rows(m: &StepMetrics, f: &Flags) -> [Row; 7] {
    use Mark::{MovingWindow, NoSteadyState, SteerMisaligned, WindowCut};
    use MarkedMetric as M;
    let (ay_steady, tb) = (m.ay_steady.is_some(), m.tb.is_some());
    let (e_ay, er) = (m.ay_total_variance.is_some(), m.er.is_some());
    [
        (
            M::YawRateGain,
            vec![(f.yaw, NoSteadyState), (f.moving, MovingWindow)],
        ),
        (
            M::AySteady,
            vec![
                (f.ay && ay_steady, NoSteadyState),
                (f.ay_window && ay_steady, MovingWindow),
            ],
        ),
        (M::BetaSteady, vec![(f.beta, MovingWindow)]),
        (
            M::Tb,
            vec![
                (f.yaw && tb, NoSteadyState),
                ((f.moving || f.beta) && tb, MovingWindow),
            ],
        ),
        (
            M::YawRateTotalVariance,
            vec![
                (f.yaw, NoSteadyState),
                (f.moving, MovingWindow),
                (f.late, SteerMisaligned),
                (f.cut, WindowCut),
            ],
        ),
        (
            M::AyTotalVariance,
            vec![
                (f.ay && e_ay, NoSteadyState),
                (f.ay_window && e_ay, MovingWindow),
                (f.late, SteerMisaligned),
                (f.cut && e_ay, WindowCut),
            ],
        ),
        (
            M::Er,
            vec![
                ((f.yaw || f.ay) && er, NoSteadyState),
                ((f.moving || f.ay_window) && er, MovingWindow),
                (f.late, SteerMisaligned),
                (f.cut && er, WindowCut),
            ],
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_response_time_before_the_steer_is_marked_and_a_lag_is_not() {
        let mut m = crate::metrics::applicability::tests::moderate();
        m.yaw_rate_response_time = 0.2;
        m.ay_response_time = Some(-0.07);
        let marks = m.marks();
        assert_eq!(
            marks.get(&MarkedMetric::AyResponseTime),
            Some(&vec![Mark::BeforeTheSteer])
        );
        assert_eq!(marks.get(&MarkedMetric::YawRateResponseTime), None);
        let json = serde_json::to_string(&marks).unwrap();
        assert_eq!(json, r#"{"ay_response_time":["before_the_steer"]}"#);
    }

    #[test]
    fn a_steer_logged_late_marks_every_time_and_variance() {
        let mut m = crate::metrics::applicability::tests::moderate();
        m.steer_logged_late = Some(0.08);
        let marks = m.marks();
        for metric in [
            MarkedMetric::YawRateResponseTime,
            MarkedMetric::AyResponseTime,
            MarkedMetric::YawRateTotalVariance,
            MarkedMetric::AyTotalVariance,
            MarkedMetric::Er,
        ] {
            assert!(
                marks[&metric].contains(&Mark::SteerMisaligned),
                "{metric:?}: {marks:?}"
            );
        }
        assert_eq!(marks.get(&MarkedMetric::YawRateGain), None);
    }

    /// A yaw rate and ay still moving in their windows mark every value
    /// read from those windows' means (the gain, steady ay, TB, the total
    /// variances), and a record ending inside the variance window marks
    /// the variances cut short; a settled run marks none of them.
    #[test]
    fn every_value_read_from_a_moving_window_is_marked() {
        let m = crate::metrics::applicability::tests::moderate();
        assert_eq!(m.marks(), Marks::new());
        let mut moving = m;
        moving.yaw_rate_window_moving = true;
        moving.ay_window_moving = true;
        moving.total_variance_window_cut = Some(2.1);
        let marks = moving.marks();
        for metric in [
            MarkedMetric::YawRateGain,
            MarkedMetric::AySteady,
            MarkedMetric::YawRateTotalVariance,
            MarkedMetric::AyTotalVariance,
            MarkedMetric::Er,
        ] {
            assert!(
                marks[&metric].contains(&Mark::MovingWindow),
                "{metric:?}: {marks:?}"
            );
        }
        for metric in [
            MarkedMetric::YawRateTotalVariance,
            MarkedMetric::AyTotalVariance,
            MarkedMetric::Er,
        ] {
            assert!(marks[&metric].contains(&Mark::WindowCut), "{metric:?}");
        }
    }
}
