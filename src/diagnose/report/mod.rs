//! The typed report of a diagnosis ([`super::diagnose`]): what
//! `diagnosis.json` holds. The outcome is typed ([`outcome`]: the verdict's
//! cases, refusals, warnings, notes, findings); its sentences are made in
//! one place ([`words`]) and written beside the types ([`json`]). Values
//! are SI and rad unless a field names its unit; held-out errors J are
//! dimensionless (residuals over channel scales).

pub(crate) mod cause;
mod evidence;
pub mod fold_refits;
pub(crate) mod gap;
mod json;
pub mod left_in;
mod lookalike;
mod narrowed;
pub mod outcome;
pub(crate) mod parts;
pub mod per_roll;
mod rank_warning;
pub(crate) mod runs_left;
pub mod separating;
pub mod shares;
pub(crate) mod summary;
pub mod traded;
pub(crate) mod trust;
pub mod tyre_class;
mod values;
pub mod words;
pub mod worth;

pub use crate::diagnose::model::scale::ScaleSource;

pub use crate::diagnose::base::identify::{Axle, AxleIdentification, AxleLimit, AxleValue, NoTyre};
pub use crate::diagnose::base::TyreSource;
use crate::diagnose::effects::{same_effects, EffectKind};
use crate::diagnose::fit::GlobalSearch;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::model::Observed;
pub use crate::diagnose::report::fold_refits::FoldRefit;
use crate::diagnose::report::gap::ChannelGap;
pub use crate::diagnose::report::outcome::{
    above_noise, AlsoFar, AssumedFloor, CalibrationSource, ChannelCause, ChannelChange,
    ChannelLeft, ChannelWorsened, ClassMismatch, Closest, Evidence, Explained, FarFromOff,
    GapFinding, InSet, Lookalike, Lookalikes, MassAlike, Narrowed, NoSignificantGap,
    NotIdentifiable, Note, OffsetMatch, OutsideLibrary, PairsFallback, Parsimony, RankWarning,
    Refusal, Refused, Searched, SetAside, StandstillBank, ThroughBank, Unseen, VehicleLimit,
    Verdict, VerdictKind, VerdictWarning, Window,
};
pub use crate::diagnose::report::parts::{Part, PartAxis};
pub use crate::diagnose::report::per_roll::{HeldRollGradient, PerLateralAcceleration};
pub use crate::diagnose::report::values::{
    jackknife, ParameterValue, Reduction, RunPart, Shrinkage, StdErrorBasis, Traded,
    LIMIT_RESOLUTION, UNDERSTATED,
};
use crate::diagnose::timing::Timing;
use crate::identify::grouping::GroupingReport;
use crate::tyre::Tyre;
use serde::Serialize;

/// Held-out RMS of one channel.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChannelError {
    /// Channel.
    pub channel: Channel,
    /// Unit.
    pub unit: &'static str,
    /// Held-out RMS residual.
    pub rms: f64,
}

/// One candidate (an effect or a combination) and its scores.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Ranked {
    /// The effect names joined by `+`.
    pub effect: String,
    /// The effects.
    pub effects: Vec<EffectKind>,
    /// The axle characteristics refitted with them (no tyre data), with
    /// their standard errors and the limits they stand on.
    pub axles: Option<Vec<AxleValue>>,
    /// What the prior's rows on the axles counted in its fits: `√(s²·τ)`
    /// of its residuals at its global stage's best (no tyre data).
    pub prior_weight: Option<f64>,
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
    /// Cross-validation that disagrees with the fit, axles that are no
    /// tyre, refits that did not converge (written as `warning`, one line
    /// or null, and `warning_details`).
    #[serde(flatten, serialize_with = "json::rank_warnings")]
    pub warnings: Vec<RankWarning>,
    /// BIC of the all-run fit.
    pub bic: f64,
    /// BIC minus the base model's (negative: better).
    pub delta_bic: f64,
    /// How the all-run fit's global stage searched (a grid along one to
    /// three parameters, a swarm along more).
    pub global_search: GlobalSearch,
}

