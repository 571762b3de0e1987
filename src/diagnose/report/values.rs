//! The two report values the verdict's types carry: a fitted parameter
//! where it stands against its bounds ([`ParameterValue`]) and a channel's
//! held-out gap in one part of the data before and after the verdict's
//! effects ([`Shrinkage`]). In their own file so that the typed outcome
//! (`outcome.rs`) reads them without reading the report that holds it.
//! Beside them the one rule by which the terminal and the page say a
//! candidate's reduction of the combined error ([`Reduction`]).
//! Values in the parameter's own unit; RMS values in the channel's unit
//! (rad/s, m/s², rad).

use crate::diagnose::effects::{Bound, Group, Parameter, RollDynamics};
use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::fold_refits::FoldRefit;
use crate::diagnose::report::parts::Part;
use crate::diagnose::report::per_roll::{HeldRollGradient, PerLateralAcceleration};
use serde::Serialize;

/// A fitted parameter.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ParameterValue {
    /// `effect.parameter`.
    pub name: String,
    /// Unit.
    pub unit: &'static str,
    /// Value fitted on all runs.
    pub value: f64,
    /// Its standard error, the larger of two where the model leaves a gap
    /// above noise ([`ParameterValue::std_error_basis`] says which): the
    /// asymptotic one ([`ParameterValue::asymptotic_std_error`]) or the
    /// spread of the fold refits ([`ParameterValue::fold_std_error`]).
    /// NaN, written as `null`, where the runs do not pin it.
    #[serde(serialize_with = "crate::report::finite_or_null")]
    pub std_error: f64,
    /// The asymptotic standard error: the Jacobian's times `√τ`, the
    /// residuals' correlation time
    /// ([`crate::diagnose::fit::FitOutcome::reported_std_errors`]). It
    /// covers the runs' noise; a model that lacks something also moves the
    /// fit, by more than it (a sensor position 7 of them off its truth
    /// where the yaw rate stays at 1.2 noise floors after the fit).
    #[serde(serialize_with = "crate::report::finite_or_null")]
    pub asymptotic_std_error: f64,
    /// Which of the two [`ParameterValue::std_error`] is.
    pub std_error_basis: StdErrorBasis,
    /// The value sits on one of its bounds ([`ParameterValue::bound`]).
    pub at_bound: bool,
    /// Which: a search bound (the data would take it further, and the
    /// standard error says nothing about how far) or a physical limit (no
    /// value lies beyond it).
    pub bound: Option<Bound>,
    /// The runs determine it: its standard error is finite and no larger
    /// than the parameter's whole range ([`ParameterValue::of`]). For a
    /// value per radian of roll ([`ParameterValue::per_lateral_acceleration`]
    /// set) only at the stated roll gradient: the runs determine its
    /// product with the gradient, not the value apart from it.
    pub determined: bool,
    /// Held at its off value because no measured channel responds to it
    /// (an offset of a channel no run carries): not fitted, not counted.
    pub unseen: bool,
    /// Held at its off value (the campaign's, for the roll dynamics)
    /// because fitted free its standard error, this, exceeded its whole
    /// range: the runs do not determine it (`null`: fitted).
    #[serde(rename = "held_std_error")]
    pub held: Option<f64>,
    /// The grouped jackknife of the fold refits (Efron & Stein 1981): how
    /// far the fit moves when a fold's runs are left out,
    /// `√((k−1)/k · Σ(θᵢ − θ̄)²)` over `k` folds (`null`: not
    /// cross-validated, or fewer than [`MIN_JACKKNIFE_FOLDS`] folds).
    /// Far above what the runs' noise alone gives it
    /// ([`ParameterValue::fold_noise_std_error`]; [`ParameterValue::understated`])
    /// the runs disagree on the value by more than their noise allows: a
    /// model that lacks something, which no standard error covers.
    pub fold_std_error: Option<f64>,
    /// The fold jackknife the runs' noise alone gives: the standard error
    /// times `f` of [`crate::diagnose::fit::fold_noise`], 1 for runs of
    /// equal information, far more where one run carries most of what
    /// determines the parameter (`null`: not cross-validated).
    pub fold_noise_std_error: Option<f64>,
    /// The degrees of freedom of that jackknife (Satterthwaite's count of
    /// the folds' unequal variances: 1 where one fold carries the rest).
    pub fold_noise_dof: Option<f64>,
    /// Each fold refit's value with the runs it left out and whether it
    /// converged ([`FoldRefit`]; empty where not cross-validated): the
    /// values [`ParameterValue::fold_std_error`] is the jackknife of, and
    /// where one stands apart, the run the words name
    /// ([`ParameterValue::folds_apart`]).
    pub fold_refits: Vec<FoldRefit>,
    /// It trades against an earlier parameter of its effect: the runs
    /// determine their sum, not the split ([`Traded`]; absent: no such
    /// pair).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub traded: Option<Traded>,
    /// A value per radian of body roll (roll steer, roll camber) acts only
    /// through its product with the campaign's roll gradient, held: that
    /// product, steer or camber thrust per m/s² of lateral acceleration
    /// with its standard error, and the gradient with where it is stated
    /// ([`PerLateralAcceleration`]; absent: a value the runs see on its
    /// own).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub per_lateral_acceleration: Option<PerLateralAcceleration>,
    /// The effect's parameter in the registry this value is, with its off
    /// value and search bounds (`None`: a roll dynamics' parameter, whose
    /// off values are the campaign's, or a value made by name alone,
    /// [`ParameterValue::plain`]). Not written: the name says it.
    #[serde(skip)]
    pub effect_parameter: Option<&'static Parameter>,
}

