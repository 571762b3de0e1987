//! A stated low-pass (`--filter-hz`) slow enough to measure itself: the
//! zero-phase Butterworth the metrics read the run through has a step
//! response of its own, and where its rise time is a fair share of the
//! car's response time the metrics (response and peak times, the total
//! variances, E_r) describe the filter as much as the car. The book refuses
//! a cutoff at or below 1 Hz outright; above it the run decides, so it is
//! said with the numbers. A cutoff suggested is weighed against the run's
//! noise too: the higher it is, the more noise passes, and the yaw-rate
//! peak the noisy copies of the run (`metrics/peak.rs`) must find can be
//! lost in them (a 25 Hz log with 1.4 % noise was sent to 6.5 Hz, where 11
//! of 32 copies lose the peak); each candidate is measured through, and
//! where none keeps both the filter's rise and the peak, that is said.
//! Units: s, Hz.

use crate::format::{fixed, rounded, significant};
use crate::metrics::{zero_phase_low_pass, StepMetrics};

mod peak_noise;
use peak_noise::{held_at, noise_bound, NoiseBound};

/// Share of the yaw rate's response time the filter's own 10–90 % rise
/// time may reach unsaid. Measured on the bundled PAC89 sedan step
/// (`scenarios/step_gbt6323_pac89.toml`, noise-free, E_r 0.0236 s at
/// 20 Hz): at 10 Hz the rise is 27 % of the response and E_r moves 1.3 %;
/// at 5 Hz 54 % and 11 %; at 3 Hz 83 % and 27 %; at 2 Hz 108 % and 43 %.
/// From half, the filter moves the metrics by a tenth or more.
pub(super) const FILTER_RISE_SHARE: f64 = 0.5;

/// The 10–90 % rise time, s, of the zero-phase low-pass at `cutoff_hz`
/// applied to a unit step sampled every `dt` s.
fn rise_time(dt: f64, cutoff_hz: f64) -> f64 {
    // Long enough either side for the filter to settle (its impulse
    // response decays within a few periods of the cutoff).
    let half = (4.0 / (cutoff_hz * dt)).ceil() as usize + 2;
    let step: Vec<f64> = (0..2 * half)
        .map(|i| f64::from(u8::from(i >= half)))
        .collect();
    let y = zero_phase_low_pass(&step, dt, cutoff_hz);
    let crossing = |level: f64| {
        let i = y.iter().position(|&v| v >= level)?;
        let (a, b) = (y[i.checked_sub(1)?], y[i]);
        Some((i as f64 - 1.0 + (level - a) / (b - a)) * dt)
    };
    match (crossing(0.1), crossing(0.9)) {
        (Some(lo), Some(hi)) => hi - lo,
        _ => 0.0,
    }
}

/// The warning where the filter `m` was read through rises in more than
/// [`FILTER_RISE_SHARE`] of the yaw rate's response time, with the least
/// cutoff that keeps it within (`simulate`'s records are unfiltered, and a
/// filter there is judged without measuring again).
pub(crate) fn filter_measures_itself(m: &StepMetrics, dt: f64) -> Option<String> {
    filter_measures_itself_with(m, dt, &|_| None)
}

/// [`filter_measures_itself`] where `metrics_at` measures the run through
/// a low-pass at a given cutoff (none where it cannot), so that the cutoff
/// suggested is one that, followed, is not warned of: its filter's rise
/// within the share, and, where the run has a yaw-rate peak, the peak
/// standing above the run's noise there ([`NoiseBound`]), or said lost.
pub(crate) fn filter_measures_itself_with(
    m: &StepMetrics,
    dt: f64,
    metrics_at: &dyn Fn(f64) -> Option<StepMetrics>,
) -> Option<String> {
    let f = m.filter_hz?;
    let response = m.yaw_rate_response_time;
    let rise = rise_time(dt, f);
    let share = rise / response;
    (response > 0.0 && share > FILTER_RISE_SHARE).then(|| {
        let least = least_cutoff(f * share / FILTER_RISE_SHARE, dt, metrics_at);
        let noise = match noise_bound(least, dt, metrics_at) {
            NoiseBound::Lost { why, holds_at } => format!(
                ", but there the yaw-rate peak does not stand above the run's noise ({}){}: no cutoff keeps both, and below it the filter's rise is in the response and peak times",
                why.words(),
                held_at(holds_at, dt, metrics_at),
            ),
            _ => String::new(),
        };
        format!(
            "the low-pass at {} Hz rises (10–90 %) in {} s, {} % of the yaw rate's response time of {} s: the response and peak times, the total variances and E_r measure the filter as much as the car; a cutoff of {} Hz or more keeps its rise within {} % (or filter less and accept more noise){noise}",
            crate::error::Num(f),
            significant(rise, 2),
            // Not "50 %" beside "within 50 %" for 50.3 %.
            crate::format::fixed_apart(&[100.0 * share, 100.0 * FILTER_RISE_SHARE], 0)[0],
            significant(response, 3),
            rounded(least, 2),
            fixed(100.0 * FILTER_RISE_SHARE, 0),
        )
    })
}

