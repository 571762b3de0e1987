//! What a log's sample interval limits in the step-steer metrics, said
//! where it does: a steer rise within one sample interval (the step is
//! faster than the log: a 1 ms step at 100 Hz read "rise 0.008 s"; its
//! onset, and every time from it, known to half an interval), a
//! response time within two (its crossing interpolated between samples
//! that far apart: a 7 Hz log read the yaw rate's 0.132 s as 0.167 s), and
//! the total variances of a log of 10 Hz or slower or of a step inside one
//! interval, biased by where the samples fall on the step.
//!
//! The biases are measured on the linear 2-DOF car of the fresh-eyes
//! round 15 (1530 kg, 2315 kg·m², a = 1.11 m, b = 1.67 m, 100/140 kN/rad
//! axles, a 0.01 rad step over 0.1 s at 25 m/s), whose 1 kHz record gives
//! the closed form's E_r 0.0245 s, E_ay 0.0242 s and yaw-rate response time
//! 0.132 s: logged every 0.1 s it reads E_r +29 %, E_ay +10 %; every 0.143 s
//! (7 Hz) E_r +27 %, E_ay +96 %, the response time +26 %; every 0.08 s
//! E_r −7 %, every 0.05 s +8 % (the response time +2 %). The same car's
//! instant 0.01 rad step at 25 m/s (E_r 0.0442 s at 1 kHz) reads E_r +11 %
//! at 100 Hz, +23 % at 50 Hz and +63 % at 20 Hz: its onset is placed up to
//! half an interval early. Units: s.

use crate::metrics::StepMetrics;

/// The sample interval from which the total variances are said, s: 10 Hz.
pub const VARIANCE_COARSE: f64 = 0.1;

/// How many sample intervals a response time must span to be given
/// without its resolution.
pub const RESPONSE_INTERVALS: f64 = 2.0;

/// The warnings of what the sample interval `dt` (s) limits in `m`, with
/// the steer's 10–90 % rise `steer_rise` (s).
pub fn coarse_said(m: &StepMetrics, dt: f64, steer_rise: f64) -> Vec<String> {
    let mut said = Vec::new();
    if !(dt.is_finite() && dt > 0.0) {
        return said;
    }
    let hz = crate::format::rounded(1.0 / dt, 3);
    let interval = crate::format::rounded(dt, 3);
    // A step inside one interval has its onset known only to about half
    // an interval, and every time measured from it carries that.
    let unresolved = steer_rise < dt;
    if unresolved {
        said.push(format!(
            "the steer's 10–90 % rise reads {} s, within one {interval} s sample interval of a {hz} Hz log: the step is faster than the log resolves, and its rise is only known to be under {interval} s; its onset, and every time measured from it (response times, peak time, E_r, E_ay), is uncertain by about half an interval, ±{} s",
            crate::format::fixed(steer_rise, 3),
            crate::format::rounded(dt / 2.0, 3)
        ));
    }
    let times = [
        ("yaw-rate", Some(m.yaw_rate_response_time)),
        ("ay", m.ay_response_time),
    ];
    for (name, t) in times {
        let Some(t) = t.filter(|t| *t < RESPONSE_INTERVALS * dt) else {
            continue;
        };
        said.push(format!(
            "the {name} response time, {} s, spans {} sample intervals of a {hz} Hz log: a crossing interpolated between samples {interval} s apart is limited by the sample interval (a 7 Hz log of a linear car's step read its 0.132 s yaw-rate response time as 0.167 s, +26 %); log at {} Hz or faster to read it finer",
            crate::format::fixed(t, 3),
            crate::format::rounded(t / dt, 2),
            crate::format::readable(RESPONSE_INTERVALS / t, 2)
        ));
    }
    // The median interval of a 10 Hz log may read a hair under 0.1 s.
    if dt >= VARIANCE_COARSE * (1.0 - 1e-6) || unresolved {
        said.push(format!(
            "E_r{} are integrals over samples {interval} s apart ({hz} Hz): on a log of 10 Hz or slower, or of a step faster than one interval, they are biased by where the samples fall on the step (a linear car's step ramped over 0.1 s, E_r 0.0245 s and E_ay 0.0242 s at 1 kHz, read E_r +29 % and E_ay +10 % at 10 Hz, E_r +27 % and E_ay ×2.0 at 7 Hz, within 10 % at 12.5 Hz and faster; an instant step the log does not resolve, E_r 0.0442 s at 1 kHz, read +11 % at 100 Hz, +23 % at 50 Hz, +63 % at 20 Hz): log at 20 Hz or faster, and ramp the step over a few intervals, to compare them",
            if m.ay_total_variance.is_some() {
                ", E_ay and Er"
            } else {
                ""
            }
        ));
    }
    said
}
