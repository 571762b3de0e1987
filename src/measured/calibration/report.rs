//! What a calibration reports: the criteria it used, every standstill and
//! straight with its channels' means, the straights refused and why, and
//! per channel the offsets pooled over the standstills and over the
//! straights with whether they agree; and the terminal lines. Units: SI,
//! rad; times in s.

use super::stats::MeanEstimate;
use crate::measured::clean::RunChannel;
use serde::Serialize;

/// The criteria a calibration applied (the constants of [`super`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Criteria {
    /// Width of the centred running medians the spans are found on, s.
    pub median_window: f64,
    /// A standstill: the running median of the speed below this, m/s.
    pub standstill_speed: f64,
    /// Cut from each end of a standstill (the body still rocks), s.
    pub standstill_trim: f64,
    /// Shortest standstill after the cut, s.
    pub standstill_seconds: f64,
    /// A straight: the running median of the speed at least this, m/s.
    pub straight_speed: f64,
    /// Largest |yaw rate − the standstills' yaw offset| (running
    /// median), rad/s.
    pub straight_yaw_rate: f64,
    /// Largest |speed·(yaw rate − the standstills' yaw offset)|, the
    /// path's lateral acceleration, m/s².
    pub straight_lateral: f64,
    /// Largest |ay − g·sin(bank)| (running median; `ay` as read without
    /// a bank column), m/s²: beyond any mounted accelerometer's offset.
    pub straight_ay: f64,
    /// Largest |steer − the run's straight-line steer| (running median),
    /// rad.
    pub straight_steer: f64,
    /// Largest |ax| (running median; without `ax`, the slope of the
    /// speed's), m/s².
    pub straight_ax: f64,
    /// Largest standard deviation of the yaw rate's running median over a
    /// straight (weaving), rad/s.
    pub straight_yaw_variation: f64,
    /// Largest (max − min)/mean of the speed's running median over a
    /// straight.
    pub straight_speed_variation: f64,
    /// Cut from each end of a straight (the corner's exit and entry), s.
    pub straight_trim: f64,
    /// Shortest straight after the cut, s.
    pub straight_seconds: f64,
    /// Largest |mean logged bank| of a straight whose sideslip is taken
    /// for an offset, rad (beyond it the car crabs).
    pub straight_beta_bank: f64,
    /// Robust deviations from a span's median beyond which a sample is a
    /// glitch.
    pub outlier_mads: f64,
    /// Quantile of χ² below which spans agree.
    pub agreement_quantile: f64,
    /// Standard errors within which the standstills' and the straights'
    /// offsets agree.
    pub agreement_sigmas: f64,
}

/// Standstill or straight.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SpanKind {
    /// Parked: no motion at all.
    Standstill,
    /// Driving straight at a steady speed.
    Straight,
}

impl SpanKind {
    /// In words, plural when `n` ≠ 1.
    pub fn words(self, n: usize) -> &'static str {
        match (self, n == 1) {
            (SpanKind::Standstill, true) => "standstill",
            (SpanKind::Standstill, false) => "standstills",
            (SpanKind::Straight, true) => "straight",
            (SpanKind::Straight, false) => "straights",
        }
    }
}

/// One channel's mean over one span.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ChannelMean {
    /// The channel (yaw rate, ay or beta).
    pub channel: RunChannel,
    /// The mean: the offset, with `bank_term` removed from ay, in the
    /// channel's unit.
    pub mean: f64,
    /// Its standard error (autocorrelation counted).
    pub std_error: f64,
    /// Samples averaged.
    pub samples: usize,
    /// Independent samples they are worth (samples over the integrated
    /// autocorrelation time).
    pub effective_samples: f64,
    /// Samples left out as glitches.
    pub outliers: usize,
    /// Mean g·sin(bank) removed from ay (a logged bank), m/s².
    pub bank_term: Option<f64>,
}

impl ChannelMean {
    pub(super) fn new(channel: RunChannel, e: MeanEstimate, bank_term: Option<f64>) -> Self {
        Self {
            channel,
            mean: e.mean,
            std_error: e.std_error,
            samples: e.samples,
            effective_samples: e.effective_samples,
            outliers: e.outliers,
            bank_term,
        }
    }
}

