//! The candidates of a diagnosis as parameter vectors: the base models
//! (the campaign's tyres, a tyre model fitted to its rig data, or axle
//! characteristics identified from the runs and refitted with every
//! candidate), and how a vector of axle characteristics, effect parameters
//! and roll dynamics becomes a model. Units: SI, rad; the roll frequency in
//! Hz.

use super::base::{identify_axles, AxleIdentification};
use super::campaign::{BaseTyres, Campaign};
use super::effects::{Bound, EffectKind, EffectSet, Parameter};
use super::fit::{fit, FitOutcome, Polish};
pub(super) use super::layout::{fits_roll, with_effects, Layout};
use super::model::Augmented;
use super::problem::Problem;
use super::refit::{refit, training_rows};
use super::replay::Prepared;
use super::report::ParameterValue;
use super::timing::{record_polish, Phase, Recorder, Stamps};
use crate::error::{DiagnosisError, Error};
use crate::identify::grouping::{group, Grouping, GroupingReport, SlipAxis};
use crate::identify::{fit_lateral, start_tyre_of, FitSettings};
use crate::optim::local::{Derivatives, Residuals};
use crate::optim::stats::covariance;
use crate::tyre::Tyre;
use crate::vehicle::VehicleModel;
use rayon::prelude::*;
use std::time::Instant;

/// A set of effects with their fitted values, and the model builder.
#[derive(Clone)]
pub(super) struct Setting<'a> {
    pub(super) base: &'a Bases,
    pub(super) kinds: Vec<EffectKind>,
    pub(super) fixed: EffectSet,
}

/// The base model of all runs and of every fold.
pub(super) struct Bases {
    pub(super) all: Augmented,
    pub(super) folds: Vec<Augmented>,
    pub(super) nominal_share: f64,
    /// Axle characteristics identified from the runs (all runs, per fold):
    /// refitted jointly with every candidate, since an effect changes what
    /// the tyres must have been.
    pub(super) axle: Option<(Vec<f64>, Vec<Vec<f64>>)>,
    /// How the runs pin them, and whether they are a tyre at all.
    pub(super) identification: Option<AxleIdentification>,
}

pub(super) use super::axles::{axle_tyres, AXLE_BOUNDS};

/// The roll degree of freedom's dynamics, fitted with the roll effects: a
/// campaign's `[roll]` is a guess (no roll channel is needed), and roll
/// steer or camber seen through the wrong roll frequency and damping is
/// mimicked by stiffness changes of the wrong sign. The roll gradient stays
/// the campaign's: it only scales the per-radian roll-steer and roll-camber
/// values. Off values (NaN) are the campaign's.
pub(super) static ROLL_DYNAMICS: [Parameter; 2] = [
    Parameter {
        name: "frequency",
        unit: "Hz",
        off: f64::NAN,
        bounds: (0.5, 4.0),
        limits: (Bound::Search, Bound::Search),
    },
    Parameter {
        name: "damping",
        unit: "-",
        off: f64::NAN,
        bounds: (0.2, 1.5),
        limits: (Bound::Search, Bound::Search),
    },
];

/// The start of a combination: the axle characteristics and effect values
/// of the current set, the added effect's values from its single fit, and
/// the roll dynamics from whichever of the two fitted them (the current
/// set first).
pub(super) fn combined_start(
    current: (&[EffectKind], &[f64]),
    added: (EffectKind, &[f64]),
    axle_count: usize,
) -> Vec<f64> {
    let (kinds, p) = current;
    let effect_len: usize = kinds.iter().map(|e| e.parameters().len()).sum();
    let end = axle_count + effect_len;
    let n = added.0.parameters().len();
    let mut start = p[..end].to_vec();
    start.extend(&added.1[axle_count..axle_count + n]);
    if fits_roll(kinds) {
        start.extend(&p[end..end + 2]);
    } else if added.0.uses_roll() {
        start.extend(&added.1[axle_count + n..axle_count + n + 2]);
    }
    start
}

