//! A channel's gap in words: the whole run's RMS against three noise
//! floors, then what it hides (a window's gap, a bias of many standard
//! errors), the time shift, and how much the residual looks like the steer
//! (worded as a likeness, not a lag). A gap that grows with the response
//! (the residual a line through the measured channel with a small
//! intercept) is said as a gain error, not as a constant offset beside a
//! dynamic error. Numbers in the channel's unit.

use super::scan::{bias_threshold, BiasTest, WindowGap, FALSE_ALARM, WINDOW};
use super::{correlation, mean, PartGap};
use crate::diagnose::model::scale::FloorCounting;

/// Which tests found a gap.
pub(super) struct Found<'a> {
    /// The whole run's RMS beyond three noise floors.
    pub whole: bool,
    /// The significant window, if any.
    pub window: Option<&'a WindowGap>,
    /// The bias against its standard error.
    pub bias: BiasTest,
}

impl Found<'_> {
    /// A gap by any test.
    pub fn any(&self) -> bool {
        self.whole || self.window.is_some() || self.bias.significant
    }
}

/// What the words are made of.
pub(super) struct Said<'a> {
    pub unit: &'static str,
    pub rms: f64,
    pub noise_floor: f64,
    /// The residual (simulated − measured).
    pub e: &'a [f64],
    /// The measured channel.
    pub measured: &'a [f64],
    pub windows: &'a [PartGap],
    pub regimes: &'a [PartGap],
    /// Sprague–Geers magnitude and phase errors.
    pub sg: (f64, f64),
    /// The residual's largest correlation with the steer and its lag, s.
    pub steer: (f64, f64),
    pub found: &'a Found<'a>,
    /// The window with the most evidence, significant or not.
    pub worst: Option<&'a WindowGap>,
    pub time_shift: Option<f64>,
    /// Sample interval, s.
    pub dt: f64,
}

/// A window's or bias's numbers as the words give them.
fn window_words(w: &WindowGap, unit: &str) -> String {
    format!(
        "RMS {:.4} {unit} ({:.1} noise floors) from t = {:.2} s to {:.2} s, where pure noise exceeds {:.1} noise floors in any of the run's {} windows of {WINDOW} s only once in {:.0} runs",
        w.rms,
        w.noise_floors,
        w.start,
        w.end,
        w.threshold_noise_floors,
        w.windows_tested,
        1.0 / FALSE_ALARM
    )
}

/// A significant window said as a stretch, or, where at least half the
/// run's windows are beyond their threshold, as a gap along the run (a
/// uniform offset read "a gap in one stretch" from its worst window while
/// 29 of 29 windows exceeded theirs).
fn stretch_words(w: &WindowGap, unit: &str) -> String {
    if 2 * w.windows_significant >= w.windows_tested.max(1) {
        format!(
            " a gap along the run, not in one stretch: {} of its {} windows of {WINDOW} s lie beyond what pure noise reaches (the largest: {})",
            w.windows_significant,
            w.windows_tested,
            window_words(w, unit)
        )
    } else {
        format!(" a gap in one stretch: {}", window_words(w, unit))
    }
}

/// How the floor was counted in a bias's standard error.
fn counted_words(counting: FloorCounting) -> &'static str {
    match counting {
        FloorCounting::White => "the floor counted as white noise",
        FloorCounting::Slow => "the floor counted as a slow error, once over the run",
    }
}

/// A bias against its standard error, with how the floor was counted in
/// it (white: over every sample; slow: once over the run).
fn bias_words(bias: f64, b: &BiasTest, unit: &str) -> String {
    let counted = counted_words(b.counting);
    format!(
        "{} {unit} ({:.1} standard errors of {:.2e} {unit}, over {:.0} effective samples; {counted})",
        crate::format::fixed(bias, 4),
        b.standard_errors,
        b.standard_error,
        b.effective_samples
    )
}

/// The noise floor and the line three of them draw: the bracket once held
/// only the floor, which read as if the RMS sat at the threshold.
fn floors_words(noise_floor: f64, unit: &str) -> String {
    format!(
        "noise floor {noise_floor:.4} {unit}, 3× = {:.4} {unit}",
        3.0 * noise_floor
    )
}