/// A standstill or a straight.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CalibrationSpan {
    /// The run (file) it is in.
    pub run: String,
    /// Which.
    pub kind: SpanKind,
    /// First sample, s.
    pub t_start: f64,
    /// Last sample, s.
    pub t_end: f64,
    /// Mean speed, m/s.
    pub speed: f64,
    /// Median steer, rad (on a straight: the steer that holds it).
    pub steer: f64,
    /// The response channels' means.
    pub channels: Vec<ChannelMean>,
    /// Channels holding one value throughout (gated or held by the
    /// logger): no offset to measure.
    pub held: Vec<RunChannel>,
    /// A straight on a logged bank beyond [`Criteria::straight_beta_bank`]
    /// (its mean bank, rad): its sideslip is the car's crab, not measured
    /// as an offset.
    pub beta_bank: Option<f64>,
}

/// The straights whose sideslip was not taken for an offset because they
/// lie on a logged bank (the car crabs there).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BankedStraights {
    /// Straights.
    pub spans: usize,
    /// Their total length, s.
    pub seconds: f64,
    /// Least |mean bank| among them, rad.
    pub least_bank: f64,
    /// Greatest |mean bank| among them, rad.
    pub greatest_bank: f64,
}

impl BankedStraights {
    /// Those of `spans`; None where there are none.
    pub fn of(spans: &[&CalibrationSpan]) -> Option<Self> {
        let banked: Vec<(f64, f64)> = spans
            .iter()
            .filter_map(|s| s.beta_bank.map(|b| (b.abs(), s.seconds())))
            .collect();
        (!banked.is_empty()).then(|| Self {
            spans: banked.len(),
            seconds: banked.iter().map(|b| b.1).sum(),
            least_bank: banked.iter().map(|b| b.0).fold(f64::MAX, f64::min),
            greatest_bank: banked.iter().map(|b| b.0).fold(0.0, f64::max),
        })
    }

    /// In words.
    pub fn words(&self) -> String {
        let deg = |a: f64| crate::format::fixed(a.to_degrees(), 1);
        format!(
            "{} {} ({:.0} s) on a logged bank of {}° to {}° left out: a car crabs on a bank (its tyres hold it up the slope, β ≈ −sin θ over the rear axle's cornering coefficient), which is no sensor offset",
            self.spans,
            SpanKind::Straight.words(self.spans),
            self.seconds,
            deg(self.least_bank),
            deg(self.greatest_bank)
        )
    }
}

impl CalibrationSpan {
    /// Its length, s.
    pub fn seconds(&self) -> f64 {
        self.t_end - self.t_start
    }
}

/// Why a candidate straight was refused.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "reason")]
pub enum Rejection {
    /// The yaw rate weaves.
    YawRateVaries {
        /// Standard deviation of its running median, rad/s.
        std: f64,
        /// The limit, rad/s.
        limit: f64,
    },
    /// The steer itself swings (its running median does not: a slalom as
    /// fast as the median's window).
    SteerSwings {
        /// RMS of the raw steer about the straight-line steer, its noise
        /// taken out, rad.
        rms: f64,
        /// The limit (the straight's steer band), rad.
        limit: f64,
    },
    /// The yaw rate itself swings.
    YawRateSwings {
        /// RMS of the raw yaw rate about the standstills' offset, its noise
        /// taken out, rad/s.
        rms: f64,
        /// The limit (the straight's yaw-rate band), rad/s.
        limit: f64,
    },
    /// The speed changes.
    SpeedVaries {
        /// (max − min)/mean of its running median.
        share: f64,
        /// The limit.
        limit: f64,
    },
}

impl Rejection {
    /// In words.
    pub fn words(&self) -> String {
        match self {
            Rejection::YawRateVaries { std, limit } => {
                format!("the yaw rate varies by {std:.4} rad/s (limit {limit:.4})")
            }
            Rejection::SteerSwings { rms, limit } => format!(
                "the steer swings by {rms:.4} rad RMS beyond its noise (limit {limit:.4}; \
                 its 1 s medians hide it)"
            ),
            Rejection::YawRateSwings { rms, limit } => format!(
                "the yaw rate swings by {rms:.4} rad/s RMS beyond its noise (limit {limit:.4}; \
                 its 1 s medians hide it)"
            ),
            Rejection::SpeedVaries { share, limit } => format!(
                "the speed varies by {:.0} % (limit {:.0} %)",
                100.0 * share,
                100.0 * limit
            ),
        }
    }
}

