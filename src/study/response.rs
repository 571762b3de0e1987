//! Whether a map point's step response is a handling response at all. An
//! oversteering combination past its critical speed does not settle to a
//! steady turn: its yaw rate grows until the tyres saturate and the car
//! slides or spins. Its "steady" values are wherever the run happened to end,
//! and its yaw rate, never peaking above a steady value, reads as 0 %
//! overshoot: the best-looking number of the map for the worst car. Such a
//! point is flagged, counted and left out of the maps, the network and the
//! inverse, as [`crate::metrics::applicability`] says of a single run.
//! On tyres with no friction limit (linear) there is no grip to slide past:
//! a point past its critical speed √(−l/K) (Genta 1997; Milliken & Milliken
//! 1995) is unstable, decided by that closed form and said with both
//! speeds, whatever sideslip the run happened to reach.
//! A slow response that is still converging at the step's end (its trend
//! heads a little further, but slows: no divergence), or one settled
//! within 2 % whose steady values are still a tenth of a percent or more
//! short of the steady state, is a handling response whose steady values
//! are a little short: it stays in the maps, flagged, and a longer step
//! settles it.

use super::Sample;
use crate::metrics::applicability::SLIDING_SIDESLIP;
use crate::metrics::StepMetrics;
use serde::Serialize;

/// What a combination's step response is.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Response {
    /// A handling response: settled, below the tyres' limit.
    Handling,
    /// A handling response still converging at the step's end: its steady
    /// values head a share (carried) of their step further. Kept in the maps.
    StillSettling(f64),
    /// Tyres with no friction limit on an oversteering car above its
    /// critical speed √(−l/K): the steady turn is unstable and the response
    /// diverges, with no grip to slide past. Carries (critical speed, the
    /// step's speed), m/s.
    Unstable(f64, f64),
    /// The sideslip passes [`SLIDING_SIDESLIP`] (10°) on tyres with
    /// a friction limit: the car slides past its grip. Carries the
    /// sideslip at the end of the run, rad, and whether it had settled.
    Sliding(f64, SideslipEnd),
    /// The steady sideslip passes [`SLIDING_SIDESLIP`] (10°) on tyres with
    /// no friction limit, below the critical speed: a steady turn, but at a
    /// sideslip far outside the range where a linear tyre stands for a real
    /// one (Pacejka 2012, §1.3). Carries the sideslip at the end of the
    /// run, rad, and whether it had settled (a slow linear car is still
    /// on its way at the end of an 8 s step: −12.5° there, −14.4° steady).
    LargeSideslip(f64, SideslipEnd),
    /// The response has not settled by the end of the step (the yaw rate,
    /// lateral acceleration or sideslip still moving: a car diverging
    /// from its steady turn).
    NotSettled,
    /// No steady state the metrics could measure at all.
    NoSteadyState,
}

impl Response {
    /// The response of a run with metrics `m` (`None`: none measured);
    /// `unstable` is [`Sample::unstable`], decided by the closed form
    /// before anything the run measured.
    pub fn of(m: Option<&StepMetrics>, unstable: Option<(f64, f64)>, unlimited: bool) -> Self {
        if let Some((critical, speed)) = unstable {
            return Response::Unstable(critical, speed);
        }
        let Some(m) = m else {
            return Response::NoSteadyState;
        };
        match m.beta_steady.filter(|b| b.abs() > SLIDING_SIDESLIP) {
            Some(beta) if unlimited => Response::LargeSideslip(beta, SideslipEnd::of(m.settled)),
            Some(beta) => Response::Sliding(beta, SideslipEnd::of(m.settled)),
            None if !m.settled => match m.settling.only_converging() {
                Some(heads) => Response::StillSettling(heads),
                None => Response::NotSettled,
            },
            // Settled within 2 %, but its steady values still short of the
            // steady state by a tenth of a percent or more (a step as short
            // as a scenario accepts, 2 s after the steer, on a slow car):
            // kept, and said, as `metrics` says it of a single run.
            None => match m.settling.approaching() {
                Some(heads) => Response::StillSettling(heads),
                None => Response::Handling,
            },
        }
    }