/// Which standard error a [`ParameterValue`] reports.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StdErrorBasis {
    /// The asymptotic one: the model fits to the noise, or the fold
    /// refits scatter less, or the candidate was not cross-validated.
    Asymptotic,
    /// The grouped jackknife of the fold refits: the model leaves a gap
    /// above noise (the held-out error after the fit above the noise
    /// level), and the refits on part of the runs move the value by more
    /// than the asymptotic standard error (a leave-runs-out spread holds
    /// under a model error that differs from run to run; Efron & Stein
    /// 1981; a sandwich, White 1982, covers the same).
    FoldSpread,
}

/// A parameter that trades against an earlier one of its effect
/// (`traded.rs`: when, and why the sum is what the runs determine).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Traded {
    /// The other parameter (`effect.parameter`), listed before this one.
    pub with: String,
    /// Their correlation, −1 to 0.
    pub correlation: f64,
    /// Their sum, in their common unit.
    pub sum: f64,
    /// Its standard error.
    pub sum_std_error: f64,
    /// The grouped jackknife of the sum over the fold refits (`null`: not
    /// cross-validated).
    pub sum_fold_std_error: Option<f64>,
    /// Nor do the runs determine how the sum splits between the two: the
    /// larger of either's standard error and fold scatter exceeds
    /// `TRADED_SPLIT` of the sum (`traded.rs`).
    pub split_undetermined: bool,
}

/// Folds below which no jackknife is given: with two, the spread of one
/// difference.
pub const MIN_JACKKNIFE_FOLDS: usize = 3;

/// How many times its standard error a parameter's fold jackknife must be
/// for the standard error to be said to understate its uncertainty: the
/// jackknife's own relative error on 3–5 folds is 35–50 %, so 3× is past
/// what its scatter explains (about the size of what the block sandwich
/// gives against the jackknife over runs on a model that lacks something:
/// 0.5–2×, `fit::std_error_tests`).
pub const UNDERSTATED: f64 = 3.0;

/// The standard normal quantile of the chance a fold jackknife is allowed
/// above its yardstick before it is said to understate: 99.9 %.
pub const FOLD_CHANCE_Z: f64 = 3.0902;

