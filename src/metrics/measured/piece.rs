//! One cleaned piece of a measured run measured: its masked responses
//! filled, put on one uniform grid (`uniform.rs`), the noise of each
//! channel a logger held between updates read on its updates
//! ([`held_noise_scale`](super::super::noise)), and a yaw-rate peak the log
//! does not measure withheld.
//!
//! A peak is not measured where the yaw rate there is not the sensor's
//! reading of the car: samples cleaning masked and filled with a straight
//! line (a gyro stuck at its saturation value: a 0.058 rad/s clip read an
//! overshoot of 3.47 % at 0.46 s for 6.23 % at 0.34 s), or a flat top at
//! the channel's largest value (a clip without noise, which no glitch scan
//! calls stuck: 3.62 % at 0.28 s). A peak within the low-pass's reach of
//! such a span (one period of the cut-off, or two samples unfiltered) is
//! the span's, so its time, overshoot and TB are withheld with the reason.
//! A hole of missing samples (`uniform.rs`) is such a span too: 4 missing
//! at the peak read 6.14 % at 0.35 s. A channel on a logger's grid repeats
//! its largest code over a smooth peak and is no clip. Units: SI, rad, s.

use super::super::step_shape::{check_steer_is_a_step, check_step_shape};
use super::super::{step_metrics_held, HeldEvery, MetricSettings, StepMetrics};
use super::{coarse_grid, hole_bound, steady_advice, uniform};
use crate::error::PieceRefusal;
use crate::measured::clean::{fill_masked_by_channel, CleaningReport, RunChannel};
use crate::measured::MeasuredRun;

/// Fewest samples of a span that makes a peak inside it unmeasured: one
/// masked sample (a spike) filled between its neighbours moves no peak.
const SPAN_SAMPLES: usize = 2;

/// Most steps of its smallest change a channel on a logger's grid spans
/// (as `noise.rs`'s): above it the channel is written to its digits.
const GRID_LEVELS: f64 = 65536.0;

/// The piece `piece` (cleaned, `found` its report) measured: the metrics,
/// the filled piece on its grid, and the warnings of what was done.
pub(super) fn measure(
    piece: &MeasuredRun,
    found: &CleaningReport,
    settings: &MetricSettings,
) -> Result<(StepMetrics, MeasuredRun, Vec<String>), PieceRefusal> {
    let filled = fill_masked_by_channel(piece, &found.glitches);
    // The low-pass's reach: one period of its cut-off, at least 2 samples.
    let dt = crate::measured::clean::median_interval(&piece.t);
    let reach = settings.filter_hz.map_or(0.0, |f| 1.0 / f).max(2.0 * dt);
    let mut spans = unmeasured(piece, &filled);
    spans.extend(
        crate::measured::clean::holes::holes(&filled.t)
            .into_iter()
            .map(|(from, length, missing)| {
                let window = reach.max(length).max(5.0 * dt);
                Span {
                    from,
                    to: from + length,
                    samples: missing,
                    why: "the log holds no sample (a hole in time, interpolated across)".into(),
                    bound: Some(hole_bound::interpolation_bound(
                        &filled.t,
                        &filled.yaw_rate,
                        from,
                        from + length,
                        window,
                    )),
                }
            }),
    );
    // The cleaning counts the whole log's missing rows; the warning the
    // piece's, beside that count.
    let log = found
        .missing_rows
        .iter()
        .fold((0, 0), |(s, h), m| (s + m.samples, h + m.holes));
    let (p, holes) = uniform::uniform(filled, Some(log));
    let every = |c: RunChannel| {
        found
            .held
            .iter()
            .find(|h| h.channel == c)
            .map_or(1, |h| h.every)
    };
    let every = HeldEvery {
        steer: every(RunChannel::Steer),
        yaw_rate: every(RunChannel::YawRate),
        ay: every(RunChannel::Ay),
        beta: every(RunChannel::Beta),
    };
    let (ay, beta) = (p.ay.as_deref(), p.beta.as_deref());
    let mut m = check_steer_is_a_step(&p.t, &p.steer)
        .and_then(|()| step_metrics_held(&p.t, &p.steer, &p.yaw_rate, ay, beta, settings, every))
        .and_then(|m| {
            check_step_shape(&p.t, &p.steer, &m, settings)
                .map(|()| m)
                .map_err(|e| steady_advice::with_advice(e, &p, settings))
        })
        .map_err(PieceRefusal::NoStepMetrics)?;
    // A logger's rounding of the held steer and yaw rate is no noise the
    // copies see: its deviation joins the gain's spread.
    if let Some(g) = coarse_grid::gain_rounding(piece, &m) {
        m.yaw_rate_gain_spread = Some(m.yaw_rate_gain_spread.map_or(g, |s| s.hypot(g)));
    }
    let mut warnings: Vec<String> = holes.into_iter().collect();
    warnings.extend(withhold_unmeasured_peak(&mut m, &spans, reach));
    warnings.extend(selected_by_noise(&m));
    warnings.extend(coarse_grid::coarse(piece, &m));
    warnings.extend(coarse_grid::coarse_steer(piece, &m));
    warnings.extend(coarse_grid::from_turn(piece, &m, settings.pre_window));
    Ok((m, p, warnings))
}

