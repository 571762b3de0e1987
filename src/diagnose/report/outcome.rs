//! What the diagnosis concludes, typed: the verdict and its four cases,
//! why a candidate was refused, the warnings on a candidate and on the
//! verdict, the notes on the inputs and the findings on where the gap
//! lies. The sentences are made from these at the edge ([`super::words`]:
//! the terminal, `diagnosis.json`'s strings, the page, the fleet table and
//! Python read them from there); no rule reads a sentence.
//!
//! One rule lives here (`change.rs`) because the page and the verdict's
//! warnings both read it: what the verdict's effects did to a channel's
//! held-out gap ([`ChannelChange::of`]).
//!
//! Units: held-out errors J dimensionless (residuals over channel scales),
//! reductions in percent, RMS values in the channel's unit (rad/s, m/s²,
//! rad).

use crate::diagnose::base::identify::NoTyre;
use crate::diagnose::effects::EffectKind;
use crate::diagnose::model::channels::Channel;
pub use crate::diagnose::report::evidence::{
    CalibrationSource, Evidence, MassAlike, PairsFallback, Parsimony, Searched, ThroughBank,
    CALIBRATION_AGREES,
};
pub use crate::diagnose::report::lookalike::{
    InSet, Lookalike, Lookalikes, SetAside, StandstillBank, Window,
};
pub use crate::diagnose::report::narrowed::{Narrowed, OffsetMatch};
use crate::diagnose::report::parts::Part;
pub use crate::diagnose::report::rank_warning::RankWarning;
pub use crate::diagnose::report::tyre_class::ClassMismatch;
use crate::diagnose::report::values::{ParameterValue, SteadyOffset};
use serde::{Deserialize, Serialize};

/// Which case a verdict is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum VerdictKind {
    /// Effects of the library explain the gap (all of it, or part).
    Explained,
    /// The base model's held-out error is within noise.
    NoSignificantGap,
    /// The base model is no tyre and no candidate makes it one.
    NotIdentifiable,
    /// A gap no candidate of the library is accepted for (or, where the
    /// campaign narrowed the candidates, none of those it names:
    /// [`OutsideLibrary::narrowed`]).
    OutsideLibrary,
}

impl VerdictKind {
    /// Every case.
    pub const ALL: [VerdictKind; 4] = [
        VerdictKind::Explained,
        VerdictKind::NoSignificantGap,
        VerdictKind::NotIdentifiable,
        VerdictKind::OutsideLibrary,
    ];

    /// Its name in reports (`verdict.kind` in `diagnosis.json`).
    pub fn name(self) -> &'static str {
        match self {
            VerdictKind::Explained => "explained",
            VerdictKind::NoSignificantGap => "no_significant_gap",
            VerdictKind::NotIdentifiable => "not_identifiable",
            VerdictKind::OutsideLibrary => "outside_library",
        }
    }
}

/// What the diagnosis concludes.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// Effects explain the gap.
    Explained(Explained),
    /// No gap above noise.
    NoSignificantGap(NoSignificantGap),
    /// The base model is not identifiable from the runs.
    NotIdentifiable(NotIdentifiable),
    /// A model-form error outside the library.
    OutsideLibrary(OutsideLibrary),
}

impl Verdict {
    /// Its case.
    pub fn kind(&self) -> VerdictKind {
        match self {
            Verdict::Explained(_) => VerdictKind::Explained,
            Verdict::NoSignificantGap(_) => VerdictKind::NoSignificantGap,
            Verdict::NotIdentifiable(_) => VerdictKind::NotIdentifiable,
            Verdict::OutsideLibrary(_) => VerdictKind::OutsideLibrary,
        }
    }

    /// The effects the evidence supports (empty unless explained).
    pub fn effects(&self) -> &[EffectKind] {
        match self {
            Verdict::Explained(e) => &e.effects,
            _ => &[],
        }
    }

    /// Their fitted parameters.
    pub fn parameters(&self) -> &[ParameterValue] {
        match self {
            Verdict::Explained(e) => &e.parameters,
            _ => &[],
        }
    }

    /// Its warnings (an explained verdict's).
    pub fn warnings(&self) -> &[VerdictWarning] {
        match self {
            Verdict::Explained(e) => &e.warnings,
            _ => &[],
        }
    }
}