/// The grouped jackknife standard error of `values`, one per fold (None
/// below [`MIN_JACKKNIFE_FOLDS`] or with a value not finite).
pub fn jackknife(values: &[f64]) -> Option<f64> {
    let k = values.len();
    if k < MIN_JACKKNIFE_FOLDS || values.iter().any(|v| !v.is_finite()) {
        return None;
    }
    let mean = values.iter().sum::<f64>() / k as f64;
    let spread: f64 = values.iter().map(|v| (v - mean).powi(2)).sum();
    Some(((k - 1) as f64 / k as f64 * spread).sqrt())
}

/// A value within this share of its parameter's range from a physical
/// limit stands on it ([`crate::optim::bounded::LIMIT_RESOLUTION`]). A
/// search bound is where a fit pressed against it stops, exactly
/// ([`Parameter::bound_at`]).
pub use crate::optim::bounded::LIMIT_RESOLUTION;

/// The share of its range within which a fitted value stands near a
/// search bound when its standard error is smaller: the fits stop short of
/// a bound they press against by their own tolerance, not the data's.
pub const NEAR_SEARCH_BOUND: f64 = 0.01;

/// Where a value stands near a search bound ([`ParameterValue::near_search_bound`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NearBound {
    /// The bound, in the parameter's unit.
    pub bound: f64,
    /// Within its standard error of it (else within [`NEAR_SEARCH_BOUND`]
    /// of the range).
    pub by_std_error: bool,
}

impl ParameterValue {
    /// The search bound the value stands near but not on: within the larger
    /// of its standard error (a determined one) and [`NEAR_SEARCH_BOUND`] of
    /// its range, where the data would take it as far (a sensor delay of
    /// 0.299 s against its 0.3 s bound was not said). The verdict's warning
    /// reads it with [`Self::at_bound`]; the verdict's rules read only
    /// `at_bound`, where the fit itself stopped.
    pub fn near_search_bound(&self) -> Option<NearBound> {
        if self.at_bound || self.unseen || self.held.is_some() || !self.value.is_finite() {
            return None;
        }
        let q = self.effect_parameter.or_else(|| {
            let name = self.name.strip_prefix("roll.")?;
            RollDynamics::PARAMETERS.iter().find(|q| q.name == name)
        })?;
        let (lo, hi) = q.bounds;
        let share = NEAR_SEARCH_BOUND * (hi - lo);
        let se = Some(self.std_error).filter(|e| self.determined && e.is_finite());
        let margin = se.map_or(share, |e| e.max(share));
        let by_std_error = se.is_some_and(|e| e > share);
        let near = |limit: Bound, gap: f64| limit == Bound::Search && gap <= margin;
        let bound = match () {
            _ if near(q.limits.1, hi - self.value) => hi,
            _ if near(q.limits.0, self.value - lo) => lo,
            _ => return None,
        };
        Some(NearBound {
            bound,
            by_std_error,
        })
    }

    /// Parameter `q` of `group` fitted to `value` with standard error
    /// `std_error`, and where it stands: on a bound (a search bound as
    /// [`Parameter::bound_at`] finds it, a physical limit within
    /// [`LIMIT_RESOLUTION`] of the range), and determined by the runs or
    /// not (a standard error missing, or larger than the whole range, says
    /// the runs do not see it).
    pub fn of(group: Group, q: &'static Parameter, value: f64, std_error: f64) -> Self {
        let (lo, hi) = q.bounds;
        let near = LIMIT_RESOLUTION * (hi - lo);
        let physical = |limit: Bound, at: bool| (limit == Bound::Physical && at).then_some(limit);
        let bound = q.bound_at(value).or_else(|| {
            physical(q.limits.0, value - lo <= near).or(physical(q.limits.1, hi - value <= near))
        });
        Self {
            at_bound: bound.is_some(),
            bound,
            determined: std_error.is_finite() && std_error <= hi - lo,
            effect_parameter: matches!(group, Group::Effect(_)).then_some(q),
            ..Self::plain(
                &format!("{}.{}", group.name(), q.name),
                q.unit,
                value,
                std_error,
            )
        }
    }

