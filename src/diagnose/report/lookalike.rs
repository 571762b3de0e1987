//! The numbers behind a verdict's look-alikes: the confounding window of
//! the look-alike rule (`verdict::rules::lookalike`) and where each
//! look-alike lies in it, alone ([`Lookalikes`]) and fitted in a set in
//! the place of its first effect ([`InSet`]). A look-alike can remove a
//! visibly smaller share of the gap than the verdict (50 % against 74 %)
//! and still lie in the window: the words say the window's numbers, not
//! "about as well". Held-out errors and gaps above noise are
//! dimensionless (J over channel scales), reductions in percent.

use crate::diagnose::effects::EffectKind;
use serde::Serialize;

/// The confounding window of a reference candidate: another that passes
/// and leaves a held-out gap above noise `G ≤ bound`, with
/// `bound = gap_factor·gap + noise_factor·noise_level`, is not told apart
/// from it. The factors are written with it so that a reader of
/// `diagnosis.json` can check the bound without the rule's source.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Window {
    /// The reference's held-out gap above noise `G = √(J² − J_n²)`.
    pub gap: f64,
    /// The noise level `J_n`.
    pub noise_level: f64,
    /// The multiple of the reference's gap the window reaches.
    pub gap_factor: f64,
    /// The noise allowance, in noise levels.
    pub noise_factor: f64,
    /// The bound on another's gap above noise.
    pub bound: f64,
}

impl Window {
    /// The window of a reference whose gap above noise is `gap` at noise
    /// level `noise_level`, by the factors `(gap_factor, noise_factor)`.
    pub fn of(gap: f64, noise_level: f64, (gap_factor, noise_factor): (f64, f64)) -> Self {
        Self {
            gap,
            noise_level,
            gap_factor,
            noise_factor,
            bound: gap_factor * gap + noise_factor * noise_level,
        }
    }
}

/// A single effect that passes alone and leaves a gap within the window
/// of the single the verdict's search started from.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Lookalike {
    /// The effect.
    pub effect: EffectKind,
    /// Its held-out reduction of the gap above noise, alone, %.
    pub reduction_percent: f64,
    /// Its held-out gap above noise, alone.
    pub gap: f64,
    /// A bank-like look-alike's bank read against the standstills (None:
    /// it fits no bank, or no standstill measured `a_y`).
    pub standstills: Option<StandstillBank>,
    /// Why it is not confounded with the verdict though its gap lies in
    /// the window (None: confounded).
    pub set_aside: Option<SetAside>,
}

impl Lookalike {
    /// Whether the runs leave it confounded with the verdict: in the
    /// window, and nothing beside the fit sets it aside.
    pub fn confounded(&self) -> bool {
        self.set_aside.is_none()
    }
}

/// Why a look-alike in the confounding window is set aside, typed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SetAside {
    /// The runs' standstills contradict the bank it fits and side with
    /// the verdict ([`Lookalike::standstills`] holds the reading).
    StandstillsContradictBank,
}

/// A bank-like look-alike (`bank_profile`, `road_bank`) against the
/// standstills' `a_y`. Parked, a body-fixed accelerometer reads its offset
/// plus `g·sin θ` of the road's bank θ (ISO 8855, bank positive with the
/// left edge higher; Groves 2013); the calibration reads the standstills
/// less `g·sin θ_logged` of a logged bank. A look-alike that fits a bank
/// `θ_fit` there and no offset predicts they read `g·sin θ_fit −
/// g·sin θ_logged`; the verdict predicts its own fitted offset (through
/// its own bank, if it fits one). Accelerations in m/s², banks in rad.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StandstillBank {
    /// What the standstills read (the logged bank's `g·sin` removed).
    pub measured: f64,
    /// Its standard error.
    pub measured_std_error: f64,
    /// The bank the look-alike fits where the standstills stood.
    pub bank: f64,
    /// The logged bank there (None: no bank column, a flat road as read).
    pub logged_bank: Option<f64>,
    /// The runs determine every parameter of that bank (none held, none
    /// traded beyond its range): false, its value there is one of many
    /// that fit the runs alike, and the standstills contradict none.
    pub determined: bool,
    /// What the standstills would read with the look-alike's bank.
    pub predicted: f64,
    /// Its standard error, from the fitted bank's.
    pub predicted_std_error: f64,
    /// `|measured − predicted|` over their combined standard error.
    pub standard_errors: f64,
    /// What the standstills read by the verdict's fit.
    pub verdict_predicted: f64,
    /// Its standard error.
    pub verdict_predicted_std_error: f64,
    /// `|measured − verdict_predicted|` over their combined standard error.
    pub verdict_standard_errors: f64,
    /// The two predictions differ by more than
    /// [`crate::diagnose::report::outcome::CALIBRATION_AGREES`] combined
    /// standard errors: the standstills can tell them apart.
    pub apart: bool,
}

/// The verdict's look-alikes alone and the window they lie in.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Lookalikes {
    /// The single the window is of: the one the verdict's search started
    /// from.
    pub start: EffectKind,
    /// Its held-out reduction alone, %.
    pub start_reduction_percent: f64,
    /// Its window.
    pub window: Window,
    /// The look-alikes the verdict did not take in, best first.
    pub members: Vec<Lookalike>,
}

/// A look-alike of a set's first effect fitted in the set in its place.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InSet {
    /// The set with the look-alike in place of the first effect.
    pub effects: Vec<EffectKind>,
    /// Its held-out reduction of the gap above noise, %.
    pub reduction_percent: f64,
    /// Its held-out gap above noise.
    pub gap: f64,
    /// The window of the verdict's set it is judged against.
    pub window: Window,
    /// Its gap lies within the window (the look-alike rule): still
    /// confounded in the set; false: the set tells them apart.
    pub confounded: bool,
}
