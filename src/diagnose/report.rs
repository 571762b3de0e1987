//! The typed report of a diagnosis ([`super::diagnose`]): what
//! `diagnosis.json` holds. Values are SI and rad unless a field names its
//! unit; held-out errors J are dimensionless (residuals over channel
//! scales).

use super::fit::Channel;
use super::gap::ChannelGap;
use super::model::Observed;
use crate::identify::grouping::GroupingReport;
use crate::tyre::Tyre;
use serde::Serialize;

/// A fitted parameter.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ParameterValue {
    /// `effect.parameter`.
    pub name: String,
    /// Unit.
    pub unit: String,
    /// Value fitted on all runs.
    pub value: f64,
    /// Its standard error (from the Jacobian; residual autocorrelation makes
    /// it optimistic).
    pub std_error: f64,
}

/// Held-out RMS of one channel.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChannelError {
    /// Channel.
    pub channel: String,
    /// Unit.
    pub unit: String,
    /// Held-out RMS residual.
    pub rms: f64,
}

/// One candidate (an effect or a combination) and its scores.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Ranked {
    /// The effect names joined by `+`.
    pub effect: String,
    /// The effect names.
    pub effects: Vec<String>,
    /// Fitted parameters.
    pub parameters: Vec<ParameterValue>,
    /// Held-out combined error J of the base model.
    pub heldout_error_before: f64,
    /// Held-out combined error J with the effect.
    pub heldout_error_after: f64,
    /// Held-out RMS per channel with the effect.
    pub heldout_channels: Vec<ChannelError>,
    /// Share of the held-out gap above noise removed, %.
    pub reduction_percent: f64,
    /// Combined error J of the all-run fit on all runs (in sample).
    pub insample_error_after: f64,
    /// Share of the in-sample gap above noise the all-run fit removes, %.
    pub insample_reduction_percent: f64,
    /// Folds whose refit converged (of `folds`).
    pub folds_converged: usize,
    /// Folds refitted.
    pub folds: usize,
    /// Cross-validation that disagrees with the fit, or refits that did not
    /// converge.
    pub warning: Option<String>,
    /// BIC of the all-run fit.
    pub bic: f64,
    /// BIC minus the base model's (negative: better).
    pub delta_bic: f64,
}

/// Effects that explain the gap about equally well.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Confounded {
    /// The effects.
    pub effects: Vec<String>,
    /// Their reductions, %.
    pub reduction_percent: Vec<f64>,
    /// The experiment that would separate them.
    pub separating_test: String,
}

/// The verdict.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Verdict {
    /// Effects the evidence supports (empty: the gap is within noise or no
    /// effect explains it).
    pub effects: Vec<String>,
    /// Their parameters.
    pub parameters: Vec<ParameterValue>,
    /// In words.
    pub statement: String,
}

/// A time window of a run, from the start of its input.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Window {
    /// Before the input starts.
    BeforeInput,
    /// The input's first 0.5 s.
    FirstHalfSecond,
    /// 0.5–2 s after the input starts.
    HalfToTwoSeconds,
    /// Later than 2 s.
    Later,
}

impl Window {
    /// Every window, in time order.
    pub const ALL: [Window; 4] = [
        Window::BeforeInput,
        Window::FirstHalfSecond,
        Window::HalfToTwoSeconds,
        Window::Later,
    ];

    /// Its name in reports.
    pub fn label(self) -> &'static str {
        match self {
            Window::BeforeInput => "before the input",
            Window::FirstHalfSecond => "first 0.5 s of the input",
            Window::HalfToTwoSeconds => "0.5–2 s after the input",
            Window::Later => "later",
        }
    }

    /// Where the gap map draws it: the window's centre, s after the input
    /// starts (the open ends half a second before and a second after).
    pub fn centre(self) -> f64 {
        match self {
            Window::BeforeInput => -0.5,
            Window::FirstHalfSecond => 0.25,
            Window::HalfToTwoSeconds => 1.25,
            Window::Later => 3.0,
        }
    }
}

/// The axis of the gap map a part lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PartAxis {
    /// Time after the input starts, s.
    Time,
    /// Lateral-acceleration level |ay|, m/s².
    Ay,
    /// Speed, m/s.
    Speed,
}