/// Below this held-out reduction (%) an accepted set explains only part
/// of the gap, and the verdict says what share it leaves.
pub const EXPLAINS_MOST: f64 = 50.0;

/// How much of the gap above noise a verdict's effects explain, as its
/// statement says it (`diagnosis.json`'s `extent`): a reader of the JSON
/// tells "explains the gap" from "explains most of the gap" without
/// parsing the sentence.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Extent {
    /// What the effects leave is noise.
    All,
    /// At least [`EXPLAINS_MOST`] % removed, but a gap above noise remains
    /// ([`VerdictWarning::GapRemains`]).
    Most,
    /// Below [`EXPLAINS_MOST`] % removed.
    Part,
}

/// A held-out error at or below this multiple of the noise level is no
/// gap (the verdict's rules apply it, `verdict::rules::SIGNIFICANT`; set
/// here, below them, where the words that say it read it too).
pub const SIGNIFICANT_GAP: f64 = 1.3;

/// Effects that explain the gap.
#[derive(Debug, Clone, PartialEq)]
pub struct Explained {
    /// The effects.
    pub effects: Vec<EffectKind>,
    /// Their parameters.
    pub parameters: Vec<ParameterValue>,
    /// Held-out J of the base model.
    pub heldout_error_before: f64,
    /// Held-out J with the effects.
    pub heldout_error_after: f64,
    /// J of the noise alone.
    pub noise_level: f64,
    /// Share of the held-out gap above noise removed, %.
    pub reduction_percent: f64,
    /// What the verdict's effects leave worse, and parameters on a bound.
    pub warnings: Vec<VerdictWarning>,
    /// What the runs show beside the fit that bears on it.
    pub evidence: Vec<Evidence>,
    /// Singles whose gap lies within the confounding window of the single
    /// the search started from ([`Lookalikes`]; the report's
    /// `confounded`): the verdict is one of them until a test separates
    /// them. None: no look-alike.
    pub confounded_with: Option<Lookalikes>,
    /// For a verdict of several effects, each look-alike fitted in the set
    /// in place of its first ([`InSet`]): whether the set's gap with it
    /// still lies within the set's window. Empty for a single effect.
    pub in_set: Vec<InSet>,
}

impl Explained {
    /// Whether the effects explain only part of the gap (below
    /// [`EXPLAINS_MOST`]).
    pub fn partial(&self) -> bool {
        self.reduction_percent < EXPLAINS_MOST
    }

    /// How much of the gap the effects explain ([`Extent`]).
    pub fn extent(&self) -> Extent {
        let remains = |w: &VerdictWarning| matches!(w, VerdictWarning::GapRemains { .. });
        if self.partial() {
            Extent::Part
        } else if self.warnings.iter().any(remains) {
            Extent::Most
        } else {
            Extent::All
        }
    }

    /// The channels whose gap the effects leave ([`ChannelLeft`]).
    pub fn channels_left(&self) -> Vec<Channel> {
        self.warnings
            .iter()
            .filter_map(|w| match w {
                VerdictWarning::ChannelLeft(c) => Some(c.channel),
                _ => None,
            })
            .collect()
    }
}

/// A held-out error within noise.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NoSignificantGap {
    /// Held-out J of the base model.
    pub heldout_error: f64,
    /// J of the noise alone.
    pub noise_level: f64,
    /// The multiple of the noise level a gap must exceed.
    pub threshold: f64,
    /// The channels whose uncertainty, stated under `[channels]`, is more
    /// than [`crate::diagnose::model::scale::STATED_EXCESS`] times what
    /// they show of themselves: the verdict rests on those statements.
    pub resting_on: Vec<crate::diagnose::model::scale::StatedExcess>,
    /// The channels whose floor is assumed (an estimated output's, nothing
    /// stated) and whose held-out RMS would be a gap against their own
    /// scatter: the verdict rests on that assumption.
    pub assumed: Vec<AssumedFloor>,
    /// The best candidate on held-out runs of those that lower the
    /// held-out error and fit a parameter [`FAR_FROM_OFF`] from off, with
    /// the others that do too: the rule weighs no candidate on a gap
    /// within noise, and the words say what it found and what would
    /// decide it (None: none fits that far from off).
    pub far_from_off: Option<FarFromOff>,
}

