//! The candidates of a diagnosis as it fitted them ([`Fitted`]): the base
//! model's tyres, each candidate's effects with their values and standard
//! errors (and its axle characteristics where the base identified them
//! from the runs), the channels' noise floors and scales, the verdict and
//! its confounded sets — what `diagnosis.json` records, read back into the
//! models the diagnosis replayed ([`FittedCandidate::model`]: the base
//! model with the candidate's parameter vector set by the diagnosis's own
//! layout). Units: SI, rad; cornering coefficients in 1/rad.

use super::{DesignRequest, SetSource};
use crate::diagnose::campaign::Campaign;
use crate::diagnose::effects::{joined, same_effects, EffectKind};
use crate::diagnose::fit::layout::Layout;
use crate::diagnose::model::axles::shares;
use crate::diagnose::model::Augmented;
use crate::diagnose::{Diagnosis, Ranked};
use crate::error::{DesignError, Error};
use crate::tyre::Tyre;
use crate::vehicle::VehicleModel;
use serde::Serialize;

/// A fitted value and how far it is known.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FittedValue {
    /// `effect.parameter`, or the axle characteristic's name.
    pub name: String,
    /// The value fitted on all runs.
    pub value: f64,
    /// Its standard error (NaN where the runs do not pin it).
    #[serde(serialize_with = "crate::report::finite_or_null")]
    pub std_error: f64,
    /// Whether its uncertainty counts: determined by the runs, off every
    /// bound and held by nothing.
    pub free: bool,
}

impl FittedValue {
    /// Value `value` of `name` with standard error `std_error` (NaN where
    /// unknown); its uncertainty counts where `free` and the error is
    /// finite.
    pub fn new(name: &str, value: f64, std_error: f64, free: bool) -> Self {
        Self {
            name: name.to_string(),
            value,
            std_error,
            free: free && std_error.is_finite(),
        }
    }
}

/// One candidate as the diagnosis fitted it on all runs.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FittedCandidate {
    /// Its effects.
    pub effects: Vec<EffectKind>,
    /// Their parameters in the fit's order (each effect's, then the roll
    /// dynamics when a roll effect is among them).
    pub parameters: Vec<FittedValue>,
    /// Front and rear cornering coefficient and peak friction refitted
    /// with it (a base identified from the runs).
    pub axles: Option<Vec<FittedValue>>,
    /// Its held-out combined error J.
    pub heldout_error: f64,
}

impl FittedCandidate {
    /// Its label, `a+b`.
    pub fn label(&self) -> String {
        joined(&self.effects, "+")
    }

    /// The candidate of a diagnosis's ranking.
    pub fn of(r: &Ranked) -> Self {
        let value = FittedValue::new;
        Self {
            effects: r.effects.clone(),
            parameters: r
                .parameters
                .iter()
                .map(|p| value(&p.name, p.value, p.std_error, p.determined && !p.at_bound))
                .collect(),
            axles: r.axles.as_ref().map(|a| {
                a.iter()
                    .map(|x| value(x.name, x.value, x.std_error, x.limit.is_none() && !x.held))
                    .collect()
            }),
            heldout_error: r.heldout_error_after,
        }
    }

    /// The number of values ([`FittedCandidate::values`]).
    pub fn len(&self) -> usize {
        self.axles.as_ref().map_or(0, Vec::len) + self.parameters.len()
    }

    /// Whether it has no values.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Its values, axles first.
    pub fn values(&self) -> impl Iterator<Item = &FittedValue> {
        self.axles.iter().flatten().chain(&self.parameters)
    }

    /// The model it sets on `base` with `values` in the order of
    /// [`FittedCandidate::values`] (its own, or perturbed), by the
    /// diagnosis's own layout; None when the counts disagree with the
    /// layout (a diagnosis written by another release).
    pub fn model_with(&self, base: &Augmented, values: &[f64]) -> Option<Augmented> {
        let layout = Layout::new(&self.effects, self.axles.is_some());
        let axles = layout.axle_count();
        let effects = layout.roll().end - axles;
        if values.len() != axles + effects {
            return None;
        }
        let mut p = Vec::with_capacity(values.len());
        if axles > 0 {
            p.extend(shares(values[0], values[1], values[2]));
        }
        p.extend(&values[axles..]);
        Some(layout.model(base, &p))
    }