impl Setting<'_> {
    pub(super) fn axle(&self) -> bool {
        self.base.axle.is_some()
    }
    /// What this setting's parameters set on `base` ([`with_effects`]).
    pub(super) fn layout(&self, base: &Augmented) -> Layout {
        Layout {
            base: base.clone(),
            kinds: self.kinds.clone(),
            axle: self.axle(),
        }
    }
    /// The effect parameters in vector order, the roll dynamics last.
    pub(super) fn parameters(&self) -> impl Iterator<Item = &'static Parameter> + '_ {
        let roll = if fits_roll(&self.kinds) {
            &ROLL_DYNAMICS[..]
        } else {
            &[]
        };
        self.kinds
            .iter()
            .flat_map(|e| e.parameters().iter())
            .chain(roll.iter())
    }
    pub(super) fn bounds(&self) -> Vec<(f64, f64)> {
        let axle = if self.axle() { &AXLE_BOUNDS[..] } else { &[] };
        axle.iter()
            .copied()
            .chain(self.parameters().map(|q| q.bounds))
            .collect()
    }
    pub(super) fn off(&self) -> Vec<f64> {
        let axle = self.base.axle.as_ref().map_or(&[][..], |a| &a.0[..]);
        let roll = self.base.all.roll;
        let mut p: Vec<f64> = axle
            .iter()
            .copied()
            .chain(self.kinds.iter().flat_map(|e| {
                e.parameters().iter().map(|q| {
                    if q.off.is_nan() {
                        self.base.nominal_share
                    } else {
                        q.off
                    }
                })
            }))
            .collect();
        if fits_roll(&self.kinds) {
            p.extend([roll.frequency, roll.damping]);
        }
        p
    }
}

/// The base models: all runs and each fold's training runs.
pub(super) fn base_models(
    c: &Campaign,
    runs: &[Prepared],
    folds: &[Vec<usize>],
    scales_hint: [f64; 3],
    timing: Option<&Recorder>,
) -> Result<(Bases, String, Option<GroupingReport>), Error> {
    let vehicle = c.vehicle.clone();
    let nominal_share = vehicle.front_transfer_share();
    let make = |f: Tyre, r: Tyre| Augmented {
        roll: c.roll,
        ..Augmented::new(VehicleModel::new(vehicle.clone(), f, r), c.friction)
    };
    // Tyres not fitted to the runs: one model for all runs and every fold.
    let fixed = |m: Augmented| Bases {
        folds: vec![m.clone(); folds.len()],
        all: m,
        nominal_share,
        axle: None,
        identification: None,
    };
    match &c.tyres {
        BaseTyres::Given(f, r) => Ok((
            fixed(make((**f).clone(), (**r).clone())),
            "given tyre files".into(),
            None,
        )),
        BaseTyres::Rig { path, data, model } => {
            let grouped = group(path, data, &Grouping::default(), SlipAxis::Angle)?;
            let conditions = grouped.conditions;
            if conditions.is_empty() {
                return Err(DiagnosisError::NoRigCondition { rig: path.clone() }.into());
            }
            let mut loads: Vec<f64> = conditions.iter().map(|q| q.fz).collect();
            loads.sort_by(f64::total_cmp);
            let t0 = start_tyre_of(*model, loads[loads.len() / 2])?;
            let mut settings = FitSettings::new(c.settings.seed);
            settings.pso.particles = 40;
            settings.pso.iterations = 150;
            let started = Instant::now();
            let f =
                fit_lateral(&t0, &conditions, &settings).map_err(|e| DiagnosisError::RigFit {
                    rig: path.clone(),
                    source: Box::new(e),
                })?;
            if let Some(rec) = timing {
                rec.add(Phase::BaseIdentification, started.elapsed(), 0);
            }
            Ok((
                fixed(make(f.tyre.clone(), f.tyre.clone())),
                format!(
                    "{} fitted to the rig data {} (σ {:.2} % of the force)",
                    model,
                    path.display(),
                    f.sigma_percent
                ),
                Some(grouped.report),
            ))
        }
        BaseTyres::FromRuns => {
            let d = c.settings.derivatives;
            let (bases, described) =
                axles_from_runs(runs, folds, (scales_hint, nominal_share), (make, d), timing);
            Ok((bases, described, None))
        }
    }
}

/// What the axle shares set on the models `make` builds: their tyres.
fn axle_layout(make: impl Fn(Tyre, Tyre) -> Augmented) -> Layout {
    let (f, r) = axle_tyres(&[0.5, 0.5, 0.5]);
    Layout {
        base: make(f, r),
        kinds: Vec::new(),
        axle: true,
    }
}