    /// Whether the metrics describe handling.
    pub fn is_handling(self) -> bool {
        matches!(self, Response::Handling | Response::StillSettling(_))
    }

    /// The word of `study.csv`'s `response` column.
    pub fn word(self) -> &'static str {
        match self {
            Response::Handling | Response::StillSettling(_) => "handling",
            Response::Unstable(..) => "unstable",
            Response::Sliding(..) => "sliding",
            Response::LargeSideslip(..) => "large_sideslip",
            Response::NotSettled => "not_settled",
            Response::NoSteadyState => "no_steady_state",
        }
    }

    /// Why the metrics of a response that is no handling response are left
    /// empty, or how far a response still settling has to go
    /// (`study.csv`'s `note`); `None` for a settled handling response.
    pub fn note(self) -> Option<String> {
        match self {
            Response::Handling => None,
            Response::StillSettling(heads) => Some(format!(
                "still settling at the end of the step: a steady value heads {} % of its step further; metrics kept, a longer step settles them",
                crate::format::significant(100.0 * heads, 2)
            )),
            Response::Unstable(critical, speed) => Some(format!(
                "unstable: oversteering (K < 0) at {speed:.2} m/s, past its critical speed sqrt(-l/K) = {critical:.2} m/s; the tyres have no friction limit, so the response diverges without bound; no handling response, metrics left empty"
            )),
            Response::Sliding(beta, end) => Some(format!(
                "{}, beyond 10 deg: the car slides past its grip; no handling response, metrics left empty",
                end.words(beta)
            )),
            Response::LargeSideslip(beta, end) => Some(format!(
                "{}, beyond 10 deg, on tyres with no friction limit: far outside the range where a linear tyre stands for a real one; no handling response, metrics left empty",
                end.words(beta)
            )),
            Response::NotSettled => Some(
                "not settled by the end of the step (a response slower than the step is long, or one that diverges from a steady turn: a longer step tells them apart); no handling response, metrics left empty"
                    .into(),
            ),
            Response::NoSteadyState => Some("no steady state; metrics left empty".into()),
        }
    }
}

/// Whether a sideslip read at the end of a run had settled: one still
/// moving is no steady value. One set of words for `study.csv`'s notes,
/// the terminal's count and `summary.json`'s (`sliding_still_moving`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SideslipEnd {
    /// Settled: a steady sideslip.
    Steady,
    /// Still moving at the end of the run: no steady value.
    StillMoving,
}

impl SideslipEnd {
    /// The end of a run whose metrics had (`true`) or had not settled.
    pub fn of(settled: bool) -> Self {
        match settled {
            true => SideslipEnd::Steady,
            false => SideslipEnd::StillMoving,
        }
    }

    /// A sideslip `beta` (rad) read at the end of the run, in words.
    pub fn words(self, beta: f64) -> String {
        match self {
            SideslipEnd::Steady => format!("steady sideslip {:.1} deg", beta.to_degrees()),
            SideslipEnd::StillMoving => format!(
                "sideslip {:.1} deg at the end of the run, {}",
                beta.to_degrees(),
                SideslipEnd::STILL_MOVING
            ),
        }
    }

    /// The words of a sideslip still moving, in the notes and the
    /// terminal's count alike.
    pub const STILL_MOVING: &'static str = "still moving (no steady value)";
}

impl Sample {
    /// What this combination's response is.
    pub fn response(&self) -> Response {
        Response::of(self.metrics.as_ref(), self.unstable, self.unlimited)
    }

    /// The metrics where they describe a handling response ([`Response`]).
    pub fn handling_metrics(&self) -> Option<StepMetrics> {
        self.metrics.filter(|_| self.response().is_handling())
    }