    /// `name` fitted to `value` in `unit` with standard error `std_error`,
    /// determined, on no bound, nothing else known ([`ParameterValue::of`]
    /// finds its bound and whether the runs determine it).
    pub(crate) fn plain(name: &str, unit: &'static str, value: f64, std_error: f64) -> Self {
        Self {
            name: name.into(),
            unit,
            value,
            std_error,
            asymptotic_std_error: std_error,
            std_error_basis: StdErrorBasis::Asymptotic,
            at_bound: false,
            bound: None,
            determined: true,
            unseen: false,
            held: None,
            fold_std_error: None,
            fold_noise_std_error: None,
            fold_noise_dof: None,
            fold_refits: Vec::new(),
            traded: None,
            per_lateral_acceleration: None,
            effect_parameter: None,
        }
    }

    /// The same with the fold refits' jackknife ([`jackknife`]) and the one
    /// the runs' noise alone gives, `noise.0` standard errors with `noise.1`
    /// degrees of freedom (None: not known). The refits are kept one by one
    /// ([`ParameterValue::fold_refits`]), as converged and with their runs
    /// unnamed until [`ParameterValue::with_fold_runs`] says otherwise.
    pub fn with_folds(self, fold_values: &[f64], noise: Option<(f64, f64)>) -> Self {
        let fold_std_error = jackknife(fold_values);
        let noise = fold_std_error.and(noise);
        let refit = |&value: &f64| FoldRefit {
            left_out: Vec::new(),
            value,
            converged: true,
        };
        Self {
            fold_refits: fold_values.iter().map(refit).collect(),
            fold_std_error,
            fold_noise_std_error: noise.map(|(f, _)| f * self.asymptotic_std_error),
            fold_noise_dof: noise.map(|(_, nu)| nu).filter(|nu| nu.is_finite()),
            ..self
        }
    }

    /// The same, where the model leaves a gap above noise (`inexact`),
    /// with the larger of the asymptotic standard error and the fold
    /// refits' spread reported ([`StdErrorBasis`]), for a fitted,
    /// determined parameter off its bounds. The asymptotic one covers the
    /// noise alone; what the model lacks moves the fit too, and the refits
    /// on part of the runs see as much of that as differs between runs.
    pub fn with_model_error(self, inexact: bool) -> Self {
        let fitted = !self.unseen && self.held.is_none() && self.bound.is_none() && self.determined;
        match self.fold_std_error {
            Some(j) if inexact && fitted && j > self.asymptotic_std_error => Self {
                std_error: j,
                std_error_basis: StdErrorBasis::FoldSpread,
                ..self
            },
            _ => self,
        }
    }

    /// What the fold jackknife is judged against: the asymptotic standard
    /// error, or the larger jackknife the runs' noise alone gives where one
    /// run carries most of what determines the parameter.
    pub fn fold_yardstick(&self) -> f64 {
        let se = self.asymptotic_std_error;
        self.fold_noise_std_error
            .filter(|x| x.is_finite())
            .map_or(se, |n| n.max(se))
    }

    /// How many times [`ParameterValue::fold_yardstick`] the fold jackknife
    /// may reach by chance: [`UNDERSTATED`], or more where few folds carry
    /// it (the 99.9 % point of `√(χ²_ν/ν)`, 3.3 for one degree of freedom).
    pub fn fold_limit(&self) -> f64 {
        let chance = self.fold_noise_dof.map_or(0.0, |nu| {
            let q = crate::measured::calibration::stats::chi2_quantile_of(nu, FOLD_CHANCE_Z);
            (q / nu).sqrt()
        });
        UNDERSTATED.max(chance)
    }

    /// The fold jackknife is more than [`ParameterValue::fold_limit`] times
    /// [`ParameterValue::fold_yardstick`] for a fitted, determined
    /// parameter: the standard error covers the noise, not what the model
    /// lacks.
    pub fn understated(&self) -> bool {
        let fitted = !self.unseen && self.held.is_none() && self.bound.is_none() && self.determined;
        match self.fold_std_error {
            Some(j) => fitted && j > self.fold_limit() * self.fold_yardstick(),
            None => false,
        }
    }

