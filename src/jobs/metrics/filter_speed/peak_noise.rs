//! Whether the yaw-rate peak, read through a low-pass cut-off, stands
//! above the run's noise, over the cut-offs a filter warning would
//! suggest. The higher the cut-off, the more of the noise passes: the
//! noisy copies of the run (`metrics/peak.rs`: its own noise added again,
//! 32 copies, a fixed seed) lose the peak or move it, and the run's own
//! peak can sink under the overshoot's noise threshold. A rise rule alone
//! sent a 25 Hz log with 1.4 % noise (a 3.8 % overshoot) to 6.5 Hz, where
//! 11 of the 32 copies lose the peak and the metrics warn of it; at 5.5 Hz
//! it holds. The peak holds where the metrics would not warn of it
//! (`jobs/metrics.rs`, `peak_time_said`): found in the run, found by three
//! quarters of the copies, and moved by them less than
//! [`PEAK_SPREAD_SAID`] of its time (or by about a sample on a log whose
//! grid limits it). Cut-offs are tried on a grid of two significant
//! digits (0.5 Hz steps below 10 Hz, 5 Hz to 100 Hz), above
//! [`MIN_FILTER_HZ`] and below the filter's limit. Units: Hz, s.

use super::super::{GRID_SAID, PEAK_SPREAD_SAID};
use super::rise_time;
use crate::format::{fixed, readable, rounded};
use crate::metrics::{below_filter_limit, StepMetrics, MIN_FILTER_HZ, PEAK_DRAWS};

/// How the peak read through a cut-off fails to stand above the noise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Loss {
    /// The run itself finds no peak above its noise threshold.
    NotFound,
    /// This many of the noisy copies lose it (find none, or only another
    /// maximum).
    Copies(usize),
    /// The copies move its time (the second, s) by this deviation, s.
    Moved(f64, f64),
}

impl Loss {
    /// The loss in words, after "at f Hz,".
    pub(crate) fn words(self) -> String {
        match self {
            Loss::NotFound => "the run finds no yaw-rate peak above its noise threshold".into(),
            Loss::Copies(k) => format!(
                "{k} of the {PEAK_DRAWS} copies of the run with its noise added again lose it"
            ),
            Loss::Moved(sd, tp) => format!(
                "the copies of the run with its noise added again move its time, {} s, by ±{} s",
                readable(tp, 3),
                readable(sd, 2)
            ),
        }
    }
}

/// The peak read through one cut-off.
#[derive(Debug, Clone, Copy, PartialEq)]
enum PeakAt {
    /// No peak found (none, or lost under the noise threshold).
    Absent,
    /// Above the noise.
    Holds,
    /// Found, but not above the noise.
    Lost(Loss),
}

/// The peak of the run measured as `m`, sampled every `dt` s (module
/// notes).
fn peak_at(m: &StepMetrics, dt: f64) -> PeakAt {
    let Some(tp) = m.yaw_rate_peak_time else {
        return PeakAt::Absent;
    };
    let (Some(sd), Some(found)) = (m.yaw_rate_peak_time_spread, m.yaw_rate_peak_found_share) else {
        // No noise measured: nothing to lose it in.
        return PeakAt::Holds;
    };
    if found < 0.75 {
        let kept = (found * PEAK_DRAWS as f64).round() as usize;
        return PeakAt::Lost(Loss::Copies(PEAK_DRAWS.saturating_sub(kept)));
    }
    let coarse = 0.5 * dt >= GRID_SAID * tp.abs();
    let grid_limited = coarse && sd / 2f64.sqrt() <= dt;
    match sd >= PEAK_SPREAD_SAID * tp.abs() && !grid_limited {
        true => PeakAt::Lost(Loss::Moved(sd, tp)),
        false => PeakAt::Holds,
    }
}

/// What the noise leaves of the cut-offs from `least` (the rise rule's).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum NoiseBound {
    /// The peak holds at every cut-off from `least` to below the limit.
    Holds,
    /// It holds from `least` up to `upto`, Hz, and is lost at `past`.
    Upto { upto: f64, past: f64, why: Loss },
    /// It is lost at `least` already (`why`), and holds at `holds_at` Hz
    /// or below, the highest cut-off tried below `least` where it does
    /// (none above [`MIN_FILTER_HZ`]).
    Lost { why: Loss, holds_at: Option<f64> },
    /// The run finds no peak at any cut-off tried: nothing to keep.
    NoPeak,
}

/// [`NoiseBound`] of the run sampled every `dt` s, measured through a
/// cut-off by `metrics_at`, from the rise rule's least cut-off `least`.
pub(crate) fn noise_bound(
    least: f64,
    dt: f64,
    metrics_at: &dyn Fn(f64) -> Option<StepMetrics>,
) -> NoiseBound {
    let probe = |f: f64| metrics_at(f).map_or(PeakAt::Absent, |m| peak_at(&m, dt));
    let first = probe(least);
    if first == PeakAt::Holds {
        let mut upto = least;
        for c in grid_up(least, dt) {
            let why = match probe(c) {
                PeakAt::Holds => {
                    upto = c;
                    continue;
                }
                PeakAt::Lost(why) => why,
                PeakAt::Absent => Loss::NotFound,
            };
            return NoiseBound::Upto { upto, past: c, why };
        }
        return NoiseBound::Holds;
    }
    let why = match first {
        PeakAt::Lost(why) => why,
        _ => Loss::NotFound,
    };
    let mut found = matches!(first, PeakAt::Lost(_));
    for c in grid_down(least) {
        match probe(c) {
            PeakAt::Holds => {
                return NoiseBound::Lost {
                    why,
                    holds_at: Some(c),
                }
            }
            PeakAt::Lost(_) => found = true,
            PeakAt::Absent => {}
        }
    }
    match found {
        true => NoiseBound::Lost {
            why,
            holds_at: None,
        },
        false => NoiseBound::NoPeak,
    }
}