    /// The model it sets on `base` with its fitted values.
    pub fn model(&self, base: &Augmented) -> Option<Augmented> {
        let v: Vec<f64> = self.values().map(|x| x.value).collect();
        self.model_with(base, &v)
    }
}

/// What the design needs of a diagnosis.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Fitted {
    /// The base model's front tyre (or axle characteristic).
    pub front: Tyre,
    /// Its rear.
    pub rear: Tyre,
    /// The noise floor of each channel by [`crate::diagnose::Channel`]
    /// index (0 where no run measures it).
    pub noise_floors: [f64; 3],
    /// The noise of one sample of each channel, by the same index: its
    /// high-frequency scatter (the median over runs), the white noise a
    /// replay's start takes from the sample it starts at and an averaged
    /// start shrinks by √n. It is the floor where the floor is the
    /// scatter; an estimated output's floor (a sideslip estimate's 0.005
    /// rad) is the uncertainty its residuals are weighed by, which may be
    /// ten times its scatter and which averaging samples does not shrink,
    /// so it is no start's noise ([`Fitted::start_noise_of`]).
    pub start_noise: [f64; 3],
    /// The scale of each channel's residuals in the fits.
    pub scales: [f64; 3],
    /// The held-out J of the noise alone.
    pub noise_level: f64,
    /// Single effects and combinations, as ranked.
    pub candidates: Vec<FittedCandidate>,
    /// Each confounded set: the verdict's first effect and its look-alikes.
    pub confounded: Vec<Vec<EffectKind>>,
    /// The candidates screened out before cross-validation: no held-out
    /// fit to design with.
    pub screened: Vec<ScreenedOut>,
    /// The candidates a verdict of no significant gap notes fitted far
    /// from off, best held-out first (`verdict.far_from_off`): none is
    /// confounded, and the refusal to design names them to ask for.
    pub noted: Vec<Vec<EffectKind>>,
    /// Whether the verdict found no significant gap.
    pub no_gap: bool,
}

/// A candidate the diagnosis screened out before cross-validating it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ScreenedOut {
    /// Its effects.
    pub effects: Vec<EffectKind>,
    /// The set it extends (a set the greedy additions screened; empty: a
    /// single, screened against the base model).
    pub extends: Vec<EffectKind>,
    /// The share of the in-sample gap above noise its all-run fit removed
    /// (of the base model's, or of the one the set it extends leaves), %.
    pub insample_reduction_percent: f64,
    /// The share below which it was screened out, % (the acceptance share
    /// less the margin).
    pub screen_percent: f64,
}

impl Fitted {
    /// What `d` fitted.
    pub fn of(d: &Diagnosis) -> Self {
        let mut noise_floors = [0.0; 3];
        let mut scales = [1.0; 3];
        let mut start_noise = [0.0; 3];
        for n in &d.gap.noise {
            noise_floors[n.channel.index()] = n.noise_floor;
            scales[n.channel.index()] = n.scale;
            start_noise[n.channel.index()] = Self::start_noise_of(n.noise_floor, Some(n.scatter));
        }
        Self {
            front: d.base.front.clone(),
            rear: d.base.rear.clone(),
            noise_floors,
            start_noise,
            scales,
            noise_level: d.gap.noise_level,
            candidates: d
                .ranking
                .iter()
                .chain(&d.combinations)
                .map(FittedCandidate::of)
                .collect(),
            confounded: d.confounded.iter().map(|c| c.effects.clone()).collect(),
            screened: d
                .screened
                .iter()
                .map(|s| ScreenedOut {
                    effects: s.effects.clone(),
                    extends: s.extends.clone(),
                    insample_reduction_percent: s.insample_reduction_percent,
                    screen_percent: s.threshold_percent - s.margin_percent,
                })
                .collect(),
            noted: noted(&d.verdict),
            no_gap: matches!(d.verdict, crate::diagnose::Verdict::NoSignificantGap(_)),
        }
    }