/// The base model of axle characteristics identified from the runs (no
/// tyre data; [`super::base`]): a grid of starts, the best basins
/// polished, the best of them fitted, then refitted on every fold.
fn axles_from_runs(
    runs: &[Prepared],
    folds: &[Vec<usize>],
    (scales_hint, nominal_share): ([f64; 3], f64),
    (make, derivatives): (impl Fn(Tyre, Tyre) -> Augmented + Sync, Derivatives),
    timing: Option<&Recorder>,
) -> (Bases, String) {
    let build = |p: &[f64]| {
        let (f, r) = axle_tyres(p);
        make(f, r)
    };
    let stamps = timing.map(|_| Stamps::default());
    let layout = axle_layout(&make);
    let problem = Problem::new(
        |p: &[f64]| counted(&stamps, build, p),
        runs.iter().collect(),
        scales_hint,
        AXLE_BOUNDS.to_vec(),
    )
    .with_layout(layout.clone(), derivatives);
    let t0 = Instant::now();
    let (start, starts) = identify_axles(&problem);
    let mark = (Instant::now(), stamps.as_ref().map_or(0, Stamps::count));
    let full = fit(&problem, &start, None, Polish::LevenbergMarquardt);
    if let (Some(rec), Some(st)) = (timing, &stamps) {
        rec.add(Phase::BaseIdentification, mark.0 - t0, mark.1);
        let phases = [
            Phase::BasePolish,
            Phase::BaseLinearisation,
            Phase::BaseLinearisation,
        ];
        let n = full.params.len();
        let jacobian = problem.jacobian_evaluations(n);
        record_polish(rec, st, mark, (n, jacobian), full.linear.is_some(), phases);
    }
    let fold_params: Vec<Vec<f64>> = (0..folds.len())
        .into_par_iter()
        .map(|k| {
            let t0 = Instant::now();
            let train: Vec<&Prepared> = (0..runs.len())
                .filter(|i| !folds[k].contains(i))
                .map(|i| &runs[i])
                .collect();
            let stamps = timing.map(|_| Stamps::default());
            let p = Problem::new(
                |p: &[f64]| counted(&stamps, build, p),
                train,
                scales_hint,
                AXLE_BOUNDS.to_vec(),
            )
            .with_layout(layout.clone(), derivatives);
            let q = refit(&p, &full, &training_rows(runs, &folds[k])).params;
            if let (Some(rec), Some(st)) = (timing, &stamps) {
                rec.add(Phase::BaseFolds, t0.elapsed(), st.count());
            }
            q
        })
        .collect();
    let p = &full.params;
    let cov = full
        .linear
        .as_ref()
        .and_then(|l| covariance(&l.jacobian, 2.0 * full.cost));
    let id = AxleIdentification::new(p, &full.std_errors, cov.as_ref(), starts);
    let described = format!("no tyre data: {}", id.describe());
    (
        Bases {
            all: build(p),
            folds: fold_params.iter().map(|q| build(q)).collect(),
            nominal_share,
            axle: Some((p.clone(), fold_params)),
            identification: Some(id),
        },
        described,
    )
}

/// The model of `p`, the evaluation stamped when the diagnosis is timed.
fn counted(stamps: &Option<Stamps>, build: impl Fn(&[f64]) -> Augmented, p: &[f64]) -> Augmented {
    if let Some(st) = stamps {
        st.tick();
    }
    build(p)
}

/// The effect parameters of a fit whose first `skip` parameters are the
/// axle characteristics.
pub(super) fn parameter_values(
    kinds: &[EffectKind],
    f: &FitOutcome,
    skip: usize,
) -> Vec<ParameterValue> {
    let named = kinds
        .iter()
        .flat_map(|e| e.parameters().iter().map(move |q| (e.name(), q)));
    let roll = fits_roll(kinds).then_some(ROLL_DYNAMICS.iter().map(|q| ("roll", q)));
    named
        .chain(roll.into_iter().flatten())
        .enumerate()
        .map(|(i, (group, q))| {
            let value = f.params[skip + i];
            ParameterValue {
                name: format!("{group}.{}", q.name),
                unit: q.unit,
                value,
                std_error: f.std_errors[skip + i],
                at_bound: q.bound_at(value).is_some(),
                bound: q.bound_at(value),
            }
        })
        .collect()
}