/// A stretch that met the per-sample criteria of a straight but not the
/// whole-span ones.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RejectedStraight {
    /// The run.
    pub run: String,
    /// First sample, s.
    pub t_start: f64,
    /// Last sample, s.
    pub t_end: f64,
    /// Why.
    pub reasons: Vec<Rejection>,
}

/// One channel's offset pooled over the spans of one kind.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Pooled {
    /// Spans.
    pub spans: usize,
    /// Their total length, s.
    pub seconds: f64,
    /// Samples averaged.
    pub samples: usize,
    /// The spans' mean, each weighed by `1/(s² + τ²)` (the inverse
    /// variance where they agree; DerSimonian & Laird 1986 where they
    /// scatter beyond their errors).
    pub mean: f64,
    /// Its standard error, the scatter beyond the spans' errors included.
    pub std_error: f64,
    /// τ: the spread of the spans' offsets beyond their own errors (0
    /// where χ² ≤ dof).
    pub between_spans: f64,
    /// χ² of the spans about the mean.
    pub chi2: f64,
    /// Its degrees of freedom (spans − 1).
    pub dof: usize,
    /// The spans agree (χ² below its quantile); false: the offset drifts.
    pub consistent: bool,
    /// Least span mean.
    pub least: f64,
    /// Greatest span mean.
    pub greatest: f64,
}

/// The straights' offset against the standstills'.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Agreement {
    /// Straights minus standstills.
    pub difference: f64,
    /// Its standard error.
    pub std_error: f64,
    /// Within [`Criteria::agreement_sigmas`] standard errors.
    pub agree: bool,
}

/// One channel's calibration.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ChannelCalibration {
    /// The channel.
    pub channel: RunChannel,
    /// Its unit.
    pub unit: &'static str,
    /// g·sin(bank) was removed (ay with a logged bank).
    pub bank_removed: bool,
    /// The standstills' reading of the logged bank (ay with a logged bank
    /// and a standstill).
    pub bank: Option<super::BankCheck>,
    /// Over the standstills, with a logged bank removed as logged (also
    /// where [`ChannelCalibration::bank`] refuses that reading: then this
    /// mean is no offset, and [`ChannelCalibration::offset`] says what is).
    pub standstill: Option<Pooled>,
    /// Over the straights.
    pub straight: Option<Pooled>,
    /// The two compared, when both are measured.
    pub agreement: Option<Agreement>,
    /// The standstills' `ay` without a bank column reads beyond
    /// [`super::PLAUSIBLE_AY_OFFSET`]: a slope or bank where they stood
    /// (`g·sin θ`), not a mounted sensor's offset, so not taken.
    pub unlogged_bank: bool,
    /// The offset the calibration gives (as evidence, and as the start of a
    /// fitted offset): the standstills' where they are measured, their
    /// bank reading is taken and no unlogged bank reads in them, else the
    /// straights'; None where neither is.
    pub offset: Option<Offset>,
    /// Sideslip: the straights on a logged bank, left out.
    pub banked_straights: Option<BankedStraights>,
}

/// The offset a channel's calibration gives, and the spans it comes from.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Offset {
    /// The offset, in the channel's unit.
    pub mean: f64,
    /// Its standard error.
    pub std_error: f64,
    /// The kind of span it is pooled over.
    pub from: SpanKind,
}

impl Offset {
    /// The offset of a channel pooled over `standstill` and `straight`, the
    /// standstills' refused where a logged `bank` reading is not taken (an
    /// offset only a bank that does not act on the car, or acts with the
    /// other sign, explains is none), and where `unlogged_bank` (one
    /// beyond a mounted sensor's without a bank column).
    pub fn of(
        standstill: Option<&Pooled>,
        straight: Option<&Pooled>,
        bank: Option<&super::BankCheck>,
        unlogged_bank: bool,
    ) -> Option<Self> {
        let refused = unlogged_bank || bank.is_some_and(|b| !b.taken());
        let (p, from) = match (standstill.filter(|_| !refused), straight) {
            (Some(p), _) => (p, SpanKind::Standstill),
            (None, Some(p)) => (p, SpanKind::Straight),
            (None, None) => return None,
        };
        Some(Self {
            mean: p.mean,
            std_error: p.std_error,
            from,
        })
    }
}

