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
        /// The fold refits' scatter where the standard error does not
        /// cover it ([`ParameterValue::understated`]): the agreement is
        /// judged on it in place of the standard error (None: it covers).
        fitted_fold_std_error: Option<f64>,
        /// Measured on the standstills, else on the straights; on
        /// standstills where the verdict fits the road's bank, read
        /// through that bank ([`ThroughBank`]).
        measured: f64,
        /// Where it was measured.
        measured_on: CalibrationSource,
        /// Its standard error.
        measured_std_error: f64,
        /// The standstills read through the verdict's fitted bank (None:
        /// the verdict fits no bank, or the offset is the straights').
        through_bank: Option<ThroughBank>,
        /// Within [`CALIBRATION_AGREES`] combined standard errors (the
        /// fitted value's trusted one: its fold scatter where that is
        /// given).
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
        /// Each pressed parameter's range searched, as [`Searched`].
        pressed_ranges: Vec<Searched>,
        /// The verdict's parameters in the unit of a pressed one, with the
        /// ranges they lie inside: a verdict whose parameters add up to
        /// the look-alike's pressed value (a steer path's delay and lag,
        /// summing to a sensor's 0.3 s delay) says why it is not pressed.
        verdict_inside: Vec<Searched>,
    },
    /// A look-alike that leaves less of the gap but leaves a parameter
    /// idle, passed over for a simpler candidate ([`Parsimony`]).
    ChosenForParsimony(Parsimony),
    /// A verdict the greedy search did not reach: from the best single on
    /// held-out runs (and its look-alikes) it stopped with no verdict, and
    /// the search that reached it started from a pair of the best singles
    /// in sample ([`crate::diagnose::verdict::pairs`]).
    PairsFallback(PairsFallback),
    /// A yaw inertia in the verdict, and the vehicle mass that would fit
    /// the runs the same ([`MassAlike`]).
    MassAlike(MassAlike),
}

/// A parameter's value and the range its fit searched, in its unit.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Searched {
    /// `effect.parameter`.
    pub name: String,
    /// Its unit.
    pub unit: &'static str,
    /// Fitted value.
    pub value: f64,
    /// The range searched (lower, upper).
    pub range: (f64, f64),
}

/// A verdict's yaw inertia scale `s`, and the vehicle mass that would fit
/// the runs the same. With the axles' cornering stiffness about
/// proportional to their loads, a mass `k` times the car's scales the
/// loads, and with them the axle forces, by `k`: the lateral balance
/// `m·ay = Fy,f + Fy,r` cancels it, the yaw balance `Iz·dr/dt = a·Fy,f −
/// b·Fy,r` does not, so it reads as the yaw inertia scaled by `k`. The
/// runs cannot tell a yaw inertia `s` times the file's from a mass `1/s`
/// times it. Masses in kg, inertias in kg·m².
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MassAlike {
    /// The fitted `yaw_inertia.scale`.
    pub scale: f64,
    /// The vehicle file's yaw inertia, kg·m².
    pub yaw_inertia: f64,
    /// The yaw inertia the scale gives, kg·m².
    pub yaw_inertia_fitted: f64,
    /// The vehicle file's mass, kg.
    pub mass: f64,
    /// The mass that fits the runs the same with the file's yaw inertia,
    /// `mass / scale`, kg.
    pub mass_alike: f64,
}

/// How a verdict reached by the pairs of the best singles in sample came
/// about: the greedy search's start and the set it ended on, refused, and
/// the pair that passed in its place. Reductions are held-out shares of
/// the gap above noise, %.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairsFallback {
    /// The best single on held-out runs, where the greedy search started.
    pub start: EffectKind,
    /// Share of the gap it removes, %.
    pub start_reduction_percent: f64,
    /// The set the greedy search ended on, refused.
    pub ended: Vec<EffectKind>,
    /// Share of the gap it removes, %.
    pub ended_reduction_percent: f64,
    /// Share a set must remove to be accepted (with a lower BIC), %.
    pub threshold_percent: f64,
    /// The best singles in sample whose pairs were formed, best first.
    pub paired_from: Vec<EffectKind>,
    /// The pair that passed and started the search that reached the
    /// verdict.
    pub pair: Vec<EffectKind>,
    /// Share of the gap it removes, %.
    pub pair_reduction_percent: f64,
    /// The start, where the pair leaves it out: the best single on
    /// held-out runs passed over.
    pub passed_over: Option<EffectKind>,
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

/// The standstills' `a_y` read through the bank a verdict fits
/// (`bank_profile`'s `scale·θ + offset`, `road_bank`'s constant): the
/// offset is `mean(a_y) − g·sin(θ_fitted)` there, where the calibration
/// read it through the logged bank `θ` (or a flat road without a bank
/// column). The verdict's sensor offset was fitted with the fitted bank,
/// so only this reading is the same quantity.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ThroughBank {
    /// The fitted bank where the standstills stood, rad.
    pub bank: f64,
    /// The logged bank there (None: no bank column), rad.
    pub logged_bank: Option<f64>,
    /// The offset read through the logged bank (or a flat road), m/s².
    pub as_logged: f64,
    /// The fitted bank's standard error there, rad: its parameters'
    /// (trusted) standard errors combined, with the correlation of a
    /// traded scale and offset. It enters the reading's uncertainty as
    /// `g·cos θ·σ_bank`.
    pub bank_std_error: f64,
}

/// Combined standard errors within which a fitted and a measured offset
/// agree.
pub const CALIBRATION_AGREES: f64 = 3.0;