/// A channel within three noise floors only because its floor is assumed:
/// read as an estimated output and trusted to an estimated output's
/// uncertainty, nothing stated, its RMS above three of its own scatter.
/// The floor is the policy of trusted channel uncertainties; the verdict
/// says it rests on it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AssumedFloor {
    /// The channel.
    pub channel: Channel,
    /// The floor it is trusted to, its unit.
    pub floor: f64,
    /// Its own high-frequency scatter, its unit.
    pub scatter: f64,
    /// Its RMS (held-out, or the replay's), its unit.
    pub rms: f64,
}

/// Standard errors from its off value beyond which a parameter fitted on a
/// gap within noise is named: far past what fitting the noise gives (a
/// no-effect campaign's candidates land within a few), since on correlated
/// residuals the standard error may understate a few times.
pub const FAR_FROM_OFF: f64 = 10.0;

/// Noise levels by which such a candidate must lower the held-out error
/// to be named: measured, a sensor delay fitted to pure noise lowered it
/// by 0.048 (a jagged well's tiny standard error, not evidence), a true
/// 0.03 rad bank on a slow oval by 0.229; a tenth lies between them with
/// a factor of two either side.
pub const FAR_FROM_OFF_REMOVAL: f64 = 0.1;

/// A candidate fitted far from off where the gap is within noise.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FarFromOff {
    /// The candidate's effects.
    pub effects: Vec<EffectKind>,
    /// Its parameter farthest from off, in standard errors.
    pub parameter: ParameterValue,
    /// That parameter's off value, in its unit.
    pub off: f64,
    /// `|value − off| / std_error`.
    pub standard_errors: f64,
    /// Held-out J with it.
    pub heldout_error_after: f64,
    /// The other candidates that lower the held-out error and fit a
    /// parameter [`FAR_FROM_OFF`] from off, best held-out first: on a gap
    /// within noise the runs tell none of them from it.
    pub also: Vec<AlsoFar>,
}

/// Another candidate fitted far from off where the gap is within noise.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AlsoFar {
    /// Its effects.
    pub effects: Vec<EffectKind>,
    /// Its parameter farthest from off, in standard errors.
    pub standard_errors: f64,
    /// Held-out J with it.
    pub heldout_error_after: f64,
}

/// A base model that is no tyre, and no candidate that makes it one.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NotIdentifiable {
    /// Held-out J of the base model.
    pub heldout_error: f64,
    /// J of the noise alone.
    pub noise_level: f64,
    /// Why the base's axles are no tyre.
    pub no_tyre: Vec<NoTyre>,
    /// The share of the gap a candidate must remove, %.
    pub threshold_percent: f64,
    /// The candidates (singles and sets) whose axles, fitted jointly with
    /// them, are a tyre, best held-out first: what the base's fingerprint
    /// may come from, though none removes enough of the gap.
    pub closest: Vec<Closest>,
    /// The road friction the campaign states, which trades off with them.
    pub road_friction: Option<crate::diagnose::campaign::StatedFriction>,
    /// Axles another tyre class's ranges hold (None: none does).
    pub tyre_class: Option<ClassMismatch>,
    /// The campaign's `[diagnose] effects` where it left effects of the
    /// library untried (None: the whole library was tried).
    pub narrowed: Option<Narrowed>,
}

/// A candidate whose jointly fitted axles are a tyre, and the share of the
/// held-out gap above noise it removes (%).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Closest {
    /// Its effects.
    pub effects: Vec<EffectKind>,
    /// Share of the held-out gap above noise removed, %.
    pub reduction_percent: f64,
}

/// A gap no candidate of the library is accepted for.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OutsideLibrary {
    /// Held-out J of the base model.
    pub heldout_error: f64,
    /// J of the noise alone.
    pub noise_level: f64,
    /// The best single candidate on held-out runs and why it was refused
    /// (None without any).
    pub refused: Option<Refused>,
    /// The share of the gap a candidate must remove, %.
    pub threshold_percent: f64,
    /// Axles another tyre class's ranges hold (None: none does).
    pub tyre_class: Option<ClassMismatch>,
    /// The campaign's `[diagnose] effects` where it left effects of the
    /// library untried (None: the whole library was tried).
    pub narrowed: Option<Narrowed>,
    /// The notes on the inputs that bear on the gap (a file whose
    /// sideslip moves against the base model's; filled once the notes are
    /// made, `report::cause::point`): an effect outside the library, or
    /// that file.
    pub bearing: Vec<ChannelCause>,
    /// The run (or two) holding most of the base model's gap above noise,
    /// or that it is spread over the runs (None: fewer than two runs).
    pub runs_carrying: Option<RunsCarrying>,
}