/// Where the peak holds below the rise rule's cut-off, in words: the
/// highest cut-off, with the filter's rise there as a share of the yaw
/// rate's response time, or that none above [`MIN_FILTER_HZ`] does.
pub(crate) fn held_at(
    holds_at: Option<f64>,
    dt: f64,
    metrics_at: &dyn Fn(f64) -> Option<StepMetrics>,
) -> String {
    let Some(h) = holds_at else {
        return format!(
            "; it stands above the noise at no cut-off above {} Hz",
            crate::error::Num(MIN_FILTER_HZ)
        );
    };
    let response = metrics_at(h).map(|m| m.yaw_rate_response_time);
    match response.filter(|r| *r > 0.0) {
        Some(r) => format!(
            "; it stands above the noise at {} Hz or less, where the filter's rise is {} % of the yaw rate's response time",
            rounded(h, 2),
            fixed(100.0 * rise_time(dt, h) / r, 0)
        ),
        None => format!("; it stands above the noise at {} Hz or less", rounded(h, 2)),
    }
}

/// The grid's step at `v`, Hz: two significant digits, the second in
/// halves of the first's unit (0.5 Hz below 10 Hz).
fn step(v: f64) -> f64 {
    0.5 * 10f64.powf(v.log10().floor())
}

/// The grid's cut-offs above `least`, below the filter's limit on a log
/// sampled every `dt` s, ascending.
fn grid_up(least: f64, dt: f64) -> Vec<f64> {
    let st = step(least);
    let mut c = ((least / st).floor() + 1.0) * st;
    let mut out = Vec::new();
    while below_filter_limit(c, dt) && out.len() < 64 {
        out.push(c);
        let st = step(c);
        c = ((c + st) / st).round() * st;
    }
    out
}

/// The grid's cut-offs below `least`, above [`MIN_FILTER_HZ`], descending.
fn grid_down(least: f64) -> Vec<f64> {
    let below = |v: f64| step(v * (1.0 - 1e-9));
    let st = below(least);
    let mut c = ((least / st).ceil() - 1.0) * st;
    let mut out = Vec::new();
    while c > MIN_FILTER_HZ && out.len() < 64 {
        out.push(c);
        let st = below(c);
        c = ((c - st) / st).round() * st;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two significant digits either way, from a cut-off off the grid or
    /// on it, across a decade; never the limit or 1 Hz.
    #[test]
    fn the_cutoffs_tried_lie_on_a_grid_of_two_significant_digits() {
        let up = grid_up(6.5, 0.04);
        assert_eq!(up, [7.0, 7.5, 8.0, 8.5, 9.0, 9.5]);
        let up = grid_up(8.7, 0.01);
        assert_eq!(up, [9.0, 9.5, 10.0, 15.0, 20.0, 25.0, 30.0, 35.0]);
        let down = grid_down(3.0);
        assert_eq!(down, [2.5, 2.0, 1.5]);
        let down = grid_down(15.0);
        assert_eq!(&down[..3], [10.0, 9.5, 9.0]);
        assert_eq!(*down.last().unwrap(), 1.5);
    }

    /// A run measured with no peak at any cut-off has none to keep; one
    /// lost above 5.5 Hz is bounded there.
    #[test]
    fn the_bound_is_the_highest_cutoff_at_which_the_peak_holds() {
        let none = |_: f64| None;
        assert_eq!(noise_bound(6.5, 0.04, &none), NoiseBound::NoPeak);
        // A first-order step measured, its peak then set by hand.
        let t: Vec<f64> = (0..600).map(|i| f64::from(i) * 0.01).collect();
        let steer: Vec<f64> = t
            .iter()
            .map(|&s| 0.02 * ((s - 1.0) / 0.1).clamp(0.0, 1.0))
            .collect();
        let r: Vec<f64> = t
            .iter()
            .map(|&s| 0.1 * (1.0 - (-3.0 * (s - 1.0).max(0.0)).exp()))
            .collect();
        let settings = crate::metrics::MetricSettings::default();
        let base = crate::metrics::step_metrics(&t, &steer, &r, None, None, &settings).unwrap();
        let m = |f: f64| {
            let mut m = base;
            m.yaw_rate_peak_time = Some(0.35);
            m.yaw_rate_peak_time_spread = Some(0.01);
            m.yaw_rate_peak_found_share = Some(if f <= 5.5 { 1.0 } else { 0.5 });
            Some(m)
        };
        assert_eq!(
            noise_bound(6.5, 0.04, &m),
            NoiseBound::Lost {
                why: Loss::Copies(16),
                holds_at: Some(5.5)
            }
        );
        assert_eq!(
            noise_bound(4.0, 0.04, &m),
            NoiseBound::Upto {
                upto: 5.5,
                past: 6.0,
                why: Loss::Copies(16)
            }
        );
    }
}