/// What the standstills and straights of a set of runs say about the
/// response sensors' offsets.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CalibrationReport {
    /// The criteria used.
    pub criteria: Criteria,
    /// Yaw rate the straights were judged against: the standstills'
    /// pooled yaw-rate offset, 0 without one, rad/s.
    pub yaw_reference: f64,
    /// Every standstill and straight, by run and time.
    pub spans: Vec<CalibrationSpan>,
    /// Candidate straights refused.
    pub rejected: Vec<RejectedStraight>,
    /// Per channel with an offset measured.
    pub channels: Vec<ChannelCalibration>,
}

impl Default for CalibrationReport {
    fn default() -> Self {
        Self {
            criteria: super::CRITERIA,
            yaw_reference: 0.0,
            spans: Vec::new(),
            rejected: Vec::new(),
            channels: Vec::new(),
        }
    }
}

/// Decimals that show `error` to its first significant digit (a drift's
/// range of spans, read at their own precision).
fn first_digit(error: f64) -> usize {
    if error > 0.0 && error.is_finite() {
        (-error.log10().floor()).clamp(1.0, 8.0) as usize
    } else {
        6
    }
}

/// Decimals that show `error` to its first significant digit, or its
/// first two where that digit is 1 or 2 (the Particle Data Group's rule,
/// Tanabashi et al. 2018, in short: a 1.4e-4 said as 0.0001 loses a
/// third of itself, and a 7.3e-5 offset beside it read "0.0001 ± 0.0001"
/// where the road line said 7.3e-5).
fn digits(error: f64) -> usize {
    let d = first_digit(error);
    let leading = error * 10f64.powi(d as i32);
    match error > 0.0 && error.is_finite() && leading < 2.95 && d < 8 {
        true => d + 1,
        false => d,
    }
}

/// `value ± error` at the decimals [`digits`] gives; a value that
/// rounds to zero there is written 0, without the sign of a digit it does
/// not show ("-0.0000 ± 0.0002" read as an offset below zero).
fn plus_minus(value: f64, error: f64) -> String {
    let d = digits(error);
    let v = format!("{value:.d$}");
    let v = match v.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => v,
    };
    format!("{v} ± {error:.d$}")
}

impl ChannelCalibration {
    /// The spans (standstills, straights) whose offsets drift beyond their
    /// errors, each as `; the … drift (least to greatest, χ²/dof)`: the
    /// tail of [`Self::line`], apart so that it reads on a screen.
    fn drifts(&self) -> String {
        let mut out = String::new();
        for (p, kind) in [
            (&self.standstill, SpanKind::Standstill),
            (&self.straight, SpanKind::Straight),
        ] {
            if let Some(p) = p.filter(|p| !p.consistent) {
                // The spans' own precision, not the pooled error the drift
                // inflated.
                let ratio = p.chi2 / p.dof as f64;
                let d = first_digit(p.std_error / ratio.sqrt().max(1.0)).min(4);
                let r = if ratio < 100.0 { 1 } else { 0 };
                out.push_str(&format!(
                    "; the {} drift ({:.d$} to {:.d$}, χ²/dof = {ratio:.r$})",
                    kind.words(2),
                    p.least,
                    p.greatest,
                ));
            }
        }
        out
    }