/// A candidate that is not the verdict, and why.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Refused {
    /// Its effects.
    pub effects: Vec<EffectKind>,
    /// Share of the held-out gap above noise it removes, %.
    pub reduction_percent: f64,
    /// The rules it fails (every one; empty only where nothing is known).
    pub why: Vec<Refusal>,
}

/// A rule a candidate fails.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Refusal {
    /// It removes less than the acceptance share.
    BelowAcceptance {
        /// The acceptance share, %.
        threshold_percent: f64,
    },
    /// Its BIC is not lower than the base model's.
    BicNotLower {
        /// Its BIC minus the base's.
        delta_bic: f64,
    },
    /// Fitted with it, the axles are no tyre.
    AxlesNoTyre {
        /// Why.
        no_tyre: Vec<NoTyre>,
    },
    /// It leaves a parameter idle: a simpler candidate within the
    /// parsimony margin was taken in its place, and refused.
    LeavesParameterIdle {
        /// The simpler candidate.
        simpler: Box<Refused>,
    },
    /// A parameter of it is pressed on its search bound: a look-alike
    /// inside its ranges was taken in its place, and refused.
    PressedOnSearchBound {
        /// The look-alike.
        inside: Box<Refused>,
    },
    /// It passes, but the search from it ended on a set that was refused.
    SearchEndedOn {
        /// The set.
        set: Box<Refused>,
    },
}

/// A warning on an explained verdict.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum VerdictWarning {
    /// A channel the verdict's effects leave worse on held-out runs.
    ChannelWorsened(ChannelWorsened),
    /// A channel whose held-out gap above noise the verdict's effects
    /// leave nearly as it was: the combined error fell through the other
    /// channels, and this one's gap has another cause.
    ChannelLeft(ChannelLeft),
    /// Parameters of the verdict's effects that lie on the end of their
    /// search range: the data would take them further, so their values
    /// are bounds, not measurements of the effects' size.
    OnSearchBound {
        /// The parameters, as the verdict reports them.
        parameters: Vec<ParameterValue>,
    },
    /// The given base tyres are used far from their load range: a wheel's
    /// static load over the file's `FNOMIN` beyond a factor of three
    /// (`simulate`'s rule); the effects fitted may stand in for a tyre of
    /// another class of vehicle.
    TyresFarFromLoad {
        /// Front wheel's static load over the front file's FNOMIN, where far.
        front: Option<f64>,
        /// The rear's.
        rear: Option<f64>,
    },
    /// What the verdict's effects leave is itself a gap: a held-out error
    /// above the significance threshold of the noise level, the rest of
    /// the gap a further cause and not noise. Said of a verdict that
    /// explains most of the gap (one that explains part says what it
    /// leaves in its sentence).
    GapRemains {
        /// Held-out J with the effects.
        heldout_error_after: f64,
        /// J of the noise alone.
        noise_level: f64,
        /// The multiple of the noise level a gap exceeds.
        threshold: f64,
        /// Share of the gap above noise left, %.
        left_percent: f64,
        /// The channel carrying more than two thirds of the held-out `J²`
        /// with the effects, where one does (filled from the gap's shares
        /// once they are made, `report::cause::point`): where the further
        /// cause lies.
        carried_by: Option<CarriedBy>,
        /// The run (or two) holding most of what the effects leave, or
        /// that it is spread over the runs (filled with `carried_by`; None
        /// without two runs or the parts to split).
        runs_carrying: Option<RunsCarrying>,
    },
    /// The axles fitted with the verdict's effects lie outside the stated
    /// tyre class's 95 % ranges and inside another class's: the class the
    /// fits' prior pulled them toward is the campaign's to check.
    TyreClass(ClassMismatch),
}

mod change;
mod channel;
mod note;
pub use crate::error::Unseen;
pub use change::{above_noise, ChannelChange, SIGNIFICANT_NOISE_FLOORS, WORSENED};
pub use channel::{CarriedBy, ChannelCause, ChannelLeft, ChannelWorsened, RunShare, RunsCarrying};
pub use note::{LoadRangeOf, Note, TyreAxles, VehicleLimit};