/// A single effect not cross-validated: its fit on all runs removes so
/// little of the gap above noise that it could not pass on held-out runs
/// (its in-sample reduction plus the margin below the acceptance share;
/// see the diagnosis's screening).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Screened {
    /// The effect names joined by `+`.
    pub effect: String,
    /// The effects.
    pub effects: Vec<EffectKind>,
    /// The set a screened combination extends (the greedy search's
    /// current set; empty: a single, screened against the base model).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub extends: Vec<EffectKind>,
    /// Combined error J of the all-run fit on all runs (in sample).
    pub insample_error_after: f64,
    /// Share of the in-sample gap above noise the all-run fit removes, %:
    /// of the base model's gap, or of the gap the set it
    /// [`Screened::extends`] leaves.
    pub insample_reduction_percent: f64,
    /// Share of the held-out gap an effect must remove to be accepted, %.
    pub threshold_percent: f64,
    /// Percentage points by which a held-out reduction may exceed the
    /// in-sample one: screened below `threshold − margin`.
    pub margin_percent: f64,
    /// BIC of the all-run fit minus the base model's.
    pub delta_bic: f64,
    /// How the all-run fit's global stage searched.
    pub global_search: GlobalSearch,
    /// A greedy step's set not cross-validated because the step's pick
    /// could not read it (None: screened below the threshold).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub outranked: Option<Outranked>,
}

/// Why a greedy step's set was not cross-validated: its least possible
/// held-out error (its in-sample share plus the screening's margin)
/// lies beyond what the step's pick reads of its best set (the verdict's
/// parsimony window, or its look-alike window where it is pressed).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Outranked {
    /// The step's best set the pick reads first.
    pub by: Vec<EffectKind>,
    /// Its held-out error J.
    pub heldout_error: f64,
    /// The spared set's least possible held-out error J.
    pub floor: f64,
}

/// Effects whose held-out gaps lie within one another's confounding window (written with the
/// experiment that separates them, `separating_test`: each one's
/// signature).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Confounded {
    /// The effects.
    #[serde(flatten, serialize_with = "json::confounded")]
    pub effects: Vec<EffectKind>,
    /// Their reductions, %.
    pub reduction_percent: Vec<f64>,
    /// On a base with no friction limit, what the design's replays of the
    /// fitted candidates separate them by instead of the signatures'
    /// tests (filled in by the `diagnose` job; None elsewhere).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub separating_runs: Option<separating::SeparatingRuns>,
}

impl Confounded {
    /// Drops `apart` (effects told apart from the verdict, with their
    /// reductions) from every group in `confounded`, and a group where one
    /// effect is left.
    pub fn without(confounded: &mut Vec<Confounded>, apart: &[EffectKind]) {
        for c in confounded.iter_mut() {
            let keep: Vec<bool> = c.effects.iter().map(|e| !apart.contains(e)).collect();
            let mut k = keep.iter();
            c.effects.retain(|_| *k.next().unwrap_or(&true));
            let mut k = keep.iter();
            c.reduction_percent.retain(|_| *k.next().unwrap_or(&true));
        }
        confounded.retain(|c| c.effects.len() > 1);
    }
}

/// Noise floor and scale of a channel.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChannelNoise {
    /// Channel.
    pub channel: Channel,
    /// Unit.
    pub unit: &'static str,
    /// The uncertainty the channel is trusted to, its noise floor: stated,
    /// or the median over runs of its scatter, at least its sensor type's
    /// floor, or an estimated output's ([`ScaleSource`]).
    pub noise_floor: f64,
    /// Residual scale used in the fits.
    pub scale: f64,
    /// Where the noise floor comes from.
    pub source: ScaleSource,
    /// The median over runs of its high-frequency scatter.
    pub scatter: f64,
    /// Runs measuring it.
    pub runs: usize,
    /// Runs whose own scatter, read alone, falls on the other side of the
    /// line between a sensor and an estimated output than the median's
    /// ([`crate::diagnose::model::scale::near_the_line`]).
    pub other_side: usize,
    /// A stated uncertainty more than
    /// [`crate::diagnose::model::scale::STATED_EXCESS`] times what the
    /// channel shows of itself: a gap below it is insignificant by the
    /// statement, not by the data.
    pub stated_excess: Option<crate::diagnose::model::scale::StatedExcess>,
}

