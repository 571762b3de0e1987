//! The metric table of a step run as the terminal prints it (`metrics`,
//! `simulate`): one line per GB/T 6323 / ISO 7401 metric in its unit
//! (times s, the steer step deg, the gain 1/s, steady ay m/s², steady
//! sideslip deg, TB s·deg, total variances s), `—` where a response lacks
//! one, the metrics read against a steady value the run never reaches
//! marked, and the notes on filtering and overshoot after it.

use crate::metrics::StepMetrics;

/// The mark of a metric read against a steady value its channel never
/// reaches (explained by [`unsteady_note`]).
const UNSTEADY_MARK: &str = "  (no steady state)";

/// Whether the yaw rate and the lateral acceleration drift without
/// slowing across the steady window: no steady state is in the record, and
/// every metric defined against one (a 90 % crossing, an overshoot, a
/// gain, a total variance) measures a level the response passes on its
/// way, not the car's response. A drift that slows, or a spread about a
/// steady value, bounds how far the steady value read may be off (the
/// warning says how far); the metrics stand with that bound.
fn unsteady_channels(m: &StepMetrics) -> (bool, bool) {
    let drifting = |s: Option<crate::metrics::Settling>| {
        matches!(
            s,
            Some(crate::metrics::Settling::Drifting {
                converging: false,
                ..
            })
        )
    };
    (drifting(Some(m.settling.yaw_rate)), drifting(m.settling.ay))
}

/// The line after the table saying what the marked metrics are.
fn unsteady_note(yaw: bool, ay: bool) -> Option<String> {
    let which = match (yaw, ay) {
        (true, true) => "the yaw rate and the lateral acceleration drift",
        (true, false) => "the yaw rate drifts",
        (false, true) => "the lateral acceleration drifts",
        (false, false) => return None,
    };
    Some(format!(
        "  no steady state: {which} without slowing through the steady window (see the warning), so the metrics marked \"(no steady state)\" are read against a level the response passes on its way, not a steady state it reaches: a 90 % crossing of that level is no response time, and an overshoot above it is not defined (a record held until the response settles reads them)"
    ))
}

/// The ay response time's cell: below one sample interval where the log
/// cannot read it (a warning says why), `—` without `ay`.
fn ay_response_cell(m: &StepMetrics) -> String {
    match (m.ay_response_time_below, m.ay_response_time) {
        (Some(dt), _) => format!("< {}", crate::format::rounded(dt, 3)),
        (None, Some(t)) => crate::format::fixed(t, 4),
        (None, None) => "—".to_string(),
    }
}

/// The metric table: one line per metric, `—` where a response lacks one,
/// and the notes on filtering and overshoot (a response that has not
/// settled is a warning of the report: [`StepMetrics::settling_warning`]).
pub(crate) fn metric_lines(m: &StepMetrics) -> Vec<String> {
    // `0.0000`, never `-0.0000`: a value that rounds to zero has no sign.
    let opt = |v: Option<f64>, scale: f64| {
        v.map_or("—".to_string(), |x| crate::format::fixed(x * scale, 4))
    };
    let (yaw, ay) = unsteady_channels(m);
    let mark = |unsteady: bool| if unsteady { UNSTEADY_MARK } else { "" };
    let mut out = vec![
        format!(
            "  steer step               {:>10.4} deg",
            m.steer_step.to_degrees()
        ),
        format!(
            "  yaw-rate response time   {:>10.4} s{}",
            m.yaw_rate_response_time,
            mark(yaw)
        ),
        format!(
            "  yaw-rate peak time       {:>10} s",
            opt(m.yaw_rate_peak_time, 1.0)
        ),
        // Without a peak the overshoot is below what the run resolves (the
        // line after the table says how far), not a measured 0.
        format!(
            "  yaw-rate overshoot       {:>10} %{}",
            match m.yaw_rate_overshoot {
                Some(percent) => format!("{percent:.2}"),
                // Withheld, beyond a spin's, or above a level the yaw rate
                // drifts past: a warning or the note says why.
                None if yaw || m.yaw_rate_peak_unmeasured || m.overshoot_unresolved() => {
                    "—".into()
                }
                None => format!("< {}", crate::format::rounded(m.yaw_rate_peak_threshold, 3)),
            },
            mark(yaw && m.yaw_rate_overshoot.is_some())
        ),
        format!(
            "  ay response time         {:>10} s{}",
            ay_response_cell(m),
            mark(ay && m.ay_response_time.is_some())
        ),
        format!(
            "  yaw-rate gain            {:>10} 1/s{}",
            crate::format::fixed(m.yaw_rate_gain, 4),
            mark(yaw)
        ),
        format!(
            "  steady ay                {:>10} m/s²{}",
            opt(m.ay_steady, 1.0),
            mark(ay && m.ay_steady.is_some())
        ),
        format!(
            "  steady sideslip          {:>10} deg",
            opt(m.beta_steady, 180.0 / std::f64::consts::PI)
        ),
        format!(
            "  TB                       {:>10} s·deg{}",
            opt(m.tb, 1.0),
            mark(yaw && m.tb.is_some())
        ),
        format!(
            "  E_r (yaw rate)           {:>10} s{}",
            crate::format::fixed(m.yaw_rate_total_variance, 4),
            mark(yaw)
        ),
        format!(
            "  E_ay                     {:>10} s{}",
            opt(m.ay_total_variance, 1.0),
            mark(ay && m.ay_total_variance.is_some())
        ),
        format!(
            "  Er                       {:>10} s{}",
            opt(m.er, 1.0),
            mark((yaw || ay) && m.er.is_some())
        ),
    ];
    out.extend(unsteady_note(yaw, ay));
    out.extend(notes_after(m, yaw));
    out
}

/// The notes after the table: the low-pass the metrics were read
/// through, and where no peak stands out, the bound the overshoot stays
/// under (none where the yaw rate drifts past its window: `drifting`).
fn notes_after(m: &StepMetrics, drifting: bool) -> Vec<String> {
    let mut out = Vec::new();
    if let Some(f) = m.filter_hz {
        out.push(format!(
            "  filtered: zero-phase 2nd-order Butterworth low-pass at {f} Hz; yaw-rate noise {}",
            m.yaw_rate_noise_text()
        ));
    }
    // A withheld peak's warning says why; it is no overshoot below a bound
    // (nor above a level the yaw rate drifts past: the note says so).
    if m.yaw_rate_peak_time.is_none()
        && !drifting
        && !m.yaw_rate_peak_unmeasured
        && !m.overshoot_unresolved()
    {
        let why = match m.yaw_rate_filter_ringing {
            0.0 => "the larger of min_overshoot and what the noise and the steady scatter allow".to_string(),
            // The filter's own overshoot on the steer step: a maximum
            // within it is the low-pass ringing, not the car.
            ringing => format!(
                "the largest of min_overshoot, what the noise and the steady scatter allow, and the {} % the low-pass alone lifts the steer step by: a maximum within that is the filter ringing, not the car",
                crate::format::rounded(ringing, 3)
            ),
        };
        out.push(format!(
            "  no overshoot: no yaw-rate maximum stands more than {} % above the steady state ({why})",
            crate::format::rounded(m.yaw_rate_peak_threshold, 3)
        ));
    }
    out
}
