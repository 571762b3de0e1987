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
/// it (white: over every sample; slow: once over the run). A slow floor's
/// error is `√(floor² + σ²τ/n)`: where the residual's own slow part (σ its
/// scatter about its mean, τ its correlation time, n its samples) lifts it
/// past the floor, the words say so: "6.83e-3 rad" beside a floor of 0.005
/// and "the floor counted … once over the run" read as a slip.
fn bias_words(bias: f64, b: &BiasTest, noise_floor: f64, unit: &str) -> String {
    let mut counted = counted_words(b.counting).to_string();
    if b.counting == FloorCounting::Slow && b.standard_error > 1.05 * noise_floor {
        counted += &format!(
            ", with the residual's own slow variation beside it (the floor alone gives {} {unit})",
            crate::format::significant(noise_floor, 2)
        );
    }
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
        let before = right_before_input(s.windows, noise_floor);
        if offset {
            out += &offset_words(bias, (rms, varying), noise_floor, unit, before);
        }
        // A time shift explains a residual shaped like the input's
        // derivative: saying "not a time shift" beside it contradicts it.
        let shaped = !offset || varying >= noise_floor || before.is_some();
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
            bias_words(bias, &found.bias, noise_floor, unit),
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
    v += &format!(
        "; bias {}",
        bias_words(bias, &found.bias, noise_floor, unit)
    );
    v
}

/// The residual as a line through the measured channel, `e ≈ k·m + c`.
struct GainLine {
    /// Slope: the simulation reads `1 + k` times the measurement.
    k: f64,
    /// Intercept, the channel's unit.
    c: f64,
    /// Correlation of the residual with the simulated channel.
    rho: f64,
    /// RMS of what the line leaves, the channel's unit.
    left: f64,
    /// The residual's own white noise (its sample-to-sample scatter,
    /// at most the floor), the channel's unit.
    noise: f64,
}

/// The least correlation of the residual with the simulated channel for
/// its gap to be said as a gain error, once the residual's own noise is
/// taken out: the line carries at least 81 % of what varies beyond it.
const GAIN_CORRELATION: f64 = 0.9;

/// The least raw correlation: the line carries at least a quarter of what
/// varies, noise included, whatever the noise's estimate.
const GAIN_CORRELATION_RAW: f64 = 0.5;

/// The residual's white noise: the scatter of its first differences over
/// √2 (a smooth model error barely moves from sample to sample), at most
/// the floor.
fn white_noise(e: &[f64], noise_floor: f64) -> f64 {
    let d: Vec<f64> = e.windows(2).map(|w| w[1] - w[0]).collect();
    let m = mean(&d);
    let var = d.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / d.len().max(1) as f64;
    (var / 2.0).sqrt().min(noise_floor)
}

/// The residual's line where it is a gain error: close to a line through
/// the simulated channel once its own white noise is taken out, whose
/// slope moves it by more than the noise floor across the channel's range,
/// with an intercept within half the residual's mean or within the noise
/// floor. A constant offset has no slope (its intercept is its mean); a
/// front tyre 20 % soft replayed on a step has residual ≈ −0.13 × the yaw
/// rate and no intercept, where the mean alone read "mostly a constant
/// offset" and the likeness to the steer "a dynamic error" in one
/// sentence. The line is fitted against the simulated channel, which holds
/// no measurement noise: against the measured one, a gyro's 0.002 rad/s
/// both flattened the slope and cut the correlation below 0.9, and the
/// book's own gain error read as an offset (Fuller 1987, errors in
/// variables). Said as a line through the measured channel: with `e =
/// k'·s + c'` and `m = s − e`, `e = k'/(1 − k')·m + c'/(1 − k')`.
fn gain_error(e: &[f64], measured: &[f64], noise_floor: f64) -> Option<GainLine> {
    let n = e.len().min(measured.len());
    let simulated: Vec<f64> = (0..n).map(|i| measured[i] + e[i]).collect();
    let sums = crate::stats::CentredSums::of(&simulated, &e[..n]);
    let rho = sums.correlation()?;
    let slope = sums.xy / sums.xx;
    if slope.is_nan() || slope >= 1.0 {
        return None;
    }
    let intercept = mean(&e[..n]) - slope * mean(&simulated);
    let var = sums.yy / n as f64;
    let noise = white_noise(&e[..n], noise_floor);
    let beyond = rho * rho * var / (var - noise * noise).max(f64::MIN_POSITIVE);
    // What the slope moves the residual by across the simulated channel's
    // 5–95 % range (a step's sd understates its range: it sits at 0 and
    // at its steady value).
    let mut sorted = simulated;
    sorted.sort_by(f64::total_cmp);
    let at = |q: f64| sorted[(q * (sorted.len() - 1) as f64).round() as usize];
    let swing = slope.abs() * (at(0.95) - at(0.05));
    let c = intercept / (1.0 - slope);
    let small = c.abs() <= (0.5 * mean(e).abs()).max(noise_floor);
    let line = beyond >= GAIN_CORRELATION * GAIN_CORRELATION && rho.abs() >= GAIN_CORRELATION_RAW;
    (line && swing >= noise_floor && small).then(|| GainLine {
        k: slope / (1.0 - slope),
        c,
        rho,
        left: (var * (1.0 - rho * rho)).max(0.0).sqrt(),
        noise,
    })
}