    /// The fold refits of [`Self::fold_refits`] that stand apart
    /// ([`crate::diagnose::report::fold_refits::folds_apart`], against [`Self::fold_yardstick`]), where the runs
    /// disagree beyond their noise ([`Self::understated`]); none else.
    pub fn folds_apart(&self) -> Vec<usize> {
        if !self.understated() {
            return Vec::new();
        }
        let values: Vec<f64> = self.fold_refits.iter().map(|f| f.value).collect();
        crate::diagnose::report::fold_refits::folds_apart(&values, self.fold_yardstick())
    }

    /// The same with the runs each fold refit leaves out, `left_out[i]`
    /// for fold `i`, and whether it converged, `converged[i]` (a fold
    /// without an entry keeps what it had).
    pub fn with_fold_runs(mut self, left_out: &[Vec<String>], converged: &[bool]) -> Self {
        for (i, f) in self.fold_refits.iter_mut().enumerate() {
            if let Some(runs) = left_out.get(i) {
                f.left_out.clone_from(runs);
            }
            if let Some(&c) = converged.get(i) {
                f.converged = c;
            }
        }
        self
    }

    /// The same, held at its off value because no measured channel
    /// responds to it ([`ParameterValue::unseen`]).
    pub fn unseen(self) -> Self {
        Self {
            unseen: true,
            ..self
        }
    }

    /// The same, held at its off value because fitted free its standard
    /// error `free_std_error` exceeded its whole range
    /// ([`ParameterValue::held`]).
    pub fn held(self, free_std_error: f64) -> Self {
        Self {
            held: Some(free_std_error),
            determined: false,
            ..self
        }
    }
}

/// A channel's residual mean of one sign over the runs (simulated minus
/// measured, the channel's unit).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SteadyOffset {
    /// The runs' mean residual, averaged over the runs.
    pub mean: f64,
    /// Runs whose mean residual has its sign.
    pub same_sign: usize,
    /// Runs with the channel.
    pub runs: usize,
    /// `|mean|` in noise floors.
    pub floors: f64,
    /// The share of the channel's mean square residual the offset
    /// carries, `mean²/RMS²`.
    pub share: f64,
    /// The standard error of `mean`: the runs' mean residuals' spread
    /// over `√runs` (each run one sample of the offset and of what the
    /// model leaves in it).
    pub std_error: f64,
}

/// Runs a steady offset needs.
pub const OFFSET_RUNS: usize = 3;
/// The share of the runs whose mean residual must have the offset's sign.
pub const OFFSET_SAME_SIGN: f64 = 0.8;
/// The least offset, in noise floors: at one floor it shifts the whole
/// trace by the scatter of the noise, plain in any overlay, while its RMS
/// alone stays far below three floors.
pub const OFFSET_FLOORS: f64 = 1.0;
/// The least share of the mean square residual an offset carries: a
/// sensor offset leaves little else (0.79–0.83 on a campaign with all
/// three logger offsets withheld), a gain error of runs that mostly turn
/// one way has a mean of one sign too, but most of its residual comes and
/// goes with the manoeuvre (0.18–0.27 with a steering compliance withheld).
pub const OFFSET_SHARE: f64 = 0.5;

