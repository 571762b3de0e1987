//! The marks a step metric carries where the record does not let it be
//! read as GB/T 6323 / ISO 7401 define it: against a level the response
//! drifts past without slowing (no steady state), against the mean of a
//! steady window the response still moves in, timed from a steer logged
//! late against the responses, or a response time at or below 0 (the 90 %
//! crossing before the steer reaches half its step: noise, or channels
//! out of step, never a lag). One function decides them: the terminal's
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
}

impl Mark {
    /// The mark as the table prints it after a value.
    pub fn text(self) -> &'static str {
        match self {
            Mark::NoSteadyState => "  (no steady state)",
            Mark::MovingWindow => "  (moving window)",
            Mark::SteerMisaligned => "  (steer misaligned)",
            Mark::BeforeTheSteer => "  (before the steer)",
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
        use Mark::{BeforeTheSteer, MovingWindow, NoSteadyState, SteerMisaligned};
        use MarkedMetric as M;
        let (yaw, ay) = self.drifting_channels();
        let late = self.steer_logged_late.is_some();
        let moving = self.yaw_rate_window_moving && !yaw;
        let ay_time = self.ay_response_time;
        let ay_moving = self.ay_window_moving && !ay && ay_time.is_some();
        let before = |t: Option<f64>| t.is_some_and(|t| t <= 0.0);
        let peak = self.yaw_rate_peak_time.is_some();
        let overshoot = self.yaw_rate_overshoot.is_some();
        let rows: [(MarkedMetric, Vec<(bool, Mark)>); 10] = [
            (
                M::YawRateResponseTime,
                vec![
                    (yaw, NoSteadyState),
                    (moving, MovingWindow),
                    (late, SteerMisaligned),
                    (before(Some(self.yaw_rate_response_time)), BeforeTheSteer),
                ],
            ),
            (M::YawRatePeakTime, vec![(moving && peak, MovingWindow)]),
            (
                M::YawRateOvershoot,
                vec![
                    (yaw && overshoot, NoSteadyState),
                    (moving && overshoot, MovingWindow),
                ],
            ),
            (
                M::AyResponseTime,
                vec![
                    (ay && ay_time.is_some(), NoSteadyState),
                    (ay_moving, MovingWindow),
                    (late, SteerMisaligned),
                    (before(ay_time), BeforeTheSteer),
                ],
            ),
            (M::YawRateGain, vec![(yaw, NoSteadyState)]),
            (
                M::AySteady,
                vec![(ay && self.ay_steady.is_some(), NoSteadyState)],
            ),
            (M::Tb, vec![(yaw && self.tb.is_some(), NoSteadyState)]),
            (
                M::YawRateTotalVariance,
                vec![(yaw, NoSteadyState), (late, SteerMisaligned)],
            ),
            (
                M::AyTotalVariance,
                vec![
                    (ay && self.ay_total_variance.is_some(), NoSteadyState),
                    (late, SteerMisaligned),
                ],
            ),
            (
                M::Er,
                vec![
                    ((yaw || ay) && self.er.is_some(), NoSteadyState),
                    (late, SteerMisaligned),
                ],
            ),
        ];
        rows.into_iter()
            .map(|(metric, flags)| {
                let on: Vec<Mark> = flags.into_iter().filter(|f| f.0).map(|f| f.1).collect();
                (metric, on)
            })
            .filter(|(_, on)| !on.is_empty())
            .collect()
    }
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
}