/// A gap that grows with the response, said as a gain error; where the
/// residual's noise holds its correlation below [`GAIN_CORRELATION`], that
/// what the line leaves is that noise.
fn gain_words(g: &GainLine, noise_floor: f64, unit: &str) -> String {
    let within = if g.c.abs() < noise_floor {
        ", within the noise floor"
    } else {
        ""
    };
    let left = if g.rho.abs() < GAIN_CORRELATION {
        format!(
            "; what the line leaves, RMS {} {unit}, is about the residual's own sample-to-sample noise, {} {unit}",
            crate::format::significant(g.left, 2),
            crate::format::significant(g.noise, 2)
        )
    } else {
        String::new()
    };
    format!(
        "; the gap grows with the response, not a constant offset: the residual follows the measured channel as a line of slope {:+.3} (the simulation reads {:.1} % of the measurement; correlation {:.2}{left}) with an intercept of {} {unit}{within}: a gain error (a stiffness, a mass or inertia, or a sensor's scale factor)",
        g.k,
        100.0 * (1.0 + g.k),
        g.rho,
        crate::format::readable(g.c, 2),
    )
}

/// The share of the residual's mean square its mean must carry for the
/// gap to be said as an offset (the mean larger than what varies about it).
const OFFSET_SHARE: f64 = 0.5;

/// The residual's mean before the input where that window is right (at
/// least 5 samples, its mean within the noise floor and its RMS within
/// three): a sensor's zero offset would show there too.
fn right_before_input(windows: &[PartGap], noise_floor: f64) -> Option<f64> {
    use crate::diagnose::report::parts::{Part, Window};
    windows
        .iter()
        .find(|p| p.name == Part::Window(Window::BeforeInput) && p.samples >= 5)
        .filter(|p| p.bias.abs() < noise_floor && p.rms <= 3.0 * noise_floor)
        .map(|p| p.bias)
}

/// A gap that is mostly its mean, said as an offset: the measured
/// channel's mean difference from the simulation (`e` = simulated −
/// measured), its share of the mean square (`rms`) and what varies about
/// it (`varying`). Where the channel is right before the input (`before`,
/// the mean residual there), the offset comes with the input and is no
/// sensor's zero offset: a step's gain error has 78 % of its mean square
/// in its mean, and was said as "a sensor's zero offset" beside "right
/// before the input".
fn offset_words(
    bias: f64,
    (rms, varying): (f64, f64),
    noise_floor: f64,
    unit: &str,
    before: Option<f64>,
) -> String {
    let way = if bias < 0.0 { "above" } else { "below" };
    let share = 100.0 * bias * bias / (rms * rms);
    let quiet = varying < noise_floor;
    let (bias, varying, floor) = (
        crate::format::significant(bias.abs(), 3),
        crate::format::significant(varying, 2),
        crate::format::significant(noise_floor, 2),
    );
    if let Some(b) = before {
        return format!(
            "; the gap's mean comes with the input: the measured channel lies {bias} {unit} {way} the simulation on average ({share:.0} % of the residual's mean square; what varies about it has RMS {varying} {unit}), but before the input the two agree (mean residual {} {unit} there, within the noise floor of {floor} {unit}), so no sensor's zero offset: the model's response to the input is off",
            crate::format::readable(b, 2),
        );
    }
    // Where what varies is above the noise, its shape is said next.
    let (against, cause) = if quiet {
        (
            "below",
            ": a sensor's zero offset, or a constant the model leaves out, not a dynamic error",
        )
    } else {
        ("above", "")
    };
    format!(
        "; the gap is mostly a constant offset: the measured channel lies {bias} {unit} {way} the simulation on average (its mean difference, {share:.0} % of the residual's mean square; what varies about it has RMS {varying} {unit}, {against} the noise floor of {floor} {unit}){cause}"
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