/// A span of yaw-rate samples the log does not measure: from, to (s), its
/// samples and why; for a hole in time, the bound of the straight line's
/// error across it (rad/s, `hole_bound.rs`; `Some(None)` where too few
/// samples read its curvature), which decides whether it hides the peak.
struct Span {
    from: f64,
    to: f64,
    samples: usize,
    why: String,
    bound: Option<Option<f64>>,
}

/// The spans of at least [`SPAN_SAMPLES`] yaw-rate samples cleaning
/// replaced (`filled` against `piece`), and the flat top of a yaw rate
/// held at its largest value (in the step's direction) that is not on a
/// logger's grid.
fn unmeasured(piece: &MeasuredRun, filled: &MeasuredRun) -> Vec<Span> {
    let (t, raw) = (&piece.t, &piece.yaw_rate);
    let replaced: Vec<bool> = raw
        .iter()
        .zip(&filled.yaw_rate)
        .map(|(a, b)| a != b && !(a.is_nan() && b.is_nan()))
        .collect();
    let mut out = runs(&replaced)
        .into_iter()
        .map(|(i, j)| Span {
            from: t[i],
            to: t[j - 1],
            samples: j - i,
            why: "cleaning masked them and filled them with a straight line".into(),
            bound: None,
        })
        .collect::<Vec<_>>();
    let (lo, hi) = extremes(raw);
    let last = raw.len().saturating_sub(1);
    // The step's direction: the end's value against the start's.
    let top = match raw.get(last).zip(raw.first()) {
        Some((e, s)) if e < s => lo,
        _ => hi,
    };
    if top.is_finite() && !on_grid(raw) {
        let flat: Vec<bool> = raw.iter().map(|x| *x == top).collect();
        out.extend(
            runs(&flat)
                .into_iter()
                .filter(|&(i, j)| j - i > SPAN_SAMPLES && j <= last)
                .map(|(i, j)| Span {
                    from: t[i],
                    to: t[j - 1],
                    samples: j - i,
                    why: format!(
                        "the yaw rate is flat at its largest value, {} rad/s, as a sensor clipped or saturated reads",
                        crate::format::readable(top, 4)
                    ),
                    bound: None,
                }),
        );
    }
    out
}

/// The index ranges `[i, j)` of the runs of `true` at least
/// [`SPAN_SAMPLES`] long.
fn runs(mask: &[bool]) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < mask.len() {
        if !mask[i] {
            i += 1;
            continue;
        }
        let j = (i..mask.len()).find(|&k| !mask[k]).unwrap_or(mask.len());
        if j - i >= SPAN_SAMPLES {
            out.push((i, j));
        }
        i = j;
    }
    out
}

fn extremes(x: &[f64]) -> (f64, f64) {
    x.iter()
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(*v), b.max(*v))
        })
}

/// Whether `x` is on a logger's grid: its range at most [`GRID_LEVELS`]
/// of its smallest non-zero change.
fn on_grid(x: &[f64]) -> bool {
    let step = x
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .filter(|d| *d > 0.0)
        .fold(f64::INFINITY, f64::min);
    let (lo, hi) = extremes(x);
    step.is_finite() && (hi - lo) / step <= GRID_LEVELS
}

