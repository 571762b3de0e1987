//! The metric table of a step run as the terminal prints it (`metrics`,
//! `simulate`): one line per GB/T 6323 / ISO 7401 metric in its unit
//! (times s, the steer step deg, the gain 1/s, steady ay m/s², steady
//! sideslip deg, TB s·deg, total variances s), `—` where a response lacks
//! one, the metrics read against a steady value the run never reaches
//! marked, and the notes on filtering and overshoot after it.

use crate::metrics::{Mark, MarkedMetric, Marks, StepMetrics};

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

/// One table line: `label` padded, `value` right-aligned, `unit` and the
/// metric's marks ([`StepMetrics::marks`]: the JSON's `marks` alike).
fn row(label: &str, value: String, unit: &str, marks: &[Mark]) -> String {
    let said: String = marks.iter().map(|m| m.text()).collect();
    format!("  {label:<25}{value:>10} {unit}{said}")
}

/// The overshoot's cell: measured, `—` where it is withheld, beyond a
/// spin's, above a level the yaw rate drifts past (`drifting`) or read
/// against a window the yaw rate still moves in (no steady value to bound
/// it by: a warning or a note says why), or below the threshold the run
/// resolves (the line after the table says how far), not a measured 0.
fn overshoot_cell(m: &StepMetrics, drifting: bool) -> String {
    match m.yaw_rate_overshoot {
        Some(percent) => format!("{percent:.2}"),
        None if drifting
            || m.yaw_rate_window_moving
            || m.yaw_rate_peak_unmeasured
            || m.overshoot_unresolved() =>
        {
            "—".into()
        }
        None => format!("< {}", crate::format::rounded(m.yaw_rate_peak_threshold, 3)),
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
    let fixed = |v: f64| crate::format::fixed(v, 4);
    let (yaw, ay) = m.drifting_channels();
    let moving = m.yaw_rate_window_moving && !yaw;
    let ay_moving = m.ay_window_moving && !ay;
    let beta_moving = m.beta_window_moving && m.beta_steady.is_some();
    let marks = m.marks();
    let of = |metric: MarkedMetric| marks.get(&metric).map_or(&[][..], |v| v.as_slice());
    use MarkedMetric as M;
    let mut out = vec![
        row(
            "steer step",
            format!("{:.4}", m.steer_step.to_degrees()),
            "deg",
            &[],
        ),
        row(
            "yaw-rate response time",
            format!("{:.4}", m.yaw_rate_response_time),
            "s",
            of(M::YawRateResponseTime),
        ),
        row(
            "yaw-rate peak time",
            opt(m.yaw_rate_peak_time, 1.0),
            "s",
            of(M::YawRatePeakTime),
        ),
        row(
            "yaw-rate overshoot",
            overshoot_cell(m, yaw),
            "%",
            of(M::YawRateOvershoot),
        ),
        row(
            "ay response time",
            ay_response_cell(m),
            "s",
            of(M::AyResponseTime),
        ),
        row(
            "yaw-rate gain",
            fixed(m.yaw_rate_gain),
            "1/s",
            of(M::YawRateGain),
        ),
        row("steady ay", opt(m.ay_steady, 1.0), "m/s²", of(M::AySteady)),
        row(
            "steady sideslip",
            opt(m.beta_steady, 180.0 / std::f64::consts::PI),
            "deg",
            of(M::BetaSteady),
        ),
        row("TB", opt(m.tb, 1.0), "s·deg", of(M::Tb)),
    ];
    out.extend(variance_rows(m, &marks));
    out.extend(unsteady_note(yaw, ay));
    out.extend((moving || ay_moving || beta_moving).then(|| moving_note(moving, ay_moving)));
    out.extend(m.total_variance_window_cut.map(cut_note));
    out.extend(m.steer_logged_late.map(misaligned_note));
    out.extend(before_note(&marks));
    out.extend(notes_after(m, yaw || moving));
    out
}

/// The total variances' lines with their marks.
fn variance_rows(m: &StepMetrics, marks: &Marks) -> Vec<String> {
    let opt = |v: Option<f64>| v.map_or("—".to_string(), |x| crate::format::fixed(x, 4));
    let of = |metric: MarkedMetric| marks.get(&metric).map_or(&[][..], |v| v.as_slice());
    vec![
        row(
            "E_r (yaw rate)",
            crate::format::fixed(m.yaw_rate_total_variance, 4),
            "s",
            of(MarkedMetric::YawRateTotalVariance),
        ),
        row(
            "E_ay",
            opt(m.ay_total_variance),
            "s",
            of(MarkedMetric::AyTotalVariance),
        ),
        row("Er", opt(m.er), "s", of(MarkedMetric::Er)),
    ]
}

/// That the steady sideslip is a change, from the sideslip `start` (rad)
/// the run holds before its step: every metric is a change from the
/// initial window. `simulate` says it of a step from its trim, `metrics`
/// of a run that starts with sideslip ([`sideslip_line`]): one set of
/// words.
pub(crate) fn sideslip_is_its_change(start: f64) -> String {
    format!(
        "the steady sideslip is its change from the {}° the run holds before the step",
        crate::format::fixed(start.to_degrees(), 4)
    )
}

/// The line after a measured run's table where it starts with sideslip
/// `start` (rad) and changes by `change` (rad): the steady sideslip is
/// that change, and where the sideslip ends.
pub(crate) fn sideslip_line(start: f64, change: f64) -> String {
    format!(
        "  sideslip: {}, to {}° over the steady window",
        sideslip_is_its_change(start),
        crate::format::fixed((start + change).to_degrees(), 4)
    )
}

/// The line after the table saying what "(before the steer)" marks: a
/// 90 % crossing before the steer reaches half its step is no lag.
fn before_note(marks: &Marks) -> Option<String> {
    marks
        .values()
        .any(|v| v.contains(&Mark::BeforeTheSteer))
        .then(|| {
            "  before the steer: a response time marked \"(before the steer)\" is a 90 % crossing read before the steer reaches half its step, which no lag gives: the response's noise (see the warnings for its spread) or channels logged out of step, not the car's response time".to_string()
        })
}

/// The line after the table saying what "(moving window)" marks: the
/// yaw rate's metrics (`yaw`), the ay metrics (`ay`), or where neither
/// moves, the steady sideslip's and TB.
fn moving_note(yaw: bool, ay: bool) -> String {
    let which = match (yaw, ay) {
        (true, true) => "the yaw rate and the lateral acceleration still move",
        (true, false) => "the yaw rate still moves",
        (false, true) => "the lateral acceleration still moves",
        (false, false) => "the sideslip still moves",
    };
    let overshoot = match yaw {
        true => "; no overshoot is measured where no maximum stands out above that mean (the steady value it would be bounded by is not in the record, and the overshoot may be larger), and one found is read against that mean",
        false => "",
    };
    format!(
        "  moving window: {which} in the steady window (see the warning), so the metrics marked \"(moving window)\" are read against the mean of a window the response passes through, not a steady state it holds{overshoot}: a record held until the response settles reads them"
    )
}

/// The line after the table saying what "(window cut short)" marks: total
/// variances integrated over the `span` s the record holds after the
/// steer's onset, less than the window set.
fn cut_note(span: f64) -> String {
    let span = crate::format::readable(span, 3);
    format!(
        "  window cut short: the record ends {span} s after the steer's onset, inside the total-variance window (variance_window), so the total variances marked \"(window cut short)\" integrate over those {span} s only and compare with no run measured over the whole window: a longer record reads them"
    )
}

/// The line after the table saying what "(steer misaligned)" marks, for
/// a steer logged `late` s late against the yaw rate.
fn misaligned_note(late: f64) -> String {
    format!(
        "  steer misaligned: the yaw rate moves {} s before the steer does (see the warning), so the metrics marked \"(steer misaligned)\" are timed from a steer logged late against the responses",
        crate::format::readable(late, 3)
    )
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