    /// One sample's noise of a channel of noise floor `floor` and
    /// high-frequency scatter `scatter` ([`Fitted::start_noise`]): the
    /// scatter, at most the floor; the floor where no scatter is known.
    pub fn start_noise_of(floor: f64, scatter: Option<f64>) -> f64 {
        match scatter {
            Some(s) if s.is_finite() && s > 0.0 => s.min(floor),
            _ => floor,
        }
    }

    /// The base model of campaign `c` with these tyres: as the diagnosis
    /// built it (the campaign's vehicle, road friction and roll).
    pub fn base(&self, c: &Campaign) -> Augmented {
        let model = VehicleModel::new(c.vehicle.clone(), self.front.clone(), self.rear.clone());
        let mut m = Augmented::new(model, c.friction);
        m.effects_mut().roll = c.roll;
        m
    }

    /// Refuses a design of a diagnosis that cross-validated no candidate
    /// (all screened out): whatever `--effects` names has no held-out fit,
    /// and a list of those it cross-validated would be empty.
    pub(crate) fn cross_validated_any(&self) -> Result<(), Error> {
        if !self.candidates.is_empty() {
            return Ok(());
        }
        Err(crate::error::DesignError::NothingCrossValidated {
            screened: self.screened.len(),
            screen_percent: self.screened.first().map_or(20.0, |s| s.screen_percent),
            no_gap: self.no_gap,
        }
        .into())
    }

    /// The candidate whose effects are `effects` (in any order).
    pub fn candidate(&self, effects: &[EffectKind]) -> Option<&FittedCandidate> {
        self.candidates
            .iter()
            .find(|x| same_effects(&x.effects, effects))
    }
}

/// The members of each set: the requested ones, else the confounded ones.
pub(crate) fn sets(
    fitted: &Fitted,
    req: &DesignRequest,
) -> Result<Vec<(Vec<FittedCandidate>, SetSource)>, Error> {
    fitted.cross_validated_any()?;
    let (wanted, source) = match &req.sets {
        Some(s) => (s.clone(), SetSource::Requested),
        None => (
            fitted
                .confounded
                .iter()
                .map(|set| set.iter().map(|e| vec![*e]).collect())
                .collect(),
            SetSource::Confounded,
        ),
    };
    if wanted.is_empty() {
        let noted = fitted.noted.iter().map(|e| joined(e, "+"));
        return Err(DesignError::NothingConfounded {
            noted: noted.collect(),
        }
        .into());
    }
    wanted
        .iter()
        .map(|set| {
            let members = set
                .iter()
                .map(|effects| {
                    fitted
                        .candidate(effects)
                        .cloned()
                        .ok_or_else(|| not_fitted(fitted, effects))
                })
                .collect::<Result<Vec<_>, _>>()?;
            if members.len() < 2 {
                return Err(DesignError::OneMember.into());
            }
            Ok((members, source))
        })
        .collect()
}

/// Why candidate `effects` has no fit to design with: screened out, or
/// never among the diagnosis's candidates.
pub(super) fn not_fitted(fitted: &Fitted, effects: &[EffectKind]) -> Error {
    let candidate = joined(effects, "+");
    let fitted_labels = fitted.candidates.iter().map(|c| c.label()).collect();
    match fitted
        .screened
        .iter()
        .find(|s| same_effects(&s.effects, effects))
    {
        Some(s) => DesignError::ScreenedOut {
            candidate,
            insample_percent: s.insample_reduction_percent,
            of: match s.extends.as_slice() {
                [] => "the base model".to_string(),
                set => joined(set, "+"),
            },
            screen_percent: s.screen_percent,
            fitted: fitted_labels,
        },
        None => DesignError::NotFitted {
            candidate,
            fitted: fitted_labels,
        },
    }
    .into()
}

/// The candidates `verdict` notes fitted far from off on a gap within
/// noise ([`Fitted::noted`]).
fn noted(verdict: &crate::diagnose::Verdict) -> Vec<Vec<EffectKind>> {
    match verdict {
        crate::diagnose::Verdict::NoSignificantGap(n) => {
            n.far_from_off.as_ref().map_or_else(Vec::new, |f| {
                let also = f.also.iter().map(|a| a.effects.clone());
                std::iter::once(f.effects.clone()).chain(also).collect()
            })
        }
        _ => Vec::new(),
    }
}