/// Withholds `m`'s peak (time, overshoot, TB and their spreads) where it
/// lies within `reach` (s) of an unmeasured span; the warning. A hole in
/// time whose straight line is within the noise of the yaw rate (or,
/// without noise, within half the overshoot's last printed digit,
/// [`HOLE_FLOOR`]) hides nothing the noise does not (`hole_bound.rs`).
fn withhold_unmeasured_peak(m: &mut StepMetrics, spans: &[Span], reach: f64) -> Option<String> {
    let at = m.time_zero + m.yaw_rate_peak_time?;
    let step = m.yaw_rate_steady.abs();
    let tolerance = step * m.yaw_rate_noise.max(HOLE_FLOOR);
    let hides = |s: &Span| s.bound.is_none_or(|b| b.is_none_or(|b| b > tolerance));
    // The span nearest the peak is named: of a log's many holes, the first
    // within reach lay 0.08 s before a peak beside another.
    let off = |s: &Span| (s.from - at).max(at - s.to).max(0.0);
    let span = spans
        .iter()
        .filter(|s| off(s) <= reach && hides(s))
        .min_by(|a, b| off(a).total_cmp(&off(b)))?;
    m.yaw_rate_peak_time = None;
    m.yaw_rate_overshoot = None;
    m.tb = None;
    m.yaw_rate_peak_time_spread = None;
    m.yaw_rate_peak_found_share = None;
    m.yaw_rate_peak_stray_share = None;
    m.yaw_rate_overshoot_spread = None;
    m.yaw_rate_peak_unmeasured = true;
    let bound = match span.bound {
        None => String::new(),
        Some(None) => " (too few samples around it to bound the straight line's error)".into(),
        Some(Some(b)) => format!(
            " (the straight line across it may miss the yaw rate by up to {} % of the step, |r''|·L²/8 with its curvature there over the {} s without a sample, more than the noise's {} %)",
            crate::format::readable(100.0 * b / step, 2),
            crate::format::readable(span.to - span.from, 3),
            crate::format::readable(100.0 * tolerance / step, 2),
        ),
    };
    let d = off(span);
    let near = match d > 0.0 {
        false => "in".to_string(),
        true => format!("{} s beside", crate::format::readable(d, 2)),
    };
    Some(format!(
        "the yaw rate's largest value lies at {} s, {near} {} from {} to {} s where {}{bound}: the log does not measure the peak there, so the peak time, the overshoot and TB are withheld",
        crate::format::readable(at, 3),
        crate::format::plural(span.samples, "sample", "samples"),
        crate::format::readable(span.from, 3),
        crate::format::readable(span.to, 3),
        span.why
    ))
}

/// The least error, as a share of the step, a hole's straight line must
/// be able to make to hide the peak of a log without noise: half the last
/// digit of the overshoot printed to 0.01 %.
const HOLE_FLOOR: f64 = 5e-5;

/// Noise deviations (after the filter) above the threshold an overshoot
/// must stand to be read as the car's: below, the noise could have made
/// the maximum pass the threshold.
const SELECTED_NOISES: f64 = 3.0;

/// The warning of an overshoot within [`SELECTED_NOISES`] noise deviations
/// of the threshold a maximum must pass: only maxima above it are kept,
/// so the noise's lift is what is selected and the value is biased high
/// (a 6.23 % overshoot read 8.1–12.7 % in 10 of 40 noisy logs, the other
/// 30 reading "< 8–10 %"), by more than its spread, which is the noise's
/// scatter about the value, not its bias. Read as an upper bound, it
/// brackets the car's overshoot with the reports without a peak.
fn selected_by_noise(m: &StepMetrics) -> Option<String> {
    let overshoot = m.yaw_rate_overshoot?;
    let sigma = 100.0 * m.yaw_rate_noise;
    let floor = m.yaw_rate_peak_threshold;
    (sigma > 0.0 && overshoot - SELECTED_NOISES * sigma < floor).then(|| {
        format!(
            "the overshoot, {} %, is an upper bound, not a measurement: it stands within {SELECTED_NOISES} noise deviations ({} % of the step each) of the {} % a maximum must pass to be a peak, and only maxima above that are kept, so the noise's lift is selected and the car's overshoot may be anywhere below {} % (the peak time with it); filter harder (--filter-hz) or log a quieter gyro",
            crate::format::fixed(overshoot, 2),
            crate::format::readable(sigma, 2),
            crate::format::readable(floor, 3),
            crate::format::fixed(overshoot, 2),
        )
    })
}