    /// The sample as the study reports it ([`ReportedSample`]).
    pub fn reported(&self) -> ReportedSample {
        let response = self.response();
        ReportedSample {
            k_front: self.k_front,
            k_rear: self.k_rear,
            response: response.word(),
            note: response.note(),
            metrics: self.handling_metrics(),
        }
    }
}

/// A combination as `study.csv` reports it, for the library's callers
/// (Python's samples): its `response` word and `note`, and its metrics
/// only where they describe handling — a sliding car's Er of 1.98 s is no
/// handling number, and `study.csv` leaves that row's cells empty.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReportedSample {
    /// Front cornering stiffness per tyre, N/rad.
    pub k_front: f64,
    /// Rear cornering stiffness per tyre, N/rad.
    pub k_rear: f64,
    /// `study.csv`'s `response`: `handling`, `sliding`, `unstable`,
    /// `large_sideslip`, `not_settled` or `no_steady_state`.
    pub response: &'static str,
    /// Why the metrics are empty, or how far a response still settling has
    /// to go ([`Response::note`]); `None` for a settled handling response.
    pub note: Option<String>,
    /// The metrics of a handling response; `None` otherwise.
    pub metrics: Option<StepMetrics>,
}

/// How many of a set of samples are no handling response, by kind.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct NotHandling {
    /// Unstable past their critical speed, on tyres with no friction limit.
    pub unstable: usize,
    /// The lowest critical speed of the unstable ones, m/s.
    pub lowest_critical_speed: Option<f64>,
    /// Beyond 10° of steady sideslip on tyres with no friction limit.
    pub large_sideslip: usize,
    /// Sliding (sideslip beyond 10° on tyres with a friction limit).
    pub sliding: usize,
    /// Of the sliding ones, those still moving at the end of the run
    /// ([`SideslipEnd::StillMoving`]: no steady value).
    pub sliding_still_moving: usize,
    /// Of the large-sideslip ones, those still moving at the end of the run.
    pub large_sideslip_still_moving: usize,
    /// Not settled by the end of the step (and not sliding).
    pub not_settled: usize,
    /// Without a steady state.
    pub without_steady_state: usize,
    /// Handling responses still converging at the step's end (kept; not
    /// in the total of those left out).
    pub still_settling: usize,
    /// The largest sideslip at the end of the run of the sliding ones, rad
    /// (signed).
    pub largest_sideslip: Option<f64>,
}

impl NotHandling {
    /// The counts over `samples`.
    pub fn count<'a>(samples: impl IntoIterator<Item = &'a Sample>) -> Self {
        let mut n = NotHandling::default();
        for s in samples {
            match s.response() {
                Response::Handling => {}
                Response::StillSettling(_) => n.still_settling += 1,
                Response::Unstable(critical, _) => {
                    n.unstable += 1;
                    let low = n
                        .lowest_critical_speed
                        .map_or(critical, |c| c.min(critical));
                    n.lowest_critical_speed = Some(low);
                }
                Response::Sliding(beta, end) => {
                    n.sliding += 1;
                    n.sliding_still_moving += usize::from(end == SideslipEnd::StillMoving);
                    if n.largest_sideslip.is_none_or(|b: f64| beta.abs() > b.abs()) {
                        n.largest_sideslip = Some(beta);
                    }
                }
                Response::LargeSideslip(_, end) => {
                    n.large_sideslip += 1;
                    n.large_sideslip_still_moving += usize::from(end == SideslipEnd::StillMoving);
                }
                Response::NotSettled => n.not_settled += 1,
                Response::NoSteadyState => n.without_steady_state += 1,
            }
        }
        n
    }

    /// All of them.
    pub fn total(&self) -> usize {
        self.unstable
            + self.sliding
            + self.large_sideslip
            + self.not_settled
            + self.without_steady_state
    }
}