/// The warning where the cut-off `f` (Hz) asked is not below 0.4 × the
/// run's sampling rate (every `dt` s) and the run is read unfiltered: said
/// as the default where it is one (a log at 25 Hz or slower meets the
/// default 10 Hz so, without the user asking for it), with the cut-offs
/// that do filter it with the filter's own rise within
/// [`FILTER_RISE_SHARE`] of the yaw rate's response time (`response`, s;
/// `metrics_at` measures the run through a cut-off) and the yaw-rate peak
/// above the run's noise ([`NoiseBound`]), or that none does. The
/// overshoot's threshold and every time are then the unfiltered run's.
pub(super) fn not_filtered(
    f: f64,
    dt: f64,
    response: f64,
    metrics_at: &dyn Fn(f64) -> Option<StepMetrics>,
) -> String {
    let rate = 1.0 / dt;
    let top = 0.4 * rate;
    let whose = match f == crate::metrics::MEASURED_FILTER_HZ {
        true => " (the default of `--filter-hz`)",
        false => "",
    };
    // The filter rises in about 0.45/f s (tests below): the first guess
    // of the cut-off whose rise is the share of the response.
    let guess = 0.45 / (FILTER_RISE_SHARE * response);
    let least = (response > 0.0).then(|| least_cutoff(guess, dt, metrics_at));
    let within = format!(
        "its own rise (10–90 %) within {} % of the yaw rate's response time of {} s",
        fixed(100.0 * FILTER_RISE_SHARE, 0),
        significant(response, 3),
    );
    let advice = match least.filter(|l| *l < top) {
        Some(l) => match noise_bound(l, dt, metrics_at) {
            NoiseBound::Upto { upto, past, why } => format!(
                "--filter-hz from {} Hz to {} Hz filters it, {within} and the yaw-rate peak above the run's noise (at {} Hz, {})",
                rounded(l, 2),
                rounded(upto, 2),
                rounded(past, 2),
                why.words(),
            ),
            NoiseBound::Lost { why, holds_at } => format!(
                "no cut-off below {} Hz filters it with both {within} ({} Hz or more) and the yaw-rate peak above the run's noise (at {} Hz, {}{}): {}",
                rounded(top, 3),
                rounded(l, 2),
                rounded(l, 2),
                why.words(),
                held_at(holds_at, dt, metrics_at),
                choice(holds_at, l),
            ),
            NoiseBound::Holds | NoiseBound::NoPeak => format!(
                "--filter-hz from {} Hz to below {} Hz filters it, {within}",
                rounded(l, 2),
                rounded(top, 3),
            ),
        },
        None => format!(
            "no cut-off below {} Hz filters it without its own rise (10–90 %) passing {} % of the yaw rate's response time of {} s: read it unfiltered (--filter-hz 0), or log faster",
            rounded(top, 3),
            fixed(100.0 * FILTER_RISE_SHARE, 0),
            significant(response, 3),
        ),
    };
    format!(
        "the low-pass at {} Hz{whose} is not below 0.4 × the run's sampling rate: the run is not filtered (0.4 × {} Hz = {} Hz; a cutoff at or above it is not applied), and its metrics, the overshoot's noise threshold with them, are the unfiltered run's; {advice}",
        crate::error::Num(f),
        rounded(rate, 3),
        rounded(top, 3),
    )
}

/// The choice left where no cut-off keeps both the filter's rise and the
/// peak: the highest that keeps the peak (`holds_at`, Hz), the least that
/// keeps the rise (`least`, Hz), or a better log.
fn choice(holds_at: Option<f64>, least: f64) -> String {
    let times = format!(
        "--filter-hz {} or more keeps the times, with no peak time to read",
        rounded(least, 2)
    );
    match holds_at {
        Some(h) => format!(
            "--filter-hz {} keeps the peak, with the filter's rise in the times; {times}; or log faster or with a quieter gyro",
            rounded(h, 2)
        ),
        None => format!("{times}; or log with a quieter gyro"),
    }
}

/// The least cutoff, two significant digits rounded up, from the first
/// guess `guess`, Hz: the guess scales the cutoff against the response
/// time the slow filter stretched, and through the faster filter the
/// response is quicker, so the filter's share of it is larger than guessed
/// (the sedan's step: 2 Hz suggested 4.3 Hz, which was warned of at 56 %
/// with 4.8 Hz suggested). Each guess is measured through and raised until
/// its share holds (a fixed point of cutoff and response, a few steps).
fn least_cutoff(guess: f64, dt: f64, metrics_at: &dyn Fn(f64) -> Option<StepMetrics>) -> f64 {
    let up = |v: f64| {
        let s = crate::format::rounded_up(v, 2);
        s.parse().unwrap_or(v)
    };
    let mut least = up(guess);
    for _ in 0..10 {
        let Some(response) = metrics_at(least)
            .map(|m| m.yaw_rate_response_time)
            .filter(|r| *r > 0.0)
        else {
            break;
        };
        let share = rise_time(dt, least) / response;
        if share <= FILTER_RISE_SHARE {
            break;
        }
        least = up(least * share / FILTER_RISE_SHARE);
    }
    least
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rise_time_falls_as_the_cutoff_rises_and_matches_a_fourth_order_butterworth() {
        // Forward and backward through a second-order Butterworth: the
        // squared magnitude 1/(1 + (f/fc)⁴), zero phase. Its rise scales
        // as 1/fc (the sampling fine against both), about 0.45/fc: between
        // a first-order lag's 0.35/fc and a moving mean's 0.8 periods.
        let (r2, r4) = (rise_time(1e-3, 2.0), rise_time(1e-3, 4.0));
        assert!((r2 / r4 - 2.0).abs() < 0.02, "{r2} {r4}");
        assert!((0.40..0.50).contains(&(r2 * 2.0)), "{r2}");
    }
}