/// The verdict of one channel.
pub(super) fn verdict(s: &Said) -> String {
    let Said {
        unit,
        rms,
        noise_floor,
        found,
        ..
    } = *s;
    let bias = mean(s.e);
    let mut out = if found.whole {
        whole_gap(s)
    } else if found.any() {
        hidden_gap(s, bias)
    } else {
        no_gap(s, bias)
    };
    if found.whole {
        if let Some(w) = found.window {
            out += &format!("; the most in one stretch: {}", window_words(w, unit));
        }
        if found.bias.significant {
            out += &format!(
                "; the bias is {:.1} standard errors of {:.2e} {unit} ({})",
                found.bias.standard_errors,
                found.bias.standard_error,
                counted_words(found.bias.counting)
            );
        }
    }
    let shifted = s.time_shift.filter(|x| x.abs() >= s.dt);
    if let Some(shift) = shifted {
        let (way, by) = if shift > 0.0 {
            ("lags", shift)
        } else {
            ("leads", -shift)
        };
        out += &format!("; the measurement {way} the simulation by {by:.2} s (the simulated channel shifted by {shift:+.2} s in time matches it best)");
    }
    if found.any() {
        if let Some(g) = gain_error(s.e, s.measured, noise_floor) {
            out += &gain_words(&g, noise_floor, unit);
            return out;
        }
        let (rho, lag) = s.steer;
        // A gap that is mostly its mean is an offset. What varies about
        // the mean has a shape (a likeness to the steer, smoothness) only
        // where it stands above the noise floor: a constant offset
        // replayed without noise leaves a numerical wiggle of 1e-4 of the
        // signal whose correlation with the steer is 0.5, no dynamic error.
        let varying = (rms * rms - bias * bias).max(0.0).sqrt();
        let offset = found.bias.significant && bias * bias >= OFFSET_SHARE * rms * rms;
        if offset {
            out += &offset_words(bias, rms, varying, noise_floor, unit);
        }
        // A time shift explains a residual shaped like the input's
        // derivative: saying "not a time shift" beside it contradicts it.
        let shaped = !offset || varying >= noise_floor;
        if shaped && rho.abs() > 0.5 && shifted.is_none() {
            out += &format!("; the residual resembles the steer input (correlation {rho:.2} with the steer {lag:.2} s earlier: a residual shaped like the input, not a time shift): a dynamic error (gain, lag or stiffness)");
        } else if shaped && correlation(s.e, s.e, 1) > 0.9 {
            out += "; the residual is slow and smooth: a model error rather than noise";
        }
    }
    out
}

/// A gap the whole run's RMS does not show, with its residual's mean
/// `bias`: the stretch and the bias that show it.
fn hidden_gap(s: &Said, bias: f64) -> String {
    let Said {
        unit,
        rms,
        noise_floor,
        found,
        ..
    } = *s;
    let mut v = format!("no significant gap over the whole run (RMS {rms:.4} {unit}, within three noise floors: {}), but", floors_words(noise_floor, unit));
    let mut parts = Vec::new();
    if let Some(w) = found.window {
        parts.push(stretch_words(w, unit));
    }
    if found.bias.significant {
        parts.push(format!(
            " a bias of {}, beyond {} standard errors",
            bias_words(bias, &found.bias, unit),
            bias_threshold(found.bias.counting)
        ));
    }
    v += &parts.join("; and");
    v
}

/// No gap by any test, with its residual's mean `bias`: the RMS, the
/// largest window against its threshold, and the bias.
fn no_gap(s: &Said, bias: f64) -> String {
    let Said {
        unit,
        rms,
        noise_floor,
        found,
        ..
    } = *s;
    let mut v = format!(
        "no significant gap: RMS {rms:.4} {unit}, within three noise floors ({})",
        floors_words(noise_floor, unit)
    );
    match s.worst {
        Some(w) if w.threshold_noise_floors.is_finite() => {
            v += &format!(
                "; no stretch either (the largest {WINDOW} s window {:.1} noise floors, below {:.1})",
                w.noise_floors, w.threshold_noise_floors
            );
        }
        // A slow residual over a short run leaves the floor's estimate
        // too few effective samples for a threshold.
        Some(w) => {
            v += &format!(
                "; no stretch judged (the largest {WINDOW} s window {:.1} noise floors, but the residual is too slow for the run's length to set a threshold)",
                w.noise_floors
            );
        }
        None => {}
    }
    v += &format!("; bias {}", bias_words(bias, &found.bias, unit));
    v
}

/// The residual as a line through the measured channel, `e ≈ k·m + c`.
struct GainLine {
    /// Slope: the simulation reads `1 + k` times the measurement.
    k: f64,
    /// Intercept, the channel's unit.
    c: f64,
    /// Correlation of the residual with the measured channel.
    rho: f64,
}

/// The least correlation of the residual with the measured channel for
/// its gap to be said as a gain error: the line carries at least 81 % of
/// what varies.
const GAIN_CORRELATION: f64 = 0.9;