/// The gap of one run with the base model.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunGap {
    /// Run.
    pub run: String,
    /// Per channel.
    pub channels: Vec<ChannelGap>,
    /// Gain and phase error per frequency band (runs with a rich input).
    pub bands: Vec<crate::diagnose::report::gap::BandGap>,
    /// Bands with the steer's power share whose response lies at the
    /// noise ([`crate::diagnose::report::gap::BAND_SNR`]): not said.
    pub bands_without_steer: usize,
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
    /// Per channel, window and regime over all runs: the base model's
    /// held-out replays before, the verdict's after (the same rows as
    /// [`Diagnosis::shrinkage`]; after = before without a verdict). Not
    /// written: the JSON holds them once, as `shrinkage` (they were a
    /// third of an 8-run campaign's file twice over).
    #[serde(skip)]
    pub parts: Vec<Shrinkage>,
    /// Each channel's share of the held-out `J²`, before the verdict and
    /// with it ([`shares::channel_shares`]).
    pub channel_shares: Vec<shares::ChannelShare>,
    /// Per run.
    pub runs: Vec<RunGap>,
    /// The findings (written as `summary`, in words, and `findings`).
    #[serde(flatten, serialize_with = "json::findings")]
    pub findings: Vec<GapFinding>,
}

/// The base model (written with `tyres`, where they come from in words).
#[derive(Debug, Clone, PartialEq)]
pub struct BaseReport {
    /// Where its tyres come from.
    pub source: TyreSource,
    /// Front tyre (all-run or rig fit).
    pub front: Tyre,
    /// Rear tyre.
    pub rear: Tyre,
    /// Where every sample of the rig data went (levels, transitions,
    /// thinning), when the tyres were fitted to rig data.
    pub rig_grouping: Option<GroupingReport>,
    /// The axle characteristics identified from the runs (no tyre data):
    /// values, standard errors, the largest correlation, the limits they
    /// stand on and whether the base is a tyre at all.
    pub axles: Option<AxleIdentification>,
}

/// Everything the diagnosis found.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Diagnosis {
    /// Campaign name.
    pub campaign: String,
    /// The campaign's file or folder, as given (`handling design` reads it
    /// back).
    pub source: std::path::PathBuf,
    /// The same, absolute, where the job that wrote the diagnosis could
    /// resolve it: `handling design` run from another folder finds the
    /// campaign by it when `source` is relative to where `diagnose` ran.
    pub source_absolute: Option<std::path::PathBuf>,
    /// Seed of every random search.
    pub seed: u64,
    /// How the fits took their Jacobians (`[diagnose] derivatives`).
    pub derivatives: crate::optim::local::Derivatives,
    /// Runs, in order.
    pub runs: Vec<String>,
    /// Folds of the cross-validation.
    pub folds: usize,
    /// Notes on the inputs (written as `notes`, in words, and
    /// `note_details`).
    #[serde(flatten, serialize_with = "json::notes")]
    pub notes: Vec<Note>,
    /// Glitches, standstills and crawling found in the runs and what was
    /// excluded, repaired or masked.
    pub cleaning: crate::measured::clean::CleaningReport,
    /// Sensor offsets from the standstills and straights of the runs as
    /// read, before the cleaning.
    pub calibration: crate::measured::calibration::CalibrationReport,
    /// The road under each replayed piece: the bank measured or estimated
    /// from the lateral kinematics, the grade from `ax − du/dt`
    /// ([`crate::measured::road`]); reported, not fitted.
    pub road: Vec<crate::measured::road::RoadGeometry>,
    /// The base model.
    pub base: BaseReport,
    /// Where the gap lies.
    pub gap: GapReport,
    /// Single effects cross-validated, best first.
    pub ranking: Vec<Ranked>,
    /// Single effects screened (not cross-validated), in library order.
    pub screened: Vec<Screened>,
    /// Combinations tried, best first.
    pub combinations: Vec<Ranked>,
    /// The verdict.
    pub verdict: Verdict,
    /// Confounded effects.
    pub confounded: Vec<Confounded>,
    /// Before and after on held-out runs, per channel, window and regime
    /// (each all-samples row written with the runs the verdict's effects
    /// leave above noise, `left_in`: [`left_in::runs_left_in`]).
    #[serde(serialize_with = "json::shrinkage")]
    pub shrinkage: Vec<Shrinkage>,
    /// Held-out replays (measured / base / verdict) for the figures.
    #[serde(skip)]
    pub overlays: Vec<Overlay>,
    /// Where the time went: wall and CPU seconds, threads, and the phases
    /// (their seconds summed over calls, which overlap on several threads).
    pub timing: Timing,
}