impl PartAxis {
    /// Every axis, in the gap map's order.
    pub const ALL: [PartAxis; 3] = [PartAxis::Time, PartAxis::Ay, PartAxis::Speed];
}

/// A part of the data a gap is pooled over: everything, a time window or a
/// regime (a band of |ay| or of speed, `lo` included, `hi` excluded).
/// Serialised as its label.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Part {
    /// All samples.
    All,
    /// A time window.
    Window(Window),
    /// Samples with `lo ≤ |ay| < hi`, m/s².
    Ay {
        /// Lower edge.
        lo: f64,
        /// Upper edge (may be infinite).
        hi: f64,
    },
    /// Samples with `lo ≤ speed < hi`, m/s.
    Speed {
        /// Lower edge.
        lo: f64,
        /// Upper edge.
        hi: f64,
    },
}

impl Part {
    /// Its label in reports: `all`, the window's name, `|ay| 2–4 m/s²`,
    /// `speed 20–30 m/s`.
    pub fn label(&self) -> String {
        match self {
            Part::All => "all".into(),
            Part::Window(w) => w.label().into(),
            Part::Ay { lo, hi } => format!("|ay| {lo}–{hi} m/s²"),
            Part::Speed { lo, hi } => format!("speed {lo}–{hi} m/s"),
        }
    }

    /// The part a label of [`super::gap::channel_gap`] names (`None`: not a
    /// label it writes). The gap analysis names its parts in text; this is
    /// the one place that reads them back, and only labels that
    /// [`Part::label`] writes again unchanged are accepted.
    pub fn from_label(label: &str) -> Option<Part> {
        let band = |s: &str, unit: &str| -> Option<(f64, f64)> {
            let (lo, hi) = s.strip_suffix(unit)?.split_once('–')?;
            Some((lo.parse().ok()?, hi.parse().ok()?))
        };
        let part = if label == "all" {
            Part::All
        } else if let Some(w) = Window::ALL.into_iter().find(|w| w.label() == label) {
            Part::Window(w)
        } else if let Some(rest) = label.strip_prefix("|ay| ") {
            let (lo, hi) = band(rest, " m/s²")?;
            Part::Ay { lo, hi }
        } else {
            let (lo, hi) = band(label.strip_prefix("speed ")?, " m/s")?;
            Part::Speed { lo, hi }
        };
        (part.label() == label).then_some(part)
    }

    /// Where the gap map draws it: its axis and position (a window's
    /// centre, a band's centre, or one above the lower edge of an open
    /// band). `None` for [`Part::All`].
    pub fn position(&self) -> Option<(PartAxis, f64)> {
        let centre = |lo: f64, hi: f64| {
            if hi.is_finite() {
                0.5 * (lo + hi)
            } else {
                lo + 1.0
            }
        };
        match *self {
            Part::All => None,
            Part::Window(w) => Some((PartAxis::Time, w.centre())),
            Part::Ay { lo, hi } => Some((PartAxis::Ay, centre(lo, hi))),
            Part::Speed { lo, hi } => Some((PartAxis::Speed, centre(lo, hi))),
        }
    }
}

impl std::fmt::Display for Part {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.label())
    }
}

impl Serialize for Part {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.label())
    }
}

/// Before/after on held-out runs for one part of the data.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Shrinkage {
    /// Channel.
    pub channel: Channel,
    /// All samples, a time window or a regime.
    pub part: Part,
    /// Samples.
    pub samples: usize,
    /// Held-out RMS with the base model.
    pub before: f64,
    /// Held-out RMS with the verdict's effects.
    pub after: f64,
    /// Noise floor of the channel.
    pub noise_floor: f64,
    /// Share of the gap above noise removed, %.
    pub reduction_percent: f64,
}

/// Noise floor and scale of a channel.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChannelNoise {
    /// Channel.
    pub channel: String,
    /// Unit.
    pub unit: String,
    /// Median over runs of the noise floor.
    pub noise_floor: f64,
    /// Residual scale used in the fits.
    pub scale: f64,
    /// Runs measuring it.
    pub runs: usize,
}

/// The gap of one run with the base model.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunGap {
    /// Run.
    pub run: String,
    /// Per channel.
    pub channels: Vec<ChannelGap>,
    /// Gain and phase error per frequency band (runs with a rich input).
    pub bands: Vec<super::gap::BandGap>,
}