/// The residual's line through the measured channel where it is a gain
/// error: close to a line (|ρ| ≥ [`GAIN_CORRELATION`]), whose slope moves
/// it by more than the noise floor across the channel's range, with an intercept within
/// half the residual's mean or within the noise floor. A constant offset
/// has no slope (its intercept is its mean); a front tyre 20 % soft
/// replayed on a step has residual ≈ −0.13 × the yaw rate and no
/// intercept, where the mean alone read "mostly a constant offset" and
/// the likeness to the steer "a dynamic error" in one sentence.
fn gain_error(e: &[f64], measured: &[f64], noise_floor: f64) -> Option<GainLine> {
    let sums = crate::stats::CentredSums::of(measured, e);
    let rho = sums.correlation()?;
    let k = sums.xy / sums.xx;
    let c = mean(e) - k * mean(&measured[..sums.n]);
    // What the slope moves the residual by across the measured channel's
    // 5–95 % range (a step's sd understates its range: it sits at 0 and
    // at its steady value).
    let mut sorted = measured[..sums.n].to_vec();
    sorted.sort_by(f64::total_cmp);
    let at = |q: f64| sorted[(q * (sorted.len() - 1) as f64).round() as usize];
    let swing = k.abs() * (at(0.95) - at(0.05));
    let small = c.abs() <= (0.5 * mean(e).abs()).max(noise_floor);
    (rho.abs() >= GAIN_CORRELATION && swing >= noise_floor && small).then_some(GainLine {
        k,
        c,
        rho,
    })
}

/// A gap that grows with the response, said as a gain error.
fn gain_words(g: &GainLine, noise_floor: f64, unit: &str) -> String {
    let within = if g.c.abs() < noise_floor {
        ", within the noise floor"
    } else {
        ""
    };
    format!(
        "; the gap grows with the response, not a constant offset: the residual follows the measured channel as a line of slope {:+.3} (the simulation reads {:.1} % of the measurement; correlation {:.2}) with an intercept of {} {unit}{within}: a gain error (a stiffness, a mass or inertia, or a sensor's scale factor)",
        g.k,
        100.0 * (1.0 + g.k),
        g.rho,
        crate::format::readable(g.c, 2),
    )
}

/// The share of the residual's mean square its mean must carry for the
/// gap to be said as an offset (the mean larger than what varies about it).
const OFFSET_SHARE: f64 = 0.5;

/// A gap that is mostly its mean, said as an offset: the measured
/// channel's mean difference from the simulation (`e` = simulated −
/// measured), its share of the mean square, and what varies about it.
fn offset_words(bias: f64, rms: f64, varying: f64, noise_floor: f64, unit: &str) -> String {
    let way = if bias < 0.0 { "above" } else { "below" };
    // Where what varies is above the noise, its shape is said next.
    let (against, cause) = if varying < noise_floor {
        (
            "below",
            ": a sensor's zero offset, or a constant the model leaves out, not a dynamic error",
        )
    } else {
        ("above", "")
    };
    format!(
        "; the gap is mostly a constant offset: the measured channel lies {} {unit} {way} the simulation on average (its mean difference, {:.0} % of the residual's mean square; what varies about it has RMS {} {unit}, {against} the noise floor of {} {unit}){cause}",
        crate::format::significant(bias.abs(), 3),
        100.0 * bias * bias / (rms * rms),
        crate::format::significant(varying, 2),
        crate::format::significant(noise_floor, 2),
    )
}

/// The words of a gap over the whole run: its size, Sprague–Geers, and
/// where it is largest.
fn whole_gap(s: &Said) -> String {
    let Said {
        unit,
        rms,
        noise_floor,
        ..
    } = *s;
    let (magnitude_error, phase_error) = s.sg;
    let worst = |v: &[PartGap]| {
        v.iter()
            .filter(|p| p.samples >= 5)
            .max_by(|a, b| a.rms.total_cmp(&b.rms))
            .map(|p| p.name)
    };
    // A channel that is all but empty has a zero floor and no magnitude or
    // phase: said in words, never as NaN or a 300-digit ratio.
    let floors = rms / noise_floor;
    let floors = if floors.is_finite() && floors < 1e6 {
        format!("{floors:.1} noise floors")
    } else {
        "a noise floor of zero: the measured channel is all but constant".to_string()
    };
    let or_undefined = |v: f64, text: String| {
        if v.is_finite() {
            text
        } else {
            "undefined".to_string()
        }
    };
    let mut out = format!(
        "gap: RMS {rms:.4} {unit} ({floors}), bias {} {unit}; Sprague–Geers magnitude error {}, phase error {} (0 in phase, 1 opposed)",
        crate::format::fixed(mean(s.e), 4),
        or_undefined(magnitude_error, format!("{:+.1} %", 100.0 * magnitude_error)),
        or_undefined(phase_error, format!("{phase_error:.3}")),
    );
    if let Some(w) = worst(s.windows) {
        out += &format!("; largest in the window '{w}'");
    }
    if let Some(r) = worst(s.regimes) {
        out += &format!(", regime '{r}'");
    }
    out
}
