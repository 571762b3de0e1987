//! What the runs show beside a verdict's fit that bears on it, typed: a
//! fitted sensor offset against the one the standstills or straights
//! measured (in the channel's unit: rad/s, m/s², rad), axles the verdict's
//! effects made a tyre again, a look-alike that needed the end of its
//! search range, one that left a parameter idle where a simpler candidate
//! did about as well. [`super::words::evidence`] words them.

use crate::diagnose::base::identify::NoTyre;
use crate::diagnose::effects::EffectKind;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::values::ParameterValue;
use serde::Serialize;

/// What the runs show beside a verdict's fit that bears on it.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Evidence {
    /// A sensor offset the verdict fitted against the one the runs'
    /// standstills (else straights) measured.
    Calibration {
        /// The channel.
        channel: Channel,
        /// Fitted, in the channel's unit.
        fitted: f64,
        /// Its standard error.
        fitted_std_error: f64,
        /// Measured on the standstills, else on the straights.
        measured: f64,
        /// Where it was measured.
        measured_on: CalibrationSource,
        /// Its standard error.
        measured_std_error: f64,
        /// Within three combined standard errors.
        agrees: bool,
    },
    /// The base model alone is no tyre; fitted with the verdict's effects
    /// the axles are one: the effects account for what the base's axles
    /// were bent to.
    AxlesRestored {
        /// Why the base alone is not.
        no_tyre: Vec<NoTyre>,
    },
    /// A look-alike that leaves less of the gap, but only with parameters
    /// pressed on the end of their search ranges: the verdict, inside its
    /// ranges, was taken in its place ([`crate::diagnose::verdict::rules::pick`]).
    LookalikePressed {
        /// Its effects.
        effects: Vec<EffectKind>,
        /// Share of the held-out gap above noise it removes, %.
        reduction_percent: f64,
        /// Its parameters on a search bound.
        pressed: Vec<ParameterValue>,
    },
    /// A look-alike that leaves less of the gap but leaves a parameter
    /// idle, passed over for a simpler candidate ([`Parsimony`]).
    ChosenForParsimony(Parsimony),
}

/// A look-alike that leaves less of the gap, but leaves a parameter idle
/// (off, or not told from off): the candidate with the fewest free
/// parameters whose held-out error is within the parsimony window of its,
/// `heldout_error + window_noise_levels · noise_level`, was taken in its
/// place ([`crate::diagnose::verdict::rules::simpler_than`]): the verdict
/// itself, or the set its search started from or extended.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Parsimony {
    /// The look-alike's effects.
    pub effects: Vec<EffectKind>,
    /// Share of the held-out gap above noise it removes, %.
    pub reduction_percent: f64,
    /// Its held-out error J.
    pub heldout_error: f64,
    /// Its parameters (axles and roll dynamics included), the idle ones
    /// counted whether fitted to their off value or held there.
    pub free_parameters: usize,
    /// Its parameters left idle.
    pub idle: Vec<ParameterValue>,
    /// The effects taken in its place.
    pub taken: Vec<EffectKind>,
    /// Share of the held-out gap above noise they remove, %.
    pub taken_reduction_percent: f64,
    /// Their held-out error J.
    pub taken_heldout_error: f64,
    /// Their free parameters.
    pub taken_free_parameters: usize,
    /// The noise level J_n.
    pub noise_level: f64,
    /// The window, in noise levels.
    pub window_noise_levels: f64,
}

/// Where a sensor offset was measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum CalibrationSource {
    /// Standing still on a flat road (or a logged bank removed).
    Standstills,
    /// On straights at constant speed (no standstill measured it).
    Straights,
}

/// Combined standard errors within which a fitted and a measured offset
/// agree.
pub const CALIBRATION_AGREES: f64 = 3.0;