impl SteadyOffset {
    /// The steady offset of the runs' mean residuals `biases` against the
    /// noise floor `noise_floor` and the channel's RMS residual `rms`:
    /// their average where at least [`OFFSET_RUNS`] runs, [`OFFSET_SAME_SIGN`]
    /// of them of its sign, at least [`OFFSET_FLOORS`] noise floors and
    /// [`OFFSET_SHARE`] of the mean square.
    pub fn of(biases: &[f64], noise_floor: f64, rms: f64) -> Option<Self> {
        let runs = biases.len();
        if runs < OFFSET_RUNS || noise_floor.is_nan() || noise_floor <= 0.0 {
            return None;
        }
        let mean = biases.iter().sum::<f64>() / runs as f64;
        let same_sign = biases
            .iter()
            .filter(|b| b.signum() == mean.signum())
            .count();
        let floors = mean.abs() / noise_floor;
        let share = (mean / rms).powi(2);
        let steady = same_sign as f64 >= OFFSET_SAME_SIGN * runs as f64
            && floors >= OFFSET_FLOORS
            && share >= OFFSET_SHARE;
        let spread = biases.iter().map(|b| (b - mean).powi(2)).sum::<f64>() / (runs - 1) as f64;
        steady.then_some(Self {
            mean,
            same_sign,
            runs,
            floors,
            share,
            std_error: (spread / runs as f64).sqrt(),
        })
    }
}

/// A candidate's reduction of the campaign's combined held-out error as
/// the report says it: a share of a gap within noise is noise, neither a
/// reduction nor a worsening, so it is not given as a percentage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Reduction {
    /// The campaign's gap is within noise (`GapReport::significant` is
    /// false): there is nothing above noise to take a share of.
    WithinNoise,
    /// Share of the gap above noise removed, % (negative: added).
    Percent(f64),
}

impl Reduction {
    /// A reduction of `percent` of a campaign's gap that is significant
    /// (`gap_significant`) or not. The terminal and the page both call
    /// this, so that they cannot disagree on a row.
    pub fn of(percent: f64, gap_significant: bool) -> Self {
        if gap_significant {
            Self::Percent(percent)
        } else {
            Self::WithinNoise
        }
    }
}

/// Before/after on held-out runs for one part of the data (written with
/// its [`crate::diagnose::report::ChannelChange`], `change`, and no
/// percentage where that is within noise).
#[derive(Debug, Clone, PartialEq)]
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
    /// Its samples' mean level on its axis, over every run: time after
    /// the input starts (s), |ay| (m/s²) or speed (m/s), where the gap map
    /// draws the part (None for all samples). A band groups the table; its
    /// samples lie where they lie in it.
    pub mean_level: Option<f64>,
    /// Each run's share of the part, in the campaign's order (runs with
    /// no sample in it left out).
    pub runs: Vec<RunPart>,
}

/// One run's share of a [`Shrinkage`] row: its samples in the part, where
/// they lie on the part's axis, and its held-out RMS before and after the
/// verdict's effects (the gap map draws each run at its own level).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunPart {
    /// The run.
    pub run: String,
    /// Its samples in the part.
    pub samples: usize,
    /// Their mean level on the part's axis (as
    /// [`Shrinkage::mean_level`]; `null` for all samples).
    pub mean_level: Option<f64>,
    /// Held-out RMS with the base model.
    pub before: f64,
    /// Held-out RMS with the verdict's effects.
    pub after: f64,
    /// Held-out mean residual with the verdict's effects (simulated −
    /// measured): where a run is left off before the input, whether it is
    /// a steady offset ([`crate::diagnose::report::left_in`], which writes
    /// it there; not written for every run and part).
    #[serde(skip)]
    pub bias_after: f64,
}

impl ParameterValue {
    /// The same with its product with the `held` roll gradient, where it is
    /// a value per radian of roll (any other is returned as it is). The
    /// product's standard error is the gradient times the value's, of
    /// whichever basis ([`ParameterValue::std_error_basis`]).
    pub fn at_roll_gradient(self, held: &HeldRollGradient) -> Self {
        let Some(quantity) = self.effect_parameter.and_then(|q| q.per_roll) else {
            return self;
        };
        let k = held.gradient;
        Self {
            per_lateral_acceleration: Some(PerLateralAcceleration {
                quantity,
                value: self.value * k,
                std_error: self.std_error * k.abs(),
                unit: quantity.unit(),
                roll_gradient: held.clone(),
            }),
            ..self
        }
    }
}
