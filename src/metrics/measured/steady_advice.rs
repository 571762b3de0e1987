//! The advice to a record too short for its steady window: a shorter
//! window that starts after the steer settles is advised only where the
//! response read with it settles. A window after the steer's settling can
//! still hold a response that moves (the linear car's record ending 0.6 s
//! after its step, read with the advised 0.58 s window, gave a yaw-rate
//! gain 7 % low and only "not settled"); where no window settles, the
//! record is said to end before the steady state. Units: s.

use super::super::step_shape::check_step_shape;
use super::super::{step_metrics, MetricSettings, MetricsError, Settling, StepMetrics};
use crate::error::SteadyAdvice;
use crate::measured::MeasuredRun;

/// The factor between successive windows tried: a fifth shorter each.
const SHORTER: f64 = 0.8;

/// Whether every channel of `m` judged has settled and no longer
/// approaches its steady value (a response still approaching reads short
/// of its steady state by about as much).
fn steady(m: &StepMetrics) -> bool {
    let ok = |s: &Settling| matches!(s, Settling::Settled | Settling::NotJudged { .. });
    let c = &m.settling;
    ok(&c.yaw_rate) && c.ay.iter().all(ok) && c.beta.iter().all(ok)
}

/// `e` with its advice found on the filled piece `p` measured with `s`,
/// where `e` is a record too short for its steady window: the windows
/// from the steer's bound down by a fifth each, to the yaw rate's
/// response time (or two sample intervals), are measured, and the
/// longest that settles is advised; none, and that is said.
pub(crate) fn with_advice(e: MetricsError, p: &MeasuredRun, s: &MetricSettings) -> MetricsError {
    let MetricsError::ShortForSteadyWindow {
        settles, from, to, ..
    } = e
    else {
        return e;
    };
    let measure = |w: f64| {
        let at = MetricSettings {
            steady_window: w,
            ..*s
        };
        let m = step_metrics(
            &p.t,
            &p.steer,
            &p.yaw_rate,
            p.ay.as_deref(),
            p.beta.as_deref(),
            &at,
        )
        .ok()?;
        check_step_shape(&p.t, &p.steer, &m, &at).ok().map(|()| m)
    };
    let dt = crate::measured::clean::median_interval(&p.t);
    // The steer's bound, in whole hundredths as the advice says it.
    let most = ((to - settles) * 100.0).floor() / 100.0;
    let mut shortest = (2.0 * dt).max(0.01);
    let mut w = most;
    let mut advice = None;
    while w >= shortest {
        if let Some(m) = measure(w) {
            // A window shorter than the response reads no steady state.
            shortest = shortest.max(m.yaw_rate_response_time);
            if w >= shortest && steady(&m) {
                advice = Some(SteadyAdvice::Settled(w));
                break;
            }
        }
        w = (w * SHORTER * 100.0).floor() / 100.0;
    }
    MetricsError::ShortForSteadyWindow {
        advice: advice.unwrap_or(SteadyAdvice::NoneSettles { shortest }),
        settles,
        from,
        to,
    }
}