impl Diagnosis {
    /// The ranking row of the verdict's effects (a single or a
    /// combination), if there is a verdict.
    pub fn verdict_row(&self) -> Option<&Ranked> {
        let effects = self.verdict.effects();
        self.ranking
            .iter()
            .chain(&self.combinations)
            // As sets: a combination's row is the set, in whichever order
            // it was built.
            .find(|r| !effects.is_empty() && same_effects(&r.effects, effects))
    }

    /// The single effects screened before their cross-validation (not the
    /// sets the greedy additions screened: [`Diagnosis::screened_sets`]).
    pub fn screened_singles(&self) -> impl Iterator<Item = &Screened> {
        self.screened.iter().filter(|s| s.extends.is_empty())
    }

    /// The sets the greedy additions screened (each with the set it
    /// [`Screened::extends`]).
    pub fn screened_sets(&self) -> impl Iterator<Item = &Screened> {
        self.screened.iter().filter(|s| !s.extends.is_empty())
    }

    /// How the report says candidate `r`'s held-out and in-sample
    /// reductions: by [`Reduction::of`] against the campaign's gap, the
    /// one rule of the terminal and the page.
    pub fn reductions(&self, r: &Ranked) -> [Reduction; 2] {
        let of = |p| Reduction::of(p, self.gap.significant);
        [of(r.reduction_percent), of(r.insample_reduction_percent)]
    }
}

/// One run's held-out replays.
#[derive(Debug, Clone, PartialEq)]
pub struct Overlay {
    /// Run name.
    pub run: String,
    /// When its replay starts, s (before `t[0]` where the opening
    /// stretch is not scored).
    pub start: f64,
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

impl AssumedFloor {
    /// The share of its floor a noise-free channel's RMS must reach to
    /// rest on it: below, the residual is a replay's arithmetic (1e-6 of
    /// the signal), far below any slip sensor's noise (0.0017 rad).
    pub const RESOLVED: f64 = 1e-3;

    /// The assumption a channel's verdict of RMS `rms` rests on, where it
    /// does: within [`outcome::SIGNIFICANT_NOISE_FLOORS`] of its assumed floor,
    /// beyond them of its scatter.
    /// A channel without scatter (noise-free: the replay of an
    /// estimator's output, 0 before the input) rests on its floor too,
    /// where its RMS is resolved (above [`Self::RESOLVED`] of the floor): a
    /// sideslip 0.0054 rad off beside a floor of 0.005 read "no
    /// significant gap" without the word.
    pub fn of(n: &ChannelNoise, rms: f64) -> Option<Self> {
        let own = n.scatter;
        let rests = n.source == ScaleSource::Estimated
            && own.is_finite()
            && own >= 0.0
            && rms > Self::RESOLVED * n.noise_floor
            && !above_noise(rms, n.noise_floor)
            && above_noise(rms, own);
        rests.then_some(AssumedFloor {
            channel: n.channel,
            floor: n.noise_floor,
            scatter: own,
            rms,
        })
    }
}