/// A finding on where the base model's gap lies.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum GapFinding {
    /// The held-out error against the noise level.
    Overall {
        /// A gap above noise.
        significant: bool,
        /// Held-out J of the base model.
        heldout_error: f64,
        /// J of the noise alone.
        noise_level: f64,
    },
    /// One channel over all runs.
    Channel {
        /// The channel.
        channel: Channel,
        /// Held-out RMS, all samples.
        rms: f64,
        /// Noise floor.
        noise_floor: f64,
        /// Runs in which its gap is significant.
        significant_runs: usize,
        /// Those runs' names and their held-out RMS of the channel (its
        /// unit): a gap in one run that no part over all runs isolates
        /// is named by its run.
        significant_in: Vec<(String, f64)>,
        /// The runs that measure the channel and in which its gap is
        /// within noise, with their held-out RMS (its unit): where they
        /// are fewer, the words name them ("all but …").
        within_in: Vec<(String, f64)>,
        /// Runs that measure the channel (a run without its column is
        /// counted in neither list).
        runs: usize,
        /// Parts (windows, regimes) above three noise floors, with their RMS.
        wrong: Vec<(Part, f64)>,
        /// Parts within three noise floors.
        right: Vec<Part>,
        /// The runs above three noise floors in a part of `right` (pooled,
        /// the others drown them): such a part is said right but for them
        /// (round 39: one run's yaw rate +0.02 rad/s, 6.5 floors before
        /// its input, under "right in: before the input").
        off_in_right: Vec<OffInRight>,
        /// A residual mean of one sign over the runs, at least a noise
        /// floor ([`SteadyOffset::of`]): a sensor offset or a bias of the
        /// model that an RMS against three noise floors does not single out.
        offset: Option<SteadyOffset>,
        /// The combined held-out gap of all channels over all runs where
        /// it is significant ([`GapFinding::Overall`]), else None: a
        /// channel within noise alone is then no gap of its own, and where
        /// no channel is significant alone the channels together carry a
        /// gap spread thinly over them, not none.
        combined: Option<CombinedGap>,
    },
    /// A frequency band whose yaw-rate response is off in a run.
    Band {
        /// The run.
        run: String,
        /// Band, Hz.
        f_low: f64,
        /// Band, Hz.
        f_high: f64,
        /// Gain error, dB.
        gain_error_db: f64,
        /// Phase error, degrees.
        phase_error_deg: f64,
    },
    /// Frequency bands holding the steer's power share whose yaw-rate
    /// response lies at the noise ([`crate::diagnose::report::gap::BAND_SNR`]):
    /// no gain or phase is said of them.
    BandsWithoutSteer {
        /// Such bands over all runs.
        bands: usize,
        /// Runs with at least one.
        runs: usize,
    },
    /// One channel carries most of the base model's held-out error: it
    /// decides every fit.
    Dominant {
        /// The channel.
        channel: Channel,
        /// Its share of `J²`, %, each channel's steady offset set aside.
        share_percent: f64,
        /// Its share of `J²`, %, the offsets counted (its `channel_shares`
        /// row's `before_percent`; equal to `share_percent` without one).
        with_offsets_percent: f64,
        /// The channels whose steady offset was set aside.
        less_offsets: Vec<Channel>,
    },
    /// Runs without an ay channel: their |ay| levels are u·r.
    WithoutAy {
        /// Such runs.
        runs: usize,
        /// All runs.
        of: usize,
    },
}

/// A run whose held-out RMS with the base model lies above three noise
/// floors ([`SIGNIFICANT_NOISE_FLOORS`]) in a part that is within them
/// pooled over the runs ([`GapFinding::Channel`]'s `right`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OffInRight {
    /// The part.
    pub part: Part,
    /// The run.
    pub run: String,
    /// Its held-out RMS in the part, the channel's unit.
    pub rms: f64,
}

/// The combined held-out gap of all channels where it is significant, as
/// a channel's finding reads it ([`GapFinding::Channel`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CombinedGap {
    /// Held-out J of the base model, all channels and runs.
    pub heldout_error: f64,
    /// J of the noise alone.
    pub noise_level: f64,
    /// The channels whose held-out RMS over all runs is above
    /// [`SIGNIFICANT_NOISE_FLOORS`] of their floor ([`above_noise`]: the
    /// per-channel table's rule): where the combined gap lies.
    pub significant_alone: Vec<Channel>,
}

#[cfg(test)]
mod tests;
