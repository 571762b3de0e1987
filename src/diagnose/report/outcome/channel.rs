//! A verdict's warnings on one channel: a held-out gap its effects make
//! larger ([`ChannelWorsened`]) or leave ([`ChannelLeft`]), each with what
//! the diagnosis already holds elsewhere about that channel
//! ([`ChannelCause`]: the sideslip-sign note, a run carrying most of the
//! gap left, a steady offset), so that "another cause" points where the
//! report already looks. Units: RMS values and floors in the channel's
//! unit (rad/s, m/s², rad); shares in percent.

use super::change::ChannelChange;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::values::SteadyOffset;
use serde::Serialize;

/// A channel's held-out gap that the verdict's effects make larger.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChannelWorsened {
    /// The channel.
    pub channel: Channel,
    /// Held-out RMS with the base model.
    pub before: f64,
    /// Held-out RMS with the verdict's effects.
    pub after: f64,
    /// The channel's noise floor.
    pub noise_floor: f64,
    /// Share of the gap above noise added, % (infinite, `null` in
    /// `diagnosis.json`, where the RMS before was at or below the floor:
    /// no gap above noise to take a share of).
    pub added_percent: f64,
    /// What the report holds elsewhere about this channel (empty: nothing).
    pub causes: Vec<ChannelCause>,
}

/// A channel's held-out gap, above noise before and after, of which the
/// verdict's effects remove less than the acceptance share
/// ([`crate::diagnose::verdict::rules::ACCEPT`]) the verdict needs of the
/// whole.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChannelLeft {
    /// The channel.
    pub channel: Channel,
    /// Held-out RMS with the base model.
    pub before: f64,
    /// Held-out RMS with the verdict's effects.
    pub after: f64,
    /// The channel's noise floor.
    pub noise_floor: f64,
    /// Share of the gap above noise removed, % (negative: grown, by less
    /// than a worsening).
    pub removed_percent: f64,
    /// The share the acceptance asks of the whole gap, %.
    pub acceptance_percent: f64,
    /// What the report holds elsewhere about this channel (empty: nothing).
    pub causes: Vec<ChannelCause>,
}

impl ChannelLeft {
    /// What the verdict's effects did to the channel's gap, by the rule
    /// the table and the page say it by ([`ChannelChange::of`]).
    pub fn change(&self) -> ChannelChange {
        ChannelChange::of(
            self.before,
            self.after,
            self.noise_floor,
            self.removed_percent,
        )
    }
}

/// What the diagnosis already found about a channel whose gap the
/// verdict's effects leave or make larger, elsewhere in its report.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum ChannelCause {
    /// A file whose measured sideslip moves against the base model's
    /// (the note [`super::Note::BetaAgainstInFile`]).
    BetaAgainst {
        /// The file.
        file: String,
        /// Its runs' pooled correlation with the base model's β.
        correlation: f64,
    },
    /// One run that carries most of the channel's held-out gap above noise
    /// with the verdict's effects (more than
    /// [`crate::diagnose::report::summary::DOMINANT_SHARE`] of it).
    RunCarries {
        /// The run.
        run: String,
        /// Its share of the channel's gap above noise left, %: its samples
        /// times `after² − floor²`, over the runs' sum.
        share_percent: f64,
        /// Its held-out RMS with the verdict's effects, the channel's unit.
        rms: f64,
        /// Its yaw rate's scale that the other runs do not share, read
        /// from its road's kinematics (its road's `scale_apart`).
        scale_apart: Option<crate::measured::road::ScaleApart>,
    },
    /// The base model's steady offset in the channel over the runs (its
    /// gap finding's, [`super::GapFinding::Channel`]).
    SteadyOffset(SteadyOffset),
}

/// The channel that carries most of what a verdict's effects leave: more
/// than [`crate::diagnose::report::shares::CARRIES_SHARE`] of the held-out
/// `J²` with them ([`super::VerdictWarning::GapRemains`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CarriedBy {
    /// The channel.
    pub channel: Channel,
    /// Its share of the held-out `J²` with the effects, %.
    pub share_percent: f64,
    /// Whether a warning on the channel ([`ChannelLeft`],
    /// [`ChannelWorsened`]) names causes the report holds.
    pub causes_named: bool,
    /// What the report holds about the channel where no warning on it
    /// names it (a run carrying most of its gap left, its steady offset;
    /// empty where `causes_named`, or nothing is held).
    pub causes: Vec<ChannelCause>,
    /// The channel's noise floor, its unit (the causes' RMS in floors).
    pub noise_floor: f64,
}

/// How the runs hold what a verdict leaves
/// ([`super::VerdictWarning::GapRemains`]): its held-out gap above noise
/// `G² = J² − J_n²` (the measure the share it leaves is of) split over the
/// runs, each run's part `Σ_c n_rc·(rms_rc²/s_c² − J_n²)` (its samples of
/// every channel over the channel's scale, less the noise level's), the
/// parts summing to `N·G²`; a run below the noise level holds none.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunsCarrying {
    /// The one run that holds more than two thirds of it, or the two that
    /// hold that much together (of four runs or more); empty: no one or two
    /// runs do, it is spread over the runs.
    pub carried_by: Vec<RunShare>,
    /// The runs with a part above the noise level.
    pub above_noise: usize,
    /// The runs measured.
    pub runs: usize,
    /// The run with the largest part, where it is not in `carried_by`
    /// (None: it is, or no run holds any).
    pub largest: Option<RunShare>,
}

/// One run's part of what a verdict leaves ([`RunsCarrying`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunShare {
    /// The run.
    pub run: String,
    /// Its part of the held-out gap above noise left, %.
    pub share_percent: f64,
    /// Its own held-out error `J` with the verdict's effects (residuals
    /// over the channels' scales, dimensionless; the noise level is the
    /// campaign's).
    pub heldout_error: f64,
    /// Its yaw rate's scale that the other runs do not share, read from
    /// its road's kinematics (its road's `scale_apart`; None: none).
    pub scale_apart: Option<crate::measured::road::ScaleApart>,
}