    /// The channel's terminal line.
    pub fn line(&self) -> String {
        let name = self.channel.name();
        let bank = if self.bank_removed {
            " (g·sin(bank) removed)"
        } else {
            ""
        };
        let part = |p: &Pooled, kind: SpanKind, first: bool| {
            let unit = if first {
                format!(" {}", self.unit)
            } else {
                String::new()
            };
            let at = if kind == SpanKind::Standstill {
                "at"
            } else {
                "on"
            };
            format!(
                "{}{unit} {at} {} {} ({:.0} s)",
                plus_minus(p.mean, p.std_error),
                p.spans,
                kind.words(p.spans),
                p.seconds
            )
        };
        let mut parts = Vec::new();
        if let Some(p) = &self.standstill {
            parts.push(part(p, SpanKind::Standstill, true));
        }
        if let Some(p) = &self.straight {
            parts.push(part(p, SpanKind::Straight, parts.is_empty()));
        }
        // A doubted bank leads: the offset read with it is no offset, and
        // a reader who stops at the number takes it for one.
        let mut out = match self.bank.as_ref().and_then(|b| b.doubt()) {
            Some(doubt) => format!(
                "{name}: {doubt}; read with the bank as logged{bank}: {}",
                parts.join(", ")
            ),
            None if self.unlogged_bank => {
                let read = self.standstill.map_or(f64::NAN, |p| p.mean);
                format!(
                    "{name}: the standstills read {} {}: a slope or bank where they stood, not an offset (no bank column; beyond the {} m/s² a mounted sensor shows), so no offset taken from them, not used as evidence: {}",
                    crate::format::fixed(read, 2),
                    self.unit,
                    super::PLAUSIBLE_AY_OFFSET,
                    parts.join(", ")
                )
            }
            None if parts.is_empty() => format!("{name}: no offset measured"),
            None => format!("{name} offset{bank} {}", parts.join(", ")),
        };
        if let Some(b) = &self.banked_straights {
            out.push_str(&format!("; {}", b.words()));
        }
        if let Some(a) = &self.agreement {
            let verdict = if a.agree { "agree" } else { "differ" };
            out.push_str(&format!(
                "; straights − standstills {}: {verdict}",
                plus_minus(a.difference, a.std_error)
            ));
        }
        let confirmed = self.agreement.is_some_and(|a| a.agree);
        let straight = self.straight.map(|p| p.mean);
        out.push_str(&super::sensor::beyond_a_sensor(
            self.channel,
            straight,
            confirmed,
        ));
        out.push_str(&self.drifts());
        out
    }
}

impl CalibrationReport {
    /// One line per channel with an offset measured, or one saying that
    /// none was found (with the refused straights counted).
    pub fn lines(&self) -> Vec<String> {
        let mut out: Vec<String> = self.channels.iter().map(|c| c.line()).collect();
        if out.is_empty() {
            let c = &self.criteria;
            out.push(format!(
                "no standstill (speed below {} m/s for {} s) or straight ({} s at {} m/s or more) in the runs: no sensor offset measured",
                c.standstill_speed,
                c.standstill_seconds + 2.0 * c.standstill_trim,
                c.straight_seconds + 2.0 * c.straight_trim,
                c.straight_speed
            ));
        }
        if !self.rejected.is_empty() {
            let first = &self.rejected[0];
            let why: Vec<String> = first.reasons.iter().map(Rejection::words).collect();
            out.push(format!(
                "{} candidate straight(s) refused, e.g. {} {:.1}–{:.1} s: {}",
                self.rejected.len(),
                first.run,
                first.t_start,
                first.t_end,
                why.join(", ")
            ));
        }
        out
    }

    /// The calibration of `channel`, when measured.
    pub fn channel(&self, channel: RunChannel) -> Option<&ChannelCalibration> {
        self.channels.iter().find(|c| c.channel == channel)
    }
}

#[cfg(test)]
mod tests {
    use super::plus_minus;

    #[test]
    fn an_error_led_by_1_or_2_keeps_two_digits_and_the_value_its_place() {
        assert_eq!(plus_minus(7.3e-5, 1.2e-4), "0.00007 ± 0.00012");
        assert_eq!(plus_minus(-4.6e-5, 1.4e-4), "-0.00005 ± 0.00014");
        assert_eq!(plus_minus(0.00401, 0.00004), "0.00401 ± 0.00004");
        assert_eq!(plus_minus(-0.0085, 0.0003), "-0.0085 ± 0.0003");
        // Zero at the error's digit is said without a sign.
        assert_eq!(plus_minus(-4e-6, 1.4e-4), "0.00000 ± 0.00014");
    }
}
