//! The warning of response times and a yaw-rate gain that the run's own
//! noise moves by a twentieth of their value or more
//! (`metrics/crossing_spread.rs` measures how far): printed to four
//! digits without a word, a single noisy run's response time read as the
//! car's (the sedan's 1° step with gyro noise of 7 % of the step: 0.145 to
//! 0.229 s over seven seeds about the noise-free 0.188 s). Times in s;
//! the gain's spread a share of it.

use crate::format::{readable, rounded};
use crate::metrics::{StepMetrics, PEAK_DRAWS, PEAK_SEED};

/// The share of its value by which the noise must move a response time
/// or the gain to be said: a twentieth, as for the peak time
/// (`jobs/metrics.rs`).
pub const SPREAD_SAID: f64 = 0.05;

/// The warning, where the noise moves a response time or the gain by
/// [`SPREAD_SAID`] of its value or more.
pub(super) fn said(m: &StepMetrics) -> Option<String> {
    let time = |name: &str, value: Option<f64>, sd: Option<f64>| {
        let (v, sd) = (value?, sd?);
        (sd >= SPREAD_SAID * v.abs()).then(|| {
            format!(
                "the {name}, {} s, by ±{} s ({} %)",
                readable(v, 4),
                readable(sd, 2),
                rounded(100.0 * sd / v.abs(), 2)
            )
        })
    };
    let times: Vec<String> = [
        time(
            "yaw-rate response time",
            Some(m.yaw_rate_response_time),
            m.yaw_rate_response_time_spread,
        ),
        time(
            "ay response time",
            m.ay_response_time,
            m.ay_response_time_spread,
        ),
    ]
    .into_iter()
    .flatten()
    .collect();
    let gain = m
        .yaw_rate_gain_spread
        .filter(|s| *s >= SPREAD_SAID)
        .map(|s| {
            format!(
                "the yaw-rate gain, {} 1/s, by ±{} % (the noise of the initial and steady windows' means it is the ratio of, and a logger's rounding of them where a grid shows)",
                readable(m.yaw_rate_gain, 4),
                rounded(100.0 * s, 2)
            )
        });
    if times.is_empty() && gain.is_none() {
        return None;
    }
    let copies = (!times.is_empty()).then(|| {
        format!(
            "in {PEAK_DRAWS} copies of the run with its noise added again (seed {PEAK_SEED}), filtered as the run was, {} (one standard deviation, the initial and steady means' noise in it; it leans high: a copy carries the noise twice)",
            times.join(" and ")
        )
    });
    let parts: Vec<String> = copies.into_iter().chain(gain).collect();
    Some(format!(
        "the run's noise moves what it reads: {}; one run reads them no closer than that: filter harder (--filter-hz), log a larger step or quieter sensors, or average several runs",
        parts.join("; ")
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn metrics(tr_sd: f64, gain_sd: f64) -> StepMetrics {
        let mut m = crate::metrics::applicability::tests::moderate();
        m.yaw_rate_response_time = 0.2;
        m.ay_response_time = Some(0.45);
        m.yaw_rate_response_time_spread = Some(tr_sd);
        m.ay_response_time_spread = Some(0.01);
        m.yaw_rate_gain_spread = Some(gain_sd);
        m
    }

    #[test]
    fn a_response_time_the_noise_moves_by_a_twentieth_is_said_with_its_spread() {
        let w = said(&metrics(0.02, 0.01)).unwrap();
        assert!(
            w.contains("the yaw-rate response time, 0.2000 s, by ±0.020 s (10 %)"),
            "{w}"
        );
        // 0.01 s of 0.45 s is 2.2 %: not said; nor is a 1 % gain.
        assert!(
            !w.contains("the ay response time") && !w.contains("yaw-rate gain"),
            "{w}"
        );
    }

    #[test]
    fn spreads_below_a_twentieth_say_nothing_and_a_gain_alone_is_said_without_copies() {
        assert_eq!(said(&metrics(0.009, 0.049)), None);
        let w = said(&metrics(0.009, 0.06)).unwrap();
        assert!(w.contains("the yaw-rate gain") && w.contains("±6 %"), "{w}");
        assert!(!w.contains("copies"), "{w}");
    }
}