/// Where the gap lies.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GapReport {
    /// Is there a gap above noise on held-out runs.
    pub significant: bool,
    /// Held-out J of the base model.
    pub heldout_error: f64,
    /// J of the noise alone.
    pub noise_level: f64,
    /// Noise floors.
    pub noise: Vec<ChannelNoise>,
    /// Per channel, window and regime over all runs (base model replays).
    pub parts: Vec<Shrinkage>,
    /// Per run.
    pub runs: Vec<RunGap>,
    /// The findings in words.
    pub summary: Vec<String>,
}

/// The base model.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BaseReport {
    /// Where its tyres come from.
    pub tyres: String,
    /// Front tyre (all-run or rig fit).
    pub front: Tyre,
    /// Rear tyre.
    pub rear: Tyre,
    /// Where every sample of the rig data went (levels, transitions,
    /// thinning), when the tyres were fitted to rig data.
    pub rig_grouping: Option<GroupingReport>,
}

/// Everything the diagnosis found.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Diagnosis {
    /// Campaign name.
    pub campaign: String,
    /// Seed of every random search.
    pub seed: u64,
    /// Runs, in order.
    pub runs: Vec<String>,
    /// Folds of the cross-validation.
    pub folds: usize,
    /// Notes on the inputs.
    pub notes: Vec<String>,
    /// Glitches, standstills and crawling found in the runs and what was
    /// excluded, repaired or masked.
    pub cleaning: crate::measured::clean::CleaningReport,
    /// The base model.
    pub base: BaseReport,
    /// Where the gap lies.
    pub gap: GapReport,
    /// Single effects, best first.
    pub ranking: Vec<Ranked>,
    /// Combinations tried, best first.
    pub combinations: Vec<Ranked>,
    /// The verdict.
    pub verdict: Verdict,
    /// Confounded effects.
    pub confounded: Vec<Confounded>,
    /// Before and after on held-out runs, per channel, window and regime.
    pub shrinkage: Vec<Shrinkage>,
    /// Held-out replays (measured / base / verdict) for the figures.
    #[serde(skip)]
    pub overlays: Vec<Overlay>,
}

/// One run's held-out replays.
#[derive(Debug, Clone, PartialEq)]
pub struct Overlay {
    /// Run name.
    pub run: String,
    /// Times, s.
    pub t: Vec<f64>,
    /// Measured channels.
    pub measured: Vec<(Channel, Vec<f64>)>,
    /// Base model.
    pub base: Observed,
    /// With the verdict's effects.
    pub after: Observed,
    /// Base-model combined error of the run.
    pub gap: f64,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::gap::{channel_gap, Record};

    #[test]
    fn every_part_of_a_gap_reads_back_as_a_typed_part() {
        // A record that visits every window, every |ay| band and three
        // speed bands.
        let t: Vec<f64> = (0..1200).map(|i| 0.01 * i as f64).collect();
        let steer: Vec<f64> = t
            .iter()
            .map(|&t| if t < 1.0 { 0.0 } else { 0.02 })
            .collect();
        let ay = t.clone();
        let speed: Vec<f64> = t.iter().map(|&t| 5.0 + 2.0 * t).collect();
        let rec = Record {
            t: &t,
            steer: &steer,
            ay: &ay,
            speed: &speed,
        };
        let sim: Vec<f64> = t.iter().map(|t| 0.1 * t.sin()).collect();
        let g = channel_gap("yaw_rate", "rad/s", &rec, &steer, &sim);
        let parts: Vec<Part> = g
            .windows
            .iter()
            .chain(&g.regimes)
            .map(|p| Part::from_label(&p.name).unwrap_or_else(|| panic!("{}", p.name)))
            .collect();
        assert_eq!(parts.len(), 4 + 5 + 3);
        assert_eq!(parts[0], Part::Window(Window::BeforeInput));
        assert_eq!(
            parts[8],
            Part::Ay {
                lo: 8.0,
                hi: f64::INFINITY
            }
        );
        assert_eq!(parts[8].position(), Some((PartAxis::Ay, 9.0)));
        assert_eq!(parts[9], Part::Speed { lo: 0.0, hi: 10.0 });
        assert_eq!(Part::from_label("speed 2–x m/s"), None);
    }
}
