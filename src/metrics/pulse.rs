//! A record without a held step, said for what its steer does: a steer
//! that leaves straight running and comes back between the metrics'
//! windows is a pulse (a step and its return within half a second), named
//! with its size, start and duration. "The steer stays at 0 rad" was true
//! of its windows and said nothing of the pulse between them. A departure
//! within [`PULSE_NOISES`] deviations of the steer's noise is the noise's,
//! no pulse: a record whose wheels are turned from its start, with a noisy
//! steer, is said so, not as a pulse of its noise. Rad, s.

use super::{noise_deviation, window_mean, MetricSettings, MetricsError, MIN_STEP};

/// Deviations of the raw steer's noise a departure must pass to be a
/// pulse: the largest of a few thousand samples of white noise lies
/// about 3.5 deviations out.
const PULSE_NOISES: f64 = 5.0;

/// A steer pulse: where it stands beyond half its largest departure from
/// the initial steer. S.
struct Pulse {
    /// Where it first passes half its size, s.
    start: f64,
    /// How long it stays beyond half its size, s.
    duration: f64,
    /// The first and last sample beyond half its size.
    lo: usize,
    hi: usize,
}

/// Why a record with steer `raw` (and `steer`, filtered where the metrics
/// filter) at times `t` holds no step: its steer's means in the initial
/// and steady windows ([`MetricsError::NoStep`]), or the pulse between
/// them ([`MetricsError::SteerPulse`]) where the steer leaves the initial
/// one by a step's worth and comes back. The pulse is found on the
/// filtered steer and sized on the raw one (a low-pass rings over a
/// pulse's edges: 1.01° of a 1° pulse).
pub(super) fn no_step(t: &[f64], raw: &[f64], steer: &[f64], s: &MetricSettings) -> MetricsError {
    let n = t.len();
    let initial = window_mean(t, steer, t[0], t[0] + s.pre_window).0;
    let steady_from = t[n - 1] - s.steady_window;
    let steady = window_mean(t, steer, steady_from, t[n - 1]).0;
    let least = MIN_STEP.max(PULSE_NOISES * noise_deviation(raw));
    match pulse(
        t,
        steer,
        (initial, steady, least),
        (t[0] + s.pre_window, steady_from),
    ) {
        Some(p) => MetricsError::SteerPulse {
            initial,
            size: raw[p.lo..=p.hi]
                .iter()
                .map(|d| d - initial)
                .fold(0.0, |a: f64, d| if d.abs() > a.abs() { d } else { a }),
            start: p.start,
            duration: p.duration,
            steady,
            steady_window: s.steady_window,
        },
        None => MetricsError::NoStep {
            initial,
            steady,
            min: MIN_STEP,
            pre_window: s.pre_window,
        },
    }
}

/// The pulse between the windows `(from, to)`: the largest departure of
/// the steer from `initial` there, where it is at least `least` (a step's
/// worth, [`MIN_STEP`], and beyond the noise) and the `steady` steer is
/// back within half of it (a change the size of the departure is a step,
/// said otherwise).
fn pulse(
    t: &[f64],
    steer: &[f64],
    (initial, steady, least): (f64, f64, f64),
    (from, to): (f64, f64),
) -> Option<Pulse> {
    let inside: Vec<usize> = (0..t.len()).filter(|&i| t[i] > from && t[i] < to).collect();
    let &peak = inside.iter().max_by(|&&a, &&b| {
        (steer[a] - initial)
            .abs()
            .total_cmp(&(steer[b] - initial).abs())
    })?;
    let size = steer[peak] - initial;
    if !size.is_finite() || size.abs() < least || (steady - initial).abs() > 0.5 * size.abs() {
        return None;
    }
    // Beyond half its size: the samples on either side of the peak that
    // stay there (its width at half height, as a pulse's is read).
    let beyond = |i: usize| (steer[i] - initial) * size.signum() >= 0.5 * size.abs();
    let mut lo = peak;
    while lo > 0 && beyond(lo - 1) {
        lo -= 1;
    }
    let mut hi = peak;
    while hi + 1 < t.len() && beyond(hi + 1) {
        hi += 1;
    }
    Some(Pulse {
        start: t[lo],
        duration: t[hi] - t[lo],
        lo,
        hi,
    })
}
